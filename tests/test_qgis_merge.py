"""cad2osmag:mergefloors headless (qgis_process): floors in different frames, levels from LEVELS,
layers with a level field, and bad input that stops without writing."""
import pytest

from algorithms import osmag, pipeline
from algorithms.sample_building import generate_building

from .qgis_process import run_alg

ANCHOR = (121.5906, 31.1790)


@pytest.fixture(scope="module")
def floor_files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("qmerge")
    s = generate_building(str(folder), floors=2, seed=2)
    files = []
    for k, dxf in enumerate(s["dxf"], 1):
        files.append(str(folder / f"wing_{k}.osm"))  # no level in the name
        # floor 2 anchored 300 m east and rotated: mergefloors registers it on the stair and the lift
        pipeline.convert_dxf(dxf, files[-1], anchor_lon=ANCHOR[0] + (3e-3 if k == 2 else 0), anchor_lat=ANCHOR[1],
                             rotation_deg=(10 if k == 2 else 0), level="1")
    return files


@pytest.mark.qgis_process
def test_mergefloors_headless(floor_files, tmp_path):
    out = tmp_path / "b.osm"
    _, res, log = run_alg("mergefloors", {"INPUT": floor_files, "LEVELS": "0,1", "HEIGHTS": "4.0",
                                          "BUILDING": "Wing", "OUTPUT": str(out),
                                          "OUTPUT_AREAS": str(tmp_path / "a.gpkg"),
                                          "OUTPUT_PASSAGES": str(tmp_path / "p.gpkg")})
    assert res["FLOOR_COUNT"] == 2 and res["VERTICAL_PASSAGES"] == 2
    assert 0 <= res["RMS"] < 0.2 and res["LEVELS_OUT"] == "0,1"
    assert "residual RMS" in log and "rotation" in log
    areas, passages, _, rep = osmag.read_osmag(str(out))
    assert res["AREA_COUNT"] == len(areas) and rep["dangling_refs"] == []
    assert {a.tags.get("height") for a in areas if a.name != "Wing"} == {"4"}
    from osgeo import ogr

    ds = ogr.Open(str(tmp_path / "a.gpkg"))  # keep the data source alive while its layer is used
    lyr = ds.GetLayer(0)
    assert lyr.GetFeatureCount() == len(areas)
    assert {f.GetField("level") for f in lyr} == {"0", "1", "0;1"}
    pds = ogr.Open(str(tmp_path / "p.gpkg"))
    plyr = pds.GetLayer(0)
    assert plyr.GetFeatureCount() == len(passages)
    # the building's layers as input again (split by their level field): the same building comes out
    out2 = tmp_path / "again.osm"
    _, res2, _ = run_alg("mergefloors", {"AREAS": str(tmp_path / "a.gpkg"), "PASSAGES": str(tmp_path / "p.gpkg"),
                                         "BUILDING": "Wing", "OUTPUT": str(out2)})
    assert res2["FLOOR_COUNT"] == 2 and res2["VERTICAL_PASSAGES"] == 2 and res2["RMS"] < 0.01
    a2, p2, _, rep2 = osmag.read_osmag(str(out2))
    assert len(a2) == len(areas) and len(p2) == len(passages) and rep2["dangling_refs"] == []


@pytest.mark.qgis_process
def test_mergefloors_bad_input_writes_nothing(floor_files, tmp_path):
    out = tmp_path / "b.osm"
    # both files say level 1 and their names give no level
    code, _, log = run_alg("mergefloors", {"INPUT": floor_files, "OUTPUT": str(out)}, check=False)
    assert code != 0 and "both claim level 1" in log and "LEVELS" in log
    code, _, log = run_alg("mergefloors", {"INPUT": floor_files, "LEVELS": "1", "OUTPUT": str(out)}, check=False)
    assert code != 0 and "LEVELS gives 1 levels for 2 floors" in log
    code, _, log = run_alg("mergefloors", {"INPUT": floor_files, "LEVELS": "1,2", "HEIGHTS": "tall",
                                           "OUTPUT": str(out)}, check=False)
    assert code != 0 and "HEIGHTS must be numbers" in log
    assert not out.exists()
