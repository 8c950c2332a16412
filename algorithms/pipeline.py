"""The whole pipeline in one call: DXF floor plan -> osmAG file (+ preview, raster, labels).

Stages: CAD import (structural layers, metres) -> rasterize -> Area Graph segmentation -> refinement
-> osmAG export (georeferenced through a ``LocalFrame``). Each stage is also its own Processing
algorithm; this module only chains them with the same defaults, for ``cad2osmag:dxftoosmag``, the demo
and scripts. Outputs are written atomically, and only after every stage succeeded.
"""
from __future__ import annotations

import contextlib
import functools
import gc
import os
import time
from dataclasses import dataclass, field
from typing import Dict, Optional, Sequence

from shapely.geometry import Polygon
from shapely.ops import unary_union

from . import anchors, cad_import, kernels, osmag, rasterize, refine, segmentation, semantics
from .area_types import Symbols, classify_vertical_areas, symbol_evidence
from .georef import LocalFrame
from .errors import Canceled, InputError
from .model import Area, AreaGraph, CadDrawing, OccupancyGrid
from .progress import ensure

# Default anchor when the user gives none: the osmAG root must be a real WGS84 position. (0, 0) would put
# the building in the Gulf of Guinea, so the log says clearly that the map is not georeferenced yet.
DEFAULT_ANCHOR = (0.0, 0.0)


@dataclass
class FloorResult:
    drawing: CadDrawing
    grid: OccupancyGrid
    segmented: AreaGraph
    refined: AreaGraph
    floor_area: Optional[Area]
    stats: Dict[str, object] = field(default_factory=dict)
    names: Optional[object] = None  # semantics.NamesReport when room names ran


def floor_outline(areas: Sequence[Area], wall_gap: float = 0.8) -> Optional[Polygon]:
    """The floor's outline: one polygon without holes that contains every area, made of the union of
    the areas with the walls between them closed (gaps up to ``wall_gap`` metres; doubled until the
    floor is one piece, up to 8 m, else the convex hull). It is the ``osmAG:parent`` of the areas."""
    polys = [a.polygon for a in areas if a.polygon is not None and not a.polygon.is_empty]
    if not polys:
        return None
    import numpy as np
    import shapely

    arr = np.asarray(polys, dtype=object)
    exact = None
    reach = _OutlineReach(arr)
    gap = wall_gap
    while True:
        half = gap / 2.0
        if gap < 8.0 and reach.apart(half):
            # the buffered areas cannot all meet at this gap: the result would not be one polygon (the mitre
            # buffers of a floor with a far piece were ~2/3 of this step on SIST-F1.dwg)
            gap *= 2.0
            continue
        if exact is None:
            exact = shapely.union_all(arr)  # containment is exact, whatever the buffers rounded
        # one vectorised buffer of every area and one union (the loop of buffers was ~1/3 of this step)
        merged = shapely.union_all(shapely.buffer(arr, half, join_style="mitre")).buffer(-half / 2.0, join_style=2)
        merged = unary_union([merged, exact])
        if merged.geom_type == "Polygon":
            return Polygon(merged.exterior)
        if gap >= 8.0:
            return Polygon(merged.convex_hull.exterior)
        gap *= 2.0


_MITRE_LIMIT = 5.0  # shapely's default mitre_limit: a mitred corner reaches at most this many distances out


class _OutlineReach:
    """Which areas' mitre buffers (``floor_outline``) can meet: the buffer of polygon P by h lies within
    h * f(P) of P, f(P) = 1 / sin(phi / 2) over its sharpest corner phi (capped by the mitre limit), so
    two buffers meet only where dist(P, Q) <= h * (f(P) + f(Q)). When the areas fall into several groups
    at that reach, the union of the buffers has several pieces, and so does the eroded outline (each
    piece still holds its areas grown by h / 2): ``floor_outline`` goes to the next gap without buffering."""

    def __init__(self, arr):
        import numpy as np
        import shapely

        self.arr = arr
        self.f = np.array([self._factor(p) for p in arr], dtype=float)
        self.tree = shapely.STRtree(arr)

    @staticmethod
    def _factor(poly) -> float:
        import numpy as np
        import shapely

        f = 1.0
        for ring in [poly.exterior] + list(poly.interiors):
            xy = shapely.get_coordinates(ring)[:-1]
            if len(xy) < 3:
                return _MITRE_LIMIT * 1.01
            a, b = np.roll(xy, 1, axis=0) - xy, np.roll(xy, -1, axis=0) - xy
            na, nb = np.hypot(a[:, 0], a[:, 1]), np.hypot(b[:, 0], b[:, 1])
            if not ((na > 0) & (nb > 0)).all():
                return _MITRE_LIMIT * 1.01  # a repeated vertex: assume the sharpest corner
            cos = np.clip((a * b).sum(axis=1) / (na * nb), -1.0, 1.0)
            s = float(np.sin(np.arccos(cos) / 2.0).min())
            f = max(f, 1.0 / s if s > 0 else _MITRE_LIMIT)
        return min(_MITRE_LIMIT, f) * 1.01 + 1e-9  # a margin for rounding: only ever buffers more often

    def apart(self, half: float) -> bool:
        """The areas fall into more than one group at the reach of buffers by ``half``."""
        import numpy as np
        import shapely
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import connected_components

        n = len(self.arr)
        if n < 2:
            return False
        i, j = self.tree.query(self.arr, predicate="dwithin", distance=2.0 * half * float(self.f.max()))
        near = shapely.distance(self.arr[i], self.arr[j]) <= half * (self.f[i] + self.f[j])
        k, _ = connected_components(coo_matrix((np.ones(int(near.sum())), (i[near], j[near])), shape=(n, n)),
                                    directed=False)
        return k > 1


def _gc_paused(func):
    """Run ``func`` with Python's cyclic garbage collector paused (re-enabled after, if it was on). A conversion
    allocates ~10^5-10^6 tracked objects (the DXF document, numba's modules as the kernels load, shapely and
    area lists): the collector's passes over them were 0.37-0.61 CPU s of a fresh SIST floor (gc.callbacks),
    for almost no garbage. The one large cyclic structure, the ezdxf document, is freed right after the import
    (``gc.collect(0)``: it was all made while the collector was paused, so it is in the youngest generation)."""
    @functools.wraps(func)
    def run(*args, **kwargs):
        was = gc.isenabled()
        gc.disable()
        try:
            return func(*args, **kwargs)
        finally:
            if was:
                gc.enable()
    return run


@_gc_paused
def process_floor(dxf_path: str, *, rules=None, layers=None, units=None, include_doors: bool = False, plan=None,
                  resolution: float = rasterize.DEFAULT_RESOLUTION, extent=None,
                  door_width: float = segmentation.DEFAULT_DOOR_WIDTH,
                  corridor_width: float = segmentation.DEFAULT_CORRIDOR_WIDTH,
                  delta: float = segmentation.DEFAULT_DELTA, prune: float = segmentation.DEFAULT_PRUNE,
                  epsilon_px: float = refine.EPSILON_PX, min_area: float = refine.MIN_AREA_M2,
                  level: str = "1", names: bool = True, name_rules=None, carve: bool = True,
                  topology_resolution: Optional[float] = None, progress=None) -> FloorResult:
    """Run stages 1-5 on one DXF floor (stage 5, room names and types, unless ``names`` is False);
    nothing is written. ``topology_resolution``: the cell size of the segmentation's topology steps
    (``segmentation.topology_scale``; None = ``segmentation.TOPOLOGY_RESOLUTION``, 0 = the raster's cells)."""
    progress = ensure(progress)
    timings: Dict[str, float] = {}
    cpu: Dict[str, float] = {}  # CPU seconds of this process per stage: what counts on a loaded machine

    def timed(name, start, end, func, *args, **kwargs):
        t0, c0 = time.perf_counter(), time.process_time()
        try:
            out = func(*args, progress=progress.sub(start, end), **kwargs)
        except (InputError, Canceled):
            raise
        except Exception as exc:  # GEOS topology errors and the like: name the stage, never a raw traceback
            if type(exc).__module__.split(".")[0] not in ("shapely", "cv2", "osgeo"):
                raise
            raise InputError(f"the {name} stage failed on this drawing's geometry ({type(exc).__name__}: {exc}); "
                             "please report the drawing") from exc
        timings[name] = time.perf_counter() - t0
        cpu[name] = time.process_time() - c0
        return out

    drawing = timed("cad_import", 0, 25, cad_import.import_dxf, dxf_path, rules=rules, layers=layers,
                    units=units, include_doors=include_doors, plan=plan)
    gc.collect(0)  # the DXF/DWG document's cycles (see _gc_paused): its memory back before the raster's
    # the compiled kernels load in a thread beside rasterize and the segmentation's first steps (their OpenCV
    # and numpy calls release the GIL); segmentation waits for them at their first use (kernels.py)
    kernels.preload()
    # projection lines no rule keeps count for the extent (a corridor closed by one lies beyond the walls)
    grid = timed("rasterize", 25, 35, rasterize.rasterize, drawing.geometries + drawing.boundary,
                 resolution=resolution, extent=extent, door_hints=drawing.doors)
    # the drawing's texts are classified once (segmentation's evidence, protected rooms, names, outdoor spaces)
    classified = semantics.classify_labels(drawing.texts, name_rules)
    seg = timed("segment", 35, 80, segmentation.segment, grid, door_width=door_width,
                corridor_width=corridor_width, delta=delta, prune=prune,
                inside_points=_inside_points(drawing, name_rules, classified), door_hints=drawing.doors, footprint=True,
                boundary=rasterize.boundary_mask(drawing.boundary, grid), topology_resolution=topology_resolution)
    note = kernels.compile_note()  # compiled beside the first steps on this machine's first run: say so
    if note:
        progress.info(note)
    t0, c0 = time.perf_counter(), time.process_time()
    evidence = symbol_evidence(drawing)  # the drawing's geometries, plus the stair/lift symbols it hides
    symbols = Symbols(evidence)  # segments, stair runs and lift crosses: found once, typing and carve
    vertical = classify_vertical_areas(seg.areas, evidence, symbols=symbols)
    if vertical:
        progress.info(f"{len(vertical)} stair/lift areas recognised from their symbols")
    protected = semantics.protect_labelled_areas(seg.areas, drawing.texts, min_area, name_rules,
                                                 classified=classified) if names else {}
    timings["types"], cpu["types"] = time.perf_counter() - t0, time.process_time() - c0
    refined, rstats = timed("refine", 80, 95, refine.refine, seg, grid.resolution, epsilon_px=epsilon_px,
                            min_area=min_area, keep_types=refine.KEEP_TYPES + (semantics.PROTECTED_TYPE,))
    semantics.restore_types(protected, seg.areas, refined.areas)
    if carve:  # stairs and lifts swallowed by a larger area become areas of their own (before names: codes name them)
        _carve_anchors(refined, drawing, grid, timings, cpu, progress, symbols)
    names_report = None
    if names:
        names_report = timed("names", 95, 98, semantics.assign_names, refined.areas, drawing.texts, level,
                             rules=name_rules, grid=grid, passages=refined.passages,
                             hidden_texts=getattr(drawing, "hidden_texts", None), classified=classified,
                             partitions=getattr(drawing, "partitions", None), door_hints=drawing.doors)
        progress.info(names_report.summary())
    # the outline (GEOS buffers and unions, which release the GIL) on the second core while the closed spaces
    # are found: both only read the areas' polygons (closed spaces set tags)
    t0, c0 = time.perf_counter(), time.process_time()
    outline_job = segmentation._Background(lambda: floor_outline(refined.areas))
    closed, share = _closed_spaces(refined, drawing, name_rules, rstats, progress, classified)
    outline = outline_job.result()
    timings["outline"], cpu["outline"] = time.perf_counter() - t0, time.process_time() - c0
    floor_area = None
    if outline is not None:
        floor_area = Area(id=0, polygon=outline, type="structure", name=f"Level {level}")
    stats = {"timings": timings, "cpu": cpu, "refine": rstats, "segment": dict(seg.stats),
             "texts": len(drawing.texts), "geometries": len(drawing.geometries), "unit": drawing.unit_name,
             "raster_shape": grid.shape, "areas": len(refined.areas), "passages": len(refined.passages),
             "components": rstats.get("components", 1), "largest_component_share": share, "closed_spaces": closed,
             "roof_spaces": rstats.get("roof_spaces", []), "outdoor_spaces": rstats.get("outdoor_spaces", [])}
    if names_report is not None:
        stats["names"] = names_report.counts()
    progress.info(f"floor {level}: {len(refined.areas)} areas, {len(refined.passages)} passages "
                  f"({rstats.get('vertex_reduction', 0):.0%} fewer vertices after refinement)")
    return FloorResult(drawing, grid, seg, refined, floor_area, stats, names_report)


def _inside_points(drawing: CadDrawing, name_rules, classified):
    """``segmentation.room_name_points`` of the drawing from its classified texts (an (n, 2) array)."""
    import numpy as np

    pts = [(x, y) for x, y, _ in semantics.room_name_points(drawing.texts, name_rules, classified=classified)]
    return np.asarray(pts, dtype=np.float64).reshape(-1, 2)


def _carve_anchors(refined: AreaGraph, drawing: CadDrawing, grid, timings, cpu, progress, symbols=None) -> None:
    """``anchors.carve_anchors`` on the refined graph (labels repainted), timed with stage "types"."""
    t0, c0 = time.perf_counter(), time.process_time()
    evidence = symbols.geometries if symbols is not None else symbol_evidence(drawing)  # typed from the same list
    found = anchors.find_anchor_symbols(evidence, shapes=symbols)
    st = anchors.carve_anchors(refined.areas, refined.passages, drawing.geometries, progress=progress.sub(95, 95),
                               symbols=found,
                               texts=list(drawing.texts) + list(getattr(drawing, "hidden_texts", None) or []))
    anchors.relabel(refined.labels, grid, refined.areas, st)
    if st.get("outdoor"):
        progress.info(f"{len(st['outdoor'])} named stair(s) drawn outside every area (outdoor) made areas of their own: "
                      + ", ".join(map(str, st["outdoor"])))
    if st["carved"]:
        progress.info(f"{len(st['carved'])} stair/lift area(s) carved out of the areas that swallowed them ("
                      + ", ".join(f"{k} {m2:.0f} m² from area {h}" for k, _n, h, m2 in st["carved"][:12]) + ")")
    # counted with the stair/lift typing it completes (stage "types")
    timings["types"] = timings.get("types", 0.0) + time.perf_counter() - t0
    cpu["types"] = cpu.get("types", 0.0) + time.process_time() - c0


def _closed_spaces(refined: AreaGraph, drawing: CadDrawing, name_rules, rstats, progress, classified=None):
    """Wall cavities, ducts and shafts the drawing closes on all sides (``segmentation.closed_spaces``):
    tagged ``cad2osmag:closed=yes`` and counted out of the largest component's share (issue 8, item 6)."""
    if rstats.get("components", 1) <= 1:
        return [], rstats.get("largest_component_share", 1.0)
    if classified is None:
        classified = semantics.classify_labels(drawing.texts, name_rules)
    pts = semantics.room_name_points(drawing.texts, name_rules, classified=classified)
    closed = segmentation.closed_spaces(refined.areas, refined.passages, pts)
    _count_out(refined, closed, "cad2osmag:closed", "closed space(s) no passage reaches and no room name labels "
               "(wall cavities, ducts, shafts", progress)
    roofs = _roof_spaces(refined, drawing, closed, rstats, progress)
    outdoor = _outdoor_spaces(refined, drawing, name_rules, list(closed) + roofs, rstats, progress, classified)
    return closed, segmentation.connected_share(refined.areas, list(closed) + roofs + outdoor)


def _roof_spaces(refined: AreaGraph, drawing: CadDrawing, closed, rstats, progress):
    """Roofs of lower parts drawn on this floor's plan, no passage reaches (``segmentation.roof_spaces``):
    tagged ``cad2osmag:roof=yes``, listed in ``rstats['roof_spaces']`` and counted out of the share."""
    roofs = segmentation.roof_spaces(refined.areas, refined.passages, drawing.texts, closed)
    rstats["roof_spaces"] = roofs
    _count_out(refined, roofs, "cad2osmag:roof", "area(s) of roofs below this floor that no passage reaches (",
               progress)
    return roofs


def _count_out(refined: AreaGraph, ids, tag: str, what: str, progress) -> None:
    """Tag the areas ``ids`` (``tag=yes``) and log them as counted out of the connectivity figure."""
    for a in refined.areas:
        if a.id in ids:
            a.tags[tag] = "yes"
    if ids:
        m2 = sum(a.area for a in refined.areas if a.id in ids)
        progress.info(f"{len(ids)} {what}, {m2:.0f} m2: areas {', '.join(map(str, list(ids)[:20]))}) are counted "
                      "out of the connectivity")


def _outdoor_spaces(refined: AreaGraph, drawing: CadDrawing, name_rules, counted_out, rstats, progress,
                    classified=None):
    """Terraces and landscape outside the facade no passage reaches and no room name labels
    (``segmentation.outdoor_spaces``), and ground open to the outside along a front no doorway explains
    (``segmentation.open_ground_spaces``: porches, yards under an overhang): tagged ``cad2osmag:outdoor=yes``,
    listed in ``rstats['outdoor_spaces']`` and counted out of the share, like roofs."""
    if classified is None:
        classified = semantics.classify_labels(drawing.texts, name_rules)
    names = [(x, y, lab.text) for lab in classified
             if lab.role in ("name", "number") for x, y in [(lab.x, lab.y)] + list(lab.alts)]
    outdoor = segmentation.outdoor_spaces(refined.areas, refined.passages, names, counted_out)
    # ground open to the outside along a front wider than a doorway (porches, yards): named or not (issue 8)
    outdoor = sorted(set(outdoor) | set(segmentation.open_ground_spaces(
        refined.areas, refined.passages, refined.grid, names, list(counted_out) + outdoor, drawing.doors)))
    rstats["outdoor_spaces"] = outdoor
    _count_out(refined, outdoor, "cad2osmag:outdoor", "area(s) of exterior ground outside the facade that no "
               "passage reaches and no room name labels (terraces, landscape, porches and yards open to the outside",
               progress)
    return outdoor


def convert_dxf(dxf_path: str, out_osm: str, *, preview_png: Optional[str] = None,
                anchor_lon: Optional[float] = None, anchor_lat: Optional[float] = None,
                rotation_deg: float = 0.0, scale: float = 1.0, level: str = "1", height: float = 3.2,
                variant: str = "semantic", progress=None, **floor_kwargs) -> Dict[str, object]:
    """DXF floor plan -> osmAG file (and optionally a preview PNG). Returns figures for the log."""
    progress = ensure(progress)
    if anchor_lon is None or anchor_lat is None:
        anchor_lon, anchor_lat = DEFAULT_ANCHOR
        progress.warning("no anchor given: the map is placed at lon/lat 0/0; give ANCHOR (and ROTATION) "
                         "or run cad2osmag:georeference to put it on the Earth")
    frame = LocalFrame(anchor_lon, anchor_lat, rotation_deg=rotation_deg, scale=scale)
    floor = process_floor(dxf_path, level=level, progress=progress.sub(0, 90), **floor_kwargs)
    structure = [floor.floor_area] if floor.floor_area is not None else []
    def _stamp(p):
        with contextlib.suppress(OSError):
            st = os.stat(p)
            return (st.st_ino, st.st_mtime_ns, st.st_size)
        return None

    before = {p: _stamp(p) for p in (out_osm, preview_png) if p}
    try:  # a cancel (or a failed preview) after the osmAG file was written must not leave it behind
        t0, c0 = time.perf_counter(), time.process_time()
        written = osmag.write_osmag(out_osm, semantics.for_osm(floor.refined.areas), floor.refined.passages,
                                    frame=frame, level=level,
                                    height=height, variant=variant, structure_areas=structure,
                                    progress=progress.sub(90, 97))
        floor.stats["timings"]["export"] = time.perf_counter() - t0
        floor.stats["cpu"]["export"] = time.process_time() - c0
        if preview_png:
            from .preview import render_preview

            render_preview(floor.grid, floor.refined, preview_png)
        progress.step(100)
    except BaseException:
        for p, stamp in before.items():
            if _stamp(p) != stamp:  # written by this run (a file this run did not touch is never removed)
                with contextlib.suppress(OSError):
                    os.remove(p)
        raise
    out = dict(floor.stats)
    out["osm"] = {k: v for k, v in written.items() if k != "warnings"}  # write_osmag logged its warnings
    return out
