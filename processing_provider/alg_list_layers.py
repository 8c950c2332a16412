"""cad2osmag:listlayers — every layer of a DXF with entity counts and what the layer rules make of it."""
from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsField,
    QgsProcessing,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterFeatureSink,
    QgsWkbTypes,
    QgsCoordinateReferenceSystem,
)

from ..algorithms import cad_import
from .base import Cad2OsmagAlgorithm, FIELD_BOOL, FIELD_INT, FIELD_STRING, make_fields

# DXF types that get their own count column; everything else is summed in n_other
COUNT_COLUMNS = ("LINE", "LWPOLYLINE", "POLYLINE", "ARC", "CIRCLE", "ELLIPSE", "SPLINE", "HATCH", "SOLID",
                 "3DFACE", "TEXT", "MTEXT", "ATTRIB", "DIMENSION")


# DWG: AutoCAD R13-2018, read directly by algorithms/cad_dwg.py (ezdwg)


class ListLayersAlgorithm(Cad2OsmagAlgorithm):
    NAME = "listlayers"
    DISPLAY_NAME = "List DXF/DWG layers"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Reports every layer of INPUT, a DXF or DWG drawing (DWG: AutoCAD R13-2018, read directly), with its "
            "entity counts by type (after exploding blocks: "
            "entities on layer 0 inside a block count on the INSERT's layer), whether it is frozen or off, "
            "and whether the layer rules keep it (kind and matching keyword; door layers are listed with kind "
            "'door' but not kept, since doorways stay open unless doors are included). Use the table to choose the "
            "LAYERS of 'Extract structure from DXF/DWG' or to write your own LAYER_RULES JSON file.\n"
            "Layer names as delivered: the rules match the meaningful part of a name (the prefix of a bound "
            "external reference, as in E1-RI-1F$0$A-WALL, is ignored); the 'matched' column shows it.\n"
            "LAYER_RULES: a JSON file of layer keywords (empty: the built-in rules, algorithms/default_layer_rules.json).\n"
            "Outputs: OUTPUT, a table without geometry, one row per layer (save it as CSV, or keep it as a "
            "memory layer); LAYER_COUNT, the number of layers; KEPT_LAYERS, the layers the rules keep "
            "(separated by ';'); HEADER_UNIT, the unit written in the drawing's header ($INSUNITS).")

    INPUT = "INPUT"
    LAYER_RULES = "LAYER_RULES"
    OUTPUT = "OUTPUT"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_drawing_parameters()
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT, self.tr("Layer report"), QgsProcessing.SourceType.TypeVector))
        self.addOutput(QgsProcessingOutputNumber("LAYER_COUNT", self.tr("Number of layers")))
        self.addOutput(QgsProcessingOutputString("KEPT_LAYERS", self.tr("Layers the rules keep (semicolon separated)")))
        self.addOutput(QgsProcessingOutputString("HEADER_UNIT", self.tr("Unit written in the header ($INSUNITS)")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        path, rules = self.drawing_and_rules(parameters, context, feedback)
        drawing = self.call(feedback, cad_import.inspect_dxf, path, rules)  # reports repairs and warnings
        infos = sorted(drawing.layers.values(), key=lambda i: i.name.lower())

        fields = make_fields(("layer", FIELD_STRING), ("matched", FIELD_STRING), ("kind", FIELD_STRING), ("kept", FIELD_BOOL),
                             ("rule", FIELD_STRING), ("frozen", FIELD_BOOL), ("off", FIELD_BOOL),
                             ("total", FIELD_INT), *(("n_" + col.lower(), FIELD_INT) for col in COUNT_COLUMNS))
        fields.append(QgsField("n_other", FIELD_INT))
        fields.append(QgsField("counts", FIELD_STRING))

        feats = []
        for info in infos:
            f = QgsFeature(fields)
            counts = info.counts
            other = sum(v for k, v in counts.items() if k not in COUNT_COLUMNS)
            attrs = [info.name, info.matched or info.name, info.kind or "", cad_import.layer_kept(info, rules), info.rule, bool(info.frozen), bool(info.off),
                     int(sum(counts.values()))]
            attrs += [int(counts.get(c, 0)) for c in COUNT_COLUMNS]
            attrs += [int(other), "; ".join(f"{k}={v}" for k, v in sorted(counts.items()))]
            f.setAttributes(attrs)
            feats.append(f)
        (sink, dest) = self.parameterAsSink(parameters, self.OUTPUT, context, fields, QgsWkbTypes.Type.NoGeometry,
                                            QgsCoordinateReferenceSystem())
        for f in feats:
            sink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        kept = [i.name for i in infos if cad_import.layer_kept(i, rules)]
        feedback.pushInfo(self.tr("{} layers, {} kept by the rules: {}").format(len(infos), len(kept), ", ".join(kept)))
        return {self.OUTPUT: dest, "LAYER_COUNT": len(infos), "KEPT_LAYERS": ";".join(kept),
                "HEADER_UNIT": drawing.header_unit}
