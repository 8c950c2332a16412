"""Speed-ups of the building fusion (session 8) must not change the merged file: each rewritten helper is
compared with the library code it replaces (shapely's ``polylabel``, scipy's Nelder-Mead) or with its previous
loop, on random inputs including ties; the merged SIST building itself is pinned in
``tests/test_building.py`` (``SIST_BUILDING_SHA256``)."""
import math

import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon, box

from algorithms import building
from algorithms.model import polylabel


def _random_polygons(seed, count):
    rng = np.random.default_rng(seed)
    out = []
    for k in range(count):
        kind = k % 4
        if kind == 0:  # star-shaped ring
            m = int(rng.integers(5, 40))
            ang = np.sort(rng.uniform(0, 2 * np.pi, m))
            rad = rng.uniform(0.5, 3.0, m)
            g = Polygon(np.column_stack([rad * np.cos(ang), rad * np.sin(ang)]) + rng.uniform(-50, 50, 2))
        elif kind == 1:  # axis-aligned rectangle: symmetric, its cells tie in the queue
            w, h = rng.uniform(0.5, 4.0, 2)
            x, y = rng.uniform(-1e4, 1e4, 2)
            g = box(x, y, x + w, y + h)
        elif kind == 2:  # a ring with holes
            g = Point(rng.uniform(-5, 5, 2)).buffer(rng.uniform(2, 4), int(rng.integers(2, 8)))
            holes = [Point(rng.uniform(-1, 1, 2) + np.array(g.centroid.coords[0])).buffer(rng.uniform(0.2, 0.6), 3)]
            g = g.difference(holes[0])
        else:  # an L-shaped core, rotated
            g = box(0, 0, 3, 1).union(box(0, 0, 1, 2.5))
            from shapely import affinity

            g = affinity.rotate(g, float(rng.uniform(0, 90)), origin=(0, 0))
        if g.geom_type == "Polygon" and g.is_valid and not g.is_empty:
            out.append(g)
    return out


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_polylabel_equals_shapelys(seed):
    from shapely.ops import polylabel as shapely_polylabel

    polys = _random_polygons(seed, 40)
    assert len(polys) >= 30
    for g in polys:
        for tol in (0.02, 0.1, 1.0):
            assert polylabel(g, tol).wkb == shapely_polylabel(g, tol).wkb, (g.wkt, tol)


def test_polylabel_rejects_an_invalid_polygon_as_shapelys_does():
    from shapely.errors import TopologicalError

    bow = Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    with pytest.raises(TopologicalError):
        polylabel(bow, 0.1)


def _nm_cases(seed):
    rng = np.random.default_rng(seed)
    for t in range(60):
        n = 2 + t % 2
        a, c = rng.normal(size=(n, n)), rng.normal(size=n)
        kind = t % 4
        if kind == 0:
            f = (lambda a, c: lambda v: float(np.sum((a @ (np.asarray(v) - c)) ** 2)))(a, c)
        elif kind == 1:  # not smooth
            f = (lambda c: lambda v: float(np.sum(np.abs(np.asarray(v) - c)) + 0.3 * math.sin(5 * v[0])))(c)
        elif kind == 2:  # plateaus: equal values, the sort's tie order matters
            f = (lambda c: lambda v: float(round(float(np.sum((np.asarray(v) - c) ** 2)), 1)))(c)
        else:  # flat zero region
            f = lambda v: float(max(0.0, float(np.sum(np.asarray(v) ** 2)) - 1.0))
        x0 = rng.normal(size=n)
        step = float(rng.choice([0.3, 0.05, 1.0]))
        yield f, np.vstack([x0] + [x0 + step * np.eye(n)[i] for i in range(n)])


@pytest.mark.parametrize("seed", [0, 1])
def test_nelder_mead_equals_scipys(seed):
    from scipy.optimize import minimize

    for f, sim in _nm_cases(seed):
        for xatol, fatol, maxiter in ((1e-3, 1e-6, 300), (1e-4, 1e-7, 400), (1e-9, 1e-12, 15)):
            r = minimize(f, sim[0], method="Nelder-Mead",
                         options={"initial_simplex": sim, "xatol": xatol, "fatol": fatol, "maxiter": maxiter})
            x, fun, ok = building._nelder_mead(f, sim, xatol=xatol, fatol=fatol, maxiter=maxiter)
            assert np.array_equal(r.x, x) and r.fun == fun and r.success == ok


def _anchor_shift_reference(moved, partner, max_move=building.MATCH_TOLERANCE):
    """building.anchor_shift as it was (shapely.transform per evaluation, scipy's minimize)."""
    import shapely
    from scipy.optimize import minimize

    small, big = (moved, partner) if moved.area <= partner.area else (partner, moved)
    sign = 1.0 if small is moved else -1.0
    a_small = max(float(small.area), 1e-9)
    shapely.prepare(big)

    def cost(v):
        g = shapely.transform(small, lambda xy: xy + (v[0], v[1]))
        return 1.0 - float(shapely.area(shapely.intersection(g, big))) / a_small + 0.01 * math.hypot(v[0], v[1])

    c0 = cost((0.0, 0.0))
    best = np.zeros(2)
    for step in (0.3, 0.05):
        x0 = best
        simplex = np.array([x0, x0 + [step, 0.0], x0 + [0.0, step]])
        res = minimize(cost, x0, method="Nelder-Mead",
                       options={"initial_simplex": simplex, "xatol": 1e-3, "fatol": 1e-6, "maxiter": 300})
        if res.fun < c0 - 1e-9 and math.hypot(*res.x) <= max_move:
            best, c0 = np.asarray(res.x, float), float(res.fun)
    return sign * best


def test_anchor_shift_equals_the_scipy_version():
    from shapely import affinity

    rng = np.random.default_rng(3)
    core = box(0, 0, 2.4, 2.0).union(box(0, 0, 1.2, 3.1))
    for _ in range(12):
        other = affinity.translate(core, *rng.uniform(-0.4, 0.4, 2))
        if rng.random() < 0.5:  # a cut longer on one floor
            other = other.union(box(0, -float(rng.uniform(0.2, 1.0)), 2.4, 0.1))
        moved = affinity.rotate(core, float(rng.uniform(-1, 1)), origin="centroid")
        assert np.array_equal(building.anchor_shift(moved, other), _anchor_shift_reference(moved, other))


def _open_probes_reference(host, pts, normal, step=0.05, probe=0.3):
    """The open-sample test of building._shaft_mouth as it was: one contains_xy call per probe step."""
    import shapely

    open_ = np.ones(len(pts), bool)
    for r in np.arange(step, probe + 1e-9, step):
        out = pts + r * normal
        open_ &= shapely.contains_xy(host, out[:, 0], out[:, 1])
    return open_


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_open_samples_in_one_call_equal_the_per_step_loop(seed):
    rng = np.random.default_rng(seed)
    hall = box(-10, -10, 10, 10).difference(box(0, 0, 2, 2).buffer(0.1, join_style=2)).union(
        LineString([(0.6, -0.2), (1.5, -0.2)]).buffer(0.25, cap_style=2))
    pts = rng.uniform(-0.5, 2.5, (300, 2))
    ang = rng.uniform(0, 2 * np.pi, 300)
    normal = np.column_stack([np.cos(ang), np.sin(ang)])
    for step, probe in ((0.05, 0.3), (0.1, 0.25), (0.05, 0.01)):
        got = building._open_samples(hall, pts, normal, step, probe)
        ref = _open_probes_reference(hall, pts, normal, step, probe)
        assert np.array_equal(got, ref)
        assert 0 < got.sum() < len(got) or probe < step


def test_open_samples_on_a_prepared_host_equal_the_unprepared_test_also_on_its_boundary():
    """The probes run on the prepared host: the same answers as the unprepared test, also for probe points on
    the host's vertices and edges (not inside), and the host is left as it came."""
    import shapely

    rng = np.random.default_rng(5)
    hall = Point(0, 0).buffer(12, 200).difference(box(-1, -1, 1, 1))  # ~800 vertices, a hole
    ring = np.asarray(hall.exterior.coords)[:-1]
    pts = np.vstack([ring[::7], (ring[:-1:5] + ring[1::5]) / 2, rng.uniform(-13, 13, (400, 2))])
    normal = np.zeros_like(pts)
    normal[:, 0] = 1.0
    for step, probe in ((0.05, 0.3), (0.5, 1.0)):
        # probe from 0.05 m behind each point: its first probe point is the point itself (on the boundary)
        got = building._open_samples(hall, pts - step * normal, normal, step, probe)
        ref = _open_probes_reference(hall, pts - step * normal, normal, step, probe)
        assert np.array_equal(got, ref)
        assert not shapely.is_prepared(hall)
    shapely.prepare(hall)
    building._open_samples(hall, pts, normal, 0.05, 0.3)
    assert shapely.is_prepared(hall)  # a host prepared by its caller stays prepared


def test_shaft_mouth_finds_the_door_of_a_lift_in_a_hall():
    hall = box(-10, -10, 10, 10).difference(box(0, 0, 2, 2).buffer(0.1, join_style=2)).union(
        LineString([(0.6, -0.2), (1.5, -0.2)]).buffer(0.25, cap_style=2))
    mouth = building._shaft_mouth(box(0, 0, 2, 2), hall)
    assert mouth is not None and 0.6 <= mouth.length <= 1.5
    assert abs(mouth.centroid.y) < 0.01 and 0.6 <= mouth.centroid.x <= 1.5


def _attach_passage_ends_reference(areas, passages, tol=building.PASSAGE_END_TOL):
    """building._attach_passage_ends as it was: one Point and one distance call per passage end (the ends it judges
    are building._passage_ends and the insertion building._insert_end, both unchanged)."""
    n = 0
    for a, c in building._passage_ends(areas, passages):
        d = a.polygon.exterior.distance(Point(c[:2]))
        if 1e-9 < d <= tol:
            n += building._insert_end(a, c, tol)
    return n


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_attach_passage_ends_in_one_distance_call_equals_the_per_end_loop(seed):
    """Passage ends on, near (1-2 mm: inserted, several into one ring) and far from their areas' rings, a
    passage to a missing area and an empty line: the same rings and the same count as the per-end loop."""
    import copy

    from algorithms.model import Area, Passage

    rng = np.random.default_rng(seed)
    areas = [Area(id=k + 1, polygon=box(12 * k, 0, 12 * k + 10, 8.0 + k % 3)) for k in range(6)]
    passages = []
    for k in range(40):
        a, b = (int(v) for v in rng.integers(1, 8, 2))  # 7: no such area
        poly = areas[min(a, 6) - 1].polygon
        ring = np.asarray(poly.exterior.coords)
        e = int(rng.integers(0, len(ring) - 1))
        t = float(rng.uniform(0.1, 0.9))
        p0 = ring[e] + t * (ring[e + 1] - ring[e])
        off = float(rng.choice([0.0, 0.001, -0.0015, 0.002, 0.5]))
        n = np.array([-(ring[e + 1] - ring[e])[1], (ring[e + 1] - ring[e])[0]])
        p0 = p0 + off * n / np.linalg.norm(n)
        line = LineString([p0, p0 + rng.uniform(-0.4, 0.4, 2)]) if k % 13 else LineString()
        passages.append(Passage(id=k + 1, from_id=a, to_id=b, line=line))
    ref_areas = copy.deepcopy(areas)
    got = building._attach_passage_ends(areas, passages)
    ref = _attach_passage_ends_reference(ref_areas, passages)
    assert got == ref and got > 0
    assert [a.polygon.wkb for a in areas] == [a.polygon.wkb for a in ref_areas]
