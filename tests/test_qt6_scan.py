"""Nothing Qt5-only in the plugin (QGIS 4 runs on Qt6 / PyQt6): our equivalent of QGIS's
scripts/pyqt5_to_pyqt6 checker, run on every Python file the plugin archive ships.

It reports what that checker rewrites:
* direct PyQt5/PyQt6/PySide imports (always go through ``qgis.PyQt``);
* ``exec_()`` / ``print_()`` (gone in PyQt6: ``exec()``);
* unscoped enum members such as ``Qt.AlignLeft``, ``QMessageBox.Yes``, ``Qgis.Info``,
  ``QgsProcessingParameterNumber.Integer`` (PyQt6 only has ``Qt.AlignmentFlag.AlignLeft``...). The
  names are resolved in the running QGIS, so only real enum members are reported, not methods, classes
  or constants;
* ``QVariant`` field types (QGIS 4 takes ``QMetaType.Type``) outside a branch on ``Qgis.QGIS_VERSION_INT``;
* classes Qt6 removed or moved: ``QRegExp``, ``QDesktopWidget``, ``QAction``/``QActionGroup``/``QShortcut``
  from QtWidgets outside a ``try: ... except ImportError`` fallback.
"""
import ast
import enum
import importlib
import sys

import pytest

from .conftest import REPO

sys.path.insert(0, str(REPO / "scripts"))
import package  # noqa: E402  (scripts/package.py: which files the plugin ships)

QT_MODULES = ("qgis.core", "qgis.gui", "qgis.PyQt.QtCore", "qgis.PyQt.QtGui", "qgis.PyQt.QtWidgets",
              "qgis.PyQt.QtNetwork", "qgis.PyQt.QtXml", "qgis.analysis")
REMOVED_IN_QT6 = {"QRegExp", "QRegExpValidator", "QDesktopWidget", "QMatrix", "QGLWidget", "QSound"}
MOVED_TO_QTGUI = {"QAction", "QActionGroup", "QShortcut", "QUndoCommand", "QUndoStack", "QFileSystemModel"}


def shipped_python_files():
    return [REPO / f for f in package.candidate_files(str(REPO)) if package.shipped(f) and f.endswith(".py")]


def resolve(name):
    for module_name in QT_MODULES:
        try:
            module = importlib.import_module(module_name)
        except ImportError:
            continue
        if hasattr(module, name):
            return getattr(module, name)
    return None


def is_enum_member(value):
    if isinstance(value, bool) or isinstance(value, type) or callable(value) and not isinstance(value, int):
        return False
    return isinstance(value, (int, enum.Enum))


class Qt5Scanner(ast.NodeVisitor):
    def __init__(self, path):
        self.path = path
        self.problems = []
        self.version_branch = 0
        self.import_fallback = 0

    def report(self, node, text):
        self.problems.append(f"{self.path.relative_to(REPO)}:{node.lineno}: {text}")

    # context: `if Qgis.QGIS_VERSION_INT ...` branches and `try/except ImportError` fallbacks
    def visit_If(self, node):  # noqa: N802
        guarded = "QGIS_VERSION_INT" in ast.dump(node.test)
        self.version_branch += guarded
        self.generic_visit(node)
        self.version_branch -= guarded

    def visit_Try(self, node):  # noqa: N802
        fallback = any("ImportError" in ast.dump(h.type) for h in node.handlers if h.type is not None)
        self.import_fallback += fallback
        self.generic_visit(node)
        self.import_fallback -= fallback

    def visit_Import(self, node):  # noqa: N802
        for alias in node.names:
            if alias.name.split(".")[0] in ("PyQt5", "PyQt6", "PySide2", "PySide6", "sip"):
                self.report(node, f"import {alias.name}: use qgis.PyQt")

    def visit_ImportFrom(self, node):  # noqa: N802
        module = node.module or ""
        if module.split(".")[0] in ("PyQt5", "PyQt6", "PySide2", "PySide6"):
            self.report(node, f"from {module} import ...: use qgis.PyQt")
        for alias in node.names:
            if alias.name in REMOVED_IN_QT6:
                self.report(node, f"{alias.name} does not exist in Qt6")
            if module == "qgis.PyQt.QtWidgets" and alias.name in MOVED_TO_QTGUI and not self.import_fallback:
                self.report(node, f"{alias.name} is in QtGui in Qt6: import it in a try/except ImportError")
            if alias.name == "QVariant" and not self.version_branch:
                self.report(node, "QVariant types: use QMetaType.Type (QGIS >= 3.38) behind a version check")

    def visit_Call(self, node):  # noqa: N802
        if isinstance(node.func, ast.Attribute) and node.func.attr in ("exec_", "print_"):
            self.report(node, f"{node.func.attr}() does not exist in PyQt6: use {node.func.attr[:-1]}()")
        self.generic_visit(node)

    def visit_Attribute(self, node):  # noqa: N802
        if isinstance(node.value, ast.Name) and node.value.id.startswith("Q"):
            owner, attr = node.value.id, node.attr
            if owner == "QVariant" and not self.version_branch:
                self.report(node, f"QVariant.{attr}: use QMetaType.Type behind a version check")
            elif attr[:1].isupper() and not attr.isupper() and not getattr(node, "_has_child_attr", False):
                cls = resolve(owner)
                value = getattr(cls, attr, None) if cls is not None else None
                if is_enum_member(value):
                    scope = type(value).__name__
                    self.report(node, f"{owner}.{attr} is an unscoped enum member: write {owner}.{scope}.{attr}")
        self.generic_visit(node)

    def visit(self, node):
        for child in ast.iter_child_nodes(node):
            if isinstance(node, ast.Attribute) and child is node.value:
                child._has_child_attr = True
        return super().visit(node)


def scan_source(path, text):
    scanner = Qt5Scanner(path)
    scanner.visit(ast.parse(text, str(path)))
    return scanner.problems


def scan(paths):
    problems = []
    for path in paths:
        problems += scan_source(path, path.read_text(encoding="utf-8"))
    return problems


def test_the_scanner_finds_what_qt6_rejects(qgis_app):
    bad = '''
from PyQt5.QtCore import Qt
from qgis.PyQt.QtCore import QVariant, QRegExp
from qgis.PyQt.QtWidgets import QAction, QMessageBox
from qgis.core import Qgis, QgsField
def f(dialog, bar):
    dialog.exec_()
    x = Qt.AlignLeft
    bar.pushMessage("a", "b", Qgis.Info)
    button = QMessageBox.Yes
    QgsField("n", QVariant.String)
'''
    problems = scan_source(REPO / "fake.py", bad)
    text = "\n".join(problems)
    for expected in ("from PyQt5.QtCore", "QRegExp", "QAction is in QtGui", "exec_()", "Qt.AlignLeft",
                     "Qgis.Info", "QMessageBox.Yes", "QVariant.String", "QVariant types"):
        assert expected in text, (expected, text)


def test_the_scanner_accepts_the_qt6_spelling(qgis_app):
    good = '''
from qgis.core import Qgis, QgsField, QgsApplication
from qgis.PyQt.QtCore import Qt, QCoreApplication
from qgis.PyQt.QtWidgets import QMessageBox
try:
    from qgis.PyQt.QtGui import QAction
except ImportError:
    from qgis.PyQt.QtWidgets import QAction
if Qgis.QGIS_VERSION_INT >= 33800:
    from qgis.PyQt.QtCore import QMetaType
    T = QMetaType.Type.QString
else:
    from qgis.PyQt.QtCore import QVariant
    T = QVariant.Type.String
def f(dialog, bar):
    dialog.exec()
    x = Qt.AlignmentFlag.AlignLeft
    bar.pushMessage("a", "b", Qgis.MessageLevel.Info)
    button = QMessageBox.StandardButton.Yes
    level = getattr(Qgis.MessageLevel, "Info")
    QgsApplication.processingRegistry()
    QCoreApplication.translate("a", "b")
    return Qgis.QGIS_VERSION_INT
'''
    assert scan_source(REPO / "fake.py", good) == []


def test_the_plugin_has_nothing_qt5_only(qgis_app):
    files = shipped_python_files()
    assert len(files) >= 20
    problems = scan(files)
    assert problems == [], "Qt5-only code (QGIS 4 / Qt6 will reject it):\n" + "\n".join(problems)


def test_metadata_declares_qt6_support():
    import configparser

    cfg = configparser.ConfigParser(interpolation=None)
    cfg.read(REPO / "metadata.txt", encoding="utf-8")
    assert cfg["general"].get("supportsQt6", "").strip() == "True"


@pytest.mark.skipif(not __import__("shutil").which("pyqt5_to_pyqt6"), reason="QGIS's pyqt5_to_pyqt6 checker is not installed")
def test_qgis_pyqt5_to_pyqt6_checker_is_clean(tmp_path):
    import shutil
    import subprocess

    for path in shipped_python_files():
        dest = tmp_path / path.relative_to(REPO)
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(path, dest)
    proc = subprocess.run([shutil.which("pyqt5_to_pyqt6"), "--logfile", str(tmp_path / "log.txt"), str(tmp_path)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
