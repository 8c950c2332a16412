"""cad2osmag:mergefloors — osmAG floors -> one building: registration on stairs/lifts, vertical passages."""
import os
import tempfile

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterMultipleLayers,
    QgsProcessingParameterString,
)

from ..algorithms import building
from ..algorithms.errors import Canceled
from ..algorithms.osmag import VARIANTS
from .base import Cad2OsmagAlgorithm


def _split_list(text):
    text = (text or "").strip()
    if not text:
        return None
    return [t.strip() for t in text.replace(";", ",").split(",")]


class MergeFloorsAlgorithm(Cad2OsmagAlgorithm):
    NAME = "mergefloors"
    DISPLAY_NAME = "Merge osmAG floors into a building"
    GROUP = "Tools"
    GROUP_ID = "tools"
    HELP = ("Fuses floors into one osmAG building. INPUT: osmAG floor files (semantic or fix-id), and/or "
            "AREAS/PASSAGES layers (e.g. from 'Load osmAG') split by their 'level' field.\n"
            "Level of each floor: LEVELS (comma-separated, in the order of the inputs), else the floor's level "
            "tags, else its file name (*-F3*, *_L-1*, *B1*, *3F*, *三层*). HEIGHTS: metres per level (one value "
            "for all, or one per floor; default: the floor's height tag, else 3.2).\n"
            "Registration: floors drawn in different frames are moved onto each other with their stairs and "
            "lifts (areas typed stairs/elevator, or named like one): matched by name first, else by type, size "
            "and position, by consensus (one wrong match does not move a floor); rotation when two anchors "
            "agree. The log gives the residual per anchor and the RMS. Floors without anchors are registered by "
            "their outline, with a warning.\n"
            "Stitching: overlapping stairs/lifts of consecutive levels get a vertical passage (a two-node way "
            "inside both shafts, tagged with the upper level and height). One building structure area is the "
            "parent of one structure area per level, which is the parent of that floor's areas; ids and names "
            "are unique across the building. Passages naming areas that do not exist are reported with their "
            "ids and left out (STRICT: stop instead). REGISTER (on by default): move the floors onto each other "
            "as above; off: keep every floor where it is. BUILDING: the building's name (the root structure "
            "area). VARIANT: the osmAG variant written: as the inputs, semantic (passages name their areas) or "
            "fix-id (passages give way ids).\n"
            "Outputs: OUTPUT, one osmAG file (written atomically); optional OUTPUT_AREAS and OUTPUT_PASSAGES "
            "layers with a 'level' field; FLOOR_COUNT, VERTICAL_PASSAGES, AREA_COUNT and PASSAGE_COUNT (numbers "
            "written), RMS (registration residual in metres), DROPPED_PASSAGES (passages left out) and "
            "LEVELS_OUT (the levels, in order).")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterMultipleLayers(
            "INPUT", self.tr("osmAG floor files"), QgsProcessing.SourceType.TypeFile, optional=True))
        self.addParameter(QgsProcessingParameterFeatureSource(
            "AREAS", self.tr("Areas layer (several floors, 'level' field)"),
            [QgsProcessing.SourceType.TypeVectorPolygon], optional=True))
        self.addParameter(QgsProcessingParameterFeatureSource(
            "PASSAGES", self.tr("Passages layer"), [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterString(
            "LEVELS", self.tr("Levels, one per floor file (empty: level tags, else file names)"), "", optional=True))
        self.addParameter(QgsProcessingParameterString(
            "HEIGHTS", self.tr("Height per level in metres (one value, or one per floor)"), "", optional=True))
        self.addParameter(QgsProcessingParameterString("BUILDING", self.tr("Building name"), "Building"))
        self.addParameter(QgsProcessingParameterEnum(
            "VARIANT", self.tr("Variant"), [self.tr(o) for o in ("as the inputs", "semantic (names)", "fix-id (way ids)")], defaultValue=0))
        self.addParameter(QgsProcessingParameterBoolean(
            "REGISTER", self.tr("Register the floors on their stairs/lifts (off: keep them where they are)"), True))
        self.addParameter(QgsProcessingParameterBoolean(
            "STRICT", self.tr("Stop on passages whose areas are missing (off: report and leave them out)"), False))
        self.addParameter(QgsProcessingParameterFileDestination(
            "OUTPUT", self.tr("Building osmAG file"), self.tr("OpenStreetMap XML (*.osm)")))
        self.addParameter(QgsProcessingParameterFeatureSink(
            "OUTPUT_AREAS", self.tr("Building areas"), QgsProcessing.SourceType.TypeVectorPolygon, optional=True,
            createByDefault=False))
        self.addParameter(QgsProcessingParameterFeatureSink(
            "OUTPUT_PASSAGES", self.tr("Building passages"), QgsProcessing.SourceType.TypeVectorLine, optional=True,
            createByDefault=False))
        for name, label in (("FLOOR_COUNT", "Floors"), ("VERTICAL_PASSAGES", "Vertical passages"),
                            ("AREA_COUNT", "Areas written"), ("PASSAGE_COUNT", "Passages written"),
                            ("RMS", "Registration residual RMS (m)"), ("DROPPED_PASSAGES", "Passages left out")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))
        self.addOutput(QgsProcessingOutputString("LEVELS_OUT", self.tr("Levels")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        from ..algorithms import osmag
        from ..algorithms.georef import transform_geometry
        from .alg_georeference import is_cad_frame, qgs_crs_to_pyproj
        from .alg_load_osmag import osmag_to_sinks
        from .alg_refine import read_areas, read_passages

        value = parameters.get("INPUT") or []
        paths = [str(v) for v in (value if isinstance(value, (list, tuple)) else str(value).split(";")) if str(v)]
        paths = [self._layer_path(p, context) for p in paths]
        src = self.parameterAsSource(parameters, "AREAS", context)
        if not paths and src is None:
            raise QgsProcessingException(self.tr("INPUT: give at least one osmAG floor file (or an AREAS layer)"))
        out = self.parameterAsFileOutput(parameters, "OUTPUT", context)
        levels = _split_list(self.parameterAsString(parameters, "LEVELS", context))
        heights_txt = _split_list(self.parameterAsString(parameters, "HEIGHTS", context))
        try:
            heights = [float(h) for h in heights_txt] if heights_txt else None
        except ValueError:
            raise QgsProcessingException(self.tr("HEIGHTS must be numbers (metres), e.g. 3.2 or 4.5,3.2,3.2"))
        name = self.parameterAsString(parameters, "BUILDING", context).strip() or "Building"
        venum = self.parameterAsEnum(parameters, "VARIANT", context)
        variant = None if venum == 0 else VARIANTS[venum - 1]
        register = self.parameterAsBool(parameters, "REGISTER", context)
        strict = self.parameterAsBool(parameters, "STRICT", context)
        progress = self.progress(feedback)
        try:
            floors, frame = [], None
            fixid = False
            for p in paths:
                if not os.path.isfile(p):
                    raise QgsProcessingException(self.tr("floor file '{}' does not exist").format(p))
                floors.append(building.read_floor(p, frame, progress=progress.sub(0, 1)))
                frame = frame or floors[-1].frame
                fixid = fixid or building.is_fix_id(p)
            if src is not None:
                crs = src.sourceCrs()
                if is_cad_frame(crs):
                    raise QgsProcessingException(self.tr(
                        "AREAS has no CRS (CAD frame): georeference it first (cad2osmag:georeference)"))
                areas = read_areas(src)
                psrc = self.parameterAsSource(parameters, "PASSAGES", context)
                passages = read_passages(psrc, areas) if psrc is not None else []
                if crs.authid() != "EPSG:4326":
                    pc = qgs_crs_to_pyproj(crs)
                    for a in areas:
                        a.polygon = transform_geometry(a.polygon, pc, "EPSG:4326")
                    for q in passages:
                        q.line = transform_geometry(q.line, pc, "EPSG:4326")
                if frame is None:
                    from ..algorithms.georef import LocalFrame

                    c = areas[0].polygon.centroid
                    frame = LocalFrame(c.x, c.y)
                floors += building.floors_from_layers(areas, passages, frame, source=src.sourceName())
            if heights and len(heights) == 1:
                heights = heights * len(floors)
            if levels is not None and len(levels) != len(floors):
                raise QgsProcessingException(self.tr("LEVELS gives {} levels for {} floors; give one per floor, in "
                                                     "the order of the inputs").format(len(levels), len(floors)))
            variant = variant or ("fix-id" if fixid else "semantic")
            stats = building.fuse_floors(floors, out, frame, building_name=name, levels=levels, heights=heights,
                                         variant=variant, register=register, strict_passages=strict,
                                         progress=progress.sub(0, 90))
        except building.InputError as exc:
            raise QgsProcessingException(str(exc))
        except Canceled:
            raise QgsProcessingException(self.tr("Canceled by the user."))
        results = {"OUTPUT": out, "FLOOR_COUNT": stats["floors"], "VERTICAL_PASSAGES": stats["vertical_passages"],
                   "AREA_COUNT": stats["areas"] + stats["structure_areas"], "PASSAGE_COUNT": stats["passages"],
                   "RMS": stats["overall_rms"] if stats["overall_rms"] is not None else -1.0,
                   "DROPPED_PASSAGES": sum(len(v) for v in stats["dropped_passages"].values()),
                   "LEVELS_OUT": ",".join(stats["levels"])}
        for lv, (dx, dy, deg, how) in stats["transforms"].items():
            feedback.pushInfo(self.tr("level {}: shift ({:.3f}, {:.3f}) m, rotation {:.3f}°, {}").format(
                lv, dx, dy, deg, how))
        if parameters.get("OUTPUT_AREAS") or parameters.get("OUTPUT_PASSAGES"):
            adest, pdest, *_ = osmag_to_sinks(self, parameters, context, feedback, out,
                                              QgsCoordinateReferenceSystem("EPSG:4326"), "OUTPUT_AREAS",
                                              "OUTPUT_PASSAGES")
            results["OUTPUT_AREAS"], results["OUTPUT_PASSAGES"] = adest, pdest
        return results

    @staticmethod
    def _layer_path(p, context):
        """A file path, or the source file of a loaded layer given by id/name."""
        if os.path.isfile(p):
            return p
        from qgis.core import QgsProcessingUtils

        layer = QgsProcessingUtils.mapLayerFromString(p, context)
        if layer is not None:
            return layer.source().split("|")[0]
        return p
