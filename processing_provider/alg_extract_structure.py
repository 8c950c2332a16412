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
    QgsProcessingParameterExtent,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterString,
    QgsWkbTypes,
)

from ..algorithms import cad_import
from ..algorithms.cad_sheet import describe_plans
from ..algorithms.rasterize import LOCAL_FRAME_WKT
from .base import Cad2OsmagAlgorithm, FIELD_BOOL, FIELD_DOUBLE, FIELD_INT, FIELD_LONG, FIELD_STRING, make_fields

UNIT_OPTIONS = ["", "mm", "cm", "m", "inch", "feet"]


def local_frame_crs():
    """The drawing's own frame: a local engineering CRS in metres (valid in QGIS 3.22)."""
    crs = QgsCoordinateReferenceSystem.fromWkt(LOCAL_FRAME_WKT)
    return crs if crs.isValid() else QgsCoordinateReferenceSystem()


def wall_fields():
    return make_fields(("layer", FIELD_STRING), ("kind", FIELD_STRING), ("entity", FIELD_STRING),
                       ("closed", FIELD_BOOL), ("filled", FIELD_BOOL), ("width", FIELD_DOUBLE),
                       ("block", FIELD_STRING), ("class", FIELD_STRING))


def wall_features(drawing, feedback):
    """One feature (wall_fields) per structure geometry of an imported drawing; None when cancelled."""
    wf = wall_fields()
    feats = []
    for g in drawing.geometries:
        f = QgsFeature(wf)
        f.setGeometry(geometry_to_qgs(g.coords, g.closed))
        f.setAttributes([g.layer, g.kind, g.entity, bool(g.closed), bool(g.filled), float(g.width), g.block,
                         g.cls])
        feats.append(f)
        if feedback.isCanceled():
            return None
    return feats


def text_fields():
    return make_fields(("text", FIELD_STRING), ("height", FIELD_DOUBLE), ("rotation", FIELD_DOUBLE),
                       ("layer", FIELD_STRING), ("entity", FIELD_STRING), ("block", FIELD_STRING),
                       ("tag", FIELD_STRING), ("id", FIELD_LONG), ("hidden", FIELD_BOOL))


def door_fields():
    return make_fields(("source", FIELD_STRING), ("width", FIELD_DOUBLE))


def add_plan_parameters(alg):
    """The PLAN (index or extent text) and PLAN_EXTENT (drawn on the canvas) parameters, shared by
    extractstructure and dxftoosmag."""
    alg.addParameter(QgsProcessingParameterString(
        "PLAN", alg.tr("Plan on the sheet (empty = main plan; an index of the log's plan list, "
                       "or xmin,ymin,xmax,ymax in metres)"), optional=True))
    alg.addParameter(QgsProcessingParameterExtent(
        "PLAN_EXTENT", alg.tr("Plan extent (drawn on the canvas over the extracted structure; wins over PLAN)"),
        optional=True))


def plan_argument(alg, parameters, context):
    """The ``plan`` argument of import_dxf from PLAN / PLAN_EXTENT (None = the main plan)."""
    if parameters.get("PLAN_EXTENT") not in (None, ""):
        rect = alg.parameterAsExtent(parameters, "PLAN_EXTENT", context)
        if rect is not None and not rect.isNull() and rect.width() > 0 and rect.height() > 0:
            return (rect.xMinimum(), rect.yMinimum(), rect.xMaximum(), rect.yMaximum())
    txt = (alg.parameterAsString(parameters, "PLAN", context) or "").strip()
    return txt or None


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


# DWG: AutoCAD R13-2018, read directly by algorithms/cad_dwg.py (ezdwg)


class ExtractStructureAlgorithm(Cad2OsmagAlgorithm):
    NAME = "extractstructure"
    DISPLAY_NAME = "Extract structure from DXF/DWG"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Reads INPUT, a DXF floor plan or a DWG (AutoCAD R13-2018, read directly: no converter needed), "
            "explodes blocks (with scale, rotation, mirror and MINSERT arrays; "
            "entities on layer 0 inside a block take the INSERT's layer), skips frozen and off layers, keeps "
            "the structural layers chosen by the layer rules (walls, columns, windows/glazing, stairs, "
            "lifts, and the reference layers 0 and Defpoints) and flattens curves to 1 cm.\n"
            "LAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). "
            "LAYERS: explicit layer names (separated by ';') that override the rules. "
            "UNITS: the header's $INSUNITS is only a hint; by default the unit is chosen so that the building "
            "is 5-500 m across (a warning names both units). Door layers are left out unless INCLUDE_DOORS "
            "is set, so that doorways stay open; door swings and door blocks (by name, in many languages) are "
            "found on any layer and written as DOORS (jamb to jamb); furniture blocks, free-standing furniture "
            "on layer 0 and pattern hatches are left out (the log counts every class).\n"
            "Whole sheets: title frames, title blocks and legends are left out and the structure is grouped "
            "into plans (groups more than 5 m apart); the main plan (largest wall mass) is kept, the log lists "
            "every group with its index, extent, title and kind (plan / detail / legend). PLAN picks another "
            "(an index, or xmin,ymin,xmax,ymax in metres); PLAN_EXTENT is the same extent drawn on the canvas.\n"
            "Outputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): "
            "WALLS (lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' "
            "rebuilds the geometry from them; block, class), TEXTS (points with text, height, rotation, layer, "
            "entity, block, tag = ATTRIB tag, id, hidden = on a frozen or off layer; 'Assign room names and types "
            "from texts' reads them) and DOORS (doorway lines with source and width). "
            "Figures: PLANS (the plans found on the sheet) and PLAN_COUNT (their number), DOOR_COUNT (doorways "
            "found), CLASSES (entities counted per class), UNIT and UNIT_SCALE (the unit used and metres per "
            "drawing unit), GEOMETRY_COUNT (structure features written) and TEXT_COUNT (texts written).")

    INPUT = "INPUT"
    LAYER_RULES = "LAYER_RULES"
    LAYERS = "LAYERS"
    UNITS = "UNITS"
    INCLUDE_DOORS = "INCLUDE_DOORS"
    WALLS = "WALLS"
    TEXTS = "TEXTS"
    DOORS = "DOORS"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_drawing_parameters()
        self.addParameter(QgsProcessingParameterString(
            self.LAYERS, self.tr("Layers to keep (';' separated, overrides the rules)"), optional=True))
        self.addParameter(QgsProcessingParameterEnum(
            self.UNITS, self.tr("Drawing units"),
            options=[self.tr("automatic (header + plausibility)"), "mm", "cm", "m", self.tr("inch"), self.tr("feet")],
            defaultValue=0))
        self.addParameter(QgsProcessingParameterBoolean(
            self.INCLUDE_DOORS, self.tr("Include doors (rasterize doorways as closed)"), defaultValue=False))
        add_plan_parameters(self)
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.WALLS, self.tr("Structure lines"), QgsProcessing.SourceType.TypeVectorLine))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.TEXTS, self.tr("Texts"), QgsProcessing.SourceType.TypeVectorPoint))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.DOORS, self.tr("Doorways found (door swings and door blocks)"),
            QgsProcessing.SourceType.TypeVectorLine, optional=True, createByDefault=False))
        self.addOutput(QgsProcessingOutputString("PLANS", self.tr("Plans found on the sheet")))
        self.addOutput(QgsProcessingOutputNumber("PLAN_COUNT", self.tr("Number of groups found on the sheet")))
        self.addOutput(QgsProcessingOutputNumber("DOOR_COUNT", self.tr("Number of doorways found")))
        self.addOutput(QgsProcessingOutputString("CLASSES", self.tr("Entity counts per class")))
        self.addOutput(QgsProcessingOutputString("UNIT", self.tr("Unit used")))
        self.addOutput(QgsProcessingOutputNumber("UNIT_SCALE", self.tr("Drawing units to metres")))
        self.addOutput(QgsProcessingOutputNumber("GEOMETRY_COUNT", self.tr("Number of structure features")))
        self.addOutput(QgsProcessingOutputNumber("TEXT_COUNT", self.tr("Number of texts")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        path, rules = self.drawing_and_rules(parameters, context, feedback)
        layers_txt = self.parameterAsString(parameters, self.LAYERS, context) or ""
        layers = [s.strip() for s in layers_txt.replace("\n", ";").split(";") if s.strip()] or None
        units = UNIT_OPTIONS[self.parameterAsEnum(parameters, self.UNITS, context)]
        include_doors = self.parameterAsBool(parameters, self.INCLUDE_DOORS, context)

        plan = plan_argument(self, parameters, context)
        drawing = self.call(feedback, cad_import.import_dxf, path, rules=rules, layers=layers, units=units or None,
                            include_doors=include_doors, plan=plan)
        # import_dxf already reported every repair through the feedback

        # build every feature before creating the sinks, so a failure leaves no half-written output
        walls = wall_features(drawing, feedback)
        if walls is None:
            return {}
        tf = text_fields()
        texts = []
        for k, t in enumerate(drawing.texts):
            f = QgsFeature(tf)
            f.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(t.x, t.y)))
            # block, tag and id feed cad2osmag:assignnames (room tags, the ids listed in label_texts)
            f.setAttributes([t.text, float(t.height), float(t.rotation), t.layer, t.entity, t.block or "",
                             t.tag or "", int(t.id) if t.id is not None and t.id >= 0 else k, False])
            texts.append(f)
        n_visible = len(texts)
        # texts of frozen / off layers (hidden = true): assignnames names only areas no visible text names
        for k, t in enumerate(getattr(drawing, "hidden_texts", []) or []):
            f = QgsFeature(tf)
            f.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(t.x, t.y)))
            f.setAttributes([t.text, float(t.height), float(t.rotation), t.layer, t.entity, t.block or "",
                             t.tag or "", int(t.id) if t.id is not None and t.id >= 0 else n_visible + k, True])
            texts.append(f)
        df = door_fields()
        doors = []
        for d in drawing.doors:
            f = QgsFeature(df)
            f.setGeometry(QgsGeometry(QgsLineString([QgsPoint(d.x0, d.y0), QgsPoint(d.x1, d.y1)])))
            f.setAttributes([d.source, float(d.width)])
            doors.append(f)

        crs = local_frame_crs()
        (wsink, wdest) = self.parameterAsSink(parameters, self.WALLS, context, wall_fields(), QgsWkbTypes.Type.MultiLineString, crs)
        for f in walls:
            wsink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        (tsink, tdest) = self.parameterAsSink(parameters, self.TEXTS, context, tf, QgsWkbTypes.Type.Point, crs)
        for f in texts:
            tsink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        ddest = None
        if parameters.get(self.DOORS) is not None:
            (dsink, ddest) = self.parameterAsSink(parameters, self.DOORS, context, df, QgsWkbTypes.Type.LineString, crs)
            if dsink is not None:
                for f in doors:
                    dsink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        classes = "; ".join(f"{k}={v}" for k, v in sorted(drawing.classes.items()))
        feedback.pushInfo(self.tr("Entity classes: {}; {} doorways found").format(classes or "-", len(doors)))
        plans = describe_plans(drawing.plans)
        feedback.pushInfo(self.tr("Sheet: {}").format(plans))
        kept = sorted({g.layer for g in drawing.geometries})
        feedback.pushInfo(self.tr("Kept {} features on layers: {}; {} texts; unit {} (header: {})").format(
            len(walls), ", ".join(kept), n_visible, drawing.unit_name, drawing.header_unit))
        out = {self.WALLS: wdest, self.TEXTS: tdest, "UNIT": drawing.unit_name,
               "UNIT_SCALE": drawing.unit_scale, "GEOMETRY_COUNT": len(walls), "TEXT_COUNT": n_visible,
               "PLANS": plans, "PLAN_COUNT": len(drawing.plans), "DOOR_COUNT": len(doors), "CLASSES": classes}
        if ddest is not None:
            out[self.DOORS] = ddest
        return out
