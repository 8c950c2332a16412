"""Route planning over the osmAG graph (algorithms/routing.py): synthetic maps and the shared osmAG maps."""
import math

import numpy as np
import pytest
from shapely.geometry import LineString, box

from algorithms.errors import Canceled, InputError
from algorithms.model import Area, Passage
from algorithms.progress import RecordingProgress
from algorithms.routing import RouteError, RouteMap, infer_area_type


def area(i, poly, name, level="1", atype="room"):
    return Area(id=i, polygon=poly, type=atype, name=name, tags={"level": level, "height": "3"})


def passage(i, a, b, p0, p1, name=None, level="1"):
    return Passage(id=i, from_id=a, to_id=b, line=LineString([p0, p1]), name=name or f"P{i}", tags={"level": level})


def clearance_ok(points, obstacles, r):
    """Every segment of the path keeps at least r from the obstacle geometry, but for the 45 degree chords
    that approximate the grown wall corners (they cut 7.6 % of r into the disc)."""
    return LineString(points).distance(obstacles) >= r * (1 - 0.077) - 1e-6


# --------------------------------------------------------------------------- one area
def u_room():
    # 10 x 10 room with a wall tongue from the top (x 4..6, y 3..10): the straight line is blocked
    return box(0, 0, 10, 10).difference(box(4, 3, 6, 10))


@pytest.mark.parametrize("r", [0.0, 0.3, 0.5])
def test_u_shaped_room_goes_around_the_tongue(r):
    rm = RouteMap.from_areas([area(1, u_room(), "U")], [])
    res = rm.route((2, 8), (8, 8), robot_radius=r)
    # exact: tangent from the start to the disc of radius r around the tongue's corner (4, 3), the arc,
    # 2 m under the tongue, and the mirror image (the wall corners are grown by 45 degree chords)
    rr = max(r, 0.01)
    d = math.hypot(2, 5)
    exact = 2 * (math.sqrt(d * d - rr * rr) + rr * (math.atan2(5, 2) + math.asin(rr / d))) + 2
    assert exact * 0.995 <= res.length <= exact + 1e-6
    assert res.points[:, 1].min() <= 3.0 - r + 0.02  # it went below the tongue
    walls = u_room().boundary
    assert clearance_ok(res.points, walls, max(r, 0.01))
    assert res.areas == ["U"] and res.passages == []
    assert res.levels == ["1"] * len(res.points)


def test_start_near_a_wall_snaps_and_far_outside_is_an_error():
    rm = RouteMap.from_areas([area(1, box(0, 0, 10, 5), "Room")], [])
    res = rm.route((-0.4, 2), (9, 2), robot_radius=0.3)  # 0.4 m outside the room: snapped by 0.7 m
    assert res.start_snap == pytest.approx(0.7, abs=0.01)
    assert res.start[0] == pytest.approx(0.3, abs=0.01)
    assert res.length == pytest.approx(8.7, abs=0.02)
    with pytest.raises(InputError, match=r"outside every area.*nearest area is 'Room'.*3\.0 m away"):
        rm.route((-3, 2), (9, 2), robot_radius=0.3)
    with pytest.raises(InputError, match="level '7' is not in the map; its levels are 1"):
        rm.route((1, 1), (9, 2), start_level="7")
    with pytest.raises(InputError, match="ROBOT_RADIUS"):
        rm.route((1, 1), (9, 2), robot_radius=-1)
    with pytest.raises(InputError, match="no area named 'Kitchen'"):
        rm.route("Kitchen", (9, 2))


# --------------------------------------------------------------------------- passages
def two_rooms(door_width):
    """Two 5 x 4 rooms side by side sharing the wall x = 5, with a door of ``door_width`` centred at y = 2."""
    a = area(1, box(0, 0, 5, 4), "West")
    b = area(2, box(5, 0, 10, 4), "East")
    p = passage(10, 1, 2, (5, 2 - door_width / 2), (5, 2 + door_width / 2), "Door")
    return [a, b], [p]


def test_route_through_a_door_and_radius_closing_it():
    areas, passages = two_rooms(0.8)
    rm = RouteMap.from_areas(areas, passages)
    res = rm.route((1, 3.5), (9, 0.5), robot_radius=0.3)
    assert res.areas == ["West", "East"] and res.passages == ["Door"]
    # the path bends at the door's usable span (y in 1.9..2.1) and keeps 0.3 m from the jambs
    jambs = areas[0].polygon.boundary.difference(passages[0].line.buffer(1e-6))
    assert clearance_ok(res.points, jambs, 0.3)
    assert res.length == pytest.approx(math.hypot(8, 3), abs=0.01)  # the straight line fits through
    # a goal behind the wall: the path bends around the upper jamb's disc
    bent = rm.route((1, 3.5), (9, 3.5), robot_radius=0.3)
    d = math.hypot(4, 1.1)
    assert 2 * math.sqrt(d * d - 0.09) <= bent.length <= 2 * math.hypot(4, 1.4) + 1e-6
    assert clearance_ok(bent.points, jambs, 0.3)
    with pytest.raises(RouteError) as exc:
        rm.route((1, 3.5), (9, 0.5), robot_radius=0.45)
    msg = str(exc.value)
    assert "'Door' (0.80 m wide, the robot needs 0.90 m)" in msg
    assert "'West'" in msg and "'East'" in msg and "2 separate parts" in msg
    assert exc.value.components["start"] == ["West"] and exc.value.components["goal"] == ["East"]


def test_unreachable_goal_names_both_components():
    areas = [area(1, box(0, 0, 4, 4), "A"), area(2, box(4, 0, 8, 4), "B"), area(3, box(20, 0, 24, 4), "C"),
             area(4, box(24, 0, 28, 4), "D")]
    passages = [passage(10, 1, 2, (4, 1), (4, 3)), passage(11, 3, 4, (24, 1), (24, 3))]
    rm = RouteMap.from_areas(areas, passages)
    parts = r"part #\d \(2 areas on level 1: A, B\).*part #\d \(2 areas on level 1: C, D\)"
    with pytest.raises(RouteError, match=parts):
        rm.route("A", "D")
    assert sorted(map(len, rm.components(0.3))) == [2, 2]


def test_wide_opening_is_crossed_where_the_straight_line_crosses_it():
    # two halves of a hall split by a 6 m wide opening: the straight route must not be forced to its middle
    areas = [area(1, box(0, 0, 6, 6), "H1", atype="corridor"), area(2, box(6, 0, 12, 6), "H2", atype="corridor")]
    passages = [passage(10, 1, 2, (6, 0), (6, 6), "Split")]
    rm = RouteMap.from_areas(areas, passages)
    res = rm.route((1, 5), (11, 4.6), robot_radius=0.3)
    assert res.length <= math.hypot(10, 0.4) * 1.005


def test_concave_corridor_route_is_optimal_against_a_fine_visibility_reference():
    # an L-shaped corridor split into two areas at the bend, rooms off it: compare with brute force
    c1 = box(0, 0, 20, 2)
    c2 = box(18, 2, 20, 20)
    rooms = [box(2, -5, 8, 0), box(10, -5, 16, 0), box(20, 10, 26, 16)]
    areas = [area(1, c1, "C1", atype="corridor"), area(2, c2, "C2", atype="corridor")]
    passages = [passage(10, 1, 2, (18, 2), (20, 2), "Bend")]
    for k, r in enumerate(rooms):
        areas.append(area(3 + k, r, f"R{k}"))
    passages += [passage(20, 3, 1, (4, 0), (5, 0), "D0"), passage(21, 4, 1, (12, 0), (13, 0), "D1"),
                 passage(22, 5, 2, (20, 12), (20, 13), "D2")]
    rm = RouteMap.from_areas(areas, passages)
    res = rm.route("R0", "R2", robot_radius=0.3)
    assert res.areas == ["R0", "C1", "C2", "R2"]
    assert res.passages == ["D0", "Bend", "D2"]
    # obstacle-free straight segments: the path never leaves the union of the areas by more than a hair
    free = areas[0].polygon
    for a in areas[1:]:
        free = free.union(a.polygon)
    assert free.buffer(1e-6).covers(LineString(res.points))
    # A* (landmarks + straight line) finds the same cost as plain Dijkstra over the graph
    check_astar_matches_dijkstra(rm, 0.3)


def check_astar_matches_dijkstra(rm, r, vc=15.0, avoid=(), pairs=20, seed=0):
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import dijkstra

    g = rm._avoid_variant(rm.graph(r), rm._avoid_set(avoid))  # with avoid: the graph whose stair openings are walls
    n = len(g.pos)
    rows, cols, w = [], [], []
    for a, lst in enumerate(g.adj):
        for (m, c, kind, data, span) in lst:
            if kind in avoid:
                continue
            rows.append(a)
            cols.append(m)
            w.append(c + vc * span + 1e-12)
    # start/goal as extra nodes n, n+1
    rng = np.random.default_rng(seed)
    ks = [k for k in range(len(rm.areas)) if g.pieces_by_area.get(k) and rm.types[k] not in avoid]
    for _ in range(pairs):
        a, b = rng.choice(ks, 2, replace=False)
        pa, pb = rm.area_point(a, r, avoid), rm.area_point(b, r, avoid)
        try:
            res = rm.route(pa, pb, rm.levels[a], rm.levels[b], robot_radius=r, vertical_cost=vc, avoid=avoid)
        except RouteError:
            continue
        s = rm.locate(pa, rm.levels[a], r, avoid=avoid)
        t = rm.locate(pb, rm.levels[b], r, avoid=avoid)
        sd, _ = s[0].point_costs(s[1])  # the dense reference: every corner tested
        td, _ = t[0].point_costs(t[1])
        R, C, W = list(rows), list(cols), list(w)
        for (m, vi, d) in s[0].entries:
            if math.isfinite(sd[vi]):
                R.append(n), C.append(m), W.append(sd[vi] + d + 1e-12)
        for (m, vi, d) in t[0].entries:
            if math.isfinite(td[vi]):
                R.append(m), C.append(n + 1), W.append(td[vi] + d + 1e-12)
        cheapest = {}  # parallel edges (two doors joined through the room and the corridor): the cheaper
        for x, y, c in zip(R, C, W):
            cheapest[(x, y)] = min(c, cheapest.get((x, y), math.inf))
        (R, C), W = zip(*cheapest.keys()), list(cheapest.values())
        mat = coo_matrix((W, (R, C)), shape=(n + 2, n + 2)).tocsr()
        ref = dijkstra(mat, directed=True, indices=n)[n + 1]
        if s[0] is t[0]:
            ref = min(ref, res.graph_cost)  # same piece: the direct in-area path is not in the node graph
        assert res.graph_cost == pytest.approx(ref, rel=1e-6, abs=1e-6)
        assert res.cost <= res.graph_cost + 1e-9  # crossings pulled: never longer than the graph's optimum


# --------------------------------------------------------------------------- several levels
def two_floors(implicit=False):
    """Two floors: a corridor with a stair at the west end and a lift at the east end on each level."""
    areas, passages = [], []
    for lv, base in (("1", 0), ("2", 100)):
        corr = area(base + 1, box(0, 0, 40, 3), f"Corridor {lv}", lv, "corridor")
        st = area(base + 2, box(0, 3, 4, 8), "ST-01" if implicit else f"Stair {lv}", lv,
                  "room" if implicit else "stairs")
        lift = area(base + 3, box(36, 3, 39, 6), "E-P1" if implicit else f"Lift {lv}", lv,
                    "room" if implicit else "elevator")
        office = area(base + 4, box(8, 3, 14, 8), f"Office {lv}", lv)
        areas += [corr, st, lift, office]
        passages += [passage(base + 10, base + 2, base + 1, (1, 3), (3, 3), f"S{lv}", lv),
                     passage(base + 11, base + 3, base + 1, (37, 3), (38.5, 3), f"L{lv}", lv),
                     passage(base + 12, base + 4, base + 1, (10, 3), (11, 3), f"O{lv}", lv)]
    if not implicit:
        passages += [passage(200, 2, 102, (1.5, 5), (2.5, 5), "Stair 1-2", "2"),
                     passage(201, 3, 103, (37, 4.5), (38, 4.5), "Lift 1-2", "2")]
    return areas, passages


def test_cross_floor_route_uses_stairs_or_lift_and_avoid_stairs_detours():
    areas, passages = two_floors()
    rm = RouteMap.from_areas(areas, passages)
    assert rm.level_list == ["1", "2"] and len(rm.vertical) == 2
    res = rm.route("Office 1", "Office 2", robot_radius=0.3, vertical_cost=10)
    assert "Stair 1-2" in res.passages and res.level_changes == 1
    assert res.levels[0] == "1" and res.levels[-1] == "2"
    assert res.z[0] == pytest.approx(3.0) and res.z[-1] == pytest.approx(6.0)
    assert res.cost == pytest.approx(res.length + 10, abs=1e-6)
    wheel = rm.route("Office 1", "Office 2", robot_radius=0.3, vertical_cost=10, avoid=["stairs"])
    assert "Lift 1-2" in wheel.passages and "Stair 1-2" not in wheel.passages
    assert "Lift 1" in wheel.areas and not any(a.startswith("Stair") for a in wheel.areas)
    assert wheel.length > res.length + 30  # the lift is 27 m farther: there and back
    check_astar_matches_dijkstra(rm, 0.3, vc=10)
    check_astar_matches_dijkstra(rm, 0.3, vc=10, avoid=("stairs",))
    # a goal inside a stair well is still reached when stairs are avoided: by lift, then in through its door
    into = rm.route("Office 1", "Stair 2", robot_radius=0.3, vertical_cost=10, avoid=["stairs"])
    assert "Lift 1-2" in into.passages and into.areas[-1] == "Stair 2" and "Stair 1" not in into.areas
    assert "the goal lies in an avoided area (stairs): its passages are open for this route" in into.warnings
    # only stairs lead up: a wheelchair route does not exist, and the message says why
    no_lift = [p for p in passages if p.name != "Lift 1-2"]
    rm2 = RouteMap.from_areas(areas, no_lift)
    with pytest.raises(RouteError, match="avoiding stairs.*level 1.*level 2"):
        rm2.route("Office 1", "Office 2", avoid=["stairs"])


def test_same_named_shafts_on_two_levels_are_linked_and_typed_by_name():
    areas, passages = two_floors(implicit=True)
    pr = RecordingProgress()
    rm = RouteMap.from_areas(areas, passages, progress=pr)
    assert infer_area_type("room", "E1-ST-09") == "stairs" and infer_area_type("room", "E2-P3") == "elevator"
    assert infer_area_type("room", "Office 12") == "room" and infer_area_type("room", "E1a-F2-PF2") == "room"
    assert len(rm.implicit) == 2 and "vertical links added between same-named" in pr.text()
    res = rm.route("Office 1", "Office 2", robot_radius=0.3, avoid=["stairs"])
    assert res.level_changes == 1 and res.areas.count("E-P1") == 2


def test_points_need_a_level_when_floors_overlap_and_cancel_is_honoured():
    areas, passages = two_floors()
    rm = RouteMap.from_areas(areas, passages)
    with pytest.raises(InputError, match="levels 1, 2; give its level"):
        rm.route((20, 1.5), (11, 5), goal_level="2")
    res = rm.route((20, 1.5), (11, 5), start_level="1", goal_level="2")
    assert res.level_changes == 1
    with pytest.raises(Canceled):
        RouteMap.from_areas(areas, passages).graph(0.2, progress=RecordingProgress(cancel_after=1))


# --------------------------------------------------------------------------- osmAG files
def test_route_on_an_osmag_file_we_wrote(tmp_path):
    from algorithms.georef import LocalFrame
    from algorithms.osmag import write_osmag

    areas, passages = two_rooms(1.0)
    path = tmp_path / "two.osm"
    write_osmag(str(path), areas, passages, frame=LocalFrame(121.59, 31.18), variant="fix-id")
    rm = RouteMap.from_osmag(str(path))
    lon, lat = rm.frame.to_wgs84(np.array([1.0, 9.0]), np.array([3.5, 0.5]))
    s = rm.frame.from_wgs84(lon[0], lat[0])
    g = rm.frame.from_wgs84(lon[1], lat[1])
    res = rm.route((float(s[0]), float(s[1])), (float(g[0]), float(g[1])), robot_radius=0.3)
    assert res.length == pytest.approx(math.hypot(8, 3), abs=0.01)
    assert res.areas == ["West", "East"]


def test_passage_to_a_missing_area_is_reported_with_its_way_id_and_skipped(tmp_path):
    """Issue 10's bad input, the ShanghaiTech_merge_2 kind (56 passages pointing at 'out'), small: a file
    whose passage names an area that is not in it loads, says which way and which name, and routes."""
    import copy
    import xml.etree.ElementTree as ET

    from algorithms.georef import LocalFrame
    from algorithms.osmag import write_osmag

    areas, passages = two_rooms(1.0)
    path = tmp_path / "two.osm"
    write_osmag(str(path), areas, passages, frame=LocalFrame(121.59, 31.18), variant="fix-id")
    tree = ET.parse(path)
    root = tree.getroot()
    way = [w for w in root.iter("way") if any(t.get("v") == "passage" for t in w.iter("tag"))][0]
    bad = copy.deepcopy(way)
    bad.set("id", "-4242")
    for t in bad.iter("tag"):
        if t.get("k") == "osmAG:to":
            t.set("v", "out")
    root.append(bad)
    tree.write(path, encoding="utf-8", xml_declaration=True)
    pr = RecordingProgress()
    rm = RouteMap.from_osmag(str(path), progress=pr)
    assert "1 passages point at areas missing from the file ('out'), e.g. ways [-4242]" in pr.text()
    assert len(rm.passages) == 1  # the good door only
    c = rm.frame.from_wgs84(*rm.frame.to_wgs84(np.array([1.0]), np.array([2.0])))
    assert rm.route((float(c[0]), float(c[1])), "East", robot_radius=0.3).areas == ["West", "East"]


@pytest.mark.slow
def test_other_tools_campus_map(shared_data):
    path = shared_data / "osmag" / "fix_id_ShanghaiTech_merge_2.osm"
    pr = RecordingProgress()
    rm = RouteMap.from_osmag(str(path), progress=pr)
    text = pr.text()
    assert "56 passages point at areas missing from the file ('out', 'out1')" in text
    assert rm.level_list == ["1", "2"]
    s = rm.summary(0.3)
    assert s["implicit_links"] >= 5  # its stairs/lifts are repeated per floor by name
    big = rm.components(0.3)[0]
    assert len(big) >= 0.75 * len(rm.areas)
    names = [rm.areas[k].name for k in big]
    assert any(rm.levels[k] == "1" for k in big) and any(rm.levels[k] == "2" for k in big)
    # two areas of the main part, far apart and on different levels
    k1 = max((k for k in big if rm.levels[k] == "1"), key=lambda k: rm.areas[k].polygon.centroid.x)
    k2 = min((k for k in big if rm.levels[k] == "2"), key=lambda k: rm.areas[k].polygon.centroid.x)
    res = rm.route(rm.area_point(k1), rm.area_point(k2), "1", "2", robot_radius=0.3)
    assert res.level_changes == 1 and res.length > 50 and names
    straight = math.hypot(*(np.asarray(rm.area_point(k1)) - rm.area_point(k2)))
    assert res.length >= straight - 1e-6
    wheel = rm.route(rm.area_point(k1), rm.area_point(k2), "1", "2", robot_radius=0.3, avoid=["stairs"])
    assert wheel.cost >= res.cost - 1e-6
    assert not any(infer_area_type("room", a) == "stairs" for a in wheel.areas[1:-1])


@pytest.mark.slow
def test_sample_floor_routes_match_grid_astar(tmp_path):
    """Our pipeline's map of the sample building's floor 1 against 8-connected grid A* on its raster
    (string-pulled), the benchmark's comparison on a few pairs."""
    import importlib.util

    from algorithms.pipeline import process_floor
    from algorithms.sample_building import generate_building
    from tests.conftest import REPO

    spec = importlib.util.spec_from_file_location("bench_route", REPO / "scripts" / "bench_route.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    sb = generate_building(str(tmp_path), floors=1, seed=0)
    fl = process_floor(sb["dxf"][0], level="1")
    rm = RouteMap.from_areas(fl.refined.areas, fl.refined.passages)
    gf = bench.GridFloor(fl.grid, fl.refined.areas, 0.3)
    pairs = bench.sample_pairs(gf, rm, 6, np.random.default_rng(3), min_dist=10.0)
    assert len(pairs) == 6
    for ps, pg, a, b in pairs:
        res = rm.route(a, b, robot_radius=0.3)
        path, g8 = gf.astar(ps, pg)
        any_angle = gf.smooth(path)
        assert res.length <= any_angle * 1.02
        assert res.length >= math.hypot(a[0] - b[0], a[1] - b[1]) - 1e-6
        assert res.length >= any_angle * 0.95  # not through walls: at most the raster's rounding shorter


@pytest.mark.slow
@pytest.mark.parametrize("name", ["semantic_tags_SIST_1.osm", "show_sist_merge_v1.osm", "show_sist_f1_v5.osm"])
def test_other_tools_maps_load_and_route_or_explain(shared_data, name):
    pr = RecordingProgress()
    rm = RouteMap.from_osmag(str(shared_data / "osmag" / name), progress=pr)
    comps = rm.components(0.3)
    big = comps[0]
    if len(big) < 2:  # show_sist_f1_v5 has no passage at all: every room is its own part
        assert name == "show_sist_f1_v5.osm" and len(comps) == len(rm.areas)
        with pytest.raises(RouteError, match=f"the map has {len(comps)} separate parts"):
            rm.route(rm.area_point(0), rm.area_point(1), rm.levels[0], rm.levels[1])
        return
    far = max(((a, b) for a in big[:40] for b in big[:40]),
              key=lambda ab: rm.areas[ab[0]].polygon.centroid.distance(rm.areas[ab[1]].polygon.centroid))
    a, b = far
    res = rm.route(rm.area_point(a), rm.area_point(b), rm.levels[a], rm.levels[b])
    assert res.areas[0] == rm.areas[a].name and res.areas[-1] == rm.areas[b].name
    assert res.length >= math.hypot(*(np.asarray(rm.area_point(a)) - rm.area_point(b))) - 1e-6
    assert res.level_changes == (rm.levels[a] != rm.levels[b])


def test_shafts_renamed_by_fusion_still_link_by_name():
    """Fusion keeps names unique by adding ' (level N)': 'E-P1 (level 1)' and 'E-P1 (level 2)' are one shaft,
    typed from the name even when the map types it 'room'."""
    areas, passages = two_floors(implicit=True)
    for a in areas:
        if a.name in ("ST-01", "E-P1"):
            a.name = f"{a.name} (level {a.tags['level']})"
    rm = RouteMap.from_areas(areas, passages)
    kinds = {a.name: rm.types[k] for k, a in enumerate(rm.areas)}
    assert kinds["E-P1 (level 2)"] == "elevator" and kinds["ST-01 (level 1)"] == "stairs"
    assert len(rm.implicit) == 2
    wheel = rm.route("Office 1", "Office 2", robot_radius=0.3, avoid=["stairs"])
    assert wheel.level_changes == 1 and "E-P1 (level 1)" in wheel.areas


def test_visibility_from_a_point_culled_by_angle_equals_the_dense_test():
    """Large halls use the angle-culled visibility test (routing._crossing_from_sparse): it must give the
    same answer as the dense one, on a comb-shaped room (many reflex corners, targets all around)."""
    from shapely.geometry import Polygon, box as _box
    from shapely.ops import unary_union

    from algorithms import routing

    teeth = [_box(2 * k, 10, 2 * k + 1, 14) for k in range(20)]
    poly = unary_union([_box(0, 0, 40, 10)] + teeth)
    poly = Polygon(poly.exterior).difference(_box(10, 3, 12, 5))  # a pillar too
    rings = routing._rings(poly)
    E = routing._edges_of(rings)
    parts = routing._edge_parts(E)
    V = np.vstack(rings)
    rng = np.random.default_rng(5)
    n = 0
    for _ in range(200):
        x, y = rng.uniform(0, 40), rng.uniform(0, 14)
        if not poly.buffer(-1e-3).contains(routing._point(x, y)):
            continue
        n += 1
        dense = routing._crossing_from(x, y, V[:, 0], V[:, 1], E, parts)
        sparse = routing._crossing_from_sparse(x, y, V[:, 0], V[:, 1], parts)
        assert (dense == sparse).all()
        assert 0 < dense.sum() < len(V)  # some corners hidden, some seen
    assert n > 100


# --------------------------------------------------------------------------- query speed-ups: same answers
def comb_hall():
    """A hall with 20 teeth on its north side and two pillars: many reflex corners, targets all around."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    teeth = [box(2 * k, 10, 2 * k + 1, 14) for k in range(20)]
    poly = unary_union([box(0, 0, 40, 10)] + teeth)
    return Polygon(poly.exterior).difference(box(10, 3, 12, 5)).difference(box(25, 4, 26, 8))


def test_visibility_polygons_equal_the_segment_test():
    """A point sees a corner iff it lies in the corner's visibility polygon (routing._Piece.build_visibility):
    the same answer as the segment-against-every-edge test, also for points lined up exactly with two
    corners (on a wedge bound) and points on the line of a bounding edge."""
    from algorithms import routing

    pc = routing._Piece((0, 0), 0, comb_hall(), "1")
    pc.add_point((20.0, 0.0))  # an entry point on the border, not a corner
    pc.solve()
    pc.build_visibility()
    V = pc.V
    rng = np.random.default_rng(7)
    pts = [tuple(rng.uniform((0, 0), (40, 14))) for _ in range(400)]
    for _ in range(200):  # lined up with two vertices: the wedge bounds
        i, j = rng.choice(len(V), 2, replace=False)
        pts.append(tuple(V[i] + rng.uniform(0.1, 2.0) * (V[j] - V[i])))
    pts += [(3.0, 5.0), (11.0, 2.0), (12.0, 4.0), (26.0, 9.0), (2.0, 9.0)]  # on edge lines
    n = 0
    for x, y in pts:
        if not pc.core.contains(routing._point(x, y)):
            continue
        n += 1
        cand = np.arange(len(V))
        fast = pc.visible_vertices(x, y, cand)
        exact = ~routing._crossing_from(x, y, V[:, 0], V[:, 1], pc.edges, pc.edge_parts)
        assert (fast == exact).all(), (x, y, np.flatnonzero(fast != exact))
    assert n > 250


def _hall_map():
    """The comb hall with four doors to four rooms, and a corridor: large pieces with many entries."""
    hall = comb_hall()
    areas = [area(1, hall, "Hall", atype="corridor")]
    passages = []
    for k, x in enumerate((5.0, 15.0, 30.0, 36.0)):
        areas.append(area(10 + k, box(x - 2, -4, x + 2, 0), f"Room {k}"))
        passages.append(passage(20 + k, 10 + k, 1, (x - 0.5, 0), (x + 0.5, 0), f"D{k}"))
    areas.append(area(30, box(40, 2, 50, 5), "Corridor", atype="corridor"))
    passages.append(passage(40, 1, 30, (40, 2.5), (40, 4.5), "East"))
    # a second door from room 0 into the corridor too: two doors join the same pair of areas
    areas[1] = area(10, box(3, -4, 7, 0).union(box(7, -4, 44, -2)).union(box(42, -2, 44, 2)), "Room 0")
    passages.append(passage(41, 10, 30, (42.5, 2), (43.5, 2), "D0b"))
    return areas, passages


def test_lazy_entry_costs_equal_the_dense_ones():
    """entry_costs (visibility polygons, lazy batches, or all candidates at once) gives the dense
    point_costs' distances at every entry."""
    from algorithms import routing

    areas, passages = _hall_map()
    rm = RouteMap.from_areas(areas, passages)
    g = rm.graph(0.3)
    hall = g.pieces_by_area[0][0]
    assert hall.large() and len(hall.entries) >= 8
    rng = np.random.default_rng(3)
    pts = [p for p in (tuple(rng.uniform((0, 0), (40, 14))) for _ in range(150))
           if hall.core.contains(routing._point(*p))]
    for mode in ("lazy", "vp"):
        if mode == "vp":
            hall.build_visibility()
        for p in pts:
            p = np.asarray(p)
            d1, v1 = hall.entry_costs(p, True)
            d2, v2 = hall.point_costs(p, entries_only=True)
            ent = np.unique(hall.e_vi)
            assert np.allclose(d1[ent], d2[ent], rtol=0, atol=1e-9, equal_nan=True)
    assert hall._vp is not None


def test_node_table_equals_astar_and_parallel_edges_keep_the_cheaper(monkeypatch):
    """The node-to-node table (maps up to MAX_TABLE_NODES nodes) and A* with landmarks (larger maps) give the
    same costs; two doors between one room and one corridor join their nodes through both areas (parallel
    edges): the cheaper one counts (scipy's sparse matrices would add them up)."""
    from algorithms import routing

    areas, passages = _hall_map()
    rm = RouteMap.from_areas(areas, passages)
    g = rm.graph(0.3)
    mat = rm._matrix(g, 15.0, set()).tocoo()
    csr = g.csr()
    cheapest = {}
    for n in range(len(g.pos)):
        for e in range(csr["indptr"][n], csr["indptr"][n + 1]):
            key = (n, int(csr["nbr"][e]))
            cheapest[key] = min(cheapest.get(key, math.inf), float(csr["cost"][e]))
    assert len(cheapest) < csr["nbr"].size  # there are parallel edges
    for r, c, w in zip(mat.row, mat.col, mat.data):
        assert w == pytest.approx(cheapest[(int(r), int(c))], abs=1e-9)
    pairs = [("Room 0", "Corridor"), ("Room 1", "Room 3"), ("Room 2", "Corridor"), ((3.0, 12.0), (39.0, 12.0)),
             ((1.0, 1.0), "Room 0")]
    table = [rm.route(a, b, robot_radius=0.3) for a, b in pairs]
    check_astar_matches_dijkstra(rm, 0.3)
    monkeypatch.setattr(routing, "MAX_TABLE_NODES", 0)
    rm2 = RouteMap.from_areas(areas, passages)
    astar = [rm2.route(a, b, robot_radius=0.3) for a, b in pairs]
    assert rm2._table(rm2.graph(0.3), 15.0, set()) is None
    for t, a in zip(table, astar):
        assert t.cost == pytest.approx(a.cost, abs=1e-9)
        assert t.length == pytest.approx(a.length, abs=1e-9)
    check_astar_matches_dijkstra(rm2, 0.3)
    # two floors, stairs avoided: a table per avoid set
    areas, passages = two_floors()
    monkeypatch.setattr(routing, "MAX_TABLE_NODES", 4000)
    rm3 = RouteMap.from_areas(areas, passages)
    wheel = rm3.route("Office 1", "Office 2", robot_radius=0.3, vertical_cost=10, avoid=["stairs"])
    walk = rm3.route("Office 1", "Office 2", robot_radius=0.3, vertical_cost=10)
    assert "Lift 1-2" in wheel.passages and "Stair 1-2" in walk.passages
    g3 = rm3.graph(0.3)  # a table per avoid set: the stairs-avoiding one on the graph whose stair openings are walls
    assert len(g3.tables) == 1 and len(g3.variants[("stairs",)].tables) == 1


def test_point_grid_locates_like_the_polygons():
    """Point location by the cell grid (cells wholly inside one piece) gives the piece the polygon test
    gives; where floors lie above one another no cell answers without a level."""
    import shapely

    from algorithms import routing

    areas, passages = two_floors()
    rm = RouteMap.from_areas(areas, passages)
    g = rm.prepare(0.3)
    rng = np.random.default_rng(11)
    hits = {None: 0, "1": 0}
    for lev in (None, "1"):
        x0, y0, h, lab, pcs = g.grids[lev]
        for _ in range(3000):
            x, y = rng.uniform(-1, 41), rng.uniform(-1, 9)
            r, c = int((y - y0) / h), int((x - x0) / h)
            if not (0 <= r < lab.shape[0] and 0 <= c < lab.shape[1]) or lab[r, c] < 0:
                continue
            k = lab[r, c]
            if k < 0:
                continue
            hits[lev] += 1
            inside = [pc for pc in g.pieces.values() if (lev is None or pc.level == lev)
                      and shapely.intersects_xy(pc.tol_poly, x, y)]
            assert inside == [pcs[k]] and pcs[k]._inside_xy(x, y)
    assert hits[None] == 0  # both floors cover every point: the level decides
    assert hits["1"] > 500
    with pytest.raises(InputError, match="give its level"):
        rm.route((20, 1.5), (11, 5), goal_level="2")
    res = rm.route((20, 1.5), (11, 5), start_level="1", goal_level="2")
    assert res.level_changes == 1
    assert routing._point_grid(g, "7") is None


def test_straight_segment_skips_the_search_and_prepare_changes_nothing():
    areas, passages = _hall_map()
    rm = RouteMap.from_areas(areas, passages)
    res = rm.route((1.0, 1.0), (39.0, 1.5), robot_radius=0.3)
    assert len(res.points) == 2 and res.length == pytest.approx(math.hypot(38, 0.5))
    assert res.passages == [] and res.expanded == 0
    rng = np.random.default_rng(5)
    pts = [tuple(rng.uniform((0.5, 0.5), (39.5, 13.5))) for _ in range(40)]
    pts = [p for p in pts if comb_hall().buffer(-0.35).contains(_pt(p))]
    before = [rm.route(pts[k], pts[k + 1], robot_radius=0.3).length for k in range(len(pts) - 1)]
    rm.prepare(0.3)
    assert rm.graph(0.3).pieces_by_area[0][0]._vp is not None
    after = [rm.route(pts[k], pts[k + 1], robot_radius=0.3).length for k in range(len(pts) - 1)]
    assert np.allclose(before, after, rtol=0, atol=1e-9)
    assert len(pts) > 20


def _pt(p):
    from shapely.geometry import Point

    return Point(p)


def test_bench_cross_building_on_a_small_fused_file(tmp_path):
    """The benchmark's fused-building row (scripts/bench_route.cross_building) on two synthetic floors written
    as one osmAG file: lift-only routes within 2 % of the best grid A* via the lift."""
    import importlib.util

    from algorithms.georef import LocalFrame
    from algorithms.osmag import write_osmag
    from tests.conftest import REPO

    spec = importlib.util.spec_from_file_location("bench_route", REPO / "scripts" / "bench_route.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    from algorithms.building import merge_floor_files

    areas, passages = two_floors()
    paths = []
    for lv in ("1", "2"):  # two floor files, fused as mergefloors does: vertical passages at the shafts
        fa = [a for a in areas if a.tags["level"] == lv]
        ids = {a.id for a in fa}
        fp = [p for p in passages if p.from_id in ids and p.to_id in ids]
        paths.append(str(tmp_path / f"two-F{lv}.osm"))
        write_osmag(paths[-1], fa, fp, frame=LocalFrame(121.59, 31.18), level=lv, variant="fix-id")
    path = tmp_path / "two.osm"
    merge_floor_files(paths, str(path), building_name="B")
    bench.ROUNDS = 2
    res = bench.cross_building(path, 4, np.random.default_rng(2), lambda m: None, "two floors")
    assert res["lifts"] == 1 and len(res["rows"]) == 4
    s = bench.stats(res["rows"])
    assert s["within"] == 4 and s["rel_min"] > -0.05  # never much shorter than the grid: not through walls
    assert s["q_cpu_best_med"] < 50
    # the speed-up is CPU over CPU: grid A* CPU / osmAG CPU best of the rounds, never below the first run's
    assert s["g_cpu_med"] > 0 and s["speed_best_med"] >= s["speed_cpu_med"] > 0
    assert "speed-up median, CPU" in bench.table([], [dict(res, label="two floors")])[0]
    # the stairs-avoiding graph (both corridors re-pieced) and a first query with it, timed on their own
    assert res["variant_areas"] == 2 and res["variant_cpu"] > 0 and res["first_avoid_cpu"] > 0
    assert "2 areas that share a passage with a stair area" in bench.variant_note(res)
    assert all("pair_call" not in r and "_call" not in r for r in res["rows"])


@pytest.mark.slow
def test_campus_map_fast_paths_give_the_reference_answers(shared_data, monkeypatch):
    """On the other tools' two-level campus map: the node table and A* with landmarks give the same costs,
    the visibility polygons of its large halls the same visibility as the segment test, and prepare()
    changes no route."""
    from algorithms import routing

    rm = RouteMap.from_osmag(str(shared_data / "osmag" / "fix_id_ShanghaiTech_merge_2.osm"))
    big = rm.components(0.3)[0]
    rng = np.random.default_rng(4)
    ks = [int(k) for k in rng.choice(big, 16, replace=False)]
    pairs = [(ks[i], ks[i + 1]) for i in range(0, 16, 2)]

    def routes(m):
        out = []
        for a, b in pairs:
            for av in ((), ("stairs",)):
                try:
                    out.append(m.route(m.area_point(a), m.area_point(b), m.levels[a], m.levels[b],
                                       robot_radius=0.3, avoid=av).cost)
                except RouteError:  # without stairs some parts of this map are cut off
                    out.append(math.inf)
        return out

    plain = routes(rm)
    assert sum(map(math.isfinite, plain)) >= 10
    g = rm.prepare(0.3)
    prepared = routes(rm)
    for x, y in zip(plain, prepared):
        assert x == pytest.approx(y, abs=1e-9)
    halls = [pc for pc in g.pieces.values() if pc._vp is not None]
    assert halls
    n = 0
    for pc in sorted(halls, key=lambda p: -len(p.V))[:3]:
        x0, y0, x1, y1 = pc.poly.bounds
        for x, y in zip(rng.uniform(x0, x1, 300), rng.uniform(y0, y1, 300)):
            if not pc._inside_xy(x, y):
                continue
            n += 1
            cand = np.arange(len(pc.V))
            exact = ~routing._crossing_from(x, y, pc.V[:, 0], pc.V[:, 1], pc.edges, pc.edge_parts)
            assert (pc.visible_vertices(x, y, cand) == exact).all()
    assert n > 100
    monkeypatch.setattr(routing, "MAX_TABLE_NODES", 0)
    rm2 = RouteMap.from_osmag(str(shared_data / "osmag" / "fix_id_ShanghaiTech_merge_2.osm"))
    for x, y in zip(plain, routes(rm2)):
        assert x == pytest.approx(y, abs=1e-6)


# --------------------------------------------------------------------------- crossing points pulled taut
def oblique_opening():
    """Two 10 x 20 rooms joined along x = 10 by a 20 m wide opening; a wall tongue hangs into the west
    room from the top (x 8..9, down to y = 7.55), another rises in the east room from the bottom (x 11..12,
    up to y = 10.05). From the top left to the bottom right the shortest path bends under the first
    tongue, crosses the opening obliquely between the two tongue corners (at y = 8.8, between the fixed
    crossing nodes at 7.5 and 10.0) and bends over the second tongue."""
    west = box(0, 0, 10, 20).difference(box(8, 7.55, 9, 20))
    east = box(10, 0, 20, 20).difference(box(11, 0, 12, 10.05))
    areas = [area(1, west, "West", atype="corridor"), area(2, east, "East", atype="corridor")]
    passages = [passage(10, 1, 2, (10, 0), (10, 20), "Opening")]
    s, t = (6, 18), (14, 1)
    exact = (math.hypot(2, 18 - 7.55) + 1 + math.hypot(2, 10.05 - 7.55) + 1 + math.hypot(2, 10.05 - 1))
    return areas, passages, s, t, exact


def test_oblique_crossing_of_a_wide_opening_is_the_analytic_shortest_path(monkeypatch):
    from algorithms import routing

    areas, passages, s, t, exact = oblique_opening()
    res = RouteMap.from_areas(areas, passages).route(s, t, robot_radius=0.0)  # walls grown by 1 cm only
    assert res.passages == ["Opening"] and res.areas == ["West", "East"]
    assert exact - 1e-6 <= res.length <= exact * 1.005
    k = int(np.argmin(np.abs(res.points[:, 0] - 10)))
    assert res.points[k, 0] == pytest.approx(10, abs=1e-6) and res.points[k, 1] == pytest.approx(8.8, abs=0.02)
    assert res.cost == pytest.approx(res.length, abs=1e-9) and res.graph_cost >= res.cost
    # with a robot radius: the path keeps r from the tongues (but for the 45 degree corner chords)
    r = 0.3
    res3 = RouteMap.from_areas(areas, passages).route(s, t, robot_radius=r)
    walls = areas[0].polygon.boundary.union(areas[1].polygon.boundary).difference(passages[0].line.buffer(1e-6))
    assert clearance_ok(res3.points, walls, r)
    assert res3.length <= res3.graph_cost - 0.2  # the nodes on the opening cost ~2 % here
    # the fixed crossing nodes alone (the rule switched off) bend at a node: ~1.8 % longer
    monkeypatch.setattr(routing, "PULL_CROSSINGS", False)
    fixed = RouteMap.from_areas(areas, passages).route(s, t, robot_radius=0.0)
    assert fixed.length > exact * 1.01
    assert fixed.length == pytest.approx(res.graph_cost, abs=1e-6)


def test_route_through_a_chain_of_wide_openings_is_the_straight_line():
    # a 20 x 20 hall cut into four strips by three 20 m wide openings: nothing blocks the straight line
    areas = [area(k + 1, box(5 * k, 0, 5 * k + 5, 20), f"S{k}", atype="corridor") for k in range(4)]
    passages = [passage(10 + k, k + 1, k + 2, (5 * k + 5, 0), (5 * k + 5, 20), f"O{k}") for k in range(3)]
    rm = RouteMap.from_areas(areas, passages)
    for s, t in (((1, 2), (19, 17.3)), ((1, 18), (19, 0.7)), ((4, 9), (16, 12))):
        res = rm.route(s, t, robot_radius=0.3)
        assert res.passages == ["O0", "O1", "O2"]
        straight = math.hypot(t[0] - s[0], t[1] - s[1])
        assert straight - 1e-9 <= res.length <= straight * 1.001
        assert res.graph_cost > res.length  # the fixed nodes alone bend


def test_compact_tables_give_the_same_routes(monkeypatch):
    """COMPACT_TABLES (float32 node and entry tables, int16 predecessors) picks on float32 sums but reports
    float64 costs: the same routes as the full-precision tables, on a hall map and two floors with stairs
    avoided, costs within 1e-9 m and the same passages and areas crossed; the tables are half the size."""
    from algorithms import routing

    cases = [(_hall_map(), [("Room 0", "Corridor"), ("Room 1", "Room 3"), ((3.0, 12.0), (39.0, 12.0)),
                            ((1.0, 1.0), "Room 0")], {}),
             (two_floors(), [("Office 1", "Office 2")], {"vertical_cost": 10, "avoid": ["stairs"]})]
    for (areas, passages), pairs, kw in cases:
        got = {}
        for compact in (False, True):
            monkeypatch.setattr(routing, "COMPACT_TABLES", compact)
            rm = RouteMap.from_areas(areas, passages)
            got[compact] = [rm.route(a, b, robot_radius=0.3, **kw) for a, b in pairs]
            av = rm._avoid_set(kw.get("avoid", ()))
            dist, pred, _ = rm._table(rm._avoid_variant(rm.graph(0.3), av), float(kw.get("vertical_cost", 15.0)), av)
            assert (dist.dtype, pred.dtype) == ((np.float32, np.int16) if compact else (np.float64, np.int32))
        for a, b in zip(got[False], got[True]):
            assert b.cost == pytest.approx(a.cost, abs=1e-9) and b.length == pytest.approx(a.length, abs=1e-9)
            assert (b.passages, b.areas) == (a.passages, a.areas)


# --------------------------------------------------------------------------- avoided areas: openings are walls
def _stair_off_a_hall(through_only=False):
    """A 20 x 10 hall with a stair box (x 8..12) opening onto it over its whole 4 m width at y = 10, and a
    block in the hall right under the opening (x 8.5..11.5, up to y 9.6): between the block and the opening
    the robot's disc (r 0.3) fits only by reaching into the opening's mouth. ``through_only``: the block
    reaches the hall's floor, so the mouth is the only way from west to east."""
    hall = box(0, 0, 20, 10).difference(box(8.5, 0 if through_only else 7, 11.5, 9.6))
    stair = box(8, 10, 12, 14)
    areas = [area(1, hall, "Hall", atype="corridor"), area(2, stair, "Stair", atype="stairs")]
    return areas, [passage(10, 2, 1, (8, 10), (12, 10), "S")], stair


def test_avoided_stairs_opening_is_a_wall_for_the_robot(monkeypatch):
    """AVOID=stairs: the passages into a stair area are walls for the robot's disc, so the route keeps r
    from the stair area (up to the 45 degree chords of the grown corners); without AVOID (or with the rule
    switched off) the same route cuts through the opening's mouth, closer than r to the stair."""
    from algorithms import routing

    areas, passages, stair = _stair_off_a_hall()
    r, s, t = 0.3, (5.0, 9.0), (15.0, 9.0)
    rm = RouteMap.from_areas(areas, passages)
    walk = rm.route(s, t, robot_radius=r)
    wheel = rm.route(s, t, robot_radius=r, avoid=["stairs"])
    assert LineString(walk.points).distance(stair) < 0.15  # through the mouth, above the block
    assert clearance_ok(wheel.points, stair, r)  # below the block: r from the stair area
    assert clearance_ok(wheel.points, areas[0].polygon.exterior, r)
    assert wheel.areas == ["Hall"] and wheel.passages == [] and wheel.length > walk.length + 1.0
    monkeypatch.setattr(routing, "AVOID_WALLS", False)
    old = RouteMap.from_areas(areas, passages).route(s, t, robot_radius=r, avoid=["stairs"])
    assert old.length == pytest.approx(walk.length, abs=1e-9)  # the limit this rule removes


def test_avoided_stairs_only_way_through_the_mouth_is_no_route():
    """When the only way between two points passes within r of the avoided stair area (here through its
    opening's mouth) or through the stair area itself, AVOID=stairs gives no route, and says why."""
    areas, passages, stair = _stair_off_a_hall(through_only=True)
    rm = RouteMap.from_areas(areas, passages)
    assert rm.route((5.0, 9.0), (15.0, 9.0), robot_radius=0.3).length > 10.0
    with pytest.raises(RouteError, match=r"too tight.*avoiding stairs, the robot keeps 0.30 m from those areas"):
        rm.route((5.0, 9.0), (15.0, 9.0), robot_radius=0.3, avoid=["stairs"])
    # a room reached only through the stair well
    areas, passages, _ = _stair_off_a_hall()
    areas.append(area(3, box(8, 14, 12, 18), "Loft"))
    passages.append(passage(11, 3, 2, (9, 14), (11, 14), "L"))
    rm = RouteMap.from_areas(areas, passages)
    assert "Stair" in rm.route((2.0, 2.0), "Loft", robot_radius=0.3).areas
    with pytest.raises(RouteError, match=r"avoiding stairs: the start \(area 'Hall'.*the goal \(area 'Loft'"):
        rm.route((2.0, 2.0), "Loft", robot_radius=0.3, avoid=["stairs"])


def test_avoid_variants_are_built_once_cached_and_leave_the_plain_graph_alone(monkeypatch):
    """The graph of an avoid set is built on its first query and reused (the second query builds nothing);
    at most MAX_VARIANTS are kept (least recently used dropped); queries without AVOID give the same bytes
    before and after, on a graph the variants did not touch (its pieces and edges shared, not changed)."""
    from algorithms import routing

    areas, passages = two_floors()
    areas.append(area(5, box(20, 3, 36, 8), "Office 1b", "1"))  # next to the lift, a door into it and one out
    passages += [passage(13, 5, 3, (36, 4), (36, 5.5), "LO"), passage(14, 5, 1, (25, 3), (26, 3), "OC")]
    rm = RouteMap.from_areas(areas, passages)
    plain = RouteMap.from_areas(areas, passages)
    pairs = [("Office 1", "Office 2", None), ((2.0, 1.5), (30.0, 1.0), "1"), ((1.0, 1.0), "Office 1", "1")]
    before = [rm.route(a, b, lv, lv, robot_radius=0.3, vertical_cost=10) for a, b, lv in pairs]
    g = rm.graph(0.3)
    adj = [list(x) for x in g.adj]
    entries = {k: list(pc.entries) for k, pc in g.pieces.items()}
    builds = []
    real = RouteMap._build_variant
    monkeypatch.setattr(RouteMap, "_build_variant", lambda self, g, av: builds.append(av) or real(self, g, av))
    w1 = rm.route("Office 1", "Office 2", robot_radius=0.3, vertical_cost=10, avoid=["stairs"])
    v = g.variants[("stairs",)]
    n_pieces = len(v.pieces)
    w2 = rm.route((2.0, 1.5), "Office 2", "1", robot_radius=0.3, vertical_cost=10, avoid=["stair"])
    assert builds == [("stairs",)] and g.variants[("stairs",)] is v and len(v.pieces) == n_pieces
    assert "Lift 1-2" in w1.passages and "Lift 1-2" in w2.passages
    # the corridors next to the stairs have new pieces, the offices and lifts share theirs
    k_corr, k_off = rm.index[1], rm.index[4]
    assert v.pieces_by_area[k_corr][0] is not g.pieces_by_area[k_corr][0]
    assert v.pieces_by_area[k_off][0] is g.pieces_by_area[k_off][0]
    assert v.build_s >= 0 and len(v.pos) == len(g.pos)
    rm.route("Office 1", "Office 1b", robot_radius=0.3, vertical_cost=10, avoid=["elevator"])
    rm.route("Office 1", "Office 1b", robot_radius=0.3, vertical_cost=10, avoid=["elevator", "stairs"])
    assert builds == [("stairs",), ("elevator",), ("elevator", "stairs")]
    k_1b = rm.index[5]  # next to the lift: re-pieced when lifts are avoided, shared when stairs are
    assert g.variants[("elevator",)].pieces_by_area[k_1b][0] is not g.pieces_by_area[k_1b][0]
    assert v.pieces_by_area[k_1b][0] is g.pieces_by_area[k_1b][0]
    assert list(g.variants) == [("elevator",), ("elevator", "stairs")]  # MAX_VARIANTS = 2: stairs dropped
    rm.route("Office 1", "Office 2", robot_radius=0.3, vertical_cost=10, avoid=["stairs"])
    assert len(builds) == 4 and list(g.variants) == [("elevator", "stairs"), ("stairs",)]
    after = [rm.route(a, b, lv, lv, robot_radius=0.3, vertical_cost=10) for a, b, lv in pairs]
    fresh = [plain.route(a, b, lv, lv, robot_radius=0.3, vertical_cost=10) for a, b, lv in pairs]
    for x, y, z in zip(before, after, fresh):
        assert x.points.tobytes() == y.points.tobytes() == z.points.tobytes()
        assert (x.cost, x.length, x.passages, x.areas) == (y.cost, y.length, y.passages, y.areas) \
            == (z.cost, z.length, z.passages, z.areas)
    assert [list(x) for x in g.adj] == adj and {k: pc.entries for k, pc in g.pieces.items()} == entries
    assert routing.MAX_VARIANTS == 2


def test_avoided_stairs_a_door_right_next_to_the_opening_is_crossed_r_away():
    """A room next to the stair box (their drawings overlap by 15 cm, as converted plans do), its door from
    the hall starting at the stair's corner: the door's crossing node at the jamb lies 15 cm from the stair
    area, so with AVOID=stairs the hall does not join it (the route crosses the door at its other node, r
    from the stair area); without AVOID both nodes are used."""
    areas, passages, stair = _stair_off_a_hall()
    stair = box(8, 10, 12.15, 14)
    areas[1] = area(2, stair, "Stair", atype="stairs")
    areas.append(area(3, box(12, 10, 16, 14), "Room"))
    passages.append(passage(11, 3, 1, (12, 10), (13.2, 10), "D"))
    rm = RouteMap.from_areas(areas, passages)
    g = rm.graph(0.3)
    door = [n for n in range(len(g.pos)) if g.passage[n] == 1]
    assert sorted(round(g.pos[n][0], 2) for n in door) == [12.3, 12.9]
    hall = {nd for pc in g.pieces_by_area[0] for nd, _, _ in pc.entries}
    v = rm._avoid_variant(g, {"stairs"})
    hall_v = {nd for pc in v.pieces_by_area[0] for nd, _, _ in pc.entries}
    assert set(door) <= hall and hall_v & set(door) == {n for n in door if g.pos[n][0] > 12.5}
    res = rm.route((14.0, 11.0), (5.0, 5.0), robot_radius=0.3, avoid=["stairs"])
    assert res.passages == ["D"] and clearance_ok(res.points, stair, 0.3)
