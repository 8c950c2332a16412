"""What one benchmark run does, in its own fresh process (called by ``scripts/bench.py``).

* :func:`run_plan`: the whole pipeline on one drawing (DXF or DWG): CAD import -> rasterize ->
  segmentation -> refinement -> room names -> osmAG export, with wall and CPU seconds per stage, the
  process's peak RSS, and the figures of the result (raster size, areas, passages, named areas,
  connected components, vertices). Optionally draws the gallery picture.
* :func:`run_merge`: fuse the first k converted floors into one building (scaling against floors).
* :func:`run_building`: the five SIST floors end to end (conversion in a 2-process pool + fusion).

Every function returns a plain dict; a failure is returned as ``{"ok": False, "error": ...}``.
"""
from __future__ import annotations

import os
import resource
import time
import traceback
from typing import Dict, Optional

ANCHOR = (121.5906, 31.1790)  # ShanghaiTech, for the benchmark only (any anchor gives the same timings)

# area type -> fill colour of the gallery pictures (matplotlib colour names / hex)
TYPE_COLOURS = {"room": "#8ecae6", "corridor": "#ffd166", "stairs": "#ef476f", "elevator": "#9b5de5",
                "structure": "#dddddd"}
OTHER_COLOUR = "#90be6d"
# areas the floor counts out of its graph (roofs below it, exterior ground, closed shafts): drawn apart, not as rooms
COUNTED_OUT_TAGS = ("cad2osmag:roof", "cad2osmag:outdoor", "cad2osmag:closed")
COUNTED_OUT_COLOUR = "#eeeeee"


def peak_rss_mb() -> float:
    """This process's peak RSS. Linux's VmHWM first: ``ru_maxrss`` survives exec, so a process started
    from a large parent (a test worker) would report the parent's peak."""
    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def _vertices(areas) -> int:
    n = 0
    for a in areas:
        p = a.polygon
        if p is None or p.is_empty:
            continue
        polys = getattr(p, "geoms", [p])
        for q in polys:
            n += len(q.exterior.coords) - 1 + sum(len(r.coords) - 1 for r in q.interiors)
    return n


def run_plan(path: str, out_osm: str, level: str = "1", png: Optional[str] = None,
             resolution: Optional[float] = None, warm: bool = False) -> Dict[str, object]:
    """One drawing through the whole pipeline; see the module docstring. ``warm``: then convert it once more
    in the same process (``out["warm"]``: wall/CPU seconds and CPU per stage of that second conversion), the
    figure a QGIS user sees from the second floor on (plugin imported, compiled kernels loaded); the cold
    figures (``wall_s``, ``cpu_s``, ``peak_mb``) stay those of the first conversion in a fresh process."""
    from algorithms import osmag, pipeline, semantics
    from algorithms.errors import InputError
    from algorithms.georef import LocalFrame

    base = peak_rss_mb()
    w0, c0 = time.perf_counter(), time.process_time()
    try:
        kw = {} if resolution is None else {"resolution": resolution}
        floor = pipeline.process_floor(path, level=level, **kw)
        t0, tc = time.perf_counter(), time.process_time()
        structure = [floor.floor_area] if floor.floor_area is not None else []
        written = osmag.write_osmag(out_osm, semantics.for_osm(floor.refined.areas), floor.refined.passages,
                                    frame=LocalFrame(*ANCHOR), level=level, structure_areas=structure)
        floor.stats["timings"]["export"] = time.perf_counter() - t0
        floor.stats["cpu"]["export"] = time.process_time() - tc
    except InputError as exc:
        return {"ok": False, "error": f"InputError: {exc}", "wall_s": time.perf_counter() - w0,
                "peak_mb": peak_rss_mb()}
    except Exception as exc:  # a raw exception is a bug: the bench reports it and goes on
        return {"ok": False, "error": f"{type(exc).__name__}: {exc}", "traceback": traceback.format_exc(limit=4),
                "wall_s": time.perf_counter() - w0, "peak_mb": peak_rss_mb()}
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    fig = semantics.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    names = floor.stats.get("names") or {}
    rows, cols = floor.grid.shape
    out = {"ok": True, "wall_s": wall, "cpu_s": cpu, "peak_mb": peak_rss_mb(), "baseline_mb": base,
           "stages_wall": dict(floor.stats["timings"]), "stages_cpu": dict(floor.stats["cpu"]),
           "raster": [int(cols), int(rows)], "resolution": float(floor.grid.resolution),
           "geometries": int(floor.stats["geometries"]), "texts": int(floor.stats["texts"]),
           "areas": fig["areas"], "passages": fig["passages"], "components": fig["components"],
           "largest_component_pct": fig["largest_component_pct"], "stairs": fig["stairs"],
           "elevators": fig["elevators"], "named_areas": int(names.get("named_areas", 0)),
           "vertices": _vertices(floor.refined.areas), "osm_nodes": int(written.get("nodes", 0)),
           "segment_steps": {k[:-2]: float(v) for k, v in floor.stats["segment"].items()
                             if k.endswith("_s") and isinstance(v, (int, float))}}
    if warm:
        out["warm"] = _warm_run(path, out_osm, level, resolution)
    if png:
        t = time.perf_counter()
        render_gallery(floor, png, title=os.path.basename(path))
        out["gallery_s"] = time.perf_counter() - t
    return out


def _warm_run(path: str, out_osm: str, level: str, resolution: Optional[float]) -> Dict[str, object]:
    """A second conversion of ``path`` in this process (everything imported and loaded): wall/CPU seconds."""
    from algorithms import osmag, pipeline, semantics
    from algorithms.georef import LocalFrame

    w0, c0 = time.perf_counter(), time.process_time()
    try:
        kw = {} if resolution is None else {"resolution": resolution}
        floor = pipeline.process_floor(path, level=level, **kw)
        structure = [floor.floor_area] if floor.floor_area is not None else []
        osmag.write_osmag(out_osm, semantics.for_osm(floor.refined.areas), floor.refined.passages,
                          frame=LocalFrame(*ANCHOR), level=level, structure_areas=structure)
    except Exception as exc:
        return {"ok": False, "error": f"{type(exc).__name__}: {exc}"}
    return {"ok": True, "wall_s": time.perf_counter() - w0, "cpu_s": time.process_time() - c0,
            "stages_cpu": dict(floor.stats["cpu"])}


def _label(a) -> str:
    """The text drawn on an area: its name (or ref) when the default font can draw it, else ''."""
    for s in (a.name, a.ref):
        s = (s or "").strip()
        if s and s.isascii() and not s.startswith(("room ", "corridor ", "area ")):
            return s[:18]
    if a.ref and a.ref.isascii():
        return a.ref[:18]
    return ""


def render_gallery(floor, path: str, title: str = "", max_px: int = 1100) -> str:
    """Gallery picture of a converted floor: walls (the occupancy raster) grey, areas filled by type,
    passages red, names (those the default font can draw) as labels. A small palette PNG, atomically."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.patches import Patch, Polygon as MplPolygon

    from algorithms.io_utils import atomic_path
    from algorithms.model import OCCUPIED

    grid = floor.grid
    rows, cols = grid.shape
    step = max(1, int(np.ceil(max(rows, cols) / 1600)))
    occ = grid.data[::step, ::step] == OCCUPIED
    x0, y_top = grid.origin_x, grid.origin_y
    extent = (x0, x0 + cols * grid.resolution, y_top - rows * grid.resolution, y_top)
    aspect = rows / max(cols, 1)
    w_in = max_px / 100.0
    fig = plt.figure(figsize=(w_in, max(2.0, w_in * aspect + 0.5)), dpi=100)
    ax = fig.add_axes((0, 0, 1, 1 - 0.5 / max(2.0, w_in * aspect + 0.5)))
    ax.imshow(np.where(occ, 0.55, 1.0), cmap="gray", vmin=0, vmax=1, extent=extent, interpolation="nearest",
              zorder=0)
    patches, colours = [], []
    areas = list(floor.refined.areas)
    for a in areas:
        for q in getattr(a.polygon, "geoms", [a.polygon]):
            if q.is_empty:
                continue
            patches.append(MplPolygon(np.asarray(q.exterior.coords), closed=True))
            out = any(a.tags.get(t) == "yes" for t in COUNTED_OUT_TAGS)
            colours.append(COUNTED_OUT_COLOUR if out else TYPE_COLOURS.get(a.type, OTHER_COLOUR))
    ax.add_collection(PatchCollection(patches, facecolors=colours, edgecolors="#335", linewidths=0.4, alpha=0.75,
                                      zorder=1))
    segs = [list(p.line.coords)[:2] for p in floor.refined.passages]
    ax.add_collection(LineCollection(segs, colors="#d00000", linewidths=1.6, zorder=2))
    fs = 5 if len(areas) > 80 else 6
    for a in areas:
        s = _label(a)
        if s:
            pt = a.polygon.representative_point()
            ax.text(pt.x, pt.y, s, fontsize=fs, ha="center", va="center", color="#111", zorder=3)
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.axis("off")
    named = sum(1 for a in areas if a.name)
    fig.suptitle(f"{title}: {len(areas)} areas, {len(floor.refined.passages)} passages, {named} named "
                 f"({cols}x{rows} px at {grid.resolution:g} m/px)", fontsize=8, y=0.995)
    handles = [Patch(color=c, label=t) for t, c in TYPE_COLOURS.items() if t != "structure"]
    handles.append(Patch(facecolor=COUNTED_OUT_COLOUR, edgecolor="#335", label="roof / outside / closed"))
    handles.append(Patch(color="#d00000", label="passage"))
    ax.legend(handles=handles, loc="lower right", fontsize=6, framealpha=0.8)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with atomic_path(str(path), suffix=".png") as tmp:
        fig.savefig(tmp, dpi=100)
        plt.close(fig)
        try:  # a palette PNG is 3-4x smaller than RGBA, and the pictures have few colours
            from PIL import Image

            Image.open(tmp).convert("RGB").quantize(colors=64).save(tmp, optimize=True)
        except Exception:
            pass
    return str(path)


def run_merge(osm_paths, out_osm: str) -> Dict[str, object]:
    """Fuse the given converted floors (osmAG files) into one building; time, CPU, peak RSS, figures."""
    from algorithms import building

    base = peak_rss_mb()
    w0, c0 = time.perf_counter(), time.process_time()
    try:
        st = building.merge_floor_files(list(osm_paths), out_osm, building_name="SIST")
    except Exception as exc:
        return {"ok": False, "error": f"{type(exc).__name__}: {exc}", "wall_s": time.perf_counter() - w0,
                "peak_mb": peak_rss_mb()}
    return {"ok": True, "wall_s": time.perf_counter() - w0, "cpu_s": time.process_time() - c0,
            "peak_mb": peak_rss_mb(), "baseline_mb": base, "floors": len(osm_paths),
            "areas": int(st.get("areas_out", 0)), "vertical": len(st.get("vertical", [])),
            "overall_rms": st.get("overall_rms")}


def run_building(dxf_paths, out_dir: str, workers: int = 2) -> Dict[str, object]:
    """The SIST building end to end: every floor converted in a ``workers``-process pool, then fused.
    CPU seconds include the pool's children (RUSAGE_CHILDREN); peak RSS is the largest process's."""
    from algorithms import building

    w0, c0 = time.perf_counter(), time.process_time()
    ch0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        conv = building.convert_floors(list(dxf_paths), out_dir, workers=workers, anchor_lon=ANCHOR[0],
                                       anchor_lat=ANCHOR[1])
        t1 = time.perf_counter()
        out = os.path.join(out_dir, "building.osm")
        st = building.merge_floor_files([c[0] for c in conv], out, building_name="SIST")
    except Exception as exc:
        return {"ok": False, "error": f"{type(exc).__name__}: {exc}", "wall_s": time.perf_counter() - w0}
    ch = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = time.process_time() - c0 + (ch.ru_utime + ch.ru_stime) - (ch0.ru_utime + ch0.ru_stime)
    return {"ok": True, "wall_s": time.perf_counter() - w0, "convert_s": t1 - w0,
            "merge_s": time.perf_counter() - t1, "cpu_s": cpu, "workers": workers,
            "peak_mb": max(peak_rss_mb(), ch.ru_maxrss / 1024.0),
            "per_floor_s": [round(c[1], 2) for c in conv], "areas": int(st.get("areas_out", 0)),
            "vertical": len(st.get("vertical", [])), "overall_rms": st.get("overall_rms")}
