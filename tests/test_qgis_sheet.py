"""listlayers / extractstructure headless through qgis_process on whole sheets, bound-xref layer names and
spaghetti drawings (PLAN, matched layer names, door hints, entity classes)."""
import csv

import ezdxf
import pytest

from algorithms.sample_building import generate_delivered

from .qgis_process import gpkg_rows as _rows, run_alg

pytestmark = pytest.mark.qgis_process


def test_listlayers_shows_the_matched_part_of_xref_names(tmp_path):
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    for lay in ("E1-RI-1F$0$A-WALL", "TEXT-XREF$0$$2$A-GLAZ", "E1$0$A-ANNO-TEXT"):
        doc.layers.add(lay)
    msp = doc.modelspace()
    for a, b in (((0, 0), (12, 0)), ((12, 0), (12, 8)), ((12, 8), (0, 8)), ((0, 8), (0, 0))):
        msp.add_line(a, b, dxfattribs={"layer": "E1-RI-1F$0$A-WALL"})
    msp.add_line((0, 3), (0, 5), dxfattribs={"layer": "TEXT-XREF$0$$2$A-GLAZ"})
    msp.add_text("Office", dxfattribs={"layer": "E1$0$A-ANNO-TEXT", "insert": (5, 4), "height": 0.3})
    dxf = str(tmp_path / "xref.dxf")
    doc.saveas(dxf)
    _, res, _ = run_alg("listlayers", {"INPUT": dxf, "OUTPUT": str(tmp_path / "layers.csv")})
    rows = {r["layer"]: r for r in csv.DictReader(open(tmp_path / "layers.csv", encoding="utf-8"))}
    assert rows["E1-RI-1F$0$A-WALL"]["matched"] == "A-WALL" and rows["E1-RI-1F$0$A-WALL"]["kind"] == "wall"
    # 'text' in the xref's file name does not exclude the glazing layer; it does exclude the real text layer
    assert rows["TEXT-XREF$0$$2$A-GLAZ"]["matched"] == "A-GLAZ" and rows["TEXT-XREF$0$$2$A-GLAZ"]["kind"] == "window"
    assert rows["E1$0$A-ANNO-TEXT"]["kind"] == ""
    assert "TEXT-XREF$0$$2$A-GLAZ" in res["KEPT_LAYERS"].split(";")


def test_extractstructure_plan_parameter_on_a_whole_sheet(tmp_path):
    out = generate_delivered(str(tmp_path), sheet=True, name="sheet")
    walls, texts = tmp_path / "walls.gpkg", tmp_path / "texts.gpkg"
    _, res, log = run_alg("extractstructure", {"INPUT": out["dxf"], "WALLS": str(walls), "TEXTS": str(texts)})
    assert res["PLAN_COUNT"] == 2 and "[0] plan" in res["PLANS"] and "[1] detail" in res["PLANS"]
    assert "详图" in res["PLANS"]
    xmax = _rows(walls, 'select max(maxx) from "rtree_{t}_geom"')[0][0]
    assert xmax <= out["plan_extent"][2] + 1.0
    names = {r[0] for r in _rows(texts, 'select text from "{t}"')}
    assert "Office 101" in names
    walls1 = tmp_path / "walls1.gpkg"
    _, res1, _ = run_alg("extractstructure", {"INPUT": out["dxf"], "PLAN": "1", "WALLS": str(walls1),
                                              "TEXTS": str(tmp_path / "texts1.gpkg")})
    x0, y0, x1, y1 = out["detail_extent"]
    minx, maxx = _rows(walls1, 'select min(minx), max(maxx) from "rtree_{t}_geom"')[0]
    assert minx >= x0 - 1.0 and maxx <= x1 + 1.0 and res1["GEOMETRY_COUNT"] < res["GEOMETRY_COUNT"]
    # the same view by its extent, as the canvas would draw it (QGIS extent text: xmin,xmax,ymin,ymax)
    _, res2, _ = run_alg("extractstructure", {"INPUT": out["dxf"], "PLAN_EXTENT": f"{x0 - 1},{x1 + 1},{y0 - 1},{y1 + 1}",
                                              "WALLS": str(tmp_path / "w2.gpkg"), "TEXTS": str(tmp_path / "t2.gpkg")})
    assert res2["GEOMETRY_COUNT"] == res1["GEOMETRY_COUNT"]
    code, _, log = run_alg("extractstructure", {"INPUT": out["dxf"], "PLAN": "7", "WALLS": str(tmp_path / "w3.gpkg"),
                                                "TEXTS": str(tmp_path / "t3.gpkg")}, check=False)
    assert code != 0 and "PLAN=7 does not exist" in log and "Traceback" not in log
    assert not (tmp_path / "w3.gpkg").exists()


def test_extractstructure_on_a_spaghetti_plan_finds_doors_and_furniture(tmp_path):
    out = generate_delivered(str(tmp_path), spaghetti=True, name="sp")
    doors = tmp_path / "doors.gpkg"
    _, res, log = run_alg("extractstructure", {"INPUT": out["dxf"], "WALLS": str(tmp_path / "w.gpkg"),
                                               "TEXTS": str(tmp_path / "t.gpkg"), "DOORS": str(doors)})
    assert res["DOOR_COUNT"] >= out["doors"] - 2
    classes = dict(kv.split("=") for kv in res["CLASSES"].split("; "))
    assert int(classes["furniture"]) >= 50 and int(classes["door"]) >= 30 and int(classes["hatch"]) == 2
    widths = [r[0] for r in _rows(doors, 'select width from "{t}"')]
    assert len(widths) == res["DOOR_COUNT"] and all(0.6 <= w <= 2.0 for w in widths)
    tags = _rows(tmp_path / "t.gpkg", 'select text, block, tag from "{t}" where entity = \'ATTRIB\'')
    assert tags and all(b == "ROOM_TAG" and t == "NAME" for _, b, t in tags)


def test_dxftoosmag_on_a_whole_sheet_converts_the_main_plan_or_the_picked_one(tmp_path):
    from algorithms import osmag

    out = generate_delivered(str(tmp_path), sheet=True, name="sheet")
    osm = tmp_path / "sheet.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": out["dxf"], "OUTPUT": str(osm), "OUTPUT_AREAS": "memory:",
                                         "OUTPUT_PASSAGES": "memory:"})
    assert res["AREA_COUNT"] >= 15 and res["PASSAGE_COUNT"] >= 15
    assert "[1] detail" in log  # the log lists the groups found on the sheet
    # picked explicitly, the enlarged detail converts too (one stair core)
    osm1 = tmp_path / "detail.osm"
    _, res1, _ = run_alg("dxftoosmag", {"INPUT": out["dxf"], "OUTPUT": str(osm1), "PLAN": "1",
                                        "OUTPUT_AREAS": "memory:", "OUTPUT_PASSAGES": "memory:"})
    assert 1 <= res1["AREA_COUNT"] <= 3
    areas, _, _, _ = osmag.read_osmag(str(osm1))
    assert areas
