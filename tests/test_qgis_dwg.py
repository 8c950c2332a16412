"""listlayers / extractstructure / dxftoosmag headless through qgis_process on DWG input."""
import csv

import pytest

from algorithms.cad_import import import_dxf

from .qgis_process import gpkg_rows as _rows, gpkg_table as _table, run_alg
from .test_dwg import _plan_pair, dwg_copy_of

pytestmark = pytest.mark.qgis_process


def test_listlayers_and_extractstructure_on_a_dwg(tmp_path):
    _, dwg = _plan_pair(tmp_path)
    _, res, _ = run_alg("listlayers", {"INPUT": dwg, "OUTPUT": str(tmp_path / "layers.csv")})
    rows = {r["layer"]: r for r in csv.DictReader(open(tmp_path / "layers.csv", encoding="utf-8"))}
    assert res["HEADER_UNIT"] == "mm" and res["LAYER_COUNT"] == len(rows)
    wall = rows["E1-RI-1F$0$A-WALL"]
    assert wall["kind"] == "wall" and wall["n_line"] == "4" and wall["n_lwpolyline"] == "1"
    assert rows["A-DOOR"]["kind"] == "door" and rows["A-DOOR"]["n_arc"] == "6"
    assert rows["A-ANNO"]["n_attrib"] == "4" and rows["A-ANNO"]["n_text"] == "1"
    assert rows["FURN"]["frozen"] == "1" and rows["OFFLAYER"]["off"] == "1"
    assert "E1-RI-1F$0$A-WALL" in res["KEPT_LAYERS"].split(";")

    walls, texts = tmp_path / "walls.gpkg", tmp_path / "texts.gpkg"
    _, res, _ = run_alg("extractstructure", {"INPUT": dwg, "WALLS": str(walls), "TEXTS": str(texts)})
    ref = import_dxf(dwg)
    assert res["UNIT"] == "mm" and res["GEOMETRY_COUNT"] == len(ref.geometries) and res["TEXT_COUNT"] == 6
    got = {r[0]: r[1:] for r in _rows(texts, f'select text, entity, layer from "{_table(texts)}"')}
    assert got["办公室"] == ("ATTRIB", "A-ANNO") and got["A102"] == ("ATTRIB", "A-ANNO")
    assert got["E1-ST-03 楼梯"][0] == "TEXT" and got["走廊 2F"][0] == "MTEXT"


def test_dxftoosmag_on_a_dwg(tmp_path):
    from algorithms import osmag
    from algorithms.sample_building import generate_building

    dxf = generate_building(str(tmp_path), floors=1, seed=2)["dxf"][0]
    dwg = dwg_copy_of(dxf, tmp_path / "sample-F1.dwg")
    out = tmp_path / "f1.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": dwg, "OUTPUT": str(out), "ANCHOR": "121.59,31.179 [EPSG:4326]"})
    assert res["AREA_COUNT"] >= 10 and res["PASSAGE_COUNT"] >= 10
    areas, passages, _, _ = osmag.read_osmag(str(out))
    assert {"stairs", "elevator", "corridor", "room"} <= {a.type for a in areas}


def test_bad_dwg_fails_clearly_without_output(tmp_path):
    _, dwg = _plan_pair(tmp_path)
    data = open(dwg, "rb").read()
    cut = tmp_path / "cut.dwg"
    cut.write_bytes(data[: len(data) // 3])
    new = tmp_path / "new.dwg"
    new.write_bytes(b"AC1040" + data[6:])
    walls = tmp_path / "walls.gpkg"
    for path, expect in ((cut, "damaged or truncated DWG"), (new, "newer than AutoCAD 2018")):
        code, _, out = run_alg("extractstructure", {"INPUT": str(path), "WALLS": str(walls),
                                                    "TEXTS": str(tmp_path / "t.gpkg")}, check=False)
        assert code != 0 and expect in out and "Traceback" not in out and not walls.exists()
    osm = tmp_path / "x.osm"
    code, _, out = run_alg("dxftoosmag", {"INPUT": str(cut), "OUTPUT": str(osm)}, check=False)
    assert code != 0 and "damaged or truncated DWG" in out and not osm.exists()


@pytest.mark.slow
def test_real_sheet_headless(shared_data, tmp_path):
    dwg = shared_data / "dwg" / "sist-original" / "SIST-F1.dwg"
    if not dwg.is_file():
        pytest.skip(f"{dwg} is missing")
    _, res, _ = run_alg("listlayers", {"INPUT": str(dwg), "OUTPUT": str(tmp_path / "layers.csv")})
    rows = {r["layer"]: r for r in csv.DictReader(open(tmp_path / "layers.csv", encoding="utf-8"))}
    assert res["LAYER_COUNT"] > 150 and res["HEADER_UNIT"] == "mm"
    assert any("$0$" in name and r["kind"] == "wall" and r["kept"] == "1" for name, r in rows.items())
    walls, texts = tmp_path / "walls.gpkg", tmp_path / "texts.gpkg"
    _, res, _ = run_alg("extractstructure", {"INPUT": str(dwg), "WALLS": str(walls), "TEXTS": str(texts)})
    assert res["GEOMETRY_COUNT"] > 5000 and res["TEXT_COUNT"] > 500
    names = {r[0] for r in _rows(texts, f'select text from "{_table(texts)}" where entity = \'ATTRIB\'')}
    assert {"E1-ST-01", "E2-P1"} <= names
