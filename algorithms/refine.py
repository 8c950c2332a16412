"""Refinement of a segmented area partition (pipeline stage 4).

Input: an :class:`AreaGraph` whose area polygons tile free space (touching areas share their common
border; along it one side may lack collinear vertices the other has), and passages that are 2-point
segments on the shared border of the two areas they join.

Steps
1. **Merge small areas**: every area below ``min_area`` (m², types in ``keep_types`` such as stairs and
   elevators are exempt) is merged into the neighbour it shares the longest border with, smallest
   first, repeatedly (a stair or a lift only when it touches no other area, ``SHAFTS_LAST``: a stretch of
   corridor merged into a stair would make the stair its way through); an isolated small area (no shared
   border) is dropped. Passages of a merged area
   are re-pointed; passages that become internal, or lead to a dropped area, are removed.
2. **Node the partition into arcs**: every ring vertex that lies on another ring's edge is inserted
   there, then the rings are cut into arcs at every vertex where the set of adjacent faces changes
   (3+ faces meet, or a shared border meets a wall) and at every passage endpoint (locked).
3. **Simplify each arc once** with its end points fixed (Douglas–Peucker, ε = ``epsilon_px`` ·
   ``resolution``; on a border between two areas ε times the segmentation's ``topology_scale``, the raster
   cells per side of the cells that decided the border, ``segmentation.topology_scale``) and **remove
   spikes** iteratively (interior vertices whose angle is below ``spike_angle`` degrees and whose protrusion from the chord of its neighbours is below
   ``spike_length`` metres; arc end points, hence passage endpoints and junctions, are never removed).
4. **Rebuild** every polygon from its arcs, so adjacent areas keep the very same vertices along their
   border (no slivers, no gaps) and every passage endpoint is a vertex of both areas it joins.
   Polygons that became invalid (or overlap a neighbour) get their arcs simplified again with ε/2,
   then not at all.
5. **Measure** the vertex reduction and the maximum deviation (Hausdorff distance, densified) of the
   result from the unsimplified arcs, after Douglas–Peucker alone and after spike removal.
"""
from __future__ import annotations

import copy
import math
import time
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .errors import InputError
from .model import Area, AreaGraph, Passage
from .progress import ensure

EPSILON_PX = 1.2
SPIKE_ANGLE_DEG = 15.0
SPIKE_LENGTH_M = 0.3
MIN_AREA_M2 = 10.0
KEEP_TYPES = ("stairs", "elevator")
SHAFT_TYPES = ("stairs", "elevator")  # a small area joins a stair or a lift only when it touches nothing else ...
SHAFTS_LAST = True  # ... (a corridor's stretch merged into a stair made the stair the corridor's only way through:
# SIST-F4.dwg level 4, 2 x 2 cells: the 10 m2 stretch between the lift lobby and the E2 wing's corridor joined
# stair E2-ST-01, its longest border, and the wing had no stair-free way to the lifts)


# =========================================================================== validation helpers
def _single_polygon(area: Area, progress):
    import shapely
    from shapely.geometry import MultiPolygon, Polygon

    g = area.polygon
    if g is None or g.is_empty:
        raise InputError(f"area {area.id} has an empty polygon; remove it or re-run segmentation")
    if isinstance(g, MultiPolygon):
        parts = sorted(g.geoms, key=lambda p: p.area, reverse=True)
        progress.warning(f"area {area.id} is a MultiPolygon of {len(parts)} parts; kept the largest "
                         f"({parts[0].area:.2f} m²), dropped {sum(p.area for p in parts[1:]):.2f} m²")
        g = parts[0]
    if not isinstance(g, Polygon):
        raise InputError(f"area {area.id} is a {g.geom_type}, not a polygon")
    if not g.is_valid:
        reason = shapely.is_valid_reason(g)
        if not reason.startswith("Ring Self-intersection"):
            raise InputError(f"area {area.id} has an invalid polygon: {reason}; fix the geometry "
                             "(e.g. with QGIS 'Fix geometries') and run again")
        # a ring touching itself at a vertex (pixel outlines pinch a hole against the shell there):
        # restructure the rings with the same vertices, so shared borders are unaffected
        fixed = shapely.make_valid(g)
        polys = [p for p in getattr(fixed, "geoms", [fixed]) if isinstance(p, Polygon) and p.area > 0]
        if not polys:
            raise InputError(f"area {area.id} has an invalid polygon: {reason}; fix the geometry and run again")
        g = max(polys, key=lambda p: p.area)
        if len(polys) > 1:
            progress.warning(f"area {area.id} touches itself ({reason}); kept its largest part "
                             f"({g.area:.2f} m²), dropped {sum(p.area for p in polys) - g.area:.2f} m²")
    if g.area <= 0:
        raise InputError(f"area {area.id} has zero area (degenerate polygon)")
    return g


def validate_graph(areas: Sequence[Area], passages: Sequence[Passage]) -> None:
    """Raise InputError naming every passage whose areas are missing and duplicate area ids."""
    ids = [a.id for a in areas]
    seen, dup = set(), set()
    for i in ids:
        (dup if i in seen else seen).add(i)
    if dup:
        raise InputError(f"duplicate area ids {sorted(dup)}; every area needs a unique id")
    bad = [f"{p.id} ({p.from_id}->{p.to_id})" for p in passages if p.from_id not in seen or p.to_id not in seen]
    if bad:
        raise InputError(f"passages reference missing areas: {', '.join(bad)}; "
                         "delete these passages or add the areas they connect")


def _overlapping_pairs(arr, valid, resolution: float):
    """Index pairs (i, j, overlap m²) of valid polygons whose interiors overlap by more than a sliver
    (including duplicates and polygons lying inside others)."""
    import shapely

    # GEOS predicates on an invalid polygon raise TopologyException (side location conflict):
    # only valid polygons are compared; invalid ones are offenders of their own
    idx = np.flatnonzero(valid)
    if len(idx) < 2:
        return []
    sub = arr[idx]
    tree = shapely.STRtree(sub)
    o1, o2 = tree.query(sub, predicate="overlaps")
    c1, c2 = tree.query(sub, predicate="contains")  # also catches duplicates and areas inside areas
    i1 = idx[np.concatenate([o1, np.minimum(c1, c2)]).astype(np.int64)]
    i2 = idx[np.concatenate([o2, np.maximum(c1, c2)]).astype(np.int64)]
    keep = i1 < i2
    pairs = sorted(set(zip(i1[keep].tolist(), i2[keep].tolist())))
    if not pairs:
        return []
    a = shapely.area(shapely.intersection(arr[[x for x, _ in pairs]], arr[[y for _, y in pairs]]))
    return [(x, y, float(v)) for (x, y), v in zip(pairs, a.tolist()) if v > (resolution ** 2) * 0.01]


# =========================================================================== 1. small areas
def merge_small_areas(areas: List[Area], passages: List[Passage], min_area: float,
                      keep_types=KEEP_TYPES, progress=None):
    """Merge areas below ``min_area`` into the neighbour sharing the longest border (with ``SHAFTS_LAST``
    into a stair or a lift, ``SHAFT_TYPES``, only when no other area shares a border with it).

    Returns (areas, passages, info) with ``info`` = {"merged": n, "dropped": n, "dropped_ids": [...],
    "merged_into": {small_id: target_id}, "passages_removed": n}.
    """
    import shapely

    progress = ensure(progress)
    areas = [copy.copy(a) for a in areas]
    by_id = {a.id: a for a in areas}
    merged_into: Dict[int, int] = {}
    dropped: List[int] = []
    # areas and bounding boxes are kept per area (only the merge target's change): the loop of
    # ``polygon.area`` over every area and the intersects test against every area, per merge, were ~2/3 of
    # this stage on a 700-area sheet. The order of ``areas`` (ties of the longest border) is unchanged.
    size = np.array([a.polygon.area for a in areas], dtype=float)
    box = np.array([a.polygon.bounds for a in areas], dtype=float).reshape(-1, 4)
    exempt = np.array([a.type in keep_types for a in areas], dtype=bool)
    ids = np.array([a.id for a in areas], dtype=np.int64)
    while True:
        if min_area <= 0:
            break
        cand = np.flatnonzero((size < min_area) & ~exempt)
        if not len(cand):
            break
        si = int(cand[np.lexsort((ids[cand], size[cand]))[0]])  # min by (area, id)
        s = areas[si]
        best = None
        b = box[si]
        near = np.flatnonzero((box[:, 0] <= b[2]) & (box[:, 2] >= b[0]) & (box[:, 1] <= b[3]) & (box[:, 3] >= b[1]))
        near = near[near != si]  # in list order: the first longest border wins, as before
        if len(near):
            polys = np.array([areas[i].polygon for i in near.tolist()], dtype=object)
            shapely.prepare(polys)  # the neighbours are often large (a hall, the outdoor space): prepared once
            touching = np.flatnonzero(shapely.intersects(polys, s.polygon))
            if len(touching):
                lens = shapely.length(shapely.intersection(s.polygon.boundary,
                                                           shapely.boundary(polys[touching])))
                if SHAFTS_LAST:
                    shaft = np.array([areas[int(near[i])].type in SHAFT_TYPES for i in touching.tolist()], bool)
                    if (~shaft & (lens > 1e-9)).any():
                        lens = np.where(shaft, 0.0, lens)
                k = int(np.argmax(lens))
                if lens[k] > 1e-9:
                    best = areas[int(near[touching[k]])]
        del areas[si]
        size, box, exempt, ids = (np.delete(x, si, axis=0) for x in (size, box, exempt, ids))
        del by_id[s.id]
        if best is None:
            dropped.append(s.id)
            progress.info(f"area {s.id} ({s.polygon.area:.2f} m²) is below {min_area} m² and touches no other "
                          "area: dropped")
            continue
        u = shapely.union(best.polygon, s.polygon)
        if u.geom_type != "Polygon":
            parts = sorted(getattr(u, "geoms", [u]), key=lambda p: p.area, reverse=True)
            u = parts[0]
        best.polygon = u
        bi = next(i for i, x in enumerate(areas) if x is best)
        size[bi], box[bi] = u.area, u.bounds
        best.max_clearance = max(best.max_clearance, s.max_clearance)
        if not best.name and s.name:
            best.name = s.name
        merged_into[s.id] = best.id
    # re-point passages
    def final(i):
        while i in merged_into:
            i = merged_into[i]
        return i

    out_p, removed = [], 0
    for p in passages:
        f, t = final(p.from_id), final(p.to_id)
        if f == t or f not in by_id or t not in by_id:
            removed += 1
            continue
        if (f, t) != (p.from_id, p.to_id):
            p = copy.copy(p)
            p.from_id, p.to_id = f, t
        out_p.append(p)
    info = {"merged": len(merged_into), "dropped": len(dropped), "dropped_ids": dropped,
            "merged_into": {k: final(k) for k in merged_into}, "passages_removed": removed}
    return areas, out_p, info


# =========================================================================== 2. noding
def _signed_area(xy: np.ndarray) -> float:
    """``shapely.algorithms.cga.signed_area`` of a closed ring's (n, 2) coordinates (the same sums)."""
    xs, ys = np.vstack([xy, xy[1]]).T
    return np.sum(xs[1:-1] * (ys[2:] - ys[:-2])) / 2.0


def _oriented_rings(poly) -> List[np.ndarray]:
    """The closed rings of ``poly`` as (n, 2) arrays, exterior counter-clockwise and holes clockwise: the
    coordinates of ``shapely.geometry.polygon.orient(poly, 1.0)`` without building a new polygon from
    Python lists (that was ~0.3 s of refinement on a 700-area floor)."""
    import shapely

    out = []
    for k, ring in enumerate([poly.exterior] + list(poly.interiors)):
        xy = shapely.get_coordinates(ring)
        a = _signed_area(xy)
        if (a < 0.0) if k == 0 else (a > 0.0):
            xy = xy[::-1]
        out.append(np.ascontiguousarray(xy, dtype=float))
    return out


class _Partition:
    """Rings of all areas as vertex-id cycles on a shared vertex table."""

    def __init__(self, polygons: Sequence, extra_points: np.ndarray, q: float):
        self.q = q
        ring_xy, ring_face, ring_hole = [], [], []
        for fi, poly in enumerate(polygons):
            # exterior CCW, holes CW: the face is left of every edge
            for k, xy in enumerate(_oriented_rings(poly)):
                ring_xy.append(xy[:-1])
                ring_face.append(fi)
                ring_hole.append(k > 0)
        self.ring_face = np.asarray(ring_face, dtype=np.int64)
        self.ring_hole = np.asarray(ring_hole, dtype=bool)
        allxy = np.concatenate(ring_xy + [extra_points.reshape(-1, 2)]) if ring_xy else extra_points
        kq = np.round(allxy / q).astype(np.int64)
        kmin = kq.min(axis=0)
        kq -= kmin
        span = int(kq[:, 1].max()) + 1
        key = kq[:, 0] * span + kq[:, 1]
        uniq, first, inv = np.unique(key, return_index=True, return_inverse=True)
        self.V = allxy[first].copy()  # vertex coordinates (first occurrence, not quantized)
        self.rings: List[np.ndarray] = []
        pos = 0
        for xy in ring_xy:
            ids = inv[pos:pos + len(xy)]
            pos += len(xy)
            # drop consecutive duplicates (cyclic)
            keep = ids != np.roll(ids, 1)
            if not keep.any():
                keep[0] = True
            self.rings.append(ids[keep])
        self.extra_ids = inv[pos:]

    def node(self) -> int:
        """Insert every vertex that lies inside another ring edge into that edge. Returns #inserts."""
        import shapely

        V, q = self.V, self.q
        lens = [len(r) for r in self.rings]
        a = np.concatenate(self.rings)
        b = np.concatenate([np.roll(r, -1) for r in self.rings])
        ring_of = np.repeat(np.arange(len(self.rings)), lens)
        idx_in_ring = np.concatenate([np.arange(n) for n in lens])
        segs = np.stack([V[a], V[b]], axis=1)
        lines = shapely.linestrings(segs)
        tree = shapely.STRtree(lines)
        pts = shapely.points(V)
        pi, ei = tree.query(pts, predicate="dwithin", distance=q)
        m = (pi != a[ei]) & (pi != b[ei])
        pi, ei = pi[m], ei[m]
        if len(pi) == 0:
            return 0
        d = segs[ei, 1] - segs[ei, 0]
        t = ((V[pi] - segs[ei, 0]) * d).sum(axis=1) / np.maximum((d * d).sum(axis=1), 1e-300)
        inserts: Dict[int, List[Tuple[int, float, int]]] = {}
        for p, e, tt in zip(pi.tolist(), ei.tolist(), t.tolist()):
            if 0.0 < tt < 1.0:
                inserts.setdefault(int(ring_of[e]), []).append((int(idx_in_ring[e]), tt, p))
        n = 0
        for r, lst in inserts.items():
            lst.sort()
            ring = self.rings[r]
            positions = np.array([i + 1 for i, _, _ in lst])
            values = np.array([p for _, _, p in lst])
            self.rings[r] = np.insert(ring, positions, values)
            n += len(lst)
        return n


def _edge_tables(part: _Partition):
    """Undirected edges with their left/right faces. Raises InputError on overlapping areas."""
    nv = len(part.V)
    lens = np.array([len(r) for r in part.rings])
    a = np.concatenate(part.rings)
    b = np.concatenate([np.roll(r, -1) for r in part.rings])
    face = np.repeat(part.ring_face, lens)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    ukey, einv = np.unique(lo * nv + hi, return_inverse=True)
    ne = len(ukey)
    fwd = a < b
    left = np.full(ne, -1, np.int64)
    right = np.full(ne, -1, np.int64)
    cnt_l = np.bincount(einv[fwd], minlength=ne)
    cnt_r = np.bincount(einv[~fwd], minlength=ne)
    left[einv[fwd]] = face[fwd]
    right[einv[~fwd]] = face[~fwd]
    bad = np.flatnonzero((cnt_l > 1) | (cnt_r > 1))
    eu, ev = ukey // nv, ukey % nv
    return einv, lens, left, right, eu, ev, bad


# =========================================================================== 3. simplification
def _lines(xys: List[np.ndarray]):
    """Array of shapely LineStrings from a ragged list of (n_i, 2) arrays (n_i >= 2)."""
    import shapely

    if not xys:
        return np.array([], dtype=object)
    lens = np.array([len(c) for c in xys])
    return shapely.linestrings(np.concatenate(xys), indices=np.repeat(np.arange(len(xys)), lens))


def _chord_bound(xy: np.ndarray, simple: np.ndarray) -> float:
    """An upper bound of the Hausdorff distance between the arc ``xy`` and ``simple``, a subsequence of
    its vertices with the same ends (Douglas-Peucker and spike removal only drop vertices): the farthest
    vertex from the chord of the kept vertices around it. Every point of the arc is that close to its chord
    (distance to a segment is convex along each edge), and every point of a chord is that close to the arc
    (the arc crosses the chord's normal there). inf when ``simple`` is not such a subsequence."""
    if len(simple) < 2 or len(xy) < 2:
        return math.inf
    kept = set(map(tuple, simple.tolist()))
    idx = np.array([k for k, p in enumerate(xy.tolist()) if tuple(p) in kept], dtype=np.int64)
    if len(idx) != len(simple) or idx[0] != 0 or idx[-1] != len(xy) - 1 or not np.array_equal(xy[idx], simple):
        return math.inf
    seg = np.clip(np.searchsorted(idx, np.arange(len(xy)), side="right") - 1, 0, len(idx) - 2)
    a, b = xy[idx[seg]], xy[idx[seg + 1]]
    d = b - a
    dd = (d * d).sum(axis=1)
    t = np.clip(((xy - a) * d).sum(axis=1) / np.where(dd > 0, dd, 1.0), 0.0, 1.0)
    dev = float(np.hypot(*(xy - (a + t[:, None] * d)).T).max())
    return dev * (1.0 + 1e-6) + 1e-9  # rounding of this sum never hides an arc


def _max_hausdorff(orig: List[np.ndarray], simple: List[np.ndarray], batch: int = 64) -> float:
    """``max(shapely.hausdorff_distance(orig_i, simple_i, densify=0.25))`` over the arcs, the same value:
    arcs are measured in decreasing order of ``_chord_bound`` until no arc left can exceed the largest
    distance measured (GEOS's discrete Hausdorff distance is quadratic in an arc's vertices: it was the
    largest item of this stage)."""
    import shapely

    bound = np.array([_chord_bound(o, s) for o, s in zip(orig, simple)])
    order = np.argsort(-bound, kind="stable")
    best = 0.0
    k = 0
    while k < len(order):
        sel = order[k:k + (1 if k == 0 else batch)]  # the arc of the largest bound first: it often is the one
        k += len(sel)
        if bound[sel[0]] < best:
            break
        sel = sel[bound[sel] >= best]
        h = shapely.hausdorff_distance(_lines([orig[i] for i in sel]), _lines([simple[i] for i in sel]), densify=0.25)
        best = max(best, float(np.max(h)))
    return best


def _despike(xy: np.ndarray, angle_deg: float, length: float) -> np.ndarray:
    """Remove interior vertices forming spikes (angle < angle_deg and protrusion < length)."""
    cos_lim = math.cos(math.radians(angle_deg))
    while len(xy) > 2:
        A, B, C = xy[:-2], xy[1:-1], xy[2:]
        u, w = A - B, C - B
        nu = np.hypot(u[:, 0], u[:, 1])
        nw = np.hypot(w[:, 0], w[:, 1])
        with np.errstate(invalid="ignore", divide="ignore"):
            cosang = (u * w).sum(axis=1) / (nu * nw)
            d = C - A
            dd = (d * d).sum(axis=1)
            t = np.clip(((B - A) * d).sum(axis=1) / np.where(dd > 0, dd, 1.0), 0.0, 1.0)
        proj = A + t[:, None] * d
        prot = np.hypot(*(B - proj).T)
        degenerate = (nu < 1e-12) | (nw < 1e-12)
        spike = degenerate | ((cosang > cos_lim) & (prot < length))
        if not spike.any():
            break
        idx = np.flatnonzero(spike)
        idx = idx[np.r_[True, np.diff(idx) > 1]]  # never two neighbours at once
        xy = np.delete(xy, idx + 1, axis=0)
    return xy


def _simplify_arcs(arc_xy: List[np.ndarray], tol: float, angle: float, length: float):
    """Douglas–Peucker (GEOS, end points kept) then spike removal. Returns (dp_only, final)."""
    import shapely

    if tol <= 0:
        return list(arc_xy), list(arc_xy)
    lines = _lines(arc_xy)
    simp = shapely.simplify(lines, tol, preserve_topology=False)
    dp = []
    for xy, g in zip(arc_xy, simp):
        c = shapely.get_coordinates(g)
        if len(c) < 2 or not (np.array_equal(c[0], xy[0]) and np.array_equal(c[-1], xy[-1])):
            c = xy[[0, -1]] if len(xy) >= 2 else xy
        dp.append(c)
    fin = [_despike(c, angle, length) if len(c) > 2 else c for c in dp]
    return dp, fin


# =========================================================================== main entry point
def refine(graph: AreaGraph, resolution: float, epsilon_px: float = EPSILON_PX,
           spike_angle: float = SPIKE_ANGLE_DEG, spike_length: float = SPIKE_LENGTH_M,
           min_area: float = MIN_AREA_M2, keep_types=KEEP_TYPES, progress=None):
    """Simplify and clean an area partition; see the module docstring.

    Returns ``(refined_graph, stats)``. ``stats`` holds: ``vertices_before``, ``vertices_after``,
    ``vertex_reduction`` (fraction), ``epsilon_m`` (= epsilon_px · resolution, the bound; ``border_epsilon_m``
    on borders between two areas),
    ``max_deviation_dp_m`` (after Douglas–Peucker), ``max_deviation_m`` (after spike removal too),
    ``spikes_removed``, ``merged``, ``dropped``, ``passages_removed``, ``arcs``, ``arcs_fallback``
    (arcs simplified less to keep polygons valid), ``vertices_inserted`` (noding), ``components`` and
    ``largest_component_share`` (connected components of the refined area graph; every output area
    carries its ``component``, 0 = the largest, and the others are logged), ``time_s``.
    Input areas are never modified.
    """
    import shapely
    from shapely.geometry import LineString, Polygon
    from shapely.ops import nearest_points

    t0 = time.perf_counter()
    progress = ensure(progress)
    if not (resolution and resolution > 0):
        raise InputError(f"resolution must be a positive number of metres per pixel, got {resolution}")
    if not graph.areas:
        raise InputError("the area graph has no areas; nothing to refine")
    validate_graph(graph.areas, graph.passages)
    areas = []
    for a in graph.areas:
        b = copy.copy(a)
        b.polygon = _single_polygon(a, progress)
        b.tags = dict(a.tags)
        areas.append(b)
    input_invalid = {a.id for a in areas if not a.polygon.is_valid}
    v_before = int(sum(len(a.polygon.exterior.coords) - 1 + sum(len(r.coords) - 1 for r in a.polygon.interiors)
                       for a in areas))
    progress.step(5, f"refine: {len(areas)} areas, {len(graph.passages)} passages, {v_before} vertices")

    # 1. small areas ---------------------------------------------------------------------------
    areas, passages, minfo = merge_small_areas(areas, list(graph.passages), min_area, keep_types, progress)
    if minfo["merged"] or minfo["dropped"]:
        progress.info(f"small areas (< {min_area} m²): {minfo['merged']} merged into a neighbour, "
                      f"{minfo['dropped']} isolated ones dropped, {minfo['passages_removed']} passages removed")
    if not areas:
        raise InputError(f"every area is smaller than {min_area} m² and isolated; lower MIN_AREA")
    progress.step(15)

    # passage endpoints: snap onto the common border of their two areas ---------------------------
    tol = epsilon_px * resolution
    q = resolution * 1e-3
    amap = {a.id: a for a in areas}
    p_xy = np.zeros((len(passages), 2, 2))
    snapped = 0
    unlocked = []
    for k, p in enumerate(passages):
        c = np.asarray(p.line.coords, dtype=float)[:, :2]
        if len(c) != 2:
            c = c[[0, -1]]
        A, B = amap[p.from_id].polygon, amap[p.to_id].polygon
        for j in range(2):
            pt = shapely.points(c[j])
            if shapely.distance(A.boundary, pt) <= q and shapely.distance(B.boundary, pt) <= q:
                continue
            common = shapely.intersection(A.boundary, B.boundary)
            if common.is_empty or shapely.distance(common, pt) > max(3 * resolution, 0.15):
                unlocked.append(p.id)
                continue
            c[j] = np.asarray(nearest_points(common, pt)[0].coords)[0, :2]
            snapped += 1
        p_xy[k] = c
    if unlocked:
        progress.warning(f"passages {sorted(set(unlocked))} do not lie on the common border of their two "
                         "areas; their end points are kept but cannot be shared by both areas")
    progress.step(20)

    # 2. node into arcs ----------------------------------------------------------------------------
    part = _Partition([a.polygon for a in areas], p_xy.reshape(-1, 2), q)
    n_ins = part.node()
    einv, lens, left, right, eu, ev, bad = _edge_tables(part)
    if len(bad):
        e = bad[0]
        faces = np.repeat(part.ring_face, lens)[einv == e]
        ids = sorted({areas[int(f)].id for f in faces})
        raise InputError(f"areas overlap: {' and '.join(str(i) for i in ids)} share the same side of the edge at "
                         f"({part.V[eu[e], 0]:.3f}, {part.V[eu[e], 1]:.3f}); the areas of a floor must not overlap "
                         "(fix them, or run segmentation again)")
    nv = len(part.V)
    deg = np.bincount(np.concatenate([eu, ev]), minlength=nv)
    nf = len(areas) + 1
    code = np.minimum(left, right) + 1 + (np.maximum(left, right) + 1) * nf
    cmin = np.full(nv, np.iinfo(np.int64).max)
    cmax = np.full(nv, -1, np.int64)
    for arr in (eu, ev):
        np.minimum.at(cmin, arr, code)
        np.maximum.at(cmax, arr, code)
    isbreak = (deg != 2) | (cmin != cmax)
    locked = np.zeros(nv, bool)
    on_ring = np.zeros(nv, bool)
    on_ring[np.concatenate(part.rings)] = True
    pe = part.extra_ids.reshape(-1, 2) if len(passages) else np.zeros((0, 2), np.int64)
    locked[pe.reshape(-1)] = True
    locked &= on_ring
    isbreak |= locked
    # rings without (enough) break points: fix their lowest-id vertex and the farthest one from it
    for r in part.rings:
        nb = int(isbreak[r].sum())
        if nb >= 2:
            continue
        first = int(r[np.flatnonzero(isbreak[r])[0]]) if nb == 1 else int(r.min())
        d2 = ((part.V[r] - part.V[first]) ** 2).sum(axis=1)
        far = int(r[np.lexsort((r, -d2))[0]])
        isbreak[first] = True
        isbreak[far] = True
    progress.step(35, f"refine: noded {nv} vertices ({n_ins} inserted on neighbours' edges)")

    # arcs --------------------------------------------------------------------------------------
    ne = len(eu)
    edge_arc = np.full(ne, -1, np.int64)
    arc_v: List[np.ndarray] = []
    ring_arcs: List[List[Tuple[int, bool]]] = []
    pos = 0
    for r, n in zip(part.rings, lens):
        eids = einv[pos:pos + n]
        pos += n
        bpos = np.flatnonzero(isbreak[r])
        s = int(bpos[0])
        rr = np.roll(r, -s)
        er = np.roll(eids, -s)
        bp = (bpos - s).tolist() + [n]
        lst = []
        for j in range(len(bp) - 1):
            i0, i1 = bp[j], bp[j + 1]
            verts = np.append(rr[i0:i1], rr[i1 % n])
            aid = int(edge_arc[er[i0]])
            if aid < 0:
                aid = len(arc_v)
                arc_v.append(verts)
                edge_arc[er[i0:i1]] = aid
                lst.append((aid, True))
            else:
                lst.append((aid, bool(arc_v[aid][0] == verts[0] and arc_v[aid][1] == verts[1])))
        ring_arcs.append(lst)
    arc_xy0 = [part.V[v] for v in arc_v]
    progress.step(45, f"refine: {len(arc_v)} arcs")

    # 3. simplify + despike, rebuild, validate, fall back --------------------------------------------
    levels = np.zeros(len(arc_v), np.int64)
    # GEOS drops vertices within the tolerance; shave it by 1e-9 so rounding never exceeds the bound
    tols = [tol * (1 - 1e-9), tol / 2.0, 0.0]
    arc_dp: List[np.ndarray] = [None] * len(arc_v)  # type: ignore
    arc_fin: List[np.ndarray] = [None] * len(arc_v)  # type: ignore
    todo = np.arange(len(arc_v))
    face_rings: Dict[int, List[int]] = {}
    for ri, f in enumerate(part.ring_face):
        face_rings.setdefault(int(f), []).append(ri)

    def build(fi):
        shell, holes = None, []
        for ri in face_rings[fi]:
            pieces = []
            for aid, fwd in ring_arcs[ri]:
                c = arc_fin[aid] if fwd else arc_fin[aid][::-1]
                pieces.append(c[:-1])
            xy = np.concatenate(pieces)
            if len(xy) < 3:
                return None
            if part.ring_hole[ri]:
                holes.append(xy)
            else:
                shell = xy
        try:
            return Polygon(shell, holes)
        except Exception:
            return None

    polys: List = [None] * len(areas)
    dirty = set(range(len(areas)))
    arc_faces: List[set] = [set() for _ in arc_v]
    for ri, lst in enumerate(ring_arcs):
        for aid, _ in lst:
            arc_faces[aid].add(int(part.ring_face[ri]))
    fallback_arcs = set()
    # a border between two areas was decided on the segmentation's topology cells (``topology_scale`` raster
    # cells per side, segmentation.topology_scale): its steps are that coarse, and so is its tolerance
    border_scale = max(1, int(graph.stats.get("topology_scale", 1)))
    shared = np.array([len(f) > 1 for f in arc_faces], bool)
    for it in range(4):
        for lv in range(3):
            for sel, scale in ((todo[(levels[todo] == lv) & ~shared[todo]], 1),
                               (todo[(levels[todo] == lv) & shared[todo]], border_scale)):
                if len(sel) == 0:
                    continue
                dp, fin = _simplify_arcs([arc_xy0[i] for i in sel], tols[lv] * scale, spike_angle, spike_length)
                for i, d, f in zip(sel.tolist(), dp, fin):
                    arc_dp[i], arc_fin[i] = d, f
        for fi in dirty:
            polys[fi] = build(fi)
        arr = np.array(polys, dtype=object)
        ok = np.array([p is not None for p in polys])
        valid = np.zeros(len(polys), bool)
        valid[ok] = shapely.is_valid(arr[ok])
        offenders = {fi for fi in range(len(polys)) if not valid[fi] and areas[fi].id not in input_invalid}
        overlapping = []
        if ok.all():
            overlapping = _overlapping_pairs(arr, valid, resolution)
            for x, y, _ in overlapping:
                offenders.update((x, y))
        if not offenders:
            break
        next_todo = set()
        for fi in offenders:
            for ri in face_rings[fi]:
                for aid, _ in ring_arcs[ri]:
                    if levels[aid] < 2:
                        next_todo.add(aid)
        if not next_todo:
            break
        todo = np.array(sorted(next_todo), np.int64)
        levels[todo] += 1
        fallback_arcs.update(next_todo)
        dirty = set()
        for aid in todo.tolist():
            dirty |= arc_faces[aid]
    if overlapping:
        # still overlapping with the unsimplified borders: the input areas overlap
        pairs = ", ".join(f"{areas[x].id} and {areas[y].id} ({a:.3f} m²)" for x, y, a in overlapping[:5])
        raise InputError(f"areas overlap: {pairs}{' ...' if len(overlapping) > 5 else ''}; the areas of a floor "
                         "must not overlap (fix them, or run segmentation again)")
    if offenders:
        progress.warning(f"areas {sorted(areas[fi].id for fi in offenders)} stay invalid or overlapping after "
                         "refinement even without simplification; check their input geometry")
    still_bad = [areas[fi].id for fi in range(len(polys)) if polys[fi] is None]
    if still_bad:
        raise InputError(f"areas {still_bad} collapsed during refinement; check their geometry")
    progress.step(80, "refine: polygons rebuilt from shared arcs")

    # 4. outputs --------------------------------------------------------------------------------
    out_areas = []
    for a, poly in zip(areas, polys):
        b = copy.copy(a)
        b.polygon = poly
        out_areas.append(b)
    out_passages = []
    for k, p in enumerate(passages):
        b = copy.copy(p)
        ia, ib = int(pe[k, 0]), int(pe[k, 1])
        b.line = LineString([part.V[ia], part.V[ib]])
        out_passages.append(b)

    # connectivity after merging: components of the refined graph (Area.component, 0 = largest)
    from .segmentation import assign_components, report_components

    comps = assign_components(out_areas, out_passages)
    report_components(comps, progress, "refine")

    # 5. figures --------------------------------------------------------------------------------
    v_after = int(sum(len(p.exterior.coords) - 1 + sum(len(r.coords) - 1 for r in p.interiors) for p in polys))
    changed = [i for i in range(len(arc_v)) if len(arc_fin[i]) != len(arc_xy0[i]) or len(arc_dp[i]) != len(arc_xy0[i])]
    dev_dp = dev_fin = 0.0
    if changed:
        orig = [arc_xy0[i] for i in changed]
        dev_dp = _max_hausdorff(orig, [arc_dp[i] for i in changed])
        dev_fin = _max_hausdorff(orig, [arc_fin[i] for i in changed])
    spikes = int(sum(len(arc_dp[i]) - len(arc_fin[i]) for i in range(len(arc_v))))
    stats = {
        "areas_in": len(graph.areas), "areas_out": len(out_areas),
        "passages_in": len(graph.passages), "passages_out": len(out_passages),
        "vertices_before": v_before, "vertices_after": v_after,
        "vertex_reduction": (1.0 - v_after / v_before) if v_before else 0.0,
        "epsilon_px": float(epsilon_px), "epsilon_m": float(tol), "border_epsilon_m": float(tol * border_scale),
        "max_deviation_dp_m": dev_dp, "max_deviation_m": dev_fin,
        "spikes_removed": spikes, "merged": minfo["merged"], "dropped": minfo["dropped"],
        "dropped_ids": minfo["dropped_ids"], "merged_into": minfo["merged_into"],
        "passages_removed": minfo["passages_removed"], "passages_snapped": snapped,
        "arcs": len(arc_v), "arcs_fallback": len(fallback_arcs), "vertices_inserted": n_ins,
        "components": len(comps), "largest_component_share": comps[0]["share"] if comps else 1.0,
        "time_s": time.perf_counter() - t0,
    }
    on_borders = "" if border_scale == 1 else f", {tol * border_scale * 100:.2f} cm on borders between two areas"
    progress.step(100, f"refine: vertices {v_before} -> {v_after} (-{100 * stats['vertex_reduction']:.1f} %), "
                       f"max deviation {dev_fin * 100:.2f} cm (DP alone {dev_dp * 100:.2f} cm, bound ε·r = "
                       f"{tol * 100:.2f} cm{on_borders}), {spikes} spike vertices removed, {len(fallback_arcs)} arcs "
                       "simplified less to stay valid")
    out = AreaGraph(out_areas, out_passages, labels=graph.labels, grid=graph.grid, stats=dict(graph.stats))
    out.stats.update({f"refine_{k}": v for k, v in stats.items() if isinstance(v, (int, float))})
    return out, stats


__all__ = ["refine", "graph_from_labels", "merge_small_areas", "validate_graph", "EPSILON_PX", "SPIKE_ANGLE_DEG",
           "SPIKE_LENGTH_M",
           "MIN_AREA_M2"]


# =========================================================================== test / benchmark helper
def graph_from_labels(labels: np.ndarray, origin_x: float, origin_y: float, resolution: float,
                      types: Optional[Dict[int, str]] = None, min_border: float = 0.0) -> AreaGraph:
    """Build an AreaGraph from an int label raster (0 = no area) the way segmentation does:
    exact pixel-edge outlines (GDAL Polygonize, 4-connected) and one passage per connected piece of
    every shared border (from one end of the piece to the other). For tests and benchmarks; a label
    split into several pieces keeps its largest piece.
    """
    import shapely
    from shapely.geometry import LineString

    from .model import OccupancyGrid
    from .segmentation import label_polygons

    labels = np.ascontiguousarray(labels, dtype=np.int32)
    polys = label_polygons(labels, OccupancyGrid(labels, origin_x, origin_y, resolution))
    types = types or {}
    areas = [Area(id=lab, polygon=polys[lab], type=types.get(lab, "room")) for lab in sorted(polys)]
    passages = []
    arr = np.array([a.polygon for a in areas], dtype=object)
    tree = shapely.STRtree(arr)
    i1, i2 = tree.query(arr, predicate="intersects")
    pid = 1
    for x, y in zip(i1.tolist(), i2.tolist()):
        if x >= y:
            continue
        common = shapely.line_merge(shapely.intersection(arr[x].boundary, arr[y].boundary))
        parts = [g for g in getattr(common, "geoms", [common]) if g.geom_type == "LineString"]
        for g in parts:
            c = np.asarray(g.coords)
            if g.length <= min_border or np.allclose(c[0], c[-1]):
                continue
            passages.append(Passage(id=pid, from_id=areas[x].id, to_id=areas[y].id,
                                    line=LineString([c[0], c[-1]])))
            pid += 1
    return AreaGraph(areas, passages, labels=labels)
