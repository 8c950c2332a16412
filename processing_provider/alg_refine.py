"""cad2osmag:refine — simplify and clean the segmented areas (stage 4).

Also home of the layer <-> AreaGraph helpers shared by the refine, georeference, export and load
algorithms. Layer conventions (what these algorithms read and write):

* AREAS (polygons): ``id`` (int), ``type`` (room | corridor | stairs | elevator | structure),
  ``name``, ``max_clearance`` (m), ``area_m2``. Readers also accept ``osm_id`` / ``area_id`` for the
  id and ``osmAG:areatype`` for the type (layers made by *loadosmag*); without an id field the
  feature id is used. Any other non-empty field is kept as an extra osmAG tag on export.
* PASSAGES (lines): ``id``, ``from_id``, ``to_id`` (area ids), ``name``, ``width_m``; readers also
  accept ``osmAG:from`` / ``osmAG:to`` holding area names or ids.
"""
from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterNumber,
    QgsWkbTypes,
)

from ..algorithms.model import Area, AreaGraph, Passage
from .base import Cad2OsmagAlgorithm, FIELD_DOUBLE, FIELD_LONG, FIELD_STRING, from_qgs, make_fields, to_qgs, tr_common

AREA_ID_FIELDS = ("id", "osm_id", "area_id", "fid")
AREA_TYPE_FIELDS = ("type", "osmAG:areatype", "osmAG:areaType", "areatype")
INTERNAL_AREA_FIELDS = {"id", "osm_id", "area_id", "fid", "type", "area_m2", "perimeter_m", "max_clearance",
                        "areatype", "component"}
INTERNAL_PASSAGE_FIELDS = {"id", "osm_id", "fid", "from_id", "to_id", "width_m", "vertical"}  # vertical: loadosmag, for the style


def _value(feat, names, field_names):
    for n in names:
        if n in field_names:
            v = feat[n]
            if v is not None and not (hasattr(v, "isNull") and v.isNull()) and str(v) != "NULL" and str(v) != "":
                return v
    return None


def _tags(feat, field_names, internal):
    tags = {}
    for n in field_names:
        if n in internal:
            continue
        v = feat[n]
        if v is None or (hasattr(v, "isNull") and v.isNull()) or str(v) in ("", "NULL"):
            continue
        tags[n] = str(v)
    return tags


def read_areas(source, feedback=None, what="AREAS"):
    """Feature source -> list of Area (geometries in the source's CRS)."""
    names = source.fields().names()
    areas = []
    bad = []
    for f in source.getFeatures():
        g = from_qgs(f.geometry())
        v = _value(f, AREA_ID_FIELDS, names)
        try:
            aid = int(v) if v is not None else int(f.id())
        except (TypeError, ValueError):
            aid = int(f.id())
        if g is None:
            bad.append(aid)
            continue
        typ = _value(f, AREA_TYPE_FIELDS, names)
        nm = _value(f, ("name",), names)
        clear = _value(f, ("max_clearance",), names)
        tags = _tags(f, names, INTERNAL_AREA_FIELDS | {"name"})
        areas.append(Area(id=aid, polygon=g, type=str(typ) if typ else "room", name=str(nm) if nm else "",
                          max_clearance=float(clear) if clear is not None else 0.0, tags=tags))
    if bad:
        raise QgsProcessingException(tr_common("{}: features with ids {} have empty or missing geometries; "
                                               "remove them or fix the layer").format(what, bad))
    return areas


def read_passages(source, areas):
    """Feature source -> list of Passage. ``osmAG:from``/``osmAG:to`` may hold names or ids."""
    if source is None:
        return []
    names = source.fields().names()
    by_name = {a.name: a.id for a in areas if a.name}
    out = []
    for f in source.getFeatures():
        g = from_qgs(f.geometry())
        v = _value(f, ("id", "osm_id"), names)
        pid = int(v) if v is not None else int(f.id())
        ends = []
        for key, alt in (("from_id", "osmAG:from"), ("to_id", "osmAG:to")):
            x = _value(f, (key,), names)
            if x is None:
                x = _value(f, (alt,), names)
                if x is not None and str(x) in by_name:
                    x = by_name[str(x)]
            try:
                ends.append(int(x))
            except (TypeError, ValueError):
                raise QgsProcessingException(tr_common("PASSAGES: passage {} has no valid {} (value {!r}); it must "
                                                       "name the id of an area").format(pid, key, x))
        if g is not None and g.geom_type == "MultiLineString" and len(g.geoms) == 1:
            g = g.geoms[0]
        if g is None or g.geom_type != "LineString":
            raise QgsProcessingException(tr_common("PASSAGES: passage {} has no line geometry").format(pid))
        nm = _value(f, ("name",), names)
        out.append(Passage(id=pid, from_id=ends[0], to_id=ends[1], line=g, name=str(nm) if nm else "",
                           tags=_tags(f, names, INTERNAL_PASSAGE_FIELDS | {"name"})))
    return out


def area_fields(extra_keys=()):
    return make_fields(("id", FIELD_LONG), ("type", FIELD_STRING), ("name", FIELD_STRING),
                       ("max_clearance", FIELD_DOUBLE), ("area_m2", FIELD_DOUBLE), ("component", FIELD_LONG),
                       *((k, FIELD_STRING) for k in extra_keys))


def passage_fields(extra_keys=()):
    return make_fields(("id", FIELD_LONG), ("from_id", FIELD_LONG), ("to_id", FIELD_LONG), ("name", FIELD_STRING),
                       ("width_m", FIELD_DOUBLE), *((k, FIELD_STRING) for k in extra_keys))


def _extra_keys(objs, core):
    keys = []
    for o in objs:
        for k in (o.tags or {}):
            if k not in core and k not in keys:
                keys.append(k)
    return keys


def write_areas(sink, fields, areas, metric=True):
    for a in areas:
        f = QgsFeature(fields)
        f.setGeometry(to_qgs(a.polygon))
        f["id"] = int(a.id)
        f["type"] = a.type
        f["name"] = a.name or None
        f["max_clearance"] = float(a.max_clearance)
        f["area_m2"] = float(a.polygon.area) if metric else None
        f["component"] = int(a.component)
        for k, v in (a.tags or {}).items():
            if fields.indexOf(k) >= 0 and k not in ("id", "type", "name", "max_clearance", "area_m2", "component"):
                f[k] = str(v)
        if not sink.addFeature(f, QgsFeatureSink.Flag.FastInsert):
            raise QgsProcessingException(tr_common("cannot write area {} to the output layer").format(a.id))


def write_passages(sink, fields, passages, metric=True):
    for p in passages:
        f = QgsFeature(fields)
        f.setGeometry(to_qgs(p.line))
        f["id"] = int(p.id)
        f["from_id"] = int(p.from_id)
        f["to_id"] = int(p.to_id)
        f["name"] = p.name or None
        f["width_m"] = float(p.line.length) if metric else None
        for k, v in (p.tags or {}).items():
            if fields.indexOf(k) >= 0 and k not in ("id", "from_id", "to_id", "name", "width_m"):
                f[k] = str(v)
        if not sink.addFeature(f, QgsFeatureSink.Flag.FastInsert):
            raise QgsProcessingException(tr_common("cannot write passage {} to the output layer").format(p.id))


def area_and_passage_fields(areas, passages):
    return (area_fields(_extra_keys(areas, INTERNAL_AREA_FIELDS | {"name"})),
            passage_fields(_extra_keys(passages, INTERNAL_PASSAGE_FIELDS | {"name"})))


class RefineAlgorithm(Cad2OsmagAlgorithm):
    NAME = "refine"
    DISPLAY_NAME = "Refine areas (simplify, remove spikes, merge small areas)"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Makes the segmented areas light and clean while adjacent areas keep identical vertices along "
            "their shared borders. Every border between two junctions is simplified once with "
            "Douglas-Peucker (tolerance EPSILON_PX x RESOLUTION, the reported physical bound), spikes "
            "(angle below SPIKE_ANGLE, protrusion below SPIKE_LENGTH) are removed iteratively, and passage "
            "end points are locked, so each passage stays a segment whose two ends are vertices of both "
            "areas it joins. Areas smaller than MIN_AREA are merged into the neighbour they share the "
            "longest border with (stairs and elevators are kept); isolated ones are dropped. Work in "
            "metres: run it on the CAD frame (before georeferencing) or on a projected CRS.\n"
            "AREAS and PASSAGES: the outputs of 'Segment' (PASSAGES optional). RESOLUTION: the raster "
            "resolution the areas were traced at, in metres per pixel. EPSILON_PX in pixels, SPIKE_ANGLE in "
            "degrees, SPIKE_LENGTH in metres, MIN_AREA in m².\n"
            "Outputs: OUTPUT_AREAS and OUTPUT_PASSAGES, the refined layers; VERTICES_BEFORE, VERTICES_AFTER and "
            "VERTEX_REDUCTION (%); MAX_DEVIATION, the largest distance from the unsimplified areas (m); "
            "EPSILON_M, the tolerance in metres; AREA_COUNT and PASSAGE_COUNT written; MERGED and DROPPED "
            "small areas; COMPONENTS, the connected parts of the area graph, and LARGEST_COMPONENT_SHARE, the "
            "share of the area in the largest one.")

    AREAS = "AREAS"
    PASSAGES = "PASSAGES"
    RESOLUTION = "RESOLUTION"
    EPSILON_PX = "EPSILON_PX"
    SPIKE_ANGLE = "SPIKE_ANGLE"
    SPIKE_LENGTH = "SPIKE_LENGTH"
    MIN_AREA = "MIN_AREA"
    OUTPUT_AREAS = "OUTPUT_AREAS"
    OUTPUT_PASSAGES = "OUTPUT_PASSAGES"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.AREAS, self.tr("Areas"), [QgsProcessing.SourceType.TypeVectorPolygon]))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.PASSAGES, self.tr("Passages"), [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterNumber(
            self.RESOLUTION, self.tr("Raster resolution r the areas were traced at (m/px)"),
            QgsProcessingParameterNumber.Type.Double, 0.044, False, 0.0001, 10.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.EPSILON_PX, self.tr("Douglas-Peucker tolerance ε (pixels)"),
            QgsProcessingParameterNumber.Type.Double, 1.2, False, 0.0, 100.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.SPIKE_ANGLE, self.tr("Spike angle below (degrees)"),
            QgsProcessingParameterNumber.Type.Double, 15.0, False, 0.0, 90.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.SPIKE_LENGTH, self.tr("Spike protrusion below (m)"),
            QgsProcessingParameterNumber.Type.Double, 0.3, False, 0.0, 100.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.MIN_AREA, self.tr("Merge areas smaller than (m²)"),
            QgsProcessingParameterNumber.Type.Double, 10.0, False, 0.0, 1e6))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_AREAS, self.tr("Refined areas"), QgsProcessing.SourceType.TypeVectorPolygon))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_PASSAGES, self.tr("Refined passages"), QgsProcessing.SourceType.TypeVectorLine, optional=True))
        for name, label in (("VERTICES_BEFORE", "Vertices before"), ("VERTICES_AFTER", "Vertices after"),
                            ("VERTEX_REDUCTION", "Vertex reduction (%)"),
                            ("MAX_DEVIATION", "Maximum deviation from the unsimplified areas (m)"),
                            ("EPSILON_M", "Tolerance ε·r (m)"), ("AREA_COUNT", "Areas written"),
                            ("PASSAGE_COUNT", "Passages written"), ("MERGED", "Small areas merged"),
                            ("DROPPED", "Isolated small areas dropped"),
                            ("COMPONENTS", "Connected components of the area graph"),
                            ("LARGEST_COMPONENT_SHARE", "Share of the area in the largest component")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        from ..algorithms.refine import refine

        src = self.parameterAsSource(parameters, self.AREAS, context)
        if src is None:
            raise QgsProcessingException(self.tr("AREAS: the input layer cannot be opened"))
        from .alg_georeference import is_cad_frame

        crs = src.sourceCrs()
        if not is_cad_frame(crs) and crs.isGeographic():
            raise QgsProcessingException(self.tr(
                "AREAS is in a geographic CRS ({}); refinement works in metres: run it on the CAD frame "
                "(before georeferencing) or reproject to a projected CRS first").format(crs.authid()))
        psrc = self.parameterAsSource(parameters, self.PASSAGES, context)
        areas = read_areas(src)
        passages = read_passages(psrc, areas)
        res = self.parameterAsDouble(parameters, self.RESOLUTION, context)
        graph = AreaGraph(areas, passages)
        out, stats = self.call(
            feedback, refine, graph, res,
            epsilon_px=self.parameterAsDouble(parameters, self.EPSILON_PX, context),
            spike_angle=self.parameterAsDouble(parameters, self.SPIKE_ANGLE, context),
            spike_length=self.parameterAsDouble(parameters, self.SPIKE_LENGTH, context),
            min_area=self.parameterAsDouble(parameters, self.MIN_AREA, context))
        # everything computed: now create the outputs
        afields, pfields = area_and_passage_fields(out.areas, out.passages)
        sink, dest = self.parameterAsSink(parameters, self.OUTPUT_AREAS, context, afields,
                                          QgsWkbTypes.Type.Polygon, crs)
        write_areas(sink, afields, out.areas)
        result = {self.OUTPUT_AREAS: dest}
        psink, pdest = self.parameterAsSink(parameters, self.OUTPUT_PASSAGES, context, pfields,
                                            QgsWkbTypes.Type.LineString, crs)
        if psink is not None:
            write_passages(psink, pfields, out.passages)
            result[self.OUTPUT_PASSAGES] = pdest
        result.update({
            "VERTICES_BEFORE": stats["vertices_before"], "VERTICES_AFTER": stats["vertices_after"],
            "VERTEX_REDUCTION": 100.0 * stats["vertex_reduction"], "MAX_DEVIATION": stats["max_deviation_m"],
            "EPSILON_M": stats["epsilon_m"], "AREA_COUNT": len(out.areas), "PASSAGE_COUNT": len(out.passages),
            "MERGED": stats["merged"], "DROPPED": stats["dropped"], "COMPONENTS": stats["components"],
            "LARGEST_COMPONENT_SHARE": stats["largest_component_share"]})
        return result
