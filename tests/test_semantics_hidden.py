"""Texts on frozen / off layers (a sheet freezing one wing's annotation layer): read apart as
``CadDrawing.hidden_texts``; they name only areas that no visible text names (algorithms/semantics.py)."""
import ezdxf
import pytest
from shapely.geometry import box

from algorithms import cad_import
from algorithms import semantics as S
from algorithms.model import Area, CadText


def T(text, x, y, layer="TXT", entity="TEXT", h=0.3, id=-1):
    return CadText(x=x, y=y, text=text, height=h, rotation=0.0, layer=layer, entity=entity, id=id)


def _three_rooms():
    return [Area(id=1, polygon=box(0, 0, 5, 5)), Area(id=2, polygon=box(5, 0, 10, 5)),
            Area(id=3, polygon=box(10, 0, 15, 5)), Area(id=4, polygon=box(20, 0, 24, 6), type="stairs")]


def test_hidden_names_fill_only_unnamed_areas():
    areas = _three_rooms()
    visible = [T("Office", 2.5, 2.5, id=0)]
    hidden = [T("Archive", 4.9, 2.5, layer="A-TEXT", id=1),  # inside the office, near its wall: never the neighbour's
              T("Store", 7.5, 2.5, layer="A-TEXT", id=2),
              T("E1-ST-04详见建施(A-E-40-04)", 18.0, 1.0, layer="A-TEXT", id=3),  # callout beside the stair
              T("-0.020", 12.0, 2.0, layer="A-TEXT", id=4)]  # not a name: ignored
    rep = S.assign_names(areas, visible, "1", hidden_texts=hidden)
    assert [a.name for a in areas] == ["Office", "Store", "1-3", "E1-ST-04"]
    assert not any(a.tags.get("label_conflict") for a in areas)
    assert areas[3].type == "stairs" and areas[3].ref == "E1-ST-04"
    c = rep.counts()
    assert (c["hidden"], c["hidden_used"]) == (3, 2)
    # the figures stay about the visible texts
    assert c["labels"] == 1 and rep.texts[0].text == "Office"
    assert "frozen/off layers" in rep.summary()


def test_hidden_names_never_split_or_conflict():
    big = Area(id=1, polygon=box(0, 0, 20, 5))
    rep = S.assign_names([big], [T("Lab", 3, 2.5)], "1", hidden_texts=[T("Office", 17, 2.5, layer="X")])
    assert big.name == "Lab" and not big.tags.get("label_conflict") and not rep.splits
    assert rep.counts()["hidden_used"] == 0


def test_no_hidden_texts_is_the_old_behaviour():
    a1, a2 = _three_rooms()[:2]
    S.assign_names([a1, a2], [T("Office", 2.5, 2.5)], "1", hidden_texts=[])
    assert (a1.name, a2.name) == ("Office", "1-2")


def _plan_with_frozen_annotations(path):
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 6  # metres
    doc.layers.add("WALL")
    doc.layers.add("TXT")
    doc.layers.add("A-TEXT").freeze()
    doc.layers.add("ANNO").off()
    msp = doc.modelspace()
    for x0 in (0, 5, 10):
        msp.add_lwpolyline([(x0, 0), (x0 + 5, 0), (x0 + 5, 5), (x0, 5)], close=True, dxfattribs={"layer": "WALL"})
    msp.add_text("Office", dxfattribs={"layer": "TXT", "height": 0.3, "insert": (2, 2.5)})
    msp.add_text("Archive", dxfattribs={"layer": "A-TEXT", "height": 0.3, "insert": (3, 1)})
    msp.add_text("Store", dxfattribs={"layer": "A-TEXT", "height": 0.3, "insert": (7, 2.5)})
    blk = doc.blocks.new("CALLOUT")
    blk.add_text("Laboratory", dxfattribs={"layer": "0", "height": 0.3, "insert": (0, 0)})
    blk.add_line((0, -0.2), (1, -0.2), dxfattribs={"layer": "0"})
    msp.add_blockref("CALLOUT", (12, 2.5), dxfattribs={"layer": "ANNO"})  # a block on an off layer
    doc.saveas(path)


def test_import_keeps_texts_of_frozen_and_off_layers_apart(tmp_path):
    path = str(tmp_path / "frozen.dxf")
    _plan_with_frozen_annotations(path)
    d = cad_import.import_dxf(path)
    assert [t.text for t in d.texts] == ["Office"]
    assert sorted(t.text for t in d.hidden_texts) == ["Archive", "Laboratory", "Store"]
    lab = next(t for t in d.hidden_texts if t.text == "Laboratory")
    assert lab.layer == "ANNO" and lab.x == pytest.approx(12) and lab.y == pytest.approx(2.5)
    assert sorted(t.id for t in d.hidden_texts) == [1, 2, 3]  # after the visible texts' ids
    # the block's line on the off layer is not geometry
    assert not any(g.layer == "ANNO" for g in d.geometries)


def test_pipeline_names_rooms_from_frozen_layers_only_where_nothing_visible_names_them(tmp_path):
    from algorithms import pipeline

    path = str(tmp_path / "frozen.dxf")
    _plan_with_frozen_annotations(path)
    floor = pipeline.process_floor(path, min_area=1.0)
    names = sorted(a.name for a in floor.refined.areas if a.type != "structure")
    assert names == ["Laboratory", "Office", "Store"]
    c = floor.names.counts()
    assert c["hidden_used"] == 2 and c["labels"] == 1


# ------------------------------------------------------------------ stair / lift codes beside their core
def test_code_in_an_atrium_names_the_small_stair_beside_it_not_the_atrium():
    atrium = Area(id=1, polygon=box(0, 0, 30, 20))  # 600 m², an open stair somewhere in it
    stair = Area(id=2, polygon=box(30, 5, 34, 11))  # 24 m² core next to it
    areas = [atrium, stair]
    rep = S.assign_names(areas, [T("E1-ST-15", 28.0, 8.0, entity="ATTRIB"), T("Atrio", 10, 10)])
    assert stair.ref == "E1-ST-15" and stair.type == "stairs"
    assert atrium.name == "Atrio" and atrium.type != "stairs" and not atrium.ref
    assert rep.counts()["outside"] == 0


def test_code_alone_in_a_large_area_never_types_it():
    hall = Area(id=1, polygon=box(0, 0, 40, 30))
    S.assign_names([hall], [T("E1-ST-16", 20, 15, entity="ATTRIB")])
    assert hall.type == "room" and hall.tags.get("room") != "stairs"


def test_callouts_share_out_nearby_cores_one_code_each_and_never_the_other_kind():
    corridor = Area(id=1, polygon=box(0, 0, 30, 3), type="corridor")
    s1 = Area(id=2, polygon=box(10, 3, 14, 9), type="stairs")
    s2 = Area(id=3, polygon=box(16, 3, 20, 9), type="stairs")
    closet = Area(id=4, polygon=box(5, 3, 8, 6))  # an unnamed small room beside the code: a core left untyped
    areas = [corridor, s1, s2, closet]
    S.assign_names(areas, [T("E1-ST-01详见建施(A-E-40-01)", 12, 1.5), T("E1-ST-02详见建施(A-E-40-02)", 13, 1.0),
                           T("E1-P2详见建施(A-E-40-19)", 8, 1.5), T("走道", 25, 1.5)])
    assert {s1.ref, s2.ref} == {"E1-ST-01", "E1-ST-02"} and s1.ref == "E1-ST-01"
    assert closet.ref == "E1-P2" and closet.type == "elevator"  # the lift code never lands on a stair
    assert corridor.type == "corridor" and not corridor.ref


def test_hidden_code_gives_the_ref_of_a_lift_named_by_a_visible_keyword():
    lift = Area(id=1, polygon=box(0, 0, 3, 3), type="elevator")
    hall = Area(id=2, polygon=box(3, -5, 20, 3))
    S.assign_names([lift, hall], [T("客梯", 1.5, 1.5), T("电梯厅", 10, 0)],
                   hidden_texts=[T("E1-P3/P4详见建施(A-E-40-20)", 5, 1, layer="A-TEXT")])
    assert (lift.name, lift.ref, lift.type) == ("客梯", "E1-P3/P4", "elevator")
    assert hall.name == "电梯厅" and not hall.ref


# ------------------------------------------------------------------ things labelled inside named rooms
def test_keywordless_labels_in_a_named_room_are_things_unless_they_name_a_room_elsewhere():
    bar = Area(id=1, polygon=box(0, 0, 10, 8))
    hall = Area(id=2, polygon=box(10, 0, 30, 8))
    expo = Area(id=3, polygon=box(30, 0, 40, 8))
    areas = [bar, hall, expo]
    rep = S.assign_names(areas, [T("area bar", 5, 4), T("cassa", 2, 2), T("gelatiera", 8, 6), T("hall", 20, 4),
                                 T("exposition", 25, 6), T("exposition", 35, 4)])
    by = {r.text: r for r in rep.texts}
    assert (by["cassa"].role, by["cassa"].reason) == ("ignored", "label in a named room")
    assert by["gelatiera"].role == "ignored"
    # 'exposition' names an area of its own elsewhere: inside the hall it is a room name the hall swallowed
    assert [r.role for r in rep.texts if r.text == "exposition"] == ["name", "name"]
    assert (bar.name, hall.name, expo.name) == ("area bar", "hall", "exposition")
    assert rep.counts()["ignored_by_reason"] == {"label in a named room": 2}
    fig = S.floor_figures(areas, [], rep)
    assert fig["room_texts"] == 4 and fig["own_texts"] == 3


def test_a_name_outside_the_room_never_beats_the_label_inside_it():
    # the corridor above the classroom was lost by segmentation; its name is 1.6 m above the room
    room = Area(id=1, polygon=box(0, 0, 8, 6))
    rep = S.assign_names([room], [T("PEDANA", 1, 4.5), T("corridoio distribuzione", 3, 7.6)])
    assert room.name == "PEDANA" and room.type == "room" and not room.tags.get("label_conflict")
    fig = S.floor_figures([room], [], rep)
    assert fig["room_texts"] == 2 and fig["own_texts"] == 1 and fig["conflicts"] == 0


def test_plain_code_in_a_corridor_names_the_stair_beside_it():
    corridor = Area(id=1, polygon=box(0, 0, 20, 2.5), type="corridor")
    stair = Area(id=2, polygon=box(8, 2.5, 12, 8), type="stairs")
    S.assign_names([corridor, stair], [T("E2-ST-02", 10, 1.2, entity="ATTRIB"), T("走道", 3, 1.2)])
    assert stair.ref == "E2-ST-02" and corridor.type == "corridor" and corridor.name == "走道"
