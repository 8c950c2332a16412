"""Stairs and lifts as areas of their own (``algorithms/anchors.py``): a stair or lift the drawing shows
inside a larger area is carved out of it, typed, with passages where it stays open (issue 9)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from shapely.geometry import LineString, box
from shapely.ops import unary_union

from algorithms import anchors
from algorithms.model import Area, CadGeometry, Passage


def _line(p, q, kind="stair", layer="A-STAIR"):
    return CadGeometry(layer=layer, kind=kind, coords=np.array([p, q], float))


def _flight(x0, y0, width=1.2, n=12, going=0.28, kind="stair"):
    """Treads of a straight flight climbing north from (x0, y0)."""
    return [_line((x0, y0 + k * going), (x0 + width, y0 + k * going), kind) for k in range(n + 1)]


def _cross(x0, y0, x1, y1, kind="elevator"):
    return [_line((x0, y0), (x1, y1), kind, "A-LIFT"), _line((x0, y1), (x1, y0), kind, "A-LIFT")]


def _graph_ok(areas, passages):
    ids = {a.id for a in areas}
    assert len(ids) == len(areas)
    for a in areas:
        assert a.polygon.geom_type == "Polygon" and a.polygon.is_valid and not a.polygon.interiors, a
    for p in passages:
        assert p.from_id in ids and p.to_id in ids and p.from_id != p.to_id
        assert len(p.line.coords) == 2 and p.line.length > 0
    # areas never overlap
    for i, a in enumerate(areas):
        for b in areas[i + 1:]:
            assert a.polygon.intersection(b.polygon).area < 1e-6, (a.id, b.id)


def test_stair_core_open_onto_a_corridor_is_carved_and_the_corridor_stays():
    """A 3 x 6 m stair core (walls on three sides) whose open side runs straight into a 2 m corridor: one
    area. The flight and its landing up to the three walls become a stairs area; the corridor keeps its id,
    its door and loses its 'stairs' type; one passage joins them across the core's open side."""
    core_and_corridor = unary_union([box(0, 0, 3, 6), box(-10, 6, 13, 8)])
    host = Area(id=1, polygon=core_and_corridor, type="stairs", name="")  # typed by the symbol density
    room = Area(id=2, polygon=box(4, 0, 8, 5.8))
    door = Passage(id=1, from_id=2, to_id=1, line=LineString([(5, 5.9), (6, 5.9)]))
    geoms = _flight(0.2, 1.0, width=1.2, n=12) + _flight(1.6, 1.0, width=1.2, n=12)
    areas, passages = [host, room], [door]
    st = anchors.carve_anchors(areas, passages, geoms)
    _graph_ok(areas, passages)
    assert len(st["carved"]) == 1
    stair = [a for a in areas if a.type == "stairs"]
    assert len(stair) == 1
    s = stair[0].polygon
    # the whole core (to the walls on three sides), not the corridor
    assert s.area == pytest.approx(18.0, rel=0.08), s.bounds
    assert s.bounds[3] <= 6.0 + 1e-6
    assert host.type == "room" and host.polygon.area == pytest.approx(46.0, rel=0.05)
    sp = [p for p in passages if {p.from_id, p.to_id} == {stair[0].id, 1}]
    assert len(sp) == 1 and sp[0].line.length == pytest.approx(3.0, abs=0.1)  # the core's open side at y = 6
    assert door.to_id == 1  # the office door stays on the corridor


def test_open_stair_in_an_atrium_becomes_an_island_area_with_passages_at_both_ends():
    """A free-standing flight in a 20 x 14 m atrium: the stair (its treads' box) becomes a stairs area, the
    atrium goes round it as one area (one ring, opened by a 1 cm slit to its outer border: an area is one
    ring; until session 7 it was cut from wall to wall into two), and the stair's passages lie across its
    first and last tread (never over its strings). More in tests/test_anchors_free_flights.py."""
    hall = Area(id=7, polygon=box(0, 0, 20, 14), type="room")
    geoms = _flight(9.3, 4.0, width=1.4, n=12)
    areas, passages = [hall], []
    st = anchors.carve_anchors(areas, passages, geoms)
    _graph_ok(areas, passages)
    assert [c[0] for c in st["carved"]] == ["stairs"]
    stair = [a for a in areas if a.type == "stairs"][0]
    assert stair.polygon.area == pytest.approx(1.4 * 12 * 0.28, rel=0.1)
    assert sum(a.polygon.area for a in areas) == pytest.approx(280.0, abs=0.1)  # nothing lost but the slit
    sp = [p for p in passages if stair.id in (p.from_id, p.to_id)]
    assert sp
    for p in sp:  # every stair passage is parallel to the treads (horizontal) at y = 4.0 or 7.36
        (x0, y0), (x1, y1) = p.line.coords
        assert abs(y1 - y0) < 1e-6 and min(abs(y0 - 4.0), abs(y0 - 7.36)) < 0.02
    assert {round(p.line.coords[0][1], 1) for p in sp} == {4.0, 7.4}
    # the atrium stays one area, joined to the stair at both ends
    assert [a.id for a in areas if a.id != stair.id] == [7] and len(sp) == 2 and st["islands"] == [7]


def test_lift_open_onto_a_corridor_is_carved_and_a_cross_in_a_hall_is_not():
    """A 2.2 x 2.2 m shaft (walls on three sides) opens straight onto a corridor: its car with a cross
    becomes an elevator area with a passage onto the corridor. A cross drawn in the middle of a hall (a
    floor void) has no walls around it: no lift."""
    corridor = Area(id=1, polygon=unary_union([box(0, 0, 30, 2.4), box(12, 2.4, 14.2, 4.6)]), type="corridor")
    hall = Area(id=2, polygon=box(0, 10, 20, 24), type="room")
    geoms = _cross(12.15, 2.65, 14.05, 4.45) + _cross(9, 16, 11, 18)
    areas, passages = [corridor, hall], []
    st = anchors.carve_anchors(areas, passages, geoms)
    _graph_ok(areas, passages)
    lifts = [a for a in areas if a.type == "elevator"]
    assert len(lifts) == 1 and lifts[0].polygon.intersection(box(12, 2.4, 14.2, 4.6)).area >= 0.8 * 2.2 * 2.2
    assert lifts[0].polygon.area <= 2.2 * 2.2 + 1e-6
    assert hall.polygon.area == pytest.approx(280.0) and hall.type == "room"
    assert st["skipped"].get("no walls around a lift cross") == 1
    lp = [p for p in passages if lifts[0].id in (p.from_id, p.to_id)]
    assert len(lp) == 1 and lp[0].line.length == pytest.approx(2.2, abs=0.3)
    assert corridor.type == "corridor"


def test_a_stair_that_is_its_own_area_is_left_alone_and_a_hall_is_never_carved_into_a_stair():
    """An enclosed stair core already typed stairs, a lift shaft already typed elevator: nothing changes. A
    small room that is mostly a stair is typed stairs, not carved. A large hall holding a flight keeps all
    but the flight's footprint."""
    core = Area(id=1, polygon=box(0, 0, 3, 6), type="stairs")
    shaft = Area(id=2, polygon=box(5, 0, 7.2, 2.2), type="elevator")
    closet = Area(id=3, polygon=box(10, 0, 12, 4.2), type="room")
    hall = Area(id=4, polygon=box(20, 0, 60, 30), type="room")
    geoms = _flight(0.2, 1.0, n=12) + _cross(5.2, 0.2, 7.0, 2.0) + _flight(10.2, 0.4, width=1.6, n=12)
    geoms += _flight(40, 10, width=1.5, n=14)
    areas, passages = [core, shaft, closet, hall], []
    before = {a.id: (a.type, a.polygon.wkt) for a in areas}
    st = anchors.carve_anchors(areas, passages, geoms)
    _graph_ok(areas, passages)
    for aid in (1, 2):
        assert (areas[aid - 1].type, areas[aid - 1].polygon.wkt) == before[aid]
    assert st["skipped"].get("already its own area") == 2
    assert closet.type == "stairs" and closet.polygon.wkt == before[3][1] and ("stairs", 3) in st["typed"]
    carved = [c for c in st["carved"] if c[2] == 4]
    assert len(carved) == 1 and carved[0][3] <= 1.5 * 15 * 0.28 * 1.15  # the flight, not the hall
    # nothing lost but the 1 cm slit by which the hall goes round the free-standing flight (anchors.SLIT)
    assert sum(a.polygon.area for a in areas if a.id not in (1, 2, 3)) == pytest.approx(1200.0, abs=0.2)


def test_no_symbols_no_change_and_cancel_is_honoured():
    from algorithms.errors import Canceled
    from algorithms.progress import RecordingProgress

    hall = Area(id=1, polygon=box(0, 0, 10, 10))
    st = anchors.carve_anchors([hall], [], [])
    assert st["carved"] == [] and st["symbols"] == 0

    class Cancelled(RecordingProgress):
        def is_canceled(self):
            return True

    with pytest.raises(Canceled):
        anchors.carve_anchors([hall], [], _flight(2, 2), progress=Cancelled())


@pytest.fixture(scope="module")
def open_anchors(tmp_path_factory):
    from algorithms import pipeline, sample_building

    info = sample_building.generate_open_anchors(str(tmp_path_factory.mktemp("open-anchors")))
    return info, pipeline.process_floor(info["dxf"], carve=False), pipeline.process_floor(info["dxf"])


def test_sample_open_stair_and_open_lift_become_typed_areas_with_passages(open_anchors):
    """The synthetic plan (``sample_building.generate_open_anchors``): segmentation alone swallows the
    open stair into the atrium and the door-less lift into the corridor; with the carve each is one typed
    area, joined to the floor by passages, and every room keeps its name."""
    info, plain, floor = open_anchors
    assert not [a for a in plain.refined.areas if a.type in ("stairs", "elevator")]  # what the rule fixes
    areas, passages = floor.refined.areas, floor.refined.passages
    stairs = [a for a in areas if a.type == "stairs"]
    lifts = [a for a in areas if a.type == "elevator"]
    assert len(stairs) == 1 and len(lifts) == 1
    gt_s, gt_l = info["stair"], info["lift"]
    assert stairs[0].polygon.intersection(gt_s).area >= 0.9 * gt_s.area
    assert stairs[0].polygon.area <= 1.25 * gt_s.area
    assert lifts[0].polygon.intersection(gt_l).area >= 0.7 * gt_l.area
    assert lifts[0].polygon.area <= 1.1 * gt_l.area
    by_id = {a.id: a for a in areas}
    s_pass = [p for p in passages if stairs[0].id in (p.from_id, p.to_id)]
    l_pass = [p for p in passages if lifts[0].id in (p.from_id, p.to_id)]
    assert len(s_pass) >= 2 and len(l_pass) == 1
    other = l_pass[0].to_id if l_pass[0].from_id == lifts[0].id else l_pass[0].from_id
    assert by_id[other].name == "CORRIDOIO" and by_id[other].type == "corridor"
    names = {a.name for a in areas}
    assert {"ATRIO", "CORRIDOIO", "UFFICIO EST", "UFFICIO NORD 1", "UFFICIO NORD 2"} <= names
    # one connected floor
    adj = {a.id: set() for a in areas}
    for p in passages:
        adj[p.from_id].add(p.to_id)
        adj[p.to_id].add(p.from_id)
    seen, todo = set(), [areas[0].id]
    while todo:
        k = todo.pop()
        if k not in seen:
            seen.add(k)
            todo.extend(adj[k] - seen)
    assert seen == set(adj)
    # and the label raster shows them (preview, later raster stages)
    lab = floor.refined.labels
    assert (lab == stairs[0].id).sum() * floor.grid.resolution ** 2 == pytest.approx(stairs[0].polygon.area, rel=0.2)


def test_carved_passages_are_nodes_of_both_areas_in_the_osmag_file(open_anchors, tmp_path):
    """The osmAG writer makes each passage end a node of both areas' ways: the carved passages' ends lie on
    both borders (no 'not on the border' warning), and the file reads back with every area and passage."""
    from algorithms import osmag
    from algorithms.georef import LocalFrame
    from algorithms.progress import RecordingProgress

    _info, _plain, floor = open_anchors
    rec = RecordingProgress()
    out = tmp_path / "open-anchors.osm"
    osmag.write_osmag(str(out), floor.refined.areas, floor.refined.passages, frame=LocalFrame(0.0, 0.0), level="1",
                      variant="fix-id", progress=rec)
    assert not [m for k, m in rec.messages if "not on the border" in m]
    areas, passages, _root, rep = osmag.read_osmag(str(out))
    assert sum(a.type != "structure" for a in areas) == len(floor.refined.areas)
    assert len(passages) == len(floor.refined.passages) and rep["dangling_refs"] == []
    assert sorted(a.type for a in areas if a.type in ("stairs", "elevator")) == ["elevator", "stairs"]


@pytest.mark.qgis_process
def test_dxftoosmag_headless_carves_the_open_stair_and_lift(tmp_path):
    """``cad2osmag:dxftoosmag`` through qgis_process on the open-anchors sample: the osmAG file holds one
    stairs and one elevator area, each joined by passages, and the log says what was carved."""
    from algorithms import osmag, sample_building

    from .qgis_process import run_alg

    info = sample_building.generate_open_anchors(str(tmp_path))
    out = tmp_path / "open-anchors.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": info["dxf"], "OUTPUT": str(out), "LEVEL": 1})
    assert "stair/lift area(s) carved out" in log
    areas, passages, _root, report = osmag.read_osmag(str(out))
    typed = [a for a in areas if a.type in ("stairs", "elevator")]
    assert sorted(a.type for a in typed) == ["elevator", "stairs"]
    for a in typed:
        assert any(a.id in (p.from_id, p.to_id) for p in passages), a.name
    assert report["dangling_refs"] == [] and res["AREA_COUNT"] == len(areas) - 1


def test_a_stair_core_typed_elevator_by_its_break_line_cross_is_a_stair():
    """A 3 x 7 m stair core whose flight is cut by a break line drawn as a cross (SIST-F4 E1-ST-02: the
    symbol typing read the cross as a lift car and typed the core elevator, so the core's detail callout
    named the next stair): the core holds a stair run and no lift car of its own, so it is a stair. A lift
    shaft with a car cross and no treads stays a lift; a lift beside a stair keeps its type."""
    core = Area(id=1, polygon=box(0, 0, 3, 7), type="elevator")
    shaft = Area(id=2, polygon=box(5, 0, 7.2, 2.2), type="elevator")
    flight = _flight(0.3, 1.0, width=1.2, n=14)
    geoms = flight + _cross(0.3, 2.6, 1.5, 3.4) + _cross(5.2, 0.2, 7.0, 2.0)
    st = anchors.carve_anchors([core, shaft], [], geoms)
    assert st["retyped"] == [1] and core.type == "stairs" and shaft.type == "elevator"
    assert not st["carved"]  # the core is its own area: only retyped
    # the same core with a real lift car beside the flight inside it: not retyped
    both = Area(id=3, polygon=box(0, 0, 6, 7), type="elevator")
    st = anchors.carve_anchors([both], [], flight + _cross(3.8, 0.5, 5.6, 2.3))
    assert st["retyped"] == []


def test_a_named_stair_outside_every_area_becomes_a_stair_of_its_own():
    """An outdoor fire-escape stair along the facade (SIST-F4 E1-ST-07: its treads stand beyond the glazing,
    its detail callout beside it): a stairs area of its own, named by its code; the same flight with no
    stair name near it (entrance steps, a detail view's stair) is left out; a flight touching an area (its
    landing) is joined to it by a passage."""
    from algorithms.model import CadText
    from algorithms import semantics

    hall = Area(id=1, polygon=box(0, 0, 10, 10))
    flight = _flight(11.0, 2.0, width=1.4, n=12)
    callout = CadText(x=14.0, y=4.0, text="E1-ST-07详见建施(A-E-40-07)", height=0.35, rotation=0.0, layer="A-TEXT")
    areas, passages = [hall], []
    st = anchors.carve_anchors(areas, passages, flight)
    assert st.get("outdoor") is None and len(areas) == 1  # no texts given: nothing
    st = anchors.carve_anchors(areas, passages, flight,
                               texts=[CadText(x=30, y=4, text="E1-ST-07", height=0.35, rotation=0.0, layer="A")])
    assert st["outdoor"] == [] and len(areas) == 1  # the code 16 m away names another stair
    st = anchors.carve_anchors(areas, passages, flight, texts=[callout])
    _graph_ok(areas, passages)
    assert len(st["outdoor"]) == 1 and not passages
    stair = areas[-1]
    assert stair.type == "stairs" and stair.polygon.area == pytest.approx(1.4 * 12 * 0.28, rel=0.1)
    semantics.assign_names(areas, [], hidden_texts=[callout])
    assert (stair.ref, stair.type) == ("E1-ST-07", "stairs")
    # a flight standing against the hall's border: a passage across the common border
    hall = Area(id=1, polygon=box(0, 0, 10, 10))
    areas, passages = [hall], []
    st = anchors.carve_anchors(areas, passages, _flight(10.0, 2.0, width=1.4, n=12, going=0.28), texts=[callout])
    # treads from x = 10 (the hall's wall) to 11.4: the box touches the hall along its whole height
    assert len(st["outdoor"]) == 1 and len(passages) >= 1
    assert all({p.from_id, p.to_id} == {1, st["outdoor"][0]} for p in passages)


@pytest.mark.qgis_process
def test_dxftoosmag_headless_makes_a_named_outdoor_stair_an_area(tmp_path):
    """``cad2osmag:dxftoosmag`` through qgis_process on the open-anchors sample with an outdoor flight added
    1.5 m beyond its east wall and its code 'E1-ST-07' written beside it: the osmAG file holds a stairs area
    with that ref, and the log says it was drawn outside every area."""
    import ezdxf
    from shapely.ops import unary_union as union

    from algorithms import osmag, sample_building

    from .qgis_process import run_alg

    info = sample_building.generate_open_anchors(str(tmp_path))
    x0, y0, x1, y1 = union(list(info["rooms"].values())).bounds
    doc = ezdxf.readfile(info["dxf"])
    msp = doc.modelspace()
    fx = x1 + 1.5
    for k in range(13):
        msp.add_line((fx, y0 + 1 + 0.28 * k), (fx + 1.2, y0 + 1 + 0.28 * k), dxfattribs={"layer": "A-STAIR"})
    msp.add_text("E1-ST-07", height=0.3, dxfattribs={"layer": "A-ANNO-TEXT"}).set_placement((fx + 2.5, y0 + 2.5))
    src = tmp_path / "outdoor-stair.dxf"
    doc.saveas(str(src))
    out = tmp_path / "outdoor-stair.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": str(src), "OUTPUT": str(out), "LEVEL": 1})
    assert "drawn outside every area (outdoor)" in log
    areas, _passages, _root, report = osmag.read_osmag(str(out))
    outdoor = [a for a in areas if a.type == "stairs" and "E1-ST-07" in (a.tags.get("ref", ""), a.name)]
    assert len(outdoor) == 1 and len(outdoor[0].polygon.exterior.coords) >= 5  # (read back in lon/lat)
    assert report["dangling_refs"] == [] and res["AREA_COUNT"] == len(areas) - 1


def _shaft_and_corridor(stubs=True):
    """A 3.2 x 2.5 m box of walls (an empty lift shaft: no car cross) south of a 13 x 2.3 m corridor, open onto
    it through a 1.4 m doorless gap in its 0.2 m front wall (or full width): one area, as segmentation merges it."""
    parts = [box(0, 0, 3.2, 2.5), box(-5, 2.7, 8, 5)]
    parts.append(box(1.0, 2.5, 2.4, 2.7) if stubs else box(0, 2.5, 3.2, 2.7))
    return Area(id=1, polygon=unary_union(parts), type="corridor", name="")


def _code(text, x, y):
    from algorithms.model import CadText

    return CadText(x=x, y=y, text=text, height=0.35, rotation=0.0, layer="A-TEXT")


def test_a_lift_code_names_an_empty_walled_box_merged_into_the_corridor_it_opens_onto():
    """SIST-F4's E1-P2: the shaft is an empty box of walls opening through a doorless gap onto the corridor,
    and its callout hangs 6 m away. A lift code with no lift within CALLOUT_REACH names the nearest lift-sized
    box the area's border closes on three sides with a front wall's stubs on the fourth: carved as an
    elevator area, a passage on the gap's chord; the corridor keeps its id and type."""
    host = _shaft_and_corridor()
    areas, passages = [host], []
    st = anchors.carve_anchors(areas, passages, [], texts=[_code("E1-P2详见建施(A-E-40-19)", -3.0, 4.0)])
    _graph_ok(areas, passages)
    lift = [a for a in areas if a.type == "elevator"]
    assert len(lift) == 1 and st.get("recesses") == [lift[0].id]
    assert lift[0].polygon.area == pytest.approx(3.2 * 2.5, rel=0.05), lift[0].polygon.bounds
    assert lift[0].polygon.bounds[3] <= 2.7 + 1e-6
    assert host.type == "corridor" and host.polygon.area == pytest.approx(13 * 2.3 + 0.28, rel=0.05)
    chord = [p for p in passages if {p.from_id, p.to_id} == {lift[0].id, 1}]
    assert len(chord) == 1 and chord[0].line.length == pytest.approx(1.4, abs=0.1)


def test_no_lift_recess_without_code_with_a_lift_in_reach_or_with_a_full_width_niche():
    """The rule needs all three: a lift code (a room name is no evidence), no lift already within reach of
    it, and a walled box with front-wall stubs (a full-width niche is any corridor's door recess or end)."""
    for host, extra, texts in (
            (_shaft_and_corridor(), [], [_code("OFFICE", -3.0, 4.0)]),
            (_shaft_and_corridor(), [Area(id=2, polygon=box(-5, 5.2, -3, 7.5), type="elevator")],
             [_code("E1-P2", -3.0, 4.0)]),
            (_shaft_and_corridor(stubs=False), [], [_code("E1-P2", -3.0, 4.0)]),
            (_shaft_and_corridor(), [], [_code("E1-P2", -12.0, 4.0)])):  # the code beyond CALLOUT_REACH
        areas, passages = [host] + extra, []
        before = host.polygon.area
        anchors.carve_anchors(areas, passages, [], texts=texts)
        assert len(areas) == 1 + len(extra) and not passages and host.polygon.area == pytest.approx(before)


def test_a_lift_code_written_inside_an_empty_box_names_it_beside_another_lift():
    """SIST-F5's E1-P1 (无障碍货梯) beside E1-S1 (货梯): two shafts side by side; the neighbour is a lift area
    already, within CALLOUT_REACH of the code, and this shaft, an empty box of walls with a wheelchair sign
    drawn in it (an island of the area), opens through its door gap onto the lobby and is merged into it. A
    copy of the code written inside the box names the box: carved as an elevator area; the sign is no wall.
    Written in the lobby instead, or in a full-width niche, the code leaves the areas as they are."""
    for where, stubs, carved in (((1.6, 1.9), True, True), ((-3.0, 4.0), True, False), ((1.6, 1.9), False, False)):
        host = _shaft_and_corridor(stubs)
        host.polygon = host.polygon.difference(box(1.3, 0.8, 1.9, 1.4))  # the sign: a 0.36 m² island
        neighbour = Area(id=2, polygon=box(-3.4, 0.0, -0.2, 2.5), type="elevator", name="货梯")
        areas, passages = [host, neighbour], []
        st = anchors.carve_anchors(areas, passages, [], texts=[_code("E1-P1", *where), _code("货梯", -1.8, 1.2)])
        lift = [a for a in areas if a.type == "elevator" and a.id != 2]
        if not carved:
            assert not lift and not passages, (where, stubs)
            continue
        assert len(lift) == 1 and st.get("recesses") == [lift[0].id]
        chord = [p for p in passages if {p.from_id, p.to_id} == {lift[0].id, 1}]
        assert len(chord) == 1 and chord[0].line.length == pytest.approx(1.4, abs=0.1)
        assert lift[0].polygon.area == pytest.approx(3.2 * 2.5, rel=0.1) and lift[0].polygon.bounds[3] <= 2.7 + 1e-6
        assert host.type == "corridor" and host.polygon.area == pytest.approx(13 * 2.3 + 0.28, rel=0.05)
        assert neighbour.polygon.area == pytest.approx(3.2 * 2.5)


@pytest.mark.qgis_process
def test_dxftoosmag_headless_carves_an_empty_lift_shaft_named_by_its_code(tmp_path):
    """``cad2osmag:dxftoosmag`` through qgis_process on a small drawing: a corridor with an empty 3.2 x 2.5 m
    box of walls (no car cross) opening onto it through a 1.4 m doorless gap, and the code 'E1-P2' written
    in the corridor 3 m away. Without the rule the box is part of the corridor (one area, measured); with it
    the osmAG file holds an elevator area with ref E1-P2 and a passage to the corridor."""
    import ezdxf

    from algorithms import osmag

    from .qgis_process import run_alg

    doc = ezdxf.new(units=6)
    msp = doc.modelspace()
    walls = _shaft_and_corridor().polygon.exterior.buffer(0.1, join_style=2)
    for ring in [walls.exterior] + list(walls.interiors):
        msp.add_lwpolyline(list(ring.coords), close=True, dxfattribs={"layer": "A-WALL"})
    msp.add_text("E1-P2", height=0.3, dxfattribs={"layer": "A-ANNO-TEXT"}).set_placement((-3, 4))
    src, out = tmp_path / "shaft.dxf", tmp_path / "shaft.osm"
    doc.saveas(str(src))
    _, res, log = run_alg("dxftoosmag", {"INPUT": str(src), "OUTPUT": str(out), "LEVEL": 1})
    assert "carved out of the areas that swallowed them" in log
    areas, passages, _root, report = osmag.read_osmag(str(out))
    lift = [a for a in areas if a.type == "elevator"]
    assert len(lift) == 1 and "E1-P2" in (lift[0].tags.get("ref", ""), lift[0].name)
    assert len(passages) == 1 and report["dangling_refs"] == [] and res["AREA_COUNT"] == len(areas) - 1


def _bridge_and_dog_leg():
    """A link corridor (10 m wide) whose outline runs diagonally through a dog-leg stair at its edge (the
    plan's envelope, not a wall: SIST-F3's E2-ST-02 on the bridge 连廊): two 1.4 m flights side by side, 37 %
    of their box inside the corridor, the rest beyond every area."""
    from shapely.geometry import Polygon

    corridor = Area(id=1, polygon=Polygon([(0, 0), (10, 0), (10, 2.6), (0, 5.6)]), type="corridor", name="")
    geoms = _flight(3.0, 3.0, width=1.4, n=12) + _flight(4.6, 3.0, width=1.4, n=12)
    return corridor, geoms


def test_a_stair_the_plan_outline_cuts_through_is_carved_whole():
    """A stair with 30 % or more of it in one area and the rest beyond every area is carved whole: the
    stairs area holds both flights (also their part beyond the corridor's old outline), the corridor keeps its
    id, its type and everything but the stair, and a passage joins them across the first treads (parallel to
    the treads, at y = 3). The same stair with its part beyond lying in another area (a stair drawn across
    two areas), with under 30 % of it inside, or a lift cross across the outline: not carved."""
    corridor, geoms = _bridge_and_dog_leg()
    old = corridor.polygon
    areas, passages = [corridor], []
    st = anchors.carve_anchors(areas, passages, geoms)
    _graph_ok(areas, passages)
    stair = [a for a in areas if a.type == "stairs"]
    assert len(stair) == 1 and st["beyond"] == [stair[0].id] and len(st["carved"]) == 1
    flights = box(3.0, 3.0, 6.0, 3.0 + 12 * 0.28)
    assert stair[0].polygon.intersection(flights).area >= 0.97 * flights.area  # whole, not the 37 % inside
    assert stair[0].polygon.area <= 1.05 * flights.area
    assert (corridor.id, corridor.type) == (1, "corridor")
    assert corridor.polygon.area == pytest.approx(old.area - old.intersection(flights).area, rel=1e-3)  # 41 - 3.75 m²
    sp = [p for p in passages if {p.from_id, p.to_id} == {1, stair[0].id}]
    assert sp and all(abs(p.line.coords[0][1] - 3.0) < 0.02 and abs(p.line.coords[1][1] - 3.0) < 0.02 for p in sp)
    assert sum(p.line.length for p in sp) == pytest.approx(3.0, abs=0.1)
    # part of the rest lies in another area (a room west of the stair, 18 % of it): a symbol across two areas
    corridor, geoms = _bridge_and_dog_leg()
    terrace = Area(id=2, polygon=box(0, 0, 4, 10).difference(corridor.polygon), type="room")
    areas = [corridor, terrace]
    st = anchors.carve_anchors(areas, [], geoms)
    assert len(areas) == 2 and st["skipped"] == {"symbol across areas": 1} and "beyond" not in st
    # under 30 % inside: the stair belongs to no area
    from shapely.geometry import Polygon

    low = Area(id=1, polygon=Polygon([(0, 0), (10, 0), (10, 2.0), (0, 5.0)]), type="corridor")
    st = anchors.carve_anchors([low], [], geoms)
    assert st["skipped"] == {"symbol across areas": 1}
    # a lift's car across the outline: never (a lift needs its shaft walls)
    corridor, _ = _bridge_and_dog_leg()
    st = anchors.carve_anchors([corridor], [], _cross(3.0, 3.5, 5.0, 5.5))
    assert not st["carved"] and "beyond" not in st


def test_a_door_the_cut_runs_through_is_laid_on_the_borders_it_lies_on():
    """A door (3 m) on the border between a hall and a room, whose hall side a carve (or a name split) cut
    into two pieces at x = 5 and which followed one piece: its end lay 2 m off that piece's ring, and the
    osmAG writer could not share its node (SIST-F1 L1-P036, F4 L4-P052, library L3-P025). Refit: one
    passage per piece along the border it shares with the room; a door on a hole's ring and a door whose
    ends are on both rings are left alone."""
    from shapely.geometry import Point

    left, right = Area(id=1, polygon=box(0, 0, 5, 5)), Area(id=2, polygon=box(5, 0, 10, 5))
    room = Area(id=3, polygon=box(0, 5, 10, 9))
    court = Area(id=4, polygon=box(20, 0, 30, 10).difference(box(24, 4, 26, 6)))
    island = Area(id=5, polygon=box(24, 4, 26, 6))
    door = Passage(id=7, from_id=1, to_id=3, line=LineString([(4.0, 5.0), (7.0, 5.0)]), name="D1",
                   tags={"door": "yes"})
    good = Passage(id=8, from_id=2, to_id=3, line=LineString([(8.0, 5.0), (9.5, 5.0)]))
    hole = Passage(id=9, from_id=4, to_id=5, line=LineString([(24.5, 4.0), (25.5, 4.0)]))
    areas, passages = [left, right, room, court, island], [door, good, hole]
    keep = {p.id: p.line.wkt for p in (good, hole)}
    done = anchors.refit_passage_ends(areas, passages, {1, 2, 4})
    assert done[0] == 7 and len(passages) == 4
    assert (door.from_id, door.to_id, door.name) == (1, 3, "D1")
    assert sorted(door.line.bounds) == sorted((4.0, 5.0, 5.0, 5.0))
    new = passages[-1]
    assert (new.from_id, new.to_id, new.tags) == (2, 3, {"door": "yes"}) and new.id == done[1]
    assert new.line.length == pytest.approx(2.0) and new.line.distance(Point(6.0, 5.0)) < 1e-9
    assert {p.id: p.line.wkt for p in (good, hole)} == keep
    by = {a.id: a for a in areas}
    for p in passages:  # every end on both of its areas' rings
        for aid in (p.from_id, p.to_id):
            assert all(by[aid].polygon.boundary.distance(Point(c)) < 1e-9 for c in p.line.coords), (p.id, aid)
