"""osmAG export and import (pipeline stage 7), see ../shared/docs/osmag-format.md.

Writing (:func:`write_osmag`)
- ``<osm version="0.6" generator="cad2osmag">``; new objects carry negative ids and
  ``action="modify" visible="true"`` (how JOSM writes new objects; older osmAG parsers require them),
  unique per element type: node -1 is the root node, then the area/passage nodes; ways -1.. are the
  structure areas, the areas, then the passages.
- One ``name=root`` node at the frame's anchor (or at ``root=(lon, lat)``).
- Every area is a closed way over its exterior ring. Nodes are shared: vertices of adjacent areas at
  the same position (and vertices lying on a neighbour's edge, which are inserted there) become one
  node, so a passage's two nodes are nodes of both areas it joins. Holes (pillars) cannot be expressed
  by a single closed way: they are left out and counted in the returned stats (``holes_dropped``).
- Area tags: ``osmAG:type=area``, ``osmAG:areatype`` (repeated as ``osmAG:areaType``, the key the
  published osmAG parsers and the paper use), ``indoor=room`` (``corridor`` for corridors),
  ``level``, ``height``, ``name`` (the area's name, else a stable generated id ``L<level>-A<id>``,
  structure areas ``L<level>-S<id>``; duplicate names get the generated id appended so names stay
  unique), ``osmAG:parent`` (the smallest structure area containing the area, or the one named in the
  area's ``osmAG:parent`` tag), ``area=yes`` (tells GDAL/OSM renderers that the closed way is an area;
  ``indoor`` alone is not in GDAL's polygon list) and the area's other tags.
- Passage tags: ``osmAG:type=passage``, ``osmAG:from``, ``osmAG:to``, ``level``, ``name``
  (else ``L<level>-P<id>``) and the passage's other tags.
- Variant ``semantic``: parent/from/to hold area names; ``fix-id``: they hold way ids.
- Coordinates: areas in the CAD frame with ``frame=LocalFrame(...)`` (the usual pipeline case), or
  in any CRS with ``crs=...`` (converted to WGS84 through pyproj). lat/lon with 10 decimals.
- The file is written atomically (temporary file + rename): a failure leaves nothing behind.

Reading (:func:`read_osmag`) accepts both variants, files from this plugin, JOSM (positive ids,
``action=`` attributes) and other osmAG tools (``osmAG:areaType`` spelling), and reports dangling
references and unclosed ways instead of failing on them.
"""
from __future__ import annotations

import math
import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Tuple
from xml.sax.saxutils import quoteattr

import numpy as np

from .errors import InputError
from .io_utils import atomic_write
from .model import PINCH_OPEN, Area, Passage, open_pinched_ring, pinch_indices
from .progress import ensure

AREA_TYPES = ("room", "corridor", "stairs", "elevator", "structure")
VARIANTS = ("semantic", "fix-id")
GENERATOR = "cad2osmag"
_CORE_AREA_KEYS = {"osmAG:type", "osmAG:areatype", "osmAG:areaType", "indoor", "level", "height", "name",
                   "osmAG:parent", "area"}
_CORE_PASSAGE_KEYS = {"osmAG:type", "osmAG:from", "osmAG:to", "level", "name"}


def _fmt_num(v: float) -> str:
    s = f"{float(v):.3f}".rstrip("0").rstrip(".")
    return s or "0"


def generated_name(level: str, kind: str, ident: int) -> str:
    """Stable name for an unnamed object: ``L1-A007`` (area), ``L1-S001`` (structure), ``L1-P012``."""
    return f"L{level}-{kind}{abs(int(ident)):03d}"


# =========================================================================== writing
@dataclass
class FloorLayer:
    """One level of a multi-level file for :func:`write_osmag_levels`: its areas (ids unique across the
    whole file), passages, structure areas (the floor outline), ``level`` (a number as a string) and
    ``height`` (metres)."""

    level: str
    areas: Sequence[Area]
    passages: Sequence[Passage] = ()
    structure_areas: Sequence[Area] = ()
    height: float = 3.2


def check_level(level) -> str:
    """``level`` as the string written to the file; it must be a number (``1``, ``-1``, ``0.5``)."""
    s = str(level).strip()
    if not s:
        raise InputError("LEVEL must not be empty (e.g. '1' or '-1')")
    try:
        v = float(s)
    except ValueError:
        raise InputError(f"level '{s}' is not a number; osmAG levels are numbers such as 1, 0 or -1 "
                         "(give LEVEL, or name the floor file like '*-F3*' / '*_L-1*')") from None
    if not np.isfinite(v):
        raise InputError(f"level '{s}' is not a finite number")
    return s.lstrip("+")


def write_osmag(path: str, areas: Sequence[Area], passages: Sequence[Passage] = (), frame=None,
                level: str = "1", height: float = 3.2, variant: str = "semantic",
                structure_areas: Sequence[Area] = (), crs=None, root: Optional[Tuple[float, float]] = None,
                progress=None) -> dict:
    """Write a one-floor osmAG file; see the module docstring for the format.

    ``areas``/``structure_areas``: :class:`Area` with shapely polygons; ``passages``: :class:`Passage`
    whose ``from_id``/``to_id`` are area ids. Georeference: ``frame`` (a
    :class:`~algorithms.georef.LocalFrame`, geometries in the CAD frame) or ``crs`` (geometries in that
    CRS, e.g. "EPSG:4326"); exactly one. ``root``: (lon, lat) of the root node (default: the frame's
    anchor, or the centre of the data's bounding box).

    Returns stats: ``nodes``, ``areas``, ``structure_areas``, ``passages``, ``shared_nodes`` (nodes used
    by 2+ area ways), ``holes_dropped``, ``vertices_inserted``, ``root`` (lon, lat), ``warnings``.
    Raises InputError (nothing written) for empty/invalid polygons, passages referencing missing areas,
    an unknown variant, a missing georeference.
    """
    level = check_level(level)
    if not areas and not structure_areas:
        raise InputError("nothing to export: no areas")
    return write_osmag_levels(path, [FloorLayer(level, list(areas), list(passages), list(structure_areas),
                                                height)], frame=frame, crs=crs, variant=variant, root=root,
                              progress=progress)


def write_osmag_levels(path: str, floors: Sequence[FloorLayer], frame=None, crs=None, variant: str = "semantic",
                       root: Optional[Tuple[float, float]] = None, top_areas: Sequence[Area] = (),
                       vertical_passages: Sequence[Passage] = (), parents: Optional[Dict[int, int]] = None,
                       progress=None) -> dict:
    """Write one osmAG file holding several levels (a building).

    Each floor's areas share nodes among themselves only (floors above one another never share a
    node). ``top_areas`` are structure areas above the floors (the building outline; their ``tags``
    may carry ``level`` such as ``1;2;3``); a floor's structure area without a parent gets the smallest
    top area containing it as ``osmAG:parent``. ``vertical_passages`` join areas of different floors
    (stairs/lift shafts): a two-node way of their own (``line``, in the frame), tagged with the upper
    floor's ``level`` and ``height`` (the osmAG spec of June 2025). ``parents`` ({area id: parent area
    id}) overrides the parent otherwise found from tags/containment. Area ids must be unique across the
    whole file. Stats as :func:`write_osmag`, plus ``levels`` and ``vertical_passages``.
    """
    import shapely
    from shapely.geometry import MultiPolygon, Polygon

    from .georef import check_lonlat, crs_is_geographic, to_wgs84_points
    from .refine import _Partition

    progress = ensure(progress)
    if variant not in VARIANTS:
        raise InputError(f"unknown osmAG variant {variant!r}; use 'semantic' or 'fix-id'")
    if (frame is None) == (crs is None):
        raise InputError("the areas carry no georeference: give a LocalFrame (anchor, rotation) for CAD-frame "
                         "geometries, or the CRS they are in; georeference the layers first")
    floors = list(floors)
    if not floors:
        raise InputError("nothing to export: no floors")
    levels = []
    for fl in floors:
        fl.level = check_level(fl.level)
        if not (fl.height and float(fl.height) > 0):
            raise InputError(f"HEIGHT must be a positive number of metres, got {fl.height} (level {fl.level})")
        levels.append(fl.level)
    dup_levels = sorted({lv for lv in levels if levels.count(lv) > 1})
    if dup_levels:
        raise InputError(f"levels {dup_levels} are given to more than one floor; every floor needs its own level")
    top_areas = list(top_areas)
    # every area of the file, in way order: top areas, then per floor its structure areas and areas
    all_areas: List[Area] = list(top_areas)
    area_floor: List[int] = [-1] * len(top_areas)  # floor index per area, -1 = top area
    is_struct: List[bool] = [True] * len(top_areas)
    for fi, fl in enumerate(floors):
        for a in fl.structure_areas:
            all_areas.append(a)
            area_floor.append(fi)
            is_struct.append(True)
        for a in fl.areas:
            all_areas.append(a)
            area_floor.append(fi)
            is_struct.append(False)
    if not all_areas:
        raise InputError("nothing to export: no areas")
    warnings: List[str] = []
    # ---- validate geometries and references
    ids = [a.id for a in all_areas]
    if len(set(ids)) != len(ids):
        from collections import Counter

        dup = sorted(i for i, c in Counter(ids).items() if c > 1)
        raise InputError(f"duplicate area ids {dup}; every area (and structure area) needs a unique id")
    empty = [a.id for a in all_areas if a.polygon is None or a.polygon.is_empty]
    if empty:
        raise InputError(f"areas {empty} have empty geometries; remove them or fix the layer")
    polys = []
    for a in all_areas:
        g = a.polygon
        if isinstance(g, MultiPolygon):
            if len(g.geoms) > 1:
                raise InputError(f"area {a.id} is a multipolygon of {len(g.geoms)} parts; an osmAG area is one "
                                 "closed way: split it into separate areas (QGIS 'Multipart to singleparts')")
            g = g.geoms[0]
        if not isinstance(g, Polygon):
            raise InputError(f"area {a.id} is a {g.geom_type}, not a polygon")
        if not g.is_valid:
            raise InputError(f"area {a.id} has an invalid polygon ({shapely.is_valid_reason(g)}); fix it "
                             "(QGIS 'Fix geometries') and export again")
        polys.append(g)
    by_id = {a.id: k for k, a in enumerate(all_areas)}
    bad = []
    for fi, fl in enumerate(floors):
        for p in fl.passages:
            if p.from_id not in by_id or p.to_id not in by_id:
                bad.append(f"{p.id} ({p.from_id}->{p.to_id})")
    bad += [f"{p.id} ({p.from_id}->{p.to_id})" for p in vertical_passages
            if p.from_id not in by_id or p.to_id not in by_id]
    if bad:
        raise InputError(f"passages reference missing areas: {', '.join(bad)}; delete them or add the areas")
    _check_passage_ids(floors, vertical_passages)
    for p in [p for fl in floors for p in fl.passages] + list(vertical_passages):
        if p.line is None or p.line.is_empty or len(p.line.coords) < 2:
            raise InputError(f"passage {p.id} has no line geometry (needs 2 points)")
    # ---- coordinates -> WGS84
    if frame is not None:
        to_ll = frame.to_wgs84
        q = 1e-6
        if root is None:
            root = (frame.anchor_lon, frame.anchor_lat)
    else:
        c = crs
        q = 1e-10 if crs_is_geographic(c) else 1e-6

        def to_ll(x, y):
            return to_wgs84_points(x, y, c)
    # one partition (shared-node table) per floor; top areas and vertical passages get their own nodes
    groups: List[List[int]] = [[k for k in range(len(all_areas)) if area_floor[k] == fi] for fi in range(len(floors))]
    group_passages: List[List[Passage]] = [list(fl.passages) for fl in floors]
    if top_areas:
        groups.insert(0, list(range(len(top_areas))))
        group_passages.insert(0, [])
    if vertical_passages:
        groups.append([])
        group_passages.append(list(vertical_passages))
    V_all, ring_of_area, pend = [], {}, []  # global vertex table, area index -> ring, passage ends
    holes = n_ins = n_pinch = 0
    offset = 0
    for g_areas, g_pass in zip(groups, group_passages):
        pxy = np.array([[p.line.coords[0][:2], p.line.coords[-1][:2]] for p in g_pass],
                       dtype=float).reshape(-1, 2)
        if not g_areas and not len(pxy):
            continue
        if g_areas:
            part = _Partition([polys[k] for k in g_areas], pxy, q)
            n_ins += part.node()
            # metres, or degrees for geometries in a geographic CRS (q 1e-10)
            n_pinch += _open_pinches(part, near=20.0 * q, dist=PINCH_OPEN if q >= 1e-6 else PINCH_OPEN / 111320.0)
            holes += int(part.ring_hole.sum())
            for ri, (f, h) in enumerate(zip(part.ring_face, part.ring_hole)):
                if not h:
                    ring_of_area[g_areas[int(f)]] = part.rings[ri] + offset
            V_all.append(part.V)
            pend.append(part.extra_ids.reshape(-1, 2) + offset)
            offset += len(part.V)
        else:  # vertical passages: two new nodes each
            V_all.append(pxy)
            pend.append(np.arange(len(pxy)).reshape(-1, 2) + offset)
            offset += len(pxy)
    V = np.concatenate(V_all) if V_all else np.zeros((0, 2))
    pe = np.concatenate(pend) if pend else np.zeros((0, 2), np.int64)
    all_passages: List[Passage] = [p for g in group_passages for p in g]
    n_vertical = len(vertical_passages)
    if n_pinch:
        progress.info(f"osmAG: {n_pinch} ring vertices visited twice (a ring touching itself) moved "
                      f"{PINCH_OPEN * 1000:g} mm apart so every area stays one simple closed way")
    if holes:  # by design, so an info line rather than a warning
        progress.info(f"osmAG: {holes} holes (pillars) left out: an osmAG area is one closed way")
    used = np.zeros(len(V), bool)
    for r in ring_of_area.values():
        used[r] = True
    used[pe.reshape(-1)] = True
    lon, lat = to_ll(V[:, 0], V[:, 1])
    lon, lat = np.atleast_1d(np.asarray(lon, float)), np.atleast_1d(np.asarray(lat, float))
    if not (np.all(np.isfinite(lon[used])) and np.all(np.isfinite(lat[used]))):
        raise InputError("some coordinates cannot be converted to WGS84; check the layer CRS / georeference")
    if root is None:
        root = (float((lon[used].min() + lon[used].max()) / 2), float((lat[used].min() + lat[used].max()) / 2))
    check_lonlat(float(root[0]), float(root[1]), what="root node")
    if lat[used].min() <= -90 or lat[used].max() >= 90:
        raise InputError("converted coordinates fall outside valid latitudes; check the georeference")
    progress.step(40, f"osmAG: {int(used.sum())} nodes ({n_ins} inserted to share borders)")
    warnings.extend(_rings_invalid_as_written(all_areas, ring_of_area, lon, lat))
    # ---- node ids, numbered in order of first use (areas in way order, then passages): reproducible
    node_id = np.zeros(len(V), np.int64)
    seq = np.concatenate([ring_of_area[k] for k in range(len(all_areas))] + [pe.reshape(-1)])
    _, first = np.unique(seq, return_index=True)
    order = seq[np.sort(first)]
    node_id[order] = -2 - np.arange(len(order))
    door_nodes = set(pe[:len(all_passages) - n_vertical].reshape(-1).tolist())
    # ---- names, way ids
    multi = len(floors) > 1
    area_level = [floors[area_floor[k]].level if area_floor[k] >= 0 else "" for k in range(len(all_areas))]
    names: List[str] = []
    seen: Dict[str, int] = {}
    for k, a in enumerate(all_areas):
        gen = generated_name(area_level[k] or "B", "S" if is_struct[k] else "A", a.id)
        nm = (a.name or "").strip() or gen
        if nm in seen:
            warnings.append(f"area {a.id}: name '{nm}' already used by area {all_areas[seen[nm]].id}; "
                            f"written as '{nm} [{gen}]'")
            nm = f"{nm} [{gen}]"
        seen[nm] = k
        names.append(nm)
    way_id = {a.id: -1 - k for k, a in enumerate(all_areas)}
    # ---- parents
    parent: Dict[int, int] = {}
    name_to_k = {n: k for k, n in enumerate(names)}
    src_names = {}
    for k, a in enumerate(all_areas):
        if a.name:
            src_names.setdefault(a.name, k)
    for k, a in enumerate(all_areas):
        if parents and a.id in parents and parents[a.id] in by_id and by_id[parents[a.id]] != k:
            parent[k] = by_id[parents[a.id]]
            continue
        explicit = str(a.tags.get("osmAG:parent", "")).strip() if a.tags else ""
        if explicit:
            pk = name_to_k.get(explicit, src_names.get(explicit))
            if pk is None:
                try:
                    pk = by_id.get(int(explicit))
                except ValueError:
                    pk = None
            if pk is not None and pk != k:
                parent[k] = pk
                continue
            warnings.append(f"area {a.id}: parent '{explicit}' is not among the exported areas; parent dropped")
        if area_floor[k] >= 0:  # the smallest structure area of its floor (or a top area) containing it
            cands = [j for j in range(len(all_areas))
                     if is_struct[j] and j != k and (area_floor[j] == area_floor[k] or area_floor[j] < 0)]
            if cands:
                rp = polys[k].representative_point()
                inside = [j for j in cands if polys[j].area > polys[k].area and polys[j].covers(rp)]
                same = [j for j in inside if area_floor[j] == area_floor[k]]
                if same:
                    parent[k] = min(same, key=lambda j: polys[j].area)
                elif is_struct[k] and len(top_areas) == 1:
                    parent[k] = 0  # a floor outline under the building
                elif inside:
                    parent[k] = min(inside, key=lambda j: polys[j].area)
    # ---- passages
    pnames = []
    pname_seen: Dict[str, int] = {}
    for k, p in enumerate(all_passages):
        if k >= len(all_passages) - n_vertical:
            lv = area_level[max(by_id[p.from_id], by_id[p.to_id], key=lambda j: float(area_level[j] or 0))]
        else:
            lv = area_level[by_id[p.from_id]]
        gen = generated_name(lv, "P", p.id)
        nm = (p.name or "").strip() or gen
        if nm in pname_seen and multi:
            nm = f"{nm} [{gen}]"
        pname_seen[nm] = k
        pnames.append(nm)
    for k, p in enumerate(all_passages[:len(all_passages) - n_vertical]):
        for aid in (p.from_id, p.to_id):
            ring = ring_of_area[by_id[aid]]
            for j in range(2):
                if not np.any(ring == pe[k, j]):
                    warnings.append(f"passage {p.id} ({pnames[k]}): end point {j + 1} is not on the border of "
                                    f"area {aid}; its node is not shared with that area")

    def ref(k):
        return names[k] if variant == "semantic" else str(way_id[all_areas[k].id])

    # ---- XML
    lines: List[str] = ['<?xml version="1.0" encoding="UTF-8"?>',
                        f'<osm version="0.6" generator="{GENERATOR}">']
    new = 'action="modify" visible="true"'  # how JOSM writes new objects; older osmAG parsers need both
    # the root node carries the frame's origin as the osmAG authors' parser wants it (it aborts without
    # root/alt/qx/qy/qz): the local frame is x east, y north, so no rotation
    lines.append(f'  <node id="-1" {new} lat="{root[1]:.10f}" lon="{root[0]:.10f}" root="true" alt="0" '
                 'x="0" y="0" z="0" qx="0" qy="0" qz="0">')
    lines.append('    <tag k="name" v="root"/>')
    lines.append('  </node>')
    for i in order.tolist():
        if i in door_nodes:
            lines.append(f'  <node id="{node_id[i]}" {new} lat="{lat[i]:.10f}" lon="{lon[i]:.10f}">')
            lines.append('    <tag k="door" v="yes"/>')
            lines.append('  </node>')
        else:
            lines.append(f'  <node id="{node_id[i]}" {new} lat="{lat[i]:.10f}" lon="{lon[i]:.10f}"/>')

    def tag(k, v):
        return f"    <tag k={quoteattr(str(k))} v={quoteattr(str(v))}/>"

    shared = np.zeros(len(V), np.int64)
    for k, a in enumerate(all_areas):
        ring = ring_of_area[k]
        shared[np.unique(ring)] += 1
        refs = np.append(ring, ring[0])
        lines.append(f'  <way id="{way_id[a.id]}" {new}>')
        lines.extend(f'    <nd ref="{node_id[v]}"/>' for v in refs.tolist())
        atype = a.type if a.type in AREA_TYPES else "room"
        if a.type not in AREA_TYPES:
            warnings.append(f"area {a.id}: unknown type '{a.type}' written as room")
        if is_struct[k]:
            atype = "structure"
        atags = a.tags or {}
        lines.append(tag("osmAG:type", "area"))
        lines.append(tag("osmAG:areatype", atype))
        lines.append(tag("osmAG:areaType", atype))  # the spelling of the published osmAG parsers
        indoor = str(atags.get("indoor") or "").strip() or {"corridor": "corridor", "structure": "area"}.get(atype, "room")
        lines.append(tag("indoor", indoor))
        if area_floor[k] >= 0:
            fl = floors[area_floor[k]]
            lines.append(tag("level", fl.level))
            lines.append(tag("height", _fmt_num(float(fl.height))))
        elif atags.get("level"):
            lines.append(tag("level", atags["level"]))
        lines.append(tag("name", names[k]))
        if k in parent:
            lines.append(tag("osmAG:parent", ref(parent[k])))
        lines.append(tag("area", "yes"))
        if (a.ref or "").strip() and not atags.get("ref"):
            lines.append(tag("ref", a.ref.strip()))
        for kk, vv in sorted(atags.items()):
            if kk not in _CORE_AREA_KEYS and vv not in (None, ""):
                lines.append(tag(kk, vv))
        lines.append("  </way>")
    wid = -1 - len(all_areas)
    for k, p in enumerate(all_passages):
        a0, a1 = int(pe[k, 0]), int(pe[k, 1])
        kf, kt = by_id[p.from_id], by_id[p.to_id]
        vertical = k >= len(all_passages) - n_vertical
        lines.append(f'  <way id="{wid - k}" {new}>')
        lines.append(f'    <nd ref="{node_id[a0]}"/>')
        lines.append(f'    <nd ref="{node_id[a1]}"/>')
        lines.append(tag("osmAG:type", "passage"))
        lines.append(tag("osmAG:from", ref(kf)))
        lines.append(tag("osmAG:to", ref(kt)))
        if vertical:  # the upper floor's level and height
            up = max((kf, kt), key=lambda j: float(area_level[j] or 0))
            lines.append(tag("level", area_level[up]))
            lines.append(tag("height", _fmt_num(float(floors[area_floor[up]].height))))
        else:
            lines.append(tag("level", area_level[kf]))
        lines.append(tag("name", pnames[k]))
        for kk, vv in sorted((p.tags or {}).items()):
            if kk not in _CORE_PASSAGE_KEYS and kk != "height" and vv not in (None, ""):
                lines.append(tag(kk, vv))
        lines.append("  </way>")
    lines.append("</osm>")
    progress.step(80)
    with atomic_write(path) as fh:
        fh.write("\n".join(lines) + "\n")
    for w in warnings:
        progress.warning(w)
    n_struct = sum(is_struct)
    stats = {"path": os.path.abspath(path), "nodes": int(len(order)) + 1, "areas": len(all_areas) - n_struct,
             "structure_areas": n_struct, "passages": len(all_passages), "vertical_passages": n_vertical,
             "shared_nodes": int((shared >= 2).sum()), "holes_dropped": holes, "vertices_inserted": n_ins,
             "root": (float(root[0]), float(root[1])), "variant": variant, "levels": levels,
             "way_ids": {a.id: way_id[a.id] for a in all_areas}, "names": {a.id: names[k] for k, a in enumerate(all_areas)},
             "warnings": warnings}
    progress.step(100, f"osmAG: wrote {len(all_areas)} areas ({n_struct} structure), {len(all_passages)} passages"
                       f"{f' ({n_vertical} vertical)' if n_vertical else ''}, "
                       f"{stats['nodes']} nodes ({stats['shared_nodes']} shared) to {path}")
    return stats


def _check_passage_ids(floors, vertical_passages) -> None:
    """Passage ids must be unique on a floor (and among the vertical passages): an unnamed passage is written
    as ``L<level>-P<id>``, so two with one id would be two passages of one name. A feature copied in QGIS keeps
    its id: the usual cause."""
    from collections import Counter

    for what, group in [(f"level {fl.level}", fl.passages) for fl in floors] + [("vertical", vertical_passages)]:
        dup = sorted(i for i, c in Counter(p.id for p in group).items() if c > 1)
        if dup:
            raise InputError(f"duplicate passage ids {dup} ({what}); every passage needs a unique id (a feature "
                             "copied in QGIS keeps its id: give the copy a new one)")


def _open_pinches(part, near: float = 0.0, dist: float = PINCH_OPEN) -> int:
    """Rings of ``part`` (a refine._Partition after ``node()``) that visit one node twice: the area's
    polygon had a neck or a zero-width finger narrower than the shared-node precision, so two of its
    vertices became one node (or a vertex was inserted into its own ring's edge). Such a way reads back as
    a self-touching ring, which a reader repairs by making the loop a hole or by cutting the finger off;
    passages on it then leave the area. Every repeated visit after the first becomes a new node moved
    ``model.PINCH_OPEN`` into (or out of) its corner, so the ring is simple; the first visit keeps the
    shared node. ``near`` (> 0): a vertex closer than that to an earlier, non-adjacent vertex of its ring
    counts as a second visit too (they would meet once rounded to the precision written). ``dist``: the
    opening in the partition's units. Returns the number of nodes added."""
    from scipy.spatial import cKDTree

    added = 0
    for ri in range(len(part.rings)):
        if part.ring_hole[ri]:
            continue
        ring = part.rings[ri]
        reps = set(pinch_indices(ring.tolist()))
        if near > 0 and len(ring) > 3:
            n = len(ring)
            for i, j in cKDTree(part.V[ring]).query_pairs(near):
                i, j = min(i, j), max(i, j)
                if j - i not in (1, n - 1) and ring[i] != ring[j]:
                    reps.add(j)
        if not reps:
            continue
        reps = sorted(reps)
        new = open_pinched_ring(part.V[ring], reps, dist)
        if new is None:
            continue
        ids = np.arange(len(part.V), len(part.V) + len(reps))
        part.V = np.concatenate([part.V, new[reps]])
        ring = ring.copy()
        ring[reps] = ids
        part.rings[ri] = ring
        added += len(reps)
    return added


def _rings_invalid_as_written(all_areas, ring_of_area, lon, lat) -> List[str]:
    """Warnings for area ways that are no valid polygon at the precision written (lon/lat at 10 decimals):
    parts closer than that cross or touch once rounded. A reader repairs a ring that only touches itself
    as one ring (``model.open_ring_pinches``); a crossing it can only repair with ``buffer(0)``."""
    import shapely

    rlon, rlat = np.round(lon, 10), np.round(lat, 10)
    ks = [k for k in range(len(all_areas)) if k in ring_of_area and len(ring_of_area[k]) >= 3]
    if not ks:
        return []
    closed = [np.append(ring_of_area[k], ring_of_area[k][0]) for k in ks]
    idx = np.concatenate(closed)
    try:
        rings = shapely.linearrings(np.c_[rlon[idx], rlat[idx]],
                                    indices=np.repeat(np.arange(len(ks)), [len(c) for c in closed]))
        ok = shapely.is_valid(shapely.polygons(rings))
    except Exception:  # a degenerate ring: the reader reports it
        return []
    return [f"area {all_areas[k].id}: its way is no valid polygon at the written precision "
            f"({shapely.is_valid_reason(shapely.polygons(rings[j]))}); parts of it closer than ~0.01 mm"
            for j, k in enumerate(ks) if not ok[j]]


# =========================================================================== reading
def get_tag(tags: Dict[str, str], key: str, default=None):
    """``tags[key]``, or the value of a key that differs only in case (osmAG:areaType vs areatype)."""
    if key in tags:
        return tags[key]
    low = key.lower()
    for k, v in tags.items():
        if k.lower() == low:
            return v
    return default


def read_osmag(path: str, progress=None):
    """Read an osmAG file (either variant).

    Returns ``(areas, passages, root, report)``:
    - ``areas``: :class:`Area` per closed way tagged ``osmAG:type=area``; ``id`` = way id, polygon in
      WGS84 lon/lat, ``type`` = osmAG:areatype, ``name``, ``tags`` = all the way's tags.
    - ``passages``: :class:`Passage` per way tagged ``osmAG:type=passage`` whose ends resolve to areas;
      ``from_id``/``to_id`` = area way ids, ``line`` = its first and last node in lon/lat.
    - ``root``: (lon, lat) of the ``name=root`` node, or None.
    - ``report``: ``variant`` (semantic | fix-id | mixed | none), ``nodes``, ``ways``, ``unclosed``
      (way ids), ``dangling_nodes`` ({way id: [missing node ids]}), ``dangling_refs`` (list of
      (way id, key, value) that name no area), ``warnings`` (readable lines), ``parents`` ({area id:
      parent area id}), ``duplicate_ids`` ({"node": [...], "way": [...]}: ids defined more than once;
      the first definition is used).
    Raises InputError if the file is missing, not OSM XML, or holds no osmAG area.
    """
    from shapely.geometry import LineString, Polygon

    progress = ensure(progress)
    if not os.path.isfile(path):
        raise InputError(f"osmAG file '{path}' does not exist")
    try:
        tree = ET.parse(path)
    except ET.ParseError as exc:
        raise InputError(f"'{os.path.basename(path)}' is not an OSM XML file ({exc})") from exc
    except OSError as exc:
        raise InputError(f"cannot read '{path}': {exc}") from exc
    osm = tree.getroot()
    if osm.tag != "osm":
        raise InputError(f"'{os.path.basename(path)}' is XML but not OSM (root element <{osm.tag}>, expected <osm>)")
    nodes: Dict[int, Tuple[float, float]] = {}
    node_tags: Dict[int, Dict[str, str]] = {}
    ways: List[Tuple[int, List[int], Dict[str, str]]] = []
    warnings: List[str] = []
    duplicates: Dict[str, List[int]] = {"node": [], "way": []}
    way_ids = set()
    for el in osm:
        if el.get("action") == "delete":
            continue
        if el.tag == "node":
            try:
                nid = int(el.get("id"))
                pos = (float(el.get("lon")), float(el.get("lat")))
            except (TypeError, ValueError):
                warnings.append(f"node {el.get('id')!r} has no valid id/lat/lon; ignored")
                continue
            if not (math.isfinite(pos[0]) and math.isfinite(pos[1]) and abs(pos[1]) <= 90 and abs(pos[0]) <= 180):
                warnings.append(f"node {nid} has an invalid position (lat {el.get('lat')}, lon {el.get('lon')}); "
                                "ignored")
                continue
            if nid in nodes:  # a broken merge or a hand edit: the first definition wins, and it is reported
                duplicates["node"].append(nid)
                warnings.append(f"node {nid} is defined twice; the second definition (lat {pos[1]}, lon {pos[0]}) "
                                "is ignored: give every node its own id")
                continue
            nodes[nid] = pos
            t = {c.get("k"): c.get("v") for c in el if c.tag == "tag"}
            if t:
                node_tags[nid] = t
        elif el.tag == "way":
            try:
                wid = int(el.get("id"))
            except (TypeError, ValueError):
                warnings.append(f"way {el.get('id')!r} has no valid id; ignored")
                continue
            if wid in way_ids:
                duplicates["way"].append(wid)
                warnings.append(f"way {wid} is defined twice; the second definition is ignored: give every way "
                                "its own id")
                continue
            way_ids.add(wid)
            try:
                refs = [int(c.get("ref")) for c in el if c.tag == "nd"]
            except (TypeError, ValueError):
                warnings.append(f"way {wid} has a node reference that is not a number; ignored")
                continue
            t = {c.get("k"): c.get("v") for c in el if c.tag == "tag"}
            ways.append((wid, refs, t))
    progress.step(40)
    root = None
    roots = [nid for nid, t in node_tags.items() if t.get("name") == "root"]
    if roots:
        root = nodes[roots[0]]
        if len(roots) > 1:
            warnings.append(f"{len(roots)} root nodes ({roots}); used node {roots[0]}")
    else:
        warnings.append("no root node (name=root)")
    area_ways = [w for w in ways if str(get_tag(w[2], "osmAG:type", "")).lower() == "area"]
    passage_ways = [w for w in ways if str(get_tag(w[2], "osmAG:type", "")).lower() == "passage"]
    if not area_ways:
        raise InputError(f"'{os.path.basename(path)}' is not an osmAG file: none of its {len(ways)} ways is tagged "
                         "osmAG:type=area (plain OSM data? export it with osmAG tags first)")
    unclosed: List[int] = []
    dangling_nodes: Dict[int, List[int]] = {}
    areas: List[Area] = []
    for wid, refs, t in area_ways:
        missing = [r for r in refs if r not in nodes]
        if missing:
            dangling_nodes[wid] = missing
            warnings.append(f"area way {wid}: {len(missing)} missing nodes ({missing[:5]}); area skipped")
            continue
        if len(refs) < 4 or refs[0] != refs[-1]:
            unclosed.append(wid)
            warnings.append(f"area way {wid} is not closed (first node {refs[0] if refs else '-'} != last node "
                            f"{refs[-1] if refs else '-'}); area skipped")
            continue
        poly = Polygon([nodes[r] for r in refs])
        if not poly.is_valid:
            warnings.append(f"area way {wid} is not a valid polygon (self-intersecting?)")
        atype = str(get_tag(t, "osmAG:areatype", "room") or "room")
        other = t.get("osmAG:areaType")
        if other is not None and "osmAG:areatype" in t and other != t["osmAG:areatype"]:
            warnings.append(f"area way {wid} has osmAG:areatype={t['osmAG:areatype']} but osmAG:areaType={other} "
                            f"(one was edited); using {atype}: make both the same in your editor")
        areas.append(Area(id=wid, polygon=poly, type=atype, name=t.get("name", ""), tags=dict(t)))
    by_name: Dict[str, List[int]] = {}
    for a in areas:
        if a.name:
            by_name.setdefault(a.name, []).append(a.id)
    ids = {a.id for a in areas}
    dangling_refs: List[Tuple[int, str, str]] = []
    kinds = {"name": 0, "id": 0}

    def resolve(wid, key, v):
        if v is None or v == "":
            dangling_refs.append((wid, key, ""))
            return None
        v = str(v).strip()
        if v in by_name:
            if len(by_name[v]) > 1:
                warnings.append(f"way {wid}: {key}='{v}' matches {len(by_name[v])} areas; used way {by_name[v][0]}")
            kinds["name"] += 1
            return by_name[v][0]
        try:
            iv = int(v)
        except ValueError:
            iv = None
        if iv is not None and iv in ids:
            kinds["id"] += 1
            return iv
        dangling_refs.append((wid, key, v))
        return None

    parents: Dict[int, int] = {}
    for a in areas:
        pv = get_tag(a.tags, "osmAG:parent")
        if pv not in (None, ""):
            pid = resolve(a.id, "osmAG:parent", pv)
            if pid is not None:
                parents[a.id] = pid
            else:
                warnings.append(f"area way {a.id}: osmAG:parent='{pv}' names no area")
    passages: List[Passage] = []
    for wid, refs, t in passage_ways:
        missing = [r for r in refs if r not in nodes]
        if missing:
            dangling_nodes[wid] = missing
            warnings.append(f"passage way {wid}: missing nodes {missing[:5]}; passage skipped")
            continue
        if len(refs) < 2:
            warnings.append(f"passage way {wid} has {len(refs)} node(s); passage skipped")
            continue
        if len(refs) > 2:
            warnings.append(f"passage way {wid} has {len(refs)} nodes; used its first and last")
        f = resolve(wid, "osmAG:from", get_tag(t, "osmAG:from"))
        to = resolve(wid, "osmAG:to", get_tag(t, "osmAG:to"))
        if f is None or to is None:
            warnings.append(f"passage way {wid}: osmAG:from='{get_tag(t, 'osmAG:from')}' / "
                            f"osmAG:to='{get_tag(t, 'osmAG:to')}' "
                            "does not name an area of this file; passage skipped")
            continue
        passages.append(Passage(id=wid, from_id=f, to_id=to, line=LineString([nodes[refs[0]], nodes[refs[-1]]]),
                                name=t.get("name", ""), tags=dict(t)))
    variant = ("none" if not (kinds["name"] or kinds["id"]) else "semantic" if not kinds["id"]
               else "fix-id" if not kinds["name"] else "mixed")
    report = {"variant": variant, "nodes": len(nodes), "ways": len(ways), "areas": len(areas),
              "passages": len(passages), "unclosed": unclosed, "dangling_nodes": dangling_nodes,
              "dangling_refs": dangling_refs, "parents": parents, "warnings": warnings, "root": root,
              "duplicate_ids": duplicates}
    for w in warnings:
        progress.warning(w)
    progress.step(100, f"osmAG: read {len(areas)} areas, {len(passages)} passages ({variant} variant), "
                       f"{len(unclosed)} unclosed ways, {len(dangling_nodes) + len(dangling_refs)} dangling references")
    return areas, passages, root, report


def frame_from_root(root: Tuple[float, float]):
    """The osmAG local metric frame (x east, y north, metres) centred on the root node."""
    from .georef import LocalFrame

    if root is None:
        raise InputError("the osmAG file has no root node (name=root); its local frame is undefined")
    return LocalFrame(root[0], root[1])


def to_frame(areas: Sequence[Area], passages: Sequence[Passage], frame) -> Tuple[List[Area], List[Passage]]:
    """Copies of lon/lat areas and passages (as read) converted into ``frame``'s CAD/local metres."""
    import copy

    geoms = np.empty(len(areas) + len(passages), dtype=object)
    geoms[:] = [a.polygon for a in areas] + [p.line for p in passages]
    moved = frame.geometry_from_crs(geoms) if len(geoms) else geoms  # one projection call for everything
    out_a, out_p = [], []
    for k, a in enumerate(areas):
        b = copy.copy(a)
        b.polygon = moved[k]
        out_a.append(b)
    for k, p in enumerate(passages):
        b = copy.copy(p)
        b.line = moved[len(areas) + k]
        out_p.append(b)
    return out_a, out_p


__all__ = ["write_osmag", "write_osmag_levels", "FloorLayer", "check_level", "read_osmag", "frame_from_root", "to_frame", "generated_name", "AREA_TYPES", "VARIANTS"]
