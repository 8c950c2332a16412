"""Base class and helpers shared by every cad2osmag Processing algorithm.

The algorithms themselves live in ``algorithms/`` (no qgis import). A Processing class only maps
parameters, layers and feedback onto them:

* ``self.progress(feedback)`` gives the pipeline a ``Progress`` that reports to the feedback and
  honours cancel;
* ``self.call(feedback, func, ...)`` runs a pipeline function and turns ``InputError``/``Canceled``
  into ``QgsProcessingException`` with the same, user-readable message;
* ``to_qgs``/``from_qgs`` convert shapely <-> QgsGeometry through WKB.
"""
import os

from qgis.core import Qgis, QgsField, QgsFields, QgsGeometry, QgsProcessingAlgorithm, QgsProcessingException
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from ..algorithms.errors import Canceled, InputError
from ..algorithms.model import valid_polygon
from ..algorithms.progress import Progress

ICON_PATH = os.path.join(os.path.dirname(os.path.dirname(__file__)), "icons", "icon.svg")

# Field types for QgsField: QVariant types up to QGIS 3.36, QMetaType types from 3.38 on (the only ones
# Qt6 / QGIS 4 accept).
if Qgis.QGIS_VERSION_INT >= 33800:
    from qgis.PyQt.QtCore import QMetaType

    FIELD_STRING, FIELD_DOUBLE, FIELD_INT, FIELD_LONG, FIELD_BOOL = (
        QMetaType.Type.QString, QMetaType.Type.Double, QMetaType.Type.Int, QMetaType.Type.LongLong,
        QMetaType.Type.Bool)
else:
    from qgis.PyQt.QtCore import QVariant

    FIELD_STRING, FIELD_DOUBLE, FIELD_INT, FIELD_LONG, FIELD_BOOL = (
        QVariant.Type.String, QVariant.Type.Double, QVariant.Type.Int, QVariant.Type.LongLong, QVariant.Type.Bool)


def tr_common(text):
    """Translate a message of a helper shared by several algorithms (context ``Cad2OsmagAlgorithm``, the one
    ``Cad2OsmagAlgorithm.tr`` falls back to; i18n/update_ts.py collects these calls)."""
    return QCoreApplication.translate("Cad2OsmagAlgorithm", text)


class FeedbackProgress(Progress):
    """Adapter: pipeline ``Progress`` -> ``QgsProcessingFeedback``."""

    def __init__(self, feedback):
        self._fb = feedback

    def set_percent(self, percent):
        if self._fb is not None:
            self._fb.setProgress(float(percent))

    def info(self, message):
        if self._fb is not None:
            self._fb.pushInfo(message)

    def warning(self, message):
        if self._fb is not None:
            # pushWarning exists from QGIS 3.16; keep a fallback for safety
            push = getattr(self._fb, "pushWarning", None) or self._fb.reportError
            push(message)

    def is_canceled(self):
        return self._fb is not None and self._fb.isCanceled()


class Cad2OsmagAlgorithm(QgsProcessingAlgorithm):
    """Subclasses set NAME, DISPLAY_NAME, GROUP, GROUP_ID and HELP and implement
    initAlgorithm/processAlgorithm."""

    NAME = ""
    DISPLAY_NAME = ""
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ""

    # --- QgsProcessingAlgorithm boilerplate -----------------------------------------------
    def tr(self, text):
        out = QCoreApplication.translate(type(self).__name__, text)
        if out == text:  # helpers shared by several algorithms (alg.tr(...)) use the common context
            out = QCoreApplication.translate("Cad2OsmagAlgorithm", text)
        return out

    def name(self):
        return self.NAME

    def displayName(self):  # noqa: N802
        return self.tr(self.DISPLAY_NAME)

    def group(self):
        return self.tr(self.GROUP)

    def groupId(self):  # noqa: N802
        return self.GROUP_ID

    def shortHelpString(self):  # noqa: N802
        return self.tr(self.HELP)

    def icon(self):
        return QIcon(ICON_PATH)

    def createInstance(self):  # noqa: N802
        return type(self)()

    # --- helpers ----------------------------------------------------------------------------
    @staticmethod
    def progress(feedback):
        return FeedbackProgress(feedback)

    def call(self, feedback, func, *args, **kwargs):
        """Run a pipeline function with a feedback-backed ``progress`` keyword argument."""
        kwargs.setdefault("progress", self.progress(feedback))
        try:
            return func(*args, **kwargs)
        except Canceled:
            raise QgsProcessingException(self.tr("Canceled by the user."))
        except InputError as exc:
            raise QgsProcessingException(str(exc))


    # --- a drawing and its layer rules (every algorithm that reads a DXF/DWG) --------------------
    def add_drawing_parameters(self):
        """INPUT, a DXF or DWG file, and LAYER_RULES, an optional JSON file of layer keywords."""
        from qgis.core import QgsProcessingParameterFile

        self.addParameter(QgsProcessingParameterFile("INPUT", self.tr("DXF or DWG drawing"), fileFilter=CAD_FILTER))
        self.addParameter(QgsProcessingParameterFile(
            "LAYER_RULES", self.tr("Layer rules (JSON, empty = built-in defaults)"), extension="json",
            optional=True))

    def drawing_and_rules(self, parameters, context, feedback):
        """(path of INPUT, the layer rules of LAYER_RULES or the built-in ones)."""
        path = self.parameterAsFile(parameters, "INPUT", context)
        rules_path = self.parameterAsFile(parameters, "LAYER_RULES", context) or None
        return path, self.call(feedback, _load_rules, rules_path)


def _load_rules(path, progress=None):
    from ..algorithms.layer_rules import load_rules

    return load_rules(path)


def make_fields(*specs):
    """QgsFields from (name, FIELD_* type) pairs, in order."""
    fields = QgsFields()
    for name, ftype in specs:
        fields.append(QgsField(name, ftype))
    return fields


def to_qgs(geom):
    """shapely geometry -> QgsGeometry; a self-touching polygon is repaired on the way (every stage's
    output layer is valid: ``model.valid_polygon``)"""
    geom = valid_polygon(geom)
    out = QgsGeometry()
    out.fromWkb(geom.wkb)
    return out


def from_qgs(qgs_geometry):
    """QgsGeometry -> shapely geometry (None for empty/null)."""
    import shapely.wkb

    if qgs_geometry is None or qgs_geometry.isNull() or qgs_geometry.isEmpty():
        return None
    return shapely.wkb.loads(bytes(qgs_geometry.asWkb()))


# file filter of every parameter that takes a drawing (the readers accept both)
CAD_FILTER = "CAD drawings (*.dxf *.DXF *.dwg *.DWG);;DXF (*.dxf *.DXF);;DWG (*.dwg *.DWG)"
