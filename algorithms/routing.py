"""Route planning over an osmAG map (pipeline stage 9).

The map is the osmAG Area Graph: areas (rooms, corridors, stairs, lifts) joined by passages. A robot of
radius ``r`` is planned for in its configuration space, built once per map and radius and cached:

* **Configuration space per level.** Walls are every area border except the passage openings
  (openings are the passage segments, flat-capped); the free space is the union of the level's areas
  (structure areas such as floor and building outlines excluded) minus the walls grown by ``r``. Each
  area's share of it (``area ∩ free``) may fall apart into several pieces when the area narrows below
  ``2r``; every piece is planned on separately.
* **Graph: passages are nodes.** A passage narrower than ``2r`` is closed. Otherwise the robot's centre
  crosses it anywhere on the passage segment shortened by ``r`` at both ends (its span); crossing nodes
  are put at both ends of the span (a route that turns through a door hugs a jamb there) and, on wide
  openings (corridor splits, halls), every ``PORTAL_SPACING`` metres between them, so routes that cut
  across an opening are not forced through one point. A node lying outside the
  shrunk area (a passage drawn off the border, a nook) joins it at the nearest point, up to ``SNAP``.
* **Inside each area piece** every pair of its nodes is joined by the shortest collision-free path: a
  visibility graph over the piece's reflex vertices, all-pairs shortest paths (scipy), kept with its
  predecessors to rebuild the polyline.
* **Vertical passages** (a passage whose two areas lie on different levels, the osmAG format's stairs and
  lift links) join the shafts on both levels at ``vertical_cost`` metres per level crossed. Maps from
  other tools that only repeat a shaft's name on each floor (``E1-ST-09`` on levels 1 and 2) get an
  implicit link between same-named stairs/lift areas on adjacent levels, reported as such. Stairs and
  lifts are recognised by ``osmAG:areatype`` or, in maps that type everything ``room``, by their names
  (``ST-03``, ``stair``, ``楼梯``; ``P3``, ``lift``, ``elevator``, ``电梯``).
* **A query** joins start and goal to the nodes of their area piece the same way (visibility from the
  point, then the precomputed shortest paths); a start and goal that see each other are joined straight.
  On maps of up to ``MAX_TABLE_NODES`` nodes the node-to-node distance table (once per map, vertical cost
  and avoid set) picks the best pair of entry nodes and its predecessors give the chain of nodes: A* with
  the exact cost-to-go as heuristic, which expands exactly that chain. Larger maps run A* with the larger
  of "planar straight-line distance + ``vertical_cost`` × levels still to cross" (admissible because every
  vertical link costs at least that and every planar edge is at least the straight distance between its
  ends) and landmark (ALT) bounds.
* **Crossing points.** The search fixes the areas and passages crossed; then every crossing slides along
  its passage's span to where the route is locally shortest (:func:`_pull_crossings`: a closed-form shift
  per crossing, the neighbouring corners kept, dropped or completed, every new segment tested to lie in
  its piece), so an oblique crossing of a wide opening is not bent at the nearest node.
* **Query speed.** A point is located by a grid of cells wholly inside one piece; in large pieces (halls)
  the corners a point sees come from the corners' visibility polygons (one binary search and one side
  test per corner, :meth:`_Piece.build_visibility`), elsewhere from a segment test against the piece's
  edges. :meth:`RouteMap.prepare` builds all of it up front for many queries.
* ``avoid`` drops area types from the search: ``("stairs",)`` for wheelchairs and wheeled robots (lifts
  only), ``("elevator",)`` for evacuation routes. Their passages are then walls for the robot's disc: the
  areas next to an avoided one get pieces that keep ``r`` from it and from its openings (a variant of the
  graph per avoid set, built on its first query and kept, :meth:`RouteMap._build_variant`).

Coordinates are metres in the map's frame (osmAG files: the local frame of the root node, x east,
y north). The result keeps the level of every vertex. :class:`RouteMap` is the entry point::

    rm = RouteMap.from_osmag("building.osm")
    rm.prepare(0.3)  # optional: tables, grids and visibility polygons now rather than on the first queries
    res = rm.route((x0, y0), (x1, y1), start_level="1", goal_level="3", robot_radius=0.3,
                   avoid=("stairs",))
    res.points, res.levels, res.length, res.areas, res.passages
"""
from __future__ import annotations

import heapq
import math
import re
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .building import shaft_base_name
from .errors import InputError
from .model import Area, Passage
from .progress import ensure

DEFAULT_ROBOT_RADIUS = 0.3  # metres
DEFAULT_VERTICAL_COST = 15.0  # metres of travel one level of stairs/lift is worth
DEFAULT_HEIGHT = 3.2  # metres per level when an area has no height tag
SNAP = 1.0  # start/goal (and passages) farther than this from the robot's free space: error / not joined
PORTAL_SPACING = 1.0  # metres between crossing nodes on a wide opening
PORTAL_MIN_SPAN = 0.05  # a usable span shorter than this gets a single crossing node
MAX_PORTAL_NODES = 9
PULL_CROSSINGS = True  # slide the crossing points of a route along their passages' spans (see _pull_crossings)
PULL_SWEEPS = 3
PULL_MIN_SPAN = 1.0  # metres: only crossings of spans this wide slide (on narrower ones the nodes at both
# ends leave at most a few centimetres to gain)
PULL_MIN_GAIN = 5e-3  # metres: a crossing moves only when that shortens the route by more than this
MIN_RADIUS = 0.01  # walls are grown by at least 1 cm so that a zero radius still cannot cross them
OPENING_TOL = 0.05  # a wall within 5 cm of a passage segment is part of the opening
QUAD_SEGS = 2  # 45 degree chords on the rounded corners of grown walls (sagitta 7.6 % of r)
AVOIDABLE = ("stairs", "elevator")
LANDMARKS = 12  # ALT heuristic landmarks (maps too large for the node distance table)
COMPACT_TABLES = True  # the query tables in compact dtypes (float32 costs, int16 predecessors where they fit):
# half the memory the tables hold; choices on float32 sums, the chosen costs recomputed in float64
MAX_TABLE_NODES = 4000  # node-to-node distance table (n^2 x 6 bytes kept, 96 MB at 4000) up to this size
MAX_TABLES = 4  # tables kept per map and radius (vertical cost x avoid set)
AVOID_WALLS = True  # passages into avoided areas are walls for the robot's disc (see RouteMap._avoid_variant)
MAX_VARIANTS = 2  # avoid variants of a graph kept (least recently used dropped)
_FAR = 1e15  # landmark distance standing for "unreachable"
KIND_CODES_INV = ("room", "corridor", "stairs", "elevator", "other")
KIND_CODES = {k: i for i, k in enumerate(KIND_CODES_INV)}

_STAIR_RE = re.compile(r"(stair|treppe|escalat|scala|escalera|楼梯|樓梯|扶梯)|(?:^|[^A-Za-z])ST[-_ ]?\d",
                       re.IGNORECASE)
_LIFT_RE = re.compile(r"(elevator|lift|aufzug|ascensore|ascensor|电梯|電梯)|(?:^|[-_ ])(?:P|EV|EL)[-_ ]?\d+[A-Za-z]?$",
                      re.IGNORECASE)


class RouteError(InputError):
    """No route: the message names the disconnected parts; ``components`` holds them."""

    def __init__(self, message, components=None):
        super().__init__(message)
        self.components = components or {}


def infer_area_type(area_type: str, name: str) -> str:
    """The area's type, with stairs and lifts recognised by name in maps that type everything 'room'."""
    t = (area_type or "room").strip().lower()
    if t in ("stairs", "elevator", "structure", "corridor"):
        return t
    if t in ("stair", "staircase"):
        return "stairs"
    if t in ("lift", "elevators"):
        return "elevator"
    # without the level suffix fusion adds to keep names unique ('E-P1 (level 2)')
    n = re.sub(r"\s*\((?:level|L)\s*-?[\w.]+\)\s*$", "", name or "", flags=re.I)
    if _STAIR_RE.search(n):
        return "stairs"
    if _LIFT_RE.search(n):
        return "elevator"
    return t or "room"


def _level_of(tags: Dict[str, str], default: str = "") -> str:
    v = str((tags or {}).get("level", default) or default).strip()
    return v.split(";")[0].strip() if v else default


def _as_float(s: str) -> Optional[float]:
    try:
        v = float(s)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


# =========================================================================== results
@dataclass
class RouteResult:
    points: np.ndarray  # (N, 2) metres, map frame
    levels: List[str]  # level of every vertex (a level change repeats the position)
    z: np.ndarray  # (N,) level elevation in metres (level x height)
    length: float  # metres travelled in the plane
    cost: float  # length + vertical_cost per level crossed
    level_changes: int
    areas: List[str]  # names of the areas crossed, in order
    passages: List[str]  # names of the passages crossed, in order
    area_ids: List[int]
    passage_ids: List[int]
    start: Tuple[float, float]  # the start used (after snapping)
    goal: Tuple[float, float]
    start_snap: float  # metres the start was moved into the robot's free space
    goal_snap: float
    query_ms: float  # time of the search alone (map already loaded)
    expanded: int = 0
    warnings: List[str] = field(default_factory=list)
    graph_cost: float = math.nan  # the node graph's optimum, before the crossings are pulled (cost <= it)


# =========================================================================== geometry helpers
def _point(x, y):
    from shapely.geometry import Point

    return Point(x, y)


def _rings(poly):
    """Rings of an oriented polygon (exterior CCW, holes CW): free space on the left of every edge."""
    from shapely.geometry.polygon import orient

    p = orient(poly, 1.0)
    out = [np.asarray(p.exterior.coords)[:-1]]
    out.extend(np.asarray(r.coords)[:-1] for r in p.interiors)
    return [r for r in out if len(r) >= 3]


def _edges_of(rings) -> np.ndarray:
    segs = [np.hstack([r, np.roll(r, -1, axis=0)]) for r in rings]
    return np.vstack(segs) if segs else np.zeros((0, 4))


def _reflex_vertices(rings):
    """Reflex vertices (the corners a shortest path bends around) and their ring neighbours:
    (V (n, 2), prev (n, 2), next (n, 2))."""
    pts, prv, nxt = [], [], []
    for r in rings:
        a, b, c = np.roll(r, 1, axis=0), r, np.roll(r, -1, axis=0)
        cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - b[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - b[:, 0])
        m = cross < -1e-9
        pts.append(b[m])
        prv.append(a[m])
        nxt.append(c[m])
    if not pts:
        z = np.zeros((0, 2))
        return z, z, z
    return np.vstack(pts), np.vstack(prv), np.vstack(nxt)


def _tangent(V, prv, nxt, i, j) -> np.ndarray:
    """(K,) bool: the line from V[i] towards V[j] leaves V[i]'s two ring neighbours on one side, i.e. it
    only grazes the corner at V[i] (a shortest path bends only at such corners). Points that are not
    corners (prev is NaN) always pass."""
    px, py = V[i, 0], V[i, 1]
    dx, dy = V[j, 0] - px, V[j, 1] - py
    s1 = dx * (prv[i, 1] - py) - dy * (prv[i, 0] - px)
    s2 = dx * (nxt[i, 1] - py) - dy * (nxt[i, 0] - px)
    return ~((s1 * s2) < -1e-12)


_EPS2 = 1e-10  # m^4: products of orientations below this count as touching


def _crossing(ax, ay, bx, by, E) -> np.ndarray:
    """For segments (a_k, b_k) (arrays of shape (K,)) -> (K,) bool: properly crosses an edge of E (M, 4).
    Touching at an end or running along an edge is not crossing (grazing a corner is allowed)."""
    cx, cy, dx, dy = E[:, 0], E[:, 1], E[:, 2], E[:, 3]
    ex, ey = dx - cx, dy - cy
    k = ex * cy - ey * cx  # edge line: ex*y - ey*x - k = 0
    ux, uy = (bx - ax)[:, None], (by - ay)[:, None]
    s = (ux[:, 0] * ay - uy[:, 0] * ax)[:, None]  # segment line: ux*y - uy*x - s = 0
    o1 = ux * cy - uy * cx - s
    o2 = ux * dy - uy * dx - s
    hit = o1 * o2 < -_EPS2
    o3 = ex * ay[:, None] - ey * ax[:, None] - k
    o4 = ex * by[:, None] - ey * bx[:, None] - k
    hit &= o3 * o4 < -_EPS2
    return hit.any(axis=1)


def _edge_parts(E) -> Tuple[np.ndarray, ...]:
    """Columns of an edge array used by :func:`_crossing_from`: (cx, cy, dx, dy, ex, ey), contiguous."""
    cx, cy, dx, dy = (np.ascontiguousarray(E[:, k]) for k in range(4))
    return cx, cy, dx, dy, dx - cx, dy - cy


def _crossing_from(px: float, py: float, bx, by, E, parts=None) -> np.ndarray:
    """:func:`_crossing` for segments that all start at one point (px, py): cheaper. ``parts``: the
    edges' :func:`_edge_parts`, precomputed once per piece (queries are dominated by call overheads)."""
    cx, cy, dx, dy, ex, ey = parts if parts is not None else _edge_parts(E)
    o3 = ex * (py - cy) - ey * (px - cx)  # (M,): side of the common start point
    near = o3 != 0  # edges through the start point cannot be crossed properly
    if not near.all():
        if not near.any():
            return np.zeros(len(bx), bool)
        cx, cy, dx, dy, ex, ey, o3 = cx[near], cy[near], dx[near], dy[near], ex[near], ey[near], o3[near]
    ux, uy = (bx - px)[:, None], (by - py)[:, None]
    o1 = ux * (cy - py) - uy * (cx - px)
    o2 = ux * (dy - py) - uy * (dx - px)
    hit = o1 * o2 < -_EPS2
    o4 = ex * (by[:, None] - cy) - ey * (bx[:, None] - cx)
    hit &= o3 * o4 < -_EPS2
    return hit.any(axis=1)


_BATCH = 8  # lazy visibility: segments tested together
_DENSE_UP_TO = 6000  # candidates x edges up to which all candidates are tested at once
VP_FROM = 2000  # pieces with edges x vertices above this get their vertices' visibility polygons ...
VP_AFTER = 3  # ... by RouteMap.prepare, or once that many queries started or ended in them
_SPARSE_FROM = 4000  # targets x edges above which the visibility from a point culls edges by angle first


def _crossing_from_sparse(px: float, py: float, bx, by, parts) -> np.ndarray:
    """:func:`_crossing_from` for many targets and edges (a large hall): an edge can only cross the segment
    from p to a target if the target's direction, seen from p, lies within the angle the edge subtends; the
    targets are sorted by angle and each edge is tested against the targets in its angle only (binary
    search), instead of against all of them. Same result as the dense test."""
    cx, cy, dx, dy, ex, ey = parts
    K = len(bx)
    o3 = ex * (py - cy) - ey * (px - cx)
    near = o3 != 0
    if not near.all():
        cx, cy, dx, dy, ex, ey, o3 = cx[near], cy[near], dx[near], dy[near], ex[near], ey[near], o3[near]
    a1 = np.arctan2(cy - py, cx - px)
    a2 = np.arctan2(dy - py, dx - px)
    d = np.mod(a2 - a1 + np.pi, 2 * np.pi) - np.pi  # the edge's signed angle seen from p, |d| < pi
    start = np.where(d >= 0, a1, a2)
    th = np.arctan2(by - py, bx - px)
    order = np.argsort(th)
    ts = th[order]
    ext = np.concatenate([ts, ts + 2 * np.pi])
    lo = np.searchsorted(ext, start - 1e-9, "left")
    hi = np.searchsorted(ext, start + np.abs(d) + 1e-9, "right")
    cnt = hi - lo
    tot = int(cnt.sum())
    hit = np.zeros(K, bool)
    if tot == 0:
        return hit
    e_idx = np.repeat(np.arange(len(cnt)), cnt)
    offs = np.arange(tot) - np.repeat(np.cumsum(cnt) - cnt, cnt)
    t_idx = order[(np.repeat(lo, cnt) + offs) % K]
    ux, uy = bx[t_idx] - px, by[t_idx] - py
    ccx, ccy = cx[e_idx], cy[e_idx]
    o1 = ux * (ccy - py) - uy * (ccx - px)
    o2 = ux * (dy[e_idx] - py) - uy * (dx[e_idx] - px)
    o4 = ex[e_idx] * (by[t_idx] - ccy) - ey[e_idx] * (bx[t_idx] - ccx)
    ok = (o1 * o2 < -_EPS2) & (o3[e_idx] * o4 < -_EPS2)
    hit[t_idx[ok]] = True
    return hit


class _Piece:
    """One connected piece of an area's free space: visibility graph and all-pairs shortest paths."""

    def __init__(self, key, area_index: int, poly, level: str):
        import shapely

        self.key = key
        self.area_index = area_index
        self.level = level
        self.poly = poly
        self.tol_poly = poly.buffer(1e-6)
        shapely.prepare(self.tol_poly)
        self.core = poly.buffer(-1e-5)  # points in here are strictly inside
        shapely.prepare(self.core)
        rings = _rings(poly)
        self.edges = _edges_of(rings)
        self.edge_parts = _edge_parts(self.edges)
        self.V, self.prv, self.nxt = _reflex_vertices(rings)  # entries are appended later
        self.entries: List[Tuple[int, int, float]] = []  # (graph node, vertex index, snap distance)
        self.D = None
        self.pred = None
        self.queries = 0
        self._vp = None
        self.paths: Dict[Tuple[int, int], np.ndarray] = {}  # (vertex, vertex) -> polyline, once rebuilt
        self.tpaths: Dict[Tuple[int, int], list] = {}  # the same as [(x, y, vertex)] (_pull_crossings)

    def large(self) -> bool:
        """Worth visibility polygons: testing a point against all corners and edges would be slow."""
        return len(self.edges) * len(self.V) > VP_FROM

    def add_point(self, xy) -> int:
        self.V = np.vstack([self.V, np.asarray(xy, float)[None, :]])
        nan = np.full((1, 2), np.nan)
        self.prv = np.vstack([self.prv, nan])
        self.nxt = np.vstack([self.nxt, nan])
        return len(self.V) - 1

    def visible_from(self, p, targets: np.ndarray, interior: bool = False) -> np.ndarray:
        """(K,) bool: is the segment from point p to each target collision-free inside the piece?
        ``interior``: p lies strictly inside, so a segment that crosses no edge stays inside."""
        if len(targets) == 0:
            return np.zeros(0, bool)
        if interior:
            if len(targets) * len(self.edges) > _SPARSE_FROM:
                return ~_crossing_from_sparse(float(p[0]), float(p[1]), targets[:, 0], targets[:, 1],
                                              self.edge_parts)
            return ~_crossing_from(float(p[0]), float(p[1]), targets[:, 0], targets[:, 1], self.edges,
                                   self.edge_parts)
        ax = np.full(len(targets), p[0])
        ay = np.full(len(targets), p[1])
        return self._visible(ax, ay, targets[:, 0], targets[:, 1], samples=True)

    def _visible(self, ax, ay, bx, by, samples: bool = True) -> np.ndarray:
        import shapely

        ok = ~_crossing(ax, ay, bx, by, self.edges)
        for t in ((0.5, 0.25, 0.75) if samples else ()):
            idx = np.nonzero(ok)[0]
            if not len(idx):
                break
            mx = ax[idx] + t * (bx[idx] - ax[idx])
            my = ay[idx] + t * (by[idx] - ay[idx])
            ok[idx] = shapely.intersects_xy(self.tol_poly, mx, my)
        return ok

    # ---------------------------------------------------------------- visibility polygons of the corners
    def build_visibility(self):
        """The visibility polygon of every vertex (corners and entry points), for the queries: seen from
        vertex o, the directions towards all the piece's vertices cut the plane into wedges; inside a wedge no
        vertex lies, so the edges crossing it keep their order, and the nearest one (found on the wedge's
        middle ray) bounds what o sees in the whole wedge. A point p strictly inside the piece sees o iff p is
        not beyond that edge: one binary search (p's wedge) and one side test per vertex, all vertices at
        once, instead of a test against every edge. Edges through o never block (as in :func:`_crossing`).
        Stored flat: per vertex k its sorted wedge bounds (keys ``32 k + 16 + angle``, with the wrap-around
        wedge at both ends), the nearest edge per wedge (-1: none) and the side of k from that edge's line."""
        V, E = self.V, self.edges
        n, m = len(V), len(E)
        if n == 0 or m == 0:
            self._vp = None
            return
        cx, cy, dx, dy, ex, ey = self.edge_parts
        elen = np.hypot(ex, ey) + 1e-300
        two_pi = 2 * np.pi
        keys, near = np.zeros((n, m + 2)), np.zeros((n, m + 2), np.int64)
        chunk = max(1, 400_000 // m)  # origins per batch: a few MB of arrays
        for k0 in range(0, n, chunk):
            ks = np.arange(k0, min(n, k0 + chunk))
            B = len(ks)
            ox, oy = V[ks, 0][:, None], V[ks, 1][:, None]
            a_c = np.arctan2(cy - oy, cx - ox)  # (B, m): every vertex is the start of one edge
            a_d = np.arctan2(dy - oy, dx - ox)
            # the wedge bounds: the directions of all vertices, sorted (o itself, at angle 0, and repeated
            # directions only add empty or split wedges: harmless)
            ang = np.sort(a_c, axis=1)
            mid = 0.5 * (ang + np.concatenate([ang[:, 1:], ang[:, :1] + two_pi], axis=1))
            mid = np.where(mid > np.pi, mid - two_pi, mid)
            order = np.argsort(mid, axis=1)
            ux, uy = np.cos(mid).ravel(), np.sin(mid).ravel()  # the wedges' middle rays
            row = np.arange(B)[:, None]
            ms = mid[row, order]
            # the rows side by side in one sorted array (each row doubled for the wrap-around), and the
            # global wedge index (origin x m + wedge) of every entry
            ext = np.concatenate([ms, ms + two_pi], axis=1) + 16.0 * row
            gidx = (np.concatenate([order, order], axis=1) + m * row).ravel()
            d = np.mod(a_d - a_c + np.pi, two_pi) - np.pi
            s = np.where(d >= 0, a_c, a_d) + 16.0 * row
            side = (ex * (oy - cy) - ey * (ox - cx)).ravel()  # cross(c - o, e)
            w = np.where(np.abs(side) <= 1e-9 * np.tile(elen, B), 0.0, np.abs(d).ravel())  # edges through o never block
            flat = ext.ravel()
            lo = np.searchsorted(flat, s.ravel(), "right")
            hi = np.searchsorted(flat, s.ravel() + w, "left")
            cnt = np.maximum(hi - lo, 0)
            tot = int(cnt.sum())
            best = np.full(B * m, -1, np.int64)
            if tot:
                pe = np.repeat(np.arange(B * m), cnt)  # (origin, edge) of every (edge, wedge) pair
                pos = np.arange(tot) + np.repeat(lo - (np.cumsum(cnt) - cnt), cnt)
                gw = gidx[pos]
                e_i = pe % m
                den = ux[gw] * ey[e_i] - uy[gw] * ex[e_i]
                with np.errstate(divide="ignore", invalid="ignore"):
                    t = side[pe] / den  # distance along the wedge's middle ray to the edge
                tmin = np.full(B * m, np.inf)
                np.fmin.at(tmin, gw, t)
                hit = t <= tmin[gw]
                best[gw[hit]] = e_i[hit]
            # per origin m + 2 bounds: the last one - 2 pi, the m sorted ones, the first one + 2 pi; between
            # them m + 1 intervals (the wrap-around wedge at both ends), padded to m + 2
            kb = np.concatenate([ang[:, -1:] - two_pi, ang, ang[:, :1] + two_pi], axis=1)
            keys[ks] = 32.0 * ks[:, None] + 16.0 + kb
            best = best.reshape(B, m)
            near[ks] = np.concatenate([best[:, -1:], best, np.full((B, 1), -1)], axis=1)
        e = near.ravel()
        ok = e >= 0
        ee = np.where(ok, e, 0)
        o3 = ex[ee] * (np.repeat(V[:, 1], m + 2) - cy[ee]) - ey[ee] * (np.repeat(V[:, 0], m + 2) - cx[ee])
        o3 = np.where(ok, o3, np.nan).astype(np.float32)  # NaN: no edge (only the outside there): test exactly
        self._vp = (keys.ravel(), e.astype(np.int32), o3)

    def visible_vertices(self, px: float, py: float, cand: np.ndarray) -> np.ndarray:
        """(K,) bool: does the point p (strictly inside the piece) see the vertices ``cand``? By the
        vertices' visibility polygons (:meth:`build_visibility`); the rare points within a hair of a wedge
        bound or of the bounding edge's line get the exact segment test."""
        keys, near, o3 = self._vp
        vx, vy = self.V[cand, 0], self.V[cand, 1]
        q = np.arctan2(py - vy, px - vx) + (32.0 * cand + 16.0)
        i = np.searchsorted(keys, q, "right") - 1
        gap = np.minimum(q - keys[i], keys[i + 1] - q)
        e = near[i]
        cx, cy, dx, dy, ex, ey = self.edge_parts
        prod = o3[i] * (ex[e] * (py - cy[e]) - ey[e] * (px - cx[e]))
        seen = prod >= -_EPS2
        unsure = (gap < 1e-9) | ~(np.abs(prod) >= 1e-8)
        if unsure.any():
            u = np.flatnonzero(unsure)
            seen[u] = self.visible_from((px, py), self.V[cand[u]], interior=True)
        return seen

    def solve(self):
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import shortest_path

        n = len(self.V)
        if n == 0:
            self.D = np.zeros((0, 0))
            self.pred = np.zeros((0, 0), np.int32)
            return
        iu, ju = np.triu_indices(n, 1)
        keep = _tangent(self.V, self.prv, self.nxt, iu, ju) & _tangent(self.V, self.prv, self.nxt, ju, iu)
        iu, ju = iu[keep], ju[keep]
        vis = np.zeros(len(iu), bool)
        chunk = max(1, 2_000_000 // max(1, len(self.edges)))
        for s in range(0, len(iu), chunk):
            i, j = iu[s:s + chunk], ju[s:s + chunk]
            vis[s:s + chunk] = self._visible(self.V[i, 0], self.V[i, 1], self.V[j, 0], self.V[j, 1])
        i, j = iu[vis], ju[vis]
        w = np.hypot(self.V[i, 0] - self.V[j, 0], self.V[i, 1] - self.V[j, 1]) + 1e-12
        g = coo_matrix((w, (i, j)), shape=(n, n)).tocsr()
        self.D, pred = shortest_path(g, method="D", directed=False, return_predecessors=True)
        self.pred = _compact_index(pred)

    def path_between(self, a: int, b: int) -> np.ndarray:
        """The shortest path a -> b as points, kept (also as [(x, y, vertex)] in ``tpaths``)."""
        idx = self.vertex_path(a, b)
        xy = self.paths[(a, b)] = self.V[idx]
        self.tpaths[(a, b)] = [(float(p[0]), float(p[1]), v) for p, v in zip(xy.tolist(), idx)]
        return xy

    def vertex_path(self, i: int, j: int) -> List[int]:
        """Vertex indices of the shortest path i -> j (both included)."""
        out = [j]
        while out[-1] != i:
            k = int(self.pred[i, out[-1]])
            if k < 0:
                return [i, j]
            out.append(k)
        return out[::-1]

    def _inside_xy(self, x, y) -> bool:
        import shapely

        return bool(shapely.contains_xy(self.core, x, y))

    def _query_tables(self):
        """Per-piece constants of :meth:`point_costs`, once the vertices are final (after :meth:`solve`):
        the grazing test of a corner from a point p is linear in p (s = A + px B + py C), the vertex
        columns and the entry vertices."""
        V, P, N = self.V, self.prv, self.nxt
        vx, vy = np.ascontiguousarray(V[:, 0]), np.ascontiguousarray(V[:, 1])
        # s1 = (vx - px)(Py - py) - (vy - py)(Px - px) = vx Py - vy Px + px (vy - Py) + py (Px - vx)
        t = [(vx * Q[:, 1] - vy * Q[:, 0], vy - Q[:, 1], Q[:, 0] - vx) for Q in (P, N)]
        ent = np.unique(np.array([vi for _, vi, _ in self.entries], np.int64)) if self.entries else \
            np.zeros(0, np.int64)
        Dent = self.D[:, ent] if self.D is not None and len(ent) else None
        if Dent is not None and COMPACT_TABLES:
            Dent = Dent.astype(np.float32)  # added to float64 distances: the sums stay float64
        self._qt = (vx, vy, t[0], t[1], ent, Dent)
        # the entries as arrays: graph node, vertex, snap distance
        self.e_node = np.array([nd for nd, _, _ in self.entries], np.int64)
        self.e_vi = np.array([vi for _, vi, _ in self.entries], np.int64)
        self.e_d = np.array([d for _, _, d in self.entries], float)
        return self._qt

    def point_costs(self, p, entries_only: bool = False):
        """Shortest distances from point p (inside the piece) to every vertex, and the first vertex used.

        Returns (dist (n,), via (n,)): via[k] = the vertex p sees directly on its way to k. With
        ``entries_only`` only the entry vertices (the passage nodes) are filled in (inf / -1 elsewhere):
        all a query between two pieces needs."""
        n = len(self.V)
        qt = getattr(self, "_qt", None)
        if qt is None or len(qt[0]) != n:
            qt = self._query_tables()
        vx, vy, (a1, b1, c1), (a2, b2, c2), ent, Dent = qt
        # only corners the line from p grazes can be the first bend of a shortest path
        px, py = float(p[0]), float(p[1])
        s1 = a1 + px * b1 + py * c1
        s2 = a2 + px * b2 + py * c2
        cand = np.nonzero(~((s1 * s2) < -1e-12))[0]
        interior = self._inside_xy(px, py)
        idx = cand[self.visible_from(p, self.V[cand], interior=interior)]
        if not len(idx):
            return np.full(n, np.inf), np.full(n, -1)
        d0 = np.hypot(vx[idx] - px, vy[idx] - py)
        if entries_only and Dent is not None:
            tot = d0[:, None] + Dent[idx]
            best = np.argmin(tot, axis=0)
            dist, via = np.full(n, np.inf), np.full(n, -1)
            dist[ent] = tot[best, np.arange(len(ent))]
            via[ent] = idx[best]
            return self._exact(px, py, ent, dist, via)
        tot = d0[:, None] + self.D[idx, :]
        best = np.argmin(tot, axis=0)
        return tot[best, np.arange(n)], idx[best]



    # ---------------------------------------------------------------- lazy visibility (queries)
    def _candidates(self, px: float, py: float):
        """Corners the line from p grazes (the only possible first bends of a shortest path from p) and
        their distances from p."""
        qt = getattr(self, "_qt", None)
        if qt is None or len(qt[0]) != len(self.V):
            qt = self._query_tables()
        vx, vy, (a1, b1, c1), (a2, b2, c2), ent, Dent = qt
        s1 = a1 + px * b1 + py * c1
        s2 = a2 + px * b2 + py * c2
        cand = np.flatnonzero(~(s1 * s2 < -1e-12))  # NaN (points that are not corners) passes
        return cand, np.hypot(vx[cand] - px, vy[cand] - py), qt

    def _test(self, p, interior, cand, state, rows, score):
        """Test the visibility from p of the candidates ``rows`` (indices into ``cand``) not tested yet,
        padded with the untested ones of smallest ``score`` up to ``_BATCH`` (a batch costs about what one
        segment costs); fills ``state`` (1 seen, -1 hidden)."""
        unk = rows[state[rows] == 0]
        if not len(unk):
            return
        if len(unk) < _BATCH:
            sc = np.where(state == 0, score, np.inf)
            sc[unk] = np.inf
            more = np.argpartition(sc, _BATCH)[:_BATCH] if len(sc) > _BATCH else np.arange(len(sc))
            more = more[np.isfinite(sc[more])]
            unk = np.concatenate([unk, more[np.argsort(sc[more])][:_BATCH - len(unk)]])
        vis = self.visible_from(p, self.V[cand[unk]], interior=interior)
        state[unk] = np.where(vis, 1, -1)

    def entry_costs(self, p, interior: Optional[bool] = None):
        """Shortest distances from point p (inside the piece) to the entry vertices (the passage nodes),
        and the first vertex of each path: (dist (n,), via (n,)), inf / -1 off the entries.

        Same result as :meth:`point_costs` with ``entries_only``, cheaper: with visibility polygons (a
        strictly interior point of a large piece) or few candidates x edges, all candidates are tested at
        once; otherwise lazily: per entry the best candidate corner (distance from p + shortest path on)
        is taken and only those are tested, in batches; a hidden one drops out and the next best is taken
        (a large hall: ~10 of ~90 candidates tested)."""
        n = len(self.V)
        px, py = float(p[0]), float(p[1])
        cand, d0, qt = self._candidates(px, py)
        ent, Dent = qt[4], qt[5]
        dist, via = np.full(n, np.inf), np.full(n, -1)
        if not len(cand) or Dent is None:
            return dist, via
        if interior is None:
            interior = self._inside_xy(px, py)
        vp = interior and self._vp is not None
        if vp or len(cand) * len(self.edges) <= _DENSE_UP_TO:  # all candidates at once
            seen = self.visible_vertices(px, py, cand) if vp else self.visible_from(p, self.V[cand], interior)
            cand, T = cand[seen], d0[seen, None] + Dent[cand[seen]]
            if not len(cand):
                return dist, via
            best = T.argmin(axis=0)
            val = T[best, np.arange(len(ent))]
            ok = np.isfinite(val)
            dist[ent[ok]] = val[ok]
            via[ent[ok]] = cand[best[ok]]
            return self._exact(px, py, ent[ok], dist, via)
        T = d0[:, None] + Dent[cand]
        state = np.zeros(len(cand), np.int8)
        cols = np.arange(len(ent))
        while True:
            best = T.argmin(axis=0)
            val = T[best, cols]
            rows = np.unique(best[np.isfinite(val)])
            if not len(rows) or (state[rows] == 1).all():
                break
            self._test(p, interior, cand, state, rows, T.min(axis=1))
            T[state == -1] = np.inf
        ok = np.isfinite(val)
        dist[ent[ok]] = val[ok]
        via[ent[ok]] = cand[best[ok]]
        return self._exact(px, py, ent[ok], dist, via)

    def _exact(self, px: float, py: float, ent: np.ndarray, dist: np.ndarray, via: np.ndarray):
        """With ``COMPACT_TABLES`` the best first corner per entry was chosen on float32 path lengths: the
        chosen ones' costs again in float64 (one element of D per entry)."""
        if COMPACT_TABLES and len(ent):
            v = via[ent]
            dist[ent] = np.hypot(self.V[v, 0] - px, self.V[v, 1] - py) + self.D[v, ent]
        return dist, via

    def pair_cost(self, sp, tp, s_int: Optional[bool] = None, t_int: Optional[bool] = None):
        """Shortest path inside the piece between two of its points: (cost, first corner, last corner);
        (inf, -1, -1) when the piece links them only through other areas. The caller has already found
        the straight segment blocked. Lazy like :meth:`entry_costs`: the best pair of candidate corners
        (one seen from each end) is tested, a hidden one drops out."""
        if not len(self.V):
            return math.inf, -1, -1
        cs, ds, _ = self._candidates(float(sp[0]), float(sp[1]))
        ct, dt, _ = self._candidates(float(tp[0]), float(tp[1]))
        if not len(cs) or not len(ct):
            return math.inf, -1, -1
        if s_int is None:
            s_int = self._inside_xy(float(sp[0]), float(sp[1]))
        if t_int is None:
            t_int = self._inside_xy(float(tp[0]), float(tp[1]))
        if self._vp is not None and (s_int or t_int):
            if s_int:
                keep = self.visible_vertices(float(sp[0]), float(sp[1]), cs)
                cs, ds = cs[keep], ds[keep]
            if t_int:
                keep = self.visible_vertices(float(tp[0]), float(tp[1]), ct)
                ct, dt = ct[keep], dt[keep]
            if not len(cs) or not len(ct):
                return math.inf, -1, -1
        M = ds[:, None] + self.D[np.ix_(cs, ct)] + dt[None, :]
        ss = np.zeros(len(cs), np.int8)
        st = np.zeros(len(ct), np.int8)
        if self._vp is not None:
            ss[:] = 1 if s_int else 0
            st[:] = 1 if t_int else 0
        st = np.zeros(len(ct), np.int8)
        while True:
            k = int(M.argmin())
            i, j = divmod(k, M.shape[1])
            c = float(M[i, j])
            if not math.isfinite(c):
                return math.inf, -1, -1
            if ss[i] == 1 and st[j] == 1:
                return c, int(cs[i]), int(ct[j])
            if ss[i] == 0:
                self._test(sp, s_int, cs, ss, np.array([i]), M.min(axis=1))
                M[ss == -1, :] = np.inf
            if st[j] == 0:
                self._test(tp, t_int, ct, st, np.array([j]), M.min(axis=0))
                M[:, st == -1] = np.inf


def _compact_index(a: np.ndarray) -> np.ndarray:
    """Predecessor indices (-9999: none) as int16 where they fit (``COMPACT_TABLES``), else int32."""
    small = COMPACT_TABLES and (a.size == 0 or (int(a.max()) < 32768 and int(a.min()) >= -32768))
    return a.astype(np.int16 if small else np.int32)


def _avoid_mask(avoid) -> Optional[np.ndarray]:
    """Per area-type code: is it avoided? (None when nothing is.)"""
    return np.array([k in avoid for k in KIND_CODES_INV]) if avoid else None


def _min_matrix(rows, cols, w, n):
    """Sparse n x n matrix keeping the cheapest of parallel edges (scipy would add them up)."""
    from scipy.sparse import csr_matrix

    rows, cols, w = np.asarray(rows, np.int64), np.asarray(cols, np.int64), np.asarray(w, float)
    if len(w):
        order = np.lexsort((w, cols, rows))
        rows, cols, w = rows[order], cols[order], w[order]
        first = np.ones(len(w), bool)
        first[1:] = (rows[1:] != rows[:-1]) | (cols[1:] != cols[:-1])
        rows, cols, w = rows[first], cols[first], w[first]
    return csr_matrix((w, (rows, cols)), shape=(n, n))



GRID_CELL = 0.15  # metres: the point-location grid's cells (coarser on large maps)
GRID_MAX_CELLS = 2_000_000


def _point_grid(g, lev):
    """Point location by a grid over the level's pieces (``lev`` None: all levels): a cell holds the piece
    it lies wholly and strictly inside of, else -1 (near a border, outside, or in pieces that overlap,
    e.g. floors above one another): (x0, y0, cell, labels, pieces), or None without pieces. Cells are
    filled by their centres and every border is drawn 3 cells wide, so a labelled cell has no border
    within it: a point in it needs no further test."""
    import cv2

    pcs = [pc for pc in g.pieces.values() if lev is None or pc.level == lev]
    if not pcs:
        return None
    b = np.array([pc.tol_poly.bounds for pc in pcs])
    x0, y0, x1, y1 = b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()
    h = max(GRID_CELL, math.sqrt((x1 - x0) * (y1 - y0) / GRID_MAX_CELLS))
    x0, y0 = x0 - 2 * h, y0 - 2 * h
    nx, ny = int((x1 - x0) / h) + 3, int((y1 - y0) / h) + 3
    count = np.zeros((ny, nx), np.uint8)
    lab = np.full((ny, nx), -1, np.int32)
    border = np.zeros((ny, nx), np.uint8)
    shift = 4  # sub-cell precision of the drawing
    for k, pc in enumerate(pcs):
        bx0, by0, bx1, by1 = pc.tol_poly.bounds
        c0, r0 = max(0, int((bx0 - x0) / h) - 2), max(0, int((by0 - y0) / h) - 2)
        c1, r1 = min(nx, int((bx1 - x0) / h) + 3), min(ny, int((by1 - y0) / h) + 3)
        rings = []
        poly = pc.poly
        for ring in [poly.exterior] + list(poly.interiors):
            xy = np.asarray(ring.coords)[:, :2]
            # cell (r, c) has its centre at x0 + (c + 0.5) h: pixel coordinates in the window
            px = (xy[:, 0] - x0) / h - 0.5 - c0
            py = (xy[:, 1] - y0) / h - 0.5 - r0
            rings.append(np.round(np.column_stack([px, py]) * (1 << shift)).astype(np.int32))
        mask = np.zeros((r1 - r0, c1 - c0), np.uint8)
        cv2.fillPoly(mask, rings, 1, lineType=cv2.LINE_8, shift=shift)
        cv2.polylines(border[r0:r1, c0:c1], rings, True, 1, thickness=3, lineType=cv2.LINE_8, shift=shift)
        count[r0:r1, c0:c1] += mask
        sub = lab[r0:r1, c0:c1]
        sub[mask > 0] = k
    lab[(count != 1) | (border > 0)] = -1
    return (float(x0), float(y0), float(h), lab, pcs)


# =========================================================================== crossing points
def _back(L, i):
    """Index of the last point of L (a list of (x, y, vertex)) before index i that differs from L[i]; -1:
    none."""
    x, y = L[i][0], L[i][1]
    j = i - 1
    while j >= 0 and abs(L[j][0] - x) + abs(L[j][1] - y) <= 1e-9:
        j -= 1
    return j


def _segments_in(segs, pcs) -> np.ndarray:
    """(S,) bool: does segment k (segs (S, 2, 2)) stay in piece pcs[k]? Inside the piece grown by 10⁻⁶ m
    (a segment may graze a corner or run along an edge), tested on its prepared polygon: one GEOS call
    for all the segments."""
    import shapely

    return shapely.contains_properly(np.array([pc.tol_poly for pc in pcs], dtype=object), shapely.linestrings(segs))


def _pull_crossings(T, cpc, cross, span) -> Tuple[float, set]:
    """Make a route locally shortest at its passage crossings; returns (length saved, chunks changed).

    The search crosses every passage at one of its fixed nodes (both ends of the usable span and every
    ``PORTAL_SPACING`` metres between), so a route that should cut a wide opening obliquely bends at the
    nearest node. Here each crossing (entry point in the area piece before it, node on the passage, entry
    point in the piece after it) slides as one along its passage's span, to the shift that minimises the
    distance from the route's previous point to the entry before plus from the entry after to the route's
    next point (closed form: where the straight line between them, or its mirror image, meets the span;
    clamped to the span). Next to a moved entry the route keeps its previous point, drops it (the point
    before it sees the new entry) or first bends at one of that corner's ring neighbours (a grown wall
    corner is several vertices), whichever is shortest and fits. Every new segment is tested to lie in its
    piece (shapely, all the segments of a round in one call), so the route stays in the robot's free space
    and crosses the same areas and passages; a shift that does not fit is halved in the next round. A round
    moves the even and then the odd crossings (neighbours stay fixed while one moves), at most
    ``PULL_SWEEPS`` rounds; a crossing moves only if that saves more than ``PULL_MIN_GAIN``, so the route is
    never longer than the search's, and deterministic. ``T``: the route's chunks (the start, then piece
    paths and crossing nodes alternately, the goal), each a list of (x, y, vertex index in its piece or -1);
    ``cpc`` the piece of every chunk (None for points), ``cross`` [(chunk, node)], ``span`` node -> the two
    ends of its passage's span, as :meth:`RouteMap._rebuild` builds them."""
    last = len(T) - 2  # the goal's piece path (the goal point is the last chunk)
    scale = [1.0] * len(cross)
    changed = set()
    saved = 0.0
    todo = [k for k, (c, n) in enumerate(cross) if span[n][2] >= PULL_MIN_SPAN]
    for _ in range(PULL_SWEEPS):
        if not todo:
            break
        again = set()
        props, polys, segs = [], [], []
        prev = -9  # chunk of the last crossing proposed to move in this round
        for k in todo:
            c, n = cross[k]
            pa, pb = cpc[c - 1], cpc[c + 1]
            if pa is None or pb is None or scale[k] < 0.2:
                continue
            L = T[c - 1] if c - 1 > 1 else T[0] + T[c - 1]  # the start point belongs to its piece's path
            R = T[c + 1][::-1] if c + 1 < last else T[-1] + T[c + 1][::-1]
            ia, ib = _back(L, len(L) - 1), _back(R, len(R) - 1)
            if ia < 0 or ib < 0:
                continue  # the entry point is the neighbouring crossing's too
            if ia == 0 and prev == c - 2 and c - 1 > 1:
                again.add(k)  # its previous point is the entry of a crossing moving in this round
                continue
            qa, qb, a, b = L[-1], R[-1], L[ia], R[ib]
            (q0x, q0y), (ux, uy), w = span[n]
            x = T[c][0]
            lo = -((x[0] - q0x) * ux + (x[1] - q0y) * uy)
            p1x, p1y, p2x, p2y = a[0] - qa[0], a[1] - qa[1], b[0] - qb[0], b[1] - qb[1]
            # the shift s minimising |p1 - s u| + |p2 - s u|: where the segment p1 p2 (or p1 and p2
            # mirrored across the line) meets the line through the origin along u
            t1, t2 = p1x * ux + p1y * uy, p2x * ux + p2y * uy
            h1, h2 = abs(p1y * ux - p1x * uy), abs(p2y * ux - p2x * uy)
            sh = t1 + (t2 - t1) * h1 / (h1 + h2) if h1 + h2 > 1e-12 else min(max(0.0, min(t1, t2)), max(t1, t2))
            sh = scale[k] * min(max(sh, lo), lo + w)
            dx, dy = sh * ux, sh * uy
            old = math.hypot(p1x, p1y) + math.hypot(p2x, p2y)
            if math.hypot(p1x - dx, p1y - dy) + math.hypot(p2x - dx, p2y - dy) >= old - PULL_MIN_GAIN:
                continue
            na, nb = (qa[0] + dx, qa[1] + dy, -1), (qb[0] + dx, qb[1] + dy, -1)
            opts = []  # per side: [(segment, index of the point kept before the new entry, bend, extra)]
            for Q, i, pc, nq in ((L, ia, pa, na), (R, ib, pb, nb)):
                o = [(len(segs), i, None, 0.0)]  # keep the previous point
                segs.append((Q[i][:2], nq[:2]))
                polys.append(pc)
                i0 = _back(Q, i)
                if i0 >= 0:  # drop it: the point before it sees the new entry
                    o.append((len(segs), i0, None, -math.hypot(Q[i0][0] - Q[i][0], Q[i0][1] - Q[i][1])))
                    segs.append((Q[i0][:2], nq[:2]))
                    polys.append(pc)
                v = Q[i][2]
                if v >= 0 and pc.prv[v, 0] == pc.prv[v, 0]:  # a corner: bend at a ring neighbour first
                    for nbr in (pc.prv[v], pc.nxt[v]):
                        bx, by = float(nbr[0]), float(nbr[1])
                        o.append((len(segs), i, (bx, by, -1), math.hypot(bx - Q[i][0], by - Q[i][1])))
                        segs.append(((bx, by), nq[:2]))
                        polys.append(pc)
                opts.append(o)
            props.append((k, c, L, R, na, nb, dx, dy, old, opts))
            prev = c
        if not props:
            continue
        ok = _segments_in(np.array(segs, float), polys)
        for (k, c, L, R, na, nb, dx, dy, old, opts) in props:
            best = []
            for Q, nq, o in ((L, na, opts[0]), (R, nb, opts[1])):
                cand = [(math.hypot((v or Q[i])[0] - nq[0], (v or Q[i])[1] - nq[1]) + extra, i, v)
                        for j, i, v, extra in o if ok[j]]
                best.append(min(cand, key=lambda t: t[0]) if cand else None)
            if best[0] is None or best[1] is None:
                scale[k] *= 0.5  # does not fit: a smaller shift next round
                again.add(k)
                continue
            if best[0][0] + best[1][0] >= old - 1e-9:
                continue
            (_, i, v), (_, j, u) = best[0][:3], best[1][:3]
            A = L[:i + 1] + ([v] if v else []) + [na]
            B = (R[:j + 1] + ([u] if u else []) + [nb])[::-1]
            T[c - 1] = A if c - 1 > 1 else A[1:]
            T[c + 1] = B if c + 1 < last else B[:-1]
            x = T[c][0]
            T[c] = [(x[0] + dx, x[1] + dy, -1)]
            changed.update((c - 1, c, c + 1))
            saved += old - best[0][0] - best[1][0]
            again.update((k - 1, k, k + 1))  # its neighbours' targets moved
        todo = [k for k in sorted(again) if 0 <= k < len(cross) and span[cross[k][1]][2] >= PULL_MIN_SPAN]
    return saved, changed


# =========================================================================== the graph
class _Graph:
    """The routing graph of a map for one robot radius."""

    def __init__(self):
        self.pos: List[Tuple[float, float]] = []  # node -> planar position
        self.rank: List[int] = []  # node -> level rank
        self.level: List[str] = []
        self.passage: List[int] = []  # node -> passage index (or -1 for an implicit vertical link)
        self.adj: List[List[tuple]] = []  # node -> [(neighbour, planar cost, kind, data)]
        self.pieces: Dict[tuple, _Piece] = {}
        self.pieces_by_area: Dict[int, List[_Piece]] = {}
        self.closed: List[Tuple[int, str]] = []  # (passage index, reason)
        self.free: Dict[str, object] = {}  # level -> free space polygon
        self.build_s = 0.0
        self.alt: Dict[tuple, np.ndarray] = {}
        self.tables: Dict[tuple, tuple] = {}
        self.last_table = None  # (vertical cost, avoid set, table) of the last query
        self.grids: Dict[object, object] = {}
        self._pos = None
        self._rank = None
        self._csr = None
        self.edata: List[tuple] = []
        self.piece_tree = None
        self.piece_list: List[_Piece] = []
        self.span: Dict[int, tuple] = {}  # crossing node -> its passage's usable span: (start, direction, length)
        self.r = 0.0  # the robot radius it was built for
        self.avoid: Tuple[str, ...] = ()  # the avoided area types this graph's pieces keep r from (a variant)
        self.variants: Dict[tuple, "_Graph"] = {}  # avoid set -> variant of this graph (RouteMap._avoid_variant)

    def csr(self) -> Dict[str, np.ndarray]:
        """The adjacency as flat arrays (built once): per node a slice of neighbours, planar costs,
        level spans (vertical links), area-type codes and edge-detail indices."""
        if self._csr is None:
            indptr = [0]
            nbr, cost, span, kcode, eid = [], [], [], [], []
            self.edata = []
            for lst in self.adj:
                for (m, c, kind, data, sp) in lst:
                    nbr.append(m)
                    cost.append(c)
                    span.append(sp)
                    kcode.append(KIND_CODES.get(kind, len(KIND_CODES_INV) - 1))
                    eid.append(len(self.edata))
                    self.edata.append(data)
                indptr.append(len(nbr))
            self._csr = {"indptr": np.asarray(indptr, np.int64), "nbr": np.asarray(nbr, np.int64),
                         "cost": np.asarray(cost, float), "span": np.asarray(span, float),
                         "kcode": np.asarray(kcode, np.int64), "eid": np.asarray(eid, np.int64)}
        return self._csr

    def pos_array(self) -> np.ndarray:
        if self._pos is None or len(self._pos) != len(self.pos):
            self._pos = np.asarray(self.pos, float).reshape(-1, 2)
        return self._pos

    def rank_array(self) -> np.ndarray:
        if self._rank is None or len(self._rank) != len(self.rank):
            self._rank = np.asarray(self.rank, float)
        return self._rank

    def add_node(self, xy, rank, level, passage) -> int:
        self.pos.append((float(xy[0]), float(xy[1])))
        self.rank.append(rank)
        self.level.append(level)
        self.passage.append(passage)
        self.adj.append([])
        return len(self.pos) - 1


# =========================================================================== the map
class RouteMap:
    """An osmAG map ready for route queries. Build it with :meth:`from_osmag` or :meth:`from_areas`."""

    def __init__(self, areas: Sequence[Area], passages: Sequence[Passage], levels: Optional[Sequence[str]] = None,
                 frame=None, warnings: Sequence[str] = (), progress=None):
        """``areas``/``passages`` in metres; ``levels``: one per area (default: each area's ``level``
        tag, else "1"). ``frame``: the LocalFrame of the coordinates (osmAG files), or None."""
        progress = ensure(progress)
        self.frame = frame
        self.warnings: List[str] = list(warnings)
        self.areas: List[Area] = []
        self.levels: List[str] = []
        self.types: List[str] = []
        self.heights: List[float] = []
        lv_in = list(levels) if levels is not None else None
        inferred = 0
        for k, a in enumerate(areas):
            if a.polygon is None or a.polygon.is_empty:
                self.warnings.append(f"area {a.id} ({a.name}) has no geometry; ignored")
                continue
            t = infer_area_type(a.type, a.name)
            if t == "structure":
                continue
            if t != (a.type or "room").lower() and t in AVOIDABLE:
                inferred += 1
            poly = a.polygon if a.polygon.is_valid else a.polygon.buffer(0)
            if poly.is_empty:
                self.warnings.append(f"area {a.id} ({a.name}) has an invalid, empty polygon; ignored")
                continue
            b = Area(id=a.id, polygon=poly, type=t, name=a.name or str(a.id), tags=dict(a.tags or {}),
                     ref=a.ref, component=a.component)
            self.areas.append(b)
            self.levels.append(str(lv_in[k]) if lv_in is not None else _level_of(a.tags, "1") or "1")
            self.types.append(t)
            h = _as_float((a.tags or {}).get("height", ""))
            self.heights.append(h if h and h > 0 else DEFAULT_HEIGHT)
        if not self.areas:
            raise InputError("the map has no area to plan in (only structure areas, or none at all)")
        if inferred:
            self.warnings.append(f"{inferred} areas typed 'room' are stairs or lifts by their names")
        self.index = {a.id: k for k, a in enumerate(self.areas)}
        lvls = sorted(set(self.levels), key=lambda s: (_as_float(s) is None, _as_float(s) or 0.0, s))
        self.level_list = lvls
        self.level_rank = {s: i for i, s in enumerate(lvls)}
        self.passages: List[Passage] = []
        dropped = []
        for p in passages:
            if p.from_id not in self.index or p.to_id not in self.index:
                dropped.append(p.id)
                continue
            if p.line is None or p.line.is_empty or len(p.line.coords) < 2:
                self.warnings.append(f"passage {p.id} has no line; ignored")
                continue
            self.passages.append(p)
        if dropped:
            self.warnings.append(f"{len(dropped)} passages join an area that is not in the map (missing or a "
                                 f"structure area): {dropped[:10]}{' ...' if len(dropped) > 10 else ''}; ignored")
        self.vertical = [i for i, p in enumerate(self.passages)
                         if self.levels[self.index[p.from_id]] != self.levels[self.index[p.to_id]]]
        self.implicit = self._implicit_links()
        if self.implicit:
            self.warnings.append(f"{len(self.implicit)} vertical links added between same-named stairs/lift areas "
                                 "on adjacent levels (the map has no vertical passage between them)")
        self._graphs: Dict[float, _Graph] = {}
        self._tree = None
        for w in self.warnings:
            progress.warning(w)
        progress.info(f"route map: {len(self.areas)} areas on {len(lvls)} level(s) {lvls}, {len(self.passages)} "
                      f"passages ({len(self.vertical)} vertical), {len(self.implicit)} implicit vertical links")

    # ------------------------------------------------------------------ construction helpers
    @classmethod
    def from_areas(cls, areas, passages, level: str = "1", progress=None) -> "RouteMap":
        """One floor (or several, by the areas' level tags) in metres, e.g. a pipeline result."""
        levels = [_level_of(a.tags, str(level)) or str(level) for a in areas]
        return cls(areas, passages, levels=levels, progress=progress)

    @classmethod
    def from_osmag(cls, path: str, progress=None) -> "RouteMap":
        """Read an osmAG file (ours or another tool's; either variant) into its root node's local frame."""
        from .georef import LocalFrame
        from .osmag import read_osmag, to_frame

        progress = ensure(progress)
        areas, passages, root, report = read_osmag(path, progress=progress.sub(0, 60))
        warnings = []
        if root is None:
            c = _lonlat_centre(areas)
            warnings.append(f"no root node: planning in a local frame centred on {c[0]:.6f}, {c[1]:.6f}")
            root = c
        frame = LocalFrame(root[0], root[1])
        passages = _resolve_by_level(areas, passages, warnings)
        ref_errors = report.get("dangling_refs") or []
        bad_pass = sorted({w for w, k, v in ref_errors if k in ("osmAG:from", "osmAG:to")})
        if bad_pass:
            targets = sorted({v for w, k, v in ref_errors if k in ("osmAG:from", "osmAG:to")})
            shown = ", ".join(map(repr, targets[:8]))
            warnings.append(f"{len(bad_pass)} passages point at areas missing from the file ({shown}"
                            f"{' ...' if len(targets) > 8 else ''}), e.g. ways {bad_pass[:5]}; they are not used")
        m_areas, m_passages = to_frame(areas, passages, frame)
        progress.step(70)
        return cls(m_areas, m_passages, frame=frame, warnings=warnings, progress=progress)

    def _implicit_links(self) -> List[Tuple[int, int]]:
        """Same-named stairs/lift areas on adjacent levels with no vertical passage between them."""
        linked = set()
        for i in self.vertical:
            p = self.passages[i]
            a, b = self.index[p.from_id], self.index[p.to_id]
            linked.add((min(a, b), max(a, b)))
        groups: Dict[str, List[int]] = {}
        for k, a in enumerate(self.areas):
            if self.types[k] in AVOIDABLE and a.name:
                # the shaft's name without the level suffix fusion adds for uniqueness ('E-P1 (level 2)')
                groups.setdefault(shaft_base_name(a.name), []).append(k)
        out = []
        for ks in groups.values():
            ks = sorted(ks, key=lambda k: self.level_rank[self.levels[k]])
            for a, b in zip(ks, ks[1:]):
                ra, rb = self.level_rank[self.levels[a]], self.level_rank[self.levels[b]]
                if rb - ra != 1 or (min(a, b), max(a, b)) in linked:
                    continue
                if self.areas[a].polygon.distance(self.areas[b].polygon) > 5.0:
                    continue  # same name, different place: not one shaft
                out.append((a, b))
        return out

    # ------------------------------------------------------------------ the graph for one radius
    def graph(self, robot_radius: float = DEFAULT_ROBOT_RADIUS, progress=None) -> _Graph:
        """The routing graph for ``robot_radius`` (built once, then cached on this object)."""
        last = self.__dict__.get("_last_graph")
        if last is not None and last[0] == robot_radius and type(robot_radius) is float:
            return last[1]  # the commonest case: the radius of the previous query (no rounding, no lookup)
        r = float(robot_radius)
        if not (math.isfinite(r) and 0 <= r <= 5):
            raise InputError(f"ROBOT_RADIUS must be between 0 and 5 m, got {robot_radius}")
        key = round(r, 4)
        g = self._graphs.get(key)
        if g is None:
            g = self._build(max(r, MIN_RADIUS), ensure(progress))
            self._graphs[key] = g
        self._last_graph = (r, g)
        return g

    def prepare(self, robot_radius: float = DEFAULT_ROBOT_RADIUS, vertical_cost: float = DEFAULT_VERTICAL_COST,
                avoid: Sequence[str] = (), progress=None) -> _Graph:
        """Everything queries use, built now rather than on the first queries: the graph, the node distance
        table (or landmarks) for this vertical cost and avoid set, the point-location grids and the
        visibility polygons of the large pieces' corners. For many queries on one map (a robot's planner,
        the benchmark); a single query does not need it (QGIS's route tool does not call it)."""
        progress = ensure(progress)
        avoid_set = self._avoid_set(avoid)
        g = self._avoid_variant(self.graph(robot_radius, progress=progress.sub(0, 50)), avoid_set)
        vc = float(vertical_cost)
        if self._table(g, vc, avoid_set) is None:
            self._landmarks(g, vc)
        for lev in [None] + list(self.level_list):
            if lev not in g.grids:
                g.grids[lev] = _point_grid(g, lev)
        for pc in g.pieces.values():  # the per-piece query constants (else built by a piece's first query)
            if getattr(pc, "_qt", None) is None:
                pc._query_tables()
        big = [pc for pc in g.pieces.values() if pc._vp is None and pc.large()]
        for m, pc in enumerate(big):
            if m % 8 == 0:
                progress.step(50 + 50.0 * m / max(1, len(big)), "visibility polygons of the large areas")
            pc.build_visibility()
        progress.step(100)
        return g

    def _build(self, r: float, progress) -> _Graph:
        import shapely
        from shapely.geometry import LineString, Polygon
        from shapely.ops import unary_union

        t0 = time.perf_counter()
        g = _Graph()
        nlev = len(self.level_list)
        vset = set(self.vertical)
        horizontal = [i for i in range(len(self.passages)) if i not in vset]
        for li, lev in enumerate(self.level_list):
            progress.step(80.0 * li / nlev, f"routing graph: level {lev}")
            ks = [k for k in range(len(self.areas)) if self.levels[k] == lev]
            hp = [i for i in horizontal if self.levels[self.index[self.passages[i].from_id]] == lev]
            lines = []
            for k in ks:
                poly = self.areas[k].polygon
                for part in getattr(poly, "geoms", [poly]):
                    lines.append(LineString(part.exterior.coords))
                    lines.extend(LineString(h.coords) for h in part.interiors)
            openings = [self.passages[i].line.buffer(OPENING_TOL, cap_style="flat") for i in hp
                        if self.passages[i].line.length > 1e-6]
            walls = unary_union(lines)
            if openings:
                walls = walls.difference(unary_union(openings))
            free = unary_union([self.areas[k].polygon for k in ks] + openings)
            free = free.difference(walls.buffer(r, quad_segs=QUAD_SEGS))
            g.free[lev] = free
            shapely.prepare(free)
            for k in ks:
                part = free.intersection(self.areas[k].polygon)
                polys = [p for p in getattr(part, "geoms", [part]) if isinstance(p, Polygon) and p.area > 1e-4]
                g.pieces_by_area[k] = []
                for n, p in enumerate(polys):
                    pc = _Piece((k, n), k, p, lev)
                    g.pieces[(k, n)] = pc
                    g.pieces_by_area[k].append(pc)
            # crossing nodes on the level's passages
            for i in hp:
                p = self.passages[i]
                a, b = self.index[p.from_id], self.index[p.to_id]
                c = np.asarray(p.line.coords)
                p0, p1 = c[0, :2], c[-1, :2]
                w = float(np.hypot(*(p1 - p0)))
                if w < 2 * r - 1e-9:
                    g.closed.append((i, f"{w:.2f} m wide, the robot needs {2 * r:.2f} m"))
                    continue
                u = (p1 - p0) / w if w > 0 else np.zeros(2)
                q0, q1 = p0 + r * u, p1 - r * u
                span = max(0.0, w - 2 * r)
                # a route bending through a door hugs a jamb: nodes at both ends of the span (and every
                # PORTAL_SPACING metres between them); a very narrow span gets one node in its middle
                n = 1 if span < PORTAL_MIN_SPAN else min(MAX_PORTAL_NODES, 1 + int(math.ceil(span / PORTAL_SPACING)))
                xs = [0.5 * (q0 + q1)] if n == 1 else [q0 + t * (q1 - q0) for t in np.linspace(0, 1, n)]
                joined_any = False
                for x in xs:
                    ends = [self._entry(g, side, x) for side in (a, b)]
                    if any(e is None for e in ends):
                        continue
                    node = g.add_node(x, li, lev, i)
                    g.span[node] = ((float(q0[0]), float(q0[1])), (float(u[0]), float(u[1])), float(span))
                    for (pc, q, d) in ends:
                        vi = pc.add_point(q)
                        pc.entries.append((node, vi, d))
                    joined_any = True
                if not joined_any:
                    g.closed.append((i, "no room for the robot on one side of it"))
        # vertical passages and implicit links
        links = []
        for i in self.vertical:
            p = self.passages[i]
            c = np.asarray(p.line.coords)
            x = 0.5 * (c[0, :2] + c[-1, :2])
            links.append((self.index[p.from_id], self.index[p.to_id], x, x, i))
        for a, b in self.implicit:
            inter = self.areas[a].polygon.intersection(self.areas[b].polygon)
            if not inter.is_empty and inter.area > 0.05:
                x = np.asarray(inter.representative_point().coords[0])
                links.append((a, b, x, x, -1))
            else:
                xa = np.asarray(self.areas[a].polygon.representative_point().coords[0])
                xb = np.asarray(self.areas[b].polygon.representative_point().coords[0])
                links.append((a, b, xa, xb, -1))
        for a, b, xa, xb, i in links:
            ea, eb = self._entry(g, a, xa, far=True), self._entry(g, b, xb, far=True)
            if ea is None or eb is None:
                g.closed.append((i, f"the shaft {self.areas[a if ea is None else b].name} has no room for the robot"))
                continue
            na = g.add_node(xa, self.level_rank[self.levels[a]], self.levels[a], i)
            nb = g.add_node(xb, self.level_rank[self.levels[b]], self.levels[b], i)
            for n, (pc, q, d) in ((na, ea), (nb, eb)):
                vi = pc.add_point(q)
                pc.entries.append((n, vi, d))
            span = abs(self.level_rank[self.levels[a]] - self.level_rank[self.levels[b]])
            kind = "stairs" if "stairs" in (self.types[a], self.types[b]) else "elevator"
            planar = float(np.hypot(*(np.asarray(xa) - np.asarray(xb))))
            g.adj[na].append((nb, planar, kind, ("V", span), span))
            g.adj[nb].append((na, planar, kind, ("V", span), span))
        # inside each piece: all pairs of its nodes
        npc = max(1, len(g.pieces))
        for m, pc in enumerate(g.pieces.values()):
            if m % 16 == 0:
                progress.step(80.0 + 20.0 * m / npc)
            self._join_piece(g, pc)
        g.r = r
        g.build_s = time.perf_counter() - t0
        progress.step(100, f"routing graph for a robot radius of {r:.2f} m: {len(g.pos)} nodes, "
                           f"{sum(len(a) for a in g.adj) // 2} edges, {len(g.pieces)} area pieces, "
                           f"{len(g.closed)} passages closed, built in {g.build_s:.2f} s")
        return g

    def _join_piece(self, g: _Graph, pc: _Piece):
        """Solve a piece (its visibility graph) and join every pair of its nodes in the graph."""
        pc.solve()
        kind = self.types[pc.area_index]
        for x in range(len(pc.entries)):
            nx, vx, dx = pc.entries[x]
            for y in range(x + 1, len(pc.entries)):
                ny, vy, dy = pc.entries[y]
                if nx == ny:
                    continue
                c = pc.D[vx, vy]
                if not math.isfinite(c):
                    continue
                cost = dx + c + dy
                g.adj[nx].append((ny, cost, kind, (pc.key, vx, vy), 0))
                g.adj[ny].append((nx, cost, kind, (pc.key, vy, vx), 0))

    # ------------------------------------------------------------------ avoided areas: their passages as walls
    def _avoid_variant(self, g: _Graph, avoid: set) -> _Graph:
        """The graph a query with this avoid set plans on: ``g`` itself when nothing is avoided, else its
        variant in which the passages into avoided areas are walls for the robot's disc (built on the first
        query with that set, the last ``MAX_VARIANTS`` kept, see :meth:`_build_variant`)."""
        if not avoid or not AVOID_WALLS:
            return g
        key = tuple(sorted(avoid))
        if g.variants and next(reversed(g.variants)) == key:  # the most recently used: nothing to reorder
            return g.variants[key]
        v = g.variants.pop(key, None)
        if v is None:
            v = self._build_variant(g, key)
        g.variants[key] = v  # (re)inserted last: the most recently used
        while len(g.variants) > MAX_VARIANTS:
            g.variants.pop(next(iter(g.variants)))
        return v

    def _build_variant(self, g: _Graph, avoid: Tuple[str, ...]) -> _Graph:
        """A copy of graph ``g`` for a robot that must not enter the areas of the types ``avoid``: every area
        that shares a (horizontal) passage with an avoided area gets new pieces, its old ones minus the
        passage's opening and the avoided area grown by the robot radius (the passage becomes a wall: the disc
        keeps r from the passage's line and from the avoided area), joined to the same passage nodes but
        those of the closed passages and those closer than r to the avoided area or the closed opening (a
        door next to a stair's opening: the robot crossing it there would come closer than r). Every other
        piece, the nodes, their positions and spans are shared with ``g`` (unchanged); the node table,
        landmarks, point grids and STR tree are the variant's own. The avoided areas' own pieces stay (a
        query that starts or ends in one is planned on ``g``)."""
        import shapely
        from shapely.geometry import Polygon
        from shapely.ops import unary_union

        t0 = time.process_time()
        r, vset, aset = g.r, set(self.vertical), set(avoid)
        keep_off: Dict[int, list] = {}  # area -> geometry its robot keeps r from
        closed: Dict[int, set] = {}  # area -> passages closed for it
        for i, p in enumerate(self.passages):
            if i in vset:
                continue
            a, b = self.index[p.from_id], self.index[p.to_id]
            for x, y in ((a, b), (b, a)):
                if self.types[y] in aset and self.types[x] not in aset and g.pieces_by_area.get(x):
                    opening = p.line.buffer(OPENING_TOL, cap_style="flat") if p.line.length > 1e-6 else p.line
                    keep_off.setdefault(x, []).extend([opening, self.areas[y].polygon])
                    closed.setdefault(x, set()).add(i)
        v = _Graph()
        v.pos, v.rank, v.level, v.passage, v.span, v.closed, v.free = g.pos, g.rank, g.level, g.passage, g.span, \
            g.closed, g.free
        v.r, v.avoid = r, avoid
        v.pieces, v.pieces_by_area, v.adj = dict(g.pieces), dict(g.pieces_by_area), list(g.adj)
        for k in sorted(keep_off):
            olds = g.pieces_by_area[k]
            old_keys = {pc.key for pc in olds}
            wall = unary_union(keep_off[k]).buffer(r, quad_segs=QUAD_SEGS)
            part = unary_union([pc.poly for pc in olds]).difference(wall)
            polys = [q for q in getattr(part, "geoms", [part]) if isinstance(q, Polygon) and q.area > 1e-4]
            new = []
            for n, q in enumerate(polys):
                pc = _Piece((k, n) + avoid, k, q, olds[0].level)
                v.pieces[pc.key] = pc
                new.append(pc)
            for pc in olds:
                del v.pieces[pc.key]
            v.pieces_by_area[k] = new
            nodes = sorted({nd for pc in olds for nd, _, _ in pc.entries})
            xy = np.array([g.pos[nd] for nd in nodes], float).reshape(-1, 2)
            near = shapely.contains_xy(wall, xy[:, 0], xy[:, 1])  # a door right next to the avoided area
            for nd, too_near in zip(nodes, near.tolist()):
                # the node's edges through the old pieces go; those through the new ones come
                v.adj[nd] = [e for e in v.adj[nd] if e[3][0] not in old_keys]
                i = g.passage[nd]
                if i in closed[k] or too_near:
                    continue
                got = self._entry(v, k, g.pos[nd], far=i < 0 or i in vset)
                if got is not None:
                    pc, q, d = got
                    pc.entries.append((nd, pc.add_point(q), d))
            for pc in new:
                self._join_piece(v, pc)
        v.build_s = time.process_time() - t0
        return v

    def _entry(self, g: _Graph, k: int, x, far: bool = False):
        """(piece, point in it, distance) where a node at x enters area k, or None."""
        from shapely.geometry import Point
        from shapely.ops import nearest_points

        best = None
        pt = Point(float(x[0]), float(x[1]))
        for pc in g.pieces_by_area.get(k, []):
            d = pc.poly.distance(pt)
            if best is None or d < best[0]:
                best = (d, pc)
        if best is None:
            return None
        d, pc = best
        if d > (np.inf if far else SNAP):
            return None
        if d <= 1e-7:
            return pc, np.array([pt.x, pt.y]), 0.0
        q = nearest_points(pc.poly, pt)[0]
        return pc, np.array([q.x, q.y]), float(d)

    # ------------------------------------------------------------------ queries
    def levels_known(self) -> List[str]:
        return list(self.level_list)

    def _check_level(self, level, what):
        if level in (None, ""):
            return None
        lev = str(level).strip()
        if lev in self.level_rank:
            return lev
        f = _as_float(lev)
        if f is not None:
            for s in self.level_list:
                if _as_float(s) == f:
                    return s
        raise InputError(f"{what}: level '{level}' is not in the map; its levels are {', '.join(self.level_list)}")

    def find_area(self, name: str, level=None) -> int:
        """Index of the area called ``name`` (case-insensitive; on ``level`` when several floors use it)."""
        lev = self._check_level(level, f"area '{name}'")
        key = str(name).strip().lower()
        ks = [k for k, a in enumerate(self.areas) if a.name.strip().lower() == key
              and (lev is None or self.levels[k] == lev)]
        if not ks:
            ks = [k for k, a in enumerate(self.areas) if str(a.id) == str(name).strip()]
        if not ks:
            close = sorted({a.name for a in self.areas if key and key[:3] in a.name.lower()})[:8]
            raise InputError(f"no area named '{name}'{f' on level {lev}' if lev else ''}"
                             f"{'; similar: ' + ', '.join(close) if close else ''}")
        if len(ks) > 1:
            raise InputError(f"{len(ks)} areas are named '{name}' (levels {', '.join(self.levels[k] for k in ks)}); "
                             "give the level too")
        return ks[0]

    def area_point(self, k: int, robot_radius: float = DEFAULT_ROBOT_RADIUS, avoid: Sequence[str] = (),
                   g: Optional[_Graph] = None) -> Tuple[float, float]:
        """A point well inside area k where the robot fits (the most interior point of its largest piece;
        with ``avoid``, of the piece that keeps the robot r from the avoided areas)."""
        from .model import polylabel

        if g is None:
            g = self._avoid_variant(self.graph(robot_radius), self._avoid_set(avoid))
        pcs = g.pieces_by_area.get(k, [])
        if not pcs:
            raise InputError(f"area '{self.areas[k].name}' (level {self.levels[k]}) has no room for a robot of "
                             f"radius {robot_radius:.2f} m")
        pc = max(pcs, key=lambda p: p.poly.area)
        pt = polylabel(pc.poly, tolerance=0.05)
        if not pc.poly.covers(pt):
            pt = pc.poly.representative_point()
        return float(pt.x), float(pt.y)

    def locate(self, xy, level=None, robot_radius: float = DEFAULT_ROBOT_RADIUS, what: str = "start",
               avoid: Sequence[str] = ()):
        """(piece, snapped point, snap distance) for a point; snaps up to SNAP metres, else InputError.
        With ``avoid``, in the pieces of the avoid set's graph (which keep r from the avoided areas)."""
        g = self._avoid_variant(self.graph(robot_radius), self._avoid_set(avoid)) if avoid else None
        return self._locate(xy, level, robot_radius, what, g)[:3]

    def _locate(self, xy, level=None, robot_radius: float = DEFAULT_ROBOT_RADIUS, what: str = "start",
                g: Optional[_Graph] = None):
        """:meth:`locate` plus whether the point lies strictly inside its piece (None: not known yet); on
        graph ``g`` (default: the radius's graph)."""
        from shapely.geometry import Point

        lev = self._check_level(level, what)
        if g is None:
            g = self.graph(robot_radius)
        x, y = float(xy[0]), float(xy[1])
        if not (math.isfinite(x) and math.isfinite(y)):
            raise InputError(f"{what}: the point ({xy[0]}, {xy[1]}) is not a valid coordinate")
        grid = g.grids.get(lev)
        if grid is None:
            grid = g.grids[lev] = _point_grid(g, lev)
        if grid is not None:  # the commonest case: well inside one piece, by a cell lookup
            x0, y0, h, lab, pcs = grid
            c, r = int((x - x0) / h), int((y - y0) / h)
            if 0 <= r < lab.shape[0] and 0 <= c < lab.shape[1] and lab[r, c] >= 0 and x >= x0 and y >= y0:
                return pcs[lab[r, c]], np.array([x, y]), 0.0, True
        pt = Point(x, y)
        # the common case first: the point lies in a piece of the robot's free space
        if g.piece_tree is None:
            import shapely

            g.piece_list = list(g.pieces.values())
            g.piece_tree = shapely.STRtree([pc.tol_poly for pc in g.piece_list])
        hits = [g.piece_list[int(i)] for i in g.piece_tree.query(pt, predicate="intersects")]
        hits = [pc for pc in hits if lev is None or pc.level == lev]
        if hits and (lev is not None or len({pc.level for pc in hits}) == 1):
            pc = hits[0] if len(hits) == 1 else min(hits, key=lambda p: self._area_size(p.area_index))
            return pc, np.array([x, y]), 0.0, None
        if self._tree is None:
            import shapely

            self._tree = shapely.STRtree([a.polygon for a in self.areas])
            for a in self.areas:
                shapely.prepare(a.polygon)
        near = [int(k) for k in self._tree.query(pt, predicate="dwithin", distance=SNAP)]
        cands = [k for k in near if lev is None or self.levels[k] == lev]
        inside = [k for k in cands if self.areas[k].polygon.covers(pt)]
        if lev is None and len({self.levels[k] for k in inside}) > 1:
            raise InputError(f"{what}: the point lies in areas on levels "
                             f"{', '.join(sorted({self.levels[k] for k in inside}))}; give its level")
        order = sorted(inside, key=lambda k: self.areas[k].polygon.area)
        for k in order:  # inside an area: its pieces first
            for pc in g.pieces_by_area.get(k, []):
                if pc.tol_poly.covers(pt):
                    return pc, np.array([x, y]), 0.0, None
        best = None
        for k in order + [k for k in cands if k not in inside]:
            if self.areas[k].polygon.distance(pt) > SNAP:
                continue
            for pc in g.pieces_by_area.get(k, []):
                d = pc.poly.distance(pt)
                if d <= SNAP and (best is None or d < best[0] - 1e-9):
                    best = (d, pc)
        if best is None:
            near = [k for k in range(len(self.areas)) if lev is None or self.levels[k] == lev]
            near = sorted(near, key=lambda k: self.areas[k].polygon.distance(pt))[:1]
            hint = ""
            if near:
                k = near[0]
                hint = (f"; the nearest area is '{self.areas[k].name}' (level {self.levels[k]}), "
                        f"{self.areas[k].polygon.distance(pt):.1f} m away")
            where = "inside an area but too close to its walls for" if inside else "outside every area reachable by"
            raise InputError(f"{what} ({x:.2f}, {y:.2f}){f' on level {lev}' if lev else ''} is {where} a robot of "
                             f"radius {robot_radius:.2f} m (more than {SNAP:.0f} m from the free space){hint}")
        from shapely.ops import nearest_points

        d, pc = best
        q = nearest_points(pc.poly, pt)[0]
        return pc, np.array([q.x, q.y]), float(d), False

    def _area_size(self, k: int) -> float:
        sizes = getattr(self, "_sizes", None)
        if sizes is None:
            sizes = self._sizes = [float(a.polygon.area) for a in self.areas]
        return sizes[k]

    def route(self, start, goal, start_level=None, goal_level=None, robot_radius: float = DEFAULT_ROBOT_RADIUS,
              avoid: Sequence[str] = (), vertical_cost: float = DEFAULT_VERTICAL_COST, progress=None) -> RouteResult:
        """Shortest route from ``start`` to ``goal``: each an (x, y) point in the map frame (with its level,
        needed when the point lies in areas of several levels) or an area name (str)."""
        quiet = progress is None  # a planner's query: no progress object, no messages to format
        progress = ensure(progress)
        if not (math.isfinite(float(vertical_cost)) and float(vertical_cost) >= 0):
            raise InputError(f"VERTICAL_COST must be a non-negative number of metres, got {vertical_cost}")
        vc = float(vertical_cost)
        avoid_set = self._avoid_set(avoid)
        base = self.graph(robot_radius, progress=None if quiet else progress.sub(0, 90))
        g = self._avoid_variant(base, avoid_set) if avoid_set else base
        ends = self._ends(g, start, goal, start_level, goal_level, robot_radius)
        if g is not base and any(self.types[e[0].area_index] in avoid_set for e in ends):
            # a start or goal inside an avoided area (sent into a stair well): it has to pass that area's
            # passage, so the passages into avoided areas stay open for this query (other avoided areas are
            # still not crossed)
            g = base
            ends = self._ends(g, start, goal, start_level, goal_level, robot_radius)
            opened = (f"the {'start' if self.types[ends[0][0].area_index] in avoid_set else 'goal'} lies in an "
                      f"avoided area ({', '.join(sorted(avoid_set))}): its passages are open for this route")
        else:
            opened = None
        if self._table(g, vc, avoid_set) is None:  # once per map, vertical cost (and avoid set)
            self._landmarks(g, vc)
        t0 = time.perf_counter()
        res = self._search(g, ends[0], ends[1], vc, avoid_set, robot_radius)
        res.query_ms = (time.perf_counter() - t0) * 1000.0
        if opened:
            res.warnings.append(opened)
        if not quiet:
            progress.step(100, f"route: {res.length:.2f} m, {res.level_changes} level changes, "
                               f"{len(res.areas)} areas, {len(res.passages)} passages ({res.query_ms:.2f} ms)")
        return res

    def _ends(self, g: _Graph, start, goal, start_level, goal_level, robot_radius: float):
        """Start and goal (points or area names) located on graph ``g``: :meth:`_locate` results."""
        ends = []
        for what, p, lev in (("start", start, start_level), ("goal", goal, goal_level)):
            if isinstance(p, str):
                k = self.find_area(p, lev)
                p = self.area_point(k, robot_radius, g=g)
                lev = self.levels[k]
            ends.append(self._locate(p, lev, robot_radius, what, g))
        return ends

    @staticmethod
    def _avoid_set(avoid) -> set:
        if not avoid:
            return set()
        out = set()
        for a in avoid or ():
            a = str(a).strip().lower()
            if not a or a == "none":
                continue
            a = {"stair": "stairs", "lift": "elevator", "lifts": "elevator", "elevators": "elevator"}.get(a, a)
            if a not in AVOIDABLE:
                raise InputError(f"AVOID: unknown area type '{a}'; use one of {', '.join(AVOIDABLE)}")
            out.add(a)
        return out

    # ------------------------------------------------------------------ A*
    def _search(self, g: _Graph, s_end, t_end, vc: float, avoid: set, robot_radius: float) -> RouteResult:
        """The route from the start point to the goal point over the passage nodes (see the module docstring).

        ``s_end``/``t_end``: :meth:`_locate` results (piece, point, snap distance, strictly inside or None).
        A start and goal that see each other are joined straight (nothing can be shorter). Otherwise both
        are joined to their piece's entry nodes; on maps of up to ``MAX_TABLE_NODES`` nodes the node-to-node
        distance table (once per map, vertical cost and avoid set) gives the best pair of entry nodes at
        once, and its predecessors the chain of nodes (A* with the exact cost-to-go as its heuristic
        would expand exactly that chain); on larger maps A* runs with the landmark bounds."""
        spc, sp, ssnap = s_end[:3]
        tpc, tp, tsnap = t_end[:3]
        s_int = s_end[3] if len(s_end) > 3 else None
        t_int = t_end[3] if len(t_end) > 3 else None
        csr = g.csr()
        inf = math.inf
        ub, came_t = inf, None  # best complete route so far: cost, (last node or None, detail)
        if spc is tpc:
            if s_int is None:
                s_int = spc._inside_xy(float(sp[0]), float(sp[1]))
            if s_int:
                direct = spc.visible_from(sp, tp[None, :], interior=True)[0]
            else:
                if t_int is None:
                    t_int = spc._inside_xy(float(tp[0]), float(tp[1]))
                direct = spc.visible_from(tp, sp[None, :], interior=t_int)[0]
            if direct:  # the straight segment: no route can be shorter
                return self._rebuild(g, csr, [], {}, {}, (None, None), spc, sp, None, tpc, tp, None, ssnap, tsnap,
                                     float(np.hypot(*(tp - sp))), 0)
            c, i, j = spc.pair_cost(sp, tp, s_int, t_int)
            if c < ub:
                ub, came_t = c, (None, (i, j))
        for pc in (spc, tpc) if spc is not tpc else (spc,):
            pc.queries += 1
            if pc.queries == VP_AFTER and pc._vp is None and pc.large():
                pc.build_visibility()  # a hall queried again and again: its corners' visibility polygons
        sd, svia = spc.entry_costs(sp, s_int)
        td, tvia = tpc.entry_costs(tp, t_int)
        # start -> entry nodes of its piece, entry nodes of the goal's piece -> goal: (node, cost, vertex)
        sc = sd[spc.e_vi] + spc.e_d
        ok = np.isfinite(sc)
        sn, sc, svi = spc.e_node[ok], sc[ok], spc.e_vi[ok]
        tc = td[tpc.e_vi] + tpc.e_d
        ok = np.isfinite(tc)
        tn, tc, tvi = tpc.e_node[ok], tc[ok], tpc.e_vi[ok]
        table = self._table(g, vc, avoid)
        if table is not None:
            nodes, came_e, s_vi = [], {}, {}
            if len(sn) and len(tn):
                dist, pred, edge = table
                M = sc[:, None] + dist[np.ix_(sn, tn)] + tc[None, :]
                i, j = divmod(int(M.argmin()), len(tn))
                if M[i, j] < ub - 1e-12:
                    ub = float(M[i, j])
                    s0, t0 = int(sn[i]), int(tn[j])
                    nodes = [t0]
                    while nodes[-1] != s0:
                        nodes.append(int(pred[s0, nodes[-1]]))
                    nodes.reverse()
                    for x, y in zip(nodes, nodes[1:]):
                        came_e[y] = edge[(x, y)]
                    if dist.dtype != np.float64:  # the cost in full precision: the chain's edges summed
                        ce = np.fromiter(came_e.values(), np.int64, len(came_e))
                        ub = float(sc[i] + tc[j] + csr["cost"][ce].sum() + vc * csr["span"][ce].sum())
                    s_vi = {s0: int(svi[i])}
                    came_t = (t0, int(tvi[j]))
            if came_t is None:
                raise self._no_route(g, spc, tpc, avoid, robot_radius)
            return self._rebuild(g, csr, nodes, came_e, s_vi, came_t, spc, sp, svia, tpc, tp, tvia, ssnap, tsnap,
                                 ub, len(nodes))
        s_edges = list(zip(sn.tolist(), sc.tolist(), svi.tolist()))
        t_in: Dict[int, Tuple[float, int]] = {}
        for n, c, vi in zip(tn.tolist(), tc.tolist(), tvi.tolist()):
            if n not in t_in or c < t_in[n][0]:
                t_in[n] = (c, vi)
        n_nodes = len(g.pos)
        h = self._heuristic(g, tp, self.level_rank[tpc.level], t_in, vc, avoid)
        # a first upper bound through the best landmark: prunes nodes that cannot beat it
        prune = ub
        dl = self._landmarks(g, vc)
        if len(dl) and s_edges and t_in and not avoid:  # (a route via a landmark may cross avoided areas)
            sn = np.array([e[0] for e in s_edges])
            sc = np.array([e[1] for e in s_edges])
            tn = np.fromiter(t_in.keys(), int)
            tc = np.array([t_in[m][0] for m in t_in])
            via = np.min(dl[:, sn] + sc[None, :], axis=1) + np.min(dl[:, tn] + tc[None, :], axis=1)
            prune = min(prune, float(np.min(via)) * (1 + 1e-9) + 1e-9)
        best = np.full(n_nodes, inf)
        came_n = np.full(n_nodes, -1, np.int64)  # -1: reached from the start point
        came_e = np.full(n_nodes, -1, np.int64)
        s_vi: Dict[int, int] = {}
        heap = []
        for (m, c, vi) in s_edges:
            if c < best[m] and c + h[m] < prune:
                best[m] = c
                s_vi[m] = vi
                heapq.heappush(heap, (c + h[m], c, m))
        indptr, nbr, cost, span, kcode = csr["indptr"], csr["nbr"], csr["cost"], csr["span"], csr["kcode"]
        amask = _avoid_mask(avoid)
        expanded = 0
        while heap:
            f, c, n = heapq.heappop(heap)
            if f >= ub - 1e-12:
                break  # nothing left can beat the route found
            if c > best[n]:
                continue
            expanded += 1
            te = t_in.get(n)
            if te is not None and c + te[0] < ub - 1e-12:
                ub, came_t = c + te[0], (n, te[1])
                prune = min(prune, ub)
            lo, hi = indptr[n], indptr[n + 1]
            if lo == hi:
                continue
            m = nbr[lo:hi]
            nc = c + cost[lo:hi]
            if vc:
                nc = nc + vc * span[lo:hi]
            fm = nc + h[m]
            ok = (nc < best[m] - 1e-12) & (fm < prune)
            if amask is not None:
                ok &= ~amask[kcode[lo:hi]]
            for j in np.nonzero(ok)[0].tolist():
                mm = int(m[j])
                best[mm] = nc[j]
                came_n[mm] = n
                came_e[mm] = lo + j
                heapq.heappush(heap, (float(fm[j]), float(nc[j]), mm))
        if came_t is None:
            raise self._no_route(g, spc, tpc, avoid, robot_radius)
        # the chain of nodes
        nodes = []
        n = came_t[0]
        while n is not None and n >= 0:
            nodes.append(n)
            n = int(came_n[n]) if came_n[n] >= 0 else None
        nodes.reverse()
        return self._rebuild(g, csr, nodes, came_e, s_vi, came_t, spc, sp, svia, tpc, tp, tvia, ssnap, tsnap,
                             ub, expanded)

    def _matrix(self, g: _Graph, vc: float, avoid: set):
        """The node graph as a sparse matrix: planar cost + vc x levels crossed, avoided area types left
        out, the cheapest of parallel edges."""
        csr = g.csr()
        n = len(g.pos)
        w = csr["cost"] + vc * csr["span"] + 1e-12
        rows = np.repeat(np.arange(n), np.diff(csr["indptr"]))
        keep = np.ones(len(w), bool)
        amask = _avoid_mask(avoid)
        if amask is not None:
            keep = ~amask[csr["kcode"]]
        return _min_matrix(rows[keep], csr["nbr"][keep], w[keep], n)

    def _table(self, g: _Graph, vc: float, avoid: set):
        """(dist, pred, edge): shortest costs and predecessors between all pairs of nodes, and the cheapest
        usable edge between two neighbours, for this vertical cost
        and avoid set (once; the last ``MAX_TABLES`` kept), or None on maps of more than
        ``MAX_TABLE_NODES`` nodes (A* with landmarks then)."""
        last = g.last_table
        if last is not None and last[0] == vc and last[1] == avoid:
            return last[2]  # the previous query's vertical cost and avoid set
        n = len(g.pos)
        if n == 0 or n > MAX_TABLE_NODES:
            return None
        key = (round(vc, 6), tuple(sorted(avoid)))
        got = g.tables.get(key)
        if got is None:
            from scipy.sparse.csgraph import shortest_path

            dist, pred = shortest_path(self._matrix(g, vc, avoid), method="D", directed=True,
                                       return_predecessors=True)
            # the cheapest usable edge between two nodes, for rebuilding the chain: (a, b) -> edge index
            csr = g.csr()
            w = csr["cost"] + vc * csr["span"]
            amask = _avoid_mask(avoid)
            if amask is not None:
                w = np.where(amask[csr["kcode"]], np.inf, w)
            rows = np.repeat(np.arange(len(g.pos)), np.diff(csr["indptr"]))
            order = np.lexsort((w, csr["nbr"], rows))
            first = np.ones(len(order), bool)
            first[1:] = (rows[order][1:] != rows[order][:-1]) | (csr["nbr"][order][1:] != csr["nbr"][order][:-1])
            sel = order[first & np.isfinite(w[order])]
            edge = dict(zip(zip(rows[sel].tolist(), csr["nbr"][sel].tolist()), sel.tolist()))
            if COMPACT_TABLES:
                dist = dist.astype(np.float32)  # read a few rows per query; summed with float64 costs
            got = (dist, _compact_index(pred), edge)
            while len(g.tables) >= MAX_TABLES:
                g.tables.pop(next(iter(g.tables)))
            g.tables[key] = got
        g.last_table = (vc, set(avoid), got)
        return got

    def _landmarks(self, g: _Graph, vc: float) -> np.ndarray:
        """Shortest distances from a few landmark nodes to every node (ALT heuristic), cached per vertical
        cost. (K, n) array, inf where unreachable. Computed on the whole graph, avoided areas included: the
        bounds stay admissible for every ``avoid`` (removing edges only lengthens routes), and joining the
        goal point to its area's nodes cannot shorten a route between two nodes (in-area paths obey the
        triangle inequality), so the goal's landmark distances follow from its entry nodes."""
        key = round(vc, 6)
        got = g.alt.get(key)
        if got is not None:
            return got
        from scipy.sparse.csgraph import dijkstra

        n = len(g.pos)
        if n == 0:
            g.alt[key] = np.zeros((0, 0))
            return g.alt[key]
        mat = self._matrix(g, vc, set())
        k = min(LANDMARKS, n)
        chosen = [0]
        dist = [dijkstra(mat, directed=True, indices=0)]
        near = np.where(np.isfinite(dist[0]), dist[0], 1e18)
        for _ in range(k - 1):
            nxt = int(np.argmax(near))
            if near[nxt] <= 0:
                break
            chosen.append(nxt)
            d = dijkstra(mat, directed=True, indices=nxt)
            dist.append(d)
            near = np.minimum(near, np.where(np.isfinite(d), d, 1e18))
        d = np.vstack(dist)
        d[~np.isfinite(d)] = _FAR
        g.alt[key] = d
        return g.alt[key]

    def _heuristic(self, g: _Graph, tp, grank: int, t_in, vc: float, avoid: set) -> List[float]:
        """Admissible lower bound of the remaining cost per node: the larger of the planar straight
        line + vc x levels to cross, and the landmark (ALT) triangle bounds."""
        n = len(g.pos)
        if n == 0:
            return []
        P = g.pos_array()
        h = np.hypot(P[:, 0] - tp[0], P[:, 1] - tp[1]) + vc * np.abs(g.rank_array() - grank)
        dl = self._landmarks(g, vc)  # unreachable = _FAR (finite: FAR - FAR = 0, no NaN)
        if len(dl) and t_in:
            tn = np.fromiter(t_in.keys(), int)
            tc = np.array([t_in[m][0] for m in t_in])
            dlt = np.min(dl[:, tn] + tc[None, :], axis=1)
            h = np.maximum(h, np.abs(dlt[:, None] - dl).max(axis=0))
            h[h >= 0.5 * _FAR] = math.inf
        elif not t_in:
            h = np.full(n, math.inf)
        return h

    def _rebuild(self, g, csr, nodes, came_e, s_vi, came_t, spc, sp, svia, tpc, tp, tvia, ssnap, tsnap, cost,
                 expanded):
        chunks: List[np.ndarray] = []  # the polyline in pieces, each on one level
        clev: List[str] = []
        area_seq: List[int] = []
        pass_seq: List[int] = []
        gpos = g.pos_array()

        def add_area(k):
            if not area_seq or area_seq[-1] != k:
                area_seq.append(k)

        def add_passage(node):
            i = g.passage[node]
            if i >= 0 and (not pass_seq or pass_seq[-1] != i):
                pass_seq.append(i)

        cpc: List[Optional[_Piece]] = []  # the piece of every chunk (None: a point)
        cross: List[Tuple[int, int]] = []  # (chunk, node) of the passage crossings on the route
        ct: List[list] = []  # the chunks as lists of (x, y, vertex in the piece or -1), for _pull_crossings

        def piece_path(pc, a, b):
            key = (a, b)
            xy = pc.paths.get(key)
            if xy is None:  # polylines inside a piece, kept once rebuilt (the same doors recur)
                xy = pc.path_between(a, b)
            chunks.append(xy)
            ct.append(pc.tpaths[key])
            clev.append(pc.level)
            cpc.append(pc)

        def node(n):
            if n in g.span:
                cross.append((len(chunks), n))
            chunks.append(gpos[n:n + 1])
            ct.append([g.pos[n] + (-1,)])
            clev.append(g.level[n])
            cpc.append(None)

        chunks.append(np.asarray(sp, float).reshape(1, 2))
        ct.append([(float(sp[0]), float(sp[1]), -1)])
        clev.append(spc.level)
        cpc.append(None)
        add_area(spc.area_index)
        if not nodes:  # start and goal in one piece
            if came_t[1] is not None:
                piece_path(spc, *came_t[1])
        else:
            vi = s_vi[nodes[0]]
            piece_path(spc, int(svia[vi]), vi)
            node(nodes[0])
            add_passage(nodes[0])
            eid = csr["eid"]
            for n in nodes[1:]:
                data = g.edata[int(eid[came_e[n]])]
                if data[0] != "V":
                    key, vx, vy = data
                    pc = g.pieces[key]
                    add_area(pc.area_index)
                    piece_path(pc, vx, vy)
                node(n)
                add_passage(n)
            add_area(tpc.area_index)
            vi = came_t[1]
            piece_path(tpc, vi, int(tvia[vi]))
        chunks.append(np.asarray(tp, float).reshape(1, 2))
        ct.append([(float(tp[0]), float(tp[1]), -1)])
        clev.append(tpc.level)
        cpc.append(None)
        graph_cost = cost
        if cross and PULL_CROSSINGS:
            saved, changed = _pull_crossings(ct, cpc, cross, g.span)
            for c in changed:
                chunks[c] = np.array([p[:2] for p in ct[c]], float).reshape(-1, 2)
            cost -= saved
        P = np.concatenate(chunks)
        d = np.diff(P, axis=0)
        keep = np.ones(len(P), bool)  # drop repeated points (a level change repeats the position)
        keep[1:] = (np.abs(d) >= 1e-9).any(axis=1)
        one_level = clev.count(clev[0]) == len(clev)
        if one_level:
            P = P[keep]
            if len(P) == 1:
                P = np.vstack([P, P])
            lvls = [clev[0]] * len(P)
            z = np.full(len(P), self._elevation(clev[0]))
            changes = 0
        else:
            lv = np.repeat(np.arange(len(chunks)), [len(c) for c in chunks])
            lcode = np.array([self.level_rank[x] for x in clev])[lv]
            keep[1:] |= lcode[1:] != lcode[:-1]
            P, lv = P[keep], lv[keep]
            if len(P) == 1:
                P, lv = np.vstack([P, P]), np.concatenate([lv, lv])
            lvls = [clev[i] for i in lv.tolist()]
            changes = sum(1 for a, b in zip(lvls, lvls[1:]) if a != b)
            elev = {x: self._elevation(x) for x in set(clev)}
            z = np.array([elev[x] for x in lvls])
        length = float(np.hypot(*np.diff(P, axis=0).T).sum())
        return RouteResult(points=P, levels=lvls, z=z, length=length, cost=float(cost), level_changes=changes,
                           areas=[self.areas[k].name for k in area_seq], area_ids=[self.areas[k].id for k in area_seq],
                           passages=[self._passage_name(i) for i in pass_seq],
                           passage_ids=[self.passages[i].id for i in pass_seq],
                           start=(float(sp[0]), float(sp[1])), goal=(float(tp[0]), float(tp[1])),
                           start_snap=ssnap, goal_snap=tsnap, query_ms=0.0, expanded=expanded,
                           warnings=[f"start moved {ssnap:.2f} m into the free space"] * (ssnap > 0.005)
                           + [f"goal moved {tsnap:.2f} m into the free space"] * (tsnap > 0.005),
                           graph_cost=float(graph_cost))

    def _passage_name(self, i: int) -> str:
        p = self.passages[i]
        return p.name or str(p.id)

    def _elevation(self, level: str) -> float:
        """z of a level: level number x that level's height (rank x height for non-numeric levels)."""
        cache = self.__dict__.setdefault("_elev", {})
        if level not in cache:
            hs = [h for k, h in enumerate(self.heights) if self.levels[k] == level]
            h = float(np.median(hs)) if hs else DEFAULT_HEIGHT
            f = _as_float(level)
            cache[level] = (f if f is not None else float(self.level_rank.get(level, 0))) * h
        return cache[level]

    def elevation(self, level: str) -> float:
        return self._elevation(level)

    # ------------------------------------------------------------------ diagnostics
    def components(self, robot_radius: float = DEFAULT_ROBOT_RADIUS, avoid: Sequence[str] = ()) -> List[List[int]]:
        """Connected parts of the map for this robot: lists of area indices (largest first)."""
        avoid = self._avoid_set(avoid)
        g = self._avoid_variant(self.graph(robot_radius), avoid)
        return [sorted(c) for c in self._area_components(g, avoid)[0]]

    def _area_components(self, g: _Graph, avoid: set):
        parent = list(range(len(self.areas)))

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        def union(a, b):
            ra, rb = find(a), find(b)
            if ra != rb:
                parent[ra] = rb

        node_area: Dict[int, List[int]] = {}
        for pc in g.pieces.values():
            if self.types[pc.area_index] in avoid:
                continue
            for (n, vi, d) in pc.entries:
                node_area.setdefault(n, []).append(pc.area_index)
        for n, ks in node_area.items():
            for k in ks[1:]:
                union(ks[0], k)
        for n, lst in enumerate(g.adj):
            for (m, c, kind, data, span) in lst:
                if span and kind not in avoid and n in node_area and m in node_area:
                    union(node_area[n][0], node_area[m][0])
        comps: Dict[int, List[int]] = {}
        for k in range(len(self.areas)):
            comps.setdefault(find(k), []).append(k)
        out = sorted(comps.values(), key=len, reverse=True)
        of = {}
        for ci, c in enumerate(out):
            for k in c:
                of[k] = ci
        return out, of

    def _no_route(self, g: _Graph, spc, tpc, avoid: set, robot_radius: float) -> RouteError:
        comps, of = self._area_components(g, avoid)
        a, b = spc.area_index, tpc.area_index
        ca, cb = of[a], of[b]

        def desc(ci, k):
            ks = comps[ci]
            names = [self.areas[j].name for j in ks[:6]]
            lv = sorted({self.levels[j] for j in ks})
            return (f"part #{ci + 1} ({len(ks)} area{'s' if len(ks) != 1 else ''} on level{'s' if len(lv) > 1 else ''} "
                    f"{', '.join(lv)}: {', '.join(names)}{' ...' if len(ks) > 6 else ''})")

        if ca == cb:
            # same part of the graph, different piece of one area: the area itself is cut by the radius
            msg = (f"no route from '{self.areas[a].name}' to '{self.areas[b].name}' for a robot of radius "
                   f"{robot_radius:.2f} m: a narrowing inside an area is too tight for it")
            if g.avoid and any(len(pc.key) > 2 for pc in (spc, tpc)):
                msg += (f" (avoiding {', '.join(g.avoid)}, the robot keeps {robot_radius:.2f} m from those areas "
                        "and their openings: that closes the way)")
        else:
            msg = (f"no route for a robot of radius {robot_radius:.2f} m"
                   f"{' avoiding ' + ', '.join(sorted(avoid)) if avoid else ''}: the start (area "
                   f"'{self.areas[a].name}', level {self.levels[a]}) is in {desc(ca, a)}, the goal (area "
                   f"'{self.areas[b].name}', level {self.levels[b]}) in {desc(cb, b)}; the map has "
                   f"{len(comps)} separate parts for this robot")
        between = []
        for i, reason in (g.closed if ca != cb else []):
            if i < 0:
                continue
            p = self.passages[i]
            x, y = self.index[p.from_id], self.index[p.to_id]
            if {of[x], of[y]} == {ca, cb}:
                between.append(f"'{self._passage_name(i)}' ({reason})")
        if between:
            msg += "; closed for this robot between them: " + ", ".join(between[:6])
        elif any(g.passage[n] >= 0 for n in range(len(g.pos))) and avoid:
            msg += f"; try without AVOID={','.join(sorted(avoid))}"
        return RouteError(msg, {"start": [self.areas[k].name for k in comps[ca]],
                                "goal": [self.areas[k].name for k in comps[cb]], "count": len(comps)})

    def summary(self, robot_radius: float = DEFAULT_ROBOT_RADIUS) -> Dict[str, object]:
        g = self.graph(robot_radius)
        return {"areas": len(self.areas), "passages": len(self.passages), "levels": list(self.level_list),
                "vertical_passages": len(self.vertical), "implicit_links": len(self.implicit),
                "nodes": len(g.pos), "edges": sum(len(a) for a in g.adj) // 2, "pieces": len(g.pieces),
                "closed": len(g.closed), "build_s": g.build_s, "warnings": list(self.warnings)}


# =========================================================================== reader helpers
def _lonlat_centre(areas):
    xs, ys = [], []
    for a in areas:
        b = a.polygon.bounds
        xs += [b[0], b[2]]
        ys += [b[1], b[3]]
    return (0.5 * (min(xs) + max(xs)), 0.5 * (min(ys) + max(ys)))


def _resolve_by_level(areas, passages, warnings):
    """Re-resolve passage ends given by name when the name is used on several levels (maps that repeat
    'E1-ST-09' on each floor): the area on the passage's level, else the nearest to the passage."""
    by_name: Dict[str, List[Area]] = {}
    for a in areas:
        if a.name:
            by_name.setdefault(a.name, []).append(a)
    fixed = 0
    out = []
    for p in passages:
        lev = _level_of(p.tags, "")
        ends = []
        for key, cur in (("osmAG:from", p.from_id), ("osmAG:to", p.to_id)):
            v = str((p.tags or {}).get(key, "")).strip()
            cands = by_name.get(v, [])
            if len(cands) <= 1:
                ends.append(cur)
                continue
            same = [a for a in cands if _level_of(a.tags, "") == lev] or cands
            best = min(same, key=lambda a: a.polygon.distance(p.line))
            ends.append(best.id)
        if ends[0] == ends[1]:  # both ends named alike: a vertical link between same-named shafts
            v = str((p.tags or {}).get("osmAG:to", "")).strip()
            others = [a for a in by_name.get(v, []) if a.id != ends[0]]
            if others:
                ends[1] = min(others, key=lambda a: a.polygon.distance(p.line)).id
        if (ends[0], ends[1]) != (p.from_id, p.to_id):
            fixed += 1
            import copy

            p = copy.copy(p)
            p.from_id, p.to_id = ends
        out.append(p)
    if fixed:
        warnings.append(f"{fixed} passages name areas that several levels share; joined to the area on the "
                        "passage's own level")
    return out


__all__ = ["RouteMap", "RouteResult", "RouteError", "infer_area_type", "DEFAULT_ROBOT_RADIUS",
           "DEFAULT_VERTICAL_COST", "SNAP", "AVOIDABLE"]
