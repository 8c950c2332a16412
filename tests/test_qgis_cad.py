"""listlayers / extractstructure / rasterize headless through qgis_process on small synthetic DXFs."""
import csv

import ezdxf
import numpy as np
import pytest

from algorithms.cad_import import import_dxf
from algorithms.raster_io import read_grid
from algorithms.rasterize import rasterize

from .qgis_inprocess import run_alg_inprocess
from .qgis_process import gpkg_rows as _gpkg_rows, gpkg_table as _table, run_alg

pytestmark = pytest.mark.qgis_process


def _plan(path, dx=0.0, units=4):
    """A 20 m x 10 m room in millimetres with a partition, a door block, a column hatch and texts."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = units
    msp = doc.modelspace()
    pts = [(0, 0), (20000, 0), (20000, 10000), (0, 10000)]
    for a, b in zip(pts, pts[1:] + pts[:1]):
        msp.add_line((a[0] + dx, a[1]), (b[0] + dx, b[1]), dxfattribs={"layer": "A-WALL"})
    msp.add_lwpolyline([(8000 + dx, 0), (8000 + dx, 4000)], dxfattribs={"layer": "Muri", "const_width": 200})
    msp.add_lwpolyline([(8000 + dx, 5000), (8000 + dx, 10000)], dxfattribs={"layer": "Muri"})
    door = doc.blocks.new("DOOR")
    door.add_arc((0, 0), 900, 0, 90, dxfattribs={"layer": "0"})
    door.add_line((0, 0), (0, 900), dxfattribs={"layer": "0"})
    msp.add_blockref("DOOR", (8000 + dx, 4000), dxfattribs={"layer": "A-DOOR"})
    h = msp.add_hatch(dxfattribs={"layer": "A-COLS"})
    h.paths.add_polyline_path([(14000 + dx, 4000), (14400 + dx, 4000), (14400 + dx, 4400), (14000 + dx, 4400)])
    msp.add_text("Office", dxfattribs={"layer": "A-ANNO-TEXT", "height": 250, "insert": (4000 + dx, 5000)})
    msp.add_mtext(r"{\LMeeting} room", dxfattribs={"layer": "A-ANNO-TEXT", "char_height": 250,
                                                    "insert": (12000 + dx, 5000)})
    msp.add_line((0, -2000), (20000, -2000), dxfattribs={"layer": "A-ANNO-DIMS"})
    doc.saveas(path)
    return str(path)


def test_listlayers_writes_a_csv_report(tmp_path):
    dxf = _plan(tmp_path / "plan.dxf")
    _, res, _ = run_alg("listlayers", {"INPUT": dxf, "OUTPUT": str(tmp_path / "layers.csv")})
    rows = {r["layer"]: r for r in csv.DictReader(open(tmp_path / "layers.csv", encoding="utf-8"))}
    assert res["HEADER_UNIT"] == "mm" and res["LAYER_COUNT"] == len(rows)
    assert rows["A-WALL"]["kind"] == "wall" and rows["A-WALL"]["n_line"] == "4"
    assert rows["A-DOOR"]["kind"] == "door" and rows["A-DOOR"]["n_arc"] == "1" and rows["A-DOOR"]["n_line"] == "1"
    assert rows["A-ANNO-TEXT"]["kind"] == "" and rows["A-ANNO-TEXT"]["n_text"] == "1"
    assert rows["A-ANNO-TEXT"]["n_mtext"] == "1"
    assert rows["A-COLS"]["n_hatch"] == "1" and rows["Muri"]["kind"] == "wall"
    kept = set(res["KEPT_LAYERS"].split(";"))
    assert {"A-WALL", "Muri", "A-COLS"} <= kept and "A-DOOR" not in kept and "A-ANNO-DIMS" not in kept


def test_extract_then_rasterize_matches_the_library(tmp_path):
    dxf = _plan(tmp_path / "plan.dxf")
    walls, texts = tmp_path / "walls.gpkg", tmp_path / "texts.gpkg"
    _, res, _ = run_alg("extractstructure", {"INPUT": dxf, "WALLS": str(walls), "TEXTS": str(texts)})
    assert res["UNIT"] == "mm" and res["UNIT_SCALE"] == pytest.approx(0.001)
    assert res["GEOMETRY_COUNT"] == 7 and res["TEXT_COUNT"] == 2
    wt = _table(walls)
    rows = _gpkg_rows(walls, f'select layer, kind, entity, closed, filled, width from "{wt}"')
    assert sorted({r[0] for r in rows}) == ["A-COLS", "A-WALL", "Muri"]
    assert ("Muri", "wall", "LWPOLYLINE", 0, 0, pytest.approx(0.2)) in [tuple(r) for r in rows]
    assert any(r[0] == "A-COLS" and r[3] == 1 and r[4] == 1 for r in rows)  # solid hatch: closed + filled
    srs = _gpkg_rows(walls, "select s.definition from gpkg_spatial_ref_sys s join gpkg_geometry_columns g "
                            "on s.srs_id = g.srs_id")[0][0]
    assert "drawing frame" in srs  # the local engineering CRS
    tt = _table(texts)
    trows = dict((r[0], r[1:]) for r in _gpkg_rows(texts, f'select text, height, layer, entity from "{tt}"'))
    assert trows["Office"] == (pytest.approx(0.25), "A-ANNO-TEXT", "TEXT")
    assert trows["Meeting room"][2] == "MTEXT"

    tif = tmp_path / "occ.tif"
    _, res, _ = run_alg("rasterize", {"WALLS": str(walls), "OCCUPANCY": str(tif)})
    grid = read_grid(str(tif))
    ref = rasterize(import_dxf(dxf).geometries)
    assert grid.shape == ref.shape and grid.geotransform == pytest.approx(ref.geotransform)
    assert np.array_equal(grid.data, ref.data)  # fields rebuild the same geometry
    assert (res["WIDTH"], res["HEIGHT"]) == (ref.shape[1], ref.shape[0])
    c, r = grid.world_to_pixel(14.2, 4.2)
    assert grid.data[int(r), int(c)] == 255  # filled column
    c, r = grid.world_to_pixel(8.0, 4.5)
    assert grid.data[int(r), int(c)] == 0  # doorway open (door layer left out)


@pytest.mark.slow
def test_rasterize_common_extent_aligns_floors(tmp_path):
    d1 = _plan(tmp_path / "f1.dxf")
    d2 = _plan(tmp_path / "f2.dxf", dx=6000)
    w1, w2 = tmp_path / "w1.gpkg", tmp_path / "w2.gpkg"
    for d, w in ((d1, w1), (d2, w2)):
        run_alg("extractstructure", {"INPUT": d, "WALLS": str(w), "TEXTS": "TEMPORARY_OUTPUT"})
    grids = []
    for w in (w1, w2):
        tif = tmp_path / (w.stem + ".tif")
        run_alg("rasterize", {"WALLS": str(w), "FLOOR_LAYERS": [str(w1), str(w2)], "OCCUPANCY": str(tif),
                              "RESOLUTION": 0.05})
        grids.append(read_grid(str(tif)))
    assert grids[0].shape == grids[1].shape and grids[0].geotransform == grids[1].geotransform
    assert grids[0].origin_x / 0.05 == pytest.approx(round(grids[0].origin_x / 0.05))
    # an explicit extent works too
    tif = tmp_path / "ext.tif"
    run_alg("rasterize", {"WALLS": str(w1), "COMMON_EXTENT": "-1,27,-1,11", "OCCUPANCY": str(tif),
                          "RESOLUTION": 0.05})
    g = read_grid(str(tif))
    assert g.extent == pytest.approx((-1.0, -1.0, 27.0, 11.0)) and g.shape == (240, 560)


def test_bad_inputs_fail_clearly_without_output(tmp_path):
    bad = tmp_path / "notes.dxf"
    bad.write_text("this is not a drawing\n" * 20)
    walls = tmp_path / "walls.gpkg"
    code, _, out = run_alg("extractstructure", {"INPUT": str(bad), "WALLS": str(walls),
                                                "TEXTS": str(tmp_path / "t.gpkg")}, check=False)
    assert code != 0 and "not a DXF file" in out and not walls.exists()

    doc = ezdxf.new("R2010", setup=False)
    for i in range(3):
        doc.modelspace().add_line((0, i * 1000), (20000, i * 1000), dxfattribs={"layer": "Furniture"})
    doc.saveas(tmp_path / "furniture.dxf")
    code, _, out = run_alg("extractstructure", {"INPUT": str(tmp_path / "furniture.dxf"), "WALLS": str(walls),
                                                "TEXTS": str(tmp_path / "t.gpkg")}, check=False)
    assert code != 0 and "'Furniture' (3 entities" in out and "LAYER_RULES" in out and not walls.exists()

    dxf = _plan(tmp_path / "plan.dxf")
    run_alg("extractstructure", {"INPUT": dxf, "WALLS": str(walls), "TEXTS": "TEMPORARY_OUTPUT"})
    tif = tmp_path / "big.tif"
    code, _, out = run_alg("rasterize", {"WALLS": str(walls), "RESOLUTION": 0.001, "MAX_MPX": 1,
                                         "OCCUPANCY": str(tif)}, check=False)
    assert code != 0 and "Mpx" in out and "resolution of at least" in out and not tif.exists()


@pytest.mark.slow
def test_all_three_on_every_real_plan(tmp_path, shared_data, provider):
    """listlayers, extractstructure and rasterize on every shared DXF plan.

    The Processing classes run inside the test's QGIS (39 qgis_process starts cost ~100 CPU s of QGIS start
    alone); the first plan also goes through qgis_process, the command line users run.
    """
    files = sorted((shared_data / "dxf").glob("*/*.dxf"))
    assert len(files) >= 13

    def run(alg, params, headless):
        if headless:  # the command line on a real drawing (even where this file ran the algorithm headless before)
            return run_alg(alg, params, headless=True)[1]
        res, ok, fb = run_alg_inprocess(alg, params)
        assert ok, f"{alg} on {params.get('INPUT') or params.get('WALLS')}:\n" + "\n".join(fb.lines)
        return res

    for i, f in enumerate(files):
        out = tmp_path / f.stem
        out.mkdir()
        headless = i == 0
        res = run("listlayers", {"INPUT": str(f), "OUTPUT": str(out / "layers.csv")}, headless)
        rows = list(csv.DictReader(open(out / "layers.csv", encoding="utf-8")))
        assert len(rows) == res["LAYER_COUNT"] >= 2 and res["KEPT_LAYERS"], f.name
        res = run("extractstructure", {"INPUT": str(f), "WALLS": str(out / "walls.gpkg"),
                                        "TEXTS": str(out / "texts.gpkg")}, headless)
        assert res["GEOMETRY_COUNT"] > 50, f.name
        res = run("rasterize", {"WALLS": str(out / "walls.gpkg"), "OCCUPANCY": str(out / "occ.tif")}, headless)
        grid = read_grid(str(out / "occ.tif"))
        assert 0.02 <= res["OCCUPIED_SHARE"] <= 0.40, f.name
        assert grid.shape == (res["HEIGHT"], res["WIDTH"]) and grid.data.size <= 60e6
    # the SIST floors on their registered common grid: same shape; F2 and F4 share a drawing frame
    sist = [str(tmp_path / f"SIST-F{k}" / "walls.gpkg") for k in range(1, 6)]
    grids = []
    for k in (2, 4):
        tif = tmp_path / f"common-F{k}.tif"
        run("rasterize", {"WALLS": sist[k - 1], "FLOOR_LAYERS": sist, "OCCUPANCY": str(tif)}, k == 2)
        grids.append(read_grid(str(tif)))
    assert grids[0].shape == grids[1].shape
    assert grids[0].geotransform == pytest.approx(grids[1].geotransform, abs=1e-6)


def test_a_second_run_in_a_file_runs_in_process_and_gives_what_qgis_process_gives(tmp_path, monkeypatch):
    """tests/qgis_process.run_alg: the first run of an algorithm in a test file spawns qgis_process, the next
    ones run the same Processing class in the test's QGIS (no QGIS start); both give the same results and
    files (a failure path, check=False, always spawns: test_bad_inputs_fail_clearly_without_output)."""
    from . import qgis_process

    dxf = _plan(tmp_path / "plan.dxf")
    monkeypatch.setattr(qgis_process, "_SPAWNED", set())
    monkeypatch.delenv("CAD2OSMAG_TEST_HEADLESS", raising=False)
    before = dict(qgis_process.COUNTS)
    outs = []
    for k in range(2):
        _, res, log = run_alg("extractstructure", {"INPUT": dxf, "WALLS": str(tmp_path / f"w{k}.gpkg"),
                                                   "TEXTS": str(tmp_path / f"t{k}.gpkg")})
        outs.append((res, log))
    assert qgis_process.COUNTS["headless"] == before["headless"] + 1
    assert qgis_process.COUNTS["inprocess"] == before["inprocess"] + 1
    (a, log_a), (b, log_b) = outs
    assert {k: v for k, v in a.items() if k not in ("WALLS", "TEXTS")} == \
        {k: v for k, v in b.items() if k not in ("WALLS", "TEXTS")}
    assert a["WALLS"] == str(tmp_path / "w0.gpkg") and b["WALLS"] == str(tmp_path / "w1.gpkg")
    assert "Kept 7 features" in log_a and "Kept 7 features" in log_b
    rows = [sorted(_gpkg_rows(tmp_path / f"w{k}.gpkg", f'select layer, kind, entity, width from "{_table(tmp_path / f"w{k}.gpkg")}"'))
            for k in range(2)]
    assert rows[0] == rows[1] and len(rows[0]) == 7
