"""cad2osmag:listplans (the wizard's plan picker) headless through qgis_process: the groups of a whole sheet
with their index, kind, title and extent, the main plan flagged, the whole sheet's structure; bad input."""

import pytest

from algorithms.sample_building import generate_delivered

from .qgis_process import gpkg_rows as _rows, run_alg

pytestmark = pytest.mark.qgis_process


def test_listplans_lists_every_group_of_a_sheet(tmp_path):
    out = generate_delivered(str(tmp_path), sheet=True, name="sheet")
    plans, lines = tmp_path / "plans.gpkg", tmp_path / "sheet.gpkg"
    _, res, _ = run_alg("listplans", {"INPUT": out["dxf"], "OUTPUT": str(plans), "STRUCTURE": str(lines)})
    assert res["PLAN_COUNT"] == 2 and res["MAIN_PLAN"] == 0 and "[1] detail" in res["PLANS"]
    rows = _rows(plans, 'select "index", kind, title, main, xmin, ymin, xmax, ymax, width from "{t}" order by "index"')
    assert [r[:2] for r in rows] == [(0, "plan"), (1, "detail")]
    assert "平面图" in rows[0][2] and "详图" in rows[1][2]
    assert rows[0][3] == 1 and rows[1][3] == 0
    for r, key in zip(rows, ("plan_extent", "detail_extent")):
        assert r[4:8] == pytest.approx(out[key], abs=1.0)
    assert rows[0][8] == pytest.approx(40.0, abs=1.0)
    # the structure of the whole sheet: both views (extractstructure keeps only the main plan)
    minx, maxx = _rows(lines, 'select min(minx), max(maxx) from "rtree_{t}_geom"')[0]
    assert minx <= out["plan_extent"][0] + 1 and maxx >= out["detail_extent"][2] - 1
    _, res_main, _ = run_alg("extractstructure", {"INPUT": out["dxf"], "WALLS": str(tmp_path / "w.gpkg"),
                                                  "TEXTS": str(tmp_path / "t.gpkg")})
    n_sheet = _rows(lines, 'select count(*) from "{t}"')[0][0]
    assert n_sheet > res_main["GEOMETRY_COUNT"]


def test_listplans_reports_bad_input_without_writing(tmp_path):
    bad = tmp_path / "notes.dxf"
    bad.write_text("this is not a drawing\n")
    plans = tmp_path / "plans.gpkg"
    code, _, log = run_alg("listplans", {"INPUT": str(bad), "OUTPUT": str(plans)}, check=False)
    assert code != 0 and "notes.dxf" in log and "Traceback" not in log
    assert not plans.exists()


@pytest.mark.slow
def test_listplans_on_a_real_dwg_sheet(shared_data, tmp_path):
    dwg = shared_data / "dwg" / "sist-original" / "SIST-F1.dwg"
    if not dwg.is_file():
        pytest.skip(f"{dwg} is missing")
    plans = tmp_path / "plans.gpkg"
    _, res, _ = run_alg("listplans", {"INPUT": str(dwg), "OUTPUT": str(plans)})
    assert res["PLAN_COUNT"] >= 1 and res["MAIN_PLAN"] == 0
    kind, width, height, walls = _rows(plans, 'select kind, width, height, wall_length from "{t}" where main')[0]
    assert kind == "plan" and 150 < width < 200 and 120 < height < 170 and walls > 3000
