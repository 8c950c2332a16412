"""Benchmark of stages 4 + 7: refine a SIST floor and export it as osmAG.

Reads work/SIST-F5.areagraph.pkl (written by the segmentation benchmark); when it is missing, the
floor is imported, rasterized and segmented here first, outside the timed part.
"""
import pickle
import shutil
import subprocess
import time
from pathlib import Path

FLOOR = "SIST-F5"


def _graph(work: Path, shared: Path):
    pkl = work / f"{FLOOR}.areagraph.pkl"
    if pkl.exists():
        with open(pkl, "rb") as fh:
            return pickle.load(fh), "segmentation benchmark output"
    from algorithms.cad_import import import_dxf
    from algorithms.rasterize import rasterize
    from algorithms.segmentation import segment

    drawing = import_dxf(str(shared / "dxf" / "sist" / f"{FLOOR}.dxf"))
    graph = segment(rasterize(drawing.geometries))
    return graph, "segmented here (no pickle from the segmentation benchmark)"


def bench_refine_export(work: Path, shared: Path) -> dict:
    from algorithms.georef import LocalFrame
    from algorithms.osmag import write_osmag
    from algorithms.refine import refine

    graph, source = _graph(work, shared)
    res = graph.grid.resolution if graph.grid is not None else 0.044
    frame = LocalFrame(121.5906, 31.1790, rotation_deg=0.0)  # ShanghaiTech, for the benchmark only
    out = work / f"{FLOOR}.osm"
    t0 = time.perf_counter()
    refined, st = refine(graph, res)
    t1 = time.perf_counter()
    written = write_osmag(str(out), refined.areas, refined.passages, frame=frame, level="5")
    t2 = time.perf_counter()
    osmium = "osmium not installed"
    if shutil.which("osmium"):
        r = subprocess.run(["osmium", "fileinfo", "-e", str(out)], capture_output=True, text=True)
        osmium = "osmium ok" if r.returncode == 0 else "osmium FAILED"
    detail = (f"{FLOOR} ({source}): refine {t1 - t0:.3f} s + export {t2 - t1:.3f} s; "
              f"vertices {st['vertices_before']} -> {st['vertices_after']} "
              f"(-{100 * st['vertex_reduction']:.1f} %, target >= 85 %); max deviation "
              f"{100 * st['max_deviation_m']:.2f} cm (DP alone {100 * st['max_deviation_dp_m']:.2f} cm) vs "
              f"eps*r = {100 * st['epsilon_m']:.2f} cm; areas {st['areas_in']} -> {st['areas_out']} "
              f"({st['merged']} merged, {st['dropped']} isolated dropped), passages {st['passages_out']}, "
              f"{written['nodes']} nodes ({written['shared_nodes']} shared); {osmium}")
    return {"wall_s": t2 - t0, "detail": detail}


STAGES = [("refine+export", bench_refine_export)]
