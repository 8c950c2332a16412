"""Stairs and lifts as areas of their own: carving vertical anchors out of the areas that swallowed them.

A robot routes between floors through stair cores and lift shafts, so the fusion of floors (``building``)
needs every stair and lift the drawing shows as an area typed stairs / elevator. Segmentation makes an
area of a space closed by walls; a stair or lift that is *open* to the space around it is swallowed:

- an open stair inside an atrium or hall (no wall around it),
- a lift shaft opening straight onto a corridor with no door (the shaft is as wide as its opening),
- a stair core whose landing runs into a corridor (the corridor and stair are one area).

This stage finds the symbols the drawing shows (stair runs: treads on any layer, ``area_types.find_stair_runs``,
including treads on wall layers that ``cad_classify.free_stair_treads`` turned into stair lines; lift cars:
their cross, ``area_types.find_lift_crosses``) and, when one lies inside a larger area, carves its
**footprint** out of that area into an area of its own:

- footprint = the (oriented) hull of the stair's runs (flights closer than ``GROUP_GAP`` are one stair) or of
  the lift group's crosses, each side pushed out to the wall it faces when that wall is within reach
  (``LANDING`` m for a stair: the landing between the last tread and the wall; ``SHAFT_REACH`` m for a lift:
  the gap between car and shaft wall) on at least ``WALL_HIT_SHARE`` of the side. A side with no wall
  within reach (the open end of a stair, the front of a lift) runs on between the walls left and right of it
  while they stay within ``SIDE_SLACK`` of the footprint (the landing inside a core up to its mouth onto a
  corridor), and stays at the symbol when there are none (an open stair in a hall).
- the rest of the area stays as it was (its id, type and passages), split into pieces when the footprint
  cuts it in two; slivers thinner than ``MIN_PIECE_WIDTH`` or smaller than ``MIN_PIECE_AREA`` go to the
  footprint.
- a stair standing free in a hall (no wall within reach: an island) is never a cut through the hall: the hall
  goes round it, one ring opened by a ``SLIT`` (1 cm) along the shortest way from the stair's side to the
  hall's outer border, off the stair's ends and the hall's doors (``_keyhole``; an osmAG area is one closed
  way, a hole would be dropped). When the run's treads go on beyond it (a curved or fanned flight,
  ``_continuing``), the stair is the whole flight: its treads chained one to the next and the area between
  neighbouring treads (``_flight_ribbon``), entered across its two end treads.
- a passage joins the footprint and each piece along every straight stretch of their common boundary (the
  open sides), and the area's old passages go to the piece they lie on.

Never carves a hall into a stair: the area is carved only when the rest keeps at least
``MIN_REST_SHARE`` of it (otherwise the area *is* the stair core or shaft and is only typed, when it is not
yet). A stair or lift that already is its own area (the footprint covers most of an area already typed so)
is left alone. A stair the plan's outline (not a wall) cuts through, with at least ``STRADDLE_SHARE`` of it
in one area and the rest beyond every area, is carved whole from that area (the stair at a bridge's or
terrace's edge). A lift needs walls: a cross with no wall within reach on at least two sides (a void marked
with a cross in a hall) is not a lift.
"""
from __future__ import annotations

import math
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
from shapely.geometry import LineString, MultiPolygon, Polygon
from shapely.ops import linemerge, unary_union

from .area_types import find_lift_crosses, stair_runs, _segments
from .model import Area, CadGeometry, Passage
from .progress import ensure
from .rasterize import repaint_polygon

ANCHOR_TYPES = ("stairs", "elevator")
GROUP_GAP = {"stairs": 0.8, "elevator": 0.6}  # m: symbols this close are one stair (flights + eye) / lift group
FLIGHT_GAP = 1.6  # m: runs of parallel treads this close are one flight (interrupted by a break line, an arrow)
LANDING_GAP = 3.0  # m: runs of parallel treads in line (same width band) this close are flights of one stair
LANDING = 1.8  # m: a stair's side is pushed to a wall up to this far (landing, or the flight's side gap)
SHAFT_REACH = 0.8  # m: a lift car's side is pushed to the shaft wall up to this far
WALL_HIT_SHARE = 0.3  # share of a side's rays that must meet a wall within reach for the side to move
MIN_REST_SHARE = 0.3  # the area keeps at least this share after the carve, else it is the stair/lift itself
ALREADY_OWN = 0.5  # a footprint covering this share of an area of its own type: the anchor is that area
OWN_MAX_AREA = {"stairs": 40.0, "elevator": 12.0}  # m²: an area typed so from its symbols and no larger is a
# stair core / lift shaft of its own, whatever part of it the symbols cover (a core split by a middle wall)
CONTINUING_TREADS = 3  # tread-like lines (within 25°, 40 % of its width) up to 0.9 m beyond a run: the flight goes on (curved), the run is a part
BREAK_GAP = 0.3  # m: a cross this close to a stair run is the flight's break line, not a lift
LANDING_PIECE_MAX = 40.0  # m²: a piece enclosed by a stair's footprint and walls up to this size is its landing
MIN_PIECE_AREA = 2.0  # m²: smaller leftover pieces join the footprint
MIN_PIECE_WIDTH = 0.35  # m: leftover pieces with no point farther than this from their border join it
MIN_PASSAGE = 0.5  # m: shorter open stretches between footprint and rest are no passage
WALL_FILL = 0.3  # m: walls up to 2 x this thick inside a stair's box (between its flights) belong to the stair
SIDE_SLACK = 0.3  # m: a landing runs on while the walls left and right stay this close to the symbol's sides
MIN_LIFT_WALLS = 2  # sides of a lift footprint that must meet a wall within reach


def _oriented_box(geom) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(centre, u, v, half) of the minimum rotated rectangle of ``geom``: axes u, v and half extents."""
    r = geom.minimum_rotated_rectangle
    xy = np.asarray(r.exterior.coords)[:4] if r.geom_type == "Polygon" else np.asarray(geom.envelope.exterior.coords)[:4]
    e1, e2 = xy[1] - xy[0], xy[2] - xy[1]
    l1, l2 = float(np.hypot(*e1)), float(np.hypot(*e2))
    u = e1 / max(l1, 1e-9)
    v = e2 / max(l2, 1e-9)
    c = xy.mean(axis=0)
    return c, u, v, np.array([l1 / 2.0, l2 / 2.0])


def _box_polygon(c, u, v, lo, hi) -> Polygon:
    """Rectangle c + s*u + t*v for s in [lo0, hi0], t in [lo1, hi1]."""
    pts = [c + lo[0] * u + lo[1] * v, c + hi[0] * u + lo[1] * v, c + hi[0] * u + hi[1] * v, c + lo[0] * u + hi[1] * v]
    return Polygon(pts)


def _wall_distances(boundary, starts: np.ndarray, direction: np.ndarray, reach: float) -> np.ndarray:
    """Distance from each start point along ``direction`` to the first crossing of ``boundary`` (inf when
    none within ``reach``)."""
    import shapely

    out = np.full(len(starts), np.inf)
    if not len(starts):
        return out
    starts = np.asarray(starts, dtype=float)
    # every ray in one vectorised intersection (the crossings' coordinates, points and overlaps alike)
    rays = shapely.linestrings(np.stack([starts, starts + direction * reach], axis=1))
    xy, idx = shapely.get_coordinates(shapely.intersection(rays, boundary), return_index=True)
    for k in np.unique(idx).tolist():
        pts = xy[idx == k]
        out[k] = float(np.min(np.hypot(*(pts - starts[k]).T)))
    return out


def footprint(symbol, host: Polygon, reach: float, min_walls: int = 0) -> Optional[Tuple[Polygon, int]]:
    """The anchor's footprint in ``host``: the symbol's oriented box with each side pushed to the wall (the
    host's border) it faces within ``reach``. Returns (polygon, number of sides that met a wall), or None."""
    c, u, v, half = _oriented_box(symbol)
    lo, hi = -half.copy(), half.copy()
    boundary = host.boundary
    walls = 0
    n = 9
    hit, opened = {}, []
    for axis in (0, 1):
        ax, other = (u, v) if axis == 0 else (v, u)
        oh = half[1 - axis]
        ts = np.linspace(-oh * 0.9, oh * 0.9, n)
        for sign in (1.0, -1.0):
            edge = half[axis] * sign
            starts = c[None, :] + edge * ax[None, :] + ts[:, None] * other[None, :]
            # start just inside the box: a wall right on the symbol's edge counts (distance ~0)
            back = 0.05
            d = _wall_distances(boundary, starts - sign * back * ax[None, :], sign * ax, reach + back) - back
            hits = d[np.isfinite(d)]
            hit[(axis, sign)] = len(hits) >= WALL_HIT_SHARE * n
            if not hit[(axis, sign)]:
                opened.append((axis, sign, True))
            if len(hits) >= WALL_HIT_SHARE * n:
                walls += 1
                push = float(np.clip(np.median(hits), 0.0, reach))
                if sign > 0:
                    hi[axis] = edge + push
                else:
                    lo[axis] = edge - push
    if walls < min_walls:
        return None
    # a side with no wall in front (the core's mouth onto a corridor): the landing still runs on between the
    # walls on its left and right, up to where they stop (the space widens)
    for axis, sign, open_side in opened:
        if not (hit[(1 - axis, 1.0)] and hit[(1 - axis, -1.0)]):
            continue
        ax, other = (u, v) if axis == 0 else (v, u)
        edge = hi[axis] if sign > 0 else lo[axis]
        span_hi, span_lo = hi[1 - axis], -lo[1 - axis]
        last = 0.0
        for step in np.arange(0.1, reach + 1e-9, 0.1):
            p = c + (edge + sign * step) * ax
            d_hi = _wall_distances(boundary, p[None, :], other, span_hi + 2 * SIDE_SLACK)[0]
            d_lo = _wall_distances(boundary, p[None, :], -other, span_lo + 2 * SIDE_SLACK)[0]
            if not (d_hi <= span_hi + SIDE_SLACK and d_lo <= span_lo + SIDE_SLACK):
                break
            last = step
        if last > 0:
            if sign > 0:
                hi[axis] = edge + last
            else:
                lo[axis] = edge - last
    box = _box_polygon(c, u, v, lo, hi)
    fp = box.intersection(host)
    if fp.is_empty:
        return None
    core = symbol.intersection(host)
    parts = [g for g in getattr(fp, "geoms", [fp]) if g.geom_type == "Polygon" and g.area > 0]
    if not parts:
        return None
    best = max(parts, key=lambda g: (g.intersection(core).area if not core.is_empty else 0.0, g.area))
    # walls inside the stair (the wall between two flights, the eye's railing) are part of its footprint, as an
    # enclosed core's outline holds them: gaps narrower than 2 x WALL_FILL inside the box are closed
    closed = best.buffer(WALL_FILL, join_style=2).buffer(-WALL_FILL, join_style=2).intersection(box)
    closed = unary_union([closed, best])
    if closed.geom_type == "Polygon" and closed.is_valid:
        best = closed
    return best, walls


def _extent(poly: Polygon, t: np.ndarray) -> float:
    xy = np.asarray(poly.exterior.coords)
    proj = xy @ t
    return float(proj.max() - proj.min())


def _groups(shapes: Sequence[Polygon], gap: float, angles=None, flight_gap: float = 0.0,
            landing_gap: float = 0.0) -> List[Tuple[Polygon, tuple]]:
    """Symbols closer than ``gap`` merged (and runs of parallel treads closer than ``flight_gap``: one flight
    whose treads a break line or an arrow interrupts; or in line and closer than ``landing_gap``: flights
    with a landing between): each group's convex hull and its members' ``angles``."""
    n = len(shapes)
    if not n:
        return []
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i in range(n):
        for j in range(i + 1, n):
            d = shapes[i].distance(shapes[j])
            same = False
            if angles is not None and d < max(flight_gap, landing_gap):
                da = abs(angles[i] - angles[j]) % math.pi
                same = min(da, math.pi - da) < math.radians(5)
                if same and d >= flight_gap:
                    # farther apart: one stair only when in line (flights with a landing between, climbing on)
                    t = np.array([math.cos(angles[i]), math.sin(angles[i])])
                    ci, cj = np.asarray(shapes[i].centroid.coords[0]), np.asarray(shapes[j].centroid.coords[0])
                    width = min(_extent(shapes[i], t), _extent(shapes[j], t))
                    same = abs(float((cj - ci) @ t)) < 0.5 * width
            if d < gap or same:
                parent[find(i)] = find(j)
    out = []
    for root in sorted({find(i) for i in range(n)}):
        idx = [k for k in range(n) if find(k) == root]
        out.append((unary_union([shapes[k] for k in idx]).convex_hull,
                    tuple(angles[k] for k in idx) if angles is not None else ()))
    return out


def find_anchor_symbols(geometries: Sequence[CadGeometry], shapes=None) -> List[Tuple[str, Polygon, tuple, object]]:
    """Stair footprints' cores (runs of treads, flights of one stair grouped) and lift groups (crosses)
    the drawing shows, on any layer: [(kind, hull, tread angles (stairs; radians modulo pi), the flight when
    treads continue beyond the hull (a curved or fanned flight: (footprint, end treads), True when none can be
    drawn; None (or False) otherwise))]. ``shapes``: the drawing's ``area_types.Symbols`` (segments,
    runs and crosses found once for the typing), used when they are of the same geometries."""
    geoms = [g for g in geometries if g.kind != "boundary"]
    if shapes is None or not shapes.same(geoms):
        from .area_types import Symbols

        shapes = Symbols(geoms)
    segs = shapes.segments
    runs = shapes.runs
    groups = _groups([r for r, _ in runs], GROUP_GAP["stairs"], [a for _, a in runs], FLIGHT_GAP, LANDING_GAP)
    out = [("stairs", g, a) for g, a in groups]
    curved = _continuing(groups, segs)
    # a cross on or beside a flight is its break line (the cut of the plan through the flight), not a lift car
    crosses = [b for b in shapes.crosses if not any(b.distance(r) < BREAK_GAP for r, _ in runs)]
    out += [("elevator", g, ()) for g, _ in _groups(crosses, GROUP_GAP["elevator"])]
    return [(k, g, a, curved[i] if i < len(groups) else None) for i, (k, g, a) in enumerate(out)]


def _continuing(groups, segs: np.ndarray) -> list:
    """Per stair group: do tread-like segments (tread length, within 40 % of the group's treads) continue
    beyond it, just outside its hull (>= CONTINUING_TREADS of them within 0.6 m)? Then the straight run is
    part of a curved (or winding, or fanned) flight the box does not describe, and the group's entry is that
    flight (``_flight_ribbon``: its footprint and its end treads), or True when no footprint can be drawn;
    else None."""
    import shapely
    from shapely import STRtree, points

    from .area_types import TREAD_LENGTH

    out: list = []
    if not len(segs):
        return [None] * len(groups)
    L = np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1)
    keep = L >= 0.6 * TREAD_LENGTH[0]
    S, L = segs[keep], L[keep]
    A = np.arctan2(S[:, 1, 1] - S[:, 0, 1], S[:, 1, 0] - S[:, 0, 0]) % math.pi
    mids = points(S.mean(axis=1))
    tree = STRtree(mids)
    lines = None
    for hull, angles in groups:
        if not len(S) or not angles:
            out.append(None)
            continue
        t = np.array([math.cos(angles[0]), math.sin(angles[0])])
        width = _extent(hull, t)
        inner = hull.buffer(0.05)
        n = 0
        for i in tree.query(hull.buffer(0.9), predicate="contains"):
            if _angle_diff(A[i], angles[0]) <= math.radians(25) and abs(L[i] - width) <= 0.4 * width and \
                    not inner.contains(mids[i]):
                n += 1
        if n < CONTINUING_TREADS:
            out.append(None)
            continue
        if lines is None:
            lines = shapely.linestrings(S)  # the segments as lines, once for every flight
        ribbon = _flight_ribbon(hull, angles[0], S, L, A, lines, tree)
        out.append(ribbon if ribbon is not None else True)
    return out


TREAD_STEP = 0.6  # m: a tread this close to a tread of the flight (and within 25°, 40 % of its length) continues it
FLIGHT_MAX_TREADS = 60  # a chain of treads longer than this is no flight (a hatch, a grid of parallel lines)
FLIGHT_MAX_AREA = 80.0  # m²: a flight's footprint larger than this is no flight (as names' vertical_max_area)
RIBBON_CONVEX = 0.9  # a flight's footprint covering this share of its convex hull is that hull (no curve)


def _flight_ribbon(hull: Polygon, angle: float, S: np.ndarray, L: np.ndarray, A: np.ndarray, lines, tree
                   ) -> Optional[Tuple[Polygon, object]]:
    """The footprint of the flight a straight run (``hull``, treads at ``angle``) is part of: its treads, and
    the tread-like segments continuing it one by one (each within ``TREAD_STEP`` of a tread already in, within
    25° of it and of a length within 40 % of its: the treads of a fanned or curved flight turn and lengthen
    little by little), joined pairwise (the quadrilateral between two neighbouring treads): the area between
    the flight's strings, following their curve; and its end treads (those lying along that footprint's
    border: where the flight is entered and left). None when the chain is no flight (longer than
    ``FLIGHT_MAX_TREADS`` treads, a footprint over ``FLIGHT_MAX_AREA`` or not one piece, not two ends)."""
    import shapely

    inner = hull.buffer(0.05)
    cand = tree.query(inner, predicate="contains")
    members = [int(i) for i in cand if _angle_diff(A[i], angle) <= math.radians(25)]
    if len(members) < 2:
        return None
    inside = set(members)
    frontier = list(members)
    while frontier:
        if len(inside) > FLIGHT_MAX_TREADS:
            return None
        i = frontier.pop()
        for j in tree.query(shapely.buffer(lines[i], TREAD_STEP + 0.5 * L[i]), predicate="contains"):
            j = int(j)
            if j in inside or _angle_diff(A[j], A[i]) > math.radians(25) or abs(L[j] - L[i]) > 0.4 * L[i]:
                continue
            if shapely.distance(lines[i], lines[j]) > TREAD_STEP:
                continue
            inside.add(j)
            frontier.append(j)
    idx = sorted(inside)
    quads = []
    for a, i in enumerate(idx):
        for j in idx[a + 1:]:
            if shapely.distance(lines[i], lines[j]) <= TREAD_STEP:
                quads.append(shapely.convex_hull(shapely.multipoints(np.concatenate([S[i], S[j]]))))
    if not quads:
        return None
    rib = unary_union(quads)
    rib = rib.buffer(0.05, join_style=2).buffer(-0.05, join_style=2)
    if rib.geom_type != "Polygon" or rib.area > FLIGHT_MAX_AREA:
        return None
    rib = Polygon(rib.exterior)
    edge = rib.exterior.buffer(0.03)
    ends = [lines[i] for i in idx if shapely.intersection(lines[i], edge).length >= 0.8 * L[i]]
    if len(ends) < 2:
        return None
    if rib.area >= RIBBON_CONVEX * rib.convex_hull.area:  # a straight or fanned flight whose treads a break line
        rib = rib.convex_hull                             # shortens (the notch is no edge of the flight)
    return rib, shapely.multilinestrings(ends)


def _angle_diff(a: float, b: float) -> float:
    d = abs(a - b) % math.pi
    return min(d, math.pi - d)


def _island_hole(g: Polygon, fpoly: Polygon) -> bool:
    """``g`` has a hole where the footprint is (the footprint is an island inside it)."""
    return any(Polygon(r).buffer(1e-6).intersects(fpoly) for r in g.interiors)


def _cut_islands(pieces: List[Polygon], fpoly: Polygon) -> Optional[List[Polygon]]:
    """Pieces with holes (the footprint is an island) split by the shortest straight cut from their outer
    border to their outer border through the footprint, along one of the footprint's axes."""
    from shapely.ops import split

    out = []
    c, u, v, half = _oriented_box(fpoly)
    for g in pieces:
        if not _island_hole(g, fpoly):
            out.append(g)
            continue
        ext = LineString(g.exterior.coords)
        best = None
        reach = math.hypot(*(np.asarray(g.bounds[2:]) - np.asarray(g.bounds[:2]))) + 1.0
        for ax in (u, v):
            ends = []
            for sgn in (1.0, -1.0):
                d = _wall_distances(ext, c[None, :], sgn * ax, reach)[0]
                if not np.isfinite(d):
                    break
                ends.append(c + sgn * ax * (d + 1e-3))
            if len(ends) == 2:
                ln = LineString([tuple(ends[1]), tuple(ends[0])])
                if best is None or ln.length < best.length:
                    best = ln
        if best is None:
            return None
        # the other holes (columns) stay holes of the pieces they fall in
        filled = Polygon(g.exterior, [r for r in g.interiors if not Polygon(r).intersects(fpoly)])
        parts = split(filled, best)
        parts = [p.difference(fpoly) for p in getattr(parts, "geoms", [parts])]
        flat = [q for p in parts for q in getattr(p, "geoms", [p]) if q.geom_type == "Polygon" and q.area > 1e-6]
        if len(flat) < 2 or any(_island_hole(q, fpoly) for q in flat):
            return None
        out.extend(flat)
    return out


FREE_FLIGHTS = True  # free-standing flights are islands their hall goes round, curved ones by their treads' footprint
# (off: as before session 7: a straight one cuts its hall from wall to wall, a curved one stays in its hall)
SLIT = 0.01  # m: width of the slit by which a hall's ring goes round a free-standing flight (an area is one ring)


def _free_flight(flight, seen: Polygon, hpoly: Polygon, others: Sequence[Area], doors=()):
    """(footprint, end treads, host pieces) of a free-standing flight (``_flight_ribbon``'s (footprint, end
    treads)) in host ``hpoly`` (``seen``: the host, with the part of the stair beyond the plan when the outline
    cuts it): the footprint within the host and off its neighbours, and the host around it as one ring: a
    notch when the footprint reaches the host's outer border (a bite from its edge), else the island opened
    by a ``SLIT`` to the outer border (``_keyhole``; ``doors``: the host's passage lines, which it avoids). None
    when that leaves no valid host."""
    rib, ends = flight
    fp = rib.intersection(seen)
    near = [a.polygon for a in _intersecting(others, fp)]
    if near:
        fp = fp.difference(unary_union(near))
    parts = [g for g in getattr(fp, "geoms", [fp]) if g.geom_type == "Polygon" and g.area > 1e-6]
    if not parts:
        return None
    fp = max(parts, key=lambda g: g.area)
    fp = Polygon(fp.exterior)
    rest = hpoly.difference(fp)
    pieces = [g for g in getattr(rest, "geoms", [rest]) if g.geom_type == "Polygon" and g.area > 1e-6]
    if any(_island_hole(g, fp) for g in pieces):
        pieces = _keyhole(pieces, fp, ends, doors)
    return (fp, ends, pieces) if pieces else None


def _faces(ln: LineString, a: Polygon, b: Polygon, band: float = 0.05) -> bool:
    """The passage line ``ln`` from ``a`` has ``b`` beside it: ``b`` fills at least 30 % of a ``band`` wide strip
    along it on one side (a border straightened within 5 cm, half the strip's two sides), not a zero-width
    spike of ``b``'s ring running along ``a``'s border."""
    return b.intersection(ln.buffer(band, cap_style=2)).area >= 0.3 * band * ln.length


def _tread_sides(fpoly: Polygon, angles):
    """The sides of a flight's footprint parallel to its treads (its first and last tread), as one geometry."""
    xy = np.asarray(fpoly.exterior.coords)
    sides = [LineString([p, q]) for p, q in zip(xy[:-1], xy[1:]) if np.hypot(*(q - p)) >= MIN_PASSAGE]
    sides = [ln for ln in sides if angles and _parallel(ln, angles)]
    return unary_union(sides) if sides else None


SLIT_CLEAR = 0.3  # m: a slit starts this far from the flight's end treads and ends this far from the host's doors


def _keyhole(pieces: List[Polygon], fpoly: Polygon, ends=None, doors=()) -> Optional[List[Polygon]]:
    """Pieces with a hole where the footprint is, opened by a slit ``SLIT`` wide along the shortest straight
    way out of the footprint (square to its border, or to the nearest point of the piece's outer border) to
    their outer border that crosses nothing but the piece, starting and passing ``SLIT_CLEAR`` off the
    footprint's ``ends`` (where the flight is entered) and ending as far off the ``doors`` on it: each piece
    stays one piece, one ring going round the footprint (the osmAG way of an area is one closed ring; a hole
    would be dropped and the stair's passages would be off the hall's way). Other holes (columns) stay holes.
    None when no slit opens it."""
    import shapely

    out = []
    keep_off = unary_union([g.buffer(SLIT_CLEAR) for g in ([ends] if ends is not None else []) + list(doors)])
    ring = fpoly.exterior
    if not ring.is_ccw:
        ring = LineString(list(ring.coords)[::-1])
    ts = np.arange(0.05, ring.length, 0.1)
    pts = np.array([ring.interpolate(t).coords[0] for t in ts]).reshape(-1, 2)
    ahead = np.array([ring.interpolate(min(t + 0.01, ring.length)).coords[0] for t in ts]).reshape(-1, 2)
    tangent = ahead - pts
    tangent /= np.maximum(np.linalg.norm(tangent, axis=1)[:, None], 1e-12)
    normal = np.stack([tangent[:, 1], -tangent[:, 0]], axis=1)  # outward of a counter-clockwise ring
    ok = np.array([keep_off.is_empty or not keep_off.contains(shapely.points(q)) for q in pts], bool)
    if ok.any():
        pts, normal = pts[ok], normal[ok]
    for g in pieces:
        if not _island_hole(g, fpoly):
            out.append(g)
            continue
        ext = LineString(g.exterior.coords)
        reach = float(np.hypot(g.bounds[2] - g.bounds[0], g.bounds[3] - g.bounds[1])) + 1.0
        cands = []
        # square to the footprint's border: the first crossing of the piece's outer border ahead
        rays = shapely.linestrings(np.stack([pts + 0.001 * normal, pts + reach * normal], axis=1))
        xy, idx = shapely.get_coordinates(shapely.intersection(rays, ext), return_index=True)
        for k in np.unique(idx).tolist():
            q = xy[idx == k]
            d = np.hypot(*(q - pts[k]).T)
            cands.append((float(d.min()), tuple(pts[k]), tuple(q[int(np.argmin(d))])))
        # ... or to the nearest point of the outer border
        for k, tip in enumerate(shapely.shortest_line(shapely.points(pts), ext).tolist()):
            cands.append((tip.length, tuple(pts[k]), tip.coords[-1]))
        cands.sort(key=lambda c: c[0])
        main, parts = None, []
        inside = g.buffer(1e-6)
        for n, a, b in cands[:200]:
            if n < 1e-9 or (not keep_off.is_empty and keep_off.contains(shapely.points(b))):
                continue
            seg = LineString([a, b])
            if not inside.contains(seg) or seg.intersection(fpoly).length > 1e-6:
                continue  # through a column or out of the piece, or along the footprint's border
            if ends is not None and seg.distance(ends) < SLIT_CLEAR - 1e-6:
                continue  # in front of the flight's first or last tread, where it is entered
            d = (np.asarray(b) - np.asarray(a)) / n
            # from inside the footprint to just beyond the outer border: the slit cuts both rings cleanly
            line = LineString([(a[0] - 0.05 * d[0], a[1] - 0.05 * d[1]), (b[0] + 0.05 * d[0], b[1] + 0.05 * d[1])])
            opened = g.difference(line.buffer(SLIT / 2.0, cap_style=2))
            parts = [q for q in getattr(opened, "geoms", [opened]) if q.geom_type == "Polygon" and q.area > 1e-6]
            main = _opened(parts, g, fpoly)
            if main is not None:
                break
        if main is None:
            return None
        out.append(main)
        out.extend(q for q in parts if q is not main)
    return out


def _opened(parts: List[Polygon], g: Polygon, fpoly: Polygon) -> Optional[Polygon]:
    """The main piece of ``g`` opened by a slit (``parts``) when it is one valid ring round the footprint (what
    the slit cut off besides is a sliver: <= 5 % of ``g``), else None."""
    main = max(parts, key=lambda q: q.area) if parts else None
    if main is None or not main.is_valid or _island_hole(main, fpoly) or \
            sum(q.area for q in parts) - main.area > 0.05 * g.area:
        return None
    return main


def _parallel(ln: LineString, angles, tol_deg: float = 25.0) -> bool:
    (x0, y0), (x1, y1) = ln.coords[0], ln.coords[-1]
    a = math.atan2(y1 - y0, x1 - x0) % math.pi
    for b in angles:
        d = abs(a - b) % math.pi
        if min(d, math.pi - d) <= math.radians(tol_deg):
            return True
    return False


def _touch(a: Polygon, b: Polygon) -> bool:
    """The two polygons share a border stretch of at least MIN_PASSAGE."""
    return a.distance(b) < 1e-6 and a.boundary.intersection(b.buffer(1e-4)).length >= MIN_PASSAGE


def _has_door(g: Polygon, host_id: int, passages, skip_ids=()) -> bool:
    """One of the host's passages (other than those to ``skip_ids``: stairs carved before) lies on piece
    ``g``'s border."""
    for p in passages:
        if host_id in (p.from_id, p.to_id) and not ({p.from_id, p.to_id} & set(skip_ids)) and \
                p.line.distance(g) < 0.3:
            return True
    return False


def _width_ok(p: Polygon) -> bool:
    return p.area >= MIN_PIECE_AREA and not p.buffer(-MIN_PIECE_WIDTH).is_empty


def _common_border_runs(a: Polygon, b: Polygon, within=None) -> list:
    """The common border of two touching polygons (within ``within`` if given), merged into runs."""
    common = a.boundary.intersection(b.buffer(1e-4))
    if within is not None:
        common = common.intersection(within)
    lines = [g for g in getattr(common, "geoms", [common]) if g.geom_type in ("LineString", "MultiLineString")]
    if not lines:
        return []
    u = unary_union(lines)
    merged = linemerge(list(u.geoms)) if hasattr(u, "geoms") else u
    return list(getattr(merged, "geoms", [merged]))


def _passage_lines(a: Polygon, b: Polygon) -> List[LineString]:
    """Straight stretches (>= MIN_PASSAGE) of the common border of two touching polygons."""
    out = []
    for ln in _common_border_runs(a, b):
        if ln.length < MIN_PASSAGE:
            continue
        xy = np.asarray(ln.simplify(0.05).coords)
        for p, q in zip(xy[:-1], xy[1:]):
            if np.hypot(*(q - p)) >= MIN_PASSAGE:
                out.append(LineString([_on_border(p, a, b), _on_border(q, a, b)]))
    return out


def _on_border(pt, a: Polygon, b: Polygon):
    """``pt`` (within 1e-4 of both borders) moved onto the nearest vertex of ``a`` or ``b`` when one is within
    1 cm, else onto ``b``'s border: the osmAG writer makes passage ends nodes of both areas' ways."""
    from shapely.geometry import Point

    p = Point(pt)
    best, dist = None, 0.01
    for poly in (a, b):
        for ring in [poly.exterior] + list(poly.interiors):
            xy = np.asarray(ring.coords)
            d = np.hypot(xy[:, 0] - pt[0], xy[:, 1] - pt[1])
            k = int(np.argmin(d))
            if d[k] < dist:
                best, dist = (float(xy[k, 0]), float(xy[k, 1])), float(d[k])
    if best is not None:
        return best
    ring = min([b.exterior] + list(b.interiors), key=lambda r: r.distance(p))
    q = ring.interpolate(ring.project(p))
    return (q.x, q.y)


def _intersecting(areas: Sequence[Area], geom) -> List[Area]:
    """The areas whose polygon intersects ``geom``, in order (one vectorised predicate, not one call per area)."""
    import shapely

    if not areas:
        return []
    hit = shapely.intersects(np.array([a.polygon for a in areas], dtype=object), geom)
    return [a for a, h in zip(areas, hit.tolist()) if h]


STRADDLE_SHARE = 0.3  # a stair with at least this share in one area and the rest beyond every area is carved
BEYOND_OTHERS = 0.05  # ... when at most this share of it lies in other areas


def _beyond_the_plan(kind: str, sym: Polygon, inside: float, cand: Sequence[Area]) -> Optional[Polygon]:
    """The part of stair symbol ``sym`` beyond every area when the plan's outline (the envelope, not a wall)
    cuts through it: at least ``STRADDLE_SHARE`` of it lies in one area (``inside`` m²) and the rest in no
    other area (the stair at the edge of a bridge or terrace, SIST-F3's E2-ST-02, whose dog-leg flights the
    link corridor's outline cuts diagonally). None for a lift, or a symbol shared by two areas (a stair
    drawn across a wall between two rooms is no evidence of either)."""
    if kind != "stairs" or inside < STRADDLE_SHARE * sym.area:
        return None
    others = sum(a.polygon.intersection(sym).area for a in cand) - inside
    if others > BEYOND_OTHERS * sym.area:
        return None
    rest = sym.difference(unary_union([a.polygon for a in cand]))
    parts = [g for g in getattr(rest, "geoms", [rest]) if g.geom_type == "Polygon" and g.area > 1e-6]
    return unary_union(parts) if parts else None


def carve_anchors(areas: List[Area], passages: List[Passage], geometries: Sequence[CadGeometry],
                  progress=None, symbols=None, texts=None) -> Dict[str, object]:
    """Carve every stair and lift the drawing shows inside a larger area into a typed area of its own (in
    place: ``areas`` and ``passages`` are extended and updated; see the module doc). Returns figures:
    ``carved`` [(kind, new area id, host id, m²)], ``pieces`` {new area id: ids of the host's other
    pieces when the carve cut it in two}, ``typed`` [(kind, area id)] (areas that are the anchor
    themselves, typed), ``skipped`` counts by reason, ``beyond`` [new area ids] (stairs the plan's outline
    cuts through, carved whole: ``_beyond_the_plan``), ``islands`` [host ids] (halls kept whole round a
    free-standing stair), ``free_flights`` [m²] (curved or fanned free-standing flights carved by their treads)."""
    progress = ensure(progress)
    symbols = find_anchor_symbols(geometries) if symbols is None else symbols
    stats: Dict[str, object] = {"symbols": len(symbols), "carved": [], "typed": [], "skipped": {}, "pieces": {}}
    if not symbols and not texts:  # (texts: a lift code may name an empty walled box, coded_lift_recesses)
        return stats

    def skip(reason):
        stats["skipped"][reason] = stats["skipped"].get(reason, 0) + 1

    stats["retyped"] = retype_break_line_lifts(areas, symbols)
    if stats["retyped"]:
        progress.info(f"{len(stats['retyped'])} area(s) typed elevator hold a stair run and no lift car (the cross is "
                      f"the flight's break line): stairs (areas {', '.join(map(str, stats['retyped']))})")

    carved_ids = set()
    outdoor: List[Tuple[Polygon, tuple]] = []  # stairs drawn outside every area (outdoor stairs)
    next_area = max([a.id for a in areas] + [0]) + 1
    next_pass = max([p.id for p in passages] + [0]) + 1
    # stairs first (larger), then lifts; larger symbols first
    order = sorted(symbols, key=lambda s: (s[0] != "stairs", -s[1].area))
    for k, (kind, sym, angles, continues) in enumerate(order):
        progress.check()
        progress.step(100.0 * k / len(order))
        cand = _intersecting([a for a in areas if a.type != "structure" and a.polygon is not None], sym)
        if not cand:
            if kind == "stairs" and texts:
                outdoor.append((sym, angles))
            skip("outside every area")
            continue
        host = max(cand, key=lambda a: a.polygon.intersection(sym).area)
        inside = host.polygon.intersection(sym).area
        if inside <= 1e-9:  # touching areas only: outside them all
            if kind == "stairs" and texts:
                outdoor.append((sym, angles))
            skip("outside every area")
            continue
        seen, straddles = host.polygon, False
        if inside < 0.5 * sym.area:
            beyond = _beyond_the_plan(kind, sym, inside, cand)
            if beyond is None:
                skip("symbol across areas")
                continue
            # a stair the plan's outline cuts through: its part beyond every area is the stair's too
            seen = unary_union([host.polygon, beyond])
            if seen.geom_type != "Polygon":
                skip("symbol across areas")
                continue
            straddles = True
        if host.type in ANCHOR_TYPES and host.type != kind:
            skip("in an area of the other kind")
            continue
        reach = LANDING if kind == "stairs" else SHAFT_REACH
        fp = footprint(sym, seen, reach, MIN_LIFT_WALLS if kind == "elevator" else 0)
        if fp is None:
            skip("no walls around a lift cross" if kind == "elevator" else "no footprint")
            continue
        fpoly, _walls = fp
        hpoly = host.polygon
        others = [a.polygon for a in _intersecting([a for a in areas if a is not host and a.type != "structure"], fpoly)]
        if others:  # the closed walls never reach into a neighbour
            cut = fpoly.difference(unary_union(others))
            cut = max(getattr(cut, "geoms", [cut]), key=lambda g: g.area) if not cut.is_empty else cut
            if cut.is_empty or cut.geom_type != "Polygon":
                skip("no footprint")
                continue
            fpoly = cut
        if host.type == kind and (fpoly.area >= ALREADY_OWN * hpoly.area or hpoly.area <= OWN_MAX_AREA[kind]):
            skip("already its own area")
            continue
        rest = hpoly.difference(fpoly)
        pieces = [g for g in getattr(rest, "geoms", [rest]) if g.geom_type == "Polygon" and g.area > 1e-6]
        ends = None  # the flight's end treads, where its passages lie (a free-standing curved flight)
        if any(_island_hole(g, fpoly) for g in pieces):
            # a free-standing stair (an island in a hall): an area is one ring, so the hall goes round the stair,
            # its ring opened by a slit to its outer border (_keyhole; a wall-to-wall cut with FREE_FLIGHTS off)
            if continues is True or (continues and not FREE_FLIGHTS):
                # the run is a straight part of a curved flight standing free in a hall: its box is no footprint,
                # and a cut through the hall for it would fragment the hall for a fragment of a stair
                skip("free-standing curved flight")
                continue
            if continues:
                # ... whose treads go on: the flight's own footprint (its treads between its strings), an island
                # the hall keeps around it (one ring, opened by a slit to its outer border, _keyhole)
                free = _free_flight(continues, seen, hpoly, [a for a in areas if a is not host and a.type != "structure"],
                                    [p.line for p in passages if host.id in (p.from_id, p.to_id)])
                if free is None:
                    skip("free-standing curved flight")
                    continue
                fpoly, ends, pieces = free
                stats.setdefault("free_flights", []).append(round(fpoly.area, 2))
            elif FREE_FLIGHTS:
                # a straight flight standing free: the hall goes round it (one ring opened by a slit), never cut
                pieces = _keyhole(pieces, fpoly, _tread_sides(fpoly, angles),
                                  [p.line for p in passages if host.id in (p.from_id, p.to_id)])
            else:
                pieces = _cut_islands(pieces, fpoly)
            if pieces is None:
                skip("island with no cut to the walls")
                continue
            if FREE_FLIGHTS:
                stats.setdefault("islands", []).append(host.id)
        keep = [g for g in pieces if _width_ok(g)]
        small = [g for g in pieces if not _width_ok(g)]
        if small:
            grown = unary_union([fpoly] + small)
            if grown.geom_type == "Polygon":
                fpoly = grown
            else:  # a sliver touching the footprint at a point only: keep it with the footprint's largest part
                fpoly = max(grown.geoms, key=lambda g: g.area)
        if not keep or sum(g.area for g in keep) < MIN_REST_SHARE * hpoly.area:
            if host.type not in ANCHOR_TYPES and hpoly.area <= 4.0 * max(fpoly.area, 1.0) and \
                    (kind == "stairs" or hpoly.area <= 40.0):
                host.type = kind
                stats["typed"].append((kind, host.id))
            else:
                skip("the area is mostly the anchor")
            continue
        fpoly = fpoly.buffer(0) if not fpoly.is_valid else fpoly
        if fpoly.geom_type != "Polygon":
            skip("footprint not one piece")
            continue
        keep.sort(key=lambda g: -g.area)
        # a piece of floor left between this stair and walls (and other stairs carved before: a curved flight
        # whose middle treads are not parallel), with no door of the host and no open side onto the rest
        # of the host, is the stair's own landing: it joins the footprint, and so do those other stairs
        absorbed = []
        if kind == "stairs" and len(keep) > 1:
            lone = [g for g in keep[1:] if g.area <= LANDING_PIECE_MAX and not _has_door(g, host.id, passages, carved_ids)
                    and not any(_touch(g, o) for o in keep if o is not g)]
            if lone:
                keep = [g for g in keep if not any(g is x for x in lone)]
                for g in lone:
                    for b in areas:
                        if b.type == kind and b.id in carved_ids and _touch(g, b.polygon):
                            absorbed.append(b)
                grown = unary_union([fpoly] + lone + [b.polygon for b in absorbed])
                if grown.geom_type != "Polygon":
                    keep.extend(lone)
                    absorbed = []
                else:
                    fpoly = grown
        old_type = host.type
        # the rest keeps the host's id and passages; a host typed as this kind only because of the
        # symbol now carved out (a corridor holding a stair) is a room again: stage 5 retypes it
        host.polygon = keep[0]
        if old_type == kind:
            host.type = "room"
        new = Area(id=next_area, polygon=fpoly, type=kind, component=host.component)
        next_area += 1
        extra = []
        for g in keep[1:]:
            extra.append(Area(id=next_area, polygon=g, type=host.type, component=host.component))
            next_area += 1
        if extra:
            stats["pieces"][new.id] = [e.id for e in extra]  # the host's other pieces, for ``relabel``
        areas.append(new)
        areas.extend(extra)
        for b in absorbed:  # earlier carved stairs joined by a landing piece: one stair
            areas.remove(b)
            for p in list(passages):
                if b.id in (p.from_id, p.to_id):
                    other = p.to_id if p.from_id == b.id else p.from_id
                    if other == host.id and p.line.distance(host.polygon) > 1e-3 or other == new.id:
                        passages.remove(p)  # a cut line now inside the stair
                        continue
                    if p.from_id == b.id:
                        p.from_id = new.id
                    else:
                        p.to_id = new.id
            stats["carved"] = [c for c in stats["carved"] if c[1] != b.id]
            carved_ids.discard(b.id)
        pieces_by_id = {host.id: host.polygon, new.id: fpoly}
        pieces_by_id.update({e.id: e.polygon for e in extra})
        rims: Dict[int, object] = {}  # each piece (and its border) buffered once, not once per passage of the host
        grown: Dict[int, object] = {}

        def rim(i):
            if i not in rims:
                rims[i] = pieces_by_id[i].boundary.buffer(1e-3)
            return rims[i]

        def grown_piece(i):
            if i not in grown:
                grown[i] = pieces_by_id[i].buffer(1e-4)
            return grown[i]

        # the host's passages go to the piece they lie on; one that spans two pieces (a door the cut runs
        # through) is split at the cut, one part per piece
        for p in list(passages):
            if host.id not in (p.from_id, p.to_id):
                continue
            end = "from_id" if p.from_id == host.id else "to_id"
            other = p.to_id if end == "from_id" else p.from_id
            parts = []
            for i, poly in pieces_by_id.items():
                if i == other:
                    continue
                seg = p.line.intersection(grown_piece(i))
                if seg.geom_type == "LineString" and seg.length >= 0.2 and seg.length < p.line.length - 1e-3:
                    parts.append((i, seg))
            if len(parts) >= 2:
                for n_part, (i, seg) in enumerate(parts):
                    xy = np.asarray(seg.coords)[[0, -1]]
                    line = LineString([_on_border(xy[0], pieces_by_id[i], pieces_by_id[i]),
                                       _on_border(xy[1], pieces_by_id[i], pieces_by_id[i])])
                    if n_part == 0:
                        p.line = line
                        setattr(p, end, i)
                    else:
                        q = Passage(id=next_pass, from_id=p.from_id, to_id=p.to_id, line=line, name="",
                                    tags=dict(p.tags or {}))
                        setattr(q, end, i)
                        passages.append(q)
                        next_pass += 1
                continue
            # the piece whose border holds most of the passage (its midpoint may lie on two borders)
            best = max(pieces_by_id, key=lambda i: (p.line.intersection(rim(i)).length,
                                                    -pieces_by_id[i].distance(p.line.interpolate(0.5, normalized=True))))
            if best != other:
                setattr(p, end, best)
        ids = [new.id, host.id] + [e.id for e in extra]
        for i, a_id in enumerate(ids):
            for b_id in ids[i + 1:]:
                if not pieces_by_id[a_id].intersects(pieces_by_id[b_id]):
                    continue
                lines = _passage_lines(pieces_by_id[a_id], pieces_by_id[b_id])
                if a_id == new.id and ends is not None:
                    # a free flight is entered across its first and last tread only (never over a string, nor
                    # across the slit by which the hall goes round it)
                    lines = [ln for ln in lines if ln.intersection(ends.buffer(0.05)).length >= 0.5 * ln.length]
                elif a_id == new.id and angles:
                    # a flight is entered across its first and last tread, not over its strings (handrails)
                    along = [ln for ln in lines if _parallel(ln, angles)]
                    lines = along or lines
                if a_id == new.id and FREE_FLIGHTS:
                    # never along a zero-width spike of the other piece's ring (an overlay leaves one where the
                    # stair's end runs beside a gap in the hall; the next overlay drops it, and the passage's end)
                    lines = [ln for ln in lines if _faces(ln, pieces_by_id[a_id], pieces_by_id[b_id])]
                for ln in lines:
                    passages.append(Passage(id=next_pass, from_id=a_id, to_id=b_id, line=ln))
                    next_pass += 1
        stats["carved"].append((kind, new.id, host.id, round(fpoly.area, 2)))
        if straddles:
            stats.setdefault("beyond", []).append(new.id)
        carved_ids.add(new.id)
    if outdoor:
        stats["outdoor"] = named_outdoor_stairs(areas, passages, outdoor, texts)
    if texts:  # lift codes with no lift drawn near them: a lift-sized walled recess merged into an area
        recess = coded_lift_recesses(areas, passages, texts)
        if recess["carved"]:
            stats["carved"].extend(recess["carved"])
            stats["pieces"].update(recess["pieces"])
            stats["recesses"] = [c[1] for c in recess["carved"]]
    changed = {i for c in stats["carved"] for i in c[1:3]} | {i for v in stats["pieces"].values() for i in v}
    if changed:
        stats["refit"] = refit_passage_ends(areas, passages, changed)
    progress.step(100)
    return stats


END_ON_RING = 1e-3  # m: a passage end this close to an area's ring is on it (the fusion attaches ends within 1 cm)
DOOR_NEAR = 0.3  # m: the common border of two areas this close to a passage's line is where that passage lies


DOOR_MIN = 0.3  # m: shorter stretches of a door's border left by a cut are no passage (as the name split's cuts)


def _border_chords(a: Polygon, b: Polygon, within) -> List[LineString]:
    """The chords (end to end, >= ``DOOR_MIN``) of the stretches of the common border of ``a`` and ``b`` in
    ``within``: a door's line across a border that zigzags along the raster stays one passage."""
    out = []
    for ln in _common_border_runs(a, b, within):
        if ln.geom_type == "LineString" and ln.length >= DOOR_MIN:
            p, q = ln.coords[0], ln.coords[-1]
            if math.hypot(q[0] - p[0], q[1] - p[1]) >= DOOR_MIN:
                out.append(LineString([_on_border(p, a, b), _on_border(q, a, b)]))
    return out


def refit_passage_ends(areas: Sequence[Area], passages: List[Passage], changed) -> List[int]:
    """Passages of the areas ``changed`` by the carve whose end is off one of their two areas' rings, laid
    again on the border the two areas share along them. A door on the host's border that the cut runs
    through, or whose end a later carve of the same host moved (the host's border near it is the next
    stair's now), keeps its line otherwise, and the osmAG writer cannot make that end a node of the area
    (the fusion warned: SIST-F1 L1-P036 0.66 m, L1-P077 0.75 m, L1-P174 0.06 m, F4 L4-P052 1.30 m, library
    3F L3-P025 0.36 m). The passage takes the chord of the stretch of the common border of its area and
    the area on its other side beside its line (within ``DOOR_NEAR``, ``_border_chords``); another changed area that
    shares such a stretch (>= ``MIN_PASSAGE``) with that other side (the other piece of a door the cut split)
    gets a passage of its own, copied from this one. A passage with no such stretch is left as it is. Returns the ids of the
    passages refit or added."""
    from shapely.geometry import Point

    by_id = {a.id: a for a in areas if a.polygon is not None and not a.polygon.is_empty}
    changed = set(changed)
    done: List[int] = []
    next_pass = max([p.id for p in passages] + [0]) + 1

    def off(p):
        ends = [Point(p.line.coords[0]), Point(p.line.coords[-1])]
        return [aid for aid in (p.from_id, p.to_id)
                if any(by_id[aid].polygon.boundary.distance(e) > END_ON_RING for e in ends)]

    for p in list(passages):
        if not ({p.from_id, p.to_id} & changed) or p.from_id not in by_id or p.to_id not in by_id or \
                p.line is None or p.line.is_empty:
            continue
        bad = off(p)
        if not bad:
            continue
        side = "from_id" if (p.from_id in bad and p.from_id in changed) or p.to_id not in changed else "to_id"
        other = by_id[p.to_id if side == "from_id" else p.from_id]
        near = p.line.buffer(DOOR_NEAR, cap_style=2)  # flat: the border beside the door, not beyond its ends
        found = []
        for x in _intersecting([by_id[i] for i in sorted(changed) if i in by_id and i != other.id], near):
            if not x.polygon.intersects(other.polygon.buffer(1e-4)):
                continue
            found += [(x.id, ln) for ln in _border_chords(x.polygon, other.polygon, near)]
        if not found:
            continue
        mine = getattr(p, side)
        found.sort(key=lambda t: (t[0] != mine, -t[1].length))
        for k, (xid, ln) in enumerate(found):
            if k == 0:
                p.line = ln
                setattr(p, side, xid)
                done.append(p.id)
                continue
            pair = {xid, other.id}
            if ln.length < MIN_PASSAGE:  # a sliver of the door beside the cut: no passage of its own
                continue
            if any({q.from_id, q.to_id} == pair and q.line.buffer(0.05).intersection(ln).length > 0.5 * ln.length
                   for q in passages):
                continue  # that stretch has its passage already (the carve's own)
            q = Passage(id=next_pass, from_id=p.from_id, to_id=p.to_id, line=ln, name="", tags=dict(p.tags or {}))
            setattr(q, side, xid)
            passages.append(q)
            done.append(q.id)
            next_pass += 1
    return done


OUTDOOR_STAIR_REACH = 1.0  # m: areas this close to an outdoor stair are cut from its box


def named_outdoor_stairs(areas: List[Area], passages: List[Passage], stairs, texts) -> List[int]:
    """Stairs drawn outside every area (an outdoor fire-escape stair along the facade: its treads stand beyond
    the walls) become stairs areas of their own when the drawing names them: a stair code or keyword
    (``semantics``: 'E1-ST-07', its detail callout, 'scala esterna') within ``semantics.CALLOUT_REACH`` of
    the flight. The area is the flight's box (less any area it overlaps); it is joined by a passage to an area
    it touches (the landing it leads from), else it stays on its own (behind a facade no door crosses on
    this plan), reported by the connectivity figures like any unreached space. An unnamed stair
    outside the plan's areas (entrance steps, a stair of a detail view) is left out. Returns the new ids."""
    from shapely.geometry import Point

    from . import semantics

    labs = semantics.classify_labels(list(texts or []))
    codes = [Point(l.x, l.y) for l in labs if l.role in ("name", "number")
             and (semantics.type_of_name(l.text, l.text) or {}).get("type") == "stairs"]
    if not codes:
        return []
    out: List[int] = []
    next_area = max([a.id for a in areas] + [0]) + 1
    next_pass = max([p.id for p in passages] + [0]) + 1
    for sym, angles in stairs:
        if not any(sym.distance(c) <= semantics.CALLOUT_REACH for c in codes):
            continue
        poly = sym
        near = [a for a in areas if a.type != "structure" and a.polygon is not None
                and a.polygon.distance(sym) <= OUTDOOR_STAIR_REACH]
        for a in near:
            poly = poly.difference(a.polygon)
        if poly.is_empty:
            continue
        poly = max(getattr(poly, "geoms", [poly]), key=lambda g: g.area)
        if poly.geom_type != "Polygon" or poly.area < MIN_PIECE_AREA:
            continue
        new = Area(id=next_area, polygon=poly, type="stairs")
        next_area += 1
        areas.append(new)
        out.append(new.id)
        for a in near:  # it touches an area (the landing it leads from): a passage across the common border
            if _touch(poly, a.polygon):
                for ln in _passage_lines(a.polygon, poly):
                    passages.append(Passage(id=next_pass, from_id=a.id, to_id=new.id, line=ln))
                    next_pass += 1
    return out


def retype_break_line_lifts(areas: Sequence[Area], symbols) -> List[int]:
    """Areas typed elevator (``area_types``: a cross, or density of a lift layer) that hold most of a stair
    run and no lift cross of their own are stair cores: the cross they hold is the break line drawn across
    the flight where the plan cuts it (``find_anchor_symbols`` drops crosses within ``BREAK_GAP`` of a run),
    not a lift car. Typed stairs in place; returns their ids. (SIST-F4: the E1-ST-02 core was an
    'elevator', so its detail callout named the next stair core, E1-ST-05, and E1-ST-05's none.)"""
    stairs = [s for k, s, _a, _c in symbols if k == "stairs"]
    lifts = [s for k, s, _a, _c in symbols if k == "elevator"]
    out: List[int] = []
    if not stairs:
        return out
    for a in areas:
        if a.type != "elevator" or a.polygon is None or a.polygon.is_empty:
            continue
        poly = a.polygon
        if not any(s.intersects(poly) and poly.intersection(s).area >= 0.5 * s.area for s in stairs):
            continue
        if any(c.intersects(poly) and poly.intersection(c).area >= 0.5 * c.area for c in lifts):
            continue
        a.type = "stairs"
        out.append(a.id)
    return out


def relabel(labels: Optional[np.ndarray], grid, areas: Sequence[Area], stats) -> None:
    """Paint the carved areas (``carve_anchors``' ``carved`` and ``pieces``) into the label raster
    of ``grid`` where it holds their host, so previews and later raster stages see them."""
    carved = stats.get("carved") or []
    if labels is None or grid is None or not carved:
        return
    by_id = {a.id: a for a in areas}
    for _kind, new_id, host_id, _m2 in carved:
        for aid in [new_id] + list(stats.get("pieces", {}).get(new_id, [])):
            a = by_id.get(aid)
            if a is None:
                continue
            repaint_polygon(labels, grid, a.polygon, a.id, old_id=host_id)


LIFT_SIDE = (1.2, 3.5)  # m: the sides of a lift shaft (a car of 0.8-2.5 m plus the gap to the shaft walls)
RECESS_STEP = 0.3  # m: grid of seed points searched for a lift recess around a lift code
RECESS_HOST_FACTOR = 3.0  # the area holding a recess is at least this many times the recess
NAMED_LIFT_MAX = 40.0  # m²: an area holding a lift name up to this size is a lift (semantics' vertical_max_area)


def _recess_box(host: Polygon, seed: np.ndarray, u: np.ndarray, v: np.ndarray, boundary=None) -> Optional[Polygon]:
    """The lift-sized box around ``seed`` that ``host``'s border (or ``boundary``, a part of it) closes on
    three sides (walls left, right and behind within LIFT_SIDE) and on the fourth with the stubs of a front
    wall left open by a doorless gap (rays straight ahead meet a wall before the side walls stop), or None.
    A box open full-width is no evidence (any corridor's door recess or dead end is one): None."""
    lo_s, hi_s = LIFT_SIDE
    boundary = host.boundary if boundary is None else boundary
    start = seed[None, :]
    for a, b in ((u, v), (v, u)):
        d = {sgn: _wall_distances(boundary, start, sgn * a, hi_s)[0] for sgn in (1.0, -1.0)}
        if not all(np.isfinite(x) for x in d.values()) or not lo_s <= d[1.0] + d[-1.0] <= hi_s:
            continue
        e = {sgn: _wall_distances(boundary, start, sgn * b, hi_s)[0] for sgn in (1.0, -1.0)}
        for back, front in ((1.0, -1.0), (-1.0, 1.0)):
            if not (np.isfinite(e[back]) and not np.isfinite(e[front])):
                continue
            half_lo, half_hi = d[-1.0], d[1.0]
            # where the side walls stop, marching out of the open side
            end = None
            steps = np.arange(0.1, hi_s + 1e-9, 0.1)
            ps = seed[None, :] + (front * steps)[:, None] * b[None, :]
            dl = _wall_distances(boundary, ps, -a, half_lo + 2 * SIDE_SLACK)
            dh = _wall_distances(boundary, ps, a, half_hi + 2 * SIDE_SLACK)
            stop = np.flatnonzero(~((dl <= half_lo + SIDE_SLACK) & (dh <= half_hi + SIDE_SLACK)))
            if len(stop):
                end = float(steps[stop[0]] - 0.1)
            # stubs of a front wall with a doorless gap: rays straight ahead across the width meet a wall
            ts = np.linspace(-half_lo * 0.9, half_hi * 0.9, 11)
            ray = _wall_distances(boundary, seed[None, :] + ts[:, None] * a[None, :], front * b, hi_s)
            hits = ray[np.isfinite(ray)]
            stub = float(np.median(hits)) if len(hits) >= 2 else None
            if stub is not None and (end is None or stub <= end + SIDE_SLACK):
                end = stub
            else:
                # a full-width mouth is any niche of a corridor (a door recess, a corridor's end): no evidence
                continue
            if end is None or end <= 0.1:
                continue
            depth = e[back] + end
            if not lo_s <= depth <= hi_s:
                continue
            lo = np.array([-half_lo, -e[back] if back < 0 else -end])
            hi = np.array([half_hi, e[back] if back > 0 else end])
            return _box_polygon(seed, a, b, lo, hi)
    return None


def _axes(poly: Polygon) -> Tuple[np.ndarray, np.ndarray]:
    """The area's wall directions: the longest edge's direction (modulo 90 degrees) weighted by length."""
    xy = np.asarray(poly.exterior.coords)
    e = np.diff(xy, axis=0)
    L = np.hypot(e[:, 0], e[:, 1])
    ang = np.arctan2(e[:, 1], e[:, 0]) % (math.pi / 2)
    bins = np.round(np.degrees(ang)).astype(int) % 90
    w = np.bincount(bins, weights=L, minlength=90)
    t = math.radians(int(np.argmax(w)))
    return np.array([math.cos(t), math.sin(t)]), np.array([-math.sin(t), math.cos(t)])


def _recess_walls(hpoly: Polygon, near=None):
    """The border a recess search casts its rays against: the area's outline and its holes, but not the holes
    smaller than a lift's least footprint (``LIFT_SIDE[0]`` squared): a symbol drawn inside an empty shaft (a
    wheelchair sign, a lift glyph on no lift layer) is an island of the area, no wall of the shaft."""
    rings = [hpoly.exterior] + [r for r in hpoly.interiors if Polygon(r).area >= LIFT_SIDE[0] ** 2]
    border = unary_union([LineString(r.coords) for r in rings])
    return border if near is None else border.intersection(near)


def _recess_at_code(areas: Sequence[Area], c) -> Optional[Tuple[Area, Polygon]]:
    """The lift-sized walled box (``_recess_box``) of a larger area that the code's own copy at ``c`` is
    written in, or None: a code written inside the box names that box whatever lift stands beside it."""
    hosts = [a for a in areas if a.polygon is not None and not a.polygon.is_empty and a.type not in ANCHOR_TYPES
             and a.type != "structure" and a.polygon.area >= RECESS_HOST_FACTOR * LIFT_SIDE[0] ** 2
             and a.polygon.contains(c)]
    import shapely
    from shapely import points as _points

    for host in hosts:
        hpoly = host.polygon
        u, v = _axes(hpoly)
        border = _recess_walls(hpoly, c.buffer(2.5 * LIFT_SIDE[1]))
        # seeds around the code (nearest first) until a box holding the code is found: a seed just anywhere in
        # a shaft may look out through its gap to a wall across a narrow lobby
        x0, y0, x1, y1 = c.buffer(LIFT_SIDE[1]).bounds
        gx, gy = np.meshgrid(np.arange(x0, x1, RECESS_STEP), np.arange(y0, y1, RECESS_STEP))
        pts = np.column_stack([gx.ravel(), gy.ravel()])
        pts = pts[shapely.contains(hpoly.buffer(-0.1), _points(pts))]
        pts = pts[np.argsort(np.hypot(pts[:, 0] - c.x, pts[:, 1] - c.y))]
        for q in pts:
            bx = _recess_box(hpoly, q, u, v, border)
            if bx is None or not bx.contains(c):
                continue
            bx = bx.intersection(hpoly)
            if bx.geom_type == "Polygon" and bx.area <= hpoly.area / RECESS_HOST_FACTOR:
                return host, bx
    return None


def coded_lift_recesses(areas: List[Area], passages: List[Passage], texts) -> Dict[str, object]:
    """Lift shafts drawn as an empty box of walls (no car cross, nothing on a lift layer) that open without a
    door onto the area in front and were merged into it, found from the lift's code. A lift code
    (``semantics``: 'E1-P2', its detail callout) with no area typed elevator within
    ``semantics.CALLOUT_REACH`` (nor a small area holding a lift name, nor a small unnamed room within
    ``semantics.D_MAX`` of any copy of the code: stage 5 names those) names the nearest *box-shaped recess*
    of a larger area within that reach: a box of lift size (``LIFT_SIDE`` a side) that the area's border
    closes on three sides and, on the fourth, with a front wall's stubs (a doorless gap). The recess is
    carved as an elevator area (``carve_anchors`` on the box as a lift symbol: a passage on the gap's chord).
    An area only counts as a host when it is ``RECESS_HOST_FACTOR`` times the box or more: a small room is
    no recess.
    Returns ``carve_anchors``' figures of the carves (``carved``, ``pieces``)."""
    import shapely
    from shapely import STRtree, points as _points
    from shapely.geometry import Point

    from . import semantics

    out: Dict[str, object] = {"carved": [], "pieces": {}}
    labs = semantics.classify_labels(list(texts or []))
    codes = [l for l in labs if l.role == "number"
             and (semantics.type_of_name("", l.text) or {}).get("type") == "elevator"]
    reach = semantics.CALLOUT_REACH
    done, carved_codes = set(), set()
    live = [a for a in areas if a.polygon is not None and not a.polygon.is_empty and a.type != "structure"]
    lifts = [a.polygon for a in live if a.type == "elevator"]
    # a small area holding a lift's name ('客梯', 'lift') is a lift too (stage 5 types it so)
    named = [Point(l.x, l.y) for l in labs if l.role == "name"
             and (semantics.type_of_name(l.text, l.text) or {}).get("type") == "elevator"]
    lifts += [a.polygon for a in live if a.type != "elevator" and a.polygon.area <= NAMED_LIFT_MAX
              and any(a.polygon.contains(q) for q in named)]
    # a code written again (a tag in the shaft, a callout beside it) is drawn as soon as one of its copies
    # has a lift within reach
    # ... and an unnamed room of at most 20 m² right beside the code (``semantics.D_MAX``): stage 5 names it
    small = [a.polygon for a in live if a.type == "room" and a.polygon.area <= 0.5 * NAMED_LIFT_MAX]
    cand = [l for l in labs if l.role in ("name", "number")]
    pts = _points(np.array([[l.x, l.y] for l in cand], dtype=float).reshape(-1, 2))
    for polys, dist in ((lifts, reach), (small, semantics.D_MAX)):
        if polys and len(cand):
            hit = STRtree(polys).query(pts, predicate="dwithin", distance=dist)[0]
            done.update(semantics._key(cand[i].text) for i in set(hit.tolist()))
    for lab in codes:
        c = Point(lab.x, lab.y)
        if semantics._key(lab.text) in done:
            # two shafts side by side (SIST-F5's E1-S1 and E1-P1): the neighbour's lift is within reach, but a
            # copy of the code written inside an empty box of a larger area names that box
            at = _recess_at_code(areas, c) if semantics._key(lab.text) not in carved_codes else None
            if at is not None:
                st = carve_anchors(areas, passages, [], symbols=[("elevator", at[1].buffer(-0.05, join_style=2), (), False)])
                if st["carved"]:
                    out["carved"].extend(st["carved"])
                    out["pieces"].update(st["pieces"])
                    carved_codes.add(semantics._key(lab.text))
            continue
        live = [a for a in areas if a.polygon is not None and not a.polygon.is_empty and a.type != "structure"]
        disk = c.buffer(reach)
        best = None
        for host in _intersecting([a for a in live if a.type not in ANCHOR_TYPES], disk):
            hpoly = host.polygon
            if hpoly.area < RECESS_HOST_FACTOR * LIFT_SIDE[0] ** 2:
                continue
            u, v = _axes(hpoly)
            x0, y0, x1, y1 = hpoly.intersection(disk).bounds
            gx, gy = np.meshgrid(np.arange(x0, x1, RECESS_STEP), np.arange(y0, y1, RECESS_STEP))
            pts = np.column_stack([gx.ravel(), gy.ravel()])
            if not len(pts):
                continue
            inside = shapely.contains(hpoly.buffer(-0.1), _points(pts)) & shapely.contains(disk, _points(pts))
            pts = pts[inside]
            # rays reach LIFT_SIDE (the march twice that) beyond a seed: the border near the code is enough
            border = _recess_walls(hpoly, disk.buffer(2.5 * LIFT_SIDE[1]))
            # a seed in a recess has walls within a lift's side on both sides across one axis and behind it
            dist = {k: _wall_distances(border, pts, sgn * ax, LIFT_SIDE[1])
                    for k, (sgn, ax) in enumerate(((1.0, u), (-1.0, u), (1.0, v), (-1.0, v)))}
            span_u, span_v = dist[0] + dist[1], dist[2] + dist[3]
            ok_u = (span_u >= LIFT_SIDE[0]) & (span_u <= LIFT_SIDE[1]) & (np.isfinite(dist[2]) ^ np.isfinite(dist[3]))
            ok_v = (span_v >= LIFT_SIDE[0]) & (span_v <= LIFT_SIDE[1]) & (np.isfinite(dist[0]) ^ np.isfinite(dist[1]))
            pts = pts[ok_u | ok_v]
            pts = pts[np.argsort(np.hypot(pts[:, 0] - c.x, pts[:, 1] - c.y))]
            free = np.ones(len(pts), bool)  # seeds not inside a box found already
            geoms = _points(pts)
            for k, q in enumerate(pts):
                if best is not None and Point(q).distance(c) > best[0] + LIFT_SIDE[1]:
                    break
                if not free[k]:
                    continue
                bx = _recess_box(hpoly, q, u, v, border)
                if bx is None:
                    continue
                bx = bx.intersection(hpoly)
                if bx.geom_type != "Polygon" or bx.area > hpoly.area / RECESS_HOST_FACTOR:
                    continue
                free &= ~shapely.contains(bx, geoms)
                d = bx.distance(c)
                if d <= reach and (best is None or d < best[0]):
                    best = (d, host, bx)
        if best is None:
            continue
        _d, host, bx = best
        sym = bx.buffer(-0.05, join_style=2)
        st = carve_anchors(areas, passages, [], symbols=[("elevator", sym, (), False)])
        if st["carved"]:
            out["carved"].extend(st["carved"])
            out["pieces"].update(st["pieces"])
            done.add(semantics._key(lab.text))
            carved_codes.add(semantics._key(lab.text))
    return out


__all__ = ["carve_anchors", "coded_lift_recesses", "refit_passage_ends", "relabel", "find_anchor_symbols", "footprint"]
