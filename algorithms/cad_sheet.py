"""Whole sheets: find the floor plan(s) on a drawing sheet.

Architects deliver sheets, not plans: one drawing holds the floor plan with a title frame and title
block, legends, notes, enlarged details (stairs, WC, lifts) and sometimes two halves of the plan drawn
side by side. ``find_plans`` works on the imported structural geometry (metres, CAD frame):

1. **Frames** are left out: geometry on frame / title-block layers (rules ``sheet.frame`` keywords such
   as ``TK``, ``图框``, ``C-SHET``, ``title``, ``cartouche``) and long (>= 20 m) straight lines or
   rectangles that stand free (on >= 85 % of their length nothing else lies within 1 m: never a wall,
   which windows, partitions and its second line touch) and together enclose the drawing (>= half of the
   other geometry inside their box, spanning >= 10 % of it). Legend layers go too.
2. **Groups**: the remaining geometry is sampled every metre and clustered by single linkage with a gap
   of ``gap`` metres (5 m by default: views on a sheet are further apart than that; parts of one
   building are connected by walls, columns, glazing or stairs closer than that). Two halves of one
   floor drawn side by side with a clear gap stay two groups.
3. **Titles and kinds**: the tallest text in or just below a group that holds a title keyword titles
   it (``平面图``/plan/pianta/planta -> plan; ``详图``/``大样``/detail/dettaglio/enlarged/section -> detail;
   legend/``图例`` -> legend). Without a title keyword the wall mass decides: a group with less than
   15 % of the largest wall mass is a detail when it is less than a third of the largest extent, and
   ``other`` when larger (site outlines, glazing diagrams); a group under ``MIN_WALL`` metres of geometry
   or ``MIN_SIZE`` metres across is ``other`` (stray symbols, north arrows, scale bars). Islands inside a
   larger group's box (free-standing columns in a hall) belong to it unless titled as a detail; an
   untitled group with less than half of the main plan's wall mass within 15 m (3 gaps) of it is a wing of
   that plan (across a courtyard or an open hall) and joins it. Halves of a floor, of comparable wall mass,
   stay apart.
4. **Selection**: the plan with the largest wall mass is index 0 and is taken by default; the others
   follow by decreasing wall mass. ``plan`` picks another (an index, or an extent
   ``(xmin, ymin, xmax, ymax)`` in metres of the CAD frame). A sheet whose groups are all details, or
   with no plan-like geometry at all, raises an InputError that lists what was found.
"""
from __future__ import annotations

import math
import re
from typing import List, Optional, Sequence, Tuple, Union

import numpy as np

from .errors import InputError
from .layer_rules import LayerRules, keyword_in
from .model import CadGeometry, CadText, PlanInfo

GAP = 5.0  # metres of empty space that separates two views on a sheet
SAMPLE = 1.0  # metres between the sample points of the geometry
FRAME_MIN_LENGTH = 20.0  # metres: shorter lines are never taken for a frame
FRAME_FREE_DIST = 1.0  # metres: nothing this close to a frame line...
FRAME_FREE_SHARE = 0.85  # ...along this share of its length
FRAME_ENCLOSED = 0.5  # share of the other geometry a frame encloses
FRAME_FILLED = 0.1  # share of the frame's box the enclosed geometry spans at least
DETAIL_WALL_SHARE = 0.15  # of the largest group's wall mass
WING_SHARE = 0.5  # an untitled group with less wall than this share of the main plan...
WING_GAP = 3.0  # ...within this many gaps of it is a wing of that plan (halves of a floor are comparable)
DETAIL_SIZE_SHARE = 1.0 / 3.0  # of the largest group's extent (diagonal)
MIN_WALL = 8.0  # metres of geometry: smaller groups are stray symbols
MIN_SIZE = 3.0  # metres across
WALL_KINDS = ("wall", "column")
STRUCT_KINDS = ("wall", "column", "window", "stair", "elevator", "reference")

PlanArg = Union[None, int, str, Sequence[float]]


def parse_plan(plan: PlanArg) -> Union[None, int, Tuple[float, float, float, float]]:
    """``None``/"" -> default; an int or "2" -> index; "x0,y0,x1,y1" or 4 numbers -> an extent
    (QGIS extent strings "x0,x1,y0,y1 [crs]" are accepted too when given as a string with a CRS)."""
    if plan is None:
        return None
    if isinstance(plan, (int, np.integer)) and not isinstance(plan, bool):
        if plan < 0:
            raise InputError(f"PLAN must be 0 or more (0 = the main plan), got {plan}")
        return int(plan)
    if isinstance(plan, str):
        txt = plan.strip()
        if not txt or txt.lower() in ("auto", "default", "main"):
            return None
        qgis_order = "[" in txt  # QGIS extent parameter text: "xmin,xmax,ymin,ymax [EPSG:...]"
        txt = re.sub(r"\[.*\]", "", txt).strip()
        parts = [p for p in re.split(r"[,;\s]+", txt) if p]
        try:
            nums = [float(p) for p in parts]
        except ValueError:
            raise InputError(f"PLAN '{plan}' is neither a plan index (0 = main plan) nor an extent "
                             "'xmin,ymin,xmax,ymax' in metres") from None
        if len(nums) == 1 and float(nums[0]).is_integer() and nums[0] >= 0:
            return int(nums[0])
        if len(nums) != 4:
            raise InputError(f"PLAN '{plan}' is neither a plan index (0 = main plan) nor an extent "
                             "'xmin,ymin,xmax,ymax' in metres")
        if qgis_order:
            nums = [nums[0], nums[2], nums[1], nums[3]]
        plan = nums
    vals = [float(v) for v in plan]  # type: ignore[union-attr]
    if len(vals) != 4 or not all(math.isfinite(v) for v in vals):
        raise InputError(f"PLAN extent must be 4 numbers xmin, ymin, xmax, ymax, got {plan}")
    x0, y0, x1, y1 = vals
    if x1 <= x0 or y1 <= y0:
        raise InputError(f"PLAN extent ({x0}, {y0}, {x1}, {y1}) is empty: xmax must exceed xmin and ymax ymin")
    return (x0, y0, x1, y1)


# ------------------------------------------------------------------------------------------ sampling
def _samples(coords: np.ndarray, step: float) -> np.ndarray:
    c = coords[np.isfinite(coords).all(axis=1)]
    if len(c) < 2:
        return c
    seg = np.diff(c, axis=0)
    ln = np.hypot(seg[:, 0], seg[:, 1])
    n = np.maximum(1, np.ceil(ln / step).astype(np.int64))
    idx = np.repeat(np.arange(len(seg)), n)
    t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
    pts = c[idx] + seg[idx] * t[:, None]
    return np.vstack((pts, c[-1:]))


def _sample_all(geoms: Sequence[CadGeometry], idx, step: float):
    """Samples of many geometries at once: ``(points, owner index, length per owner)``; every vertex
    is a sample and segments are cut to at most ``step``."""
    idx = np.asarray(list(idx), dtype=np.int64)
    if not len(idx):
        return np.zeros((0, 2)), np.zeros(0, dtype=np.int64), np.zeros(0)
    coords = [geoms[i].coords for i in idx]
    lens = np.fromiter((len(c) for c in coords), dtype=np.int64, count=len(coords))
    allc = np.concatenate(coords, axis=0)
    own = np.repeat(idx, lens)
    ok = np.isfinite(allc).all(axis=1)
    # segments between consecutive rows of one geometry, both ends finite
    same = own[1:] == own[:-1]
    segok = same & ok[1:] & ok[:-1]
    a = allc[:-1][segok]
    seg = allc[1:][segok] - a
    sown = own[:-1][segok]
    ln = np.hypot(seg[:, 0], seg[:, 1])
    n = np.maximum(1, np.ceil(ln / step).astype(np.int64))
    rep_i = np.repeat(np.arange(len(seg)), n)
    t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
    pts = np.vstack((a[rep_i] + seg[rep_i] * t[:, None], allc[ok]))
    owner = np.concatenate((sown[rep_i], own[ok]))
    length = np.bincount(np.searchsorted(idx, sown), weights=ln, minlength=len(idx))
    return pts, owner, length


def _length(coords: np.ndarray) -> float:
    c = coords[np.isfinite(coords).all(axis=1)]
    if len(c) < 2:
        return 0.0
    return float(np.hypot(*np.diff(c, axis=0).T).sum())


def _straight_run(coords: np.ndarray) -> float:
    c = coords[np.isfinite(coords).all(axis=1)]
    if len(c) < 2:
        return 0.0
    return float(np.hypot(*np.diff(c, axis=0).T).max())


def _is_straightish(g: CadGeometry) -> bool:
    """A line, or a polyline of at most 5 vertices (a rectangle): the shapes of frames."""
    return g.entity in ("LINE", "LWPOLYLINE", "POLYLINE") and len(g.coords) <= 5 and not g.filled


# ------------------------------------------------------------------------------------------ frames
def frame_mask(geoms: Sequence[CadGeometry], rules: LayerRules) -> np.ndarray:
    """True for geometry that belongs to a title frame / block or a legend (by layer name or because
    it is a long straight line or rectangle standing free)."""
    from scipy.spatial import cKDTree

    n = len(geoms)
    out = np.zeros(n, dtype=bool)
    layer_hit = {}
    for i, g in enumerate(geoms):
        hit = layer_hit.get(g.layer)
        if hit is None:
            hit = layer_hit[g.layer] = rules.layer_is(g.layer, "frame") or rules.layer_is(g.layer, "legend")
        out[i] = hit
    rest_idx = np.flatnonzero(~out)
    allp, own, lens = _sample_all(geoms, rest_idx, FRAME_FREE_DIST)
    if not len(allp):
        return out
    cands = [int(i) for i, ln in zip(rest_idx, lens) if ln >= FRAME_MIN_LENGTH and _is_straightish(geoms[i])]
    if not cands:
        return out
    tree = cKDTree(allp)
    free_ids = []
    in_cset = np.zeros(len(geoms), dtype=bool)  # frame lines touch each other (corners) and are often drawn twice
    in_cset[cands] = True
    for i in cands:
        s = _samples(geoms[i].coords, 0.5)
        hits = tree.query_ball_point(s, FRAME_FREE_DIST)
        # samples whose every neighbour belongs to a candidate line (counted over all neighbours at once)
        n_hit = np.fromiter((len(h) for h in hits), dtype=np.int64, count=len(hits))
        flat = np.fromiter((j for h in hits for j in h), dtype=np.int64, count=int(n_hit.sum()))
        other = np.bincount(np.repeat(np.arange(len(hits)), n_hit)[~in_cset[own[flat]]], minlength=len(hits))
        free = int((other == 0).sum())
        if free >= FRAME_FREE_SHARE * len(s):
            free_ids.append(i)
    if not free_ids:
        return out
    # free lines far longer than the drawing itself (sheet borders, leaders across the sheet) go anyway
    lo, hi = np.percentile(allp, [2, 98], axis=0)
    robust = float(np.max(hi - lo))
    for i in free_ids:
        if _length(geoms[i].coords) > 2.0 * robust and _straight_run(geoms[i].coords) > 2.0 * robust:
            out[i] = True
    free_ids = [i for i in free_ids if not out[i]]
    if not free_ids:
        return out
    # the free lines are a frame only when they enclose the drawing: most other geometry lies inside
    # their box and fills a fair part of it (a lone room outline with a table in it is no frame)
    fc = np.concatenate([geoms[i].coords for i in free_ids])
    fc = fc[np.isfinite(fc).all(axis=1)]
    x0, y0 = fc.min(axis=0) + FRAME_FREE_DIST
    x1, y1 = fc.max(axis=0) - FRAME_FREE_DIST
    rest = allp[~np.isin(own, free_ids)]
    if x1 <= x0 or y1 <= y0 or not len(rest):
        return out
    inside = rest[(rest[:, 0] > x0) & (rest[:, 0] < x1) & (rest[:, 1] > y0) & (rest[:, 1] < y1)]
    if len(inside) < FRAME_ENCLOSED * len(rest):
        return out
    span = inside.max(axis=0) - inside.min(axis=0)
    if span[0] * span[1] < FRAME_FILLED * (x1 - x0) * (y1 - y0):
        return out
    out[free_ids] = True
    return out


# ------------------------------------------------------------------------------------------ groups
def _title_kinds(texts: Sequence[CadText], rules: LayerRules) -> List[Tuple[CadText, str]]:
    """The texts that hold a title keyword, with the kind they say (detail | legend | plan)."""
    out = []
    words = [(k, rules.sheet_words(key)) for key, k in
             (("detail_titles", "detail"), ("legend_titles", "legend"), ("plan_titles", "plan"))]
    for t in texts:
        low = t.text.lower()
        for k, ws in words:
            if any(keyword_in(w, low) for w in ws):
                out.append((t, k))
                break
    return out


def _title_of(ext, texts, rules: LayerRules) -> Tuple[str, str]:
    """(title text, kind from the title: plan | detail | legend | ""). ``texts``: CadTexts or the
    output of ``_title_kinds``."""
    if texts and not isinstance(texts[0], tuple):
        texts = _title_kinds(texts, rules)
    x0, y0, x1, y1 = ext
    size = max(x1 - x0, y1 - y0)
    m = max(3.0, 0.15 * size)
    best = None
    for t, kind in texts:
        if not (x0 - m <= t.x <= x1 + m and y0 - m <= t.y <= y1 + m):
            continue
        inside = x0 <= t.x <= x1 and y0 <= t.y <= y1
        # titles sit below or beside the view in large letters; a room name inside says "plan" rarely
        score = t.height * (1.0 if not inside else 0.5)
        if best is None or score > best[0]:
            best = (score, t.text, kind)
    if best is None:
        return "", ""
    return best[1], best[2]


# titles of elevations and sections (views drawn beside the plan on the same sheet, often only 1-2 m away)
ELEVATION_TITLE_WORDS = ("prospetto", "elevation", "elevacion", "elevación", "alzado", "fachada", "section",
                         "sezione", "seccion", "sección", "corte", "schnitt", "ansicht", "coupe", "façade",
                         "facade", "立面", "剖面", "разрез", "фасад")
ELEVATION_BAND = 1.5  # metres: an empty band this wide across a group separates an elevation from the plan
ELEVATION_TITLE_DIST = 3.0  # metres: the elevation's title lies this close to its drawing


def _elevation_titles(texts: Sequence[CadText], rules: LayerRules) -> np.ndarray:
    """(x, y) of the texts that title an elevation or a section (``ELEVATION_TITLE_WORDS``, and the rules'
    ``sheet.elevation_titles`` when given)."""
    words = list(ELEVATION_TITLE_WORDS) + [w.lower() for w in rules.sheet_words("elevation_titles")]
    pts = [(t.x, t.y) for t in texts if any(keyword_in(w, t.text.lower()) for w in words)]
    return np.array(pts, dtype=np.float64).reshape(-1, 2)


def _box_dist(pts: np.ndarray, box) -> np.ndarray:
    dx = np.maximum(np.maximum(box[0] - pts[:, 0], pts[:, 0] - box[2]), 0.0)
    dy = np.maximum(np.maximum(box[1] - pts[:, 1], pts[:, 1] - box[3]), 0.0)
    return np.hypot(dx, dy)


def _own_titles(tk, ext: np.ndarray) -> List[list]:
    """The title texts (``_title_kinds`` output) of each group (``ext`` rows): each text titles only the group
    whose extent lies nearest to it (an elevation's title below it is not the plan's, a few metres above)."""
    if not tk or len(ext) <= 1:
        return [list(tk) for _ in range(len(ext))]
    pts = np.array([(t.x, t.y) for t, _ in tk], dtype=np.float64)
    d = np.stack([_box_dist(pts, e) for e in ext], axis=1)
    d = np.where(np.isfinite(d), d, np.inf)
    near = np.argmin(d, axis=1)
    out: List[list] = [[] for _ in range(len(ext))]
    for i, j in enumerate(near):
        out[int(j)].append(tk[i])
    return out


def split_elevations(allp: np.ndarray, plab: np.ndarray, ncomp: int, texts: Sequence[CadText], rules: LayerRules,
                     band: float = ELEVATION_BAND) -> Tuple[np.ndarray, int, int]:
    """An elevation or section drawn close to the plan (closer than the sheet gap) joins it as one group: a
    group whose samples (``allp``, group ``plab``) fall apart across an empty band at least ``band`` wide
    (horizontal or vertical, across the whole group) into parts, one of which is titled as an elevation or
    section (the title text within ``ELEVATION_TITLE_DIST`` of that part and nearer to it than to the other
    parts), gets that part split off as a group of its own. Geometry samples are at most ``SAMPLE`` apart,
    so no geometry straddles such a band. Returns ``(plab, ncomp, number of parts split off)``."""
    tp = _elevation_titles(texts, rules)
    if not len(tp) or ncomp == 0:
        return plab, ncomp, 0
    plab = plab.copy()
    split = 0
    for k in range(ncomp):
        sel = np.flatnonzero(plab == k)
        if len(sel) < 4:
            continue
        pts = allp[sel]
        for axis in (1, 0):
            v = pts[:, axis]
            order = np.sort(np.unique(v))
            gaps = np.flatnonzero(np.diff(order) >= band)
            if not len(gaps):
                continue
            cuts = (order[gaps] + order[gaps + 1]) / 2.0
            part = np.searchsorted(cuts, v)
            boxes = [(pts[part == j, 0].min(), pts[part == j, 1].min(), pts[part == j, 0].max(),
                      pts[part == j, 1].max()) for j in range(len(cuts) + 1)]
            d = np.stack([_box_dist(tp, b) for b in boxes], axis=1)  # titles x parts
            near = np.argmin(d, axis=1)
            titled = {int(near[i]) for i in range(len(tp)) if d[i, near[i]] <= ELEVATION_TITLE_DIST}
            # the part with the most samples is the plan: never split off
            main = int(np.argmax(np.bincount(part, minlength=len(boxes))))
            titled.discard(main)
            if not titled:
                continue
            for j in sorted(titled):
                plab[sel[part == j]] = ncomp
                ncomp += 1
                split += 1
            break
    return plab, ncomp, split


ALIGN_SHEET = True  # a plan whose walls run at an angle to the CAD frame is grouped in the frame of its walls ...
ALIGN_MIN_DEG = 1.0  # ... when they are at least this far from the axes (degrees): 1 degree turns a 1.5 m band
#                     by 1.5 m over 86 m, the width of a large plan
ALIGN_MIN_COHERENCE = 0.25  # ... and have a dominant direction at all (see ``wall_direction``)


def wall_direction(geoms: Sequence[CadGeometry]) -> Tuple[float, float]:
    """The dominant direction of the wall geometry, modulo 90 degrees: ``(angle, coherence)``, ``angle`` in
    (-45, 45] degrees counter-clockwise in the CAD frame, ``coherence`` in [0, 1] (1: every wall segment
    parallel or square to it). Each segment of a wall-kind geometry votes with its length on its quadrupled
    angle (walls and the walls square to them agree)."""
    z = 0j
    total = 0.0
    for g in geoms:
        if g.kind not in WALL_KINDS or len(g.coords) < 2:
            continue
        d = np.diff(g.coords[:, :2], axis=0)
        d = d[np.isfinite(d).all(axis=1)]
        length = np.hypot(d[:, 0], d[:, 1])
        a = 4.0 * np.arctan2(d[:, 1], d[:, 0])
        z += complex(float((length * np.cos(a)).sum()), float((length * np.sin(a)).sum()))
        total += float(length.sum())
    if total <= 0:
        return 0.0, 0.0
    angle = math.degrees(math.atan2(z.imag, z.real) / 4.0)
    return (45.0 if angle <= -45.0 else angle), abs(z) / total


def find_plans(geoms: Sequence[CadGeometry], texts: Sequence[CadText], rules: LayerRules,
               plan: PlanArg = None, gap: float = GAP, progress=None):
    """Group the sheet's structural geometry into plans and select one.

    Returns ``(plans, keep_geom, keep_text, dropped_frames)``: ``plans`` a list of PlanInfo (index 0 =
    the default plan, the selected one flagged), boolean masks over ``geoms`` and ``texts`` of what lies
    in the selected plan, and the number of frame/legend geometries left out.

    The groups' boxes, the bands that split an elevation off and the titles' reach are taken along the
    axes: on a plan whose walls run at an angle (``ALIGN_MIN_DEG`` or more: a building drawn in site or
    survey coordinates, a turned sheet) they are taken along its walls' directions instead. The extents
    returned and the texts kept are in the CAD frame either way."""
    choice = parse_plan(plan)
    if ALIGN_SHEET and not isinstance(choice, tuple):
        angle, coherence = wall_direction(geoms)
        if abs(angle) >= ALIGN_MIN_DEG and coherence >= ALIGN_MIN_COHERENCE:
            c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            return _find_plans(geoms, texts, rules, plan, gap, turn=np.array(((c, -s), (s, c))))
    return _find_plans(geoms, texts, rules, plan, gap)


def _find_plans(geoms: Sequence[CadGeometry], texts: Sequence[CadText], rules: LayerRules,
                plan: PlanArg = None, gap: float = GAP, turn: Optional[np.ndarray] = None):
    """``find_plans``; ``turn`` (2x2, row vectors @ turn): the frame of the walls' directions, in which the
    elevation bands, the groups' boxes and the titles' reach are judged (None: the CAD frame)."""
    import dataclasses

    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    choice = parse_plan(plan)
    n = len(geoms)
    frames = frame_mask(geoms, rules)
    struct = np.array([(g.kind in STRUCT_KINDS) and not frames[i] for i, g in enumerate(geoms)], dtype=bool)
    sidx = np.flatnonzero(struct)
    allp, own, glen = _sample_all(geoms, sidx, SAMPLE)
    length_of = np.zeros(n)
    length_of[sidx] = glen
    if not len(allp):
        raise InputError("the sheet has no plan-like geometry: after leaving out title frames and legends, no wall, "
                         "column, window or stair geometry is left. Check the layer rules (listlayers) or pick the "
                         "wall layers with LAYERS")
    # single linkage on cells of gap/5: cells whose centres are within the gap are connected (so the
    # separating gap is resolved to +-30 %)
    cell = gap / 5.0
    keys = np.floor(allp / cell).astype(np.int64)
    keys -= keys.min(axis=0)
    flat = keys[:, 0] * (int(keys[:, 1].max()) + 1) + keys[:, 1]
    ukeys, inv = np.unique(flat, return_inverse=True)
    inv = inv.ravel()
    uniq = np.zeros((len(ukeys), 2), dtype=np.int64)
    uniq[inv] = keys
    ctree = cKDTree(uniq.astype(np.float64))
    pairs = ctree.query_pairs(r=5.0 + 1e-9, output_type="ndarray")
    m = len(uniq)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(m, m)) if len(pairs) else \
        coo_matrix((m, m))
    ncomp, clab = connected_components(graph, directed=False)
    plab = clab[inv]
    n_joined = ncomp
    allo, texts_d = allp, texts  # the CAD frame: the extents returned and the texts kept
    if turn is not None:  # boxes, bands and titles' reach along the walls' directions
        allp = allp @ turn
        tp = np.array([(t.x, t.y) for t in texts], dtype=np.float64).reshape(-1, 2) @ turn
        texts_d = [dataclasses.replace(t, x=float(x), y=float(y)) for t, (x, y) in zip(texts, tp)]
    plab, ncomp, _ = split_elevations(allp, plab, ncomp, texts_d, rules)
    # a geometry's samples are at most SAMPLE apart, so all of them fall in one group
    geom_group = np.full(n, -1, dtype=np.int64)
    geom_group[own] = plab
    gsel = np.flatnonzero(geom_group >= 0)
    is_wall = np.array([geoms[i].kind in WALL_KINDS for i in gsel], dtype=bool)
    total = np.bincount(geom_group[gsel], weights=length_of[gsel], minlength=ncomp)
    wall = np.bincount(geom_group[gsel[is_wall]], weights=length_of[gsel[is_wall]], minlength=ncomp)
    ext = np.tile(np.array([np.inf, np.inf, -np.inf, -np.inf]), (ncomp, 1))
    np.minimum.at(ext[:, 0], plab, allp[:, 0])
    np.minimum.at(ext[:, 1], plab, allp[:, 1])
    np.maximum.at(ext[:, 2], plab, allp[:, 0])
    np.maximum.at(ext[:, 3], plab, allp[:, 1])
    exto = ext.copy()
    if turn is not None:
        exto[:] = (np.inf, np.inf, -np.inf, -np.inf)
        np.minimum.at(exto[:, 0], plab, allo[:, 0])
        np.minimum.at(exto[:, 1], plab, allo[:, 1])
        np.maximum.at(exto[:, 2], plab, allo[:, 0])
        np.maximum.at(exto[:, 3], plab, allo[:, 1])
    mass = np.where(wall > 0, wall, 0.0)
    if mass.max() <= 0:  # no wall layer at all (spaghetti drawings on reference layers): all structure counts
        mass = total.copy()
    # islands inside a larger group's box (free-standing columns in a hall, a kiosk in an atrium) belong
    # to it, unless a title says they are a detail view
    tk = _title_kinds(texts_d, rules)
    own = _own_titles(tk, ext)
    titles = [_title_of(tuple(ext[k]), own[k], rules) for k in range(ncomp)]
    for k in range(n_joined, ncomp):  # elevations split off: never merged back as a wing
        titles[k] = (titles[k][0], "detail")
    parent = np.arange(ncomp)
    biggest0 = float(mass.max())

    def near(k, b, dist):
        # only b's samples around k's box can be within ``dist`` of k (a margin keeps rounding out): a tree of
        # those, not of the whole (large) group b, gives the same answer
        pk = allp[plab == k]
        pb = allp[plab == b]
        m = dist * 1.01 + 1e-6
        lo, hi = pk.min(axis=0) - m, pk.max(axis=0) + m
        pb = pb[(pb >= lo).all(axis=1) & (pb <= hi).all(axis=1)]
        if not len(pb):
            return False
        lo, hi = pb.min(axis=0) - m, pb.max(axis=0) + m  # and only k's samples around what is left of b
        pk = pk[(pk >= lo).all(axis=1) & (pk <= hi).all(axis=1)]
        tree = cKDTree(pb)
        for s0 in range(0, len(pk), 4096):  # stop at the first sample within reach
            d, _ = tree.query(pk[s0:s0 + 4096], distance_upper_bound=dist)
            if np.isfinite(d).any():
                return True
        return False

    for k in np.argsort(-mass):
        if titles[k][1] in ("detail", "legend"):
            continue
        for b in np.argsort(-mass):
            if b == k or mass[b] <= mass[k] or parent[b] != b:
                continue
            if ext[k, 0] >= ext[b, 0] and ext[k, 1] >= ext[b, 1] and ext[k, 2] <= ext[b, 2] and ext[k, 3] <= ext[b, 3]:
                parent[k] = b
                break
            # a wing: much less wall than a main plan close by (a courtyard or an open hall between)
            if not titles[k][1] and mass[k] < WING_SHARE * biggest0 <= mass[b] and near(k, b, WING_GAP * gap):
                parent[k] = b
                break
    if (parent != np.arange(ncomp)).any():
        for k in range(ncomp):
            r = k
            while parent[r] != r:
                r = parent[r]
            parent[k] = r
        uniq_roots, new = np.unique(parent, return_inverse=True)
        plab = new[plab]
        geom_group = np.where(geom_group >= 0, new[np.maximum(geom_group, 0)], -1)
        ext2 = np.tile(np.array([np.inf, np.inf, -np.inf, -np.inf]), (len(uniq_roots), 1))
        exto2 = ext2.copy()
        for k in range(ncomp):
            j = new[k]
            for e2, e1 in ((ext2, ext), (exto2, exto)):
                e2[j, :2] = np.minimum(e2[j, :2], e1[k, :2])
                e2[j, 2:] = np.maximum(e2[j, 2:], e1[k, 2:])
        wall, total, mass = (np.bincount(new, weights=v, minlength=len(uniq_roots)) for v in (wall, total, mass))
        ext, exto, ncomp = ext2, exto2, len(uniq_roots)
    infos = []
    own = _own_titles(tk, ext)
    biggest = float(mass.max())
    big = int(np.argmax(mass))
    big_diag = math.hypot(ext[big, 2] - ext[big, 0], ext[big, 3] - ext[big, 1])
    for k in range(ncomp):
        e = tuple(float(v) for v in ext[k])
        diag = math.hypot(e[2] - e[0], e[3] - e[1])
        title, tkind = _title_of(e, own[k], rules)
        if total[k] < MIN_WALL or diag < MIN_SIZE:
            kind = "other"
        elif tkind == "plan" and mass[k] < DETAIL_WALL_SHARE * biggest and diag < DETAIL_SIZE_SHARE * big_diag:
            kind = "detail"  # a key plan / site plan thumbnail: titled "plan", but a small view
        elif tkind:
            kind = tkind
        elif mass[k] < DETAIL_WALL_SHARE * biggest:
            # little wall mass: a small view is a detail; a large one (a site outline, glazing or
            # annotation diagrams) is no plan either
            kind = "detail" if diag < DETAIL_SIZE_SHARE * big_diag else "other"
        else:
            kind = "plan"
        infos.append([k, PlanInfo(index=-1, extent=tuple(float(v) for v in exto[k]), wall_length=round(float(mass[k]), 2),
                                  title=title, kind=kind)])
    if not any(info.kind != "other" for _, info in infos):
        # nothing on the sheet is plan-sized: a small drawing, not a sheet; keep it whole
        allc = np.concatenate([g.coords[np.isfinite(g.coords).all(axis=1)] for g in geoms])
        e = tuple(float(v) for v in (*allc.min(axis=0), *allc.max(axis=0)))
        title, _ = _title_of(e, texts, rules)
        whole = PlanInfo(index=0, extent=e, wall_length=round(float(mass.sum()), 2), title=title, kind="plan",
                         selected=choice in (None, 0))
        if choice is None or choice == 0:
            return [whole], ~frames, np.ones(len(texts), dtype=bool), int(frames.sum())
        if not isinstance(choice, tuple):
            raise InputError(f"PLAN={choice} does not exist: the drawing is one small plan ({describe_plans([whole])}); "
                             "use PLAN=0")
        infos = [[0, whole]]
        geom_group[:] = 0
    rank = {"plan": 0, "detail": 1, "legend": 2, "other": 3}
    infos.sort(key=lambda ki: (rank.get(ki[1].kind, 3), -ki[1].wall_length))
    for idx, (_, info) in enumerate(infos):
        info.index = idx
    plans = [info for _, info in infos]
    comp_of = {info.index: k for k, info in infos}
    texts_xy = np.array([(t.x, t.y) for t in texts], dtype=np.float64).reshape(-1, 2)
    if isinstance(choice, tuple):
        x0, y0, x1, y1 = choice
        keep = np.zeros(n, dtype=bool)
        for i, g in enumerate(geoms):
            c = g.coords[np.isfinite(g.coords).all(axis=1)]
            if len(c) and not frames[i] and c[:, 0].max() >= x0 and c[:, 0].min() <= x1 and \
                    c[:, 1].max() >= y0 and c[:, 1].min() <= y1:
                keep[i] = True
        if not keep.any():
            raise InputError(f"the PLAN extent ({x0:g}, {y0:g}, {x1:g}, {y1:g}) holds no drawing geometry. "
                             + describe_plans(plans))
        tkeep = (texts_xy[:, 0] >= x0) & (texts_xy[:, 0] <= x1) & (texts_xy[:, 1] >= y0) & (texts_xy[:, 1] <= y1)
        return plans, keep, tkeep, int(frames.sum())
    if choice is None:
        if not plans or plans[0].kind != "plan":
            found = describe_plans(plans)
            if not any(p.kind in ("plan", "detail") for p in plans):
                raise InputError("the sheet has no plan-like geometry (only frames, legends or stray symbols). "
                                 + found + " Check the layer rules (listlayers) or pick an extent with PLAN")
            raise InputError("the sheet's only plan-like groups are detail views, not a floor plan. " + found +
                             " Give PLAN=<index> to convert one of them anyway, or PLAN=xmin,ymin,xmax,ymax")
        sel = 0
    else:
        if choice >= len(plans):
            raise InputError(f"PLAN={choice} does not exist: the sheet has {len(plans)} group(s). "
                             + describe_plans(plans))
        sel = choice
    plans[sel].selected = True
    k = comp_of[sel]
    keep = geom_group == k
    # non-structural geometry kept by the import (doors when asked, hatches...) follows the nearest group
    others = np.flatnonzero((geom_group < 0) & ~frames)
    tree = cKDTree(allo)
    if len(others):
        cen = np.array([np.nanmean(geoms[i].coords, axis=0) for i in others])
        ok = np.isfinite(cen).all(axis=1)
        d, j = tree.query(np.where(ok[:, None], cen, 0.0), distance_upper_bound=gap)
        hit = ok & np.isfinite(d)
        jj = np.where(hit, j, 0)
        keep[others[hit & (plab[jj] == k)]] = True
    if len(texts_xy):
        d, j = tree.query(texts_xy, distance_upper_bound=gap)
        hit = np.isfinite(d)
        jj = np.where(hit, j, 0)
        x0, y0, x1, y1 = plans[sel].extent
        inside = (texts_xy[:, 0] >= x0) & (texts_xy[:, 0] <= x1) & (texts_xy[:, 1] >= y0) & (texts_xy[:, 1] <= y1)
        tkeep = (hit & (plab[jj] == k)) | (inside & ~hit)
    else:
        tkeep = np.zeros(0, dtype=bool)
    return plans, keep, tkeep, int(frames.sum())


def describe_plans(plans: Sequence[PlanInfo]) -> str:
    if not plans:
        return "No group of geometry was found."
    parts = []
    for p in plans[:12]:
        x0, y0, x1, y1 = p.extent
        parts.append(f"[{p.index}] {p.kind} {x1 - x0:.0f} x {y1 - y0:.0f} m at ({x0:.0f}, {y0:.0f}), "
                     f"{p.wall_length:.0f} m of walls" + (f", titled '{p.title[:40]}'" if p.title else ""))
    more = f"; … and {len(plans) - 12} more" if len(plans) > 12 else ""
    return f"Found {len(plans)} group(s): " + "; ".join(parts) + more + "."
