"""The "CAD to osmAG" Processing provider (id ``cad2osmag``).

Algorithms are discovered from the ``alg_*.py`` modules of this package: each defines one subclass of
``Cad2OsmagAlgorithm``. Adding a stage means adding one file; the provider never changes. The graphical
models shipped in ``models/*.model3`` are added too (e.g. ``cad2osmag:cad_to_osmag``).
"""
import inspect
import os
import pkgutil

from qgis.core import QgsMessageLog, QgsProcessingProvider, Qgis
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from .. import deps
from .base import Cad2OsmagAlgorithm

PROVIDER_ID = "cad2osmag"
ICON_PATH = os.path.join(os.path.dirname(os.path.dirname(__file__)), "icons", "icon.svg")
MODELS_DIR = os.path.join(os.path.dirname(os.path.dirname(__file__)), "models")


def shipped_models():
    """The graphical models of ``models/*.model3``, loaded (a broken file is logged and skipped)."""
    from qgis.core import QgsProcessingModelAlgorithm

    models = []
    if not os.path.isdir(MODELS_DIR):
        return models
    for name in sorted(os.listdir(MODELS_DIR)):
        if not name.endswith(".model3"):
            continue
        model = QgsProcessingModelAlgorithm()
        if model.fromFile(os.path.join(MODELS_DIR, name)):
            translate_model(model)
            models.append(model)
        else:
            QgsMessageLog.logMessage(f"cannot load the model {name}", "cad2osmag", Qgis.MessageLevel.Critical)
    return models


MODEL_CONTEXT = "Cad2OsmagModel"


def translate_model(model):
    """The shipped model's help, parameter and output descriptions in the user's language (the strings of
    models/*.model3 are collected by i18n/update_ts.py under the context ``Cad2OsmagModel``)."""
    def tr(text):
        return QCoreApplication.translate(MODEL_CONTEXT, text) if text else text

    for definition in list(model.parameterDefinitions()) + list(model.outputDefinitions()):
        definition.setDescription(tr(definition.description()))
    model.setHelpContent({k: tr(v) if isinstance(v, str) else v for k, v in model.helpContent().items()})


def algorithm_classes():
    """Every concrete ``Cad2OsmagAlgorithm`` subclass in ``processing_provider/alg_*.py``, sorted by name."""
    classes = {}
    pkg_dir = os.path.dirname(__file__)
    lacking = deps.missing()  # packages QGIS's Python lacks: their algorithms are listed but say so
    for info in sorted(pkgutil.iter_modules([pkg_dir]), key=lambda i: i.name):
        if not info.name.startswith("alg_"):
            continue
        try:
            module, failed = deps.import_algorithm_module(f"{__package__}.{info.name}", lacking)
        except Exception as exc:  # a broken module must not hide the others
            QgsMessageLog.logMessage(f"cannot load {info.name}: {exc!r}", "cad2osmag", Qgis.MessageLevel.Critical)
            continue
        for _, obj in inspect.getmembers(module, inspect.isclass):
            if issubclass(obj, Cad2OsmagAlgorithm) and obj is not Cad2OsmagAlgorithm and obj.__module__ == module.__name__:
                classes[obj.NAME] = deps.guard_algorithm(obj, module.__file__, failed, lacking) if lacking else obj
    return [classes[k] for k in sorted(classes)]


class Cad2OsmagProvider(QgsProcessingProvider):
    def __init__(self, include_models=True):
        super().__init__()
        self.include_models = include_models

    def id(self):
        return PROVIDER_ID

    def name(self):
        return QCoreApplication.translate("Cad2OsmagProvider", "CAD to osmAG")

    def longName(self):
        return self.name()

    def icon(self):
        return QIcon(ICON_PATH)

    def svgIconPath(self):
        return ICON_PATH

    def loadAlgorithms(self):
        for cls in algorithm_classes():
            self.addAlgorithm(cls())
        if self.include_models:
            for model in shipped_models():
                self.addAlgorithm(model)
