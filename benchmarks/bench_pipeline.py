"""Benchmark: the whole pipeline on one SIST floor (DXF -> osmAG), the figure the paper reports as 35 s."""
import time


def bench_whole_floor(work, shared):
    from algorithms import pipeline

    dxf = shared / "dxf" / "sist" / "SIST-F5.dxf"
    t0 = time.perf_counter()
    stats = pipeline.convert_dxf(str(dxf), str(work / "SIST-F5.osm"), anchor_lon=121.5906, anchor_lat=31.1790,
                                 level="5")
    wall = time.perf_counter() - t0
    steps = ", ".join(f"{k} {v:.2f} s" for k, v in stats["timings"].items())
    return {"wall_s": wall, "detail": f"SIST-F5 DXF -> osmAG: {stats['areas']} areas, {stats['passages']} passages; "
                                      f"{steps}"}


STAGES = [("whole floor DXF -> osmAG", bench_whole_floor)]
