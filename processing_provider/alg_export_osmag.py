"""cad2osmag:exportosmag — write areas and passages as an osmAG file (stage 7)."""
from qgis.core import (
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterString,
)

from ..algorithms.osmag import VARIANTS
from ..algorithms.semantics import for_osm
from .alg_georeference import is_cad_frame, qgs_crs_to_pyproj
from .alg_refine import read_areas, read_passages
from .base import Cad2OsmagAlgorithm


class ExportOsmagAlgorithm(Cad2OsmagAlgorithm):
    NAME = "exportosmag"
    DISPLAY_NAME = "Export osmAG (.osm)"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Writes AREAS and PASSAGES (and optional floor/building outlines as structure areas, which become "
            "the osmAG:parent of the areas inside them) as an osmAG file: OpenStreetMap XML that JOSM, GDAL and "
            "osmium open, with one root node, negative ids, closed area ways sharing their border nodes, and "
            "passage ways whose two nodes belong to both areas they join.\n"
            "Georeference: layers in a geographic or projected CRS are converted to WGS84 (the root node is "
            "placed at ANCHOR_LON/ANCHOR_LAT when given, else at the centre of the data). Layers in the CAD "
            "frame (no CRS) are placed with ANCHOR_LON/ANCHOR_LAT (where the CAD origin lies, also the root "
            "node), ROTATION and SCALE; without an anchor the export stops and asks you to georeference first.\n"
            "VARIANT 'semantic' references areas by name (survives JOSM editing), 'fix-id' by way id. The file "
            "is written atomically: a failed export leaves no file behind. Holes (pillars) are not part of "
            "an osmAG area way and are left out (counted in the log).\n"
            "STRUCTURE (optional): polygons of the floor or building outline, written as structure areas.\n"
            "LEVEL: the level tag of every area and passage (e.g. 1, -1); empty keeps the layers' own level "
            "field, else 1. HEIGHT: height per level in metres (height tag).\n"
            "ANCHOR_LON / ANCHOR_LAT in degrees (WGS84), ROTATION in degrees clockwise from north, SCALE in "
            "ground metres per CAD metre: the placement of 'Place a floor plan on the map' gives all four.\n"
            "OUTPUT: the .osm file to write.\n"
            "Outputs: AREA_COUNT, PASSAGE_COUNT and NODE_COUNT written; SHARED_NODES, the nodes shared by two "
            "or more areas; HOLES_DROPPED, the holes of areas left out (osmAG areas have no holes).")

    AREAS = "AREAS"
    PASSAGES = "PASSAGES"
    STRUCTURE = "STRUCTURE"
    LEVEL = "LEVEL"
    HEIGHT = "HEIGHT"
    VARIANT = "VARIANT"
    ANCHOR_LON = "ANCHOR_LON"
    ANCHOR_LAT = "ANCHOR_LAT"
    ROTATION = "ROTATION"
    SCALE = "SCALE"
    OUTPUT = "OUTPUT"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.AREAS, self.tr("Areas"), [QgsProcessing.SourceType.TypeVectorPolygon]))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.PASSAGES, self.tr("Passages"), [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.STRUCTURE, self.tr("Floor / building outlines (structure areas)"),
            [QgsProcessing.SourceType.TypeVectorPolygon], optional=True))
        self.addParameter(QgsProcessingParameterString(
            self.LEVEL, self.tr("Level (empty: the areas' own level field, else 1)"), "", optional=True))
        self.addParameter(QgsProcessingParameterNumber(
            self.HEIGHT, self.tr("Height per level (m)"), QgsProcessingParameterNumber.Type.Double, 3.2, False, 0.01,
            1000.0))
        self.addParameter(QgsProcessingParameterEnum(
            self.VARIANT, self.tr("Variant"), [self.tr("semantic (names)"), self.tr("fix-id (way ids)")],
            defaultValue=0))
        self.addParameter(QgsProcessingParameterNumber(
            self.ANCHOR_LON, self.tr("Anchor / root longitude (CAD-frame layers: where the CAD origin lies)"),
            QgsProcessingParameterNumber.Type.Double, None, True, -180.0, 180.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.ANCHOR_LAT, self.tr("Anchor / root latitude"), QgsProcessingParameterNumber.Type.Double, None, True,
            -90.0, 90.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.ROTATION, self.tr("Rotation of CAD-frame layers (degrees clockwise from north)"),
            QgsProcessingParameterNumber.Type.Double, 0.0, False, -360.0, 360.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.SCALE, self.tr("Scale of CAD-frame layers"), QgsProcessingParameterNumber.Type.Double, 1.0, False,
            1e-6, 1e6))
        self.addParameter(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("osmAG file"), self.tr("OpenStreetMap XML (*.osm)")))
        for name, label in (("AREA_COUNT", "Areas written"), ("PASSAGE_COUNT", "Passages written"),
                            ("NODE_COUNT", "Nodes written"), ("SHARED_NODES", "Nodes shared by 2+ areas"),
                            ("HOLES_DROPPED", "Holes left out")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        from ..algorithms.georef import LocalFrame
        from ..algorithms.osmag import write_osmag

        src = self.parameterAsSource(parameters, self.AREAS, context)
        if src is None:
            raise QgsProcessingException(self.tr("AREAS: the input layer cannot be opened"))
        psrc = self.parameterAsSource(parameters, self.PASSAGES, context)
        ssrc = self.parameterAsSource(parameters, self.STRUCTURE, context)
        crs = src.sourceCrs()
        cad = is_cad_frame(crs)
        for other, what in ((psrc, "PASSAGES"), (ssrc, "STRUCTURE")):
            if other is not None and is_cad_frame(other.sourceCrs()) != cad or (
                    other is not None and not cad and other.sourceCrs() != crs):
                raise QgsProcessingException(self.tr(
                    "{} is in {} but AREAS is in {}; reproject it to the CRS of AREAS first").format(
                        what, other.sourceCrs().authid() or "no CRS", crs.authid() or "no CRS"))
        # label_score / label_texts / label_conflict are layer fields for the user, not osmAG tags (a conflict
        # becomes a fixme); edited name, ref and type are written as they are
        areas = for_osm(read_areas(src))
        structure = read_areas(ssrc, what="STRUCTURE") if ssrc is not None else []
        for s in structure:
            s.type = "structure"
        if structure:
            # structure ids must not collide with area ids
            used = {a.id for a in areas}
            nxt = max(used | {0}) + 1
            for s in structure:
                if s.id in used:
                    s.id, nxt = nxt, nxt + 1
                used.add(s.id)
        passages = read_passages(psrc, areas)
        level = (self.parameterAsString(parameters, self.LEVEL, context) or "").strip()
        if not level:  # re-exporting loaded or edited layers keeps their level
            levels = sorted({str(a.tags.get("level", "")).strip() for a in areas} - {""})
            if len(levels) > 1:
                raise QgsProcessingException(self.tr(
                    "AREAS holds several levels ({}): export one level at a time (filter the layer, or set LEVEL), "
                    "then combine the files with 'Merge osmAG floors into a building'").format(", ".join(levels)))
            level = levels[0] if levels else "1"
        height = self.parameterAsDouble(parameters, self.HEIGHT, context)
        if parameters.get(self.HEIGHT) in (None, ""):
            heights = {str(a.tags.get("height", "")).strip() for a in areas} - {""}
            if len(heights) == 1:
                try:
                    height = float(heights.pop())
                except ValueError:
                    pass
        variant = VARIANTS[self.parameterAsEnum(parameters, self.VARIANT, context)]
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        has_anchor = parameters.get(self.ANCHOR_LON) not in (None, "") and \
            parameters.get(self.ANCHOR_LAT) not in (None, "")
        lon = self.parameterAsDouble(parameters, self.ANCHOR_LON, context) if has_anchor else None
        lat = self.parameterAsDouble(parameters, self.ANCHOR_LAT, context) if has_anchor else None
        kwargs = dict(level=level, height=height, variant=variant, structure_areas=structure)
        if not cad:
            kwargs["crs"] = qgs_crs_to_pyproj(crs)
            if has_anchor:
                kwargs["root"] = (lon, lat)
            feedback.pushInfo(self.tr("layers are in {}: converting to WGS84").format(
                crs.authid() or crs.description()))
        else:
            if not has_anchor:
                raise QgsProcessingException(self.tr(
                    "AREAS has no CRS (CAD frame): georeference the layers first (cad2osmag:georeference), or "
                    "give ANCHOR_LON and ANCHOR_LAT (where the CAD origin lies) and ROTATION"))
            try:
                kwargs["frame"] = LocalFrame(lon, lat, self.parameterAsDouble(parameters, self.ROTATION, context),
                                             self.parameterAsDouble(parameters, self.SCALE, context))
            except Exception as exc:  # InputError from the frame
                raise QgsProcessingException(str(exc))
            feedback.pushInfo(self.tr("CAD-frame layers placed with {}").format(repr(kwargs["frame"])))
        stats = self.call(feedback, write_osmag, out, areas, passages, **kwargs)
        return {self.OUTPUT: out, "AREA_COUNT": stats["areas"] + stats["structure_areas"],
                "PASSAGE_COUNT": stats["passages"], "NODE_COUNT": stats["nodes"],
                "SHARED_NODES": stats["shared_nodes"], "HOLES_DROPPED": stats["holes_dropped"]}
