"""Typing areas as stairs or elevators from the stair and lift symbols of the drawing.

Stair runs (treads, handrails, arrows) and lift symbols (car outline and its cross) are drawn on their
own layers, which the layer rules classify as ``stair`` and ``elevator``. The rasterizer leaves them out
of the obstacles, so each stair core and lift shaft becomes an area; this module recognises those areas
by the density of symbol lines inside them (metres of line per square metre of floor). A stair run has
treads every ~0.3 m (about 3 m/m² over the run), a lift car its outline and two diagonals (about 1.5 m/m²
in a 2 x 2 m shaft), whereas a hall that merely contains a stair keeps a low density and stays a room.
Text labels refine this later (semantics stage).

Many drawings put the symbols on other layers (treads on the wall layer, lift crosses on a generic
layer), so the symbols are also found by their shape, whatever the layer:
- a **stair run** is at least ``MIN_TREADS`` parallel segments of similar length (0.8–3.5 m), side by
  side at a regular tread spacing (0.2–0.42 m) (:func:`find_stair_runs`);
- a **lift symbol** is a cross: two segments of similar length (1.2–4.3 m) crossing near both their
  midpoints at 40–140°, i.e. the diagonals of a car or shaft 1–3 m a side (:func:`find_lift_crosses`).
An area that holds most of a stair run becomes ``stairs``; the smallest area holding a lift cross
becomes ``elevator`` (when it is not much larger than the cross's box).

A plan reduced to its structure by turning layers off still holds its symbols: ``symbol_evidence`` adds the
drawing's hidden stair/lift lines and the lines of lift-named blocks (``cad_explode.kept_symbols``, read
when the drawing shows none) to the evidence, never to the walls; an elevator door symbol types the car-sized
box behind it (:func:`lift_door_boxes`).
"""
from __future__ import annotations

import math
import re
from typing import Dict, List, Sequence

import numpy as np
from shapely.geometry import LineString, MultiLineString, MultiPoint, Polygon
from shapely.strtree import STRtree

from .model import Area, CadGeometry

DENSITY = {"stairs": 0.6, "elevator": 0.5}
MIN_TREADS = 6
TREAD_LENGTH = (0.8, 3.5)  # metres
TREAD_SPACING = (0.2, 0.42)  # metres between consecutive treads
CROSS_LENGTH = (1.2, 4.3)  # metres: diagonals of a 0.85..3 m car/shaft  # metres of symbol line per m² of area, at least
MAX_LIFT_AREA = 30.0  # m²: the largest lift shaft (a group of cars); a larger area dense in lift-layer lines is not one
MAX_LIFT_ELONGATION = 4.0  # long / short side: a shaft is compact, a strip along a railing is not
KIND_TO_TYPE = {"stair": "stairs", "elevator": "elevator"}


def _lines(geometries: Sequence[CadGeometry], kind: str):
    """The geometries of ``kind`` as LineStrings (NaN ring separators dropped, closed ones closed),
    built in one vectorised call."""
    import shapely

    arrs = []
    for g in geometries:
        if g.kind != kind or len(g.coords) < 2:
            continue
        c = g.coords[~(g.coords != g.coords).any(axis=1)]  # drop NaN ring separators
        if len(c) >= 2:
            arrs.append(np.concatenate([c[:, :2], c[:1, :2]]) if g.closed else c[:, :2])
    if not arrs:
        return []
    xy = np.concatenate(arrs).astype(np.float64, copy=False)
    idx = np.repeat(np.arange(len(arrs)), [len(a) for a in arrs])
    return list(shapely.linestrings(xy, indices=idx))


class Symbols:
    """Straight segments, stair runs and lift crosses of one drawing's geometries, each found once and
    shared by the stair/lift typing (``classify_by_symbol_shapes``) and the carve (``anchors``)."""

    def __init__(self, geometries: Sequence[CadGeometry]):
        self.geometries = list(geometries)
        self._segments = self._runs = self._crosses = None

    def same(self, geometries: Sequence[CadGeometry]) -> bool:
        """``geometries`` are this drawing's (the very same objects, in order)."""
        return len(geometries) == len(self.geometries) and all(a is b for a, b in zip(geometries, self.geometries))

    @property
    def segments(self) -> np.ndarray:
        if self._segments is None:
            self._segments = _segments(self.geometries)
        return self._segments

    @property
    def runs(self):
        """``stair_runs`` of the geometries: [(rectangle, tread angle)]."""
        if self._runs is None:
            self._runs = stair_runs(self.geometries, segments=self.segments)
        return self._runs

    @property
    def crosses(self) -> List[Polygon]:
        if self._crosses is None:
            self._crosses = find_lift_crosses(self.geometries, segments=self.segments)
        return self._crosses


def classify_vertical_areas(areas: Sequence[Area], geometries: Sequence[CadGeometry],
                            density: Dict[str, float] = None, shapes: bool = True,
                            symbols: "Symbols" = None) -> Dict[int, str]:
    """Set ``type`` to "stairs"/"elevator" on areas dense in stair/lift symbols (symbol layers), then,
    with ``shapes``, on areas holding a stair run or a lift cross drawn on any layer. Returns {id: type}.
    ``symbols``: the drawing's ``Symbols`` of ``geometries`` when the caller shares them with the carve."""
    density = dict(DENSITY, **(density or {}))
    changed: Dict[int, str] = {}
    runs = None
    for kind, area_type in KIND_TO_TYPE.items():
        lines = _lines(geometries, kind)
        if not lines:
            continue
        tree = STRtree(lines)
        for a in areas:
            if a.type in ("stairs", "elevator") or a.polygon.area <= 0:
                continue
            hits = tree.query(a.polygon, predicate="intersects")
            if len(hits) == 0:
                continue
            inside = MultiLineString([lines[i] for i in hits]).intersection(a.polygon).length
            if inside / a.polygon.area >= density[area_type]:
                typ = area_type
                if area_type == "elevator":
                    # one layer for stairs, lifts and railings ('A—楼梯、电梯、栏杆') is read as a lift layer:
                    # an area of it holding a stair run (treads) is a stair
                    if runs is None:
                        runs = find_stair_runs([g for g in geometries if g.kind in ("stair", "elevator")])
                    if _holds_run(a.polygon, runs):
                        typ = "stairs"
                    elif a.polygon.area > MAX_LIFT_AREA or _elongation(a.polygon) > MAX_LIFT_ELONGATION:
                        continue  # a room or gallery dense in railings of that layer, not a shaft
                a.type = typ
                changed[a.id] = typ
    if any(t == "stairs" for t in changed.values()):
        _lift_cars_on_stair_layers(areas, geometries, changed, symbols)
    if shapes:
        changed.update(classify_by_symbol_shapes(areas, geometries, symbols=symbols))
    changed.update(lift_door_boxes(areas, geometries))
    changed.update(hidden_stair_marks(areas, geometries))
    return changed


STAIR_MARK_AREA = (6.0, 50.0)  # m²: a stair core (one dog-leg flight pair and its landings)
STAIR_MARK_LENGTH = 1.0  # metres of hidden stair line inside the core at least


def hidden_stair_marks(areas: Sequence[Area], geometries: Sequence[CadGeometry]) -> Dict[int, str]:
    """What a plan whose stair layer was turned off keeps of an enclosed stair core drawn without treads: its
    cut symbol (the zig-zag break line, an arrow) on the hidden stair layer (``cad_explode.HIDDEN_SYMBOL_CLS``;
    SIST-F2 marks three cores so). An untyped area holding ≥ ``STAIR_MARK_LENGTH`` of such lines,
    core-sized (``STAIR_MARK_AREA``, compact), is stairs. Only hidden lines count: a plan that shows its stair
    layer types by treads and density. Returns {id: "stairs"}."""
    from .cad_explode import HIDDEN_SYMBOL_CLS

    marks = [g for g in geometries if g.cls == HIDDEN_SYMBOL_CLS and g.kind == "stair"]
    lines = _lines(marks, "stair")
    if not lines:
        return {}
    cand = [a for a in areas if a.type not in ("stairs", "elevator", "structure")
            and STAIR_MARK_AREA[0] <= a.polygon.area <= STAIR_MARK_AREA[1]
            and _elongation(a.polygon) <= MAX_LIFT_ELONGATION]
    changed: Dict[int, str] = {}
    tree = STRtree(lines)
    for a in sorted(cand, key=lambda a: a.polygon.area):
        hits = tree.query(a.polygon, predicate="intersects")
        if not len(hits):
            continue
        if MultiLineString([lines[i] for i in hits]).intersection(a.polygon).length >= STAIR_MARK_LENGTH:
            a.type = "stairs"
            changed[a.id] = "stairs"
    return changed


LIFT_DOOR_GROUP = 0.3  # metres: lines of one elevator door symbol lie this close together
LIFT_CAR_AREA = (1.0, 12.0)  # m²: the box behind a lift door (one car's shaft: 0.9 x 1.2 m to 3 x 4 m)
LIFT_CAR_WIDTH = 0.8  # metres: narrower everywhere is a sliver, not a car


def symbol_evidence(drawing) -> List[CadGeometry]:
    """The geometries stair and lift areas are typed from: the drawing's, plus the stair / lift symbols it holds
    but hides (``CadDrawing.hidden_symbols``: off layers, lift-named blocks); the very same list when it hides
    none (``Symbols.same`` then holds for the carve)."""
    hidden = getattr(drawing, "hidden_symbols", None) or []
    return list(drawing.geometries) + list(hidden) if hidden else drawing.geometries


def lift_door_boxes(areas: Sequence[Area], geometries: Sequence[CadGeometry]) -> Dict[int, str]:
    """An elevator door symbol (the lines of a lift-named block, ``cad_explode.LIFT_DOOR_CLS``: 'Elevator -
    Single Side Open - 54_w x 96_h', nested in a bound xref or not) opens from a lobby into the lift: of the
    areas its symbol touches, the smallest car-sized one (``LIFT_CAR_AREA``, ``LIFT_CAR_WIDTH`` wide somewhere,
    compact) is the shaft behind the door, typed elevator, unless an area it touches is a lift already (a cross
    typed it). A door touching only larger areas (a car the segmentation merged into its lobby) types nothing.
    Returns {id: "elevator"}."""
    from shapely.ops import unary_union

    from .cad_explode import LIFT_DOOR_CLS

    doors = [LineString(g.coords[:, :2]) for g in geometries
             if g.cls == LIFT_DOOR_CLS and len(g.coords) >= 2 and np.isfinite(g.coords).all()]
    if not doors:
        return {}
    blobs = unary_union([d.buffer(LIFT_DOOR_GROUP / 2) for d in doors])
    blobs = list(getattr(blobs, "geoms", [blobs]))
    cand = [a for a in areas if a.type not in ("stairs", "structure") and a.polygon.area > 0]
    tree = STRtree([a.polygon for a in cand]) if cand else None
    changed: Dict[int, str] = {}
    for blob in blobs:
        if tree is None:
            break
        hits = [cand[i] for i in tree.query(blob, predicate="intersects")]
        if any(a.type == "elevator" for a in hits):
            continue
        cars = [a for a in hits if LIFT_CAR_AREA[0] <= a.polygon.area <= LIFT_CAR_AREA[1]
                and _elongation(a.polygon) <= MAX_LIFT_ELONGATION
                and not a.polygon.buffer(-LIFT_CAR_WIDTH / 2).is_empty]
        if cars:
            car = min(cars, key=lambda a: a.polygon.area)
            car.type = "elevator"
            changed[car.id] = "elevator"
    return changed


# a block named as a lift car: 电梯 / 客梯 (passenger) / 货梯 (goods), their pinyin initials (kt1, dt2, ht), lift, elevator
LIFT_BLOCK = re.compile(r"(lift|elev|aufzug|ascen|电梯|客梯|货梯|^(kt|dt|ht)[-_ ]?\d*[a-z]?$)", re.IGNORECASE)
LIFT_BLOCK_SHARE = 0.5  # of the stair-layer lines inside the area, at least this share (length) in lift-named blocks


def _lift_cars_on_stair_layers(areas: Sequence[Area], geometries: Sequence[CadGeometry], changed: Dict[int, str],
                               symbols: "Symbols" = None) -> None:
    """A lift car drawn on a stair layer (A-A3-10-04: lift A3-T3's car block ``kt1``, 客梯 1, sits on layer
    ``...$an-stairs``; on the floor above the same block is on ``A-EVTR``) made its shaft dense in stair lines:
    an area typed stairs here that holds no run of treads, is lift-sized (``MAX_LIFT_AREA``, compact) and whose
    stair-layer lines are mostly (``LIFT_BLOCK_SHARE``) a block named as a lift (``LIFT_BLOCK``), or that holds
    a lift cross, is an elevator. The mirror of ``anchors.retype_break_line_lifts``. ``changed`` in place."""
    cand = [a for a in areas if changed.get(a.id) == "stairs" and a.type == "stairs"
            and 0 < a.polygon.area <= MAX_LIFT_AREA and _elongation(a.polygon) <= MAX_LIFT_ELONGATION]
    if not cand:
        return
    if symbols is None or not symbols.same(geometries):
        symbols = Symbols(geometries)
    runs = [r for r, _ in symbols.runs]
    # as ``_lines`` keeps them (NaN ring separators dropped, at least two points), so indices match
    stair = [g for g in geometries if g.kind == "stair" and len(g.coords) >= 2
             and int((~(g.coords != g.coords).any(axis=1)).sum()) >= 2]
    lines = _lines(stair, "stair")
    if len(lines) != len(stair):
        return
    lifty = np.array([bool(LIFT_BLOCK.search((g.block or "").rsplit("$", 1)[-1].strip())) for g in stair])
    tree = STRtree(lines)
    for a in cand:
        if _holds_run(a.polygon, runs):
            continue
        cross = any(a.polygon.contains(b.centroid) and a.polygon.area <= 4.0 * b.area for b in symbols.crosses)
        if not cross:
            hits = tree.query(a.polygon, predicate="intersects")
            if not len(hits) or not lifty[hits].any():
                continue
            total = MultiLineString([lines[i] for i in hits]).intersection(a.polygon).length
            car = MultiLineString([lines[i] for i in hits if lifty[i]]).intersection(a.polygon).length
            if total <= 0 or car < LIFT_BLOCK_SHARE * total:
                continue
        a.type = "elevator"
        changed[a.id] = "elevator"


def _elongation(poly) -> float:
    r = poly.minimum_rotated_rectangle
    if r.geom_type != "Polygon":
        return float("inf")
    xy = np.asarray(r.exterior.coords)
    a, b = np.hypot(*(xy[1] - xy[0])), np.hypot(*(xy[2] - xy[1]))
    return max(a, b) / max(min(a, b), 1e-9)


def _holds_run(poly, runs) -> bool:
    """``poly`` holds most of one of the stair ``runs`` and that run is a real part of it."""
    for run in runs:
        if not run.intersects(poly):
            continue
        ov = poly.intersection(run).area
        if ov >= 0.5 * run.area and ov >= 0.15 * poly.area:
            return True
    return False


def _segments(geometries: Sequence[CadGeometry]) -> np.ndarray:
    """Every straight piece of every geometry as an (N, 2, 2) array (NaN rows split rings)."""
    gap = np.full((1, 2), np.nan)
    arrs = []
    for g in geometries:
        c = np.asarray(g.coords, float)
        if len(c) < 2:
            continue
        if g.closed:
            if np.isnan(c).any():  # several rings: close each one
                for part in np.split(c, np.where(np.isnan(c).any(axis=1))[0]):
                    part = part[~np.isnan(part).any(axis=1)]
                    if len(part) >= 2:
                        arrs += [part, part[:1], gap]
                continue
            arrs += [c, c[:1], gap]
        else:
            arrs += [c, gap]
    if not arrs:
        return np.zeros((0, 2, 2))
    allc = np.concatenate(arrs)
    seg = np.stack([allc[:-1], allc[1:]], axis=1)
    return seg[~np.isnan(seg).any(axis=(1, 2))]


def find_stair_runs(geometries: Sequence[CadGeometry], min_treads: int = MIN_TREADS, segments=None) -> List[Polygon]:
    """Stair runs drawn as treads on any layer: clusters of >= ``min_treads`` parallel segments of similar
    length side by side at a regular tread spacing. Returns each run's minimum rotated rectangle."""
    return [r for r, _ in stair_runs(geometries, min_treads, segments)]


def stair_runs(geometries: Sequence[CadGeometry], min_treads: int = MIN_TREADS, segments=None):
    """``find_stair_runs`` with each run's tread direction: [(rectangle, angle of the treads in radians,
    modulo pi)]. A flight is entered and left across its treads' direction (its first and last tread)."""
    import shapely
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    S = _segments(geometries) if segments is None else segments
    if len(S) < min_treads:
        return []
    L = np.linalg.norm(S[:, 1] - S[:, 0], axis=1)
    m = (L >= TREAD_LENGTH[0]) & (L <= TREAD_LENGTH[1])
    S, L = S[m], L[m]
    if len(S) < min_treads:
        return []
    ang = np.arctan2(S[:, 1, 1] - S[:, 0, 1], S[:, 1, 0] - S[:, 0, 0]) % np.pi
    mid = S.mean(axis=1)
    pairs = cKDTree(mid).query_pairs(TREAD_SPACING[1] + 0.05, output_type="ndarray")
    if len(pairs) == 0:
        return []
    i, j = pairs[:, 0], pairs[:, 1]
    da = np.abs(ang[i] - ang[j])
    da = np.minimum(da, np.pi - da)
    dl = np.abs(L[i] - L[j]) / np.maximum(L[i], L[j])
    u = np.stack([np.cos(ang[i]), np.sin(ang[i])], 1)
    dm = mid[j] - mid[i]
    along = np.abs((dm * u).sum(1))
    perp = np.abs(dm[:, 0] * u[:, 1] - dm[:, 1] * u[:, 0])
    ok = (da < math.radians(3)) & (dl < 0.15) & (perp >= TREAD_SPACING[0]) & (perp <= TREAD_SPACING[1]) & \
        (along < 0.3 * np.minimum(L[i], L[j]))
    n = len(S)
    _, lab = connected_components(coo_matrix((np.ones(int(ok.sum())), (i[ok], j[ok])), shape=(n, n)), directed=False)
    runs = []
    # only components of >= min_treads segments, in label order, each with its indices ascending (one
    # np.where per component over every segment was quadratic: most segments are components of their own)
    sizes = np.bincount(lab)
    order = np.argsort(lab, kind="stable")
    starts = np.concatenate([[0], np.cumsum(sizes)])
    for c in np.flatnonzero(sizes >= min_treads).tolist():
        idx = order[starts[c]:starts[c + 1]]
        # regular spacing: offsets along the run's normal, sorted, have a steady step
        a0 = ang[idx[0]]
        normal = np.array([-math.sin(a0), math.cos(a0)])
        off = np.sort(mid[idx] @ normal)
        steps = np.diff(off)
        steps = steps[steps > 0.05]
        if len(steps) < min_treads - 1 or np.std(steps) > 0.25 * np.mean(steps):
            continue
        # the points in one vectorised call (MultiPoint() of an array builds a Point per row in Python)
        runs.append((shapely.multipoints(S[idx].reshape(-1, 2)).minimum_rotated_rectangle, float(a0)))
    return runs


def find_lift_crosses(geometries: Sequence[CadGeometry], segments=None) -> List[Polygon]:
    """Lift symbols drawn as a cross on any layer: two segments of similar length crossing near both
    their midpoints at 40-140 degrees. Returns the box the cross spans (its four end points)."""
    from scipy.spatial import cKDTree

    S = _segments(geometries) if segments is None else segments
    if len(S) < 2:
        return []
    L = np.linalg.norm(S[:, 1] - S[:, 0], axis=1)
    m = (L >= CROSS_LENGTH[0]) & (L <= CROSS_LENGTH[1])
    S, L = S[m], L[m]
    if len(S) < 2:
        return []
    mid = S.mean(axis=1)
    pairs = cKDTree(mid).query_pairs(0.15 * CROSS_LENGTH[1], output_type="ndarray")
    if len(pairs):
        # the tests below that need no state, on every pair at once (same arithmetic); the loop keeps the rest
        pi, pj = pairs[:, 0], pairs[:, 1]
        ok = ~(np.abs(L[pi] - L[pj]) > 0.15 * np.maximum(L[pi], L[pj]))
        ok &= ~(np.hypot(*(mid[pi] - mid[pj]).T) > 0.1 * np.minimum(L[pi], L[pj]))
        pairs = pairs[ok]
    out, used = [], set()
    for i, j in pairs.tolist():
        if i in used or j in used:
            continue
        if abs(L[i] - L[j]) > 0.15 * max(L[i], L[j]):
            continue
        if np.hypot(*(mid[i] - mid[j])) > 0.1 * min(L[i], L[j]):
            continue
        di, dj = (S[i, 1] - S[i, 0]) / L[i], (S[j, 1] - S[j, 0]) / L[j]
        cosang = abs(float(di @ dj))
        if cosang > math.cos(math.radians(40)):
            continue
        box = MultiPoint(np.vstack([S[i], S[j]])).convex_hull
        if box.geom_type != "Polygon" or not (0.7 <= box.area <= 9.5):
            continue
        used.update((i, j))
        out.append(box)
    return out


def classify_by_symbol_shapes(areas: Sequence[Area], geometries: Sequence[CadGeometry],
                              symbols: "Symbols" = None) -> Dict[int, str]:
    """Type areas from stair runs and lift crosses found by shape on any layer (see the module doc).
    Areas already typed stairs/elevator are left alone. Returns {id: type}."""
    changed: Dict[int, str] = {}
    cand = [a for a in areas if a.type not in ("stairs", "elevator") and a.polygon.area > 0]
    if not cand:
        return changed
    tree = STRtree([a.polygon for a in cand])
    if symbols is None or not symbols.same(geometries):
        symbols = Symbols(geometries)
    for run in [r for r, _ in symbols.runs]:
        hits = tree.query(run, predicate="intersects")
        best, share = None, 0.0
        for h in hits:
            a = cand[int(h)]
            ov = a.polygon.intersection(run).area
            if ov > share:
                best, share = a, ov
        # the area holds most of the run, and the run is a real part of the area (not a hall with a stair)
        if best is not None and share >= 0.5 * run.area and share >= 0.25 * best.polygon.area:
            best.type = "stairs"
            changed[best.id] = "stairs"
    for box in symbols.crosses:
        c = box.centroid
        hits = [cand[int(h)] for h in tree.query(c, predicate="intersects")]
        hits = [a for a in hits if a.id not in changed and a.polygon.area <= 4.0 * box.area]
        if hits:
            a = min(hits, key=lambda x: x.polygon.area)
            a.type = "elevator"
            changed[a.id] = "elevator"
    return changed
