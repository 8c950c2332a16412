"""cad2osmag:route headless through qgis_process: osmAG files (ours, other tools'), CAD-frame layers, errors."""
import math

import pytest
from pyproj import Transformer

from algorithms.building import merge_floor_files
from algorithms.georef import LocalFrame
from algorithms.osmag import write_osmag
from tests.test_qgis_osmag import read_gpkg, write_gpkg
from tests.test_routing import two_floors, two_rooms

from .qgis_process import run_alg

ROOT = (121.59, 31.18)


@pytest.fixture(scope="module")
def building_osm(tmp_path_factory):
    """Two floors written by write_osmag (same anchor), merged: the shafts repeat their names per floor
    (ST-01, E-P1), the way other tools' maps link floors."""
    folder = tmp_path_factory.mktemp("route")
    areas, passages = two_floors(implicit=True)
    frame = LocalFrame(*ROOT)
    files = []
    for lv in ("1", "2"):
        a = [x for x in areas if x.tags["level"] == lv]
        ids = {x.id for x in a}
        p = [x for x in passages if x.from_id in ids]
        path = folder / f"F{lv}.osm"
        write_osmag(str(path), a, p, frame=frame, level=lv, height=3.0, variant="fix-id",
                    structure_areas=[type(a[0])(id=900 + int(lv), polygon=a[0].polygon.envelope.buffer(10),
                                                type="structure", name=f"Level {lv}")])
        files.append(str(path))
    out = folder / "building.osm"
    merge_floor_files(files, str(out))
    return out, frame


@pytest.mark.qgis_process
def test_route_headless_on_an_osmag_building(building_osm, tmp_path):
    path, frame = building_osm
    # start picked on a Web Mercator canvas, in Office 1 (level 1); goal given by name on level 2
    lon, lat = frame.to_wgs84(11.0, 6.0)
    x, y = Transformer.from_crs("EPSG:4326", "EPSG:3857", always_xy=True).transform(float(lon), float(lat))
    out = tmp_path / "route.gpkg"
    _, res, log = run_alg("route", {"INPUT": str(path), "START": f"{x},{y} [EPSG:3857]", "START_LEVEL": "1",
                                    "END_NAME": "Office 2", "ROBOT_RADIUS": 0.3, "AVOID": 1, "VERTICAL_COST": 10,
                                    "OUTPUT": str(out)}, timeout=300)
    assert res["LEVEL_CHANGES"] == 1
    assert res["AREAS_CROSSED"].split(" > ")[0] == "Office 1"
    assert res["AREAS_CROSSED"].split(" > ")[-1] == "Office 2"
    assert "E-P1" in res["AREAS_CROSSED"] and "ST-01" not in res["AREAS_CROSSED"]  # lifts only
    # Office 1 -> lift (x 37.5) -> back to Office 2: at least 2 x 26 m, at most 2 x 34 m
    assert 52 <= res["LENGTH"] <= 68 and res["COST"] == pytest.approx(res["LENGTH"] + 10, abs=1e-6)
    assert res["START_SNAP"] == 0.0
    levels = res["LEVELS"].split(",")
    assert levels[0] == "1" and levels[-1] == "2"
    feats, code = read_gpkg(out)
    assert code == "4326" and len(feats) == 1
    attrs, wkt = feats[0]
    assert wkt.upper().startswith("LINESTRING")
    assert attrs["level_from"] == "1" and attrs["level_to"] == "2" and attrs["level_changes"] == 1
    assert attrs["length_m"] == pytest.approx(res["LENGTH"], abs=1e-3)
    # z = level x height (3 m)
    zs = [float(c.split()[2]) for c in wkt[wkt.index("(") + 1:wkt.rindex(")")].split(",")]
    assert zs[0] == pytest.approx(3.0) and zs[-1] == pytest.approx(6.0)
    # the stairs are allowed by default: a shorter route through ST-01
    _, res2, _ = run_alg("route", {"INPUT": str(path), "START": f"{x},{y} [EPSG:3857]", "START_LEVEL": "1",
                                   "END_NAME": "Office 2", "VERTICAL_COST": 10,
                                   "OUTPUT": str(tmp_path / "r2.gpkg")}, timeout=300)
    assert "ST-01" in res2["AREAS_CROSSED"] and res2["LENGTH"] < res["LENGTH"] - 30


@pytest.mark.qgis_process
def test_route_headless_on_cad_layers_and_bad_input(tmp_path):
    areas, passages = two_rooms(0.8)
    gpkg = tmp_path / "layers.gpkg"
    a = write_gpkg(gpkg, "areas", [x.polygon for x in areas], {"id": [x.id for x in areas],
                                                              "name": [x.name for x in areas]})
    p = write_gpkg(gpkg, "passages", [x.line for x in passages],
                   {"id": [x.id for x in passages], "from_id": [x.from_id for x in passages],
                    "to_id": [x.to_id for x in passages], "name": [x.name for x in passages]})
    _, res, _ = run_alg("route", {"AREAS": a, "PASSAGES": p, "START": "1,3.5", "END": "9,0.5",
                                  "OUTPUT": str(tmp_path / "r.gpkg")}, timeout=300)
    assert res["LENGTH"] == pytest.approx(math.hypot(8, 3), abs=0.01)
    assert res["AREAS_CROSSED"] == "West > East" and res["PASSAGES_CROSSED"] == "Door"
    # a start 3 m outside every area: a clear error, no output written
    bad = tmp_path / "bad.gpkg"
    rc, _, log = run_alg("route", {"AREAS": a, "PASSAGES": p, "START": "-3,2", "END": "9,0.5",
                                   "OUTPUT": str(bad)}, timeout=300, check=False)
    assert rc != 0 and "outside every area" in log and "nearest area is 'West'" in log
    assert not bad.exists()
    # a robot too wide for the door: the message names both parts and the closed door
    rc, _, log = run_alg("route", {"AREAS": a, "PASSAGES": p, "START": "1,3.5", "END": "9,0.5",
                                   "ROBOT_RADIUS": 0.45, "OUTPUT": str(bad)}, timeout=300, check=False)
    assert rc != 0 and "'Door' (0.80 m wide, the robot needs 0.90 m)" in log and not bad.exists()
    # an unknown level
    rc, _, log = run_alg("route", {"AREAS": a, "PASSAGES": p, "START": "1,3.5", "START_LEVEL": "4",
                                   "END": "9,0.5", "OUTPUT": str(bad)}, timeout=300, check=False)
    assert rc != 0 and "level '4' is not in the map" in log


@pytest.mark.qgis_process
@pytest.mark.slow
def test_route_headless_on_another_tools_campus_map(shared_data, tmp_path):
    path = shared_data / "osmag" / "fix_id_ShanghaiTech_merge_2.osm"
    _, res, log = run_alg("route", {"INPUT": str(path), "START_NAME": "E1d-F1-COR-01", "START_LEVEL": "1",
                                    "END_NAME": "E1a-F2-COR-01", "END_LEVEL": "2", "AVOID": 1,
                                    "OUTPUT": str(tmp_path / "campus.gpkg")}, timeout=600)
    assert "56 passages point at areas missing from the file" in log
    assert res["LEVEL_CHANGES"] == 1 and res["LENGTH"] > 50
    assert res["AREAS_CROSSED"].startswith("E1d-F1-COR-01") and res["AREAS_CROSSED"].endswith("E1a-F2-COR-01")
