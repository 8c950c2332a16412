"""Stage 5: room names, numbers and types from texts (algorithms/semantics.py)."""
import json
import math

import numpy as np
import pytest
from shapely.geometry import LineString, Polygon, box

from algorithms import semantics as S
from algorithms.errors import InputError
from algorithms.model import Area, CadText, Passage
from algorithms.progress import RecordingProgress


def T(text, x=0.0, y=0.0, layer="TXT", entity="TEXT", h=0.3, block="", tag="", id=-1, rot=0.0):
    return CadText(x=x, y=y, text=text, height=h, rotation=rot, layer=layer, entity=entity, block=block, tag=tag,
                   id=id)


# ------------------------------------------------------------------------------------ classification
NAMES = ["Office 101", "Meeting Room 105", "WC", "ＷＣ", "卫生间", "放映室", "办公室", "楼梯间", "AMBIENTE 4",
         "CORREDOR", "ZAGUAN DE INGRESO", "corridoio distribuzione", "Aula 2", "спальня", "Stair A", "Lift 1",
         "غرفة الاجتماعات", "\u202eחדר ישיבות\u202c", "cinema", "Technical room", "wc men", "DEPOSITO"]
NUMBERS = ["101", "A007", "B-204", "E1-ST-03", "E2-P1", "E1-OP-2", "2105"]
IGNORED = [("", "empty"), ("   ", "empty"), ("\x00\x07\u200f", "empty"), ("---", "empty"), ("800", "dimension"),
           ("1200", "dimension"), ("3,600", "dimension"), ("23.5 m²", "area"), ("mq 1.6", "area"),
           ("S=12.5㎡", "area"), ("-0.020", "elevation"), ("+4,200", "elevation"), ("±0.000", "elevation"),
           ("(178,900)", "elevation"), ("NPT + 0.20", "elevation"), ("N.P.T.=+0.20 m", "elevation"),
           ("Level -6.000", "elevation"), ("FM乙1522", "door/window code"), ("FM乙", "door/window code"), ("甲级防火门", "door/window code"), ("SGFM甲1822", "door/window code"),
           ("M1021", "door/window code"), ("C1518", "door/window code"), ("D1", "door/window code"),
           ("上", "stair arrow"), ("下", "stair arrow"), ("UP", "stair arrow"), ("DN", "stair arrow"),
           ("A", "axis"), ("7\"", "axis"), ("А", "axis"), ("2", "axis"), ("1/A", "axis"),
           ("PLANTA DE DISTRIBUCION", "title"), ("Section 1-1", "title"), ("三层平面图", "title"),
           ("楼梯放大详图", "title"), ("1:100", "scale"), ("www.archweb.it", "title block"),
           ("C A L L E  B E A T E R I O", "spaced title"), ("PISO DE LADRILLO ESPINA DE PEZ", "note"),
           ("注：所有尺寸以毫米计", "note"), ("6 lockers guard", "furniture"), ("white board", "furniture"),
           ("this is a long remark about the works to be carried out here", "long text"),
           ("1/A3-11", "axis"), ("A3`-L", "axis"), ("A-A3-40-04,05", "drawing reference"), ("5F板边线", "note"),
           ("1F顶板至5F底板开洞", "note"), ("i=1%", "dimension"), ("SCALE", "title block"),
           ('("nullsurf" "")', "cad internals"), ("BYLAYER", "cad internals"), ("$DDT_AUDIT_GENERATED_(0)", "cad internals"), ("不上人平屋面", "note"),
           ("平 面 图", "title")]


@pytest.mark.parametrize("text", NAMES)
def test_room_names_are_names(text):
    role, reason = S.classify_text(text)
    assert role == "name", (text, reason)


@pytest.mark.parametrize("text", NUMBERS)
def test_room_numbers_are_numbers(text):
    assert S.classify_text(text)[0] == "number", text


@pytest.mark.parametrize("text,reason", IGNORED)
def test_other_texts_are_ignored_with_their_reason(text, reason):
    assert S.classify_text(text) == ("ignored", reason), text


def test_layer_block_and_tag_decide_when_the_text_cannot():
    # a digits-only number is a room number on a room-number layer or in a room-number attribute
    assert S.classify_text("12", layer="A-ANNO-ROOM") == ("number", "name layer")
    assert S.classify_text(T("7", tag="ROOM_NO", entity="ATTRIB")) == ("number", "room tag")
    assert S.classify_text(T("Lab 3", tag="ROOMNAME", entity="ATTRIB")) == ("name", "room tag")
    # bound xref prefixes are stripped before the layer rules: room layer, dimension layer, axis layer
    assert S.classify_text("放映室", layer="E1-RI-1F$0$房间名称")[0] == "name"
    assert S.classify_text("Hall", layer="E1-RI-1F$0$A-ANNO-DIMS") == ("ignored", "dimension (layer)")
    assert S.classify_text("B", layer="X$0$$2$S-GRID") == ("ignored", "axis (layer)")
    # a stair name on the stair layer is a name, the arrow is not
    assert S.classify_text("Stair A", layer="A-STAIR")[0] == "name"
    assert S.classify_text("UP", layer="A-STAIR") == ("ignored", "stair arrow (layer)")
    assert S.strip_xref("E1-RI-1F$0$A-WALL") == "A-WALL"
    assert S.strip_xref("X$0$$2$LAYER") == "LAYER"


def test_normalize_strips_codes_controls_and_bidi():
    assert S.normalize_text("{\\fArial|b1;Office} 105") == "Office 105"
    assert S.normalize_text("Meeting\\PRoom") == "Meeting Room"
    assert S.normalize_text("%%p0.000") == "±0.000"
    assert S.normalize_text("\u202eWC\u202c\u200b\x07") == "WC"
    assert S.normalize_text("ＷＣ　１０１") == "WC 101"
    assert S.normalize_text(None) == ""
    assert S.normalize_text("走 道") == "走道" and S.normalize_text("wc men") == "wc men"


def test_multiline_text_labels_are_joined():
    texts = [T("Technical", 10.0, 12.0, h=0.36), T("room", 10.7, 11.1, h=0.36),
             T("PISO DE LADRILLO", 20.0, 5.2, h=0.12), T("ESPINA DE PEZ", 20.1, 5.0, h=0.12),
             T("AMBIENTE 4", 30.0, 5.2, h=0.22), T("NPT + 0.20", 30.4, 4.9, h=0.15)]
    labs = S.classify_labels(texts)
    got = {lab.text: (lab.role, lab.reason, lab.ids) for lab in labs}
    assert got["Technical room"][0] == "name" and got["Technical room"][2] == [0, 1]
    assert got["PISO DE LADRILLO ESPINA DE PEZ"][:2] == ("ignored", "note")
    assert got["AMBIENTE 4"][0] == "name" and got["NPT + 0.20"][:2] == ("ignored", "elevation")


def test_room_name_points():
    pts = S.room_name_points([T("Office", 1, 2), T("101", 1, 1.5), T("+0.20", 3, 3), T("A", 5, 5, layer="AXIS")])
    assert [(x, y, t) for x, y, t in pts] == [(1, 2, "Office"), (1, 1.5, "101")]


def test_rules_file_errors_and_custom_rules(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        S.load_name_rules(str(tmp_path / "nope.json"))
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    with pytest.raises(InputError, match="not valid JSON"):
        S.load_name_rules(str(bad))
    data = json.load(open(S.DEFAULT_NAME_RULES_PATH, encoding="utf-8"))
    data["ignore_patterns"].insert(0, ["note", "^pedana$"])
    data["types"][0]["keywords"].append("scalinata")
    custom = tmp_path / "rules.json"
    custom.write_text(json.dumps(data))
    rules = S.load_name_rules(str(custom))
    assert S.classify_text("PEDANA", rules) == ("ignored", "note")
    assert S.classify_text("PEDANA")[0] == "name"
    assert S.type_of_name("Scalinata nord", rules=rules)["type"] == "stairs"
    data["types"][0]["type"] = "spaceship"
    custom.write_text(json.dumps(data))
    with pytest.raises(InputError, match="unknown area type"):
        S.load_name_rules(str(custom))


@pytest.mark.parametrize("name,ref,typ,room", [
    ("Stair A", "", "stairs", "stairs"), ("楼梯间", "", "stairs", "stairs"), ("Treppenhaus", "", "stairs", "stairs"),
    ("", "E1-ST-03", "stairs", "stairs"), ("", "E2-P1", "elevator", "elevator"), ("", "E1-FG-2", "elevator", "elevator"),
    ("货梯", "", "elevator", "elevator"), ("ascensore", "", "elevator", "elevator"), ("电梯厅", "", "room", "lobby"), ("电梯机房", "", "room", "technical"), ("候梯厅", "", "room", "lobby"),
    ("Flur", "", "corridor", ""), ("走廊", "", "corridor", ""), ("pasillo", "", "corridor", ""),
    ("卫生间", "", "room", "toilets"), ("bagno", "", "room", "toilets"), ("rest room", "", "room", "toilets"),
    ("Ufficio 03", "", "room", "office"), ("atrio", "", "room", "lobby"), ("sala riunioni", "", "room", "conference")])
def test_types_from_keywords_and_codes(name, ref, typ, room):
    e = S.type_of_name(name, ref)
    assert e is not None and e["type"] == typ and (e.get("room") or "") == room


# ------------------------------------------------------------------------------------ score
def test_score_is_the_papers():
    sq = box(0, 0, 10, 10)  # 100 m², S = sqrt(100/pi)
    S_ = math.sqrt(100 / math.pi)
    assert S.score(5, 5, sq) == (pytest.approx(100.0), "inside")
    s, how = S.score(5 + 0.5 * S_, 5, sq)
    assert how == "inside" and s == pytest.approx(100 - 50 * 0.5)
    s, _ = S.score(5 + 0.9 * S_ / math.sqrt(2), 5 + 0.9 * S_ / math.sqrt(2), sq)
    assert s == pytest.approx(50 - 25 * (0.9 - 0.7))
    s, how = S.score(11.0, 5, sq)  # 1 m outside
    f_size = 1 / (1 + math.log10(1 + 100 / 10000))
    assert how == "nearby" and s == pytest.approx(40 + 30 * f_size + 20 * (1 - 1 / 2.2))
    assert S.score(12.3, 5, sq) == (0.0, "")
    # far from the centroid of a long corridor: the paper's score would be <= 0; the area stays a candidate
    corridor = box(0, 0, 100, 2)
    s, how = S.score(99, 1, corridor)
    assert how == "inside" and s == 1.0


# ------------------------------------------------------------------------------------ assignment
def rooms():
    return [Area(id=1, polygon=box(0, 0, 5, 4)), Area(id=2, polygon=box(5, 0, 10, 4)),
            Area(id=3, polygon=box(0, 4, 10, 6), type="corridor")]


def test_names_numbers_auto_ids_and_tags():
    areas = rooms()
    texts = [T("Office", 2.5, 2.2, id=10), T("101", 2.5, 1.6, id=11), T("+0.20", 2.5, 1.0, id=12),
             T("卫生间", 7.5, 2.0, id=13), T("Hall far away", 50, 50, id=14)]
    pr = RecordingProgress()
    rep = S.assign_names(areas, texts, level="3", progress=pr)
    a1, a2, a3 = areas
    assert (a1.name, a1.ref, a1.type) == ("Office", "101", "room")
    assert a1.tags["ref"] == "101" and a1.tags["room"] == "office" and a1.tags["indoor"] == "room"
    assert a1.tags["label_texts"] == "10;11" and float(a1.tags["label_score"]) > 90
    assert (a2.name, a2.tags["room"]) == ("卫生间", "toilets")
    assert a3.name == "3-3" and a3.tags["indoor"] == "corridor"  # stable generated id <level>-<id>
    c = rep.counts()
    assert c["names"] == 3 and c["numbers"] == 1 and c["ignored_by_reason"] == {"elevation": 1}
    assert c["outside"] == 1 and c["named_areas"] == 2 and c["auto_ids"] == 1
    assert "outside every area" in pr.text()
    # rerun: same result (stable)
    again = rooms()
    S.assign_names(again, texts, level="3")
    assert [a.name for a in again] == [a.name for a in areas]


def test_nearby_text_goes_to_the_small_room_not_the_corridor():
    areas = rooms()
    rep = S.assign_names(areas, [T("Store", 2.5, -0.5)])
    assert areas[0].name == "Store" and rep.texts[0].match == "nearby"


def test_duplicate_names_get_suffixes_never_merged():
    areas = [Area(id=k, polygon=box(5 * k, 0, 5 * k + 4, 4)) for k in range(1, 5)]
    texts = [T("wc", 7, 2), T("wc", 12, 2), T("WC", 17, 2), T("12", 17, 1.5, layer="A-ANNO-ROOM"), T("Office", 22, 2)]
    rep = S.assign_names(areas, texts)
    assert [a.name for a in areas] == ["wc (1)", "wc (2)", "WC 12", "Office"]
    assert len({a.name for a in areas}) == 4 and list(rep.duplicates.values()) == [[1, 2, 3]]


def test_same_name_twice_in_one_area_is_one_name():
    areas = [Area(id=1, polygon=box(0, 0, 10, 10))]
    S.assign_names(areas, [T("Storage", 3, 3), T("Storage", 7, 7)])
    assert areas[0].name == "Storage" and "label_conflict" not in areas[0].tags


def test_a_short_label_beside_a_room_name_is_not_a_conflict():
    areas = [Area(id=1, polygon=box(0, 0, 6, 5))]
    S.assign_names(areas, [T("copy", 1, 1), T("amministrazione", 3, 2.5)])
    assert areas[0].name == "amministrazione" and "label_conflict" not in areas[0].tags


def two_rooms_one_area(door=1.0):
    """Two 5 x 4 m rooms joined by a ``door``-wide opening in their common wall, as one area."""
    left, right = box(0, 0, 5, 4), box(5.2, 0, 10.2, 4)
    y0 = 2 - door / 2
    return left.union(box(4.9, y0, 5.3, y0 + door)).union(right)


def test_two_names_split_at_the_narrowing():
    poly = two_rooms_one_area()
    areas = [Area(id=7, polygon=poly), Area(id=8, polygon=box(0, 4, 10.2, 6), type="corridor")]
    passages = [Passage(id=1, from_id=7, to_id=8, line=LineString([(8, 4), (9, 4)])),
                Passage(id=2, from_id=7, to_id=8, line=LineString([(1, 4), (2, 4)]))]
    pr = RecordingProgress()
    rep = S.assign_names(areas, [T("Office A", 2.5, 2), T("Office B", 7.7, 2)], passages=passages, progress=pr)
    assert len(rep.splits) == 1 and rep.splits[0][0] == 7
    by_name = {a.name: a for a in areas}
    a, b = by_name["Office A"], by_name["Office B"]
    assert a.id == 7 and b.id == 9
    assert a.polygon.area == pytest.approx(20.2, abs=0.6) and b.polygon.area == pytest.approx(20.2, abs=0.6)
    assert a.polygon.union(b.polygon).area == pytest.approx(poly.area, rel=1e-6)
    assert a.polygon.intersection(b.polygon).area < 1e-6
    # the passages follow the pieces; the cut is a new passage between them, across the doorway
    assert {(p.from_id, p.to_id) for p in passages[:2]} == {(9, 8), (7, 8)}
    cut = [p for p in passages if p.id in rep.new_passages]
    assert len(cut) == 1 and {cut[0].from_id, cut[0].to_id} == {7, 9}
    assert cut[0].line.length == pytest.approx(1.0, abs=0.25) and 4.8 < cut[0].line.centroid.x < 5.4
    assert "split" in pr.text() and not rep.conflicts


def test_two_names_without_narrowing_are_a_conflict():
    areas = [Area(id=1, polygon=box(0, 0, 12, 5))]
    pr = RecordingProgress()
    rep = S.assign_names(areas, [T("Office A", 3, 2.5), T("Office B", 9, 2.5)], progress=pr)
    assert not rep.splits and rep.conflicts == [1]
    assert areas[0].name in ("Office A", "Office B") and areas[0].tags["label_conflict"] in ("Office A", "Office B")
    assert "label_conflict" in pr.text()
    osm = S.osm_tags(areas[0])
    assert "label_conflict" not in osm and "label_score" not in osm and osm["fixme"].startswith("several room names")


def test_split_can_be_turned_off():
    areas = [Area(id=7, polygon=two_rooms_one_area())]
    rep = S.assign_names(areas, [T("Office A", 2.5, 2), T("Office B", 7.7, 2)], split=False)
    assert not rep.splits and rep.conflicts == [7] and len(areas) == 1


def test_unnamed_long_narrow_hub_is_a_corridor():
    hub = Area(id=1, polygon=box(0, 4, 30, 6))  # 30 x 2 m
    rooms_ = [Area(id=k + 2, polygon=box(3 * k, 0, 3 * k + 3, 4)) for k in range(4)]
    passages = [Passage(id=k, from_id=1, to_id=k + 2, line=LineString([(3 * k + 1, 4), (3 * k + 2, 4)]))
                for k in range(4)]
    areas = [hub] + rooms_
    rep = S.assign_names(areas, [], passages=passages)
    assert hub.type == "corridor" and hub.tags["indoor"] == "corridor"
    assert all(a.type == "room" for a in rooms_) and rep.typed == {"corridor (geometry)": 1}


def test_keyword_types_and_symbol_types():
    areas = [Area(id=1, polygon=box(0, 0, 4, 6)), Area(id=2, polygon=box(4, 0, 6, 2)),
             Area(id=3, polygon=box(6, 0, 10, 6), type="stairs"), Area(id=4, polygon=box(10, 0, 14, 6)),
             Area(id=5, polygon=box(20, 0, 24, 6), type="elevator"), Area(id=6, polygon=box(30, 0, 34, 6), type="elevator")]
    S.assign_names(areas, [T("E1-ST-03", 2, 3), T("E2-P1", 5, 1), T("Office", 9.8, 5.8), T("走道", 12, 3),
                           T("E1-ST-05", 22, 3), T("门厅", 32, 3)])
    assert [a.type for a in areas] == ["stairs", "elevator", "stairs", "corridor", "stairs", "room"]
    assert areas[0].name == "E1-ST-03" and areas[0].ref == "E1-ST-03" and areas[0].tags["room"] == "stairs"
    assert areas[1].tags["room"] == "elevator"
    assert areas[2].tags["room"] == "stairs"  # typed from its symbols: a name in its corner does not untype it
    # the text beats the symbols when it names the stair, or when it is the area's own centred label
    assert areas[4].tags["room"] == "stairs" and areas[5].tags == {"indoor": "area", "room": "lobby",
                                                                   "label_score": "100.0", "label_texts": "5"}


def test_bad_texts_never_raise_and_are_counted():
    areas = rooms()
    texts = [T("", 1, 1), T(None, 1, 1), T("\x00\x1b[31m", 1, 1), T("\u200f\u202e", 1, 1),
             T("غرفة", 2, 2), T("会议室", 7, 2), T("42", 7, 3), T("Office", float("nan"), 1),
             T("Office", float("inf"), 1), T("y" * 500, 1, 1), T("Room", 1e9, 1e9)]
    rep = S.assign_names(areas, texts)
    c = rep.counts()
    assert c["labels"] == len(texts)
    assert c["ignored_by_reason"]["empty"] == 4 and c["ignored_by_reason"]["axis"] == 1
    assert c["ignored_by_reason"]["long text"] == 1
    assert areas[0].name == "غرفة" and areas[1].name == "会议室"
    assert c["outside"] == 3  # nan, inf and the far one


def test_no_areas_and_no_texts():
    assert S.assign_names([], [T("Office", 1, 1)]).counts()["outside"] == 1
    areas = rooms()
    rep = S.assign_names(areas, [])
    assert rep.auto == 3 and [a.name for a in areas] == ["1-1", "1-2", "1-3"]


def test_user_names_survive_when_no_text_claims_the_area():
    areas = rooms()
    areas[2].name = "Main corridor"
    S.assign_names(areas, [T("Office", 2.5, 2)])
    assert areas[2].name == "Main corridor"


def test_protect_labelled_small_areas():
    areas = [Area(id=1, polygon=box(0, 0, 2, 2)), Area(id=2, polygon=box(2, 0, 4, 2)),
             Area(id=3, polygon=box(4, 0, 20, 10))]
    saved = S.protect_labelled_areas(areas, [T("WC", 1, 1), T("Office", 10, 5)], min_area=10.0)
    assert saved == {1: "room"} and areas[0].type == S.PROTECTED_TYPE and areas[1].type == "room"
    S.restore_types(saved, areas)
    assert areas[0].type == "room"


def test_floor_figures():
    areas = rooms()
    passages = [Passage(id=1, from_id=1, to_id=3, line=LineString([(1, 4), (2, 4)]))]
    rep = S.assign_names(areas, [T("Office", 2.5, 2), T("Store", 7.5, 2), T("Hall", 7.0, 3.5)], passages=passages)
    fig = S.floor_figures(areas, passages, rep)
    assert fig["areas"] == 3 and fig["components"] == 2
    assert fig["largest_component_pct"] == pytest.approx(100 * 40 / 60)
    assert fig["room_texts"] == 3 and fig["inside_pct"] == 100.0
    assert fig["own_area_pct"] == pytest.approx(100 / 3)  # Store and Hall share an area: neither has its own
    assert fig["conflicts"] == 1 and fig["named_areas"] == 2 and fig["semantic_accuracy_pct"] == 100.0


# ------------------------------------------------------------------------------------ real data
# Hand labels of the shared ArchWeb plans' texts (read once from the drawings): texts that are room names and
# texts that are not (notes, equipment, titles...). Texts a reader could take either way are left out.
ARCHWEB_HAND = {
    "Aule-scolastiche-pianta-1.dxf": ({"DEPOSITO", "corridoio distribuzione"},
                                      {"+0.30", "Archweb.it", "Disegno in scala 1:1 (metri)"}),
    "CASONA_DE_YANAHUARA.dxf": ({"CORREDOR", "PATIO - HUERTA", "ZAGUAN DE INGRESO"} | {f"AMBIENTE {k}" for k in range(1, 21)},
                                {"N.P.T.=+0.20 m", "NPT + 0.20", "PISO DE SILLAR CON CANTO RODADO EN TRAMA",
                                 "PISO DE LADRILLO ESPINA DE PEZ", "TECHO DE CALAMINA EN MAL ESTADO", "PISO DE TIERRA CON VEGETACION",
                                 "C A L L E B E A T E R I O", "ELEVACION PRINCIPAL", "PLANTA DE DISTRIBUCION",
                                 "BOVEDA COLAPSADA", "SISTEMA ESTRUCTURAL PAR Y NUDILLO COBERTURA DE TEJA"}),
    "historical_museum.dxf": ({"Technical room", "exposition", "Administration", "conference hall", "Storage", "cinema",
                               "wc", "Office", "Staff room", "cloakroom", "hall"},
                              {"Level -6.000", "2", "3", "6", "А", "7\"", "-4.900", "Section 1-1", "-6.000"}),
    "kindergarten-1.dxf": ({"спальня"}, {"+4,200", "(178,900)", "0.000", "Level 1", "Section 5-5", "Вид А", "800"}),
    "schema-ufficio-1.dxf": ({"commissario generale", "amministrazione", "wc men", "direttore", "segreteria", "wc women",
                              "wc handicap", "segretario generale", "management", "waiting room", "rest room", "washroom",
                              "meeting room 70 seats", "storage", "office", "area bar", "wine & water bar"},
                             {"mq 1.6", "mq 8.5", "6 lockers guard", "46 lockers + bench", "white board",
                              "bancone refrigerato per esposizione vini", "vetrine espositive per cioccolato",
                              "www.archweb.it", "Pianta uffici / Office building plan"}),
    "modular_housing.dxf": (set(), {"PLAN", "FACADE A-H", "SECTION 1-1", "0,000", "-2,000", "A", "17"}),
}


@pytest.mark.slow
@pytest.mark.parametrize("plan", sorted(ARCHWEB_HAND))
def test_archweb_texts_classified_as_read_by_hand(shared_data, plan):
    from algorithms import cad_import

    # every view of the sheet (sections and facades too: their labels are what the classifier must ignore)
    drawing = cad_import.import_dxf(str(shared_data / "dxf" / "archweb" / plan), plan="-1e9,-1e9,1e9,1e9")
    labs = S.classify_labels(drawing.texts)
    role = {}
    for lab in labs:
        role.setdefault(S.normalize_text(lab.text), set()).add(lab.role)
    names, others = ARCHWEB_HAND[plan]
    missing = {n for n in names if role.get(n) != {"name"}}
    assert not missing, f"{plan}: room names not classified as names: {missing}"
    wrong = {t for t in others if t in role and "name" in role[t]}
    assert not wrong, f"{plan}: not room names, classified as names: {wrong}"
    assert not (others - set(role)), f"{plan}: hand-labelled texts not found: {others - set(role)}"


# known defects, reported as expected failures until fixed (the floor stays the target)
NAMES_KNOWN_BELOW = {
    # (empty since 2026-12-02 session 7: schema-ufficio-1's last conflict, 'area bar' / 'wine & water bar', was
    # under-segmentation after all: the wine bar's service space is closed by its counter, 'bancone refrigerato
    # per esposizione vini', drawn on the furniture layer from the bar's north wall to the jamb of its service
    # door; furniture is never a wall in the raster, so the space joined the octagonal showroom. It splits
    # along the counter now (cad_classify.counter_partitions, tests/test_cad_classify_counter.py))
}


@pytest.mark.slow
@pytest.mark.parametrize("plan,floors", [
    # measured figures (make evaluate-cad), kept as floors against regressions; see README for the targets
    # (2026-12-02 session 7: ufficio 100 / 100 / 100 / 0 since the wine bar splits off along its counter;
    # 2026-12-02 session 6: ufficio 100 / 89.5 / 100 / 1 since the secretaries' room splits along its folding
    # partition; session 5: ufficio 100 / 78.9 / 100 / 2 since the washroom splits off at its door;
    # 2026-12-01 session 4: ufficio 100 / 73.7 / 100 / 2, museum 97.0 / 93.9 / 96.8 / 0 since the hall and
    # the void split at their narrowing, Aule 100 / 100 / 100 / 0, CASONA 100 / 100 / 100 / 0 since a label on a
    # pillar is inside its room)
    ("schema-ufficio-1.dxf", {"inside_pct": 95, "own_area_pct": 95, "semantic_accuracy_pct": 95, "max_conflicts": 0}),
    ("historical_museum.dxf", {"inside_pct": 95, "own_area_pct": 90, "semantic_accuracy_pct": 95, "max_conflicts": 1}),
    ("Aule-scolastiche-pianta-1.dxf", {"inside_pct": 95, "own_area_pct": 95, "semantic_accuracy_pct": 95, "max_conflicts": 0}),
    ("CASONA_DE_YANAHUARA.dxf", {"inside_pct": 95, "own_area_pct": 95, "semantic_accuracy_pct": 95, "max_conflicts": 0}),
])
def test_archweb_names_figures(shared_data, plan, floors, floor_cache):
    floor = floor_cache.process_floor(shared_data / "dxf" / "archweb" / plan)  # pipeline.process_floor, shared
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    if plan in NAMES_KNOWN_BELOW and fig["own_area_pct"] < floors["own_area_pct"]:
        pytest.xfail(f"{plan}: own area {fig['own_area_pct']:.1f} % < {floors['own_area_pct']} %: "
                     f"{NAMES_KNOWN_BELOW[plan]}")
    assert fig["inside_pct"] >= floors["inside_pct"] and fig["own_area_pct"] >= floors["own_area_pct"], fig
    assert fig["semantic_accuracy_pct"] >= floors["semantic_accuracy_pct"] and fig["conflicts"] <= floors["max_conflicts"]
    names = [a.name for a in floor.refined.areas]
    assert len(names) == len(set(names))  # duplicates suffixed, never merged
    assert all(a.name for a in floor.refined.areas)


@pytest.mark.slow
def test_sample_building_every_room_named_and_typed(tmp_path):
    from algorithms import pipeline
    from algorithms.sample_building import generate_building, ground_truth_rooms

    info = generate_building(str(tmp_path), floors=2, seed=3)
    for k, dxf in enumerate(info["dxf"], 1):
        floor = pipeline.process_floor(dxf, level=str(k))
        areas = floor.refined.areas
        for room in ground_truth_rooms(info["ground_truth"][k - 1]):
            best = max(areas, key=lambda a: a.polygon.intersection(room["polygon"]).area)
            assert best.name == room["name"], (k, room["name"], best.name)
            assert best.type == room["areatype"], (room["name"], best.type)
        fig = S.floor_figures(areas, floor.refined.passages, floor.names)
        assert fig["own_area_pct"] == 100.0 and fig["conflicts"] == 0 and fig["semantic_accuracy_pct"] == 100.0


# Stairs and lifts named on the original DWG sheets, counted by hand from the sheets' texts (stair codes on
# A-SYMB-NUMB-T and in the detail callouts "E1-ST-01详见建施(A-E-40-01)" of A-TEXT; lift codes likewise).
DWG_VERTICAL = {
    "sist-original/SIST-F1.dwg": ({"E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06", "E1-ST-08",
                                   "E1-ST-09", "E1-ST-10", "E1-ST-11", "E1-ST-13", "E2-ST-01", "E2-ST-02", "E2-ST-03",
                                   "E2-ST-04"},
                                  {"E1-P1", "E1-P2", "E2-P1", "E2-P2", "E2-P3", "E2-P4"}),
    "sist-original/SIST-F3.dwg": ({"E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06", "E1-ST-07",
                                   "E1-ST-08", "E1-ST-09", "E1-ST-14", "E1-ST-15", "E2-ST-01", "E2-ST-02", "E2-ST-05"},
                                  {"E1-P1", "E1-P2", "E2-P1", "E2-P2", "E2-P3", "E2-P4"}),
    # the library's lifts (A3-FG-01, A3-OP-01/02) are named only in the titles of their enlarged details
    "library/A-A3-10-06.dwg": ({"A3-ST-01", "A3-ST-02", "A3-ST-03", "A3-ST-04", "A3-ST-06", "A3-ST-11", "A3-ST-12"}, set()),
    "library/A-A3-10-08.dwg": (set(), set()),
    # 3F and 4F of the library: every code is a stair tag on A3-SYMB-<n>F-100$0$A-SYMB-NUMB-T inside the plan; their
    # lifts are tagged A3-T1/T2/T3 (no lift-code pattern: not counted here; they name lift areas all the same)
    "library/A-A3-10-04.dwg": ({"A3-ST-01", "A3-ST-02", "A3-ST-03", "A3-ST-04", "A3-ST-06", "A3-ST-07", "A3-ST-08",
                                "A3-ST-09", "A3-ST-10"}, set()),
    "library/A-A3-10-05.dwg": ({"A3-ST-01", "A3-ST-02", "A3-ST-03", "A3-ST-04", "A3-ST-06", "A3-ST-09", "A3-ST-10",
                                "A3-ST-11", "A3-ST-12"}, set()),
    # SIST-F5: the whole sheet; the codes of its 5F plan are the tags on E1-/E2-RV-5F$0$A-SYMB-NUMB-T (10 stairs, 3
    # lifts); DWG_VERTICAL_ELSEWHERE lists those written only in the bound 2F xref (see there)
    "sist-original/SIST-F5.dwg": ({"E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06", "E1-ST-07",
                                   "E1-ST-08", "E1-ST-09", "E1-ST-10", "E1-ST-11", "E1-ST-14", "E2-ST-01", "E2-ST-02",
                                   "E2-ST-03"},
                                  {"E1-P1", "E1-P2", "E1-P3/P4", "E1-S1/P1", "E2-P1", "E2-P1/P2", "E2-P2"}),
    "sist-original/SIST-F4.dwg": ({"E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06", "E1-ST-07",
                                   "E1-ST-08", "E1-ST-09", "E1-ST-15", "E1-ST-16", "E2-ST-01", "E2-ST-02", "E2-ST-05"},
                                  {"E1-P2", "E1-P3/P4", "E1-S1/P1", "E2-P1/P2"}),
}


# codes that name a stair/lift area (measured 2026-12-02, session 5: F4 13 -> 16, F1 20 -> 21 and F3 19 -> 20, i.e.
# every code of F1 and F3; F4 16 -> 17: E1-P2's shaft, an empty box of walls (no car cross, no lift-layer entity,
# 11770.6..11773.8 x -6178.1..-6175.7) opening through a doorless gap onto area 107, is carved by its code,
# anchors.coded_lift_recesses). SIST-F4's one left, with the evidence: E2-ST-02's callout hangs 6.7 m north of the
# plan (11766.6, -6071.7) and no stair is drawn within 8 m of it nor where F3's E2-ST-02 registers on F4 (one
# degenerate 0-length line on A-FLOR-STRS; the wing ends at x 11770; re-checked 2026-12-02 on a picture: within
# 8 m of the callout the import keeps 12 wall, 8 window and 2 column entities and no stair-kind one, and the only
# area is a 12.6 m² room 7.3 m away): the code names a stair of another floor's detail
# SIST-F5 (2026-12-02, session 6): 13 of 13 plan codes (E1-ST-01..03, -05..09, E2-ST-01, -02, E1-P1, E2-P1, -P2);
# the nine codes of DWG_VERTICAL_ELSEWHERE are another floor's. E1-P1 (无障碍货梯) stands beside E1-S1 (货梯): its
# empty shaft (a wheelchair sign in it) opens through its door gap onto the lift lobby and was merged into it, the
# lobby named 无障碍货梯, and the code named E1-S1's shaft; since 2026-12-02 a lift code written inside an empty
# walled box names that box (anchors.coded_lift_recesses): its own 5.5 m² elevator area, 3 -> 4 lifts on F5.
# A-A3-10-05 (4F): 9 of 9. A-A3-10-04 (3F): 9 of 9 since 2026-12-02 (session 7, was 8): A3-ST-08 (tag at 11958.6,
# -6417.6) is a fanned flight of 17 treads (A3-RV-3F$0$A-STRS, 2.5 -> 4.5 m long, only the first ones parallel: a 9.1 m²
# run box) standing free in the atrium gallery 中庭回廊, no wall around it; it was left in the hall ("free-standing
# curved flight": the run's box is no footprint of it). anchors.carve_anchors now carves such a flight by its
# chained treads (_flight_ribbon: 17.4 m², passages across its first and last tread) as an island the gallery
# goes round (_keyhole: one ring, never a cut; the gallery was cut in four by its free-standing runs before).
# tests/test_anchors_free_flights.py checks the flight and the gallery round it
TYPED_AT_LEAST = {"sist-original/SIST-F4.dwg": 17, "sist-original/SIST-F1.dwg": 21, "sist-original/SIST-F3.dwg": 20,
                  "library/A-A3-10-06.dwg": 7, "sist-original/SIST-F5.dwg": 13, "library/A-A3-10-05.dwg": 9,
                  "library/A-A3-10-04.dwg": 9}
# A-A3-10-04's lift A3-T3 (tagged A3-T3: no lift-code pattern, so not in the hand count) draws its car block kt1
# (客梯 1) on the stair layer 'A3-RI-3F$0$an-stairs': its shaft was typed stairs, and is an elevator since
# area_types._lift_cars_on_stair_layers (2026-12-02, branch bays: 3F stairs 11 -> 10, elevators 2 -> 3, as on 4F)

# Codes the sheet writes only outside its plan, on another floor's drawing: they name no area of this floor.
# SIST-F5.dwg binds a 2F xref 11.7 km off its 5F plan (the plan lies near 0..140 x -5..130 m, the xref near
# 11690..11850 x -6215..-6070, frozen layers E1-/E2-RI-2F$0$A-TEXT and one on E1-RI-2F$0$$6$A-DIMS-100) whose
# detail callouts 'E1-ST-04详见建施(A-E-40-04)' ... are the 2F's; the 5F plan tags none of these nine, and none is
# drawn there (E1-ST-04 registered from F4 falls on F5's roof, 24, 34: no stair-kind entity)
DWG_VERTICAL_ELSEWHERE = {
    "sist-original/SIST-F5.dwg": {"E1-ST-04", "E1-ST-10", "E1-ST-11", "E1-ST-14", "E2-ST-03",
                                  "E1-P2", "E1-P3/P4", "E1-S1/P1", "E2-P1/P2"},
}


def _dwg_reader():
    try:
        from algorithms import cad_dwg  # noqa: F401  (task A: DWG reading)
    except ImportError:
        pytest.skip("DWG reading (algorithms.cad_dwg) is not available in this build")
    from algorithms import cad_import

    return getattr(cad_dwg, "import_dwg", None) or cad_import.import_dxf


@pytest.mark.slow
@pytest.mark.parametrize("sheet", sorted(DWG_VERTICAL))
def test_dwg_stair_and_lift_names_found(shared_data, sheet):
    read = _dwg_reader()
    drawing = read(str(shared_data / "dwg" / sheet), plan="-1e9,-1e9,1e9,1e9")  # every code on the sheet
    # texts of frozen / off layers count: SIST-F4 freezes the A-TEXT layer holding 15 of its 18 callouts
    labs = S.classify_labels(list(drawing.texts) + list(getattr(drawing, "hidden_texts", [])))
    stairs = {lab.text for lab in labs if lab.role in ("name", "number")
              and (S.type_of_name(lab.text, lab.text) or {}).get("type") == "stairs"}
    lifts = {lab.text for lab in labs if lab.role in ("name", "number")
             and (S.type_of_name(lab.text, lab.text) or {}).get("type") == "elevator" and "-" in lab.text}
    want_st, want_el = DWG_VERTICAL[sheet]
    assert stairs == want_st and lifts == want_el
    chinese = [lab for lab in labs if lab.role == "name" and any("\u4e00" <= ch <= "\u9fff" for ch in lab.text)]
    if sheet.startswith("sist"):
        assert len(chinese) >= 50 and {"办公室", "客梯"} & {lab.text for lab in chinese}


@pytest.mark.slow
@pytest.mark.parametrize("sheet", sorted(DWG_VERTICAL))
def test_dwg_stairs_and_lifts_become_typed_areas(shared_data, sheet, floor_cache):
    _dwg_reader()
    floor = floor_cache.process_floor(shared_data / "dwg" / sheet)  # pipeline.process_floor, shared
    want_st, want_el = DWG_VERTICAL[sheet]
    typed = {}
    for a in floor.refined.areas:
        for code in (a.ref, a.name):
            if code:
                typed.setdefault(code.split(" (")[0], set()).add(a.type)
    plan = [c for c in want_st | want_el if c in typed]
    assert plan or not (want_st | want_el), "no stair or lift of the sheet named an area"
    for code in plan:
        assert typed[code] <= ({"stairs"} if code in want_st else {"elevator"}), (code, typed[code])
    if sheet == "sist-original/SIST-F5.dwg":  # two shafts side by side, each named by its own code and name
        refs = {a.ref: a for a in floor.refined.areas if a.type == "elevator"}
        assert {"E1-P1", "E1-S1"} <= set(refs) and refs["E1-P1"] is not refs["E1-S1"], sorted(refs)
        assert refs["E1-P1"].name.startswith("无障碍货梯") and refs["E1-S1"].name.startswith("货梯")
    # measured: on SIST-F4 16 of the 18 codes name a stair/lift area (9 before stairs and lifts swallowed by a
    # larger area were carved out, anchors.carve_anchors; 13 before a core typed elevator by its break-line
    # cross became a stair (E1-ST-02, -05), callouts just outside the plan were kept (E1-ST-01) and named
    # outdoor stairs became areas (E1-ST-07)); E1-P2 and E2-ST-02: see TYPED_AT_LEAST
    print(sheet, "codes naming a stair/lift area:", len(plan), sorted(plan))
    assert len(plan) >= TYPED_AT_LEAST.get(sheet, 0), sorted(plan)
    elsewhere = DWG_VERTICAL_ELSEWHERE.get(sheet, set())
    assert elsewhere <= want_st | want_el and not elsewhere & set(typed), sorted(elsewhere & set(typed))
    assert TYPED_AT_LEAST.get(sheet, 0) <= len(want_st | want_el) - len(elsewhere)
    for a in floor.refined.areas:  # a code never makes an atrium a stair
        if a.type in ("stairs", "elevator") and any(c in (a.ref or "") for c in want_st | want_el):
            assert a.polygon.area <= 80.0, (a.name, a.polygon.area)
    if sheet.startswith("sist"):
        assert sum(1 for a in floor.refined.areas if any("\u4e00" <= ch <= "\u9fff" for ch in a.name)) >= 10


# Issue 8/9 figures per DWG sheet (make evaluate-cad): >= 95 % of the room-name texts inside an area and
# >= 90 % naming an area of their own, per plan. Below it, with the evidence (a picture and the texts):
DWG_NAMES_KNOWN_BELOW = {
    # library/A-A3-10-06.dwg reaches the targets since 2026-12-02 (session 6: 88.6 / 88.6 -> 100 / 100 %): the atrium
    # gallery 中庭回廊 (six tags), ~1,900 m² between the two wings, opens through a colonnade onto a terrace; the
    # 12 m footprint piece holding its tags (gallery + terrace, 2,703 m²) was too large to be believed, so four
    # tags lay outside; the gallery is now kept inside up to its mouth (segmentation._claim_named_bays)
}
# measured 2026-12-01 (session 4): (inside %, own %, conflicts at most), kept as floors against regressions;
# A-A3-10-06 88 / 88 -> 100 / 100 (2026-12-02, named bays);
# SIST-F1: the passage 通道 between the wings is an area since the named-passage rule, holding two labels (通道,
# 残疾人出入口): inside 96.4 -> 98.2 %, own 93.6 -> 92.7 %, conflicts 3 -> 4;
# named parts split at a door drawn across their area (semantics._split_at_doors, 2026-12-02): SIST-F1 own
# 92.7 -> 94.5 %, conflicts 4 -> 3 (走道 and 大厅, 储藏室 and 开水间 apart; 清洁间 off its lobby); SIST-F3 own
# 96.7 -> 98.4 %, conflicts 2 -> 1 (开水间 and 走道 apart; two 清洁间 closets off their lobbies); session 7:
# SIST-F3's two '开水间' labels of water points in corridor branches no longer name the branches (ignored,
# 'point in a corridor'): 122 -> 120 room texts, own 98.4 -> 98.3 % (the same two misses, fewer texts); then
# partition walls on layers no rule names split two names (cad_classify.stray_wall_partitions): SIST-F1 own
# 94.5 -> 96.3 %, conflicts 3 -> 2 (空调机房 / 开水间); SIST-F3 own 98.3 -> 100 %, conflicts 1 -> 0 (弱电间 / 强电间)
DWG_NAMES_FLOORS = {
    "library/A-A3-10-04.dwg": (100.0, 100.0, 0), "library/A-A3-10-05.dwg": (100.0, 100.0, 0),
    "library/A-A3-10-06.dwg": (100.0, 100.0, 0), "sist-original/SIST-F1.dwg": (98.0, 96.0, 2),
    "sist-original/SIST-F3.dwg": (97.0, 99.0, 0), "sist-original/SIST-F4.dwg": (99.0, 98.0, 1),
    "sist-original/SIST-F5.dwg": (97.0, 98.0, 0),
}


@pytest.mark.slow
@pytest.mark.parametrize("sheet", sorted(DWG_NAMES_FLOORS) + ["library/A-A3-10-08.dwg"])
def test_dwg_room_name_figures(shared_data, sheet, floor_cache):
    _dwg_reader()
    floor = floor_cache.process_floor(shared_data / "dwg" / sheet)  # pipeline.process_floor, shared
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    if sheet.endswith("A-A3-10-08.dwg"):  # a roof plan: its labels are roof elements ('卷轴斜墙顶面'), no rooms
        assert fig["room_texts"] == 0
        return
    inside, own, conflicts = DWG_NAMES_FLOORS[sheet]
    assert fig["inside_pct"] >= inside and fig["own_area_pct"] >= own and fig["conflicts"] <= conflicts, fig
    assert fig["semantic_accuracy_pct"] >= 95.0, fig
    if fig["inside_pct"] < 95.0 or fig["own_area_pct"] < 90.0:
        assert sheet in DWG_NAMES_KNOWN_BELOW, fig
        pytest.xfail(f"{sheet}: {fig['inside_pct']:.1f} % inside, {fig['own_area_pct']:.1f} % own: "
                     f"{DWG_NAMES_KNOWN_BELOW[sheet]}")
    assert sheet not in DWG_NAMES_KNOWN_BELOW, f"{sheet} reaches the targets now: remove it from DWG_NAMES_KNOWN_BELOW"


def test_invalid_polygons_do_not_stop_naming():
    bowtie = Polygon([(0, 0), (4, 4), (4, 0), (0, 4)])  # self-intersecting
    areas = [Area(id=1, polygon=bowtie), Area(id=2, polygon=box(10, 0, 14, 4))]
    rep = S.assign_names(areas, [T("Office A", 1, 2), T("Office B", 3, 2), T("Store", 12, 2)])
    assert areas[1].name == "Store" and rep.counts()["labels"] == 3


def test_detail_callouts_name_the_nearest_stair_never_the_corridor():
    corridor = Area(id=1, polygon=box(0, 0, 30, 3), type="corridor")
    stair = Area(id=2, polygon=box(10, 3, 14, 9), type="stairs")
    lift = Area(id=3, polygon=box(14, 3, 16, 5), type="elevator")
    far_stair = Area(id=4, polygon=box(40, 0, 44, 6), type="stairs")
    areas = [corridor, stair, lift, far_stair]
    rep = S.assign_names(areas, [T("E1-ST-01详见建施(A-E-40-01)", 9, 1.5), T("E1-P2详见建施(A-E-40-19)", 15, 1.5),
                                 T("E1-ST-09详见建施(A-E-40-09)", 25, 1.5), T("走道", 5, 1.5)])
    assert (stair.name, stair.ref) == ("E1-ST-01", "E1-ST-01") and (lift.ref, lift.type) == ("E1-P2", "elevator")
    assert corridor.name == "走道" and corridor.type == "corridor" and not corridor.ref
    assert far_stair.ref == ""  # 15 m away: the callout is left unassigned (counted outside)
    assert rep.counts()["outside"] == 1


# ------------------------------------------------------------------ texts that name no space where they lie
def test_a_label_drawn_twice_is_one_label():
    # a room-tag block inserted twice at the same point (library sheets: every tag twice)
    tag = dict(layer="A-SYMB", entity="ATTRIB", block="ECADI-TAG-ROOM", tag="CHINESENAME", h=0.45)
    labs = S.classify_labels([T("前室", 3, 2, id=1, **tag), T("前室", 3, 2, id=2, **tag)])
    assert [(l.text, l.ids) for l in labs] == [("前室", [1, 2])]
    # the same name copied to a layer for another print scale: shifted by a line, half the height (SIST-F1)
    labs = S.classify_labels([T("大厅", 10.0, 5.0, layer="I-平面-文字", h=0.6, id=3),
                              T("大厅", 10.26, 5.95, layer="I-平面-文字(放大1:100)", h=0.3, id=4)])
    assert [l.ids for l in labs] == [[3, 4]]
    # two rooms of one name side by side stay two labels; so does one name repeated along a long space
    labs = S.classify_labels([T("WC", 1, 1, h=0.3, id=5), T("WC", 2.2, 1, h=0.3, id=6),
                              T("中庭回廊", 0, 0, h=0.45, id=7), T("中庭回廊", 12, 3, h=0.45, id=8)])
    assert len(labs) == 4
    # and the figures count the label once: one name, naming its area
    areas = [Area(id=1, polygon=box(0, 0, 6, 5))]
    rep = S.assign_names(areas, [T("前室", 3, 2, id=1, **tag), T("前室", 3, 2, id=2, **tag)])
    fig = S.floor_figures(areas, [], rep)
    assert fig["room_texts"] == 1 and fig["own_area_pct"] == 100.0 and areas[0].tags["label_texts"] == "1;2"


def test_a_label_on_a_pillar_is_inside_its_room():
    # the name's insertion point falls on a pillar (a small hole of the room): inside the room, not nearby
    room = box(0, 0, 6, 5).difference(box(2.8, 2.3, 3.3, 2.8))
    areas = [Area(id=1, polygon=room), Area(id=2, polygon=box(6.2, 0, 9, 5))]
    rep = S.assign_names(areas, [T("AMBIENTE 15", 3.0, 2.5)])
    assert areas[0].name == "AMBIENTE 15" and rep.texts[0].match == "inside"
    assert S.floor_figures(areas, [], rep)["inside_pct"] == 100.0
    # a courtyard (a large hole) is no pillar: a label in it lies outside the ring around it
    ring = box(0, 0, 20, 20).difference(box(4, 4, 16, 16))
    areas = [Area(id=1, polygon=ring)]
    rep = S.assign_names(areas, [T("Patio", 10, 10)])
    assert rep.texts[0].match != "inside"
    # an area standing in the hole keeps its own label
    areas = [Area(id=1, polygon=box(0, 0, 6, 5).difference(box(2, 2, 3.5, 3.5))),
             Area(id=2, polygon=box(2, 2, 3.5, 3.5))]
    S.assign_names(areas, [T("Lift lobby", 2.8, 2.8)])
    assert areas[1].name == "Lift lobby" and areas[0].name != "Lift lobby"


def test_shaft_labels_beside_a_room_are_no_conflict():
    # '加压' (pressurisation shaft) written in the hall beside its shaft, a closed cavity of the wall
    areas = [Area(id=1, polygon=box(0, 0, 20, 15)), Area(id=2, polygon=box(0, 15, 4, 19))]
    texts = [T("媒体实验室", 10, 10, layer="A-ROOM"), T("加压", 9, 2.5, layer="A-ROOM"),
             T("水井", 30, 30, layer="A-ROOM"), T("Shaft", 2, 17), T("电梯厅", 2, 18)]
    pr = RecordingProgress()
    rep = S.assign_names(areas, texts, progress=pr)
    assert areas[0].name == "媒体实验室" and "label_conflict" not in areas[0].tags and not rep.conflicts
    reasons = {r.text: (r.role, r.reason) for r in rep.texts}
    assert reasons["加压"] == ("ignored", "shaft label") and reasons["水井"] == ("ignored", "shaft label")
    assert rep.counts()["ignored_by_reason"]["shaft label"] == 3
    assert areas[1].name == "电梯厅"  # the lift lobby's name wins over the shaft beside it
    # a shaft segmentation made an area of keeps its label
    areas = [Area(id=1, polygon=box(0, 0, 2, 2)), Area(id=2, polygon=box(2.2, 0, 9, 5))]
    rep = S.assign_names(areas, [T("风井", 1, 1), T("办公室", 5, 2.5)])
    assert areas[0].name == "风井" and rep.texts[0].role == "name"


def test_outdoor_and_roof_labels_are_no_room_names():
    areas = [Area(id=1, polygon=box(0, 0, 10, 8))]
    rep = S.assign_names(areas, [T("室外庭院", 30, 3), T("排水暗沟", 40, 3), T("办公室", 5, 4)])
    reasons = {r.text: (r.role, r.reason) for r in rep.texts}
    assert reasons["室外庭院"] == ("ignored", "outdoor") == reasons["排水暗沟"]
    fig = S.floor_figures(areas, [], rep)
    assert fig["room_texts"] == 1 and fig["inside_pct"] == 100.0
    # a courtyard segmentation made an area of keeps its name
    areas = [Area(id=1, polygon=box(0, 0, 10, 8))]
    rep = S.assign_names(areas, [T("室外庭院", 5, 4)])
    assert areas[0].name == "室外庭院" and rep.texts[0].role == "name"
    # roof plans label building elements, not rooms ('scroll slanted wall, top face', parapet, gutter)
    tag = dict(layer="A-SYMB", block="ECADI-TAG-ROOM", tag="CHINESENAME")
    for text in ("卷轴斜墙顶面", "女儿墙", "天沟"):
        assert S.classify_text(text, **tag) == ("ignored", "note"), text


def test_copies_of_a_label_name_the_area_no_other_name_labels():
    # 'WC' drawn at 0.6 m and copied at 0.3 m one line up on a 1:100 layer; the first copy falls in the
    # office next door (near its centre), the other in the WC: the WC is named, the office keeps its name
    areas = [Area(id=1, polygon=box(0, 0, 4, 4)), Area(id=2, polygon=box(4.2, 0, 7, 4))]
    texts = [T("Office", 2, 2.6, layer="A-ROOM", h=0.6), T("WC", 3.5, 1.9, layer="A-TEXT", h=0.6),
             T("WC", 4.5, 2.2, layer="A-TEXT-100", h=0.3)]
    rep = S.assign_names(areas, texts)
    assert [a.name for a in areas] == ["Office", "WC"] and not rep.conflicts
    fig = S.floor_figures(areas, [], rep)
    assert fig["room_texts"] == 2 and fig["own_area_pct"] == 100.0 and fig["inside_pct"] == 100.0
    # segmentation still gets every copy as evidence of the inside
    assert len(S.room_name_points(texts)) == 3


@pytest.mark.parametrize("text,reason", [("18.750(结构)", "elevation"), ("+19.700（建筑）", "elevation"),
                                         ("外部参照.\\E-RT-3F .dwg", "cad internals"), ("E-RG-2F.dwg", "cad internals")])
def test_structural_elevations_and_xref_names_are_ignored(text, reason):
    assert S.classify_text(text, layer="I-平面-文字", block="ROOMBLOCK") == ("ignored", reason)


def test_one_character_shaft_labels():
    # '水' / '暖' beside the water / heating shaft, in the WC next to it: no name of the WC
    areas = [Area(id=1, polygon=box(0, 0, 4, 3)), Area(id=2, polygon=box(4.2, 0, 5.2, 1))]
    rep = S.assign_names(areas, [T("女卫生间", 2, 1.5), T("水", 3.6, 0.4), T("暖", 4.7, 0.5)])
    assert areas[0].name == "女卫生间" and not rep.conflicts
    assert {r.text: r.reason for r in rep.texts}["水"] == "shaft label"
    assert areas[1].name == "暖"  # the heating shaft is an area of its own: its label names it
    assert S.classify_text("水泵房")[0] == "name"  # a pump room is a room


def test_three_names_split_in_rounds_at_a_door_and_at_a_wide_opening():
    # a 20 x 14 m hall; a 10 x 10 m room opens onto it through a 4.5 m wide opening (wider than any door);
    # a 2 m corridor is joined to the hall by a 1 m door. Three names: the corridor comes off first (at
    # the door), the room at its wide opening in a second round
    hall = box(0, 0, 20, 14)
    room = box(20.2, 2, 30.2, 12).union(box(19.9, 4.75, 20.3, 9.25))  # 4.5 m opening
    corridor = box(0, 14.2, 20, 16.2).union(box(9.5, 13.9, 10.5, 14.3))  # 1 m door
    poly = hall.union(room).union(corridor)
    areas = [Area(id=1, polygon=poly)]
    pr = RecordingProgress()
    rep = S.assign_names(areas, [T("Hall", 10, 7), T("Reading room", 25, 7), T("Corridor", 15, 15.2)],
                         progress=pr)
    by_name = {a.name: a for a in areas}
    assert set(by_name) == {"Hall", "Reading room", "Corridor"} and not rep.conflicts, [a.name for a in areas]
    assert by_name["Reading room"].polygon.area == pytest.approx(100, rel=0.08)
    assert by_name["Corridor"].polygon.area == pytest.approx(40, rel=0.08)
    assert sum(a.polygon.area for a in areas) == pytest.approx(poly.area, rel=1e-6)
    assert len(rep.splits) == 2
    # an opening as wide as the room itself is no narrowing: a conflict, not a split
    areas = [Area(id=1, polygon=box(0, 0, 20, 14).union(box(20, 2, 26, 12)))]
    rep = S.assign_names(areas, [T("Hall", 10, 7), T("Reading room", 23, 7)])
    assert not rep.splits and rep.conflicts == [1]


def test_a_name_in_the_wall_beside_a_small_room_keeps_the_room():
    # a 4 m² store room and a 6 m² boiled-water room behind one 0.2 m wall; the store's name starts in
    # the wall, 9 cm from its room: without it the merge gave the store to its neighbour (SIST-F3)
    from algorithms import refine

    store, boiler = box(0, 0, 2, 2), box(2.2, 0, 5.2, 2)
    hall = box(0, 2.2, 20, 10)
    areas = [Area(id=1, polygon=store), Area(id=2, polygon=boiler), Area(id=3, polygon=hall)]
    texts = [T("储藏室", -0.09, 1.0), T("开水间", 3.7, 1.0)]
    saved = S.protect_labelled_areas(areas, texts, min_area=10.0)
    assert set(saved) == {1, 2}
    # a name far from any small area protects nothing; a name inside a big area protects nothing else
    fresh = [Area(id=1, polygon=store), Area(id=3, polygon=hall)]
    assert S.protect_labelled_areas(fresh, [T("储藏室", -1.0, 1.0), T("大厅", 10, 2.1)], min_area=10.0) == {}
    # through the merge: both small rooms survive and get their names
    kept, _, info = refine.merge_small_areas(areas, [], 10.0, keep_types=refine.KEEP_TYPES + (S.PROTECTED_TYPE,))
    S.restore_types(saved, kept)
    assert {a.id for a in kept} == {1, 2, 3} and info["merged"] == 0
    S.assign_names(kept, texts)
    assert {a.id: a.name for a in kept}[1] == "储藏室" and {a.id: a.name for a in kept}[2] == "开水间"


def test_a_zone_of_an_open_space_is_no_second_room():
    # library A-A3-10-04: the atrium gallery (named seven times) holds '阅览区(随意开放性坐区)', a reading
    # zone with free seating, with no wall nor narrowing between them: one space, no conflict
    gallery = box(0, 0, 60, 12)
    tag = dict(layer="A-SYMB", entity="ATTRIB", block="ECADI-TAG-ROOM", tag="CHINESENAME", h=0.45)
    texts = [T("中庭回廊", 8, 6, **tag), T("中庭回廊", 30, 6, **tag), T("阅览区(随意开放性坐区)", 52, 6, **tag)]
    areas = [Area(id=1, polygon=gallery)]
    rep = S.assign_names(areas, texts)
    assert areas[0].name == "中庭回廊" and not rep.conflicts and "label_conflict" not in areas[0].tags
    assert {r.text: r.reason for r in rep.texts}["阅览区(随意开放性坐区)"] == "zone in a named space"
    assert S.floor_figures(areas, [], rep)["own_area_pct"] == 100.0
    # a zone walled off as an area of its own keeps its name; two rooms in one area are still a conflict
    areas = [Area(id=1, polygon=box(0, 0, 10, 8)), Area(id=2, polygon=box(10.2, 0, 20, 8))]
    S.assign_names(areas, [T("办公区", 5, 4), T("Office", 15, 4)])
    assert [a.name for a in areas] == ["办公区", "Office"]
    areas = [Area(id=1, polygon=box(0, 0, 12, 5))]
    rep = S.assign_names(areas, [T("会议室", 3, 2.5), T("办公室", 9, 2.5)])
    assert rep.conflicts == [1]


def test_a_shaft_label_in_a_stair_core_is_not_its_name():
    # '暖' (heating duct) written inside a stair core typed from its treads labels the duct in the core's
    # wall: the stair keeps the code its callout gives (SIST-F4: the E1-ST-01 core was named '暖')
    core = Area(id=1, polygon=box(0, 0, 8, 5), type="stairs")
    office = Area(id=2, polygon=box(8.2, 0, 14, 5))
    rep = S.assign_names([core, office], [T("暖", 7.5, 4.5), T("风井", 13.5, 4.5), T("办公室", 11, 2.5)],
                         hidden_texts=[T("E1-ST-01详见建施(A-E-40-01)", 4, -3, layer="A-TEXT")])
    assert (core.name, core.ref, core.type) == ("E1-ST-01", "E1-ST-01", "stairs")
    reasons = {r.text: r.reason for r in rep.texts}
    assert reasons["暖"] == "shaft label" and office.name == "办公室"
    # a shaft segmentation made an area of keeps its label; so does a lift lobby named '电梯厅'
    shaft = Area(id=3, polygon=box(0, 0, 1, 1))
    S.assign_names([shaft], [T("暖", 0.5, 0.5)])
    assert shaft.name == "暖"


def test_stair_callouts_beside_the_plan_are_kept():
    # frozen-layer callouts hang at the end of leaders drawn out of the plan: 2 m below it (SIST-F4 E1-ST-01)
    # is the plan's; a room name there, or a callout 20 m away (another view), is not
    from algorithms import cad_import

    raw = [(50.0, -2.0, "E1-ST-01详见建施(A-E-40-01)", 0.35, 0.0, "A-TEXT", "TEXT", "", ""),
           (50.0, -3.0, "办公室", 0.35, 0.0, "A-TEXT", "TEXT", "", ""),
           (50.0, -20.0, "E1-ST-09详见建施(A-E-40-09)", 0.35, 0.0, "A-TEXT", "TEXT", "", ""),
           (105.0, 30.0, "E2-P1详见建施(A-E-40-19)", 0.35, 0.0, "A-TEXT", "MTEXT", "*U5", ""),
           (50.0, 20.0, "E1-ST-02详见建施(A-E-40-02)", 0.35, 0.0, "A-TEXT", "TEXT", "", "")]
    extent = (0.0, 0.0, 100.0, 60.0)
    inside = cad_import._hidden_texts(raw, 1.0, extent, 10)
    beside = cad_import._callouts_beside_plan(raw, 1.0, extent, 10 + len(inside))
    assert [t.text for t in inside] == ["E1-ST-02详见建施(A-E-40-02)"]
    assert sorted(t.text[:8] for t in beside) == ["E1-ST-01", "E2-P1详见建"]
    assert sorted(t.id for t in beside) == [11, 12]
    assert cad_import._callouts_beside_plan(raw, 1.0, None, 0) == []  # no plan picked: every text is kept anyway


def test_a_washroom_behind_its_door_splits_off_the_room_it_opens_onto():
    # schema-ufficio-1: a 2.1 x 1.3 m washroom entered through a 0.85 m door from the bar's back room, one
    # area with it: the door takes 65 % of the washroom's width (more than the 60 % a wide opening may), but an
    # opening no wider than a door is a doorway up to 80 % of the pieces' width
    big = box(0, 0, 10, 8)
    wash = box(10.2, 3.0, 12.3, 4.3).union(box(9.9, 3.225, 10.3, 4.075))  # 0.85 m door in a 0.2 m wall
    poly = big.union(wash)
    areas = [Area(id=1, polygon=poly)]
    rep = S.assign_names(areas, [T("area bar", 5, 4), T("washroom", 11.3, 3.65)])
    by_name = {a.name: a for a in areas}
    assert set(by_name) == {"area bar", "washroom"} and not rep.conflicts and len(rep.splits) == 1
    assert by_name["washroom"].polygon.area == pytest.approx(2.1 * 1.3, rel=0.15)
    # the same washroom open over its whole width (no door) stays one area with the room: a conflict
    areas = [Area(id=1, polygon=big.union(box(10, 3.0, 12.3, 4.3)))]
    rep = S.assign_names(areas, [T("area bar", 5, 4), T("washroom", 11.3, 3.65)])
    assert not rep.splits and rep.conflicts == [1]


def _corridor_with_branch(rooms_on_branch: int):
    """A 2 m wide corridor 0..32 m, a door drawn across it at x 20; rooms along it (4 m wide, above it),
    ``rooms_on_branch`` of them along the branch 20..32; passages from the corridor to every room."""
    from algorithms.model import DoorHint, Passage

    corridor = box(0, 0, 32, 2)
    areas = [Area(id=1, polygon=corridor)]
    passages = []
    xs = [0, 4, 8, 12, 16] + [20 + 4 * k for k in range(rooms_on_branch)]
    for k, x in enumerate(xs, 2):
        areas.append(Area(id=k, polygon=box(x, 2.2, x + 4, 6), name=f"R{k}"))
        passages.append(Passage(id=k, from_id=1, to_id=k, line=LineString([(x + 1.5, 2.0), (x + 2.5, 2.0)])))
    return areas, passages, [DoorHint(20.0, 0.0, 20.0, 2.0, "block")]


def test_a_room_label_in_a_corridor_branch_behind_a_door_marks_a_point_along_it():
    # SIST-F3: a corridor's branch behind its double door, six offices opening onto it, carries '开水间' where a
    # water boiler stands along its wall: the branch splits off at the door, but it is a corridor, not the 开水间
    areas, passages, doors = _corridor_with_branch(3)
    rep = S.assign_names(areas, [T("走道", 8, 1), T("开水间", 21, 1)], passages=passages, door_hints=doors)
    corridor = [a for a in areas if a.polygon.bounds[1] < 1]
    assert len(corridor) == 2 and len(rep.splits) == 1 and not rep.conflicts
    main, branch = sorted(corridor, key=lambda a: a.polygon.bounds[0])
    assert main.name == "走道" and main.type == "corridor"
    assert branch.polygon.bounds[0] == pytest.approx(20.0) and branch.name == S.auto_id("1", branch.id)
    assert branch.type == "corridor"
    assert [r.reason for r in rep.texts if r.text == "开水间"] == ["point in a corridor"]
    assert any({p.from_id, p.to_id} == {main.id, branch.id} for p in passages)
    # a dead-end part behind the door (one room on it: no corridor) is the 开水间: named as before
    areas, passages, doors = _corridor_with_branch(1)
    rep = S.assign_names(areas, [T("走道", 8, 1), T("开水间", 21, 1)], passages=passages, door_hints=doors)
    assert {a.name for a in areas} >= {"走道", "开水间"} and not rep.conflicts


def test_a_room_label_in_a_corridor_piece_of_a_narrowing_split_marks_a_point_along_it():
    # SIST-F3: an upper corridor along eight offices, joined to the main corridor through a narrowing, with
    # '开水间' at a water point along its wall: split at the narrowing, it is a corridor named by no label
    from algorithms.model import OccupancyGrid, Passage

    main = box(0, 0, 30, 3)
    upper = box(0, 4, 30, 6.5)
    neck = box(14.5, 2.9, 15.5, 4.1)  # a 1 m doorway between them
    areas = [Area(id=1, polygon=main.union(upper).union(neck))]
    passages = []
    for k, x in enumerate(range(0, 30, 6), 2):  # five offices along the upper corridor, above it
        areas.append(Area(id=k, polygon=box(x, 6.7, x + 6, 10), name=f"R{k}"))
        passages.append(Passage(id=k, from_id=1, to_id=k, line=LineString([(x + 2.5, 6.5), (x + 3.5, 6.5)])))
    grid = OccupancyGrid(np.zeros((10, 10), np.uint8), 0.0, 10.0, 0.05)
    rep = S.assign_names(areas, [T("走道", 8, 1.5), T("开水间", 27, 5)], passages=passages, grid=grid)
    pieces = sorted([a for a in areas if a.id == 1 or a.id > 6], key=lambda a: a.polygon.centroid.y)
    assert len(pieces) == 2 and len(rep.splits) == 1 and not rep.conflicts
    assert pieces[0].name == "走道" and pieces[1].name == S.auto_id("1", pieces[1].id)
    assert pieces[1].type == "corridor" and [r.reason for r in rep.texts if r.text == "开水间"] == ["point in a corridor"]


def test_a_name_with_another_floors_prefix_yields_to_its_plain_spelling(monkeypatch):
    # A-A3-10-04 (3F): the atrium gallery spans floors and carries seven copies of its label, some written
    # '2F中庭回廊' (copied from the 2F sheet), some '中庭回廊': one name for the names stage (_key drops the
    # prefix); the best-placed copy is a '2F' one, but the plan's name is the plain spelling
    def run(level="1", texts=None):
        areas = [Area(id=1, polygon=box(0, 0, 40, 20))]
        texts = texts or [T("2F中庭回廊", 20, 10), T("中庭回廊", 3, 3), T("2F 中庭回廊", 37, 17)]
        rep = S.assign_names(areas, texts, level=level)
        return areas[0], rep

    a, rep = run()
    assert a.name == "中庭回廊" and "label_conflict" not in a.tags and not rep.conflicts
    assert a.tags["label_score"] == f"{max(r.score for r in rep.texts):.1f}"  # the best copy still scores it
    # every copy prefixed: the one naming this plan's level, else the best-placed one
    prefixed = [T("2F中庭回廊", 20, 10), T("3F中庭回廊", 3, 3)]
    assert run("3", prefixed)[0].name == "3F中庭回廊"
    assert run("L3", prefixed)[0].name == "3F中庭回廊"
    assert run("1", prefixed)[0].name == "2F中庭回廊"
    # two copies at one spot (merged into one label): the plain spelling is the label's text
    a, rep = run(texts=[T("2F中庭回廊", 20, 10, layer="A"), T("中庭回廊", 20, 10, layer="B")])
    assert a.name == "中庭回廊" and len([r for r in rep.texts if r.role == "name"]) == 1
    # the rule off: the best-placed copy names the gallery, prefix and all (session 7's slip)
    monkeypatch.setattr(S, "PLAIN_SPELLING", False)
    assert run()[0].name == "2F中庭回廊"
    assert run("3", prefixed)[0].name == "2F中庭回廊"


def test_floor_prefixes_of_a_level():
    assert S._level_prefixes("3") == {"3f"} and S._level_prefixes("L3") == {"3f"} and S._level_prefixes("3F") == {"3f"}
    assert S._level_prefixes("-1") == {"b1"} and S._level_prefixes("B1") == {"b1"}
    assert S._level_prefixes("0") == set() and S._level_prefixes("roof") == set()
    assert S._floor_prefix("2F中庭回廊") == "2f" and S._floor_prefix("中庭回廊") == "" and S._floor_prefix("2F office") == ""


def _long_corridor(doors: int = 8, length: float = 40.0):
    """A 3 m wide corridor ``length`` m long, ``doors`` offices (5 m wide) above it, a passage to each."""
    areas = [Area(id=1, polygon=box(0, 0, length, 3))]
    passages = []
    for k in range(doors):
        x = 5.0 * k
        areas.append(Area(id=k + 2, polygon=box(x, 3.2, x + 5, 8), name=f"R{k}"))
        passages.append(Passage(id=k + 2, from_id=1, to_id=k + 2, line=LineString([(x + 2, 3), (x + 3, 3)])))
    return areas, passages


def test_a_service_room_label_at_a_corridors_end_marks_a_point_along_it(monkeypatch):
    # SIST-F1: a 60 m corridor with 24 doors was '开水间 (2)' after a water point's label at its far end (no
    # corridor label in it, nothing to split); the same kind: a 清洁间 in a corridor's side niche, a 弱电
    # closet label at a corridor's end (A-A3-10-06, SIST-F3)
    def run(text, x, y=1.5, doors=8, length=40.0, box_=None):
        areas, passages = _long_corridor(doors, length)
        if box_ is not None:
            areas[0] = Area(id=1, polygon=box_)
        rep = S.assign_names(areas, [T(text, x, y)], passages=passages)
        return areas[0], rep

    for text in ("开水间", "清洁间", "弱电", "janitor"):
        a, rep = run(text, 1.0)
        assert a.name == S.auto_id("1", 1) and a.type == "corridor", text
        assert [r.reason for r in rep.texts] == ["point in a corridor"] and rep.named == 0
    # controls: the label near the centre names it; a room name no service keyword (前室, a fire lobby: long,
    # narrow and busy); a small area (a 开水间 room of 15 m² with three doors); too few doors (not a corridor)
    assert run("开水间", 20.0)[0].name == "开水间"
    assert run("前室", 1.0)[0].name == "前室"
    assert run("开水间", 0.5, doors=3, box_=box(0, 0, 10, 1.5), y=0.75)[0].name == "开水间"
    assert run("开水间", 1.0, doors=2)[0].name == "开水间"
    # the rule off: the corridor is named after the water point (session 7's slip on SIST-F1)
    monkeypatch.setattr(S, "SERVICE_POINTS", False)
    a, rep = run("开水间", 1.0)
    assert a.name == "开水间" and a.type == "room"


@pytest.mark.slow
def test_dwg_gallery_keeps_its_plain_name_and_corridors_no_water_point_name(shared_data, floor_cache):
    # the session's conversions (test_dwg_room_name_figures): A-A3-10-04's 3F atrium gallery (seven copies of
    # its label, the best-placed one '2F中庭回廊') is '中庭回廊'; SIST-F1's 60 m corridor, '开水间 (2)' after the
    # water point's label at its far end, is a corridor with an auto id, and the two 开水间 rooms keep the name
    _dwg_reader()
    lib = floor_cache.process_floor(shared_data / "dwg" / "library" / "A-A3-10-04.dwg")
    gallery = [a for a in lib.refined.areas if S._key(a.name or "") == S._key("中庭回廊")]
    assert len(gallery) == 1 and gallery[0].name == "中庭回廊" and gallery[0].polygon.area > 1000
    assert not any(S._floor_prefix(a.name or "") for a in lib.refined.areas)
    f1 = floor_cache.process_floor(shared_data / "dwg" / "sist-original" / "SIST-F1.dwg")
    water = [a for a in f1.refined.areas if "开水间" in (a.name or "")]
    assert len(water) == 2 and all(a.polygon.area < 20 for a in water), [(a.name, a.polygon.area) for a in water]
    points = [r for r in f1.names.texts if r.reason == "point in a corridor"]
    assert [r.text for r in points] == ["开水间"]
    by_id = {a.id: a for a in f1.refined.areas}
    corridor = by_id[points[0].area_id]
    assert corridor.type == "corridor" and corridor.polygon.area > 150 and corridor.name == S.auto_id("1", corridor.id)


@pytest.mark.qgis_process
def test_naming_slips_headless(tmp_path):
    # assignnames on small layers: a gallery labelled '2F中庭回廊' (best placed) and '中庭回廊' is '中庭回廊'; a
    # 40 m corridor with eight doors and a '开水间' label at its end is a corridor with a generated id
    from osgeo import ogr

    from .qgis_process import run_alg

    areas, passages = _long_corridor(8)
    areas.append(Area(id=20, polygon=box(0, 20, 40, 40)))
    drv = ogr.GetDriverByName("GPKG")

    def layer(path, geom, fields, rows):
        ds = drv.CreateDataSource(str(path))
        lyr = ds.CreateLayer("l", None, geom)
        for name, typ in fields:
            lyr.CreateField(ogr.FieldDefn(name, typ))
        for g, vals in rows:
            f = ogr.Feature(lyr.GetLayerDefn())
            f.SetGeometry(ogr.CreateGeometryFromWkt(g.wkt))
            for k, v in vals.items():
                f.SetField(k, v)
            lyr.CreateFeature(f)
        ds = None

    layer(tmp_path / "areas.gpkg", ogr.wkbPolygon, [("id", ogr.OFTInteger), ("type", ogr.OFTString)],
          [(a.polygon, {"id": a.id, "type": "room"}) for a in areas])
    layer(tmp_path / "pass.gpkg", ogr.wkbLineString, [("id", ogr.OFTInteger), ("from_id", ogr.OFTInteger),
                                                      ("to_id", ogr.OFTInteger)],
          [(p.line, {"id": p.id, "from_id": p.from_id, "to_id": p.to_id}) for p in passages])
    from shapely.geometry import Point
    texts = [("2F中庭回廊", 20, 30), ("中庭回廊", 3, 23), ("开水间", 1, 1.5)]
    layer(tmp_path / "texts.gpkg", ogr.wkbPoint, [("text", ogr.OFTString), ("id", ogr.OFTInteger)],
          [(Point(x, y), {"text": t, "id": k}) for k, (t, x, y) in enumerate(texts)])
    _, res, log = run_alg("assignnames", {"AREAS": str(tmp_path / "areas.gpkg"), "TEXTS": str(tmp_path / "texts.gpkg"),
                                          "PASSAGES": str(tmp_path / "pass.gpkg"), "LEVEL": "3",
                                          "OUTPUT_AREAS": str(tmp_path / "named.gpkg")})
    ds = ogr.Open(str(tmp_path / "named.gpkg"))
    got = {f.GetField("id"): (f.GetField("name"), f.GetField("type")) for f in ds.GetLayer(0)}
    assert got[20][0] == "中庭回廊" and got[1] == ("3-1", "corridor"), got
    assert "marks a point along it" in log
