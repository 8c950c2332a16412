"""Benchmark of stage 3: Area Graph segmentation of SIST-F5 at 0.044 m/px.

Reads ``work/SIST-F5.tif`` written by the CAD benchmark (builds it with import_dxf + rasterize,
untimed, when it is missing) and writes ``work/SIST-F5.areagraph.pkl`` for the refine benchmark.
"""
import pickle
import time
from pathlib import Path


def _grid(work: Path, shared: Path):
    from algorithms.raster_io import read_grid, write_grid

    tif = work / "SIST-F5.tif"
    if not tif.exists():
        from algorithms.cad_import import import_dxf
        from algorithms.rasterize import rasterize

        drawing = import_dxf(str(shared / "dxf" / "sist" / "SIST-F5.dxf"))
        write_grid(str(tif), rasterize(drawing.geometries, resolution=0.044))
    return read_grid(str(tif))


def bench_segment(work: Path, shared: Path) -> dict:
    from algorithms.segmentation import segment

    grid = _grid(work, shared)
    t0 = time.perf_counter()
    ag = segment(grid)
    wall = time.perf_counter() - t0
    with open(work / "SIST-F5.areagraph.pkl", "wb") as fh:
        pickle.dump(ag, fh, protocol=pickle.HIGHEST_PROTOCOL)
    st = ag.stats
    steps = ", ".join(f"{k[:-2]} {st[k]:.2f}" for k in
                      ("interior_s", "skeleton_s", "regions_s", "graph_s", "merge_s", "polygons_s", "passages_s") if k in st)
    rows, cols = grid.shape
    detail = (f"SIST-F5 {cols}x{rows} px ({rows * cols / 1e6:.1f} Mpx) at {grid.resolution:g} m/px, "
              f"alpha {int(st['alpha_px2'])} px^2: {len(ag.areas)} areas, {len(ag.passages)} passages, "
              f"interior {st['interior_area_m2']:.0f} m2; steps (s): {steps} "
              f"(skeleton = clearance + thinning + skeleton graph, {int(st['skeleton_edges'])} edges; "
              f"regions = one per skeleton edge piece; merge = alpha rooms + door narrowings)")
    return {"wall_s": wall, "detail": detail}


STAGES = [("segment", bench_segment)]
