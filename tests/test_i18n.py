"""Translations: the plugin loads i18n/cad2osmag_<locale>.qm for the QGIS locale; algorithm names,
parameters, help, log messages and menus appear translated; every user-facing string has a German and a
Simplified Chinese translation whose placeholders, tags and parameter ids match the English."""
import re
import sys
import xml.etree.ElementTree as ET

import pytest

from .conftest import REPO, plugin_package
from .qgis_inprocess import log_feedback

LANGUAGES = ("de", "zh_CN")
# strings allowed to stay untranslated (empty: every string is translated)
ALLOWED_UNTRANSLATED = set()


def _i18n():
    if str(REPO / "i18n") not in sys.path:
        sys.path.insert(0, str(REPO / "i18n"))
    import seed_translations
    import update_ts

    return update_ts, seed_translations.SEED


@pytest.mark.parametrize("locale, name, parameter, plan, help_start, log, menu", [
    ("de", "DXF/DWG-Grundriss in osmAG umwandeln", "DXF- oder DWG-Grundriss", "Plan auf dem Blatt (leer = Hauptplan",
     "Führt die ganze Verarbeitungskette für ein Geschoss aus", " geschrieben", "Einen Grundriss umwandeln…"),
    ("zh_CN", "将 DXF/DWG 平面图转换为 osmAG", "DXF 或 DWG 平面图", "图幅上的平面图（留空 = 主平面图",
     "对一个楼层运行完整的处理流程", "已写出 ", "转换平面图…"),
])
def test_plugin_speaks_the_qgis_locale(qgis_iface, qgis_app, tmp_path, locale, name, parameter, plan, help_start,
                                       log, menu):
    from qgis.core import QgsApplication, QgsProcessingContext
    from qgis.PyQt.QtCore import QSettings

    settings = QSettings()
    old = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", locale)
    plugin = plugin_package().classFactory(qgis_iface)
    try:
        assert plugin.translator is not None
        plugin.initGui()
        registry = QgsApplication.processingRegistry()
        alg = registry.algorithmById("cad2osmag:dxftoosmag")
        assert alg.displayName() == name
        assert alg.parameterDefinition("INPUT").description() == parameter
        # a parameter added by a helper shared by two algorithms (common translation context)
        assert alg.parameterDefinition("PLAN").description().startswith(plan)
        assert alg.shortHelpString().startswith(help_start)
        assert "RESOLUTION" in alg.shortHelpString() and "ANCHOR" in alg.shortHelpString()  # ids stay English
        assert alg.group() != "Pipeline"
        assert registry.providerById("cad2osmag").name() != "CAD to osmAG"
        assert menu in [a.text() for a in plugin.actions]
        # the shipped model: parameters and help (also in the copy a dialog creates)
        model = registry.algorithmById("cad2osmag:cad_to_osmag").create()
        assert model.parameterDefinition("DOOR_WIDTH").description() == {"de": "Breiteste Tür (m)",
                                                                        "zh_CN": "最宽门宽（米）"}[locale]
        assert {"de": "Die ganze Umwandlung eines Geschosses", "zh_CN": "以各个算法组成的图形模型"}[locale] in \
            model.shortHelpString()
        # enum options, also those of a module-level list translated in a comprehension
        avoid = registry.algorithmById("cad2osmag:route").parameterDefinition("AVOID").options()
        assert avoid[1].startswith({"de": "Treppen (", "zh_CN": "楼梯（"}[locale]), avoid
        assert "feet" not in registry.algorithmById("cad2osmag:dxftoosmag").parameterDefinition("UNITS").options()
        # a log message of a real run
        sample = registry.createAlgorithmById("cad2osmag:samplebuilding")
        feedback = log_feedback()
        results, ok = sample.run({"FLOORS": 1, "OUTPUT_FOLDER": str(tmp_path)}, QgsProcessingContext(), feedback)
        assert ok and results["FLOOR_COUNT"] == 1
        wrote = [line for line in feedback.lines if results["FIRST_FLOOR_DXF"] in line]
        assert wrote and all(log in line and "Wrote" not in line for line in wrote), feedback.lines
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


def test_every_string_is_translated_in_both_languages():
    """Fails when a user-facing string has no translation: `python3 i18n/update_ts.py --missing` lists them
    (add them to i18n/translations_<lang>.py, then `make translations`)."""
    update_ts, _ = _i18n()
    messages = update_ts.all_messages()
    assert len(messages) > 400
    gaps = {lang: [(c, t) for c, t in items if t not in ALLOWED_UNTRANSLATED]
            for lang, items in update_ts.missing(messages).items()}
    report = {lang: f"{len(items)} of {len(messages)} untranslated, e.g. {items[:5]}" for lang, items in gaps.items()}
    assert not any(gaps.values()), report


def test_ts_and_qm_files_are_built_from_the_tables(qgis_app):
    """The .ts files hold every string, finished, with the table's translation, and the compiled .qm files
    answer with it (i.e. `make translations` ran after the last table edit)."""
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator

    update_ts, seed = _i18n()
    messages = update_ts.all_messages()
    for lang in LANGUAGES:
        table = seed[lang]
        root = ET.parse(REPO / "i18n" / f"cad2osmag_{lang}.ts").getroot()
        ts = {(c.findtext("name"), m.findtext("source")): m.find("translation")
              for c in root.iter("context") for m in c.iter("message")}
        translator = QTranslator()
        assert translator.load(str(REPO / "i18n" / f"cad2osmag_{lang}.qm"))
        stale = []
        QCoreApplication.installTranslator(translator)
        try:
            for ctx, text in messages:
                want = table.get((ctx, text)) or table.get(text)
                if not want:
                    continue  # reported by test_every_string_is_translated_in_both_languages
                el = ts.get((ctx, text))
                if el is None or el.get("type") == "unfinished" or el.text != want or \
                        QCoreApplication.translate(ctx, text) != want:
                    stale.append((ctx, text[:60]))
        finally:
            QCoreApplication.removeTranslator(translator)
        assert not stale, f"{lang}: run `make translations`; {len(stale)} strings differ, e.g. {stale[:5]}"


PLACEHOLDER = re.compile(r"\{[^{}]*\}|%\d+|%[sd]")
TAG = re.compile(r"</?[A-Za-z][A-Za-z0-9]*(?:\s[^<>]*)?/?>")
PARAMETER_ID = re.compile(r"\b[A-Z][A-Z0-9]*(?:_[A-Z0-9]+)+\b")


@pytest.mark.parametrize("lang", LANGUAGES)
def test_translations_keep_placeholders_tags_and_parameter_ids(lang):
    update_ts, seed = _i18n()
    bad = []
    for key, value in seed[lang].items():
        source = key[1] if isinstance(key, tuple) else key
        # {} placeholders are filled by position: same ones, same order
        if PLACEHOLDER.findall(source) != PLACEHOLDER.findall(value):
            bad.append(("placeholders", source[:50], PLACEHOLDER.findall(value)))
        if sorted(TAG.findall(source)) != sorted(TAG.findall(value)):
            bad.append(("tags", source[:50]))
        missing_ids = set(PARAMETER_ID.findall(source)) - set(PARAMETER_ID.findall(value))
        if missing_ids:
            bad.append(("parameter ids", source[:50], sorted(missing_ids)))
        if source.count("\n") != value.count("\n"):
            bad.append(("paragraphs", source[:50]))
        if not value.strip():
            bad.append(("empty", source[:50]))
    assert not bad, bad


def test_terms_are_consistent():
    """The glossary of the brief: the same English term always gets the same word."""
    _, seed = _i18n()
    terms = {"de": {"Passages": "Durchgänge", "Areas": "Flächen", "Floor plan": "Grundriss", "Level": "Geschoss"},
             "zh_CN": {"Passages": "通道", "Areas": "区域", "Floor plan": "平面图", "Level": "楼层"}}
    for lang, words in terms.items():
        for en, tr in words.items():
            assert seed[lang][en] == tr
        # every string naming passages / stairs / lifts in words uses the glossary word (tag values such as
        # type=stairs and parameter ids such as PASSAGES stay English)
        bad = []
        for key, value in seed[lang].items():
            source = key[1] if isinstance(key, tuple) else key
            for en, want in {"de": (("passage", "Durchg"), ("stair", "Treppe"), ("lift", "Aufz"),
                                    ("floor plan", "Grundriss")),
                             "zh_CN": (("passage", "通道"), ("stair", "楼梯"), ("lift", "电梯"),
                                       ("floor plan", "平面图"))}[lang]:
                words = re.sub(r"\b(stairs/elevator|room, corridor, stairs, elevator|[A-Z_]+|\w+\.\w+)\b", "", source)
                if re.search(rf"\b{en}", words, re.I) and want not in value:
                    bad.append((lang, en, source[:60], value[:60]))
        assert not bad, bad


def test_processing_dialog_in_german(qgis_iface, qgis_app, qgis_processing, repo_root, monkeypatch):
    """The algorithm dialog a user opens: title, parameter labels and the help panel in German
    (screenshot tests/artifacts/dialog_de_dxftoosmag.png)."""
    from processing.gui.AlgorithmDialog import AlgorithmDialog
    from qgis.core import QgsApplication
    from qgis.PyQt.QtCore import QSettings
    from qgis.PyQt.QtWidgets import QLabel, QTextBrowser

    from qgis.gui import QgsBrowserGuiModel

    browser = QgsBrowserGuiModel()  # the test iface has none; the dialog's file widgets ask for it
    monkeypatch.setattr(qgis_iface, "browserModel", lambda: browser, raising=False)
    settings = QSettings()
    old = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "de")
    plugin = plugin_package().classFactory(qgis_iface)
    try:
        plugin.initGui()
        alg = QgsApplication.processingRegistry().createAlgorithmById("cad2osmag:dxftoosmag")
        dialog = AlgorithmDialog(alg, False, None)
        dialog.resize(1100, 800)
        dialog.show()
        qgis_app.processEvents()
        art = repo_root / "tests" / "artifacts"
        art.mkdir(exist_ok=True)
        dialog.grab().save(str(art / "dialog_de_dxftoosmag.png"))
        assert dialog.windowTitle().startswith("DXF/DWG-Grundriss in osmAG umwandeln")
        labels = {w.text() for w in dialog.findChildren(QLabel)}
        assert any("Breiteste Tür (m)" in t for t in labels), sorted(labels)[:20]
        help_text = " ".join(w.toPlainText() for w in dialog.findChildren(QTextBrowser))
        assert "Führt die ganze Verarbeitungskette" in help_text
        assert "RESOLUTION: Pixelgröße des Rasters in Metern" in help_text
        dialog.close()
    finally:
        plugin.unload()
        settings.setValue("locale/userLocale", old)


def _qgis_process_in(locale, tmp_path, *args):
    """scripts/qgis-process with a throw-away QGIS profile whose user locale is ``locale`` (plugin enabled)."""
    import os
    import subprocess
    import sysconfig

    profile = tmp_path / f"profile-{locale}"
    plugins = profile / "profiles" / "default" / "python" / "plugins"
    plugins.mkdir(parents=True)
    (plugins / "cad2osmag").symlink_to(REPO)
    ini = profile / "profiles" / "default" / "QGIS" / "QGIS3.ini"
    ini.parent.mkdir(parents=True)
    ini.write_text(f"[PythonPlugins]\ncad2osmag=true\n\n[locale]\nuserLocale={locale}\noverrideFlag=true\n")
    env = dict(os.environ, QGIS_CUSTOM_CONFIG_PATH=str(profile), QT_QPA_PLATFORM="offscreen",
               PYTHONPATH=sysconfig.get_paths()["purelib"])
    env.setdefault("XDG_RUNTIME_DIR", f"/tmp/runtime-{os.getuid()}")
    proc = subprocess.run(["/usr/bin/qgis_process.bin", *args], capture_output=True, text=True, timeout=600,
                          env=env, stdin=subprocess.DEVNULL)
    return proc.returncode, proc.stdout + proc.stderr


@pytest.mark.qgis_process
@pytest.mark.parametrize("locale, title, parameter, option, help_start", [
    ("de", "DXF/DWG-Grundriss in osmAG umwandeln", "DOOR_WIDTH: Breiteste Tür (m)", "4: Zoll",
     "Führt die ganze Verarbeitungskette"),
    ("zh_CN", "将 DXF/DWG 平面图转换为 osmAG", "DOOR_WIDTH: 最宽门宽（米）", "4: 英寸", "对一个楼层运行完整的处理流程"),
])
def test_qgis_process_help_in_the_users_language(tmp_path, locale, title, parameter, option, help_start):
    code, out = _qgis_process_in(locale, tmp_path, "help", "cad2osmag:dxftoosmag")
    assert code == 0, out[-3000:]
    assert title in out and parameter in out and option in out and help_start in out, out[:3000]


@pytest.mark.qgis_process
def test_qgis_process_log_in_german(tmp_path):
    code, out = _qgis_process_in("de", tmp_path, "run", "cad2osmag:samplebuilding", "--", "FLOORS=1",
                                 f"OUTPUT_FOLDER={tmp_path / 'out'}")
    assert code == 0, out[-3000:]
    assert f"{tmp_path / 'out'}" in out and " geschrieben" in out and "Wrote " not in out, out[-3000:]


def test_wizard_in_german(qgis_iface, qgis_app, provider, tmp_path, repo_root):
    """The guided conversion in German: page titles, table headers and the yes/no of the layer table
    (screenshot tests/artifacts/wizard_de_files.png)."""
    from qgis.gui import QgsMapCanvas
    from qgis.PyQt.QtCore import QSettings

    sys.path.insert(0, str(REPO))
    from algorithms.sample_building import generate_building

    settings = QSettings()
    old = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "de")
    plugin = plugin_package().classFactory(qgis_iface)
    try:
        from cad2osmag.ui.convert_wizard import ConvertWizard

        sample = generate_building(str(tmp_path / "dxf"), floors=1, seed=0)
        canvas = QgsMapCanvas()
        wiz = ConvertWizard(canvas)
        wiz.resize(900, 700)
        wiz.show()
        page = wiz.files_page
        page.add_files(sample["dxf"])
        qgis_app.processEvents()
        art = repo_root / "tests" / "artifacts"
        art.mkdir(exist_ok=True)
        wiz.grab().save(str(art / "wizard_de_files.png"))
        assert wiz.windowTitle() == "Einen Grundriss in osmAG umwandeln"
        assert page.title() == "1. Grundrisse"
        headers = [page.layers.horizontalHeaderItem(c).text() for c in range(page.layers.columnCount())]
        assert "Layer" in headers and "Behalten" in headers, headers
        kept = {page.layers.item(r, 2).text() for r in range(page.layers.rowCount())}
        assert kept <= {"ja", "nein"} and "ja" in kept, kept
        # no page's explanation is cut off where the English is not: the header has room for the German
        from qgis.PyQt.QtCore import QRect, Qt
        from qgis.PyQt.QtGui import QFontMetrics
        from qgis.PyQt.QtWidgets import QLabel

        label = next(w for w in wiz.findChildren(QLabel) if w.text() == page.subTitle() and w.isVisible())
        english = {v: k for k, v in _i18n()[1]["de"].items()}

        def need(text):
            return QFontMetrics(label.font()).boundingRect(QRect(0, 0, label.width(), 10000),
                                                           Qt.TextFlag.TextWordWrap, text).height()

        for page_id in wiz.pageIds():  # every page's explanation, in the same header
            text = wiz.page(page_id).subTitle()
            if need(english.get(text, "")) > label.height() + 2:
                continue  # the English does not fit either: a layout matter, not a translation one
            assert need(text) <= label.height() + 2, (need(text), label.height(), text)
        assert need(label.text() + " " + label.text()) > label.height() + 2  # the measure sees a text too long
        wiz.close()
    finally:
        plugin.unload()
        settings.setValue("locale/userLocale", old)
