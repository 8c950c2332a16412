"""Whole sheets, layer names as delivered and spaghetti drawings (cad_sheet, cad_classify, layer_rules)
on small synthetic inputs and on the sample building's 'delivered' variants."""
import ezdxf
import numpy as np
import pytest
from shapely.geometry import LineString, Point

from algorithms.cad_import import import_dxf, inspect_dxf, list_layers
from algorithms.cad_sheet import parse_plan
from algorithms.errors import InputError
from algorithms.layer_rules import default_rules, keyword_in, meaningful_part, rules_from_dict
from algorithms.sample_building import generate_delivered, ground_truth_doors


def _doc():
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6  # metres
    return doc


def _box(msp, x0, y0, x1, y1, layer="A-WALL", door_gap=None):
    """A room outline as lines; ``door_gap`` = (x_from, x_to) leaves an opening in the south wall."""
    if door_gap:
        msp.add_line((x0, y0), (door_gap[0], y0), dxfattribs={"layer": layer})
        msp.add_line((door_gap[1], y0), (x1, y0), dxfattribs={"layer": layer})
    else:
        msp.add_line((x0, y0), (x1, y0), dxfattribs={"layer": layer})
    msp.add_line((x1, y0), (x1, y1), dxfattribs={"layer": layer})
    msp.add_line((x1, y1), (x0, y1), dxfattribs={"layer": layer})
    msp.add_line((x0, y1), (x0, y0), dxfattribs={"layer": layer})


def _save(doc, tmp_path, name="t.dxf"):
    p = tmp_path / name
    doc.saveas(p)
    return str(p)


def _inside(g, ext, tol=1.0):
    c = g.coords[np.isfinite(g.coords).all(axis=1)]
    x0, y0, x1, y1 = ext
    return c[:, 0].min() >= x0 - tol and c[:, 0].max() <= x1 + tol and c[:, 1].min() >= y0 - tol and \
        c[:, 1].max() <= y1 + tol


# ------------------------------------------------------------------------------------------ layer names
@pytest.mark.parametrize("name,part", [
    ("E1-RI-1F$0$A-WALL", "A-WALL"), ("X$0$$2$A-WALL", "A-WALL"), ("E1-RV-1F$0$$0$A-GLAZ", "A-GLAZ"),
    ("$1$0S-COLS-LINE", "0S-COLS-LINE"), ("SITE|A-WALL", "A-WALL"), ("A-WALL", "A-WALL"), ("X$0$0", "0"),
    ("1F_MURO_NEW", "1F_MURO_NEW")])
def test_meaningful_part_of_bound_xref_names(name, part):
    assert meaningful_part(name) == part


def test_rules_match_the_meaningful_part_not_the_xref_file_name():
    r = default_rules()
    # the xref's file name holds an exclude keyword ('text', 'dim'): the layer is still a wall
    assert r.classify("TEXT-BASE$0$A-WALL")[0] == "wall"
    assert r.classify("DIM-XREF$0$$2$A-WALL")[0] == "wall"
    assert r.classify("E1-RV-1F$0$A-FLOR-STRS")[0] == "stair"
    assert r.classify("E2-RW$0$A-GLAZ-CWMG")[0] == "window"
    assert r.classify("X$0$0")[0] == "reference"  # a bound layer "0" is preserved like "0"
    # prefixes and suffixes around the keyword do not matter
    assert r.classify("3F-A-WALL-EXIST")[0] == "wall"
    # and the meaningful part can still be excluded
    assert r.classify("E1$0$A-ANNO-TEXT")[0] is None


def test_list_layers_reports_the_matched_part(tmp_path):
    doc = _doc()
    for lay in ("E1-RI-1F$0$A-WALL", "X$0$$2$A-GLAZ"):
        doc.layers.add(lay)
    msp = doc.modelspace()
    _box(msp, 0, 0, 10, 8, layer="E1-RI-1F$0$A-WALL")
    msp.add_line((0, 3), (0, 5), dxfattribs={"layer": "X$0$$2$A-GLAZ"})
    infos = {i.name: i for i in list_layers(_save(doc, tmp_path))}
    assert infos["E1-RI-1F$0$A-WALL"].matched == "A-WALL" and infos["E1-RI-1F$0$A-WALL"].kind == "wall"
    assert infos["X$0$$2$A-GLAZ"].matched == "A-GLAZ" and infos["X$0$$2$A-GLAZ"].kind == "window"


def test_short_keywords_match_whole_tokens_only():
    assert keyword_in("wc", "wc_pan") and keyword_in("wc", "bagno-wc2")
    assert not keyword_in("wc", "swc") and not keyword_in("car", "carpet")
    assert keyword_in("chair", "armchair_01")  # longer keywords are substrings
    r = default_rules()
    assert r.block_class(["OFFICE_MODULE", "DOOR_900"]) == ("door", "DOOR_900")
    assert r.block_class(["WORKSTATION", "CHAIR"])[0] == "furniture"
    assert r.block_class(["PORTA_90"])[0] == "door" and r.block_class(["Tür-1"])[0] == "door"
    assert r.block_class(["门M1021"])[0] == "door" and r.block_class(["洁具-坐便"])[0] == "furniture"
    assert r.block_class(["SEDIA"])[0] == "furniture" and r.block_class(["finestra_120"])[0] == "window"
    assert r.block_class(["PIANTA_PIANO_TERRA"])[0] is None and r.block_class(["SWC"])[0] is None


def test_block_keywords_are_configurable():
    r = rules_from_dict({"kinds": {"wall": ["wall"]}, "blocks": {"furniture": ["poltrona"]}})
    assert r.block_class(["POLTRONA_1"])[0] == "furniture"
    assert r.block_class(["CHAIR"])[0] is None  # only the configured keywords
    with pytest.raises(InputError, match="blocks"):
        rules_from_dict({"kinds": {"wall": ["wall"]}, "blocks": {"sofa": ["x"]}})
    # a rules file without the sections gets the built-in block and sheet keywords
    r2 = rules_from_dict({"kinds": {"wall": ["wall"]}})
    assert r2.block_class(["CHAIR"])[0] == "furniture" and "详图" in r2.sheet_words("detail_titles")


# ------------------------------------------------------------------------------------------ texts
def test_texts_carry_block_tag_and_index(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 12, 8)
    tag = doc.blocks.new("ROOM_TAG")
    tag.add_attdef("NAME", (0, 0), dxfattribs={"height": 0.3})
    tag.add_text("label", dxfattribs={"height": 0.2, "insert": (0, -0.5)})
    outer = doc.blocks.new("NEST")
    outer.add_blockref("ROOM_TAG", (0, 0))
    ref = msp.add_blockref("ROOM_TAG", (3, 4))
    ref.add_auto_attribs({"NAME": "Office 1"})
    msp.add_blockref("NEST", (8, 4))
    msp.add_text("Hall", dxfattribs={"height": 0.3, "insert": (6, 2)})
    d = import_dxf(_save(doc, tmp_path))
    by = {(t.text, t.entity): t for t in d.texts}
    att = by[("Office 1", "ATTRIB")]
    assert att.block == "ROOM_TAG" and att.tag == "NAME"
    assert by[("Hall", "TEXT")].block == "" and by[("Hall", "TEXT")].tag == ""
    nested = [t for t in d.texts if t.text == "label" and t.x > 7]
    assert nested and nested[0].block == "ROOM_TAG"  # the innermost block
    assert [t.id for t in d.texts] == list(range(len(d.texts)))


# ------------------------------------------------------------------------------------------ sheets
@pytest.fixture(scope="module")
def sheet(tmp_path_factory):
    return generate_delivered(str(tmp_path_factory.mktemp("sheet")), sheet=True, name="sheet")


def test_sheet_takes_the_main_plan_and_drops_frame_detail_legend(sheet):
    d = import_dxf(sheet["dxf"])
    kinds = [(p.index, p.kind) for p in d.plans]
    assert kinds[0] == (0, "plan") and d.plans[0].selected
    assert ("plan", "detail") == (d.plans[0].kind, d.plans[1].kind) and len(d.plans) == 2
    assert "详图" in d.plans[1].title and "平面图" in d.plans[0].title
    pe = d.plans[0].extent
    assert np.allclose(pe, sheet["plan_extent"], atol=0.6)
    assert np.allclose(d.plans[1].extent, sheet["detail_extent"], atol=0.6)
    # every kept geometry lies on the plan: frame (layer 0, bare rectangle), detail and legend are gone
    assert all(_inside(g, sheet["plan_extent"]) for g in d.geometries)
    assert d.classes.get("frame", 0) >= 1
    names = {t.text for t in d.texts}
    assert "Office 101" in names and "cad2osmag sample sheet" not in names and "LEGEND" not in names
    assert [t.id for t in d.texts] == list(range(len(d.texts)))


def test_sheet_plan_parameter_picks_the_detail(sheet):
    d = import_dxf(sheet["dxf"], plan=1)
    assert d.plans[1].selected and not d.plans[0].selected
    assert d.geometries and all(_inside(g, sheet["detail_extent"]) for g in d.geometries)
    x0, y0, x1, y1 = sheet["detail_extent"]
    d2 = import_dxf(sheet["dxf"], plan=f"{x0 - 1},{y0 - 1},{x1 + 1},{y1 + 1}")
    assert len(d2.geometries) == len(d.geometries)
    with pytest.raises(InputError, match="PLAN=5 does not exist"):
        import_dxf(sheet["dxf"], plan=5)
    with pytest.raises(InputError, match="holds no drawing geometry"):
        import_dxf(sheet["dxf"], plan="500,500,600,600")


def test_parse_plan():
    assert parse_plan(None) is None and parse_plan("") is None and parse_plan("2") == 2 and parse_plan(3) == 3
    assert parse_plan("1,2,3,4") == (1, 2, 3, 4)
    assert parse_plan("1,3,2,4 [EPSG:3857]") == (1, 2, 3, 4)  # QGIS extent text: xmin,xmax,ymin,ymax
    for bad in ("abc", "1,2,3", "3,3,1,1", -1):
        with pytest.raises(InputError):
            parse_plan(bad)


def _building(msp, x0, w=30.0, h=16.0, layer="A-WALL"):
    _box(msp, x0, 0, x0 + w, h, layer)
    for k in range(1, 5):
        x = x0 + k * w / 5
        msp.add_line((x, 0), (x, 6), dxfattribs={"layer": layer})
        msp.add_line((x, 9), (x, h), dxfattribs={"layer": layer})


def test_two_halves_side_by_side_stay_two_plans(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _building(msp, 0, w=30)
    _building(msp, 40, w=26)  # a 10 m gap
    msp.add_text("一层平面图 (左)", dxfattribs={"height": 1.0, "insert": (5, -4)})
    d = import_dxf(_save(doc, tmp_path))
    assert [p.kind for p in d.plans] == ["plan", "plan"]
    assert d.plans[0].extent[2] <= 31 and d.plans[1].extent[0] >= 39  # the larger half is the default
    assert all(g.coords[:, 0].max() <= 31 for g in d.geometries)
    d1 = import_dxf(str(tmp_path / "t.dxf"), plan=1)
    assert all(g.coords[:, 0].min() >= 39 for g in d1.geometries)


def test_free_standing_columns_in_a_hall_stay_with_the_plan(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 40, 30)
    for x in (12, 20, 28):  # 12+ m from every wall, 8 m apart
        msp.add_lwpolyline([(x, 15), (x + 0.5, 15), (x + 0.5, 15.5), (x, 15.5)], close=True,
                           dxfattribs={"layer": "A-COLS"})
    d = import_dxf(_save(doc, tmp_path))
    assert len(d.plans) == 1 and sum(g.kind == "column" for g in d.geometries) == 3


def test_sheet_with_only_a_detail_view_is_refused(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _building(msp, 0, w=8, h=6)
    msp.add_text("楼梯放大详图 1:50", dxfattribs={"height": 0.5, "insert": (0, -2)})
    with pytest.raises(InputError, match="detail views.*PLAN="):
        import_dxf(_save(doc, tmp_path))
    assert import_dxf(str(tmp_path / "t.dxf"), plan=0).geometries  # but it can be picked explicitly


def test_sheet_with_no_plan_like_geometry_is_refused(tmp_path):
    doc = _doc()
    doc.layers.add("TK")
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (84, 0), (84, 59), (0, 59)], close=True, dxfattribs={"layer": "TK"})
    msp.add_lwpolyline([(60, 0), (84, 0), (84, 8), (60, 8)], close=True, dxfattribs={"layer": "TK"})
    msp.add_text("图纸目录", dxfattribs={"height": 1.0, "insert": (62, 4), "layer": "TK"})
    with pytest.raises(InputError, match="no plan-like geometry"):
        import_dxf(_save(doc, tmp_path))


def test_a_bare_rectangle_frame_around_the_plan_is_dropped(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _building(msp, 0)
    msp.add_lwpolyline([(-10, -12), (70, -12), (70, 40), (-10, 40)], close=True)  # on layer 0
    d = import_dxf(_save(doc, tmp_path))
    assert d.classes.get("frame") == 1
    assert all(g.coords[:, 0].min() >= -0.01 and g.coords[:, 0].max() <= 30.01 for g in d.geometries)


# ------------------------------------------------------------------------------------------ spaghetti
def _thick(g):
    from algorithms.cad_classify import _thickness

    return _thickness(g.coords)


def _hint_for(door, hints, tol=0.5):
    mid = door["line"].interpolate(0.5, normalized=True)
    return [h for h in hints if LineString([(h.x0, h.y0), (h.x1, h.y1)]).distance(mid) <= tol]


@pytest.mark.parametrize("explode", [False, True])
def test_spaghetti_plan_keeps_doorways_open_and_drops_furniture(tmp_path, explode):
    out = generate_delivered(str(tmp_path), spaghetti=True, explode_doors=explode, name="sp")
    d = import_dxf(out["dxf"])
    assert set(g.layer for g in d.geometries) == {"0"}
    gt = ground_truth_doors(out["ground_truth"])
    found = [dr for dr in gt if _hint_for(dr, d.doors)]
    assert len(found) >= len(gt) - 1, f"{len(found)} of {len(gt)} doors found"
    for h in d.doors:
        assert 0.6 <= h.width <= 2.0
    # no door leaf or swing arc is left across a doorway
    for dr in gt:
        line = dr["line"]
        hits = [g for g in d.geometries if LineString(g.coords).intersects(line.buffer(0.05))
                and g.entity == "ARC"]
        assert not hits
    assert d.classes.get("furniture", 0) >= 50 and d.classes.get("door", 0) >= 30
    assert d.classes.get("hatch", 0) == 2  # the floor patterns of the hall and the WC
    assert not any(g.block in ("CHAIR", "DESK_1600", "WC_PAN", "WASHBASIN", "TABLE_MEETING") for g in d.geometries)
    # the hatched wall sections stay (thin), the floor patterns go
    assert all(_thick(g) < 0.5 for g in d.geometries if g.entity == "HATCH" and not g.filled)
    # the lounge tables (circles on layer 0 standing free in the hall) are furniture by shape
    assert not any(g.entity == "CIRCLE" and 0.3 < np.ptp(g.coords[:, 0]) / 2 < 0.5 for g in d.geometries)


def test_door_swing_becomes_a_hint_from_jamb_to_jamb(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 10, 8, layer="0", door_gap=(4.0, 4.9))
    msp.add_arc((4.0, 0.0), 0.9, 0, 90, dxfattribs={"layer": "0"})  # hinge at (4, 0), closed end (4.9, 0)
    msp.add_line((4.0, 0.0), (4.0, 0.9), dxfattribs={"layer": "0"})  # the open leaf
    d = import_dxf(_save(doc, tmp_path))
    assert len(d.doors) == 1
    h = d.doors[0]
    assert np.allclose(sorted([(h.x0, h.y0), (h.x1, h.y1)]), [(4.0, 0.0), (4.9, 0.0)], atol=0.02)
    assert not any(g.entity == "ARC" for g in d.geometries)
    assert d.classes["door"] == 2


def test_leafless_swing_hinged_at_a_wall_end_is_a_door(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 10, 8, layer="0", door_gap=(4.0, 4.9))
    msp.add_arc((4.0, 0.0), 0.9, 0, 90)  # no leaf: hinge and closed end at the two wall ends
    msp.add_arc((8.0, 8.0), 0.9, 180, 270)  # an arc in a corner region with no wall end at its centre
    d = import_dxf(_save(doc, tmp_path))
    assert len(d.doors) == 1
    h = d.doors[0]
    assert np.allclose(sorted([(h.x0, h.y0), (h.x1, h.y1)]), [(4.0, 0.0), (4.9, 0.0)], atol=0.02)


def test_double_door_is_one_hint(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 10, 8, layer="0", door_gap=(3.0, 4.8))
    msp.add_arc((3.0, 0.0), 0.9, 0, 90)
    msp.add_line((3.0, 0.0), (3.0, 0.9))
    msp.add_arc((4.8, 0.0), 0.9, 90, 180)
    msp.add_line((4.8, 0.0), (4.8, 0.9))
    d = import_dxf(_save(doc, tmp_path))
    assert len(d.doors) == 1 and abs(d.doors[0].width - 1.8) < 0.02


def test_pattern_hatch_is_never_a_wall_but_a_hatched_wall_stays(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 10, 8)
    floor = msp.add_hatch(dxfattribs={"layer": "A-WALL"})
    floor.set_pattern_fill("NET", scale=0.5)
    floor.paths.add_polyline_path([(0.2, 0.2), (9.8, 0.2), (9.8, 7.8), (0.2, 7.8)], is_closed=True)
    wall = msp.add_hatch(dxfattribs={"layer": "A-WALL"})
    wall.set_pattern_fill("ANSI31", scale=0.1)
    wall.paths.add_polyline_path([(0, 8), (10, 8), (10, 8.25), (0, 8.25)], is_closed=True)
    d = import_dxf(_save(doc, tmp_path))
    hatches = [g for g in d.geometries if g.entity == "HATCH"]
    assert len(hatches) == 1 and np.ptp(hatches[0].coords[:, 1]) < 0.3
    assert d.classes["hatch"] == 1


def test_furniture_touching_a_wall_stays_and_free_furniture_goes(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _box(msp, 0, 0, 10, 8, layer="0")
    msp.add_lwpolyline([(4, 3), (5.6, 3), (5.6, 3.8), (4, 3.8)], close=True)  # desk in the room
    msp.add_line((4.3, 3.6), (5.3, 3.6))  # its monitor, inside it
    msp.add_lwpolyline([(0, 5), (0.6, 5), (0.6, 7), (0, 7)], close=True)  # a cupboard against the wall
    col = msp.add_hatch(color=7)  # a column: outline and solid fill, standing free -> stays
    col.paths.add_polyline_path([(7, 4), (7.6, 4), (7.6, 4.6), (7, 4.6)], is_closed=True)
    msp.add_lwpolyline([(7, 4), (7.6, 4), (7.6, 4.6), (7, 4.6)], close=True)
    d = import_dxf(_save(doc, tmp_path))
    assert d.classes["furniture"] == 2
    assert sum(1 for g in d.geometries if np.isclose(np.nanmin(g.coords[:, 0]), 7.0)) == 2
    xs = [g.coords[:, 0].min() for g in d.geometries]
    assert not any(3.9 < x < 4.4 for x in xs)
    assert any(g.closed and np.allclose(g.coords[:, 0].min(), 0) and np.ptp(g.coords[:, 1]) == 2 for g in d.geometries)


def test_inspect_still_lists_every_layer(sheet):
    d = inspect_dxf(sheet["dxf"])
    assert "图框" in d.layers and d.layers["图框"].kind is None


def test_spaghetti_plan_converts_with_open_doorways(tmp_path):
    """The whole pipeline on the layer-"0" variant: every room is reached through its doorway."""
    from algorithms.pipeline import process_floor

    out = generate_delivered(str(tmp_path), spaghetti=True, name="sp")
    floor = process_floor(out["dxf"])
    areas, passages = floor.refined.areas, floor.refined.passages
    assert len(areas) >= 15 and len(passages) >= 15, (len(areas), len(passages))
    linked = {p.from_id for p in passages} | {p.to_id for p in passages}
    assert sum(a.id in linked for a in areas) >= len(areas) - 2  # at most the stair and lift cores unlinked
