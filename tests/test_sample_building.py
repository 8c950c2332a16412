"""The built-in sample building: determinism, DXF structure and ground-truth consistency."""
import itertools
import os

import ezdxf
import numpy as np
import pytest
from ezdxf import path as dxfpath
from shapely.geometry import LineString, Point, box
from shapely.strtree import STRtree

from algorithms.errors import Canceled, InputError
from algorithms.progress import RecordingProgress
from algorithms.sample_building import (generate_building, ground_truth_anchors, ground_truth_doors,
                                        ground_truth_envelope, ground_truth_rooms)

FLOORS = 3


@pytest.fixture(scope="module")
def build(tmp_path_factory):
    base = tmp_path_factory.mktemp("sample_building")
    a = generate_building(str(base / "a"), floors=FLOORS, seed=0)
    b = generate_building(str(base / "b"), floors=FLOORS, seed=0)
    c = generate_building(str(base / "c"), floors=FLOORS, seed=1, name="other")
    return {"a": a, "b": b, "c": c}


@pytest.fixture(scope="module")
def docs(build):
    return [ezdxf.readfile(p) for p in build["a"]["dxf"]]


def explode(doc):
    """(effective layer, entity) for every entity of the model space, blocks exploded recursively;
    entities on layer "0" inside a block take the layer of the INSERT that places them."""
    out = []

    def rec(entities, parent):
        for e in entities:
            layer = e.dxf.layer
            if layer == "0" and parent:
                layer = parent
            kind = e.dxftype()
            if kind == "INSERT":
                rec(list(e.virtual_entities()), layer)
                out.extend((a.dxf.layer, a) for a in e.attribs)
            elif kind == "DIMENSION":
                rec(list(e.virtual_entities()), layer)
            else:
                out.append((layer, e))

    rec(doc.modelspace(), None)
    return out


def segments_m(entities):
    """Straight pieces (metres, WCS) of LINE / LWPOLYLINE / ARC entities."""
    segs = []
    for e in entities:
        if e.dxftype() not in ("LINE", "LWPOLYLINE", "ARC", "POLYLINE"):
            continue
        pts = [(v.x / 1000.0, v.y / 1000.0) for v in dxfpath.make_path(e).flattening(5)]
        segs += [LineString([p, q]) for p, q in zip(pts, pts[1:]) if p != q]
    return segs


def plain(e):
    kind = e.dxftype()
    if kind == "MTEXT":
        return " ".join(e.plain_text().split())
    return e.dxf.text


# --------------------------------------------------------------------------- files and determinism
def test_files_and_return_value(build):
    res = build["a"]
    assert res["floors"] == FLOORS
    assert [os.path.basename(p) for p in res["dxf"]] == [f"sample-F{k}.dxf" for k in (1, 2, 3)]
    assert [os.path.basename(p) for p in res["ground_truth"]] == [f"sample-F{k}.gt.geojson" for k in (1, 2, 3)]
    for p in res["dxf"] + res["ground_truth"]:
        assert os.path.getsize(p) > 10000
    # no temporary files are left behind by the atomic writes
    assert sorted(os.listdir(os.path.dirname(res["dxf"][0]))) == sorted(
        os.path.basename(p) for p in res["dxf"] + res["ground_truth"])
    assert [os.path.basename(p) for p in build["c"]["dxf"]][0] == "other-F1.dxf"
    assert res["anchors"] == {"Stair A": (17.7, 17.1), "Lift 1": (20.5, 15.4)}
    assert res["envelope"] == (0.0, 0.0, 40.0, 25.0)
    assert res["names"][0][:2] == ["Hall", "Office 101"] and len(res["names"]) == FLOORS


def test_same_seed_is_byte_identical_other_seed_differs(build):
    for pa, pb, pc in zip(build["a"]["dxf"] + build["a"]["ground_truth"],
                          build["b"]["dxf"] + build["b"]["ground_truth"],
                          build["c"]["dxf"] + build["c"]["ground_truth"]):
        da, db, dc = (open(p, "rb").read() for p in (pa, pb, pc))
        assert da == db, pa
        assert da != dc, pa
    # floors differ from each other too
    f1, f2 = (open(p, "rb").read() for p in build["a"]["dxf"][:2])
    assert f1 != f2


# --------------------------------------------------------------------------- DXF structure
def test_header_layers_and_blocks(docs):
    for doc in docs:
        assert doc.dxfversion in ("AC1027", "AC1032")
        assert doc.header["$INSUNITS"] == 4
        emin, emax = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
        assert emin[0] < 0 < 40000 < emax[0] and emin[1] < 0 < 25000 < emax[1]
        layers = {layer.dxf.name for layer in doc.layers}
        for name in ("A-WALL", "A-WALL-PATT", "A-DOOR", "A-GLAZ", "A-STAIR", "A-FLOR-EVTR", "A-COLS",
                     "A-FURN", "A-ANNO-TEXT",
                     "A-ANNO-DIMS", "S-GRID", "A-FLOR-PATT"):
            assert name in layers
        for name in ("DOOR_800", "DOOR_900", "DOOR_1000", "DOOR_DBL_1800", "OFFICE_MODULE", "ROOM_TAG",
                     "WORKSTATION"):
            assert name in doc.blocks
        door = doc.blocks["DOOR_900"]
        assert sorted(e.dxftype() for e in door) == ["ARC", "LINE"]
        assert all(e.dxf.layer == "0" for e in door)
        module = list(doc.blocks["OFFICE_MODULE"])
        walls = [e for e in module if e.dxftype() in ("LINE", "LWPOLYLINE")]
        assert len(walls) >= 4 and all(e.dxf.layer == "0" for e in walls)
        nested = [e for e in module if e.dxftype() == "INSERT"]
        assert any(e.dxf.name.startswith("DOOR_") and e.dxf.layer == "A-DOOR" for e in nested)
        assert any(e.dxf.name == "WORKSTATION" for e in nested)  # itself nests DESK and CHAIR
        assert {e.dxf.name for e in doc.blocks["WORKSTATION"]} == {"DESK_1600", "CHAIR"}
        assert [e.dxf.tag for e in doc.blocks["ROOM_TAG"] if e.dxftype() == "ATTDEF"] == ["NAME"]


def test_inserts_rotated_and_mirrored(docs):
    for doc in docs:
        msp = doc.modelspace()
        doors = [e for e in msp.query("INSERT") if e.dxf.name.startswith("DOOR_")]
        assert all(e.dxf.layer == "A-DOOR" for e in doors)
        assert any(e.dxf.xscale < 0 for e in doors)
        assert any(round(e.dxf.rotation) % 360 in (90, 270) for e in doors)
        assert any(round(e.dxf.rotation) % 360 == 0 and e.dxf.xscale > 0 for e in doors)
        modules = [e for e in msp.query("INSERT") if e.dxf.name == "OFFICE_MODULE"]
        assert len(modules) >= 3 and all(e.dxf.layer == "A-WALL" for e in modules)
        assert any(round(e.dxf.rotation) == 180 and e.dxf.xscale > 0 for e in modules)
        assert any(e.dxf.xscale < 0 for e in modules)


def test_text_mtext_attrib_and_annotations(docs):
    for doc in docs:
        msp = doc.modelspace()
        texts = [e for e in msp.query("TEXT") if e.dxf.layer == "A-ANNO-TEXT"]
        mtexts = [e for e in msp.query("MTEXT") if e.dxf.layer == "A-ANNO-TEXT"]
        assert len(texts) >= 5 and len(mtexts) >= 3
        raw = [m.text for m in mtexts]
        assert any("{\\fArial|b1;" in t for t in raw) and any("\\P" in t for t in raw)
        tags = [e for e in msp.query("INSERT") if e.dxf.name == "ROOM_TAG"]
        assert tags and all(e.attribs and e.attribs[0].dxf.tag == "NAME" for e in tags)
        dims = msp.query("DIMENSION")
        assert len(dims) >= 5 and all(d.dxf.layer == "A-ANNO-DIMS" for d in dims)
        hatches = msp.query("HATCH")
        assert any(h.dxf.solid_fill and h.dxf.layer == "A-WALL" for h in hatches)
        assert any(h.dxf.solid_fill and h.dxf.layer == "A-COLS" for h in hatches)
        assert any(not h.dxf.solid_fill and h.dxf.layer == "A-FLOR-PATT" for h in hatches)
        grid = [e for e in msp.query("LINE") if e.dxf.layer == "S-GRID"]
        assert max(e.dxf.start.distance(e.dxf.end) for e in grid) > 30000  # axes reach past the walls
        assert any("LEVEL" in e.dxf.text for e in msp.query("TEXT") if e.dxf.layer == "A-ANNO-TITL")


def test_room_texts_equal_ground_truth_names_and_sit_in_their_room(build, docs):
    for doc, gt in zip(docs, build["a"]["ground_truth"]):
        rooms = {r["name"]: r["polygon"] for r in ground_truth_rooms(gt)}
        labels = {}
        for layer, e in explode(doc):
            if layer == "A-ANNO-TEXT" and e.dxftype() in ("TEXT", "MTEXT", "ATTRIB"):
                name = plain(e)
                assert name not in labels, f"duplicate label {name}"
                ins = e.dxf.align_point if e.dxftype() != "MTEXT" and e.dxf.halign else e.dxf.insert
                labels[name] = Point(ins.x / 1000.0, ins.y / 1000.0)
        assert set(labels) == set(rooms)
        for name, pt in labels.items():
            assert rooms[name].contains(pt), name


# --------------------------------------------------------------------------- ground-truth figures
def test_ground_truth_rooms(build):
    counts = []
    for k, gt in enumerate(build["a"]["ground_truth"], start=1):
        rooms = ground_truth_rooms(gt)
        counts.append(len(rooms))
        names = [r["name"] for r in rooms]
        assert len(names) == len(set(names))
        for must in ("Stair A", "Lift 1", "Hall", "WC", "Corridor", f"Office {k}01", f"Office {k}02"):
            assert must in names
        assert all(r["level"] == k for r in rooms)
        numbered = [n for n in names if n.startswith(("Office", "Meeting Room"))]
        assert all(n.split()[-1].startswith(str(k)) and len(n.split()[-1]) == 3 for n in numbered)
        assert any(n.startswith("Meeting Room") for n in names)
        types = {r["name"]: r["areatype"] for r in rooms}
        assert types["Stair A"] == "stairs" and types["Lift 1"] == "elevator"
        assert types["Corridor"] == "corridor" and types["Office 101".replace("1", str(k), 1)] == "room"

        env = ground_truth_envelope(gt)
        assert env.bounds == (0.0, 0.0, 40.0, 25.0)
        total = sum(r["polygon"].area for r in rooms)
        assert 0.85 * env.area < total < env.area  # walls take the rest
        for r in rooms:
            assert r["polygon"].is_valid and r["polygon"].area > 5.0, r["name"]
            assert env.contains(r["polygon"])
        for a, b in itertools.combinations(rooms, 2):
            assert a["polygon"].intersection(b["polygon"]).area < 1e-9, (a["name"], b["name"])

        poly = {r["name"]: r["polygon"] for r in rooms}
        hall = poly["Hall"]
        x0, y0, x1, y1 = hall.bounds
        assert hall.area > 100.0 and x1 - x0 > 10.0 and y1 - y0 > 10.0
        # corridor: vertical cuts every 0.5 m across its whole length are 1.8-2.4 m long
        cor = poly["Corridor"]
        cx0, cy0, cx1, cy1 = cor.bounds
        assert cx1 - cx0 > 35.0
        widths = []
        for x in np.arange(cx0 + 0.25, cx1, 0.5):
            cut = cor.intersection(LineString([(x, cy0 - 1), (x, cy1 + 1)]))
            widths.append(cut.length)
        assert 1.8 - 1e-9 <= min(widths) and max(widths) <= 2.4 + 1e-9
        assert poly["Stair A"].area > 15.0 and 4.0 < poly["Lift 1"].area < 8.0
    assert counts == build["a"]["rooms"]
    assert counts == [18, 19, 20]  # seed 0: upper floors have more offices


def test_ground_truth_doors(build):
    for k, gt in enumerate(build["a"]["ground_truth"], start=1):
        rooms = {r["name"]: r["polygon"] for r in ground_truth_rooms(gt)}
        doors = ground_truth_doors(gt)
        assert len(doors) == build["a"]["doors"][k - 1]
        outside = [d for d in doors if d["to"] == "outside"]
        assert len(outside) == (1 if k == 1 else 0)
        if outside:
            assert outside[0]["from"] == "Hall" and abs(outside[0]["width"] - 1.8) < 1e-9
        pairs = set()
        for d in doors:
            assert d["from"] in rooms and (d["to"] in rooms or d["to"] == "outside")
            assert d["from"] != d["to"]
            assert d["level"] == k
            assert d["width"] in (0.8, 0.9, 1.0, 1.8)
            assert abs(d["line"].length - d["width"]) < 1e-9
            pairs.add(frozenset((d["from"], d["to"])))
            # the opening touches both rooms it joins but lies in neither (openings belong to no room)
            mid = d["line"].interpolate(0.5, normalized=True)
            assert not any(p.contains(mid) for p in rooms.values())
            for n in (d["from"], d["to"]):
                if n != "outside":
                    assert rooms[n].distance(d["line"]) < 0.16
        assert frozenset(("Hall", "Corridor")) in pairs
        assert any(d["width"] == 1.8 and {d["from"], d["to"]} == {"Hall", "Corridor"} for d in doors)
        for n in rooms:  # every room can be reached
            assert any(n in p for p in pairs), n


def test_stair_and_lift_identical_across_floors(build):
    ref = None
    for gt in build["a"]["ground_truth"] + build["c"]["ground_truth"]:
        rooms = {r["name"]: r["polygon"] for r in ground_truth_rooms(gt)}
        anchors = {a["name"]: a for a in ground_truth_anchors(gt)}
        assert set(anchors) == {"Stair A", "Lift 1"}
        assert anchors["Lift 1"]["areatype"] == "elevator" and anchors["Stair A"]["areatype"] == "stairs"
        for n, a in anchors.items():
            assert rooms[n].contains(a["point"])
            assert a["point"].distance(Point(build["a"]["anchors"][n])) < 1e-9
        cur = (rooms["Stair A"], rooms["Lift 1"])
        if ref is None:
            ref = cur
        else:
            assert cur[0].equals_exact(ref[0], 1e-9) and cur[1].equals_exact(ref[1], 1e-9)
    assert ref[1].bounds == (19.4, 14.2, 21.6, 16.6)


# --------------------------------------------------------------------------- geometry consistency
def test_exploded_geometry_matches_ground_truth(build, docs):
    for doc, gt in zip(docs, build["a"]["ground_truth"]):
        ents = explode(doc)
        layers = {layer for layer, _ in ents}
        assert "0" not in {layer for layer, e in ents if e.dxftype() in ("LINE", "LWPOLYLINE", "ARC")}
        assert {"A-WALL", "A-DOOR", "A-GLAZ", "A-STAIR", "A-FLOR-EVTR", "A-COLS", "A-FURN"} <= layers
        walls = segments_m([e for layer, e in ents if layer == "A-WALL"])
        assert len(walls) > 100
        xs = [c[0] for s in walls for c in s.coords]
        ys = [c[1] for s in walls for c in s.coords]
        assert abs(max(xs) - min(xs) - 40.0) < 0.05 and abs(max(ys) - min(ys) - 25.0) < 0.05

        rooms = ground_truth_rooms(gt)
        shrunk = [r["polygon"].buffer(-0.01) for r in rooms]
        tree = STRtree(shrunk)
        for s in walls:  # no wall drawn inside a room
            for f in (0.1, 0.5, 0.9):
                p = s.interpolate(f, normalized=True)
                hits = tree.query(p, predicate="intersects")
                assert len(hits) == 0, (rooms[hits[0]]["name"], p)

        # every door endpoint lies on a jamb, i.e. on drawn wall geometry
        wtree = STRtree(walls)
        for d in ground_truth_doors(gt):
            for c in d["line"].coords:
                p = Point(c)
                nearest = walls[wtree.nearest(p)]
                assert nearest.distance(p) < 1e-3, (d, c)

        # each swing arc is hinged at a jamb of a ground-truth door with the door's radius
        arcs = [e for layer, e in ents if layer == "A-DOOR" and e.dxftype() == "ARC"]
        ends = [(Point(c), d["width"]) for d in ground_truth_doors(gt) for c in d["line"].coords]
        lift_doors = [d for d in ground_truth_doors(gt) if "Lift 1" in (d["from"], d["to"])]
        assert len(arcs) == sum(2 if d["width"] == 1.8 else 1 for d in ground_truth_doors(gt)) - len(lift_doors)
        for a in arcs:
            c = a.ocs().to_wcs(a.dxf.center)
            hinge = Point(c.x / 1000.0, c.y / 1000.0)
            r = a.dxf.radius / 1000.0
            assert any(hinge.distance(p) <= 0.16 and abs(r - (w / 2 if w == 1.8 else w)) < 1e-6
                       for p, w in ends), (hinge, r)
            # the leaf swings into a room, not into a wall
            mid = list(dxfpath.make_path(a).flattening(10))
            m = mid[len(mid) // 2]
            assert any(rr["polygon"].contains(Point(m.x / 1000.0, m.y / 1000.0)) for rr in rooms)

        # glazing sits in the exterior wall band
        glaz = segments_m([e for layer, e in ents if layer == "A-GLAZ"])
        assert len(glaz) > 40
        band = box(0, 0, 40, 25).difference(box(0.3, 0.3, 39.7, 24.7))
        assert all(band.buffer(1e-6).contains(s) for s in glaz)
        # stair treads and the lift cross are inside their rooms
        poly = {r["name"]: r["polygon"] for r in rooms}
        for layer, name in (("A-STAIR", "Stair A"), ("A-FLOR-EVTR", "Lift 1")):
            segs = segments_m([e for lay, e in ents if lay == layer])
            assert len(segs) > (20 if layer == "A-STAIR" else 4)
            assert all(poly[name].buffer(1e-6).contains(s) for s in segs)


# --------------------------------------------------------------------------- other seeds, errors
@pytest.mark.parametrize("seed", [2, 3, 4, 5, 6, 7])
def test_other_seeds_are_valid(tmp_path, seed):
    # the generator checks itself that every free region carries exactly one label and every door
    # joins two different regions; here: the figures that later stages rely on
    res = generate_building(str(tmp_path), floors=2, seed=seed)
    for gt in res["ground_truth"]:
        rooms = {r["name"]: r["polygon"] for r in ground_truth_rooms(gt)}
        assert 17 <= len(rooms) <= 24
        hall = rooms["Hall"]
        assert hall.area > 100 and hall.bounds[2] - hall.bounds[0] > 10
        assert rooms["Lift 1"].bounds == (19.4, 14.2, 21.6, 16.6)
        assert all(d["from"] in rooms for d in ground_truth_doors(gt))


def test_invalid_arguments(tmp_path):
    with pytest.raises(InputError):
        generate_building(str(tmp_path / "x"), floors=0)
    with pytest.raises(InputError):
        generate_building(str(tmp_path / "x"), floors="many")
    with pytest.raises(InputError):
        generate_building(str(tmp_path / "x"), floors=1, name="a/b")
    assert not (tmp_path / "x").exists()


def test_progress_and_cancel(tmp_path):
    rec = RecordingProgress()
    generate_building(str(tmp_path / "ok"), floors=2, seed=0, progress=rec)
    assert rec.percents[-1] == 100.0 and rec.percents == sorted(rec.percents)
    assert "floor 2 of 2" in rec.text()
    with pytest.raises(Canceled):
        generate_building(str(tmp_path / "stop"), floors=3, seed=0, progress=RecordingProgress(cancel_after=1))
    assert not os.path.exists(tmp_path / "stop" / "sample-F2.dxf")


def test_identical_bytes_across_processes_with_different_string_hashing(tmp_path):
    """The same seed gives the same bytes in another process too (qgis_process, CI), whatever its
    PYTHONHASHSEED: nothing in the file may follow set or dict-of-hash order."""
    import os
    import subprocess
    import sys

    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    digests = []
    for hashseed in ("1", "7"):
        out = tmp_path / hashseed
        code = ("import sys; sys.path.insert(0, %r); from algorithms.sample_building import generate_building; "
                "generate_building(%r, floors=1, seed=3)") % (repo, str(out))
        subprocess.run([sys.executable, "-c", code], check=True, env=dict(os.environ, PYTHONHASHSEED=hashseed))
        digests.append((out / "sample-F1.dxf").read_bytes())
    assert digests[0] == digests[1]
