"""Tag blocks that say what they tag, floor-to-floor stair notes, fire-rated window labels, level prefixes
(library sheets: door-size codes '1522' in ECADI-TAG-DOOR blocks became room refs)."""
import pytest
from shapely.geometry import box

from algorithms import semantics as S
from algorithms.model import Area, CadText


def A(text, layer="A-SYMB", block="ECADI-TAG-ROOM", tag="CHINESENAME", x=0.0, y=0.0):
    return CadText(x=x, y=y, text=text, height=0.3, rotation=0.0, layer=layer, entity="ATTRIB", block=block, tag=tag)


@pytest.mark.parametrize("text,layer,block,tag,want", [
    ("1522", "X$0$A-SYMB-DOOR", "X$0$ECADI-TAG-DOOR", "门窗主编号2", ("ignored", "door/window code (block)")),
    ("0922a", "A-SYMB", "ECADI-TAG-DOOR", "门窗主编号2", ("ignored", "door/window code (block)")),
    ("A3-4", "A-SYMB", "X$0$$0$ECADI-TAG-GRID", "GRID", ("ignored", "axis (block)")),
    ("3F到2F下30", "A-SYMB-STRS", "ECADI-TAG-NAME", "CHINESENAME", ("ignored", "stair arrow")),
    ("(固定乙级窗)", "A-SYMB", "ECADI-TAG-ROOM", "CHINESENAME", ("ignored", "door/window code")),
    ("媒体实验室", "A-SYMB", "ECADI-TAG-ROOM", "CHINESENAME", ("name", "room tag")),
    ("A3-ST-07", "A-SYMB-NUMB-T", "ECADI-TAG-CODE", "CODE", ("number", "room block")),
    ("101", "A-SYMB", "DOOR_TAG", "ROOM_NO", ("number", "room tag")),  # the ATTRIB tag still wins
])
def test_tag_blocks_say_what_they_tag(text, layer, block, tag, want):
    assert S.classify_text(A(text, layer, block, tag)) == want


def test_door_size_codes_never_become_room_refs_and_level_prefixes_are_one_name():
    room = Area(id=1, polygon=box(0, 0, 6, 5))
    gallery = Area(id=2, polygon=box(6, 0, 30, 5))
    rep = S.assign_names([room, gallery], [
        A("媒体实验室", x=3, y=2.5), A("1522", "A-SYMB-DOOR", "ECADI-TAG-DOOR", "门窗主编号2", x=5.5, y=1),
        A("2F中庭回廊", x=10, y=2.5), A("中庭回廊", x=20, y=2.5), A("中庭回廊", x=27, y=2.5)])
    assert (room.name, room.ref) == ("媒体实验室", "")
    # one name; the plain spelling wins over another floor's prefix (semantics._spelling, session 7 T8b)
    assert gallery.name == "中庭回廊" and not gallery.tags.get("label_conflict")
    fig = S.floor_figures([room, gallery], [], rep)
    assert fig["room_texts"] == 4 and fig["own_texts"] == 4


def test_door_tags_are_no_names_but_still_evidence_of_the_inside():
    texts = [A("1522", "A-SYMB-DOOR", "ECADI-TAG-DOOR", "门窗主编号2", x=1, y=1), A("A3-4", "A-SYMB", "TAG-GRID", "GRID"),
             A("媒体实验室", x=3, y=3)]
    pts = S.room_name_points(texts)
    assert sorted(t for _, _, t in pts) == ["1522", "媒体实验室"]  # the axis bubble is not
