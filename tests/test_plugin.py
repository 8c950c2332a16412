"""The plugin as QGIS sees it: metadata, classFactory/initGui/unload, the provider and its algorithms."""
import configparser
import re
import subprocess

import pytest

from .conftest import REPO, plugin_package

REQUIRED_METADATA = ("name", "qgisMinimumVersion", "description", "about", "version", "author", "email",
                     "tracker", "repository", "tags", "category", "icon")


def test_metadata_is_complete():
    cfg = configparser.ConfigParser()
    cfg.read(REPO / "metadata.txt", encoding="utf-8")
    general = cfg["general"]
    for key in REQUIRED_METADATA:
        assert general.get(key, "").strip(), f"metadata.txt lacks {key}"
    assert general["qgisMinimumVersion"] == "3.22"
    assert general["hasProcessingProvider"] == "yes"
    assert (REPO / general["icon"]).is_file()
    assert len(general["about"]) > 100


def test_algorithms_package_never_imports_qgis():
    for path in sorted((REPO / "algorithms").rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        assert "import qgis" not in text and "from qgis" not in text, f"{path.name} imports qgis"


def test_plugin_loads_and_unloads(qgis_iface, qgis_app):
    from qgis.core import QgsApplication

    plugin = plugin_package().classFactory(qgis_iface)
    plugin.initGui()
    try:
        provider = QgsApplication.processingRegistry().providerById("cad2osmag")
        assert provider is not None
        assert provider.name() == "CAD to osmAG"
        ids = {alg.id() for alg in provider.algorithms()}
        assert "cad2osmag:samplebuilding" in ids
        assert len(plugin.actions) >= 3
    finally:
        plugin.unload()
    assert QgsApplication.processingRegistry().providerById("cad2osmag") is None
    assert plugin.actions == []


def test_qgis_opens_osmag_polygons_once_the_plugin_is_loaded(qgis_iface, qgis_app, tmp_path):
    from osgeo import gdal
    from qgis.core import QgsVectorLayer
    from shapely.geometry import LineString, box

    from algorithms.georef import LocalFrame
    from algorithms.model import Area, Passage
    from algorithms.osmag import write_osmag

    gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", None)
    plugin_package().classFactory(qgis_iface)
    assert gdal.GetConfigOption("OSM_USE_CUSTOM_INDEXING") == "NO"
    path = tmp_path / "two_rooms.osm"
    areas = [Area(1, box(0, 0, 5, 4), name="Office 1"), Area(2, box(5, 0, 9, 4), type="corridor", name="Hall")]
    write_osmag(str(path), areas, [Passage(1, 1, 2, LineString([(5, 1), (5, 2)]))], frame=LocalFrame(121.5, 31.2))
    layer = QgsVectorLayer(f"{path}|layername=multipolygons", "areas", "ogr")
    assert layer.isValid()
    feats = list(layer.getFeatures())
    assert sorted(f["name"] for f in feats) == ["Hall", "Office 1"]
    assert all(f.geometry().area() > 0 for f in feats)


@pytest.mark.qgis_process
def test_qgis_process_lists_provider_algorithms():
    out = subprocess.run([str(REPO / "scripts" / "qgis-process"), "list"], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    assert "cannot load" not in out.stdout + out.stderr, out.stdout + out.stderr
    listed = {line.split()[0] for line in out.stdout.splitlines() if line.strip().startswith("cad2osmag:")}
    assert expected_algorithm_ids() <= listed
    assert "cad2osmag:samplebuilding" in listed


def expected_algorithm_ids():
    """Every NAME declared in processing_provider/alg_*.py."""
    ids = set()
    for path in (REPO / "processing_provider").glob("alg_*.py"):
        match = re.search(r'^    NAME = "([a-z0-9_]+)"', path.read_text(encoding="utf-8"), re.M)
        assert match, f"{path.name} declares no NAME"
        ids.add("cad2osmag:" + match.group(1))
    return ids


def test_feedback_adapter_reports_progress_and_turns_cancel_into_a_processing_exception(qgis_app):
    from qgis.core import QgsProcessingException, QgsProcessingFeedback

    plugin_package()
    from cad2osmag.processing_provider.base import Cad2OsmagAlgorithm, FeedbackProgress

    feedback = QgsProcessingFeedback()
    progress = FeedbackProgress(feedback)
    progress.sub(50, 100).set_percent(50)
    assert feedback.progress() == pytest.approx(75.0)

    def long_stage(progress=None):
        progress.step(10)
        feedback.cancel()
        progress.step(20)  # raises Canceled
        raise AssertionError("not reached")

    with pytest.raises(QgsProcessingException, match="Canceled"):
        Cad2OsmagAlgorithm().call(feedback, long_stage)

    def bad_input(progress=None):
        from cad2osmag.algorithms.errors import InputError

        raise InputError("layer 'A-WALL' is empty: pick another layer")

    with pytest.raises(QgsProcessingException, match="A-WALL"):
        Cad2OsmagAlgorithm().call(QgsProcessingFeedback(), bad_input)
