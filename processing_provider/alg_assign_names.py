"""cad2osmag:assignnames — room names, numbers and types from the drawing's texts (stage 5)."""
from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsGeometry,
    QgsPointXY,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterFile,
    QgsProcessingParameterString,
    QgsWkbTypes,
)

from ..algorithms import semantics
from ..algorithms.model import CadText
from .alg_georeference import is_cad_frame
from .alg_refine import INTERNAL_AREA_FIELDS, passage_fields, read_areas, read_passages, write_passages
from .base import (Cad2OsmagAlgorithm, FIELD_DOUBLE, FIELD_LONG, FIELD_STRING, from_qgs, make_fields, to_qgs,
                   tr_common)

# fields the algorithm always writes on AREAS, in this order (then any other tag of the input)
NAME_FIELDS = ("ref", "indoor", "room", "label_score", "label_texts", "label_conflict")


def _val(feat, names, field_names, default=None):
    for n in names:
        if n in field_names:
            v = feat[n]
            if v is not None and not (hasattr(v, "isNull") and v.isNull()) and str(v) != "NULL":
                return v
    return default


def read_texts(source, with_hidden: bool = False):
    """TEXTS points (extractstructure's text output, or any point layer with a 'text' field) -> CadText.
    ``with_hidden``: return (visible, hidden): texts whose 'hidden' field is true come from frozen / off
    layers (semantics.assign_names' ``hidden_texts``)."""
    hid = []
    names = source.fields().names()
    if "text" not in names:
        raise QgsProcessingException(tr_common(
            "TEXTS has no 'text' field: use the TEXTS output of 'Extract structure from DXF' (or a point layer "
            "with fields text and, optionally, layer, height, rotation, entity, block, tag, id)"))
    out = []
    for k, f in enumerate(source.getFeatures()):
        g = from_qgs(f.geometry())
        if g is None or g.geom_type not in ("Point", "MultiPoint"):
            continue
        if g.geom_type == "MultiPoint":
            g = g.geoms[0]
        try:
            tid = int(_val(f, ("id", "text_id"), names, k))
        except (TypeError, ValueError):
            tid = k
        try:
            h = float(_val(f, ("height",), names, 0.0) or 0.0)
            rot = float(_val(f, ("rotation",), names, 0.0) or 0.0)
        except (TypeError, ValueError):
            h, rot = 0.0, 0.0
        t = (CadText(x=float(g.x), y=float(g.y), text=str(_val(f, ("text",), names, "") or ""), height=h,
                           rotation=rot, layer=str(_val(f, ("layer",), names, "") or ""),
                           entity=str(_val(f, ("entity",), names, "TEXT") or "TEXT"),
                           block=str(_val(f, ("block",), names, "") or ""), tag=str(_val(f, ("tag",), names, "") or ""),
                           id=tid))
        hidden = str(_val(f, ("hidden",), names, False)).strip().lower() in ("true", "1", "yes", "t")
        (hid if hidden else out).append(t)
    return (out, hid) if with_hidden else out


def named_area_fields(areas):
    extra = []
    for a in areas:
        for k in (a.tags or {}):
            if k not in INTERNAL_AREA_FIELDS and k not in NAME_FIELDS and k != "name" and k not in extra \
                    and not k.startswith("_"):
                extra.append(k)
    return make_fields(("id", FIELD_LONG), ("type", FIELD_STRING), ("name", FIELD_STRING), ("ref", FIELD_STRING),
                       ("max_clearance", FIELD_DOUBLE), ("area_m2", FIELD_DOUBLE), ("indoor", FIELD_STRING),
                       ("room", FIELD_STRING), ("label_score", FIELD_DOUBLE), ("label_texts", FIELD_STRING),
                       ("label_conflict", FIELD_STRING), *((k, FIELD_STRING) for k in extra))


def text_report_fields():
    return make_fields(("text_ids", FIELD_STRING), ("text", FIELD_STRING), ("layer", FIELD_STRING),
                       ("role", FIELD_STRING), ("reason", FIELD_STRING), ("area_id", FIELD_LONG),
                       ("score", FIELD_DOUBLE), ("match", FIELD_STRING))


class AssignNamesAlgorithm(Cad2OsmagAlgorithm):
    NAME = "assignnames"
    DISPLAY_NAME = "Assign room names and types from texts"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Names, numbers and types the AREAS from the drawing's TEXTS (the text output of 'Extract structure "
            "from DXF', with block attributes).\n"
            "Which texts are room names: configurable rules (NAME_RULES, a copy of "
            "algorithms/default_name_rules.json) classify every text as a room name, a room number (kept as "
            "ref) or ignored, with the reason (dimension, area, elevation, door/window code, axis, stair arrow, "
            "note, title, title block, furniture...), using the text itself, the layer it sits on (room-name "
            "layers such as A-ANNO-ROOM, *-SYMB-NAME, 房间; bound-xref prefixes are stripped) and its block "
            "and attribute tag. Lines of a multi-line TEXT label are joined first.\n"
            "Which area: every text is scored against every area as in the CAD-to-osmAG paper (inside: 100 - "
            "50 rho up to rho_max 0.7, then 50 - 25 (rho - 0.7); outside but within 2.2 m of the border: 40 + "
            "30 f_size + 20 f_dist) and goes to its best area; a text inside an area belongs to it. Name and "
            "number join; an area holding two different room names is split at the narrowing between them "
            "(SPLIT, grown from the cores of its clearance map; a corridor between them becomes its own area), else it "
            "keeps the best-placed name and lists the others in label_conflict. Duplicate names get a suffix "
            "(the room number, else (1), (2)...); areas without text get the stable id level-area id (e.g. 2-17).\n"
            "Types: keywords (English, Italian, Spanish, German, French, Chinese...) and codes (*-ST-* stairs, "
            "*-P1/*-OP-*/*-FG-* lifts) set type stairs/elevator/corridor/room and the Simple Indoor Tagging "
            "fields indoor and room; long, narrow unnamed areas with three or more passages become corridors.\n"
            "Edit name, ref or type in the output layer to fix them: 'Export osmAG' keeps the edits and the "
            "passages follow renamed areas. TEXT_REPORT (optional) lists every label with its role, reason, "
            "area and score.\n"
            "PASSAGES (optional): the passages of the areas; split areas get theirs, and corridors are "
            "recognised by their number of passages. LEVEL: the level used in generated ids (empty: the areas' "
            "level field, else 1).\n"
            "Outputs: OUTPUT_AREAS, the named areas (fields name, ref, type, indoor, room, label_conflict); "
            "OUTPUT_PASSAGES, the passages including those of split areas; counts NAMED (areas named from the "
            "drawing), NUMBERED (with a room number), AUTO_IDS (with a generated id), CONFLICTS (holding "
            "several names), SPLITS (areas split), IGNORED (texts ignored) and OUTSIDE (room texts outside "
            "every area).")

    AREAS = "AREAS"
    TEXTS = "TEXTS"
    PASSAGES = "PASSAGES"
    LEVEL = "LEVEL"
    NAME_RULES = "NAME_RULES"
    SPLIT = "SPLIT"
    OUTPUT_AREAS = "OUTPUT_AREAS"
    OUTPUT_PASSAGES = "OUTPUT_PASSAGES"
    TEXT_REPORT = "TEXT_REPORT"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.AREAS, self.tr("Areas"), [QgsProcessing.SourceType.TypeVectorPolygon]))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.TEXTS, self.tr("Texts (from 'Extract structure from DXF')"), [QgsProcessing.SourceType.TypeVectorPoint]))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.PASSAGES, self.tr("Passages (optional: split areas get their passages, corridors their degree)"),
            [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterString(
            self.LEVEL, self.tr("Level (for generated ids; empty: the areas' level field, else 1)"), "", optional=True))
        self.addParameter(QgsProcessingParameterFile(
            self.NAME_RULES, self.tr("Name rules (JSON, empty = built-in defaults)"), extension="json", optional=True))
        self.addParameter(QgsProcessingParameterBoolean(
            self.SPLIT, self.tr("Split areas holding two room names at the narrowing between them"), True))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_AREAS, self.tr("Named areas"), QgsProcessing.SourceType.TypeVectorPolygon))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_PASSAGES, self.tr("Passages (with those of split areas)"),
            QgsProcessing.SourceType.TypeVectorLine, optional=True, createByDefault=False))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.TEXT_REPORT, self.tr("Text report (role, reason, area of every label)"),
            QgsProcessing.SourceType.TypeVectorPoint, optional=True, createByDefault=False))
        for key, label in (("NAMED", "Areas named from the drawing"), ("NUMBERED", "Areas with a room number"),
                           ("AUTO_IDS", "Areas with a generated id"), ("CONFLICTS", "Areas holding several names"),
                           ("SPLITS", "Areas split"), ("IGNORED", "Texts ignored"),
                           ("OUTSIDE", "Room texts outside every area")):
            self.addOutput(QgsProcessingOutputNumber(key, self.tr(label)))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        src = self.parameterAsSource(parameters, self.AREAS, context)
        tsrc = self.parameterAsSource(parameters, self.TEXTS, context)
        if src is None:
            raise QgsProcessingException(self.tr("AREAS: the input layer cannot be opened"))
        if tsrc is None:
            raise QgsProcessingException(self.tr("TEXTS: the input layer cannot be opened"))
        psrc = self.parameterAsSource(parameters, self.PASSAGES, context)
        crs = src.sourceCrs()
        for other, what in ((tsrc, "TEXTS"), (psrc, "PASSAGES")):
            if other is None:
                continue
            ocrs = other.sourceCrs()
            if is_cad_frame(ocrs) != is_cad_frame(crs) or (not is_cad_frame(crs) and ocrs != crs):
                raise QgsProcessingException(self.tr(
                    "{} is in {} but AREAS is in {}: reproject it to the CRS of AREAS first").format(
                        what, other.sourceCrs().authid() or other.sourceCrs().description(),
                        crs.authid() or crs.description()))
        if crs.isValid() and not is_cad_frame(crs) and crs.isGeographic():
            raise QgsProcessingException(self.tr(
                "AREAS is in a geographic CRS (degrees); the scores use metres: run this on the CAD-frame layers "
                "(before georeferencing) or reproject to a projected CRS"))
        areas = read_areas(src)
        passages = read_passages(psrc, areas) if psrc is not None else None
        texts, hidden = read_texts(tsrc, with_hidden=True)
        if not areas:
            feedback.pushWarning(self.tr("AREAS holds no area: nothing to name; every room text is counted as "
                                         "outside every area"))
        if not texts and not hidden:
            feedback.pushWarning(self.tr("TEXTS holds no text: every area gets its generated id (level-area id)"))
        level = (self.parameterAsString(parameters, self.LEVEL, context) or "").strip()
        if not level:
            levels = sorted({str(a.tags.get("level", "")).strip() for a in areas} - {""})
            level = levels[0] if len(levels) == 1 else "1"
        rules_path = self.parameterAsFile(parameters, self.NAME_RULES, context) or None
        rules = self.call(feedback, _load, rules_path)
        report = self.call(feedback, semantics.assign_names, areas, texts, level, rules=rules,
                           passages=passages, split=self.parameterAsBool(parameters, self.SPLIT, context),
                           hidden_texts=hidden)
        feedback.pushInfo(report.summary())
        # write
        af = named_area_fields(areas)
        (sink, adest) = self.parameterAsSink(parameters, self.OUTPUT_AREAS, context, af, QgsWkbTypes.Type.Polygon, crs)
        for a in areas:
            f = QgsFeature(af)
            f.setGeometry(to_qgs(a.polygon))
            f["id"] = int(a.id)
            f["type"] = a.type
            f["name"] = a.name or None
            f["ref"] = a.ref or None
            f["max_clearance"] = float(a.max_clearance)
            f["area_m2"] = float(a.polygon.area)
            for k, v in (a.tags or {}).items():
                if k in ("ref", "name") or k.startswith("_") or af.indexOf(k) < 0:
                    continue
                if k == "label_score":
                    f[k] = float(v)
                else:
                    f[k] = str(v)
            if not sink.addFeature(f, QgsFeatureSink.Flag.FastInsert):
                raise QgsProcessingException(self.tr("cannot write area {} to the output layer").format(a.id))
        result = {self.OUTPUT_AREAS: adest}
        if passages is not None and parameters.get(self.OUTPUT_PASSAGES) not in (None, ""):
            pf = passage_fields([k for p in passages for k in (p.tags or {})
                                 if k not in ("id", "from_id", "to_id", "name", "width_m")])
            (psink, pdest) = self.parameterAsSink(parameters, self.OUTPUT_PASSAGES, context, pf,
                                                  QgsWkbTypes.Type.LineString, crs)
            if psink is not None:
                write_passages(psink, pf, passages)
                result[self.OUTPUT_PASSAGES] = pdest
        if parameters.get(self.TEXT_REPORT) not in (None, ""):
            tf = text_report_fields()
            (tsink, tdest) = self.parameterAsSink(parameters, self.TEXT_REPORT, context, tf, QgsWkbTypes.Type.Point, crs)
            if tsink is not None:
                for r in report.texts:
                    f = QgsFeature(tf)
                    f.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(r.x, r.y)))
                    f.setAttributes([";".join(map(str, r.ids)), r.text, r.layer, r.role, r.reason,
                                     r.area_id, float(r.score), r.match])
                    tsink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
                result[self.TEXT_REPORT] = tdest
        c = report.counts()
        result.update({"NAMED": c["named_areas"], "NUMBERED": c["numbered_areas"], "AUTO_IDS": c["auto_ids"],
                       "CONFLICTS": c["conflicts"], "SPLITS": c["splits"], "IGNORED": c["ignored"],
                       "OUTSIDE": c["outside"]})
        return result


def _load(path, progress=None):
    return semantics.load_name_rules(path) if path else semantics.default_name_rules()
