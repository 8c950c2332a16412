"""Refine, georeference, export and load osmAG through qgis_process (headless), basemaps and styles
in-process (pytest-qgis)."""
import subprocess
from pathlib import Path

import numpy as np
import pytest

from algorithms.georef import LocalFrame, geodesic_distance
from algorithms.osmag import read_osmag
from algorithms.refine import graph_from_labels
from tests.test_refine import RES, synthetic_labels

from .qgis_process import run_alg

DATA = Path(__file__).parent / "data"


def write_gpkg(path, layer, geoms, fields, srs_epsg=None):
    """A GeoPackage layer (no CRS unless ``srs_epsg``) from shapely geometries and {field: values}."""
    from osgeo import ogr, osr

    ogr.UseExceptions()
    ds = ogr.Open(str(path), 1) if Path(path).exists() else ogr.GetDriverByName("GPKG").CreateDataSource(str(path))
    srs = None
    if srs_epsg:
        srs = osr.SpatialReference()
        srs.ImportFromEPSG(srs_epsg)
        srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    gt = {"Polygon": ogr.wkbPolygon, "LineString": ogr.wkbLineString, "Point": ogr.wkbPoint}[geoms[0].geom_type]
    lyr = ds.CreateLayer(layer, srs, gt)
    for name, values in fields.items():
        v = values[0]
        t = (ogr.OFTInteger64 if isinstance(v, (int, np.integer)) else ogr.OFTReal if isinstance(v, float)
             else ogr.OFTString)
        lyr.CreateField(ogr.FieldDefn(name, t))
    for i, g in enumerate(geoms):
        f = ogr.Feature(lyr.GetLayerDefn())
        f.SetGeometry(ogr.CreateGeometryFromWkb(g.wkb))
        for name, values in fields.items():
            v = values[i]
            f.SetField(name, int(v) if isinstance(v, (int, np.integer)) else v)
        lyr.CreateFeature(f)
    ds = None
    return f"{path}|layername={layer}"


def read_gpkg(path, layer=None):
    from osgeo import ogr

    ds = ogr.Open(str(path))
    lyr = ds.GetLayerByName(layer) if layer else ds.GetLayer(0)
    feats = [(f.items(), f.GetGeometryRef().ExportToWkt()) for f in lyr]
    srs = lyr.GetSpatialRef()
    return feats, (srs.GetAuthorityCode(None) if srs else None)


@pytest.fixture(scope="module")
def cad_layers(tmp_path_factory):
    """The synthetic floor straight from 'segmentation', as CAD-frame layers (no CRS)."""
    g = graph_from_labels(synthetic_labels(), 0.0, 20.0, RES, types={3: "corridor"})
    path = tmp_path_factory.mktemp("cad") / "seg.gpkg"
    areas = write_gpkg(path, "areas", [a.polygon for a in g.areas],
                       {"id": [a.id for a in g.areas], "type": [a.type for a in g.areas],
                        "name": ["" for _ in g.areas]})
    passages = write_gpkg(path, "passages", [p.line for p in g.passages],
                          {"id": [p.id for p in g.passages], "from_id": [p.from_id for p in g.passages],
                           "to_id": [p.to_id for p in g.passages]})
    return g, areas, passages, path.parent


@pytest.fixture(scope="module")
def refined_layers(cad_layers):
    g, areas, passages, folder = cad_layers
    out = folder / "refined.gpkg"
    _, res, _ = run_alg("refine", {"AREAS": areas, "PASSAGES": passages, "RESOLUTION": RES,
                                   "OUTPUT_AREAS": str(out.parent / (out.stem + "_areas.gpkg")),
                                   "OUTPUT_PASSAGES": str(out.parent / (out.stem + "_passages.gpkg"))}, timeout=120)
    return res, res["OUTPUT_AREAS"], res["OUTPUT_PASSAGES"], folder


@pytest.mark.qgis_process
@pytest.mark.slow
def test_refine_georeference_export_load_headless(refined_layers, tmp_path):
    res, areas, passages, folder = refined_layers
    assert res["AREA_COUNT"] == 4 and res["PASSAGE_COUNT"] == 3
    assert res["MERGED"] == 1 and res["DROPPED"] == 1
    assert res["VERTEX_REDUCTION"] >= 85.0
    assert res["MAX_DEVIATION"] <= res["EPSILON_M"] + 1e-9
    feats, _ = read_gpkg(areas)
    assert sorted(f[0]["id"] for f in feats) == [1, 2, 3, 4]
    # georeference with an anchor picked in WGS84 and a rotation
    geo = tmp_path / "geo.gpkg"
    _, gres, _ = run_alg("georeference", {
        "AREAS": areas, "PASSAGES": passages, "MODE": 0, "ANCHOR": "121.5906,31.179 [EPSG:4326]",
        "ROTATION": 20, "TARGET_CRS": "EPSG:4326",
        "OUTPUT_AREAS": str(geo.parent / (geo.stem + "_areas.gpkg")),
        "OUTPUT_PASSAGES": str(geo.parent / (geo.stem + "_passages.gpkg"))}, timeout=120)
    assert gres["ANCHOR_LON"] == pytest.approx(121.5906) and gres["ROTATION_DEG"] == pytest.approx(20.0)
    gfeats, code = read_gpkg(gres["OUTPUT_AREAS"])
    assert code == "4326" and len(gfeats) == 4
    # export the georeferenced layers (WGS84) with the anchor as root
    osm = tmp_path / "floor.osm"
    _, eres, _ = run_alg("exportosmag", {"AREAS": gres["OUTPUT_AREAS"], "PASSAGES": gres["OUTPUT_PASSAGES"],
                                         "LEVEL": "2", "ANCHOR_LON": 121.5906, "ANCHOR_LAT": 31.179,
                                         "OUTPUT": str(osm)}, timeout=120)
    assert eres["AREA_COUNT"] == 4 and eres["PASSAGE_COUNT"] == 3 and eres["SHARED_NODES"] >= 6
    a, p, root, rep = read_osmag(str(osm))
    assert root == pytest.approx((121.5906, 31.179)) and len(a) == 4 and len(p) == 3
    assert {x.tags["level"] for x in a} == {"2"}
    # the same floor exported straight from the CAD-frame layers with the frame: identical positions (<= 1 mm)
    osm2 = tmp_path / "floor_cad.osm"
    run_alg("exportosmag", {"AREAS": areas, "PASSAGES": passages, "LEVEL": "2", "ANCHOR_LON": 121.5906,
                            "ANCHOR_LAT": 31.179, "ROTATION": 20, "OUTPUT": str(osm2)}, timeout=120)
    a2, _, _, _ = read_osmag(str(osm2))
    by = {x.name: np.asarray(x.polygon.exterior.coords) for x in a}
    for x in a2:
        c1, c2 = by[x.name], np.asarray(x.polygon.exterior.coords)
        assert c1.shape == c2.shape
        assert np.max(geodesic_distance(c1[:, 0], c1[:, 1], c2[:, 0], c2[:, 1])) <= 1e-3
    # osmium accepts it
    r = subprocess.run(["osmium", "fileinfo", "-e", str(osm)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0
    # and loadosmag gives styled-ready layers with the tags as fields
    out = tmp_path / "loaded.gpkg"
    _, lres, _ = run_alg("loadosmag", {"INPUT": str(osm), "OUTPUT_AREAS": str(out.parent / (out.stem + "_areas.gpkg")),
                                       "OUTPUT_PASSAGES": str(out.parent / (out.stem + "_passages.gpkg"))}, timeout=120)
    assert lres["AREA_COUNT"] == 4 and lres["PASSAGE_COUNT"] == 3 and lres["VARIANT"] == "semantic"
    lf, code = read_gpkg(lres["OUTPUT_AREAS"])
    assert code == "4326"
    assert {f[0]["osmAG:areatype"] for f in lf} == {"room", "corridor"}
    pf, _ = read_gpkg(lres["OUTPUT_PASSAGES"])
    ids = {f[0]["osm_id"] for f in lf}
    assert all(f[0]["from_id"] in ids and f[0]["to_id"] in ids and f[0]["osmAG:type"] == "passage" for f in pf)
    # round trip: export the loaded layers again -> same areas, passages, tags and coordinates (<= 1 mm)
    osm3 = tmp_path / "again.osm"
    run_alg("exportosmag", {"AREAS": lres["OUTPUT_AREAS"], "PASSAGES": lres["OUTPUT_PASSAGES"], "LEVEL": "2",
                            "ANCHOR_LON": lres["ROOT_LON"], "ANCHOR_LAT": lres["ROOT_LAT"], "OUTPUT": str(osm3)},
            timeout=120)
    a3, p3, root3, _ = read_osmag(str(osm3))
    assert root3 == pytest.approx(root, abs=1e-10)
    m1 = {x.name: x for x in a}
    assert {x.name for x in a3} == set(m1)
    for x in a3:
        assert x.tags == m1[x.name].tags
        c1, c3 = np.asarray(m1[x.name].polygon.exterior.coords), np.asarray(x.polygon.exterior.coords)
        assert c1.shape == c3.shape
        assert np.max(geodesic_distance(c1[:, 0], c1[:, 1], c3[:, 0], c3[:, 1])) <= 1e-3
    q1 = {x.name: (x.tags, np.asarray(x.line.coords)) for x in p}
    assert {x.name for x in p3} == set(q1)
    for x in p3:
        assert x.tags == q1[x.name][0] and np.abs(np.asarray(x.line.coords) - q1[x.name][1]).max() < 1e-8
    # loading into a projected CRS
    _, ures, _ = run_alg("loadosmag", {"INPUT": str(osm), "TARGET_CRS": "EPSG:32651",
                                       "OUTPUT_AREAS": str(tmp_path / "utm_a.gpkg"),
                                       "OUTPUT_PASSAGES": str(tmp_path / "utm_p.gpkg")}, timeout=120)
    uf, code = read_gpkg(ures["OUTPUT_AREAS"])
    assert code == "32651" and "POLYGON ((36" in uf[0][1]


@pytest.mark.qgis_process
@pytest.mark.slow
def test_georeference_gcps_headless(refined_layers, tmp_path):
    _, areas, _, _ = refined_layers
    truth = LocalFrame(121.5906, 31.179, rotation_deg=-12.0)
    cad = np.array([[0.0, 0.0], [30.0, 0.0], [30.0, 20.0], [2.0, 19.0]])
    lon, lat = truth.to_wgs84(cad[:, 0], cad[:, 1])
    import pyproj
    from shapely.geometry import Point

    X, Y = pyproj.Transformer.from_crs(4326, 32651, always_xy=True).transform(lon, lat)
    gcp = write_gpkg(tmp_path / "gcp.gpkg", "gcp", [Point(x, y) for x, y in zip(X, Y)],
                     {"name": ["a", "b", "c", "d"], "cad_x": list(cad[:, 0]), "cad_y": list(cad[:, 1])},
                     srs_epsg=32651)
    out = tmp_path / "g.gpkg"
    _, res, log = run_alg("georeference", {"AREAS": areas, "MODE": 1, "GCPS": gcp, "TARGET_CRS": "EPSG:32651",
                                           "OUTPUT_AREAS": str(out.parent / (out.stem + "_areas.gpkg"))}, timeout=120)
    assert res["RMS"] <= 0.01
    assert res["RESIDUALS"].startswith("a=")
    feats, code = read_gpkg(res["OUTPUT_AREAS"])
    assert code == "32651" and len(feats) == 4
    # anchor mode with both points picked on a Web Mercator canvas: rotation from the two points
    merc = pyproj.Transformer.from_crs(4326, 3857, always_xy=True)
    ax, ay = merc.transform(lon[0], lat[0])  # CAD (0, 0)
    bx, by = merc.transform(lon[1], lat[1])  # CAD (30, 0)
    out3 = tmp_path / "a.gpkg"
    _, res3, _ = run_alg("georeference", {"AREAS": areas, "MODE": 0, "ANCHOR": f"{ax!r},{ay!r} [EPSG:3857]",
                                          "ROTATION_POINT": f"{bx!r},{by!r} [EPSG:3857]", "CAD_ROTATION_X": 30,
                                          "CAD_ROTATION_Y": 0, "OUTPUT_AREAS": str(out3)}, timeout=120)
    assert res3["ANCHOR_LON"] == pytest.approx(121.5906, abs=1e-9)
    assert res3["ANCHOR_LAT"] == pytest.approx(31.179, abs=1e-9)
    assert (res3["ROTATION_DEG"] - truth.rotation_deg + 180) % 360 - 180 == pytest.approx(0.0, abs=1e-4)
    # collinear control points: clear error naming them, no output
    bad = write_gpkg(tmp_path / "gcp_bad.gpkg", "gcp", [Point(X[i], Y[i]) for i in range(3)],
                     {"name": ["p", "q", "r"], "cad_x": [0.0, 10.0, 20.0], "cad_y": [0.0, 10.0, 20.0]},
                     srs_epsg=32651)
    out2 = tmp_path / "bad.gpkg"
    code, _, log = run_alg("georeference", {"AREAS": areas, "MODE": 1, "GCPS": bad,
                                            "OUTPUT_AREAS": str(out2)}, timeout=120, check=False)
    assert code != 0 and "p, q, r are collinear" in log
    assert not out2.exists()


@pytest.mark.qgis_process
@pytest.mark.slow
def test_bad_input_headless(cad_layers, tmp_path):
    g, areas, passages, folder = cad_layers
    # export of CAD-frame layers without an anchor: asks to georeference, writes nothing
    osm = tmp_path / "x.osm"
    code, _, log = run_alg("exportosmag", {"AREAS": areas, "PASSAGES": passages, "OUTPUT": str(osm)},
                           timeout=120, check=False)
    assert code != 0 and "georeference" in log and not osm.exists()
    # a passage to a missing area: the error names the passage
    path = tmp_path / "bad.gpkg"
    from shapely.geometry import LineString

    bad_p = write_gpkg(path, "passages", [LineString([(0, 0), (1, 0)])], {"id": [41], "from_id": [1], "to_id": [99]})
    code, _, log = run_alg("refine", {"AREAS": areas, "PASSAGES": bad_p, "RESOLUTION": RES,
                                      "OUTPUT_AREAS": str(tmp_path / "r.gpkg")}, timeout=120, check=False)
    assert code != 0 and "41 (1->99)" in log and not (tmp_path / "r.gpkg").exists()
    # an anchor outside valid lat/lon
    code, _, log = run_alg("georeference", {"AREAS": areas, "MODE": 0, "ANCHOR": "31.18,121.59 [EPSG:4326]",
                                            "OUTPUT_AREAS": str(tmp_path / "g.gpkg")}, timeout=120, check=False)
    assert code != 0 and "latitude 121.59" in log and not (tmp_path / "g.gpkg").exists()
    # a plain OSM file is not osmAG
    code, _, log = run_alg("loadosmag", {"INPUT": str(DATA / "not_osmag.osm"),
                                         "OUTPUT_AREAS": str(tmp_path / "l.gpkg"),
                                         "OUTPUT_PASSAGES": str(tmp_path / "lp.gpkg")}, timeout=120, check=False)
    assert code != 0 and "not an osmAG file" in log and not (tmp_path / "l.gpkg").exists()
    # a broken osmAG file loads what is sound and reports the rest
    _, res, log = run_alg("loadosmag", {"INPUT": str(DATA / "broken_osmag.osm"),
                                        "OUTPUT_AREAS": str(tmp_path / "b.gpkg"),
                                        "OUTPUT_PASSAGES": str(tmp_path / "bp.gpkg")}, timeout=120)
    assert res["AREA_COUNT"] == 1 and res["UNCLOSED"] == 1 and res["DANGLING"] == 2
    assert "-99" in log


# ----------------------------------------------------------------------------- in-process QGIS
def _plugin_package():
    import importlib

    from .conftest import plugin_package

    package = plugin_package()
    importlib.import_module("cad2osmag.processing_provider.alg_load_osmag")
    return package


def test_basemaps_added_without_fetching(qgis_app, qgis_new_project):
    from qgis.core import QgsProject

    from ui.basemaps import add_xyz_basemap

    project = QgsProject.instance()
    osm = add_xyz_basemap("osm", project)
    sat = add_xyz_basemap("satellite", project)
    assert osm is not None and osm.isValid() and osm.providerType() == "wms"
    assert "type=xyz" in osm.source() and "tile.openstreetmap.org" in osm.source()
    assert sat.isValid() and "World_Imagery" in sat.source()
    assert {osm.id(), sat.id()} <= set(project.mapLayers())
    # the basemaps sit at the bottom of the layer tree and are not added twice
    assert add_xyz_basemap("OpenStreetMap", project) is osm
    names = [n.name() for n in project.layerTreeRoot().findLayers()]
    assert names == ["OpenStreetMap", "Esri World Imagery"]
    with pytest.raises(ValueError, match="unknown basemap"):
        add_xyz_basemap("bing", project)


def test_load_styles(qgis_app, qgis_new_project):
    from qgis.core import QgsCategorizedSymbolRenderer, QgsRuleBasedRenderer, QgsVectorLayer

    apply_osmag_style = _plugin_package().processing_provider.alg_load_osmag.apply_osmag_style

    areas = QgsVectorLayer("Polygon?crs=EPSG:4326&field=osmAG:areatype:string&field=name:string", "a", "memory")
    passages = QgsVectorLayer("LineString?crs=EPSG:4326&field=name:string", "p", "memory")
    apply_osmag_style(areas, "areas")
    apply_osmag_style(passages, "passages")
    r = areas.renderer()
    assert isinstance(r, QgsCategorizedSymbolRenderer) and r.classAttribute() == "osmAG:areatype"
    assert {c.value() for c in r.categories()} >= {"room", "corridor", "stairs", "elevator", "structure"}
    assert areas.labelsEnabled() and areas.labeling().settings().fieldName == "name"
    pr = passages.renderer()  # door passages red (ELSE rule), vertical passages blue: tests/test_gui_styles.py
    assert isinstance(pr, QgsRuleBasedRenderer)
    door = [r for r in pr.rootRule().children() if r.isElse()][0].symbol()
    assert door.width() >= 1.0 and door.color().red() > 200 and door.color().green() < 50
    assert passages.labelsEnabled()


def test_gdal_osm_driver_in_qgis(qgis_app, qgis_new_project, tmp_path):
    """QgsVectorLayer(path|layername=multipolygons) opens what we write and sees every area with its tags."""
    from osgeo import gdal
    from qgis.core import QgsVectorLayer

    from algorithms.osmag import write_osmag
    from algorithms.refine import refine

    g = graph_from_labels(synthetic_labels(), 0.0, 20.0, RES, types={3: "corridor"})
    out, _ = refine(g, RES)
    path = tmp_path / "f.osm"
    write_osmag(str(path), out.areas, out.passages, frame=LocalFrame(121.5906, 31.179), level="1")
    # new objects carry negative ids (JOSM convention); GDAL's default node index rejects them
    gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", "NO")
    try:
        lyr = QgsVectorLayer(f"{path}|layername=multipolygons", "m", "ogr")
        assert lyr.isValid()
        feats = list(lyr.getFeatures())
        assert len(feats) == len(out.areas)
        for f in feats:
            assert f.geometry().area() > 0 and f["name"].startswith("L1-A")
            assert '"osmAG:areatype"=>' in f["other_tags"] and '"indoor"=>' in f["other_tags"]
        lines = QgsVectorLayer(f"{path}|layername=lines", "l", "ogr")
        assert len(list(lines.getFeatures())) == len(out.passages)
    finally:
        gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", None)


def test_style_is_stored_in_the_geopackage(qgis_app, qgis_new_project, tmp_path):
    """A styled GeoPackage output reopens styled (the style is its default style in the file)."""
    from osgeo import ogr, osr
    from qgis.core import QgsCategorizedSymbolRenderer, QgsVectorLayer

    module = _plugin_package().processing_provider.alg_load_osmag
    path = str(tmp_path / "areas.gpkg")
    ds = ogr.GetDriverByName("GPKG").CreateDataSource(path)
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(4326)
    lyr = ds.CreateLayer("areas", srs, ogr.wkbPolygon)
    lyr.CreateField(ogr.FieldDefn("osmAG:areatype", ogr.OFTString))
    f = ogr.Feature(lyr.GetLayerDefn())
    f.SetField("osmAG:areatype", "room")
    f.SetGeometry(ogr.CreateGeometryFromWkt("POLYGON ((0 0, 1 0, 1 1, 0 0))"))
    lyr.CreateFeature(f)
    ds = None
    layer = QgsVectorLayer(path, "areas", "ogr")
    module.apply_osmag_style(layer, "areas")
    assert module.save_default_style(layer)
    again = QgsVectorLayer(path, "again", "ogr")
    assert isinstance(again.renderer(), QgsCategorizedSymbolRenderer)
    assert again.renderer().classAttribute() == "osmAG:areatype"
    memory = QgsVectorLayer("Polygon?crs=EPSG:4326", "m", "memory")
    assert not module.save_default_style(memory)
