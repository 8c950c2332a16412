"""CAD import on small synthetic DXFs written with ezdxf (no real data needed)."""
import math
import os

import ezdxf
import numpy as np
import pytest

from algorithms.cad_import import choose_unit, import_dxf, inspect_dxf, list_layers
from algorithms.errors import InputError
from algorithms.layer_rules import default_rules, load_rules
from algorithms.progress import RecordingProgress


def new_doc(units=4):
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = units
    return doc


def save(doc, tmp_path, name="plan.dxf"):
    p = tmp_path / name
    doc.saveas(p)
    return str(p)


def room(msp, x0, y0, w, h, layer="A-WALL"):
    """A closed rectangle of 4 LINEs."""
    pts = [(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)]
    for a, b in zip(pts, pts[1:] + pts[:1]):
        msp.add_line(a, b, dxfattribs={"layer": layer})


def bounds(geoms):
    c = np.concatenate([g.coords for g in geoms])
    c = c[np.isfinite(c).all(axis=1)]
    return c.min(axis=0), c.max(axis=0)


# ----------------------------------------------------------------------------------------- rules
@pytest.mark.parametrize("name,kind", [
    ("A-WALL", "wall"), ("a-wall-full", "wall"), ("E1-RI-1F$0$A-WALL", "wall"), ("A—墙体", "wall"),
    ("MURATURA sezioni - section wall", "wall"), ("muri", "wall"), ("Muro portante", "wall"), ("Wand", "wall"),
    ("Tabiqueria", "wall"), ("стены", "wall"), ("A-COLS", "column"), ("PILASTRI struttura", "column"),
    ("柱", "column"), ("A-STAIR", "stair"), ("A-FLOR-STRS", "stair"), ("楼梯", "stair"), ("Treppe", "stair"),
    ("A-EVTR", "elevator"), ("电梯", "elevator"), ("A-GLAZ", "window"), ("窗", "window"),
    ("VETRATE sezioni - windows", "window"), ("A-DOOR", "door"), ("门", "door"), ("PUERTAS", "door"),
    ("Türen", "door"), ("0", "reference"), ("Defpoints", "reference"), ("DEFPOINTS", "reference"),
    ("A-ANNO-TEXT", None), ("QUOTE - dimension", None), ("ARREDI attrezzature - furniture", None),
    ("J-WINDOW_TEXT门窗编号", None), ("A-WALL-DIMS", None), ("mobiliario", None), ("Pluma 8", None),
    ("PARETI", "wall"), ("STRUTTURA PORTANTE", "wall"), ("Cerramientos", "wall"), ("A-COLU", "column"),
    ("S-COLU", "column"), ("A-ANNO-SCALE", None),
])
def test_default_rules_classify(name, kind):
    assert default_rules().classify(name)[0] == kind


def test_mixed_door_window_layer_is_kept_as_window():
    # a layer holding doors and windows must stay in the raster (windows close the facade)
    assert default_rules().classify("PORTE finestre - doors windows")[0] == "window"
    assert default_rules().classify("A—门窗")[0] == "window"


def test_load_rules_custom_and_errors(tmp_path):
    p = tmp_path / "rules.json"
    p.write_text('{"kinds": {"wall": ["pluma 8"]}, "exclude": ["txt"]}', encoding="utf-8")
    r = load_rules(str(p))
    assert r.classify("PLUMA 8")[0] == "wall"
    assert r.classify("Pluma 8 txt")[0] is None
    assert r.classify("0")[0] == "reference"  # preserved by default
    bad = tmp_path / "bad.json"
    bad.write_text("{kinds: ", encoding="utf-8")
    with pytest.raises(InputError, match="not valid JSON"):
        load_rules(str(bad))
    bad.write_text('{"kinds": {"walls": ["x"]}}', encoding="utf-8")
    with pytest.raises(InputError, match="unknown category 'walls'"):
        load_rules(str(bad))
    with pytest.raises(InputError, match="does not exist"):
        load_rules(str(tmp_path / "missing.json"))


# ----------------------------------------------------------------------------------------- geometry
def test_lines_in_mm_become_metres(tmp_path):
    doc = new_doc(4)
    room(doc.modelspace(), 0, 0, 20000, 10000)
    d = import_dxf(save(doc, tmp_path))
    assert d.unit_name == "mm" and d.unit_scale == 0.001 and d.header_unit == "mm"
    lo, hi = bounds(d.geometries)
    assert np.allclose(lo, (0, 0)) and np.allclose(hi, (20, 10))
    assert all(g.kind == "wall" and g.layer == "A-WALL" and g.entity == "LINE" for g in d.geometries)
    assert not d.warnings


def test_blocks_transforms_layer0_inheritance_and_nesting(tmp_path):
    doc = new_doc(6)
    inner = doc.blocks.new("INNER")
    inner.add_line((0, 0), (1, 0), dxfattribs={"layer": "0"})
    outer = doc.blocks.new("OUTER", base_point=(1, 1))
    outer.add_blockref("INNER", (1, 1), dxfattribs={"layer": "0", "xscale": 2, "yscale": 2})
    outer.add_line((1, 1), (1, 2), dxfattribs={"layer": "A-COLS"})  # keeps its own layer
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10)
    # rotation 90 deg, insert at (10, 5); base point (1, 1) -> block origin shifted
    msp.add_blockref("OUTER", (10, 5), dxfattribs={"layer": "A-WALL", "rotation": 90})
    # mirrored copy (negative x scale) on a furniture layer: inherited geometry is dropped
    msp.add_blockref("OUTER", (3, 3), dxfattribs={"layer": "FURNITURE", "xscale": -1})
    d = import_dxf(save(doc, tmp_path))
    # INNER line: (0,0)-(1,0) scaled 2 -> (0,0)-(2,0), at (1,1) in OUTER -> (1,1)-(3,1);
    # minus base (1,1) -> (0,0)-(2,0); rotated 90 -> (0,0)-(0,2); at (10,5) -> (10,5)-(10,7)
    hits = [g for g in d.geometries if g.layer == "A-WALL" and np.allclose(np.sort(g.coords[:, 1]), (5, 7))
            and np.allclose(g.coords[:, 0], 10)]
    assert len(hits) == 1
    cols = [g for g in d.geometries if g.layer == "A-COLS"]
    # the column line is kept from both inserts (its own layer is visible), mirrored in the second
    assert len(cols) == 2
    # OUTER col line (1,1)-(1,2) minus base -> (0,0)-(0,1); rotated 90 -> (0,0)-(-1,0) -> (9..10, 5)
    assert any(np.allclose(np.sort(c.coords[:, 0]), (9, 10)) and np.allclose(c.coords[:, 1], 5) for c in cols)
    # mirrored: (0,0)-(0,1) with x scale -1 -> same x; at (3,3): (3,3)-(3,4)
    assert any(np.allclose(c.coords[:, 0], 3) and np.allclose(np.sort(c.coords[:, 1]), (3, 4)) for c in cols)
    assert "FURNITURE" not in {g.layer for g in d.geometries}
    info = {i.name: i for i in list_layers(save(doc, tmp_path, "b.dxf"))}
    assert info["FURNITURE"].counts == {"LINE": 1} and info["FURNITURE"].kind is None
    assert info["A-WALL"].counts["LINE"] == 5 and info["A-WALL"].kind == "wall"


def test_minsert_array(tmp_path):
    doc = new_doc(6)
    blk = doc.blocks.new("COL")
    blk.add_lwpolyline([(0, 0), (0.4, 0), (0.4, 0.4), (0, 0.4)], close=True, dxfattribs={"layer": "0"})
    msp = doc.modelspace()
    room(msp, 0, 0, 30, 20)
    ins = msp.add_blockref("COL", (2, 2), dxfattribs={"layer": "A-COLS"})
    ins.dxf.row_count, ins.dxf.column_count = 3, 4
    ins.dxf.row_spacing, ins.dxf.column_spacing = 5.0, 6.0
    d = import_dxf(save(doc, tmp_path))
    cols = [g for g in d.geometries if g.kind == "column"]
    assert len(cols) == 12
    xs = sorted({round(float(g.coords[:, 0].min()), 6) for g in cols})
    ys = sorted({round(float(g.coords[:, 1].min()), 6) for g in cols})
    assert xs == [2, 8, 14, 20] and ys == [2, 7, 12]
    assert all(g.closed for g in cols)


def test_frozen_and_off_layers_skipped(tmp_path):
    doc = new_doc(6)
    doc.layers.add("A-WALL-OLD").freeze()
    doc.layers.add("A-WALL-OFF").off()
    doc.layers.add("A-WALL")
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10)
    room(msp, 100, 100, 5, 5, layer="A-WALL-OLD")
    room(msp, 200, 200, 5, 5, layer="A-WALL-OFF")
    blk = doc.blocks.new("B")
    blk.add_line((0, 0), (3, 0), dxfattribs={"layer": "0"})
    msp.add_blockref("B", (50, 50), dxfattribs={"layer": "A-WALL-OLD"})  # frozen INSERT: skipped
    d = import_dxf(save(doc, tmp_path))
    assert {g.layer for g in d.geometries} == {"A-WALL"}
    assert len(d.geometries) == 4
    info = d.layers
    assert info["A-WALL-OLD"].frozen and not info["A-WALL-OLD"].kept
    assert info["A-WALL-OFF"].off and not info["A-WALL-OFF"].kept


def test_xref_only_drawing_is_reported(tmp_path):
    doc = new_doc(4)
    doc.add_xref_def("../shell/Building-Shell.dxf", "SHELL")
    doc.add_xref_def("grid.dwg", "GRID")
    msp = doc.modelspace()
    msp.add_blockref("SHELL", (0, 0))
    msp.add_blockref("GRID", (0, 0))
    with pytest.raises(InputError, match=r"references external files .*Building-Shell\.dxf.*grid\.dwg.*bind them in CAD"):
        import_dxf(save(doc, tmp_path))


def test_curves_flattened_within_1cm(tmp_path):
    doc = new_doc(4)  # millimetres
    msp = doc.modelspace()
    room(msp, 0, 0, 20000, 10000)
    msp.add_circle((5000, 5000), 3000, dxfattribs={"layer": "A-WALL"})
    msp.add_arc((12000, 5000), 2000, 0, 90, dxfattribs={"layer": "A-WALL"})
    msp.add_ellipse((15000, 5000), major_axis=(2000, 0), ratio=0.5, dxfattribs={"layer": "A-WALL"})
    msp.add_lwpolyline([(1000, 1000, 0, 0, 1.0), (3000, 1000, 0, 0, 0)], format="xyseb",
                       dxfattribs={"layer": "A-WALL"})  # half circle of radius 1 m
    msp.add_spline([(0, 12000), (5000, 15000), (10000, 12000), (15000, 15000)], dxfattribs={"layer": "A-WALL"})
    d = import_dxf(save(doc, tmp_path))
    by = {}
    for g in d.geometries:
        by.setdefault(g.entity, []).append(g)
    circ = by["CIRCLE"][0]
    r = np.hypot(circ.coords[:, 0] - 5, circ.coords[:, 1] - 5)
    assert np.allclose(r, 3.0) and circ.closed
    # chord sagitta r(1 - cos(step/2)) <= 1 cm
    ang = np.unwrap(np.arctan2(circ.coords[:, 1] - 5, circ.coords[:, 0] - 5))
    step = np.max(np.abs(np.diff(ang)))
    assert 3.0 * (1 - math.cos(step / 2)) <= 0.01 + 1e-9
    arc = by["ARC"][0]
    assert np.allclose(arc.coords[0], (14, 5)) and np.allclose(arc.coords[-1], (12, 7))
    ell = by["ELLIPSE"][0]
    assert np.isclose(ell.coords[:, 0].max(), 17, atol=1e-6) and np.isclose(ell.coords[:, 1].max(), 6, atol=0.01)
    bulge = by["LWPOLYLINE"][0]
    rr = np.hypot(bulge.coords[:, 0] - 2, bulge.coords[:, 1] - 1)
    assert np.allclose(rr, 1.0) and len(bulge.coords) > 10
    assert bulge.coords[:, 1].min() < 0.01  # bulge 1 from (1,1) to (3,1): CCW, swings below the chord
    sp = by["SPLINE"][0]
    assert np.allclose(sp.coords[0], (0, 12)) and np.allclose(sp.coords[-1], (15, 15)) and len(sp.coords) > 10


def test_hatch_solid_trace_3dface_widths(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10)
    h = msp.add_hatch(color=1, dxfattribs={"layer": "A-WALL"})  # solid by default
    h.paths.add_polyline_path([(0, 0), (4, 0), (4, 4), (0, 4)], is_closed=True, flags=1)
    h.paths.add_polyline_path([(1, 1), (3, 1), (3, 3), (1, 3)], is_closed=True, flags=16)
    hp = msp.add_hatch(dxfattribs={"layer": "A-WALL"})
    hp.set_pattern_fill("ANSI31", scale=0.1)
    hp.paths.add_polyline_path([(10, 0), (12, 0), (12, 2)], is_closed=True)
    msp.add_solid([(5, 5), (6, 5), (5, 6), (6, 6)], dxfattribs={"layer": "A-COLS"})
    msp.add_3dface([(7, 7, 0), (8, 7, 0), (8, 8, 0), (7, 8, 0)], dxfattribs={"layer": "A-WALL"})
    msp.add_lwpolyline([(0, 9), (10, 9)], dxfattribs={"layer": "A-WALL", "const_width": 0.3})
    msp.add_polyline2d([(0, 8), (5, 8), (5, 7)], dxfattribs={"layer": "A-WALL"})
    d = import_dxf(save(doc, tmp_path))
    hat = [g for g in d.geometries if g.entity == "HATCH"]
    solid = [g for g in hat if g.filled]
    assert len(solid) == 1 and np.isnan(solid[0].coords).any()  # outer ring + island in one geometry
    assert len([g for g in hat if not g.filled]) == 1  # pattern hatch: outline only
    sol = [g for g in d.geometries if g.entity == "SOLID"][0]
    assert sol.filled and sol.closed and sol.kind == "column"
    assert np.allclose(sorted(map(tuple, sol.coords)), [(5, 5), (5, 6), (6, 5), (6, 6)])
    face = [g for g in d.geometries if g.entity == "3DFACE"][0]
    assert face.closed and not face.filled and len(face.coords) == 4
    wide = [g for g in d.geometries if g.entity == "LWPOLYLINE"][0]
    assert wide.width == pytest.approx(0.3)
    p2 = [g for g in d.geometries if g.entity == "POLYLINE"][0]
    assert len(p2.coords) == 3


def test_texts_mtext_attrib(tmp_path):
    doc = new_doc(4)
    msp = doc.modelspace()
    room(msp, 0, 0, 20000, 10000)
    msp.add_text("Aula 1", dxfattribs={"layer": "TXT", "height": 300, "rotation": 90, "insert": (5000, 5000)})
    msp.add_mtext(r"{\fArial|b1;Sala}\Priunioni", dxfattribs={"layer": "SCRITTE", "char_height": 250,
                                                              "insert": (12000, 3000)})
    blk = doc.blocks.new("TAG")
    blk.add_attdef("NAME", (0, 0), dxfattribs={"height": 200})
    ins = msp.add_blockref("TAG", (15000, 8000), dxfattribs={"layer": "A-ANNO"})
    ins.add_attrib("NAME", "Office 12", (15000, 8000), dxfattribs={"height": 200})
    d = import_dxf(save(doc, tmp_path))
    t = {x.text: x for x in d.texts}
    assert set(t) == {"Aula 1", "Sala riunioni", "Office 12"}
    a = t["Aula 1"]
    assert a.x == pytest.approx(5.0) and a.y == pytest.approx(5.0) and a.height == pytest.approx(0.3)
    assert a.rotation == pytest.approx(90.0) and a.layer == "TXT" and a.entity == "TEXT"
    assert t["Sala riunioni"].entity == "MTEXT" and t["Sala riunioni"].height == pytest.approx(0.25)
    assert t["Office 12"].entity == "ATTRIB" and t["Office 12"].x == pytest.approx(15.0)


def test_text_inside_rotated_block(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10)
    blk = doc.blocks.new("LBL")
    blk.add_text("Bagno", dxfattribs={"insert": (1, 0), "height": 0.2, "layer": "0"})
    msp.add_blockref("LBL", (10, 5), dxfattribs={"rotation": 90, "xscale": 2, "yscale": 2, "layer": "TESTI"})
    d = import_dxf(save(doc, tmp_path))
    (t,) = d.texts
    assert (t.x, t.y) == pytest.approx((10, 7)) and t.height == pytest.approx(0.4)
    assert t.rotation == pytest.approx(90) and t.layer == "TESTI"


# ----------------------------------------------------------------------------------------- units
def test_header_mm_but_drawn_in_metres(tmp_path):
    doc = new_doc(4)
    room(doc.modelspace(), 100, 200, 30, 12)
    prog = RecordingProgress()
    d = import_dxf(save(doc, tmp_path), progress=prog)
    assert d.unit_name == "m" and d.header_unit == "mm" and d.unit_scale == 1.0
    assert any("mm" in w and "using m" in w for w in d.warnings)
    assert any(k == "warning" and "using m" in m for k, m in prog.messages)
    lo, hi = bounds(d.geometries)
    assert np.allclose(hi - lo, (30, 12))


def test_unitless_and_override(tmp_path):
    doc = new_doc(0)
    room(doc.modelspace(), 0, 0, 2500, 1200)  # cm -> 25 m
    path = save(doc, tmp_path)
    d = import_dxf(path)
    assert d.unit_name == "cm" and d.header_unit == "unitless"
    assert any("no unit" in w for w in d.warnings)
    d2 = import_dxf(path, units="mm")
    assert d2.unit_name == "mm" and not any("unit" in w for w in d2.warnings)
    assert np.allclose(bounds(d2.geometries)[1], (2.5, 1.2))
    with pytest.raises(InputError, match="unknown unit"):
        import_dxf(path, units="parsec")


def test_choose_unit_rules():
    assert choose_unit(150000, "mm") == ("mm", None)
    assert choose_unit(40, "mm")[0] == "m"
    assert choose_unit(4000, "unitless")[0] == "cm"  # 40 m
    assert choose_unit(30, "feet") == ("feet", None)  # 9 m is plausible: header kept
    u, msg = choose_unit(1e9, "mm")
    assert "implausible" in msg


def test_curves_flattened_for_the_chosen_unit(tmp_path):
    doc = new_doc(4)  # says mm, drawn in metres: curves must be re-flattened at 1 cm
    msp = doc.modelspace()
    room(msp, 0, 0, 30, 20)
    msp.add_circle((10, 10), 2.0, dxfattribs={"layer": "A-WALL"})
    d = import_dxf(save(doc, tmp_path))
    c = [g for g in d.geometries if g.entity == "CIRCLE"][0]
    assert d.unit_name == "m" and len(c.coords) >= 30


# ----------------------------------------------------------------------------------------- layers
def test_doors_left_out_unless_asked(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10)
    msp.add_arc((5, 0), 0.9, 0, 90, dxfattribs={"layer": "A-DOOR"})
    msp.add_line((5, 0), (5, 0.9), dxfattribs={"layer": "A-DOOR"})
    path = save(doc, tmp_path)
    d = import_dxf(path)
    assert "A-DOOR" not in {g.layer for g in d.geometries}
    assert d.layers["A-DOOR"].kind == "door"
    d2 = import_dxf(path, include_doors=True)
    assert len([g for g in d2.geometries if g.kind == "door"]) == 2


def test_explicit_layers_override_rules(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10, layer="Pluma 8")
    room(msp, 0, 0, 5, 5, layer="A-WALL")
    path = save(doc, tmp_path)
    d = import_dxf(path, layers=["pluma 8"])
    assert {g.layer for g in d.geometries} == {"Pluma 8"} and all(g.kind == "wall" for g in d.geometries)
    with pytest.raises(InputError, match=r"do not exist .*A-WALL"):
        import_dxf(path, layers=["Muri"])


def test_fallback_walls_when_no_wall_keyword(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10, layer="Pluma 8")
    room(msp, 1, 1, 1, 1, layer="Cotas")  # excluded (dimensions)
    d = import_dxf(save(doc, tmp_path))
    assert {g.layer for g in d.geometries} == {"Pluma 8"}
    assert any("no layer name matched a wall keyword" in w for w in d.warnings)


def test_filter_keeps_nothing_lists_layers(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10, layer="Furniture")
    msp.add_text("Hall", dxfattribs={"layer": "TEXT"})
    with pytest.raises(InputError) as exc:
        import_dxf(save(doc, tmp_path))
    msg = str(exc.value)
    assert "'Furniture' (4 entities, exclude: 'furn')" in msg and "'wall' list" in msg and "LAYERS" in msg


# ----------------------------------------------------------------------------------------- bad input
def test_not_a_dxf(tmp_path):
    p = tmp_path / "photo.dxf"
    p.write_bytes(b"\x89PNG\r\n\x1a\n" + os.urandom(200))
    with pytest.raises(InputError, match="not a DXF"):
        import_dxf(str(p))
    dwg = tmp_path / "plan.dxf"
    dwg.write_bytes(b"AC1032" + b"\0" * 100)
    with pytest.raises(InputError, match="DWG"):
        import_dxf(str(dwg))
    with pytest.raises(InputError, match="does not exist"):
        import_dxf(str(tmp_path / "nope.dxf"))
    empty = tmp_path / "zero.dxf"
    empty.write_bytes(b"")
    with pytest.raises(InputError, match="empty"):
        import_dxf(str(empty))


def test_empty_drawing(tmp_path):
    with pytest.raises(InputError, match="empty drawing"):
        import_dxf(save(new_doc(4), tmp_path))


def test_truncated_dxf_is_recovered_and_reported(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    room(msp, 0, 0, 20, 10)
    room(msp, 2, 2, 3, 3)
    path = save(doc, tmp_path)
    data = open(path, "rb").read()
    start = data.find(b"ENTITIES")
    end = data.find(b"ENDSEC", start)
    bad = tmp_path / "truncated.dxf"
    bad.write_bytes(data[:end])  # cut right after the last entity
    prog = RecordingProgress()
    d = import_dxf(str(bad), progress=prog)
    text = " ".join(d.repairs)
    assert "truncated" in text and "recover mode" in text
    assert any(k == "warning" and "truncated" in m for k, m in prog.messages)
    assert len(d.geometries) == 8
    bad.write_bytes(data[:(start + end) // 2 + 7])  # cut in the middle of an entity
    d = import_dxf(str(bad))
    assert 2 <= len(d.geometries) < 8 and "truncated" in " ".join(d.repairs)


def test_garbage_after_header_fails_clearly(tmp_path):
    p = tmp_path / "broken.dxf"
    p.write_text("0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n",
                 encoding="ascii")
    with pytest.raises(InputError) as exc:
        import_dxf(str(p))
    assert os.path.basename(str(p)) in str(exc.value)


def test_inspect_reports_header_and_counts(tmp_path):
    doc = new_doc(4)
    msp = doc.modelspace()
    room(msp, 0, 0, 20000, 10000)
    msp.add_text("x", dxfattribs={"layer": "A-WALL"})
    d = inspect_dxf(save(doc, tmp_path))
    assert d.header_unit == "mm"
    assert d.layers["A-WALL"].counts == {"LINE": 4, "TEXT": 1}
    assert d.layers["A-WALL"].kept and d.layers["0"].kind == "reference"


# ----------------------------------------------------------------------------------------- sample building
@pytest.fixture(scope="module")
def sample_floor(tmp_path_factory):
    sb = pytest.importorskip("algorithms.sample_building")
    out = tmp_path_factory.mktemp("sample")
    res = sb.generate_building(str(out), floors=1, seed=0)
    import json

    gt = json.load(open(res["ground_truth"][0], encoding="utf-8"))
    return res["dxf"][0], gt


def test_sample_building_structure_texts_and_raster(sample_floor):
    import cv2
    from shapely.geometry import Point, shape

    from algorithms.rasterize import rasterize

    path, gt = sample_floor
    d = import_dxf(path)
    assert d.unit_name == "mm" and not d.warnings
    kept = {g.layer for g in d.geometries}
    assert {"A-WALL", "A-COLS", "A-GLAZ"} <= kept
    assert not kept & {"A-DOOR", "A-FURN", "A-ANNO-DIMS", "A-ANNO-TEXT", "S-GRID", "P-SANR-FIXT", "A-FLOR-PATT"}
    lo, hi = bounds(d.geometries)
    assert np.allclose(lo, (0, 0), atol=0.01) and np.allclose(hi, (40, 25), atol=0.01)
    # every room name of the ground truth is among the texts, formatting codes stripped
    names = {f["properties"]["name"] for f in gt["features"] if f["properties"]["kind"] == "room"}
    texts = {t.text for t in d.texts}
    missing = [n for n in names if n not in texts and n not in ("Corridor",)]
    assert not missing, (missing, sorted(texts)[:40])
    assert {t.entity for t in d.texts} >= {"TEXT", "MTEXT", "ATTRIB"}

    grid = rasterize(d.geometries)
    rooms = [f for f in gt["features"] if f["properties"]["kind"] == "room"]
    n, labels = cv2.connectedComponents((grid.data == 0).astype(np.uint8), connectivity=4)
    comp = {}
    for f in rooms:
        poly = shape(f["geometry"])
        inner = poly.buffer(-0.25)
        if inner.is_empty or f["properties"]["areatype"] in ("stairs", "elevator"):
            continue  # stair treads and the lift car are drawn (kept layers)
        # the room's inside is free space
        minx, miny, maxx, maxy = inner.bounds
        xs = np.arange(minx, maxx, 0.2)
        ys = np.arange(miny, maxy, 0.2)
        pts = [(x, y) for x in xs for y in ys if inner.contains(Point(x, y))]
        c, r = grid.world_to_pixel(np.array([p[0] for p in pts]), np.array([p[1] for p in pts]))
        vals = grid.data[r.astype(int), c.astype(int)]
        assert (vals == 0).mean() > 0.9, (f["properties"]["name"], (vals == 0).mean())
        p = inner.representative_point()
        c, r = grid.world_to_pixel(p.x, p.y)
        comp[f["properties"]["name"]] = labels[int(r), int(c)]
    # doors stay open: every door's midpoint is free and the rooms it joins are connected
    for f in gt["features"]:
        pr = f["properties"]
        if pr["kind"] != "door" or pr["to"] == "outside":
            continue
        (x0, y0), (x1, y1) = f["geometry"]["coordinates"]
        c, r = grid.world_to_pixel((x0 + x1) / 2, (y0 + y1) / 2)
        assert grid.data[int(r), int(c)] == 0, pr
        if pr["from"] in comp and pr["to"] in comp:
            assert comp[pr["from"]] == comp[pr["to"]], pr
    # with doors included, the doorways are drawn (door blocks on A-DOOR)
    d2 = import_dxf(path, include_doors=True)
    assert "A-DOOR" in {g.layer for g in d2.geometries}
    assert len(d2.geometries) > len(d.geometries)

    def big_free_parts(g):
        n, _, st, _ = cv2.connectedComponentsWithStats((g.data == 0).astype(np.uint8), connectivity=4)
        return int((st[1:, cv2.CC_STAT_AREA] * g.resolution ** 2 > 2.0).sum())

    # open doors: the floor's free space is one piece (plus the outside); closed doors: one per room
    assert big_free_parts(grid) <= 3
    assert big_free_parts(rasterize(d2.geometries)) >= len(rooms) - 3


def test_scaled_block_keeps_1cm_chord_error(tmp_path):
    doc = new_doc(6)
    blk = doc.blocks.new("RING")
    blk.add_circle((0, 0), 1.0, dxfattribs={"layer": "0"})
    msp = doc.modelspace()
    room(msp, 0, 0, 40, 30)
    msp.add_blockref("RING", (20, 15), dxfattribs={"layer": "A-WALL", "xscale": 10, "yscale": 10})
    d = import_dxf(save(doc, tmp_path))
    circ = [g for g in d.geometries if g.entity == "CIRCLE"][0]
    assert np.allclose(np.hypot(circ.coords[:, 0] - 20, circ.coords[:, 1] - 15), 10.0)
    ang = np.sort(np.arctan2(circ.coords[:, 1] - 15, circ.coords[:, 0] - 20))
    step = np.max(np.diff(np.concatenate([ang, ang[:1] + 2 * np.pi])))
    assert 10.0 * (1 - math.cos(step / 2)) <= 0.01 + 1e-9


def test_cancel_stops_the_import(tmp_path):
    from algorithms.errors import Canceled

    doc = new_doc(6)
    room(doc.modelspace(), 0, 0, 20, 10)
    with pytest.raises(Canceled):
        import_dxf(save(doc, tmp_path), progress=RecordingProgress(cancel_after=0))


def test_entity_with_unreadable_number_is_dropped_and_reported(tmp_path):
    doc = new_doc(6)
    msp = doc.modelspace()
    for i in range(8):
        msp.add_line((i * 3, 0), (i * 3, 20), dxfattribs={"layer": "A-WALL"})
    path = save(doc, tmp_path)
    text = open(path, encoding="utf-8").read()
    ent = text.find("ENTITIES")
    j = text.find("\n 10\n", text.find("\nLINE\n", ent))
    k = text.find("\n", j + 5)
    bad = tmp_path / "corrupt.dxf"
    bad.write_text(text[:j + 5] + "abc" + text[k:], encoding="utf-8")  # recover mode alone gives up
    prog = RecordingProgress()
    d = import_dxf(str(bad), progress=prog)
    assert len(d.geometries) == 7
    assert any("dropped 1 entities with unreadable numbers" in r for r in d.repairs)
    assert any(kind == "warning" and "recover mode" in m for kind, m in prog.messages)


def test_rounded_wall_corners_are_walls_not_door_swings(tmp_path):
    """Quarter arcs of door-swing size on a wall layer, with no leaf hinged at their centre, stay walls."""
    from algorithms.rasterize import rasterize
    from scipy import ndimage

    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    r, w, h = 1.0, 20.0, 10.0
    for (x0, y0), (x1, y1) in (((r, 0), (w - r, 0)), ((w, r), (w, h - r)), ((w - r, h), (r, h)), ((0, h - r), (0, r))):
        msp.add_line((x0, y0), (x1, y1), dxfattribs={"layer": "A-WALL"})
    for (cx, cy), start in (((w - r, r), 270), ((w - r, h - r), 0), ((r, h - r), 90), ((r, r), 180)):
        msp.add_arc((cx, cy), r, start, start + 90, dxfattribs={"layer": "A-WALL"})
    d = import_dxf(save(doc, tmp_path))
    assert sum(g.entity == "ARC" for g in d.geometries) == 4
    grid = rasterize(d.geometries)
    _, n = ndimage.label(grid.data == 0)
    assert n == 2  # the room is closed: inside and outside are two free components


def test_a_few_far_stray_entities_do_not_change_the_unit(tmp_path):
    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 6  # metres, and drawn in metres
    msp = doc.modelspace()
    for i in range(40):  # a 40 x 15 m building of many wall pieces
        msp.add_line((i, 0), (i + 1, 0), dxfattribs={"layer": "A-WALL"})
        msp.add_line((i, 15), (i + 1, 15), dxfattribs={"layer": "A-WALL"})
    msp.add_line((9000, 9000), (9001, 9000), dxfattribs={"layer": "A-WALL"})  # 1 m of debris 9 km away
    d = import_dxf(save(doc, tmp_path))
    assert d.unit_name == "m" and not any("instead" in w for w in d.warnings)


def test_practically_empty_raster_is_an_error_not_a_silent_output():
    from algorithms.errors import InputError
    from algorithms.model import CadGeometry
    from algorithms.rasterize import rasterize

    far = [CadGeometry("A-WALL", "wall", np.array([[0.0, 0.0], [1.0, 0.0]])),
           CadGeometry("A-WALL", "wall", np.array([[300.0, 300.0], [301.0, 300.0]]))]
    with pytest.raises(InputError, match="practically empty"):
        rasterize(far, percentiles=(0, 100))


def test_list_layers_tells_the_same_story_as_the_import(tmp_path):
    """The wall fallback (no layer name looks like a wall) shows in the layer report, and a drawing with
    nothing in model space is an error there too, not a report of two empty layers."""
    from algorithms.cad_import import layer_kept

    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    for k in range(4):
        msp.add_lwpolyline([(0, 0), (20, 0), (20, 10), (0, 10)], close=True, dxfattribs={"layer": "Pluma 8"})
    msp.add_text("Aula 1", dxfattribs={"layer": "testo", "insert": (5, 5)})
    infos = {i.name: i for i in list_layers(save(doc, tmp_path))}
    assert layer_kept(infos["Pluma 8"]) and not layer_kept(infos["testo"])
    assert {g.layer for g in import_dxf(save(doc, tmp_path, "b.dxf")).geometries} == {"Pluma 8"}
    empty = ezdxf.new("R2013")
    with pytest.raises(InputError, match="no geometry and no text"):
        list_layers(save(empty, tmp_path, "empty.dxf"))


def test_inspect_reports_each_warning_once(tmp_path):
    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 6
    doc.modelspace().add_lwpolyline([(0, 0), (20, 0), (20, 10), (0, 10)], close=True, dxfattribs={"layer": "Pluma 8"})
    rec = RecordingProgress()
    drawing = inspect_dxf(save(doc, tmp_path), progress=rec)
    warned = [m for kind, m in rec.messages if kind == "warning"]
    assert any("no layer name matched a wall keyword" in m for m in warned)
    assert sorted(warned) == sorted(set(warned)) == sorted(drawing.repairs + drawing.warnings)


def test_unicode_escapes_of_old_dxf_versions_are_decoded(tmp_path):
    """DXF R2000/R2004 store CJK text as \\U+XXXX (and \\M+nXXXX) escapes; room names must come out as text."""
    import ezdxf

    from algorithms import cad_import
    from algorithms.cad_explode import decode_escapes

    assert decode_escapes(r"E1-ST-03 \U+697c\U+68af") == "E1-ST-03 楼梯"
    assert decode_escapes(r"\M+5C2A5") == "楼"  # code page 5 = GBK
    assert decode_escapes(r"a\M+9FFFFb") == r"a\M+9FFFFb"  # unknown code page: left as is
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (10000, 0), (10000, 8000), (0, 8000)], close=True, dxfattribs={"layer": "A-WALL"})
    msp.add_text("E1-ST-03 楼梯", dxfattribs={"layer": "A-ANNO"}).set_placement((2000, 2000))
    msp.add_mtext("房间\\P101", dxfattribs={"layer": "A-ANNO"}).set_location((5000, 5000))
    path = tmp_path / "r2000.dxf"
    doc.saveas(path)
    assert b"\\U+" in path.read_bytes()
    texts = sorted(t.text for t in cad_import.import_dxf(str(path)).texts)
    assert texts == ["E1-ST-03 楼梯", "房间 101"]


def test_dxf_and_dwg_get_the_same_file_checks(tmp_path):
    """One check (cad_read.check_drawing_file) for both formats: a missing path, a folder and a file of only
    NUL bytes (a save cut off by a crash) are named as such, with the format in the message."""
    blank = tmp_path / "blank.dxf"
    blank.write_bytes(b"\0" * 5000)
    with pytest.raises(InputError, match=r"'blank.dxf' is empty \(5000 bytes, no drawing data\); export"):
        import_dxf(str(blank))
    for suffix, kind in ((".dxf", "DXF"), (".dwg", "DWG")):
        with pytest.raises(InputError, match=f"{kind} file .* does not exist"):
            import_dxf(str(tmp_path / f"nope{suffix}"))
    (tmp_path / "dir.dxf").mkdir()
    with pytest.raises(InputError, match="is a folder, not a DXF file"):
        import_dxf(str(tmp_path / "dir.dxf"))


def test_a_1e308_coordinate_never_reaches_the_every_layer_searches(tmp_path):
    """A damaged coordinate of 1e308 (found by the fuzz: scipy's KD-tree of the folding-partition search
    overflowed with a raw ValueError) leaves the partition / counter searches; the import goes on."""
    import numpy as np

    from algorithms import cad_import
    from algorithms.cad_explode import _Pieces

    p = _Pieces()
    p.add(np.array([[0.0, 0.0], [1000.0, 0.0]]), "A-WALL", "LINE")
    p.add(np.array([[0.0, 1.0e308], [-1.0e308, 5.0]]), "A-WALL", "LINE")
    p.add(np.array([[0.0, 500.0], [1000.0, 500.0]]), "0", "LINE")
    p.texts.append((0.0, 0.0, "x", 1.0, 0.0, "0", "TEXT", "", ""))
    s = cad_import._sound_pieces(p, 0.001)
    assert len(s.coords) == 2 and s.layer == ["A-WALL", "0"] and len(s.texts) == 1
    assert cad_import._sound_pieces(s, 0.001) is s  # nothing broken: the same object
    assert cad_import._folding_partitions(s, 0.001, None, {}) == []
