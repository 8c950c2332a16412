"""DWG input (algorithms/cad_dwg.py): synthetic DWGs written with ezdwg compared with the same drawing as
DXF, bad input, and every shared DWG sheet (slow)."""
import collections
import os
import time

import ezdxf
import numpy as np
import pytest

from algorithms import cad_dwg
from algorithms.cad_import import import_dxf, inspect_dxf, list_layers
from algorithms.errors import InputError
from algorithms.progress import RecordingProgress

ezdwg = pytest.importorskip("ezdwg")


# ------------------------------------------------------------------------------------------ synthetic pair
class _Both:
    """Write the same drawing to an ezdxf document and an ezdwg drawing."""

    def __init__(self, insunits=4):
        self.dxf = ezdxf.new("R2010", setup=False)  # UTF-8 (R2000 DXF stores CJK as \\U+ escapes)
        self.dxf.header["$INSUNITS"] = insunits
        self.dwg = ezdwg.new()
        self.dwg.header["insunits"] = insunits

    def layer(self, name, frozen=False, off=False):
        lay = self.dxf.layers.add(name)
        if frozen:
            lay.freeze()
        if off:
            lay.off()
        self.dwg.layers[name] = {"color_index": 7, "frozen": frozen, "off": off}

    def block(self, name, base=(0.0, 0.0)):
        return self.dxf.blocks.new(name, base_point=(base[0], base[1], 0.0)), \
            self.dwg.blocks.new(name, base_point=(base[0], base[1], 0.0))

    def save(self, folder, stem):
        dxf_path, dwg_path = str(folder / f"{stem}.dxf"), str(folder / f"{stem}.dwg")
        self.dxf.saveas(dxf_path)
        self.dwg.save(dwg_path)
        return dxf_path, dwg_path


def _plan_pair(tmp_path):
    """A 20 x 12 m office floor in mm: walls (lines, a bulged polyline, an arc), a column hatch, door
    blocks inserted rotated / mirrored / scaled with a base point, a nested block, room-name blocks
    with Chinese ATTRIBs, Chinese TEXT and MTEXT, a frozen furniture layer and an off layer."""
    b = _Both()
    for name in ("E1-RI-1F$0$A-WALL", "A-DOOR", "A-COLS", "A-ANNO", "FURN", "OFFLAYER"):
        b.layer(name, frozen=name == "FURN", off=name == "OFFLAYER")
    (xm, wm) = (b.dxf.modelspace(), b.dwg.modelspace())
    wall = "E1-RI-1F$0$A-WALL"
    pts = [(0, 0), (20000, 0), (20000, 12000), (0, 12000)]
    for p, q in zip(pts, pts[1:] + pts[:1]):
        xm.add_line(p, q, dxfattribs={"layer": wall})
        wm.add_line(p, q, layer=wall)
    # a partition with a rounded end (bulge) and an arc wall
    lw = [(8000, 0, 0.0), (8000, 5000, 1.0), (8200, 5000, 0.0), (8200, 0, 0.0)]
    xm.add_lwpolyline([(x, y, 0, 0, bb) for x, y, bb in lw], format="xyseb", dxfattribs={"layer": wall})
    wm.add_lwpolyline([(x, y) for x, y, _ in lw], bulges=[bb for _, _, bb in lw], layer=wall)
    xm.add_arc((14000, 12000), 3000, 180, 270, dxfattribs={"layer": wall})
    wm.add_arc((14000, 12000, 0), 3000, 180, 270, layer=wall)
    # column: solid hatch
    sq = [(16000, 6000), (16400, 6000), (16400, 6400), (16000, 6400)]
    h = xm.add_hatch(dxfattribs={"layer": "A-COLS"})
    h.paths.add_polyline_path(sq)
    wm.add_hatch([sq], layer="A-COLS")
    # door block: leaf + swing, base point at the hinge (500, 0)
    xd, wd = b.block("DOOR", base=(500.0, 0.0))
    xd.add_line((500, 0), (500, 900), dxfattribs={"layer": "0"})
    wd.add_line((500, 0), (500, 900), layer="0")
    xd.add_arc((500, 0), 900, 0, 90, dxfattribs={"layer": "0"})
    wd.add_arc((500, 0, 0), 900, 0, 90, layer="0")
    # nested: a double door made of two DOORs
    xdd, wdd = b.block("DOUBLE")
    xdd.add_blockref("DOOR", (0, 0))
    wdd.add_blockref("DOOR", (0, 0, 0))
    xdd.add_blockref("DOOR", (1800, 0), dxfattribs={"xscale": -1})
    wdd.add_blockref("DOOR", (1800, 0, 0), scale=(-1, 1, 1))
    for ins, rot, sc in (((3000, 0), 0.0, (1, 1)), ((20000, 4000), 90.0, (1, 1)), ((12000, 12000), 180.0, (-1, 1)),
                         ((5000, 6000), 30.0, (1.2, 0.8))):
        xm.add_blockref("DOOR", ins, dxfattribs={"layer": "A-DOOR", "rotation": rot, "xscale": sc[0],
                                                  "yscale": sc[1]})
        wm.add_blockref("DOOR", (ins[0], ins[1], 0), rotation=rot, scale=(sc[0], sc[1], 1), layer="A-DOOR")
    xm.add_blockref("DOUBLE", (9000, 12000), dxfattribs={"layer": "A-DOOR", "rotation": 270})
    wm.add_blockref("DOUBLE", (9000, 12000, 0), rotation=270, layer="A-DOOR")
    # room tags: block with an ATTDEF, inserted with ATTRIBs (room name + number)
    xt, wt = b.block("ROOMTAG")
    xt.add_circle((0, 0), 100, dxfattribs={"layer": "0"})
    wt.add_circle((0, 0, 0), 100, layer="0")
    for name, num, pos in (("办公室", "A101", (4000, 8000)), ("会议室", "A102", (14000, 4000))):
        xi = xm.add_blockref("ROOMTAG", pos, dxfattribs={"layer": "A-ANNO"})
        xi.add_attrib("ROOMNAME", name, (pos[0], pos[1] + 300), dxfattribs={"layer": "A-ANNO", "height": 250})
        xi.add_attrib("ROOMNO", num, (pos[0], pos[1] - 300), dxfattribs={"layer": "A-ANNO", "height": 200})
        wi = wm.add_blockref("ROOMTAG", (pos[0], pos[1], 0), layer="A-ANNO")
        wm.add_attrib(wi, "ROOMNAME", name, (pos[0], pos[1] + 300, 0), 250, layer="A-ANNO")
        wm.add_attrib(wi, "ROOMNO", num, (pos[0], pos[1] - 300, 0), 200, layer="A-ANNO")
    xm.add_text("E1-ST-03 楼梯", dxfattribs={"layer": "A-ANNO", "height": 300, "insert": (17000, 10000)})
    wm.add_text("E1-ST-03 楼梯", (17000, 10000, 0), 300, layer="A-ANNO")
    xm.add_mtext(r"{\fSimSun|b0;走廊}\P2F", dxfattribs={"layer": "A-ANNO", "char_height": 250,
                                                        "insert": (10000, 2000)})
    wm.add_mtext(r"{\fSimSun|b0;走廊}\P2F", (10000, 2000, 0), 250, layer="A-ANNO")
    # hidden content: furniture on a frozen layer, a line on an off layer
    xm.add_circle((2000, 2000), 400, dxfattribs={"layer": "FURN"})
    wm.add_circle((2000, 2000, 0), 400, layer="FURN")
    xm.add_line((0, 6000), (3000, 6000), dxfattribs={"layer": "OFFLAYER"})
    wm.add_line((0, 6000, 0), (3000, 6000, 0), layer="OFFLAYER")
    return b.save(tmp_path, "plan")


def dwg_copy_of(dxf_path, dwg_path):
    """Write an R2000 DWG (with ezdwg) holding what a DXF holds: layers with their states, $INSUNITS,
    blocks with base points, LINE, LWPOLYLINE, ARC, CIRCLE, ELLIPSE, SOLID, TEXT, MTEXT, INSERT with
    ATTRIBs and HATCH (boundaries as polylines). Used to run whole pipelines on a DWG of a known drawing."""
    src = ezdxf.readfile(str(dxf_path))
    out = ezdwg.new()
    out.header["insunits"] = int(src.header.get("$INSUNITS", 0) or 0)
    for lay in src.layers:
        if lay.dxf.name != "0":
            out.layers[lay.dxf.name] = {"color_index": 7, "frozen": lay.is_frozen(), "off": lay.is_off()}

    def copy(e, dst):
        t, d = e.dxftype(), e.dxf
        common = {"layer": d.get("layer", "0")}
        if t == "LINE":
            dst.add_line(tuple(d.start), tuple(d.end), **common)
        elif t == "LWPOLYLINE":
            pts = list(e.get_points("xyseb"))
            dst.add_lwpolyline([(p[0], p[1]) for p in pts], bulges=[p[4] for p in pts], closed=bool(e.closed),
                               const_width=float(d.get("const_width", 0.0) or 0.0), **common)
        elif t == "ARC":
            dst.add_arc(tuple(d.center), d.radius, d.start_angle, d.end_angle, **common)
        elif t == "CIRCLE":
            dst.add_circle(tuple(d.center), d.radius, **common)
        elif t == "ELLIPSE":
            dst.add_ellipse(tuple(d.center), tuple(d.major_axis), d.ratio, d.start_param, d.end_param, **common)
        elif t == "SOLID":
            dst.add_solid([tuple(d.get(f"vtx{i}")) for i in range(4)], **common)
        elif t == "TEXT":
            dst.add_text(d.text, tuple(d.insert), d.get("height", 1.0), rotation=d.get("rotation", 0.0), **common)
        elif t == "MTEXT":
            dst.add_mtext(e.text, tuple(d.insert), d.get("char_height", 1.0), **common)
        elif t == "INSERT":
            ref = dst.add_blockref(d.name, tuple(d.insert), rotation=d.get("rotation", 0.0),
                                   scale=(d.get("xscale", 1.0), d.get("yscale", 1.0), d.get("zscale", 1.0)), **common)
            for a in e.attribs:
                dst.add_attrib(ref, a.dxf.tag, a.dxf.text, tuple(a.dxf.insert), a.dxf.get("height", 1.0),
                               layer=a.dxf.get("layer", "0"))
        elif t == "HATCH":
            from ezdxf import path as ezpath

            rings = []
            for bp in e.paths:
                pts = [(v.x, v.y) for v in ezpath.from_hatch_boundary_path(bp).flattening(0.5)]
                if len(pts) >= 3:
                    rings.append(pts)
            if rings:
                if e.dxf.solid_fill:
                    dst.add_hatch(rings, **common)
                else:
                    dst.add_hatch(rings, pattern="ANSI31", **common)

    for blk in src.blocks:
        if blk.name.lower().startswith(("*model_space", "*paper_space")):
            continue
        bp = blk.block.dxf.base_point
        nb = out.blocks.new(blk.name, base_point=(bp[0], bp[1], 0.0))
        for e in blk:
            copy(e, nb)
    for e in src.modelspace():
        copy(e, out.modelspace())
    out.save(str(dwg_path))
    return str(dwg_path)


def _key(g):
    return (g.layer, g.entity, round(float(np.nanmin(g.coords[:, 0])), 3), round(float(np.nanmin(g.coords[:, 1])), 3),
            round(float(np.nanmax(g.coords[:, 0])), 3), round(float(np.nanmax(g.coords[:, 1])), 3))


def test_synthetic_dwg_reads_like_the_same_dxf(tmp_path):
    dxf_path, dwg_path = _plan_pair(tmp_path)
    a = import_dxf(dxf_path, include_doors=True)
    b = import_dxf(dwg_path, include_doors=True)
    assert b.unit_name == a.unit_name == "mm" and b.header_unit == "mm"
    # same geometries, same places (blocks exploded with base point, rotation, mirror, nesting)
    assert sorted(map(_key, b.geometries)) == sorted(map(_key, a.geometries))
    assert collections.Counter(g.kind for g in b.geometries) == collections.Counter(g.kind for g in a.geometries)
    # 4 DOORs + 2 in the nested DOUBLE: 6 leaves and 6 swings, on the INSERT's layer
    door = [g for g in b.geometries if g.layer == "A-DOOR"]
    assert collections.Counter(g.entity for g in door) == {"LINE": 6, "ARC": 6}
    # bulge 1 = a counter-clockwise half circle of radius 100 mm, below the chord at y = 5000 mm
    lw = [g for g in b.geometries if g.entity == "LWPOLYLINE"][0]
    assert len(lw.coords) >= 6  # flattened at <= 1 cm chord error
    assert lw.coords[:, 1][lw.coords[:, 1] > 1.0].min() == pytest.approx(4.9, abs=0.002)
    assert [g for g in b.geometries if g.entity == "HATCH"][0].filled
    # texts: Chinese TEXT, MTEXT stripped of formatting, ATTRIB values
    ta = sorted((t.text, t.entity, round(t.x, 3), round(t.y, 3)) for t in a.texts)
    tb = sorted((t.text, t.entity, round(t.x, 3), round(t.y, 3)) for t in b.texts)
    assert tb == ta
    texts = {t.text for t in b.texts}
    assert {"办公室", "会议室", "A101", "A102", "E1-ST-03 楼梯", "走廊 2F"} <= texts
    # frozen / off layers are hidden in both
    assert not any(g.layer in ("FURN", "OFFLAYER") for g in b.geometries)
    assert b.undecoded == {}


def test_mirrored_by_extrusion_like_dxf(tmp_path):
    """Entities mirrored with an extrusion of -Z (CAD MIRROR on arcs, blocks) land where the DXF puts them."""
    b = _Both()
    b.layer("A-WALL")
    xm, wm = b.dxf.modelspace(), b.dwg.modelspace()
    xm.add_arc((1000, 2000), 900, 0, 90, dxfattribs={"layer": "A-WALL", "extrusion": (0, 0, -1)})
    wm.add_arc((1000, 2000, 0), 900, 0, 90, layer="A-WALL", extrusion=(0, 0, -1))
    xb, wb = b.block("LEAF", base=(100.0, 0.0))
    for p, q in (((100, 0), (1100, 0)), ((100, 0), (100, 500))):
        xb.add_line(p, q)
        wb.add_line(p, q)
    xm.add_blockref("LEAF", (5000, 5000), dxfattribs={"layer": "A-WALL", "extrusion": (0, 0, -1), "rotation": 30})
    wm.add_blockref("LEAF", (5000, 5000, 0), layer="A-WALL", extrusion=(0, 0, -1), rotation=30)
    dxf_path, dwg_path = b.save(tmp_path, "mirror")
    a, d = import_dxf(dxf_path, units="mm"), import_dxf(dwg_path, units="mm")
    assert sorted(map(_key, d.geometries)) == sorted(map(_key, a.geometries))
    arc = [g for g in d.geometries if g.entity == "ARC"][0]
    assert arc.coords[0] == pytest.approx((-1.9, 2.0), abs=1e-3)  # x mirrored: centre at x = -1 m


def test_dwg_layers_states_and_bound_xref_names(tmp_path):
    _, dwg_path = _plan_pair(tmp_path)
    infos = {i.name: i for i in list_layers(dwg_path)}
    assert infos["FURN"].frozen and not infos["FURN"].kept
    assert infos["OFFLAYER"].off
    wall = infos["E1-RI-1F$0$A-WALL"]
    assert wall.kind == "wall" and wall.counts == {"LINE": 4, "LWPOLYLINE": 1, "ARC": 1}
    assert infos["A-ANNO"].counts.get("ATTRIB") == 4 and infos["A-ANNO"].counts.get("TEXT") == 1
    assert infos["A-DOOR"].counts == {"LINE": 6, "ARC": 6}


def test_dwg_read_reports_progress_and_counts(tmp_path):
    _, dwg_path = _plan_pair(tmp_path)
    rec = RecordingProgress()
    doc, repairs = cad_dwg.read_dwg(dwg_path, rec)
    assert repairs == [] and doc.version == "AC1015" and doc.release == "R2000"
    assert doc.counts["INSERT"] == 9 and doc.counts["ATTRIB"] == 4 and doc.counts["MTEXT"] == 1
    assert rec.percents and rec.percents[-1] == 100
    assert "DWG R2000 (AC1015)" in rec.text()
    assert [b.name for b in doc.blocks if b.name in ("DOOR", "DOUBLE", "ROOMTAG")]
    assert doc.blocks.get("door").block.dxf.base_point[:2] == (500.0, 0.0)
    # the ezdxf-like entity interface the import's exploder relies on
    e = next(x for x in doc.modelspace() if x.dxftype() == "LINE")
    assert e.dxf.layer == "E1-RI-1F$0$A-WALL" and e.dxf.get("nothing", 7) == 7 and not e.dxf.hasattr("nothing")
    assert isinstance(e.dxf.handle, str) and int(e.dxf.handle, 16) > 0
    tag = next(x for x in doc.modelspace() if x.dxftype() == "INSERT" and x.dxf.name == "ROOMTAG")
    assert sorted(a.dxf.tag for a in tag.attribs) == ["ROOMNAME", "ROOMNO"]


def test_dwg_read_honours_cancel(tmp_path):
    from algorithms.errors import Canceled

    _, dwg_path = _plan_pair(tmp_path)
    with pytest.raises(Canceled):
        import_dxf(dwg_path, progress=RecordingProgress(cancel_after=2))


def test_sample_building_as_dwg_converts_like_the_dxf(tmp_path):
    """The whole pipeline on a DWG copy of the sample building gives the same Area Graph as on the DXF."""
    from algorithms import osmag
    from algorithms.pipeline import convert_dxf
    from algorithms.sample_building import generate_building

    dxf = generate_building(str(tmp_path), floors=1, seed=3)["dxf"][0]
    dwg = dwg_copy_of(dxf, tmp_path / "sample-F1.dwg")
    a, b = import_dxf(dxf), import_dxf(dwg)
    assert sorted(map(_key, b.geometries)) == sorted(map(_key, a.geometries))
    assert sorted(t.text for t in b.texts) == sorted(t.text for t in a.texts)
    ra = convert_dxf(dxf, str(tmp_path / "a.osm"))
    rb = convert_dxf(dwg, str(tmp_path / "b.osm"))
    assert (rb["areas"], rb["passages"]) == (ra["areas"], ra["passages"]) and ra["areas"] >= 10
    aa, pa, _, _ = osmag.read_osmag(str(tmp_path / "a.osm"))
    ab, pb, _, _ = osmag.read_osmag(str(tmp_path / "b.osm"))
    assert sorted((x.type, x.name) for x in ab) == sorted((x.type, x.name) for x in aa)
    assert sorted(round(x.polygon.area, 1) for x in ab) == sorted(round(x.polygon.area, 1) for x in aa)


# ------------------------------------------------------------------------------------------ bad input
@pytest.fixture(scope="module")
def small_dwg(tmp_path_factory):
    _, dwg_path = _plan_pair(tmp_path_factory.mktemp("dwg"))
    with open(dwg_path, "rb") as fh:
        return fh.read()


def _write(tmp_path, name, data):
    p = tmp_path / name
    p.write_bytes(data)
    return str(p)


@pytest.mark.parametrize("case, expect", [
    ("empty", "is empty"),
    ("blank", "is empty"),
    ("random", "is not a DWG file"),
    ("too_new", "newer than AutoCAD 2018"),
    ("r12", "older than the oldest version"),
    ("unknown_code", "version the reader does not know"),
    ("truncated_head", "damaged or truncated DWG"),
    ("truncated_half", "damaged or truncated DWG"),
])
def test_bad_dwg_gives_a_clear_error(tmp_path, small_dwg, case, expect):
    rng = np.random.default_rng(1)
    data = {
        "empty": b"",
        "blank": b"\x00" * 4096,
        "random": rng.integers(0, 256, 60000, dtype=np.uint8).tobytes(),
        "too_new": b"AC1036" + small_dwg[6:],
        "r12": b"AC1009" + small_dwg[6:],
        "unknown_code": b"AC1030" + small_dwg[6:],
        "truncated_head": small_dwg[:300],
        "truncated_half": small_dwg[:len(small_dwg) // 2],
    }[case]
    path = _write(tmp_path, f"{case}.dwg", data)
    for fn in (import_dxf, inspect_dxf):
        with pytest.raises(InputError) as err:
            fn(path)
        msg = str(err.value)
        assert expect in msg and f"{case}.dwg" in msg
        assert any(w in msg for w in ("save", "export", "choose", "rename")), msg  # says what to do


def test_encrypted_dwg_is_refused(tmp_path):
    """R2004+ header: security flags at 0x18 (1 = encrypted data, 2 = encrypted properties)."""
    head = bytearray(b"AC1018" + b"\x00" * 0x7A)
    head[0x18] = 1
    path = _write(tmp_path, "locked.dwg", bytes(head) + os.urandom(4000))
    with pytest.raises(InputError, match="password-protected"):
        import_dxf(path)


def test_damaged_dwg_never_escapes_as_a_raw_error(tmp_path, small_dwg):
    """Byte-flipped copies either read (the flip hit unused bytes) or raise InputError."""
    n = len(small_dwg)
    for frac in (0.1, 0.3, 0.5, 0.7, 0.9):
        o = int(n * frac)
        data = small_dwg[:o] + bytes(x ^ 0xA5 for x in small_dwg[o:o + 64]) + small_dwg[o + 64:]
        path = _write(tmp_path, f"flip{frac}.dwg", data)
        try:
            d = import_dxf(path, include_doors=True)
        except InputError as exc:
            assert "flip" in str(exc)
        else:
            assert d.geometries


def test_dxf_saved_with_a_dwg_name_reads_as_dxf(tmp_path):
    dxf_path, _ = _plan_pair(tmp_path)
    renamed = tmp_path / "really-a-dxf.dwg"
    renamed.write_bytes(open(dxf_path, "rb").read())
    assert not cad_dwg.is_dwg(str(renamed))
    assert len(import_dxf(str(renamed)).geometries) == len(import_dxf(dxf_path).geometries)


def test_missing_dwg(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        import_dxf(str(tmp_path / "nope.dwg"))


def test_is_dwg_by_extension_or_signature(tmp_path, small_dwg):
    assert cad_dwg.is_dwg(str(tmp_path / "missing.DWG"))
    p = _write(tmp_path, "plan.bin", small_dwg)
    assert cad_dwg.is_dwg(p)
    assert not cad_dwg.is_dwg(_write(tmp_path, "x.dxf", b"  0\nSECTION\n"))


def test_undecoded_message_names_types_and_counts():
    msg = cad_dwg.undecoded_message({"TCH_TEXT": 3, "ACAD_TABLE": 1})
    assert "4 entities" in msg and "3 TCH_TEXT" in msg and "1 ACAD_TABLE" in msg


# ------------------------------------------------------------------------------------------ real sheets
SHEETS = ["sist-original/SIST-F1.dwg", "sist-original/SIST-F3.dwg", "sist-original/SIST-F4.dwg",
          "sist-original/SIST-F5.dwg", "library/A-A3-10-04.dwg", "library/A-A3-10-05.dwg",
          "library/A-A3-10-06.dwg", "library/A-A3-10-08.dwg"]


def _sheet(shared_data, rel):
    p = shared_data / "dwg" / rel
    if not p.is_file():
        pytest.skip(f"{p} is missing")
    return str(p)


@pytest.mark.slow
@pytest.mark.parametrize("rel", SHEETS)
def test_every_shared_sheet_reads(shared_data, rel):
    path = _sheet(shared_data, rel)
    t0 = time.perf_counter()
    d = import_dxf(path, plan="-1e9,-1e9,1e9,1e9")  # the whole sheet: this tests the reader, not plan finding
    dt = time.perf_counter() - t0
    kinds = collections.Counter(g.kind for g in d.geometries)
    ents = collections.Counter(g.entity for g in d.geometries)
    assert len(d.geometries) > 400 and ents["LINE"] > 300, (kinds, ents)
    # floor plans are mostly walls; A-A3-10-08 is the library's roof plan (skylights, slopes): few walls
    assert kinds["wall"] > (50 if rel.endswith("10-08.dwg") else 1000), kinds
    # bound external references keep their full names
    assert any("$0$" in name for name in d.layers)
    # metres after scaling: a floor (or sheet) of plausible size
    xy = np.concatenate([g.coords for g in d.geometries])
    xy = xy[np.isfinite(xy).all(axis=1)]
    size = np.percentile(xy, 98, axis=0) - np.percentile(xy, 2, axis=0)
    assert 20 < size.max() < 1000, size
    assert d.unit_name == "mm"
    # Chinese texts decoded (CJK characters present, no replacement characters)
    texts = [t.text for t in d.texts]
    assert len(texts) > 50
    assert sum(any("\u4e00" <= ch <= "\u9fff" for ch in t) for t in texts) > 10 or rel.startswith("library")
    assert not any("\ufffd" in t for t in texts)
    assert collections.Counter(t.entity for t in d.texts)["ATTRIB"] > 100
    assert dt < 60


@pytest.mark.slow
def test_sist_f1_names_and_attributes(shared_data, floor_cache):
    d = floor_cache.import_dxf(_sheet(shared_data, "sist-original/SIST-F1.dwg"))  # the session's read
    attrib = {t.text for t in d.texts if t.entity == "ATTRIB"}
    text = {t.text for t in d.texts if t.entity != "ATTRIB"}
    assert {"E1-ST-01", "E1-ST-03", "E2-P1"} <= attrib  # stair and lift tags are block attributes
    assert any("楼梯" in t or "卫生间" in t for t in text | attrib)
    assert any(name.startswith("E1-RI-1F$0$") for name in d.layers)


@pytest.mark.slow
def test_library_undecoded_types_are_reported(shared_data):
    rec = RecordingProgress()
    d = import_dxf(_sheet(shared_data, "library/A-A3-10-05.dwg"), progress=rec)
    assert d.undecoded.get("TCH_PATH_ARRAY") == 5 and d.undecoded.get("TCH_TEXT") == 1
    assert any("cannot decode" in m and "TCH_PATH_ARRAY" in m for _, m in rec.messages)


@pytest.mark.slow
def test_sist_f5_reads_fast(shared_data):
    """The largest sheet (77k entities in the file, 67k drawable) must read + explode well under 10 s of CPU."""
    path = _sheet(shared_data, "sist-original/SIST-F5.dwg")
    c0 = time.process_time()
    d = import_dxf(path)
    cpu = time.process_time() - c0
    assert len(d.geometries) > 10000
    assert cpu < 10.0, f"{cpu:.1f} s of CPU"


@pytest.mark.slow
def test_agrees_with_ezdwg_high_level_api(shared_data):
    """Independent check: the model-space entities found through the native row decoders are exactly
    those ezdwg's own (slower) high-level modelspace() query lists, type by type."""
    path = _sheet(shared_data, "sist-original/SIST-F4.dwg")
    doc, _ = cad_dwg.read_dwg(path)
    types = ["LINE", "ARC", "CIRCLE", "LWPOLYLINE", "HATCH", "TEXT", "INSERT", "SOLID", "ELLIPSE"]
    ref = collections.Counter(e.dxftype for e in ezdwg.read(path).modelspace().query(types, include_styles=False))
    ours = collections.Counter(e.dxftype() for e in doc.modelspace() if e.dxftype() in types)
    assert ours == ref
    # and the exploded geometry lies inside the extents the DWG header records
    hv = ezdwg.read(path).header_variables()
    d = import_dxf(path, units="mm")
    xy = np.concatenate([g.coords for g in d.geometries]) / 0.001
    xy = xy[np.isfinite(xy).all(axis=1)]
    lo, hi = np.percentile(xy, 0.5, axis=0), np.percentile(xy, 99.5, axis=0)
    assert lo[0] >= hv["extmin"][0] - 1 and lo[1] >= hv["extmin"][1] - 1
    assert hi[0] <= hv["extmax"][0] + 1 and hi[1] <= hv["extmax"][1] + 1


@pytest.mark.parametrize("extrusion", [(0, 0, 1), (0, 0, -1), (0.6, 0, 0.8)])
def test_insert_matrix_equals_ezdxf(extrusion):
    """The INSERT transform (base point, scale, rotation, OCS) is ezdxf's, also for tilted extrusions."""
    doc = ezdxf.new()
    doc.blocks.new("B", base_point=(100, 50, 0))
    attribs = {"extrusion": extrusion, "rotation": 30, "xscale": 2, "yscale": -1.5}
    ref = doc.modelspace().add_blockref("B", (500, 700, 0), dxfattribs=attribs).matrix44()
    ref = np.array([list(ref.get_row(i)) for i in range(4)])

    class _Doc:
        _base_points = {"b": (100.0, 50.0, 0.0)}

    ours = cad_dwg._Insert(1, {"name": "B", "insert": (500, 700, 0), "zscale": 1, **attribs}, _Doc()).matrix44()
    assert np.allclose(ours[[0, 1, 3], :2], ref[[0, 1, 3], :2], atol=1e-9)


def test_malformed_dwg_entity_data_is_an_input_error(monkeypatch, tmp_path):
    """A damaged DWG the reader decodes without complaint but whose entities hold malformed data (e.g. vertex
    arrays of mixed dimensions) is reported as a damaged DWG naming the file, not as a raw numpy error."""
    from algorithms import cad_import
    from algorithms.errors import InputError

    def broken(*args, **kwargs):
        raise ValueError("all the input arrays must have same number of dimensions")

    monkeypatch.setattr(cad_import, "_read_doc", broken)
    path = tmp_path / "broken.dwg"
    path.write_bytes(b"AC1015" + bytes(100))
    with pytest.raises(InputError, match="broken.dwg.*damaged DWG"):
        cad_import.import_dxf(str(path))
    # an InputError from the reader passes through unchanged
    monkeypatch.setattr(cad_import, "_read_doc", lambda *a, **k: (_ for _ in ()).throw(InputError("named")))
    with pytest.raises(InputError, match="^named$"):
        cad_import.import_dxf(str(path))
