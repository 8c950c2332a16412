"""cad2osmag:extractstructure — structural lines (walls, columns, glazing, stairs...) and texts of a DXF."""
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsFeature,
    QgsFeatureSink,
    QgsGeometry,
    QgsLineString,
    QgsMultiLineString,
    QgsPoint,
    QgsPointXY,
    QgsProcessing,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFile,
    QgsProcessingParameterString,
    QgsWkbTypes,
)

from ..algorithms import cad_import
from ..algorithms.layer_rules import load_rules
from ..algorithms.rasterize import LOCAL_FRAME_WKT
from .base import Cad2OsmagAlgorithm, FIELD_BOOL, FIELD_DOUBLE, FIELD_LONG, FIELD_STRING, make_fields

UNIT_OPTIONS = ["", "mm", "cm", "m", "inch", "feet"]


def local_frame_crs():
    """The drawing's own frame: a local engineering CRS in metres (valid in QGIS 3.22)."""
    crs = QgsCoordinateReferenceSystem.fromWkt(LOCAL_FRAME_WKT)
    return crs if crs.isValid() else QgsCoordinateReferenceSystem()


def wall_fields():
    return make_fields(("layer", FIELD_STRING), ("kind", FIELD_STRING), ("entity", FIELD_STRING),
                       ("closed", FIELD_BOOL), ("filled", FIELD_BOOL), ("width", FIELD_DOUBLE))


def text_fields():
    return make_fields(("text", FIELD_STRING), ("height", FIELD_DOUBLE), ("rotation", FIELD_DOUBLE),
                       ("layer", FIELD_STRING), ("entity", FIELD_STRING), ("block", FIELD_STRING),
                       ("tag", FIELD_STRING), ("id", FIELD_LONG))


def geometry_to_qgs(coords, closed):
    """(N, 2) metres, rings separated by NaN rows -> MultiLineString (closed rings repeat their start)."""
    import numpy as np

    multi = QgsMultiLineString()
    bad = np.isnan(coords).any(axis=1)
    parts = np.split(coords, np.flatnonzero(bad)) if bad.any() else [coords]
    for part in parts:
        part = part[~np.isnan(part).any(axis=1)]
        if len(part) == 0:
            continue
        if len(part) == 1:
            part = np.vstack((part, part))
        if closed and len(part) >= 3 and not np.array_equal(part[0], part[-1]):
            part = np.vstack((part, part[:1]))
        multi.addGeometry(QgsLineString([QgsPoint(float(x), float(y)) for x, y in part]))
    return QgsGeometry(multi)


class ExtractStructureAlgorithm(Cad2OsmagAlgorithm):
    NAME = "extractstructure"
    DISPLAY_NAME = "Extract structure from DXF"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Reads a DXF floor plan, explodes blocks (with scale, rotation, mirror and MINSERT arrays; "
            "entities on layer 0 inside a block take the INSERT's layer), skips frozen and off layers, keeps "
            "the structural layers chosen by the layer rules (walls, columns, windows/glazing, stairs, "
            "lifts, and the reference layers 0 and Defpoints) and flattens curves to 1 cm.\n"
            "LAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). "
            "LAYERS: explicit layer names (separated by ';') that override the rules. "
            "UNITS: the header's $INSUNITS is only a hint; by default the unit is chosen so that the building "
            "is 5-500 m across (a warning names both units). Door layers are left out unless INCLUDE_DOORS "
            "is set, so that doorways stay open.\n"
            "Outputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): "
            "WALLS (lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' "
            "rebuilds the geometry from them) and TEXTS (points with text, height, rotation, layer, entity, block, "
            "ATTRIB tag and id; 'Assign room names and types from texts' reads them).")

    INPUT = "INPUT"
    LAYER_RULES = "LAYER_RULES"
    LAYERS = "LAYERS"
    UNITS = "UNITS"
    INCLUDE_DOORS = "INCLUDE_DOORS"
    WALLS = "WALLS"
    TEXTS = "TEXTS"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFile(self.INPUT, self.tr("DXF drawing"), extension="dxf"))
        self.addParameter(QgsProcessingParameterFile(
            self.LAYER_RULES, self.tr("Layer rules (JSON, empty = built-in defaults)"), extension="json",
            optional=True))
        self.addParameter(QgsProcessingParameterString(
            self.LAYERS, self.tr("Layers to keep (';' separated, overrides the rules)"), optional=True))
        self.addParameter(QgsProcessingParameterEnum(
            self.UNITS, self.tr("Drawing units"),
            options=[self.tr("automatic (header + plausibility)"), "mm", "cm", "m", "inch", "feet"],
            defaultValue=0))
        self.addParameter(QgsProcessingParameterBoolean(
            self.INCLUDE_DOORS, self.tr("Include doors (rasterize doorways as closed)"), defaultValue=False))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.WALLS, self.tr("Structure lines"), QgsProcessing.SourceType.TypeVectorLine))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.TEXTS, self.tr("Texts"), QgsProcessing.SourceType.TypeVectorPoint))
        self.addOutput(QgsProcessingOutputString("UNIT", self.tr("Unit used")))
        self.addOutput(QgsProcessingOutputNumber("UNIT_SCALE", self.tr("Drawing units to metres")))
        self.addOutput(QgsProcessingOutputNumber("GEOMETRY_COUNT", self.tr("Number of structure features")))
        self.addOutput(QgsProcessingOutputNumber("TEXT_COUNT", self.tr("Number of texts")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        path = self.parameterAsFile(parameters, self.INPUT, context)
        rules_path = self.parameterAsFile(parameters, self.LAYER_RULES, context) or None
        layers_txt = self.parameterAsString(parameters, self.LAYERS, context) or ""
        layers = [s.strip() for s in layers_txt.replace("\n", ";").split(";") if s.strip()] or None
        units = UNIT_OPTIONS[self.parameterAsEnum(parameters, self.UNITS, context)]
        include_doors = self.parameterAsBool(parameters, self.INCLUDE_DOORS, context)

        rules = self.call(feedback, _load_rules, rules_path)
        drawing = self.call(feedback, cad_import.import_dxf, path, rules=rules, layers=layers, units=units or None,
                            include_doors=include_doors)
        # import_dxf already reported every repair through the feedback

        # build every feature before creating the sinks, so a failure leaves no half-written output
        wf = wall_fields()
        walls = []
        for g in drawing.geometries:
            f = QgsFeature(wf)
            f.setGeometry(geometry_to_qgs(g.coords, g.closed))
            f.setAttributes([g.layer, g.kind, g.entity, bool(g.closed), bool(g.filled), float(g.width)])
            walls.append(f)
            if feedback.isCanceled():
                return {}
        tf = text_fields()
        texts = []
        for k, t in enumerate(drawing.texts):
            f = QgsFeature(tf)
            f.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(t.x, t.y)))
            # block, tag and id feed cad2osmag:assignnames (room tags, the ids listed in label_texts)
            f.setAttributes([t.text, float(t.height), float(t.rotation), t.layer, t.entity, t.block or "",
                             t.tag or "", int(t.id) if t.id is not None and t.id >= 0 else k])
            texts.append(f)

        crs = local_frame_crs()
        (wsink, wdest) = self.parameterAsSink(parameters, self.WALLS, context, wf, QgsWkbTypes.Type.MultiLineString, crs)
        for f in walls:
            wsink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        (tsink, tdest) = self.parameterAsSink(parameters, self.TEXTS, context, tf, QgsWkbTypes.Type.Point, crs)
        for f in texts:
            tsink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        kept = sorted({g.layer for g in drawing.geometries})
        feedback.pushInfo(self.tr("Kept {} features on layers: {}; {} texts; unit {} (header: {})").format(
            len(walls), ", ".join(kept), len(texts), drawing.unit_name, drawing.header_unit))
        return {self.WALLS: wdest, self.TEXTS: tdest, "UNIT": drawing.unit_name,
                "UNIT_SCALE": drawing.unit_scale, "GEOMETRY_COUNT": len(walls), "TEXT_COUNT": len(texts)}


def _load_rules(path, progress=None):
    return load_rules(path)
