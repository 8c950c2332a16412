"""Benchmark of stages 1-2 on SIST-F5 (~15 k entities after block explosion): DXF -> occupancy raster.

Stages (each in its own process, see scripts/bench.py):
* ``cad_import``: import_dxf(SIST-F5) -> ``work/SIST-F5.cad.pkl`` (geometries, metres).
* ``rasterize``: the pickle -> rasterize at 0.044 m/px -> ``work/SIST-F5.tif``.
* ``cad_import+rasterize``: the whole DXF -> GeoTIFF path in one process (the issue's target:
  <= 3 s, <= 1 GB); then, untimed, every SIST floor on the registered common grid as
  ``work/SIST-F<k>.tif`` for the segmentation benchmark.
"""
import pickle
import time
from pathlib import Path

from algorithms.cad_import import import_dxf
from algorithms.raster_io import write_grid
from algorithms.rasterize import floor_grids, rasterize


def _sist(shared: Path, k: int = 5) -> str:
    return str(shared / "dxf" / "sist" / f"SIST-F{k}.dxf")


def bench_import(work: Path, shared: Path) -> dict:
    t0 = time.perf_counter()
    drawing = import_dxf(_sist(shared))
    wall = time.perf_counter() - t0
    with open(work / "SIST-F5.cad.pkl", "wb") as fh:
        pickle.dump({"geometries": drawing.geometries, "texts": drawing.texts, "unit": drawing.unit_name}, fh)
    n_pts = sum(len(g.coords) for g in drawing.geometries)
    return {"wall_s": wall, "detail": f"SIST-F5: {len(drawing.geometries)} geometries ({n_pts} vertices) on "
                                      f"{len({g.layer for g in drawing.geometries})} layers, unit {drawing.unit_name}"}


def bench_rasterize(work: Path, shared: Path) -> dict:
    pkl = work / "SIST-F5.cad.pkl"
    if pkl.exists():
        with open(pkl, "rb") as fh:
            geoms = pickle.load(fh)["geometries"]
    else:
        geoms = import_dxf(_sist(shared)).geometries
    t0 = time.perf_counter()
    grid = rasterize(geoms)
    write_grid(str(work / "SIST-F5.tif"), grid)
    wall = time.perf_counter() - t0
    rows, cols = grid.shape
    return {"wall_s": wall, "detail": f"{cols}x{rows} px ({rows * cols / 1e6:.1f} Mpx) at {grid.resolution} m/px, "
                                      f"{(grid.data > 0).mean():.1%} occupied"}


def bench_dxf_to_raster(work: Path, shared: Path) -> dict:
    t0 = time.perf_counter()
    drawing = import_dxf(_sist(shared))
    t1 = time.perf_counter()
    grid = rasterize(drawing.geometries)
    write_grid(str(work / "SIST-F5.tif"), grid)
    wall = time.perf_counter() - t0
    detail = (f"import {t1 - t0:.2f} s + rasterize/write {wall - (t1 - t0):.2f} s; "
              f"{grid.shape[1]}x{grid.shape[0]} px")
    # untimed: every floor on the registered common grid, for the segmentation benchmark
    sets = [import_dxf(_sist(shared, k)).geometries for k in range(1, 6)]
    grids, offs = floor_grids(sets)
    for k, g in enumerate(grids, start=1):
        write_grid(str(work / f"SIST-F{k}.tif"), g)
    detail += f"; common grid of F1-F5 {grids[0].shape[1]}x{grids[0].shape[0]} px written"
    return {"wall_s": wall, "detail": detail}


STAGES = [
    ("cad_import", bench_import),
    ("rasterize", bench_rasterize),
    ("cad_import+rasterize", bench_dxf_to_raster),
]
