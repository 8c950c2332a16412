"""Classifying drawing entities by what the drawing says: door swings (arc + leaf), door and furniture
blocks, pattern hatches."""
from __future__ import annotations

import math
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

import numpy as np

from .layer_rules import meaningful_part
from .model import CadGeometry, DoorHint


DOOR_RADIUS = (0.5, 1.6)  # metres: leaf width of a swing door
DOOR_SWEEP = (60.0, 100.0)  # degrees: a swing arc is (about) a quarter circle, often drawn a bit short
WIDE_SWEEP = 185.0  # degrees: a door drawn opening flat against the wall (half circle), accepted with its leaf only


def _circle_from_3(p0, p1, p2):
    """(cx, cy, r) of the circle through three points, None when they are (nearly) on a line. Where the
    squares of the coordinates lose the circle (georeferenced drawings: UTM coordinates of 10^6 m, whose
    squares cancel to nothing in float64) it is computed again relative to ``p0``."""
    circ = _circle_at(p0, p1, p2)
    if circ is not None:
        ux, uy, r = circ
        tol = 1e-6 * max(1.0, r)
        if abs(math.hypot(p1[0] - ux, p1[1] - uy) - r) <= tol and abs(math.hypot(p2[0] - ux, p2[1] - uy) - r) <= tol:
            return circ
    ox, oy = float(p0[0]), float(p0[1])
    circ = _circle_at((0.0, 0.0), (p1[0] - ox, p1[1] - oy), (p2[0] - ox, p2[1] - oy))
    return None if circ is None else (circ[0] + ox, circ[1] + oy, circ[2])


def _circle_at(p0, p1, p2):
    ax, ay = p0
    bx, by = p1
    cx, cy = p2
    d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if abs(d) < 1e-12:
        return None
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return ux, uy, math.hypot(ax - ux, ay - uy)


def find_door_swings(geoms: Sequence[CadGeometry]) -> List[int]:
    """Indices of door swing arcs (quarter arcs of 0.5-1.6 m radius) and of the door leaves hinged at
    their centre (a line or thin rectangle from the centre to an end of the arc). On wall layers an arc
    counts as a swing only together with its leaf: a rounded wall corner is a wall."""
    return _swings(geoms, False)[0]


# ------------------------------------------------------------------------------------------ door hints
def door_swings(geoms: Sequence[CadGeometry], candidates: Optional[Sequence[int]] = None,
                leaf_required: bool = False) -> Tuple[List[int], List[DoorHint]]:
    """Door swings among ``geoms`` (or only among ``candidates``): the indices to leave out (arcs and
    leaves, as ``find_door_swings``) and one DoorHint per swing with its leaf: the doorway from the hinge
    (arc centre) to the arc end where the closed leaf lies (the end the open leaf does not reach).
    The two halves of a double door become one hint from hinge to hinge."""
    sub_idx = list(range(len(geoms))) if candidates is None else list(candidates)
    sub = [geoms[i] for i in sub_idx]
    drop_local, pairs = _swings(sub, leaf_required)
    hints = []
    for (cx, cy, closed_end) in pairs:
        hints.append(DoorHint(float(cx), float(cy), float(closed_end[0]), float(closed_end[1]), "swing"))
    return sorted(sub_idx[i] for i in drop_local), merge_double_doors(hints)


def merge_double_doors(hints: List[DoorHint], tol: float = 0.12) -> List[DoorHint]:
    """Two hints whose closed-leaf ends meet and that point in opposite directions are one double door."""
    used = set()
    out = []
    for i, a in enumerate(hints):
        if i in used:
            continue
        for j in range(i + 1, len(hints)):
            if j in used:
                continue
            b = hints[j]
            if math.hypot(a.x1 - b.x1, a.y1 - b.y1) <= tol:
                ua = np.array((a.x1 - a.x0, a.y1 - a.y0))
                ub = np.array((b.x1 - b.x0, b.y1 - b.y0))
                if np.dot(ua, ub) < -0.9 * np.linalg.norm(ua) * np.linalg.norm(ub):
                    used.update((i, j))
                    out.append(DoorHint(a.x0, a.y0, b.x0, b.y0, a.source))
                    break
        else:
            out.append(a)
            continue
    return out


def _swings(geoms: Sequence[CadGeometry], leaf_required: bool):
    """Core of find_door_swings: (indices to drop, [(cx, cy, closed-leaf end)] per arc with a leaf)."""
    arcs = []  # (index, cx, cy, r, end points)
    wide = set()  # positions in ``arcs`` of arcs sweeping more than DOOR_SWEEP (up to WIDE_SWEEP)
    combined = {}  # index -> (cx, cy, closed-leaf end): leaf and arc drawn as one polyline
    for i, g in enumerate(geoms):
        if g.entity not in ("ARC", "LWPOLYLINE", "POLYLINE") or g.kind == "column" or g.closed or len(g.coords) < 5:
            continue
        c = g.coords
        if g.entity != "ARC":
            one = _leaf_and_arc(c)
            if one is not None:
                combined[i] = one
                continue
        circ = _circle_from_3(c[0], c[len(c) // 2], c[-1])
        if circ is None:
            continue
        cx, cy, r = circ
        if not (DOOR_RADIUS[0] <= r <= DOOR_RADIUS[1]):
            continue
        if np.max(np.abs(np.hypot(c[:, 0] - cx, c[:, 1] - cy) - r)) > 0.02:
            continue
        a = np.unwrap(np.arctan2(c[:, 1] - cy, c[:, 0] - cx))
        sweep = abs(math.degrees(a[-1] - a[0]))
        if DOOR_SWEEP[0] <= sweep <= DOOR_SWEEP[1]:
            arcs.append((i, cx, cy, r, c[0], c[-1]))
        elif DOOR_SWEEP[1] < sweep <= WIDE_SWEEP:
            wide.add(len(arcs))  # a door opening up to 180 degrees (flat against the wall): only with its leaf
            arcs.append((i, cx, cy, r, c[0], c[-1]))
    if not arcs:
        return sorted(combined), list(combined.values())
    from scipy.spatial import cKDTree

    centres = np.array([(a[1], a[2]) for a in arcs])
    tree = cKDTree(centres)
    arc_set = {a[0] for a in arcs}
    with_leaf = {}
    drop = set()
    # leaves: short lines / thin rectangles with a vertex at an arc centre (vectorised prefilter)
    short = [i for i, g in enumerate(geoms) if 2 <= len(g.coords) <= 5 and i not in arc_set
             and g.kind != "column" and not g.filled]
    if short:
        verts = np.concatenate([geoms[i].coords for i in short])
        owner = np.repeat(np.asarray(short), [len(geoms[i].coords) for i in short])
        fin = np.isfinite(verts).all(axis=1)
        dist, _ = tree.query(np.where(fin[:, None], verts, 1e18), distance_upper_bound=0.16)
        near = sorted(set(owner[np.isfinite(dist)].tolist()))
    else:
        near = []
    for i in near:
        g = geoms[i]
        c = g.coords
        if not np.isfinite(c).all():
            continue
        for k in set(j for lst in tree.query_ball_point(c, 0.16) for j in lst):
            ai, cx, cy, r, e0, e1 = arcs[k]
            d = np.hypot(c[:, 0] - cx, c[:, 1] - cy)
            if d.min() > 0.1 * r or not (0.85 * r <= d.max() <= 1.15 * r):
                continue
            far = c[int(np.argmax(d))]
            d0, d1 = math.hypot(*(far - e0)), math.hypot(*(far - e1))
            if min(d0, d1) <= 0.15 * r:
                drop.add(i)
                with_leaf[ai] = (cx, cy, e1 if d0 <= d1 else e0)
                break
    hints = list(with_leaf.values())
    # swings drawn without a leaf: the hinge is at a wall end (a jamb) and so is the arc end where the
    # closed leaf lies; the open end stands in the room. Such arcs are doors with a hint.
    lone = [a for k, a in enumerate(arcs) if a[0] not in with_leaf and k not in wide]
    if lone:
        ends = _end_points([g.coords for i, g in enumerate(geoms) if i not in arc_set and len(g.coords) >= 2])
        if len(ends):
            etree = cKDTree(ends)
            for ai, cx, cy, r, e0, e1 in lone:
                tol = 0.1 * r
                if not etree.query_ball_point((cx, cy), tol):
                    continue
                n0, n1 = bool(etree.query_ball_point(e0, tol)), bool(etree.query_ball_point(e1, tol))
                if n0 != n1:
                    hints.append((cx, cy, e0 if n0 else e1))
                    with_leaf[ai] = hints[-1]
        on_wall = [a for a in lone if a[0] not in with_leaf and geoms[a[0]].kind != "wall"]
        for ai, closed_end in _swings_on_walls(geoms, arc_set, on_wall):
            a = next(x for x in on_wall if x[0] == ai)
            hints.append((a[1], a[2], closed_end))
            with_leaf[ai] = hints[-1]
    wide_idx = {arcs[k][0] for k in wide}
    drop |= {i for i in arc_set if i in with_leaf
             or (geoms[i].kind != "wall" and not leaf_required and i not in wide_idx)}
    drop |= set(combined)
    return sorted(drop), hints + list(combined.values())


ON_WALL_ANGLE = 20.0  # degrees: the closed leaf (hinge -> closed end) of a swing on a wall runs along the wall


def _swings_on_walls(geoms: Sequence[CadGeometry], arc_set, lone) -> List[Tuple[int, np.ndarray]]:
    """Swings drawn without a leaf on a wall drawn straight through the doorway (a facade drawn as two long
    lines, the door only a quarter arc beside it): the hinge (arc centre) and the closed end lie on the
    wall's lines (within 0.1 r; the line runs on 0.1 m beyond both), the hinge -> closed end chord runs
    along the wall (within ON_WALL_ANGLE), the open end stands off the wall in the room (at least 0.6 r
    from the line), and the arc is drawn on another layer than that wall (a door symbol on its own layer; an
    arc on the wall's own layer may belong to the wall drawing). Only arcs that are no walls themselves
    (``lone``: (index, cx, cy, r, e0, e1)). Returns (arc index, closed end) per door."""
    if not lone:
        return []
    import shapely
    from shapely import STRtree

    others = [g for i, g in enumerate(geoms) if i not in arc_set and len(g.coords) >= 2
              and g.kind not in ("column", "boundary", AUX_KIND)]
    segs, sown = _segments_many([g.coords for g in others], [g.closed for g in others])
    if not len(segs):
        return []
    d = segs[:, 1] - segs[:, 0]
    seg_len = np.hypot(d[:, 0], d[:, 1])
    ok = seg_len >= 0.5
    segs, d, seg_len = segs[ok], d[ok] / np.maximum(seg_len[ok, None], 1e-12), seg_len[ok]
    seg_layer = [others[i].layer for i in sown[ok]]
    if not len(segs):
        return []
    tree = STRtree(shapely.linestrings(segs))
    cos_max = math.cos(math.radians(ON_WALL_ANGLE))
    out = []
    for ai, cx, cy, r, e0, e1 in lone:
        hinge = np.array((cx, cy))
        found = None
        for closed, opened in ((e0, e1), (e1, e0)):
            chord = closed - hinge
            lc = float(np.hypot(*chord))
            if lc <= 0:
                continue
            for k in tree.query(shapely.points(hinge), predicate="dwithin", distance=0.1 * r):
                if seg_layer[k] == geoms[ai].layer:
                    continue  # on the wall's own layer it may be part of the wall drawing
                a, u = segs[k, 0], d[k]
                if abs(float(chord @ u)) < cos_max * lc:
                    continue  # the closed leaf crosses this line: no wall it lies along
                t = float((hinge - a) @ u)
                if not (0.1 < t < seg_len[k] - 0.1):
                    continue  # the hinge at (or near) the line's end: the wall-end rule's case
                nrm = np.array((-u[1], u[0]))
                if abs(float((closed - a) @ nrm)) > 0.1 * r + 0.2:  # on this line or on the wall's other face
                    continue
                tc = float((closed - a) @ u)
                if not (0.1 < tc < seg_len[k] - 0.1):
                    continue  # the wall runs on beyond the closed end too (a short edge is no wall drawn through)
                if abs(float((opened - a) @ nrm)) < 0.6 * r:
                    continue  # the open end must stand off the wall
                found = closed
                break
            if found is not None:
                break
        if found is not None:
            out.append((ai, found))
    return out


def _end_points(coords: Sequence[np.ndarray]) -> np.ndarray:
    """(2k, 2) first and last vertex of each array (>= 2 rows) whose two ends are finite, in order."""
    if not coords:
        return np.zeros((0, 2))
    first = np.array([c[0] for c in coords], dtype=np.float64)
    last = np.array([c[-1] for c in coords], dtype=np.float64)
    ok = np.isfinite(first).all(axis=1) & np.isfinite(last).all(axis=1)
    return np.stack([first[ok], last[ok]], axis=1).reshape(-1, 2)


def _leaf_and_arc(c: np.ndarray):
    """A door swing drawn as one open polyline (a common PLINE habit): the hinge, the open leaf's end, then
    the arc around the hinge to the closed leaf's end (or the same backwards). Returns (cx, cy, closed
    end) or None. The leaf is as long as the arc's radius (0.5-1.6 m) and the arc sweeps 60-100 degrees."""
    if not np.isfinite(c).all():
        return None
    for hinge, rest in ((c[0], c[1:]), (c[-1], c[-2::-1])):
        if len(rest) < 4:
            continue
        d = np.hypot(rest[:, 0] - hinge[0], rest[:, 1] - hinge[1])
        r = float(d[0])
        if not (DOOR_RADIUS[0] <= r <= DOOR_RADIUS[1]) or np.max(np.abs(d - r)) > 0.03 * r:
            continue
        a = np.unwrap(np.arctan2(rest[:, 1] - hinge[1], rest[:, 0] - hinge[0]))
        step = np.diff(a)
        if not (np.all(step > 0) or np.all(step < 0)):
            continue
        if DOOR_SWEEP[0] <= abs(math.degrees(a[-1] - a[0])) <= DOOR_SWEEP[1]:
            return float(hinge[0]), float(hinge[1]), rest[-1].copy()
    return None


# ------------------------------------------------------------------------------------------ spaghetti
HATCH_THICK = 0.8  # metres: a pattern hatch region thicker than this (2 * area / perimeter) is a floor finish
FURNITURE_MAX = 2.5  # metres: the larger side of a free-standing closed outline taken for furniture
FURNITURE_MIN = 0.35  # metres: its smaller side (thinner closed outlines are wall pieces)
TOUCH = 0.05  # metres


def _thickness(coords: np.ndarray) -> float:
    c = coords[np.isfinite(coords).all(axis=1)]
    if len(c) < 3:
        return 0.0
    x, y = c[:, 0], c[:, 1]
    area = 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
    per = float(np.hypot(*(np.roll(c, -1, axis=0) - c).T).sum())
    return 2.0 * area / per if per > 0 else 0.0


AUX_KIND = "swing?"  # CadGeometry.kind of an arc from a layer no rule names: looked at as a door swing only


def swing_candidates(pieces, infos, scale: float) -> List[CadGeometry]:
    """Arcs (ARC, or open polylines of 5+ vertices) on layers that no rule names ("no keyword": e.g. 'fine
    projection lines'), as auxiliary geometries (kind ``AUX_KIND``, metres). Drawings put door swings on such
    layers while the leaves sit on a door or window layer; ``classify_entities`` uses them to find swings and
    never keeps them."""
    out = []
    for i, lay in enumerate(pieces.layer):
        info = infos.get(lay)
        if info is None or info.kind is not None or info.rule != "no keyword":
            continue
        if pieces.etype[i] not in ("ARC", "LWPOLYLINE", "POLYLINE") or pieces.closed[i] or pieces.filled[i]:
            continue
        c = pieces.coords[i]
        if len(c) < 5 or not np.isfinite(c).all():
            continue
        span = (c.max(axis=0) - c.min(axis=0)) * scale
        if span.max() > 2.0 * DOOR_RADIUS[1] or span.max() < 0.5 * DOOR_RADIUS[0]:
            continue
        out.append(CadGeometry(layer=lay, kind=AUX_KIND, coords=c * scale, entity=pieces.etype[i]))
    return out


# ------------------------------------------------------------------------------------------ boundary evidence
# layer names of projection / overhead / hidden lines (what lies above or beyond the cut: canopies, the edge of
# a corridor open on one side, a portico)
PROJECTION_LAYER_WORDS = ("proiez", "projection", "projektion", "proyecc", "overhead", "ovhd", "hidden", "隐藏",
                          "虚线", "投影", "uberkopf", "überkopf", "au-dessus", "sopra")
# grid axes are drawn dash-dot (CENTER) through the whole building: never boundary evidence
AXIS_LAYER_WORDS = ("grid", "axis", "axes", "achs", "asse", "eje", "轴", "оси", "raster")
BOUNDARY_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE", "ARC", "SPLINE", "ELLIPSE")
BOUNDARY_MIN_LEN = 1.0  # metres: shorter pieces (hatch dashes, symbols) say nothing about a boundary


def _boundary_layer(info) -> bool:
    """A layer whose lines may be boundary evidence: dropped by the rules for no keyword, or for a hidden /
    projection keyword; never a text, dimension, furniture, axis or frame layer."""
    if info is None or info.kind is not None:
        return False
    low = meaningful_part(info.name).lower()
    if any(w in low for w in AXIS_LAYER_WORDS):
        return False
    if info.rule == "no keyword":
        return True
    return info.rule.startswith("exclude") and any(w in info.rule.lower() for w in PROJECTION_LAYER_WORDS)


def boundary_evidence(pieces, infos, scale: float) -> List[CadGeometry]:
    """Projection lines no rule keeps, as boundary evidence for the building interior (kind "boundary",
    metres): lines drawn with a dashed / dash-dot / hidden linetype (by entity or by layer,
    ``cad_explode.is_dashed_linetype``) or on a layer named for projections (``PROJECTION_LAYER_WORDS``:
    'PROIEZIONI', 'overhead', '虚线'...), on a layer that the rules drop for no keyword or as hidden.
    A corridor closed only by such a line (open on one side, or at its ends) is inside; the lines are never
    walls (the segmentation gets them as a separate mask, ``rasterize.boundary_mask``)."""
    out = []
    named = {}
    for i, lay in enumerate(pieces.layer):
        info = infos.get(lay)
        if not _boundary_layer(info):
            continue
        if pieces.etype[i] not in BOUNDARY_TYPES or pieces.filled[i]:
            continue
        if lay not in named:
            low = lay.lower()
            named[lay] = any(w in low for w in PROJECTION_LAYER_WORDS)
        dashed = pieces.dashed[i] if i < len(pieces.dashed) else False
        if not (dashed or named[lay]):
            continue
        c = pieces.coords[i]
        if len(c) < 2 or not np.isfinite(c).all():
            continue
        if float(np.hypot(*np.diff(c, axis=0).T).sum()) * scale < BOUNDARY_MIN_LEN:
            continue
        out.append(CadGeometry(layer=lay, kind="boundary", coords=c * scale, closed=pieces.closed[i],
                               entity=pieces.etype[i], cls="boundary"))
    return out


def classify_entities(geoms: Sequence[CadGeometry], chains: Sequence[str], rules, include_doors: bool = False,
                      weak_layers: Iterable[str] = (), drop_door_swings: bool = True, aux_from: Optional[int] = None,
                      progress=None):
    """Classify the imported geometry by what the drawing says, for drawings whose layers do not.

    * block names (rules ``blocks``): door / window / furniture, the innermost matching block decides;
      door and furniture geometry is left out (doors kept when ``include_doors``);
    * door swings (quarter arc + leaf, see ``door_swings``) anywhere: left out, and each becomes a DoorHint
      from jamb to jamb; swings inside door blocks give hints too;
    * pattern (non-solid) hatches thicker than HATCH_THICK (tiles, flooring) are never walls;
    * on ``weak_layers`` (layer "0", fallback layers): closed compact outlines (0.35-2.5 m) that touch no
      other geometry, and what lies inside them, are furniture (unless filled or hatched: a column).

    ``geoms[aux_from:]`` are auxiliary arcs (``swing_candidates``): door swings when they swing a leaf of the
    kept geometry (or hinge at a wall end), never kept otherwise.

    Returns ``(keep mask, classes {class: count}, door hints)``."""
    from .cad_explode import BLOCK_SEP

    n = len(geoms)
    cls = [""] * n
    for i, g in enumerate(geoms):
        chain = chains[i] if i < len(chains) else ""
        if chain:
            c, _ = rules.block_class(chain.split(BLOCK_SEP))
            if c:
                cls[i] = c
    for i, g in enumerate(geoms):
        if g.kind == "door" and cls[i] != "furniture":
            cls[i] = "door"  # door layers: their swings give door hints
        elif not cls[i] and g.entity == "HATCH" and not g.filled and _thickness(g.coords) >= HATCH_THICK:
            cls[i] = "hatch"
    hints: List[DoorHint] = []
    check = progress.check if progress is not None else (lambda: None)  # cancel between the searches
    check()
    door_idx = [i for i in range(n) if cls[i] == "door"]
    if door_idx:
        _, h = door_swings(geoms, door_idx, leaf_required=True)
        for d in h:
            d.source = "block"
        hints.extend(h)
    check()
    if drop_door_swings and not include_doors:
        rest = [i for i in range(n) if not cls[i]]
        drop, h = door_swings(geoms, rest)
        for i in drop:
            cls[i] = "door"
        hints.extend(h)
    check()
    weak = set(weak_layers)
    if weak:
        end = len(geoms) if aux_from is None else aux_from
        main_cls = cls[:end]
        _free_furniture(geoms[:end], main_cls, weak)
        check()
        furniture_groups(geoms[:end], main_cls, weak)
        check()
        floor_markings(geoms[:end], main_cls, weak)
        check()
        hints.extend(lined_doorways(geoms[:end], main_cls, weak, hints))
        cls[:end] = main_cls
    keep = np.array([c in ("", "window") or (c == "door" and include_doors) for c in cls], dtype=bool)
    if aux_from is not None:
        keep[aux_from:] = False
    check()
    free_stair_treads(geoms, keep)
    check()
    if drop_door_swings and not include_doors:
        hints.extend(curtain_wall_doors(geoms, keep))
    check()
    for i, g in enumerate(geoms):
        g.cls = cls[i] or ("wall" if g.kind in ("wall", "reference") else g.kind)
    classes: Dict[str, int] = {}
    for i, g in enumerate(geoms):
        if g.kind != AUX_KIND or g.cls == "door":
            classes[g.cls] = classes.get(g.cls, 0) + 1
    return keep, classes, hints


def free_stair_treads(geoms: Sequence[CadGeometry], keep: Optional[np.ndarray] = None) -> int:
    """Stair treads drawn on a wall (or any kept) layer become kind "stair": the raster keeps them free (a
    flight between two parts of a floor, half a level apart, is a way through, not a wall) and the stair
    recognition still sees them. Treads: single straight lines in a run of parallel lines of similar length
    at a regular tread spacing (``area_types.find_stair_runs``). Returns how many lines changed kind."""
    import shapely
    from shapely import STRtree

    from .area_types import TREAD_LENGTH, find_stair_runs

    n = _curved_treads(geoms, keep)
    skip = ("stair", "elevator", "column")
    two = [i for i, g in enumerate(geoms) if len(g.coords) == 2 and g.kind not in skip and not g.filled
           and (keep is None or keep[i])]
    if len(two) < 6:
        return n
    C = np.stack([geoms[i].coords for i in two])
    L = np.hypot(C[:, 1, 0] - C[:, 0, 0], C[:, 1, 1] - C[:, 0, 1])
    ok = np.isfinite(L) & (L >= TREAD_LENGTH[0]) & (L <= TREAD_LENGTH[1])
    cand = [two[k] for k in np.flatnonzero(ok)]
    if len(cand) < 6:
        return n
    runs = find_stair_runs([geoms[i] for i in cand])
    if not runs:
        return n
    zones = [r.buffer(0.05) for r in runs]
    tree = STRtree(zones)
    # both ends of a line in one tread zone (bulk queries: a Point per end cost 0.15 CPU s on kindergarten-1)
    ends = C[ok]
    ends_a = tree.query(shapely.points(ends[:, 0]), predicate="intersects")
    ends_b = tree.query(shapely.points(ends[:, 1]), predicate="intersects")
    both = set(zip(ends_a[0].tolist(), ends_a[1].tolist())) & set(zip(ends_b[0].tolist(), ends_b[1].tolist()))
    for k in sorted({p for p, _ in both}):
        geoms[cand[k]].kind = "stair"
        n += 1
    return n


CURVED_TREADS = 4  # concentric arcs at a tread spacing that make a curved flight


def _curved_treads(geoms: Sequence[CadGeometry], keep) -> int:
    """Curved flights: >= CURVED_TREADS open arcs sharing a centre (within 0.1 m) whose radii step by a tread
    spacing (``area_types.TREAD_SPACING``) become kind "stair"."""
    from .area_types import TREAD_SPACING

    arcs = []
    for i, g in enumerate(geoms):
        if (keep is not None and not keep[i]) or g.entity != "ARC" or g.kind in ("stair", "elevator", "column"):
            continue
        c = g.coords
        if len(c) < 3 or g.closed or not np.isfinite(c).all():
            continue
        circ = _circle_from_3(c[0], c[len(c) // 2], c[-1])
        if circ is not None and 0.5 <= circ[2] <= 30.0:
            arcs.append((i, circ[0], circ[1], circ[2]))
    if len(arcs) < CURVED_TREADS:
        return 0
    groups: Dict[Tuple[int, int], List[tuple]] = {}
    for a in arcs:
        groups.setdefault((int(round(a[1] / 0.1)), int(round(a[2] / 0.1))), []).append(a)
    n = 0
    seen = set()
    for key, members in groups.items():
        near = [a for dx in (-1, 0, 1) for dy in (-1, 0, 1) for a in groups.get((key[0] + dx, key[1] + dy), [])
                if a[0] not in seen]
        if len(near) < CURVED_TREADS:
            continue
        near.sort(key=lambda a: a[3])
        radii = np.array([a[3] for a in near])
        steps = np.diff(radii)
        # the longest chain of consecutive radii stepping by a tread spacing
        ok = (steps >= TREAD_SPACING[0]) & (steps <= TREAD_SPACING[1])
        best, run, start, bstart = 0, 0, 0, 0
        for k, v in enumerate(ok):
            run = run + 1 if v else 0
            if run == 1:
                start = k
            if run > best:
                best, bstart = run, start
        if best + 1 >= CURVED_TREADS and np.std(steps[bstart:bstart + best]) <= 0.25 * np.mean(steps[bstart:bstart + best]):
            for a in near[bstart:bstart + best + 1]:
                geoms[a[0]].kind = "stair"
                seen.add(a[0])
                n += 1
    return n


def _free_furniture(geoms: Sequence[CadGeometry], cls: List[str], weak: set) -> None:
    import shapely
    from shapely import STRtree

    cand = []
    for i, g in enumerate(geoms):
        if cls[i] or g.layer not in weak or g.filled or not (g.closed or g.entity == "CIRCLE"):
            continue
        c = g.coords
        if len(c) < 3 or not np.isfinite(c).all():
            continue
        span = c.max(axis=0) - c.min(axis=0)
        if span.max() <= FURNITURE_MAX and span.min() >= FURNITURE_MIN:
            cand.append(i)
    if not cand:
        return
    idx, coords = _finite_lines(geoms, [i for i in range(len(geoms)) if not cls[i]])
    lines = _linestrings(coords)  # one vectorised call (a LineString per entity cost 0.4 s on SIST-F1.dwg)
    tree = STRtree(lines)
    # every candidate at once (the outcome of one does not depend on another's): its outline, the zone
    # TOUCH around it, its inside TOUCH in from it, the lines the zone meets and which of them lie inside
    lens = np.fromiter((len(geoms[i].coords) for i in cand), dtype=np.int64, count=len(cand))
    polys = shapely.polygons(shapely.linearrings(np.concatenate([geoms[i].coords for i in cand]),
                                                 indices=np.repeat(np.arange(len(cand)), lens)))
    for k in np.flatnonzero(~shapely.is_valid(polys)):
        polys[k] = polys[k].buffer(0)
    zones = shapely.buffer(polys, TOUCH, quad_segs=16)  # quad_segs as BaseGeometry.buffer's default
    inside = polys.copy()
    solid = shapely.area(polys) > 0
    inside[solid] = shapely.buffer(polys[solid], -TOUCH, quad_segs=16)
    qc, ql = tree.query(zones, predicate="intersects")
    hit = np.asarray(idx, dtype=np.int64)[ql]
    cand_arr = np.asarray(cand, dtype=np.int64)
    other = hit != cand_arr[qc]
    contained = shapely.contains(inside[qc], lines[ql])
    in_cand = np.zeros(len(geoms), dtype=bool)
    in_cand[cand_arr] = True
    stiff = np.array([g.filled or g.kind == "column" for g in geoms], dtype=bool)
    # touching a line that is no candidate and not inside, or a hatched / filled outline (a column): no furniture
    veto = other & ((~in_cand[hit] & ~contained) | stiff[hit])
    free = np.bincount(qc[veto], minlength=len(cand)) == 0
    for k in np.flatnonzero(free):
        cls[cand[k]] = "furniture"
    for j in hit[free[qc] & other & contained].tolist():
        cls[j] = "furniture"  # what lies inside it (only unclassified lines are in the tree)


def _line(g: CadGeometry):
    from shapely.geometry import LineString, Point

    c = g.coords[np.isfinite(g.coords).all(axis=1)]
    return LineString(c) if len(c) >= 2 else Point(c[0])


# ------------------------------------------------------------------------------------------ curtain-wall doors
CW_FRAME_MIN = 4.0  # metres: a frame line of a curtain wall runs along several panels
CW_DEPTH = 0.4  # metres: panels lie within this distance of the frame line (the curtain wall's thickness)
CW_GAP = (0.8, 2.5)  # metres: a door in the row of panels (narrower: a joint; wider: a wall or an open bay)
CW_PANEL_RUN = 0.5  # metres of panels on each side of the gap (mullions alone, 0.1 m, are a glass wall's rhythm)


def curtain_wall_doors(geoms: Sequence[CadGeometry], keep: Optional[np.ndarray] = None) -> List[DoorHint]:
    """Doors in curtain walls drawn as a gap in the row of glazing panels: curtain walls are drawn as long
    frame lines (>= ``CW_FRAME_MIN``) with the panels between them, and a door is often drawn as no panel,
    the frame line running on across the opening (a threshold). Along every long straight window-kind
    segment, the window pieces within ``CW_DEPTH`` of it cover runs; a gap of ``CW_GAP`` between two runs of at
    least ``CW_PANEL_RUN`` of panels, with no wall or column across it, is a doorway (a pier between two
    strip windows is a wall; a glass wall of mullions only has no panel runs). Returns one DoorHint
    (source "curtain_wall") per gap, jamb to jamb along the frame line."""
    from scipy.spatial import cKDTree

    idx = [i for i, g in enumerate(geoms) if g.kind == "window" and not g.filled and len(g.coords) >= 2
           and (keep is None or keep[i])]
    if len(idx) < 4:
        return []
    # every segment of the window pieces (a closed one's closing segment last), in one vectorised pass
    lens = np.fromiter((len(geoms[i].coords) for i in idx), dtype=np.int64, count=len(idx))
    allc = np.concatenate([geoms[i].coords for i in idx])
    row_own = np.repeat(np.arange(len(idx)), lens)
    k = np.flatnonzero(row_own[1:] == row_own[:-1])
    shut = np.flatnonzero(np.fromiter((geoms[i].closed for i in idx), dtype=bool, count=len(idx)))
    start = np.cumsum(lens) - lens
    P = np.concatenate([allc[k], allc[start[shut] + lens[shut] - 1]])
    Q = np.concatenate([allc[k + 1], allc[start[shut]]])
    pos = np.concatenate([row_own[k], shut])
    order = np.argsort(pos, kind="stable")
    P, Q = P[order], Q[order]
    own = np.asarray(idx, dtype=np.int64)[pos[order]]
    L = np.hypot(*(Q - P).T)
    ok = np.isfinite(L) & (L > 0.01)
    P, Q, own, L = P[ok], Q[ok], own[ok], L[ok]
    frames = np.flatnonzero(L >= CW_FRAME_MIN)
    if not len(frames):
        return []
    mid = (P + Q) / 2.0
    tree = cKDTree(mid)
    gaps = []
    for k in frames:
        a, Lk = P[k], L[k]
        u = (Q[k] - a) / Lk
        nrm = np.array((-u[1], u[0]))
        near = np.asarray(tree.query_ball_point(mid[k], Lk / 2.0 + CW_DEPTH), dtype=np.int64)
        near = near[(own[near] != own[k]) & (L[near] <= 0.9 * Lk)]
        if len(near) < 3:
            continue
        dp, dq = (P[near] - a) @ nrm, (Q[near] - a) @ nrm
        near = near[(np.abs(dp) <= CW_DEPTH) & (np.abs(dq) <= CW_DEPTH)]
        if len(near) < 3:
            continue
        tp, tq = (P[near] - a) @ u, (Q[near] - a) @ u
        lo, hi = np.clip(np.minimum(tp, tq), 0, Lk), np.clip(np.maximum(tp, tq), 0, Lk)
        order = np.argsort(lo)
        runs = []
        for l0, h0 in zip(lo[order], hi[order]):
            if runs and l0 <= runs[-1][1] + 0.02:
                runs[-1][1] = max(runs[-1][1], h0)
            else:
                runs.append([l0, h0])
        for (l0, h0), (l1, h1) in zip(runs[:-1], runs[1:]):
            if CW_GAP[0] <= l1 - h0 <= CW_GAP[1] and h0 - l0 >= CW_PANEL_RUN and h1 - l1 >= CW_PANEL_RUN:
                gaps.append((a + u * h0, a + u * l1))
    if not gaps:
        return []
    rails = np.flatnonzero(L >= CW_GAP[0])
    return _unblocked_gaps(geoms, gaps, np.stack([P[rails], Q[rails]], axis=1))


def _unblocked_gaps(geoms, gaps, rails) -> List[DoorHint]:
    """The gaps (pairs of points) no wall or column crosses (within CW_DEPTH of the gap, its inner 80 %) and
    only one frame line runs across (the threshold; the other frame line stops at the jambs: where both run
    on, only a panel is missing from a fixed bay), one hint per doorway. ``rails``: (n, 2, 2) window segments."""
    from shapely import STRtree
    from shapely.geometry import LineString, Polygon

    lo = np.min([np.minimum(p, q) for p, q in gaps], axis=0) - 1.0
    hi = np.max([np.maximum(p, q) for p, q in gaps], axis=0) + 1.0
    rmin, rmax = np.minimum(rails[:, 0], rails[:, 1]), np.maximum(rails[:, 0], rails[:, 1])
    inb = (rmax >= lo).all(axis=1) & (rmin <= hi).all(axis=1)
    rails = rails[inb]
    rail_tree = STRtree([LineString(r) for r in rails])
    # walls and columns near the gaps (bounds of all of them at once), as polygons / lines built vectorised
    import shapely

    wc = [g for g in geoms if g.kind in ("wall", "column") and len(g.coords) >= 2]
    solid = []
    if wc:
        lens = np.fromiter((len(g.coords) for g in wc), dtype=np.int64, count=len(wc))
        allc = np.concatenate([g.coords for g in wc])
        at = np.cumsum(lens) - lens
        with np.errstate(invalid="ignore"):
            gmin, gmax = np.minimum.reduceat(allc, at), np.maximum.reduceat(allc, at)  # NaN where a vertex is
            near = ~((gmax[:, 0] < lo[0]) | (gmin[:, 0] > hi[0]) | (gmax[:, 1] < lo[1]) | (gmin[:, 1] > hi[1]))
        fin = np.bincount(np.repeat(np.arange(len(wc)), lens)[~np.isfinite(allc).all(axis=1)], minlength=len(wc)) == 0
        polys, lines = [], []
        for k in np.flatnonzero(near & fin).tolist():
            g = wc[k]
            c = g.coords
            if g.filled and len(c) >= 3:
                polys.append(c)
            else:
                lines.append(np.vstack([c, c[:1]]) if g.closed else c)
        if polys:
            plens = np.fromiter((len(c) for c in polys), dtype=np.int64, count=len(polys))
            solid.extend(shapely.polygons(shapely.linearrings(np.concatenate(polys),
                                                              indices=np.repeat(np.arange(len(polys)), plens))))
        solid.extend(_linestrings(lines))
    tree = STRtree(solid) if solid else None
    out: List[DoorHint] = []
    for p, q in gaps:
        w = float(np.hypot(*(q - p)))
        u = (q - p) / w
        nrm = np.array((-u[1], u[0])) * CW_DEPTH
        a2, b2 = p + u * 0.1 * w, q - u * 0.1 * w
        rect = Polygon([a2 + nrm, b2 + nrm, b2 - nrm, a2 - nrm])
        if tree is not None and len(tree.query(rect, predicate="intersects")):
            continue
        across = 0
        for j in rail_tree.query(rect, predicate="intersects"):
            d = rails[j, 1] - rails[j, 0]
            n = float(np.hypot(*d))
            if n >= 0.8 * w and abs(float(np.dot(d, u))) >= 0.98 * n:
                across += 1
        if across != 1:
            continue
        m = (p + q) / 2.0
        if any(math.hypot(m[0] - (h.x0 + h.x1) / 2.0, m[1] - (h.y0 + h.y1) / 2.0) < 0.5 for h in out):
            continue
        out.append(DoorHint(float(p[0]), float(p[1]), float(q[0]), float(q[1]), "curtain_wall"))
    return out


# ------------------------------------------------------------------------------------------ dashed lines on kept layers
PROJECTION_KINDS = ("wall", "reference")  # kinds whose dashed lines are projections, not walls
PROJECTION_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE", "ARC", "SPLINE", "ELLIPSE")


def is_projection_line(g: CadGeometry, dashed: bool) -> bool:
    """A line drawn with a broken linetype (dashed / dash-dot / hidden, by name or by its pattern's gaps) on a
    wall (or reference) layer: what lies above or beyond the cut plane (a vault, a beam, a roof truss, a
    collapsed vault's outline, a canopy), never a wall. Such lines cut rooms into pieces and, drawn across a
    doorway (a vault's springing line), close it. They are kept as boundary evidence (kind "boundary")."""
    return bool(dashed) and g.kind in PROJECTION_KINDS and g.entity in PROJECTION_TYPES and not g.filled


# a floor opening (a void over the floor below, an atrium, a double-height space) is outlined dashed too, and its
# edge is a drop: those lines stay walls
VOID_WORDS = ("void", "vuoto", "vacio", "vacío", "hueco", "luftraum", "vide", "open to below", "double height",
              "doppia altezza", "doble altura", "挑空", "中空", "上空", "空洞")


def keep_void_edges(geoms: Sequence[CadGeometry], texts, was: Dict[int, str]) -> int:
    """Dashed lines (``was``: index -> kind before ``is_projection_line`` made them "boundary") that outline a
    floor opening stay what their layer says: a group of touching dashed lines whose bounding box holds a
    text naming a void (VOID_WORDS: 'void', 'vuoto', 'Luftraum', '挑空'...). Returns how many were restored."""
    if not was:
        return 0
    import shapely
    from shapely import STRtree
    from shapely.geometry import Point

    idx = [i for i in was if len(geoms[i].coords) >= 2 and np.isfinite(geoms[i].coords).all()]
    lines = _linestrings([geoms[i].coords for i in idx])
    if not len(lines):
        return 0
    groups = _touching_groups(lines, STRtree(lines))
    bounds = shapely.bounds(lines)
    void = np.asarray([(t.x, t.y) for t in texts if any(w in (t.text or "").lower() for w in VOID_WORDS)],
                      dtype=float).reshape(-1, 2)
    named = [Point(t.x, t.y) for t in texts if sum(ch.isalpha() for ch in (t.text or "")) >= 3]
    walls = None
    n = 0
    for ks in groups.values():
        b = bounds[ks]
        x0, y0, x1, y1 = b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()
        keep = bool(np.any((void[:, 0] > x0) & (void[:, 0] < x1) & (void[:, 1] > y0) & (void[:, 1] < y1)))
        if not keep and named and len(ks) >= 2:
            if walls is None:
                walls = _linestrings([g.coords for g in geoms if g.kind in PROJECTION_KINDS and len(g.coords) >= 2
                                      and np.isfinite(g.coords).all()])  # one vectorised call
                walls = STRtree(walls) if len(walls) else False
            keep = _zone_outline([lines[k] for k in ks], named, walls)
        if keep:
            for k in ks:
                geoms[idx[k]].kind = was[idx[k]]
                n += 1
    return n


ZONE_HUG = 0.6  # metres: an outline this close to walls runs along them (a vault or roof over the room)


def _zone_outline(lines, named, walls) -> bool:
    """The dashed lines close a polygon of their own that holds a name (a cinema corner, a reception zone
    marked on the floor) and run mostly free of the walls (less than half of the outline within ZONE_HUG of a
    wall: a vault's or roof's outline follows the room's walls and is a projection)."""
    from shapely.ops import polygonize, unary_union

    for poly in polygonize(unary_union(lines)):
        if poly.area < 2.0 or not any(poly.contains(p) for p in named):
            continue
        ring = poly.exterior
        if walls is False:
            return True
        near = [walls.geometries[k] for k in walls.query(ring, predicate="dwithin", distance=ZONE_HUG)]
        if not near:
            return True
        hug = ring.intersection(unary_union([w.buffer(ZONE_HUG, 2) for w in near])).length
        if hug < 0.5 * ring.length:
            return True
    return False


def split_projection_lines(geoms: List[CadGeometry]) -> Tuple[List[CadGeometry], List[CadGeometry]]:
    """(geometries without the projection lines, the projection lines as boundary evidence): the ones
    ``is_projection_line`` marked with kind "boundary" at import (and that classification left as they were)."""
    keep, proj = [], []
    for g in geoms:
        if g.kind == "boundary":
            g.cls = "boundary"
            proj.append(g)
        else:
            keep.append(g)
    return keep, proj


# ------------------------------------------------------------------------------------------ floor markings
MARKING_MIN_SPAN = FURNITURE_MAX  # metres: a free-standing group larger than any furniture
WALL_PAIR = (0.04, 0.6)  # metres: two parallel lines this far apart are the two faces of a wall
MARKING_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE", "ARC", "CIRCLE", "ELLIPSE", "SPLINE")


def _segments(c: np.ndarray, closed: bool = False) -> np.ndarray:
    c = c[np.isfinite(c).all(axis=1)]
    if closed and len(c) >= 3 and not np.allclose(c[0], c[-1]):
        c = np.vstack([c, c[:1]])
    return np.stack([c[:-1], c[1:]], axis=1) if len(c) >= 2 else np.zeros((0, 2, 2))


def _segments_many(coords: Sequence[np.ndarray], closed: Sequence[bool]) -> Tuple[np.ndarray, np.ndarray]:
    """``_segments`` of many geometries at once: ``(segments (m, 2, 2), owner position (m,))``, each owner's
    segments in order (its closing segment last), owners in order; the same segments as one call each."""
    n = len(coords)
    if not n:
        return np.zeros((0, 2, 2)), np.zeros(0, dtype=np.int64)
    lens = np.fromiter((len(c) for c in coords), dtype=np.int64, count=n)
    allc = np.concatenate(coords).astype(np.float64, copy=False).reshape(-1, 2)
    own = np.repeat(np.arange(n), lens)
    fin = np.isfinite(allc).all(axis=1)
    allc, own = allc[fin], own[fin]
    cnt = np.bincount(own, minlength=n)  # finite rows per owner
    start = np.cumsum(cnt) - cnt
    has = cnt > 0
    first = np.full((n, 2), np.nan)
    last = np.full((n, 2), np.nan)
    first[has] = allc[start[has]]
    last[has] = allc[start[has] + cnt[has] - 1]
    close = np.asarray(closed, dtype=bool) & (cnt >= 3)
    close[close] = ~np.isclose(first[close], last[close]).all(axis=1)  # as np.allclose, per owner
    # consecutive rows of one owner, then each closing segment (last -> first), sorted back into owner order
    k = np.flatnonzero(own[1:] == own[:-1])
    cl = np.flatnonzero(close)
    seg = np.concatenate([np.stack([allc[k], allc[k + 1]], axis=1), np.stack([last[cl], first[cl]], axis=1)])
    sown = np.concatenate([own[k], cl])
    order = np.argsort(sown, kind="stable")
    return seg[order], sown[order]


def _has_wall_pair(segs: np.ndarray, others: Optional[np.ndarray] = None, min_overlap: float = 0.5) -> bool:
    """A straight segment of ``segs`` and another one (of ``segs`` or ``others``), parallel (within 3
    degrees), WALL_PAIR apart and overlapping by ``min_overlap`` m along their direction: two faces of a wall."""
    def _clean(x):
        d = x[:, 1] - x[:, 0]
        length = np.hypot(d[:, 0], d[:, 1])
        ok = length >= min_overlap
        return x[ok], d[ok] / np.maximum(length[ok, None], 1e-12), length[ok]

    segs, u, length = _clean(segs)
    every = segs if others is None or not len(others) else np.concatenate([segs, _clean(others)[0]])
    if len(segs) < 1 or len(every) < 2:
        return False
    ue = (every[:, 1] - every[:, 0]) / np.maximum(np.hypot(*(every[:, 1] - every[:, 0]).T)[:, None], 1e-12)
    for i in range(len(segs)):
        cross = np.abs(u[i, 0] * ue[:, 1] - u[i, 1] * ue[:, 0])
        par = cross < math.sin(math.radians(3.0))
        par[i] = False
        if not par.any():
            continue
        rel = every[par, 0] - segs[i, 0]
        off = np.abs(rel[:, 0] * u[i, 1] - rel[:, 1] * u[i, 0])
        near = (off >= WALL_PAIR[0]) & (off <= WALL_PAIR[1])
        if not near.any():
            continue
        a0 = (every[par][near] - segs[i, 0]) @ u[i]  # (k, 2) positions of the other's ends along i
        lo, hi = a0.min(axis=1), a0.max(axis=1)
        if np.any(np.minimum(hi, length[i]) - np.maximum(lo, 0.0) >= min_overlap):
            return True
    return False


def _touching_groups(lines, tree) -> Dict[int, List[int]]:
    """Groups of ``lines`` (indices) that touch each other within TOUCH (connected components)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    a_idx, b_idx = tree.query(lines, predicate="dwithin", distance=TOUCH)
    n = len(lines)
    _, lab = connected_components(coo_matrix((np.ones(len(a_idx)), (a_idx, b_idx)), shape=(n, n)), directed=False)
    groups: Dict[int, List[int]] = {}
    for k, r in enumerate(lab.tolist()):
        groups.setdefault(r, []).append(k)
    return groups


def _linestrings(coords: Sequence[np.ndarray]) -> np.ndarray:
    """LineStrings of (n_i, 2) coordinate arrays (n_i >= 2, finite) built in one vectorised call."""
    import shapely

    if not len(coords):
        return np.empty(0, dtype=object)
    lens = np.fromiter((len(c) for c in coords), dtype=np.int64, count=len(coords))
    return shapely.linestrings(np.concatenate(coords), indices=np.repeat(np.arange(len(coords)), lens))


def _finite_rows(coords: List[np.ndarray]) -> List[np.ndarray]:
    """Each array without its non-finite rows (the array itself when all are finite), tested all at once."""
    if not coords:
        return []
    lens = np.fromiter((len(c) for c in coords), dtype=np.int64, count=len(coords))
    fin = np.isfinite(np.concatenate(coords)).all(axis=1)
    if fin.all():
        return list(coords)
    out = list(coords)
    for k in np.unique(np.repeat(np.arange(len(coords)), lens)[~fin]).tolist():
        out[k] = coords[k][np.isfinite(coords[k]).all(axis=1)]
    return out


def _finite_lines(geoms: Sequence[CadGeometry], sel: Sequence[int]) -> Tuple[List[int], List[np.ndarray]]:
    """(indices, coordinates) of the geometries ``sel`` that keep at least two finite points (``_finite_rows``):
    the lines a ``_linestrings`` call can build, in ``sel``'s order."""
    idx, coords = [], []
    for i, c in zip(sel, _finite_rows([geoms[i].coords for i in sel])):
        if len(c) >= 2:
            idx.append(i)
            coords.append(c)
    return idx, coords


def floor_markings(geoms: Sequence[CadGeometry], cls: List[str], weak: set) -> int:
    """Markings drawn on the floor (a sports court's lines, circles and arcs; a painted play area) on the
    same layer as the walls ("0", fallback layers): a group of lines on ``weak`` layers that touches no other
    geometry (it closes no space with the walls), is larger than furniture (MARKING_MIN_SPAN), lies inside
    the extent of the drawing's largest group, and has no two lines at a wall's thickness apart (single
    lines only: no wall). Marked class "marking" in ``cls`` (left out like furniture). Returns how many.

    Only lines on weak layers can be markings: their groups are found among themselves first, and the
    touching groups of the whole drawing (its largest group) are computed only when one of them passes
    every other test (a drawing with walls on named layers has few such lines; SIST-F5: 142 of 15,308)."""
    import shapely
    from shapely import STRtree

    sel = [i for i, g in enumerate(geoms)
           if not (cls[i] or g.filled or g.kind in ("column", "stair", "elevator", "boundary", AUX_KIND))]
    idx, coords = _finite_lines(geoms, sel)
    if len(idx) < 4:
        return 0
    cand = [k for k, i in enumerate(idx) if geoms[i].layer in weak and geoms[i].entity in MARKING_TYPES]
    if len(cand) < 3:
        return 0
    in_cand = np.zeros(len(idx), dtype=bool)
    in_cand[cand] = True
    lines = tree = full = None
    groups = []  # (member positions in ``idx``) of whole groups of weak lines large enough to be a marking
    if 2 * len(cand) > len(idx):  # mostly weak lines (a spaghetti drawing): the whole drawing's groups at once
        lines = _linestrings(coords)
        tree = STRtree(lines)
        full = _touching_groups(lines, tree)
        bounds = shapely.bounds(lines)
        for ks in full.values():
            if len(ks) < 3 or not in_cand[ks].all():
                continue
            b = bounds[ks]
            if max(b[:, 2].max() - b[:, 0].min(), b[:, 3].max() - b[:, 1].min()) >= MARKING_MIN_SPAN:
                groups.append(ks)
    else:
        cand_lines = _linestrings([coords[k] for k in cand])
        cand_bounds = shapely.bounds(cand_lines)
        local = []  # groups of weak lines (positions in ``cand``) large enough to be a marking
        for ks in _touching_groups(cand_lines, STRtree(cand_lines)).values():
            if len(ks) < 3:
                continue
            b = cand_bounds[ks]
            if max(b[:, 2].max() - b[:, 0].min(), b[:, 3].max() - b[:, 1].min()) < MARKING_MIN_SPAN:
                continue
            local.append(ks)
        if not local:
            return 0
        lines = _linestrings(coords)
        tree = STRtree(lines)
        cand_arr = np.asarray(cand)
        for ks in local:
            ks_all = cand_arr[ks]
            hit = tree.query(lines[ks_all], predicate="dwithin", distance=TOUCH)[1]
            if not in_cand[hit].all():
                continue  # touches a line of another layer or type: part of a larger group
            groups.append(ks_all.tolist())
    passing = []
    for ks in groups:
        members = [idx[k] for k in ks]
        straight = [geoms[i] for i in members if geoms[i].entity in ("LINE", "LWPOLYLINE", "POLYLINE")]
        segs = np.concatenate([_segments(g.coords, g.closed) for g in straight]) if straight else np.zeros((0, 2, 2))
        if len(segs):
            # the other face of a wall may be a line of another group (two closed outlines that never touch)
            mine = set(members)
            near = {idx[k] for k in tree.query(lines[ks], predicate="dwithin",
                                               distance=WALL_PAIR[1])[1].tolist()} - mine
            others = [_segments(geoms[j].coords, geoms[j].closed) for j in near
                      if geoms[j].entity in ("LINE", "LWPOLYLINE", "POLYLINE")]
            others = np.concatenate(others) if others else None
            if _has_wall_pair(segs, others):
                continue
        passing.append(ks)
    if not passing:
        return 0
    # the drawing's largest group (by length) and its extent: a marking lies inside it and is not it
    if full is None:
        full = _touching_groups(lines, tree)
    if len(full) < 2:
        return 0
    length = shapely.length(lines).tolist()
    glen = {r: sum(length[k] for k in ks) for r, ks in full.items()}
    main = max(glen, key=glen.get)
    main_set = set(full[main])
    bounds = shapely.bounds(lines)
    mb = bounds[full[main]]
    box = (mb[:, 0].min(), mb[:, 1].min(), mb[:, 2].max(), mb[:, 3].max())
    n = 0
    for ks in passing:
        if ks[0] in main_set:
            continue
        b = bounds[ks]
        x0, y0, x1, y1 = b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()
        if x0 < box[0] or y0 < box[1] or x1 > box[2] or y1 > box[3]:
            continue
        for k in ks:
            cls[idx[k]] = "marking"
        n += len(ks)
    return n


# ------------------------------------------------------------------------------------------ furniture in pieces
FURNITURE_GROUPS = True  # switch: free-standing furniture drawn in many strokes or with curves (below)
FURNITURE_PIECES = 8  # lines: a free-standing group of this many straight pieces is furniture drawn in strokes
CURVED_TYPES = ("ARC", "CIRCLE", "ELLIPSE", "SPLINE")


def furniture_groups(geoms: Sequence[CadGeometry], cls: List[str], weak: set) -> int:
    """Free-standing furniture drawn in pieces on ``weak`` layers (layer "0", fallback layers): a group of
    touching open lines (chairs drawn as dozens of elliptic arcs, a table with its chairs, a sink, a plant)
    that touches no other geometry (no wall, hatch, column or filled piece within TOUCH), is furniture-sized
    (its oriented box FURNITURE_MIN-FURNITURE_MAX), holds a curved piece or at least FURNITURE_PIECES pieces,
    and has no two lines at a wall's thickness apart (``_has_wall_pair``: a wall stub). Columns, shafts and
    voids are drawn as few straight strokes (a square, a square with its diagonals) or filled, and stay; a
    single closed outline is ``_free_furniture``'s. Marked "furniture" in ``cls``. Returns how many lines.

    A hall full of tables and chairs on the wall layer otherwise splits into areas along the rows of chairs
    (kindergarten-1's round dining hall: twelve areas)."""
    import shapely
    from shapely import STRtree

    if not FURNITURE_GROUPS:
        return 0
    cand, coords = _finite_lines(geoms, [
        i for i, g in enumerate(geoms) if not cls[i] and g.layer in weak and not g.filled
        and g.entity in MARKING_TYPES and g.kind not in ("column", "stair", "elevator", "boundary", AUX_KIND)])
    if len(cand) < 2:
        return 0
    lines = _linestrings(coords)
    bounds = shapely.bounds(lines)
    groups = []
    for ks in _touching_groups(lines, STRtree(lines)).values():
        if len(ks) < 2:
            continue
        b = bounds[ks]
        if max(b[:, 2].max() - b[:, 0].min(), b[:, 3].max() - b[:, 1].min()) >= FURNITURE_MAX * math.sqrt(2):
            continue  # no oriented box of furniture size fits (quick test before the exact one)
        curved = any(geoms[cand[k]].entity in CURVED_TYPES for k in ks)
        if not curved and len(ks) < FURNITURE_PIECES:
            continue
        box = shapely.oriented_envelope(shapely.multilinestrings(lines[ks].tolist()))
        if box.geom_type != "Polygon":
            continue
        xy = np.asarray(box.exterior.coords)
        side = np.hypot(*np.diff(xy[:3], axis=0).T)
        if side.max() > FURNITURE_MAX or side.min() < FURNITURE_MIN:
            continue
        straight = [geoms[cand[k]] for k in ks if geoms[cand[k]].entity in ("LINE", "LWPOLYLINE", "POLYLINE")]
        if straight and _has_wall_pair(np.concatenate([_segments(g.coords, g.closed) for g in straight])):
            continue
        groups.append(ks)
    if not groups:
        return 0
    # touching nothing else: every other piece of the drawing (filled, columns, other layers, classified ones
    # but furniture) within TOUCH of the group vetoes it
    others = [i for i, g in enumerate(geoms) if cls[i] != "furniture" and g.kind not in ("boundary", AUX_KIND)]
    o_idx, o_coords = [], []
    for i, c in zip(others, _finite_rows([geoms[i].coords for i in others])):
        if len(c) >= 1:
            o_idx.append(i)
            o_coords.append(c if len(c) >= 2 else np.vstack([c, c]))
    tree = STRtree(_linestrings(o_coords))
    o_idx = np.asarray(o_idx, dtype=np.int64)
    n = 0
    for ks in groups:
        members = {cand[k] for k in ks}
        hit = o_idx[tree.query(lines[ks], predicate="dwithin", distance=TOUCH)[1]]
        if any(int(j) not in members for j in hit):
            continue
        for i in members:
            cls[i] = "furniture"
        n += len(members)
    return n


# ------------------------------------------------------------------------------------------ lined doorways
JAMB_LENGTH = (0.05, 0.6)  # metres: a jamb cap joins the two faces of a wall across its thickness
OPENING_WIDTH = (0.7, 2.5)  # metres: a doorway between two jamb caps
LINING_GAP = 0.6  # metres: a line this close in front of a doorway, parallel to its wall, runs across it


def lined_doorways(geoms: Sequence[CadGeometry], cls: List[str], weak: set,
                   known: Sequence[DoorHint] = ()) -> List[DoorHint]:
    """Doorways drawn without a door (an opening in a two-line wall, both jambs capped, nothing inside)
    across which a single line parallel to the wall runs within LINING_GAP: the lining of a sports hall's
    walls, a skirting or floor-finish edge drawn on the wall layer. The line would close the doorway in the
    raster; a DoorHint keeps it open (``rasterize`` clears the opening and goes on through the thin strip
    and the line behind it, ``deepen_openings``). Only on ``weak`` layers (walls, linings and windows share
    the layer there, so an empty opening is no window left on another layer)."""
    from scipy.spatial import cKDTree
    from shapely import STRtree
    from shapely.geometry import Polygon

    import shapely

    sel = [g for i, g in enumerate(geoms) if not (cls[i] or g.layer not in weak or g.filled
                                                   or g.kind in ("column", "stair", "elevator", "boundary", AUX_KIND))]
    segs, sown = _segments_many([g.coords for g in sel], [g.closed for g in sel])
    if not len(segs):
        return []
    is_two = np.array([len(g.coords) == 2 for g in sel], dtype=bool)[sown]
    seg_len = np.hypot(*(segs[:, 1] - segs[:, 0]).T)
    ok = seg_len >= 0.02
    segs, is_two, seg_len = segs[ok], is_two[ok], seg_len[ok]
    cap_k = np.flatnonzero(is_two & (seg_len >= JAMB_LENGTH[0]) & (seg_len <= JAMB_LENGTH[1]))
    if len(cap_k) < 2:
        return []
    mids = (segs[cap_k, 0] + segs[cap_k, 1]) / 2
    pairs = cKDTree(mids).query_pairs(OPENING_WIDTH[1], output_type="ndarray")
    if not len(pairs):
        return []
    # vectorised prefilter: equal lengths, parallel, side by side along the wall, a doorway's width apart
    la, lb = seg_len[cap_k[pairs[:, 0]]], seg_len[cap_k[pairs[:, 1]]]
    va = (segs[cap_k[pairs[:, 0]], 1] - segs[cap_k[pairs[:, 0]], 0]) / la[:, None]
    vb = (segs[cap_k[pairs[:, 1]], 1] - segs[cap_k[pairs[:, 1]], 0]) / lb[:, None]
    w = mids[pairs[:, 1]] - mids[pairs[:, 0]]
    wl = np.hypot(w[:, 0], w[:, 1])
    keep = ((np.abs(la - lb) <= 0.03) & (np.abs(va[:, 0] * vb[:, 1] - va[:, 1] * vb[:, 0]) <= math.sin(math.radians(3.0)))
            & (np.abs((w * va).sum(axis=1)) <= 0.03) & (wl >= OPENING_WIDTH[0]) & (wl <= OPENING_WIDTH[1]))
    pairs = pairs[keep]
    if not len(pairs):
        return []
    seg_lines = shapely.linestrings(segs)
    tree = STRtree(seg_lines)
    ends = segs.reshape(-1, 2)
    end_owner = np.repeat(np.arange(len(segs)), 2)
    etree = cKDTree(ends)
    ktree = cKDTree(np.array([((d.x0 + d.x1) / 2, (d.y0 + d.y1) / 2) for d in known])) if known else None
    hints: List[DoorHint] = []
    used = set()
    ball: Dict[bytes, list] = {}
    for a, b in sorted(map(tuple, pairs.tolist())):
        if a in used or b in used:
            continue
        sa, sb = segs[cap_k[a]], segs[cap_k[b]]
        La = float(seg_len[cap_k[a]])
        v = (sa[1] - sa[0]) / La
        w = mids[b] - mids[a]
        width = float(np.hypot(*w))
        u = w / width
        # each cap joins two faces that run away from the opening (one of them may run on across it)
        ok = True
        through = []  # faces that run on across the opening from a cap end: the wall drawn through the doorway
        for cap, sign in ((sa, -1.0), (sb, 1.0)):
            for p in cap:
                key = p.tobytes()
                near = ball.get(key)
                if near is None:  # a cap is in several candidate pairs: look its ends up once
                    near = ball[key] = [end_owner[k] for k in etree.query_ball_point(p, 0.02)] + [
                        -1 - int(k) for k in tree.query(shapely.points(p), predicate="dwithin", distance=0.02)]
                face = False
                for k in near:
                    run_on = k < 0  # a segment passing the cap end (not ending there)
                    c = segs[-1 - k if run_on else k]
                    d = c[1] - c[0]
                    Ld = float(np.hypot(*d))
                    if Ld <= 0.2 or abs(float(d @ v)) >= 0.05 * Ld:
                        continue
                    if run_on:
                        t = (c - p) @ u * sign
                        if t.max() > 0.1 and t.min() < -0.5 * width:  # on away from the opening and across it
                            face = True
                            through.append(-1 - k)
                            break
                        continue
                    far = c[1] if np.hypot(*(c[0] - p)) < np.hypot(*(c[1] - p)) else c[0]
                    if float((far - p) @ u) * sign > 0.1:
                        face = True
                        break
                ok = ok and face
        if not ok or (through and not _face_is_outer(segs, tree, through[0], mids[a], mids[b], v)):
            continue
        # nothing inside the opening
        c0, c1 = sa[0] + 0.1 * (sa[1] - sa[0]), sa[1] - 0.1 * (sa[1] - sa[0])  # the faces and a line on them stay out
        inner = Polygon([c0 + 0.02 * u, c1 + 0.02 * u, c1 + (width - 0.02) * u, c0 + (width - 0.02) * u])
        if not inner.is_valid or any(seg_len[k] >= 0.05 for k in tree.query(inner, predicate="intersects")):
            continue
        # a line in front of it, parallel to the wall, running across the whole opening
        lo, hi = min(float(sa[0] @ v), float(sa[1] @ v)), max(float(sa[0] @ v), float(sa[1] @ v))
        lo, hi = lo + 0.02, hi - 0.02  # a face drawn on across the opening lies on the caps' ends: it is in front
        front = []
        for side in (-1.0, 1.0):
            edge = hi if side > 0 else lo
            box = Polygon([p for p in (
                mids[a] + (edge - mids[a] @ v) * v + 0.05 * u, mids[a] + (edge - mids[a] @ v + side * LINING_GAP) * v + 0.05 * u,
                mids[b] + (edge - mids[b] @ v + side * LINING_GAP) * v - 0.05 * u, mids[b] + (edge - mids[b] @ v) * v - 0.05 * u)])
            for k in tree.query(box, predicate="intersects"):
                c = segs[k]
                d = c[1] - c[0]
                Ld = float(np.hypot(*d))
                if Ld < width + 0.2 or abs(float(d @ v)) > 0.05 * Ld:
                    continue
                t = (c - mids[a]) @ u
                if t.min() <= 0.0 and t.max() >= width:
                    front.append(k)
        if not front:
            continue
        if ktree is not None and ktree.query_ball_point((mids[a] + mids[b]) / 2, 0.5):
            continue
        used.update((a, b))
        hints.append(DoorHint(float(mids[a][0]), float(mids[a][1]), float(mids[b][0]), float(mids[b][1]), "lined"))
    return hints


def _face_is_outer(segs: np.ndarray, tree, k: int, ma: np.ndarray, mb: np.ndarray, v: np.ndarray) -> bool:
    """The face ``segs[k]`` that runs on across an opening between the caps at ``ma`` and ``mb`` (cap
    direction ``v``) is the wall's outer face: no other line parallel to it lies beyond it within a wall's
    thickness (JAMB_LENGTH) along half the opening (else the caps end on a middle line of a thicker wall:
    a niche, not a doorway)."""
    from shapely.geometry import Polygon

    c = segs[k]
    side = 1.0 if float(((c[0] + c[1]) / 2.0 - (ma + mb) / 2.0) @ v) > 0 else -1.0  # outwards, across the wall
    w = mb - ma
    width = float(np.hypot(*w))
    u = w / width
    p0 = ma + float((c[0] - ma) @ v) * v  # on the face, level with the first cap
    depth = JAMB_LENGTH[1]  # the rest of a wall thicker than the cap (a niche) would lie within this
    box = Polygon([p0 + 0.1 * u + side * 0.03 * v, p0 + (width - 0.1) * u + side * 0.03 * v,
                   p0 + (width - 0.1) * u + side * depth * v, p0 + 0.1 * u + side * depth * v])
    for j in tree.query(box, predicate="intersects"):
        if j == k:
            continue
        s = segs[j]
        d = s[1] - s[0]
        Ld = float(np.hypot(*d))
        if Ld <= 0.2 or abs(float(d @ v)) >= 0.05 * Ld:
            continue
        t = (s - ma) @ u
        if min(t.max(), width) - max(t.min(), 0.0) >= 0.5 * width:
            return False
    return True


# ------------------------------------------------------------------------------------------ level marks
# block names of spot-level symbols (a circle with a hatched quadrant and a leader line under the level
# value): Spanish NPT / N.P.T. (nivel de piso terminado), FFL / NFL, German OKFF, Italian quota, 标高
LEVEL_MARK_BLOCKS = ("npt", "n.p.t", "ffl", "nfl", "okff", "quota", "cota", "标高")


def level_marks(geoms: Sequence[CadGeometry]) -> List[bool]:
    """Which geometries belong to a spot-level symbol block (LEVEL_MARK_BLOCKS, by the innermost block name)
    on a wall or reference layer: a level mark's leader line drawn across a small room cuts it in two. They
    are annotation, never walls. Applied after the plans are found (the sheet's grouping is unchanged)."""
    from .layer_rules import keyword_in

    hit: Dict[str, bool] = {}
    out = []
    for g in geoms:
        b = g.block
        if not b or g.kind not in PROJECTION_KINDS:
            out.append(False)
            continue
        if b not in hit:
            low = b.lower()
            hit[b] = any(keyword_in(w, low) for w in LEVEL_MARK_BLOCKS)
        out.append(hit[b])
    return out


# ------------------------------------------------------------------------------------ folding partitions
FOLD_LEAF = (0.25, 1.3)  # metres: a leaf of a folding (accordion) partition
FOLD_JOIN = 0.1  # metres: leaves whose ends lie this close are hinged (a leaf drawn 4 cm thick, two faces)
FOLD_ANGLE = 60.0  # degrees: two hinged leaves at most this far apart (and 10 at least) are folded (a V)
FOLD_STACK_MAX = 1.6  # metres: a folded stack fits in a box this long
FOLD_SPAN = (1.2, 8.0)  # metres: the track between the two stacks
FOLD_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE")


def folding_partitions(pieces, scale: float) -> List[CadGeometry]:
    """Folding (accordion) partitions, on any layer: a partition drawn folded at both ends of its track is two
    zig-zag stacks -- at least two hinged leaves of 0.25-1.3 m (``FOLD_LEAF``, ends within ``FOLD_JOIN``) that
    double back (a V of 10 to ``FOLD_ANGLE`` degrees) and fit in ``FOLD_STACK_MAX`` -- facing each other 1.2-8 m apart
    (``FOLD_SPAN``). The track between the two stacks is a wall that opens: where two room names share the
    space it crosses, the room is split along it and the two rooms get a passage along it
    (``semantics.assign_names(partitions=...)``); it is never a wall in the raster. Returns one line per
    partition (kind "partition", metres, from one stack's centre to the other's)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    idx = [i for i in range(len(pieces.coords)) if len(pieces.coords[i]) >= 2]
    if not idx:
        return []
    segs, own = _segments_many([pieces.coords[i] for i in idx], [pieces.closed[i] for i in idx])
    if not len(segs):
        return []
    allsegs = segs * scale  # every drawn segment: the span of a partition crosses none
    kind_ok = np.array([pieces.etype[i] in FOLD_TYPES and not pieces.filled[i] and len(pieces.coords[i]) <= 16
                        for i in idx], dtype=bool)[own]
    segs = allsegs
    d = segs[:, 1] - segs[:, 0]
    length = np.hypot(d[:, 0], d[:, 1])
    leaf = (length >= FOLD_LEAF[0]) & (length <= FOLD_LEAF[1]) & kind_ok
    leaf_at = np.flatnonzero(leaf)
    segs, d, length = segs[leaf], d[leaf], length[leaf]
    n = len(segs)
    if n < 4:
        return []
    ends = segs.reshape(-1, 2)
    pairs = cKDTree(ends).query_pairs(FOLD_JOIN, output_type="ndarray")
    if not len(pairs):
        return []
    a, b = pairs[:, 0] // 2, pairs[:, 1] // 2
    m = a != b
    a, b = a[m], b[m]
    ea, eb = pairs[m, 0] % 2, pairs[m, 1] % 2  # which end of each leaf is hinged
    va = segs[a, 1 - ea] - segs[a, ea]  # from the hinge along each leaf
    vb = segs[b, 1 - eb] - segs[b, eb]
    cos = (va * vb).sum(axis=1) / np.maximum(length[a] * length[b], 1e-12)
    turn = np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
    folded_at = (turn >= 10.0) & (turn <= FOLD_ANGLE)
    # a leaf end hinged to another leaf (not its own parallel face): a stack has free ends, a triangle or a
    # closed outline (an elevation marker, a chair) has none
    hinged = np.zeros(2 * n, bool)
    hinged[pairs[m][turn >= 10.0].ravel()] = True
    k, comp = connected_components(coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n)), directed=False)
    size = np.bincount(comp, minlength=k)
    stacks = []
    order = np.argsort(comp, kind="stable")
    first = np.concatenate([[0], np.cumsum(size)])
    comp_a = comp[a]
    for c in np.flatnonzero((size >= 2) & (size <= 40)):
        mem = order[first[c]:first[c + 1]]
        pts = segs[mem].reshape(-1, 2)
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        if np.hypot(*(hi - lo)) > FOLD_STACK_MAX * 1.42:
            continue
        # folded: two leaves hinged at one end that double back (a V: 10 to FOLD_ANGLE degrees between them;
        # the two faces of one leaf are parallel, a corner of a chair or a door frame is square)
        sel = comp_a == c
        if not folded_at[sel].any() or hinged[2 * mem].all() and hinged[2 * mem + 1].all():
            continue
        if max(hi - lo) <= FOLD_STACK_MAX:
            stacks.append((pts.mean(axis=0), float(np.median(length[mem])), set(leaf_at[mem].tolist())))
    if len(stacks) < 2:
        return []
    cen = np.array([s[0] for s in stacks])
    box = (allsegs.min(axis=1), allsegs.max(axis=1))
    out = []
    used = set()
    # the two stacks of one partition face each other: each is the other's nearest stack
    _, nn = cKDTree(cen).query(cen, k=2)
    nn = nn[:, 1]
    for i, j in sorted({(min(i, int(nn[i])), max(i, int(nn[i]))) for i in range(len(cen)) if nn[nn[i]] == i}):
        if i in used or j in used or np.hypot(*(cen[i] - cen[j])) > FOLD_SPAN[1]:
            continue
        span = float(np.hypot(*(cen[i] - cen[j])))
        li, lj = stacks[i][1], stacks[j][1]
        if span < FOLD_SPAN[0] or max(li, lj) > 1.5 * min(li, lj):  # two stacks of the same leaves
            continue
        if _crossed(allsegs, box, cen[i], cen[j], stacks[i][2] | stacks[j][2]):
            continue  # something drawn across the span (a wall, shelves): no open track
        used.update((i, j))
        out.append(CadGeometry(layer="", kind="partition", coords=np.array([cen[i], cen[j]]), entity="LINE",
                               cls="folding partition"))
    return out


def _crossed(segs: np.ndarray, box, p: np.ndarray, q: np.ndarray, skip: set) -> bool:
    """A segment of ``segs`` (m, 2, 2; ``box`` their (min, max) corners) other than those in ``skip``
    crosses the segment p-q."""
    lo, hi = np.minimum(p, q), np.maximum(p, q)
    near = np.flatnonzero((box[1] >= lo).all(axis=1) & (box[0] <= hi).all(axis=1))
    near = np.array([k for k in near if k not in skip], dtype=np.int64)
    if not len(near):
        return False
    a, b = segs[near, 0], segs[near, 1]

    def side(o, u, v):
        return (u[..., 0] - o[..., 0]) * (v[..., 1] - o[..., 1]) - (u[..., 1] - o[..., 1]) * (v[..., 0] - o[..., 0])

    d1, d2 = side(p, q, a), side(p, q, b)
    d3, d4 = side(a, b, p[None]), side(a, b, q[None])
    return bool(((d1 * d2 < 0) & (d3 * d4 < 0)).any())


# --------------------------------------------------------------------------- counters closing a space
COUNTER_JOIN = 0.03  # metres: furniture lines whose ends lie this close are one piece of furniture
COUNTER_CONTACT = 0.1  # metres: a furniture vertex this close to a wall face stands against the wall
COUNTER_CLUSTER = 1.0  # metres: contacts this close together are one end of the counter (its depth: both corners)
COUNTER_SPAN = (1.0, 8.0)  # metres: between the counter's two ends on the walls (a service space is >= 1 m wide)
COUNTER_DEPTH = 1.0  # metres: every line of the counter lies this close to the line between its two ends
COUNTER_MAX_LINES = 200  # a furniture group with more lines is a furnished zone, not one counter


def counter_partitions(furniture: Sequence[np.ndarray], walls: Sequence[CadGeometry]) -> List[CadGeometry]:
    """Counters that close a space: a piece of fixed furniture (a bar or reception counter, a shelving run:
    furniture lines touching end to end, ``COUNTER_JOIN``) that stands against a wall face at exactly two
    places (its two ends: contacts within ``COUNTER_CONTACT`` of a wall, clustered at ``COUNTER_CLUSTER``),
    ``COUNTER_SPAN`` apart, runs along the line between them (every vertex within ``COUNTER_DEPTH`` of it) and
    crosses no wall on the way. The space behind it (the bar's service side, the back office behind a
    reception desk) is closed off from the room in front: nobody walks across a counter. Furniture is never
    a wall in the raster (chairs and desks would cut rooms up), so segmentation joins both sides; where two
    room names share that space, ``semantics.assign_names(partitions=...)`` splits it along the counter, like
    a folding partition. ``furniture``: vertex arrays (metres) of the furniture lines (furniture layers and
    blocks); ``walls``: the wall and column geometry. Returns one line per counter (kind "partition", class
    "counter", metres, from one end's contact to the other's)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree
    from shapely import STRtree, points as shp_points

    furniture = [np.asarray(c, float) for c in furniture if len(c) >= 2]
    wall_segs, _ = _segments_many([g.coords for g in walls if len(g.coords) >= 2],
                                  [g.closed for g in walls if len(g.coords) >= 2])
    if not furniture or not len(wall_segs):
        return []
    segs, own = _segments_many(furniture, [False] * len(furniture))
    if not len(segs):
        return []
    n = len(furniture)
    # furniture lines touching end to end (or a vertex on another's vertex) are one piece
    verts = segs.reshape(-1, 2)
    vown = np.repeat(own, 2)
    pairs = cKDTree(verts).query_pairs(COUNTER_JOIN, output_type="ndarray")
    a, b = (vown[pairs[:, 0]], vown[pairs[:, 1]]) if len(pairs) else (np.zeros(0, int), np.zeros(0, int))
    k, comp = connected_components(coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n)), directed=False)
    scomp = comp[own]
    lines = _linestrings(list(wall_segs))
    tree = STRtree(lines)
    wall_box = (wall_segs.min(axis=1), wall_segs.max(axis=1))
    order = np.argsort(scomp, kind="stable")
    bounds = np.searchsorted(scomp[order], np.arange(k + 1))
    out = []
    for c in range(k):
        mem = order[bounds[c]:bounds[c + 1]]
        if not len(mem) or len(mem) > COUNTER_MAX_LINES:
            continue
        pts = np.unique(np.round(segs[mem].reshape(-1, 2), 4), axis=0)
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        if np.hypot(*(hi - lo)) < COUNTER_SPAN[0] or np.hypot(*(hi - lo)) > COUNTER_SPAN[1] + 2 * COUNTER_DEPTH:
            continue
        hit = tree.query(shp_points(pts), predicate="dwithin", distance=COUNTER_CONTACT)
        if not hit.size:
            continue
        touch = pts[np.unique(hit[0])]
        if len(touch) < 2:
            continue
        # the contacts, clustered: a counter stands against the walls at its two ends only
        cp = cKDTree(touch).query_pairs(COUNTER_CLUSTER, output_type="ndarray")
        m = len(touch)
        nc, lab = connected_components(coo_matrix((np.ones(len(cp)), (cp[:, 0], cp[:, 1])) if len(cp) else
                                                  (np.zeros(0), (np.zeros(0, int), np.zeros(0, int))),
                                                  shape=(m, m)), directed=False)
        if nc != 2:
            continue
        p, q = touch[lab == 0].mean(axis=0), touch[lab == 1].mean(axis=0)
        span = float(np.hypot(*(q - p)))
        if not COUNTER_SPAN[0] <= span <= COUNTER_SPAN[1]:
            continue
        u = (q - p) / span
        rel = pts - p
        along = rel @ u
        across = np.abs(rel[:, 0] * u[1] - rel[:, 1] * u[0])
        if across.max() > COUNTER_DEPTH or along.min() < -COUNTER_DEPTH or along.max() > span + COUNTER_DEPTH:
            continue
        # the line between the ends crosses no wall (clear of the wall faces it starts and ends on)
        e = min(2 * COUNTER_CONTACT, span / 4)
        if _crossed(wall_segs, wall_box, p + u * e, q - u * e, set()):
            continue
        out.append(CadGeometry(layer="", kind="partition", coords=np.array([p, q]), entity="LINE", cls="counter"))
    return out


def counters_from_pieces(pieces, scale: float, rules, walls: Sequence[CadGeometry]) -> List[CadGeometry]:
    """``counter_partitions`` of an import's exploded pieces: the furniture lines are the pieces on furniture
    layers (the meaningful part of the layer name holds a furniture keyword of the rules' ``blocks``) or
    exploded from furniture blocks (``rules.block_class``), scaled to metres."""
    from .cad_explode import BLOCK_SEP
    from .layer_rules import keyword_in

    words = [w for w in getattr(rules, "blocks", {}).get("furniture", [])]
    layer_ok: Dict[str, bool] = {}
    chain_ok: Dict[str, bool] = {}
    furn = []
    for i in range(len(pieces.coords)):
        c = pieces.coords[i]
        if len(c) < 2 or pieces.filled[i]:
            continue
        lay = pieces.layer[i]
        ok = layer_ok.get(lay)
        if ok is None:
            low = meaningful_part(lay).lower()
            ok = layer_ok[lay] = any(keyword_in(w, low) for w in words)
        if not ok:
            chain = pieces.block[i]
            if chain:
                ok = chain_ok.get(chain)
                if ok is None:
                    ok = chain_ok[chain] = rules.block_class(chain.split(BLOCK_SEP))[0] == "furniture"
        if ok:
            furn.append(np.asarray(c, float) * scale)
    return counter_partitions(furn, [g for g in walls if g.kind in ("wall", "column")])


# --------------------------------------------------------------------------- walls on layers no rule names
STRAY_WALL_GAP = (0.05, 0.3)  # metres: the two faces of a partition wall
STRAY_WALL_MIN = 1.0  # metres: both faces at least this long, overlapping at least this much
STRAY_WALL_ANGLE = 3.0  # degrees: the faces are parallel within this
STRAY_WALL_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE")
STRAY_WALL_REACH = 0.3  # metres: both ends of the partition lie this close to the drawing's walls


def stray_wall_partitions(pieces, infos, scale: float, rules, walls: Sequence[CadGeometry] = ()) -> List[CadGeometry]:
    """Partition walls drawn on a layer no rule names (a CAD repair layer ``AUDIT_D_...``, ``修改`` = changes,
    a misc layer): two parallel faces (within ``STRAY_WALL_ANGLE``) ``STRAY_WALL_GAP`` apart, overlapping by at
    least ``STRAY_WALL_MIN``, on the same layer that no rule names (not excluded, no kind: text, furniture and
    dimension layers are excluded), outside door / window / furniture blocks, on no frozen or off layer; each
    face has no other parallel partner (stair treads and racks come in series) and both ends of the wall lie
    within ``STRAY_WALL_REACH`` of the drawing's walls (``walls``: a partition runs from wall to wall).
    They are not walls of the raster (the layer says nothing; guessing walls from unnamed layers would close
    doorways with their swings and leaves), but where two room names share the space one of them crosses,
    ``semantics.assign_names(partitions=...)`` splits it along the wall, with no passage across it when both
    rooms have a door of their own. Returns one line per wall (kind "partition", class "wall pair", metres, the
    centre line of the faces' overlap)."""
    from shapely import STRtree
    from shapely.geometry import Point

    from .cad_explode import BLOCK_SEP

    walls = [g for g in walls if g.kind in ("wall", "column")]
    ok_layer: Dict[str, bool] = {}
    ok_chain: Dict[str, bool] = {}
    segs, lay = [], []
    for i in range(len(pieces.coords)):
        if pieces.etype[i] not in STRAY_WALL_TYPES or pieces.filled[i] or len(pieces.coords[i]) < 2:
            continue
        name = pieces.layer[i]
        ok = ok_layer.get(name)
        if ok is None:
            info = infos.get(name)
            ok = ok_layer[name] = (info is not None and info.kind is None and info.rule == "no keyword"
                                   and not info.frozen and not info.off)
        if not ok:
            continue
        if i < len(pieces.dashed) and pieces.dashed[i]:
            continue  # a projection line
        chain = pieces.block[i]
        if chain:
            c_ok = ok_chain.get(chain)
            if c_ok is None:
                c_ok = ok_chain[chain] = rules.block_class(chain.split(BLOCK_SEP))[0] is None
            if not c_ok:
                continue
        s = _segments(np.asarray(pieces.coords[i], float) * scale, bool(pieces.closed[i]))
        if not len(s):
            continue
        d = s[:, 1] - s[:, 0]
        keep = np.hypot(d[:, 0], d[:, 1]) >= STRAY_WALL_MIN
        segs.append(s[keep])
        lay.extend([name] * int(keep.sum()))
    if not segs:
        return []
    segs = np.concatenate(segs)
    if len(segs) < 2:
        return []
    d = segs[:, 1] - segs[:, 0]
    length = np.hypot(d[:, 0], d[:, 1])
    u = d / length[:, None]
    out = []
    cos_min = math.cos(math.radians(STRAY_WALL_ANGLE))
    lines = _linestrings(list(segs))
    pi, pj = STRtree(lines).query(lines, predicate="dwithin", distance=STRAY_WALL_GAP[1])
    found = []
    for i, j in zip(pi.tolist(), pj.tolist()):
        if i >= j:
            continue
        if lay[i] != lay[j] or abs(float(u[i] @ u[j])) < cos_min:
            continue
        n = np.array([-u[i][1], u[i][0]])
        gap = abs(float((segs[j, 0] - segs[i, 0]) @ n))
        gap2 = abs(float((segs[j, 1] - segs[i, 0]) @ n))
        if not (STRAY_WALL_GAP[0] <= min(gap, gap2) and max(gap, gap2) <= STRAY_WALL_GAP[1]):
            continue
        t = sorted([0.0, float(length[i])])
        tj = sorted([float((segs[j, 0] - segs[i, 0]) @ u[i]), float((segs[j, 1] - segs[i, 0]) @ u[i])])
        lo, hi = max(t[0], tj[0]), min(t[1], tj[1])
        if hi - lo < STRAY_WALL_MIN:
            continue
        off = n * float(((segs[j, 0] + segs[j, 1]) / 2 - segs[i, 0]) @ n) / 2.0
        found.append((i, j, segs[i, 0] + u[i] * lo + off, segs[i, 0] + u[i] * hi + off))
    # a wall is two faces: a face with a second parallel partner is a series (stair treads, racks, a pattern)
    partners = np.bincount(np.array([k for i, j, _, _ in found for k in (i, j)], dtype=np.int64),
                           minlength=len(segs)) if found else np.zeros(len(segs), int)
    wall_lines = _linestrings([g.coords for g in walls if len(g.coords) >= 2])
    wtree = STRtree(wall_lines) if len(wall_lines) else None
    for i, j, p, q in found:
        if partners[i] != 1 or partners[j] != 1:
            continue
        # a partition runs from wall to wall: both ends on the walls (a free-standing pair is a rack, a bench)
        if wtree is None or any(not len(wtree.query(Point(*e), predicate="dwithin", distance=STRAY_WALL_REACH))
                                for e in (p, q)):
            continue
        out.append(CadGeometry(layer=lay[i], kind="partition", coords=np.array([p, q]), entity="LINE",
                               cls="wall pair"))
    return out
