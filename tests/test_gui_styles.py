"""Shipped QML styles of osmAG layers: areas coloured by type, passages red, vertical passages highlighted,
labels with names; applied on load and kept by GeoPackage outputs."""
import pytest
from shapely.geometry import LineString, box

from .conftest import REPO, plugin_package
from .qgis_inprocess import run_alg_inprocess


@pytest.fixture()
def osm_file(tmp_path):
    from algorithms.georef import LocalFrame
    from algorithms.model import Area, Passage
    from algorithms.osmag import write_osmag

    areas = [Area(1, box(0, 0, 8, 6), name="Office 101"), Area(2, box(8, 0, 20, 6), type="corridor", name="Hall"),
             Area(3, box(20, 0, 24, 6), type="stairs", name="Stair A"),
             Area(4, box(24, 0, 27, 3), type="elevator", name="Lift 1"),
             Area(5, box(20, 6, 24, 12), type="stairs", name="Stair A upper")]
    passages = [Passage(1, 1, 2, LineString([(8, 2), (8, 3)]), name="door 1"),
                Passage(2, 2, 3, LineString([(20, 2), (20, 3.5)])),
                Passage(3, 3, 5, LineString([(21, 6), (23, 6)]), name="stairs up")]
    path = tmp_path / "floor.osm"
    write_osmag(str(path), areas, passages, frame=LocalFrame(121.59, 31.18, 20.0))
    return path


def _run(alg_id, params):
    return run_alg_inprocess(alg_id, params, check=True)[0]


def test_shipped_qml_files_exist_and_describe_the_osmag_style():
    areas = (REPO / "styles" / "osmag_areas.qml").read_text(encoding="utf-8")
    passages = (REPO / "styles" / "osmag_passages.qml").read_text(encoding="utf-8")
    assert 'attr="osmAG:areatype"' in areas
    for value in ("room", "corridor", "stairs", "elevator", "structure"):
        assert f'value="{value}"' in areas
    assert "&quot;vertical&quot; = 'yes'" in passages
    assert 'fieldName="name"' in areas and 'fieldName="name"' in passages


def test_loaded_osmag_layers_are_styled_and_a_geopackage_keeps_the_style(provider, osm_file, tmp_path):
    from qgis.core import QgsRenderContext, QgsVectorLayer

    from cad2osmag.processing_provider.alg_load_osmag import apply_osmag_style, save_default_style

    res = _run("cad2osmag:loadosmag", {"INPUT": str(osm_file), "OUTPUT_AREAS": str(tmp_path / "areas.gpkg"),
                                       "OUTPUT_PASSAGES": str(tmp_path / "passages.gpkg")})
    areas = QgsVectorLayer(res["OUTPUT_AREAS"], "areas", "ogr")
    passages = QgsVectorLayer(res["OUTPUT_PASSAGES"], "passages", "ogr")
    assert areas.isValid() and passages.isValid()
    vertical = {f["name"] or f["osm_id"]: f["vertical"] for f in passages.getFeatures()}
    assert sorted(vertical.values()) == ["no", "no", "yes"]
    assert vertical["stairs up"] == "yes"
    for layer, kind in ((areas, "areas"), (passages, "passages")):
        apply_osmag_style(layer, kind)
        assert layer.labelsEnabled() and layer.labeling().settings().fieldName == "name"
        assert save_default_style(layer)
    assert areas.renderer().type() == "categorizedSymbol"
    assert areas.renderer().classAttribute() == "osmAG:areatype"
    colours = {c.value(): c.symbol().color().name() for c in areas.renderer().categories()}
    assert len({colours[k] for k in ("room", "corridor", "stairs", "elevator")}) == 4
    # the vertical passage is drawn thick blue, the others red (the ELSE rule)
    ctx = QgsRenderContext()
    vertical_rule, else_rule = passages.renderer().rootRule().children()
    assert else_rule.isElse()
    vertical_rule.startRender(ctx, passages.fields(), "")
    matched = {f["vertical"]: vertical_rule.isFilterOK(f, ctx)
               for f in list(QgsVectorLayer(res["OUTPUT_PASSAGES"], "p", "ogr").getFeatures())}
    vertical_rule.stopRender(ctx)
    assert matched == {"yes": True, "no": False}
    assert vertical_rule.symbol().color().name() == "#005aff" and else_rule.symbol().color().name() == "#dc1414"
    assert vertical_rule.symbol().width() > else_rule.symbol().width()
    # reopened from the GeoPackage: the style comes back
    again = QgsVectorLayer(res["OUTPUT_PASSAGES"], "again", "ogr")
    assert again.renderer().type() == "RuleRenderer"
    again_a = QgsVectorLayer(res["OUTPUT_AREAS"], "again", "ogr")
    assert again_a.renderer().type() == "categorizedSymbol" and again_a.labelsEnabled()


def test_styled_floor_renders_for_the_readme(provider, osm_file, tmp_path, repo_root):
    from qgis.core import QgsMapRendererParallelJob, QgsMapSettings, QgsRectangle, QgsVectorLayer
    from qgis.PyQt.QtCore import QSize
    from qgis.PyQt.QtGui import QColor

    from cad2osmag.processing_provider.alg_load_osmag import apply_osmag_style

    res = _run("cad2osmag:loadosmag", {"INPUT": str(osm_file), "OUTPUT_AREAS": str(tmp_path / "a.gpkg"),
                                       "OUTPUT_PASSAGES": str(tmp_path / "p.gpkg")})
    layers = [QgsVectorLayer(res["OUTPUT_PASSAGES"], "passages", "ogr"),
              QgsVectorLayer(res["OUTPUT_AREAS"], "areas", "ogr")]
    ms = QgsMapSettings()
    ms.setLayers(layers)
    ms.setDestinationCrs(layers[1].crs())
    ext = QgsRectangle(layers[1].extent())
    ext.scale(1.2)
    ms.setExtent(ext)
    ms.setOutputSize(QSize(640, 400))
    ms.setBackgroundColor(QColor("white"))
    for layer, kind in zip(layers, ("passages", "areas")):
        apply_osmag_style(layer, kind)
    job = QgsMapRendererParallelJob(ms)
    job.start()
    job.waitForFinished()
    img = job.renderedImage()
    art = repo_root / "tests" / "artifacts"
    art.mkdir(parents=True, exist_ok=True)
    img.save(str(art / "styled_floor.png"))
    # the stairs colour and the vertical passage blue are both on the picture
    colours = {img.pixelColor(x, y).name() for x in range(0, 640, 2) for y in range(0, 400, 2)}
    assert "#005aff" in colours
    assert any(c != "#ffffff" for c in colours)
