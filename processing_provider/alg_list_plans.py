"""cad2osmag:listplans — the plans (views) found on a whole drawing sheet, with their extents, for picking one.

The guided conversion (ui/convert_wizard.py) runs it to show the plans of each sheet, pre-select the main one
and draw the sheet on its canvas; the index or extent the user picks is the PLAN / PLAN_EXTENT of
``extractstructure`` and ``dxftoosmag``.
"""
from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsGeometry,
    QgsProcessing,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterFeatureSink,
    QgsRectangle,
    QgsWkbTypes,
)

from ..algorithms import cad_import
from ..algorithms.cad_sheet import describe_plans
from .alg_extract_structure import local_frame_crs, wall_features, wall_fields
from .base import Cad2OsmagAlgorithm, FIELD_BOOL, FIELD_DOUBLE, FIELD_INT, FIELD_STRING, make_fields

# an extent that holds any drawing: import_dxf then keeps the structure of every group on the sheet
# (frames, title blocks and legends still left out) and still lists the groups it found
WHOLE_SHEET = (-1e12, -1e12, 1e12, 1e12)


def plan_fields():
    return make_fields(("index", FIELD_INT), ("kind", FIELD_STRING), ("title", FIELD_STRING),
                       ("width", FIELD_DOUBLE), ("height", FIELD_DOUBLE), ("wall_length", FIELD_DOUBLE),
                       ("main", FIELD_BOOL), ("xmin", FIELD_DOUBLE), ("ymin", FIELD_DOUBLE),
                       ("xmax", FIELD_DOUBLE), ("ymax", FIELD_DOUBLE))


class ListPlansAlgorithm(Cad2OsmagAlgorithm):
    NAME = "listplans"
    DISPLAY_NAME = "List the plans on a DXF/DWG sheet"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Finds the plans on a whole drawing sheet (DXF or DWG), as 'Extract structure from DXF/DWG' does, "
            "and lists every group instead of keeping one: INPUT is the drawing, LAYER_RULES the optional JSON "
            "layer rules. OUTPUT holds one rectangle per group, in metres in the drawing's own frame, with its "
            "index (the value of PLAN), kind (plan, detail, legend, other), title (e.g. '三层平面图'), width and "
            "height in metres, metres of walls, and main = true for the plan converted by default (index 0 when "
            "it is a plan). STRUCTURE (optional) holds the structure lines of the whole sheet (title frames and "
            "legends left out) to draw the sheet under the rectangles; draw an extent over it to give "
            "PLAN_EXTENT. MAIN_PLAN is the index of the main plan (-1 when the sheet holds only details)."
            " PLAN_COUNT is the number of groups and PLANS lists them as text.")

    INPUT = "INPUT"
    LAYER_RULES = "LAYER_RULES"
    OUTPUT = "OUTPUT"
    STRUCTURE = "STRUCTURE"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_drawing_parameters()
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT, self.tr("Plans on the sheet"), QgsProcessing.SourceType.TypeVectorPolygon))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.STRUCTURE, self.tr("Structure lines of the whole sheet"), QgsProcessing.SourceType.TypeVectorLine,
            optional=True, createByDefault=False))
        self.addOutput(QgsProcessingOutputNumber("PLAN_COUNT", self.tr("Number of groups found on the sheet")))
        self.addOutput(QgsProcessingOutputNumber("MAIN_PLAN", self.tr("Index of the main plan (-1: none)")))
        self.addOutput(QgsProcessingOutputString("PLANS", self.tr("Plans found on the sheet")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        path, rules = self.drawing_and_rules(parameters, context, feedback)
        drawing = self.call(feedback, cad_import.import_dxf, path, rules=rules, plan=WHOLE_SHEET)
        if feedback.isCanceled():
            return {}
        plans = sorted(drawing.plans, key=lambda p: p.index)
        main = plans[0].index if plans and plans[0].kind == "plan" else -1
        pf = plan_fields()
        feats = []
        for p in plans:
            x0, y0, x1, y1 = (float(v) for v in p.extent)
            f = QgsFeature(pf)
            f.setGeometry(QgsGeometry.fromRect(QgsRectangle(x0, y0, x1, y1)))
            f.setAttributes([int(p.index), p.kind, p.title or "", x1 - x0, y1 - y0, float(p.wall_length),
                             p.index == main, x0, y0, x1, y1])
            feats.append(f)
        lines = []
        if parameters.get(self.STRUCTURE) is not None:
            lines = wall_features(drawing, feedback)
            if lines is None:
                return {}
        crs = local_frame_crs()
        sink, dest = self.parameterAsSink(parameters, self.OUTPUT, context, pf, QgsWkbTypes.Type.Polygon, crs)
        for f in feats:
            sink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        out = {self.OUTPUT: dest, "PLAN_COUNT": len(plans), "MAIN_PLAN": main, "PLANS": describe_plans(plans)}
        if parameters.get(self.STRUCTURE) is not None:
            ssink, sdest = self.parameterAsSink(parameters, self.STRUCTURE, context, wall_fields(),
                                                QgsWkbTypes.Type.MultiLineString, crs)
            if ssink is not None:
                for f in lines:
                    ssink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
                out[self.STRUCTURE] = sdest
        feedback.pushInfo(self.tr("Sheet: {}").format(out["PLANS"]))
        return out
