"""A named closet as wide as its door (issue 9; SIST-F5's 弱电间, A-A3-10-04's 弱电 closet).

Duct, shaft and storage closets (强电间 / 弱电间 / 管井) are often no wider than their door: the clearance map has
no narrowing at the mouth, so segmentation keeps the closet in the hall, corridor or roof outside it and the
closet's label names that space. ``semantics._split_at_doors``: a door hint (the import's doorways) whose jambs
lie on the area's outline and whose line cuts off a dead-end part holding a room name (none or another name in
the rest) splits the area at the door; the part is its own area, joined by a passage on the door line.

Second kind, same file: a lift car block drawn on a stair layer (A-A3-10-04's lift A3-T3: block ``kt1``, 客梯 1, on
layer ``A3-RI-3F$0$an-stairs``) typed its shaft stairs; ``area_types._lift_cars_on_stair_layers`` makes a
lift-sized stairs area with no run of treads whose stair lines are mostly a lift-named block (or that holds a
lift cross) an elevator.
Each test builds the small drawing the rule is about."""
import ezdxf
import pytest
from shapely.geometry import LineString, Point, box
from shapely.ops import unary_union

from algorithms import pipeline, semantics
from algorithms.model import Area, CadText, DoorHint, Passage

# a 10 x 8 m hall; a 1.2 x 5 m closet on its top wall, open over its whole width (x 4.0-5.2, y 8)
HALL = box(0, 0, 10, 8)
CLOSET = box(4.0, 8.0, 5.2, 13.0)
DOOR = DoorHint(4.0, 8.0, 5.2, 8.0, source="swing")


def _text(s, x, y, layer="A-ANNO-ROOM", k=0):
    return CadText(x=x, y=y, text=s, height=0.3, rotation=0.0, layer=layer, id=k)


def _name(areas, texts, hints=(DOOR,), passages=None):
    passages = [] if passages is None else passages
    rep = semantics.assign_names(areas, texts, "1", passages=passages, door_hints=list(hints))
    return rep, passages


def _one_area():
    return [Area(id=1, polygon=unary_union([HALL, CLOSET]).buffer(0))]


def test_a_named_closet_as_wide_as_its_door_is_split_off_at_the_door():
    areas = _one_area()
    rep, passages = _name(areas, [_text("弱电间", 4.3, 10.5)])
    assert len(areas) == 2 and len(rep.splits) == 1
    closet = next(a for a in areas if a.name == "弱电间")
    hall = next(a for a in areas if a is not closet)
    assert closet.polygon.area == pytest.approx(6.0, abs=0.05)
    assert hall.polygon.area == pytest.approx(80.0, abs=0.05) and not hall.name.startswith("弱电")
    # one passage on the door line joins them
    assert len(passages) == 1
    p = passages[0]
    assert {p.from_id, p.to_id} == {closet.id, hall.id}
    assert p.line.distance(Point(4.6, 8.0)) < 0.05 and p.line.length == pytest.approx(1.2, abs=0.05)


def test_without_the_door_hint_or_without_the_label_nothing_is_split():
    areas = _one_area()
    rep, _ = _name(areas, [_text("弱电间", 4.3, 10.5)], hints=())
    assert len(areas) == 1 and not rep.splits and areas[0].name == "弱电间"  # the known defect, no hint: unchanged
    areas = _one_area()
    rep, _ = _name(areas, [_text("101", 4.3, 10.5)])  # a number only: no room name in the part
    assert len(areas) == 1 and not rep.splits
    areas = _one_area()
    rep, _ = _name(areas, [])
    assert len(areas) == 1 and not rep.splits


def test_the_name_in_the_larger_piece_or_on_both_sides_keeps_the_area_whole():
    # the label in the hall: the door cuts off an unnamed dead end, not a named one
    areas = _one_area()
    rep, _ = _name(areas, [_text("大厅", 5.0, 4.0)])
    assert len(areas) == 1 and not rep.splits
    # the same name written in both pieces (one room drawn across a door leaf): kept whole
    areas = _one_area()
    rep, _ = _name(areas, [_text("大厅", 5.0, 4.0, k=0), _text("大厅", 4.3, 11.0, layer="房间", k=1)])
    assert len(areas) == 1 and not rep.splits


def test_another_name_in_the_rest_still_splits_and_names_both():
    areas = _one_area()
    rep, _ = _name(areas, [_text("大厅", 5.0, 4.0, k=0), _text("储藏间", 4.3, 10.5, k=1)])
    assert len(areas) == 2
    assert sorted(a.name for a in areas) == ["储藏间", "大厅"]
    assert next(a for a in areas if a.name == "储藏间").polygon.area == pytest.approx(6.0, abs=0.05)


def test_a_part_with_another_way_out_is_no_dead_end():
    # a second passage of the area ends on the closet (a door at its far end): not a closet, kept whole
    areas = _one_area()
    passages = [Passage(id=1, from_id=1, to_id=2, line=LineString([(4.0, 13.0), (5.2, 13.0)]))]
    rep, _ = _name(areas, [_text("弱电间", 4.3, 10.5)], passages=passages)
    assert len(areas) == 1 and not rep.splits


def test_a_hint_whose_jambs_are_off_the_outline_splits_nothing():
    # a door swing drawn in the middle of the hall (a leaf standing free): its jambs touch no wall
    areas = _one_area()
    rep, _ = _name(areas, [_text("弱电间", 4.3, 10.5)], hints=(DoorHint(2.0, 4.0, 3.0, 4.0, source="swing"),))
    assert len(areas) == 1 and not rep.splits


def test_a_label_drawn_twice_once_across_the_door_names_the_closet():
    # SIST-F5: one copy of 弱电间 starts on the door line (in the hall by its insertion point), the other
    # lies in the closet: the closet takes the name, the hall none
    areas = _one_area()
    texts = [_text("弱电间", 4.5, 7.9, k=0), _text("弱电间", 4.4, 10.0, layer="房间名", k=1)]
    rep, _ = _name(areas, texts)
    assert len(areas) == 2
    closet = next(a for a in areas if a.name.startswith("弱电间"))
    assert closet.polygon.area == pytest.approx(6.0, abs=0.05)
    assert sum(a.name.startswith("弱电间") for a in areas) == 1


# ------------------------------------------------------------------ the whole pipeline on a small DXF
def _closet_dxf(tmp_path, door=True, label=True):
    """The hall and closet above as walls (layer WALL), the closet's door as a swing (arc + leaf, layer
    DOOR) from jamb (4.0, 8.0) to jamb (5.2, 8.0), the label 弱电间 inside the closet (layer A-ANNO-ROOM)."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    w = {"layer": "WALL"}
    for a, b in (((0, 0), (10, 0)), ((10, 0), (10, 8)), ((10, 8), (5.2, 8)), ((4.0, 8), (0, 8)), ((0, 8), (0, 0)),
                 ((4.0, 8), (4.0, 13)), ((4.0, 13), (5.2, 13)), ((5.2, 13), (5.2, 8))):
        msp.add_line(a, b, dxfattribs=w)
    if door:
        d = {"layer": "DOOR"}
        msp.add_line((4.0, 8.0), (4.0, 9.2), dxfattribs=d)  # the leaf, open into the closet
        msp.add_arc((4.0, 8.0), 1.2, 0, 90, dxfattribs=d)
    if label:
        msp.add_text("弱电间", height=0.3, dxfattribs={"layer": "A-ANNO-ROOM", "insert": (4.2, 10.5)})
    msp.add_text("大厅", height=0.4, dxfattribs={"layer": "A-ANNO-ROOM", "insert": (4.5, 4.0)})
    p = tmp_path / f"closet-{int(door)}{int(label)}.dxf"
    doc.saveas(p)
    return str(p)


def test_pipeline_splits_the_closet_at_its_drawn_door(tmp_path):
    fl = pipeline.process_floor(_closet_dxf(tmp_path))
    assert fl.drawing.doors, "the swing gives a door hint"
    areas = fl.refined.areas
    closet = [a for a in areas if a.name == "弱电间"]
    hall = [a for a in areas if a.name == "大厅"]
    assert len(closet) == 1 and len(hall) == 1
    assert 4.5 < closet[0].polygon.area < 7.0 and hall[0].polygon.area > 60
    assert any({p.from_id, p.to_id} == {closet[0].id, hall[0].id} for p in fl.refined.passages)


# ------------------------------------------------------------------ a lift car block on a stair layer
import numpy as np  # noqa: E402

from algorithms.area_types import classify_vertical_areas  # noqa: E402
from algorithms.model import CadGeometry  # noqa: E402

SHAFT = box(0, 0, 2.2, 2.6)


def _car(block="A3-RI-3F$0$kt1", layer="A3-RI-3F$0$an-stairs"):
    """A lift car as its block draws it: the car (1.6 x 1.4 m), the counterweight and the doors' sills."""
    g = []
    for x0, y0, x1, y1 in ((0.3, 0.3, 1.9, 1.7), (0.3, 1.9, 1.9, 2.3), (0.5, 0.1, 1.7, 0.25)):
        c = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], float)
        g.append(CadGeometry(layer=layer, kind="stair", coords=c, closed=True, entity="LWPOLYLINE", block=block))
    return g


def _treads(n=8):
    return [CadGeometry(layer="A-STRS", kind="stair", coords=np.array([(0.2, 0.2 + 0.28 * k), (2.0, 0.2 + 0.28 * k)]),
                        entity="LINE") for k in range(n)]


def test_a_lift_car_block_on_a_stair_layer_types_its_shaft_elevator():
    a = Area(id=1, polygon=SHAFT)
    got = classify_vertical_areas([a], _car(), shapes=False)
    assert got == {1: "elevator"} and a.type == "elevator"


def test_a_stair_layer_shaft_without_a_lift_block_or_with_treads_stays_stairs():
    for geoms in (_car(block="A3-RI-3F$0$stair-1"), _car(block=""), _car() + _treads()):
        a = Area(id=1, polygon=SHAFT)
        assert classify_vertical_areas([a], geoms, shapes=False) == {1: "stairs"}, geoms[0].block


def test_qgis_process_dxftoosmag_gives_the_closet_its_own_area(tmp_path):
    """Headless (qgis_process): the osmAG file holds the closet 弱电间 as an area of its own, joined to the hall
    by a passage."""
    from algorithms import osmag

    from .qgis_process import run_alg

    out = tmp_path / "closet.osm"
    run_alg("dxftoosmag", {"INPUT": _closet_dxf(tmp_path), "OUTPUT": str(out), "ANCHOR": "121.5906,31.1790 [EPSG:4326]"})
    areas, passages, _, _ = osmag.read_osmag(str(out))
    names = {a.name: a for a in areas}
    assert "弱电间" in names and "大厅" in names
    assert any({p.from_id, p.to_id} == {names["弱电间"].id, names["大厅"].id} for p in passages)
