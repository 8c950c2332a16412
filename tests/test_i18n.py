"""Translations: the plugin loads i18n/cad2osmag_<locale>.qm for the QGIS locale; algorithm names,
parameters and menus appear translated."""
import pytest

from .conftest import REPO, plugin_package


@pytest.mark.parametrize("locale, name, parameter, menu", [
    ("de", "DXF/DWG-Grundriss in osmAG umwandeln", "DXF- oder DWG-Grundriss", "Einen Grundriss umwandeln…"),
    ("zh_CN", "将 DXF/DWG 平面图转换为 osmAG", "DXF 或 DWG 平面图", "转换平面图…"),
])
def test_plugin_speaks_the_qgis_locale(qgis_iface, qgis_app, locale, name, parameter, menu):
    from qgis.core import QgsApplication
    from qgis.PyQt.QtCore import QSettings

    settings = QSettings()
    old = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", locale)
    plugin = plugin_package().classFactory(qgis_iface)
    try:
        assert plugin.translator is not None
        plugin.initGui()
        alg = QgsApplication.processingRegistry().algorithmById("cad2osmag:dxftoosmag")
        assert alg.displayName() == name
        assert alg.parameterDefinition("INPUT").description() == parameter
        assert alg.group() != "Pipeline"
        assert QgsApplication.processingRegistry().providerById("cad2osmag").name() != "CAD to osmAG"
        assert menu in [a.text() for a in plugin.actions]
    finally:
        plugin.unload()
        settings.setValue("locale/userLocale", old)
    # unloading removes the translator: English again
    assert plugin.translator is None
    from qgis.PyQt.QtCore import QCoreApplication

    assert QCoreApplication.translate("DxfToOsmagAlgorithm", "DXF floor plan") == "DXF floor plan"


def test_english_locale_loads_no_translation(qgis_iface, qgis_app):
    from qgis.PyQt.QtCore import QSettings

    settings = QSettings()
    old = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "en_US")
    try:
        assert plugin_package().classFactory(qgis_iface).translator is None
    finally:
        settings.setValue("locale/userLocale", old)


def test_ts_files_hold_every_algorithm_name_and_menu_entry():
    import sys
    import xml.etree.ElementTree as ET

    sys.path.insert(0, str(REPO / "i18n"))
    import update_ts

    messages = update_ts.all_messages()
    for lang in ("de", "zh_CN"):
        assert (REPO / "i18n" / f"cad2osmag_{lang}.qm").is_file()
        root = ET.parse(REPO / "i18n" / f"cad2osmag_{lang}.ts").getroot()
        done = {(c.findtext("name"), m.findtext("source")) for c in root.iter("context") for m in c.iter("message")
                if (m.find("translation").text or "") and m.find("translation").get("type") != "unfinished"}
        assert ("Cad2OsmagPlugin", "Convert a floor plan…") in done
        assert ("DxfToOsmagBatchAlgorithm", "Convert a folder of floor plans to osmAG (parallel)") in done
        assert len(done) >= 120 and len(messages) > len(done)  # the rest falls back to English
