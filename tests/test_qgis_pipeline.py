"""The whole-pipeline algorithms headless (qgis_process): dxftoosmag and mergefloors, and make demo."""
import subprocess

import pytest
from pyproj import Transformer

from algorithms import osmag
from algorithms.sample_building import generate_building

from .conftest import REPO
from .qgis_process import run_alg

ANCHOR = (121.5906, 31.1790)


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    return generate_building(str(tmp_path_factory.mktemp("sample")), floors=2, seed=1)


@pytest.mark.qgis_process
def test_dxftoosmag_and_mergefloors_headless(sample, tmp_path):
    # the anchor picked on a web-mercator basemap: the algorithm converts it to WGS84
    x, y = Transformer.from_crs("EPSG:4326", "EPSG:3857", always_xy=True).transform(*ANCHOR)
    files = []
    for k, dxf in enumerate(sample["dxf"], 1):
        out = tmp_path / f"floor-{k}.osm"
        params = {"INPUT": dxf, "OUTPUT": str(out), "LEVEL": k, "ANCHOR": f"{x},{y} [EPSG:3857]", "ROTATION": 30}
        if k == 1:
            params["PREVIEW"] = str(tmp_path / "preview.png")
            params["OUTPUT_AREAS"] = str(tmp_path / "areas.gpkg")
            params["OUTPUT_PASSAGES"] = str(tmp_path / "passages.gpkg")
        _, res, log = run_alg("dxftoosmag", params)
        assert res["AREA_COUNT"] >= 15 and res["PASSAGE_COUNT"] >= 15
        assert "Stage times" in log
        areas, passages, root, report = osmag.read_osmag(str(out))
        assert root == pytest.approx(ANCHOR, abs=1e-8)
        assert len([a for a in areas if a.type != "structure"]) == res["AREA_COUNT"]
        assert {"stairs", "elevator", "corridor", "room", "structure"} == {a.type for a in areas}
        files.append(str(out))
    assert (tmp_path / "preview.png").stat().st_size > 10000
    # the converted floor as map layers (what a GUI run shows): every area + the floor outline, in WGS84
    from osgeo import ogr

    ds = ogr.Open(str(tmp_path / "areas.gpkg"))
    layer = ds.GetLayer(0)
    assert layer.GetFeatureCount() == len(osmag.read_osmag(files[0])[0])
    assert layer.GetSpatialRef().GetAuthorityCode(None) == "4326"
    assert {f.GetField("osmAG:areatype") for f in layer} >= {"room", "corridor", "stairs", "elevator", "structure"}
    pds = ogr.Open(str(tmp_path / "passages.gpkg"))
    assert pds.GetLayer(0).GetFeatureCount() > 10
    _, res, _ = run_alg("mergefloors", {"INPUT": files, "BUILDING": "Block B", "OUTPUT": str(tmp_path / "b.osm")})
    assert res["FLOOR_COUNT"] == 2
    areas, _, _, report = osmag.read_osmag(str(tmp_path / "b.osm"))
    assert [a.tags["level"] for a in areas if a.name == "Block B"] == ["1;2"]
    assert report["dangling_refs"] == []


@pytest.mark.qgis_process
def test_dxftoosmag_bad_input_writes_nothing(tmp_path):
    bad = tmp_path / "broken.dxf"
    bad.write_bytes(b"\x00\x01 definitely not DXF")
    out = tmp_path / "out.osm"
    code, _, log = run_alg("dxftoosmag", {"INPUT": str(bad), "OUTPUT": str(out)}, check=False)
    assert code != 0 and "broken.dxf" in log
    assert not out.exists()


@pytest.mark.slow
@pytest.mark.qgis_process
def test_make_demo_writes_building_and_preview():
    proc = subprocess.run(["bash", str(REPO / "scripts" / "demo.sh")], capture_output=True, text=True,
                          timeout=900, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    demo = REPO / "out" / "demo"
    assert "Results in" in proc.stdout
    areas, passages, root, report = osmag.read_osmag(str(demo / "building.osm"))
    levels = {a.tags.get("level") for a in areas}
    assert {"1", "2", "3"} <= levels
    assert len(areas) > 50 and len(passages) > 45 and report["dangling_refs"] == []
    import cv2

    img = cv2.imread(str(demo / "preview.png"))
    assert img is not None and img.shape[1] > 500
    for name in ("layers.csv", "walls.gpkg", "occupancy.tif", "areas.gpkg", "refined_areas.gpkg", "floor-1.osm"):
        assert (demo / "stages" / name).exists(), name
    # stage by stage and in one step give the same floor, with the root node at the anchor
    staged, _, staged_root, _ = osmag.read_osmag(str(demo / "stages" / "floor-1.osm"))
    direct, _, direct_root, _ = osmag.read_osmag(str(demo / "floor-1.osm"))
    assert staged_root == pytest.approx(ANCHOR, abs=1e-9)
    assert direct_root == pytest.approx(ANCHOR, abs=1e-9)
    assert len([a for a in staged if a.type != "structure"]) == len([a for a in direct if a.type != "structure"])


@pytest.mark.qgis_process
def test_stage_chain_layers_in_the_cad_frame_export_and_georeference(sample, tmp_path):
    """Layers written by the stages carry the plugin's local CAD-frame CRS; export and georeference
    must treat them as the CAD frame (they once handed that CRS to PROJ and crashed)."""
    s = tmp_path
    run_alg("extractstructure", {"INPUT": sample["dxf"][0], "WALLS": str(s / "walls.gpkg"), "TEXTS": str(s / "t.gpkg")})
    run_alg("rasterize", {"WALLS": str(s / "walls.gpkg"), "OCCUPANCY": str(s / "occ.tif")})
    run_alg("segment", {"INPUT": str(s / "occ.tif"), "AREAS": str(s / "a.gpkg"), "PASSAGES": str(s / "p.gpkg"),
                        "LABELS": str(s / "l.tif")})
    run_alg("refine", {"AREAS": str(s / "a.gpkg"), "PASSAGES": str(s / "p.gpkg"), "RESOLUTION": 0.044,
                       "OUTPUT_AREAS": str(s / "ra.gpkg"), "OUTPUT_PASSAGES": str(s / "rp.gpkg")})
    _, res, _ = run_alg("exportosmag", {"AREAS": str(s / "ra.gpkg"), "PASSAGES": str(s / "rp.gpkg"), "LEVEL": 1,
                                        "ANCHOR_LON": ANCHOR[0], "ANCHOR_LAT": ANCHOR[1], "OUTPUT": str(s / "f.osm")})
    areas, passages, root, report = osmag.read_osmag(str(s / "f.osm"))
    assert root == pytest.approx(ANCHOR, abs=1e-9)
    assert len(areas) == res["AREA_COUNT"] >= 15 and len(passages) == res["PASSAGE_COUNT"] >= 15
    # georeference places CAD-frame layers, and refuses layers that are already placed
    run_alg("georeference", {"AREAS": str(s / "ra.gpkg"), "MODE": 0, "ANCHOR": f"{ANCHOR[0]},{ANCHOR[1]} [EPSG:4326]",
                             "TARGET_CRS": "EPSG:32651", "OUTPUT_AREAS": str(s / "utm.gpkg")})
    code, _, log = run_alg("georeference", {"AREAS": str(s / "utm.gpkg"), "MODE": 0,
                                            "ANCHOR": f"{ANCHOR[0]},{ANCHOR[1]} [EPSG:4326]",
                                            "OUTPUT_AREAS": str(s / "twice.gpkg")}, check=False)
    assert code != 0 and "already georeferenced" in log and "32651" in log
    assert not (s / "twice.gpkg").exists()


@pytest.mark.qgis_process
def test_reexport_of_loaded_layers_keeps_their_level(sample, tmp_path):
    from algorithms import building, pipeline

    files = []
    for k, dxf in enumerate(sample["dxf"], 1):
        files.append(str(tmp_path / f"f{k}.osm"))
        pipeline.convert_dxf(dxf, files[-1], anchor_lon=ANCHOR[0], anchor_lat=ANCHOR[1], level=str(k))
    run_alg("loadosmag", {"INPUT": files[1], "OUTPUT_AREAS": str(tmp_path / "a.gpkg"),
                          "OUTPUT_PASSAGES": str(tmp_path / "p.gpkg")})
    run_alg("exportosmag", {"AREAS": str(tmp_path / "a.gpkg"), "PASSAGES": str(tmp_path / "p.gpkg"),
                            "OUTPUT": str(tmp_path / "re.osm")})
    areas, passages, _, _ = osmag.read_osmag(str(tmp_path / "re.osm"))
    assert {a.tags["level"] for a in areas} == {"2"} and {p.tags["level"] for p in passages} == {"2"}
    # a layer holding two levels must be split, not silently flattened onto one
    building.merge_floor_files(files, str(tmp_path / "b.osm"))
    run_alg("loadosmag", {"INPUT": str(tmp_path / "b.osm"), "OUTPUT_AREAS": str(tmp_path / "ba.gpkg"),
                          "OUTPUT_PASSAGES": str(tmp_path / "bp.gpkg")})
    code, _, log = run_alg("exportosmag", {"AREAS": str(tmp_path / "ba.gpkg"), "OUTPUT": str(tmp_path / "x.osm")},
                           check=False)
    assert code != 0 and "several levels" in log and not (tmp_path / "x.osm").exists()


@pytest.mark.qgis_process
def test_segment_writes_the_skeleton_graph(sample, tmp_path):
    """The optional SKELETON output: one line per skeleton edge, with length and clearance, inside free space."""
    from osgeo import ogr

    from algorithms.cad_import import import_dxf
    from algorithms.raster_io import write_grid
    from algorithms.rasterize import rasterize

    grid = rasterize(import_dxf(sample["dxf"][0]).geometries)
    write_grid(str(tmp_path / "occ.tif"), grid)
    run_alg("segment", {"INPUT": str(tmp_path / "occ.tif"), "AREAS": str(tmp_path / "a.gpkg"),
                        "PASSAGES": str(tmp_path / "p.gpkg"), "LABELS": str(tmp_path / "l.tif"),
                        "SKELETON": str(tmp_path / "s.gpkg")})
    ds = ogr.Open(str(tmp_path / "s.gpkg"))  # keep the datasource alive while its layer is read
    feats = list(ds.GetLayer(0))
    assert len(feats) >= 20
    from algorithms import segmentation

    # the line runs through the node pixels at both ends, the length between them: about two skeleton cells apart
    # (the skeleton lies on the topology cells, segmentation.topology_scale x the raster's)
    cell = grid.resolution * segmentation.topology_scale(grid.resolution)
    for f in feats:
        g = f.GetGeometryRef()
        assert f.GetField("length_m") == pytest.approx(g.Length(), rel=0.2, abs=max(0.1, 2.2 * cell))
        assert 0 < f.GetField("min_clearance_m") <= f.GetField("max_clearance_m") < 8


def test_segment_topology_cell_parameter(sample, tmp_path):
    """TOPOLOGY_CELL: 0 segments on the raster's own pixels, the default on 2 x 2 cells: the sample floor's rooms
    either way; a negative cell size is refused by the parameter, naming it, and writes nothing."""
    from algorithms.cad_import import import_dxf
    from algorithms.raster_io import write_grid
    from algorithms.rasterize import rasterize

    grid = rasterize(import_dxf(sample["dxf"][0]).geometries)
    write_grid(str(tmp_path / "occ.tif"), grid)
    counts = {}
    for cell in ("", "0"):
        params = {"INPUT": str(tmp_path / "occ.tif"), "AREAS": str(tmp_path / f"a{cell}.gpkg"),
                  "PASSAGES": str(tmp_path / f"p{cell}.gpkg"), "LABELS": str(tmp_path / f"l{cell}.tif")}
        if cell:
            params["TOPOLOGY_CELL"] = cell
        _, res, _ = run_alg("segment", params)
        counts[cell] = (res["AREA_COUNT"], res["PASSAGE_COUNT"])
    assert counts[""] == counts["0"] and counts[""][0] >= 15
    code, _, log = run_alg("segment", {"INPUT": str(tmp_path / "occ.tif"), "AREAS": str(tmp_path / "bad.gpkg"),
                                       "PASSAGES": str(tmp_path / "badp.gpkg"), "LABELS": str(tmp_path / "bad.tif"),
                                       "TOPOLOGY_CELL": "-1"}, check=False)
    assert code != 0 and "TOPOLOGY_CELL" in log
    assert not (tmp_path / "bad.gpkg").exists()
