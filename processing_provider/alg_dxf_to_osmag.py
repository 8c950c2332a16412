"""cad2osmag:dxftoosmag — the whole pipeline for one floor: DXF -> osmAG (+ preview)."""
from qgis.core import (
    QgsProcessing,
    QgsProcessingParameterFeatureSink,
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterPoint,
    QgsProcessingParameterString,
)

from ..algorithms import pipeline, segmentation
from .alg_extract_structure import add_plan_parameters, plan_argument
from .alg_load_osmag import osmag_to_sinks
from .base import CAD_FILTER, Cad2OsmagAlgorithm

UNITS = ["auto", "mm", "cm", "m", "inch", "feet"]
VARIANTS = ["semantic", "fix-id"]


# DWG: AutoCAD R13-2018, read directly by algorithms/cad_dwg.py (ezdwg)


class DxfToOsmagAlgorithm(Cad2OsmagAlgorithm):
    NAME = "dxftoosmag"
    DISPLAY_NAME = "Convert DXF/DWG floor plan to osmAG"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Runs the whole pipeline on one floor (a DXF, or a DWG of AutoCAD R13-2018 read directly): "
            "structural layers of the drawing are kept (walls, columns, "
            "glazing, stairs), rasterized, segmented into an Area Graph of rooms, corridors and the passages "
            "between them, refined (simplified polygons with shared borders) and written as an osmAG file "
            "anchored on the Earth. Each step is also available as its own algorithm for finer control.\n"
            "INPUT: the floor plan (.dxf or .dwg). LAYER_RULES: a JSON file of layer keywords (empty: the "
            "built-in rules; see 'List DXF/DWG layers'). UNITS: the unit the drawing is drawn in (auto: read "
            "from the header and checked for a plausible building size).\n"
            "RESOLUTION: raster pixel size in metres (0.044 m by default; smaller follows thin walls better "
            "but is slower). TOPOLOGY_CELL: the cell size (m) of the segmentation's skeleton and merges (0.088 m, "
            "two raster pixels; the outlines keep the raster's pixels; 0 = the raster's pixels, slower). "
            "DOOR_WIDTH: the widest door in metres (2.8 m): narrower openings separate rooms. "
            "CORRIDOR_WIDTH: corridor width in metres (8 m). MIN_AREA: areas smaller than this (m²) merge into "
            "a neighbour (stairs and lifts are kept). INCLUDE_DOORS: draw door layers as walls (doorways "
            "closed; off by default, so that doorways stay open).\n"
            "PLAN / PLAN_EXTENT: which plan of a sheet with several (empty: the main plan; an index of the "
            "plan list in the log, or xmin,ymin,xmax,ymax in metres, or an extent drawn on the canvas).\n"
            "NAMES (on by default): the drawing's texts name, number and type the areas "
            "(see 'Assign room names and types from texts'); NAME_RULES: a JSON file that adapts those rules.\n"
            "LEVEL: the floor's level (osmAG level tag, e.g. 1, -1). HEIGHT: floor height in metres (3.2 m). "
            "ANCHOR: where the drawing origin (0, 0) lies on the map (pick it on a basemap; empty: longitude 0, "
            "latitude 0). ROTATION: the direction of the drawing's +y axis in degrees clockwise from north. "
            "VARIANT: semantic (passages name their areas) or fix-id (passages give way ids).\n"
            "Outputs: OUTPUT, the osmAG file (.osm); OUTPUT_AREAS and OUTPUT_PASSAGES, the same areas and "
            "passages as layers in WGS84 to show on the map; PREVIEW, an optional PNG picture of the areas; "
            "AREA_COUNT and PASSAGE_COUNT, the numbers written.")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFile("INPUT", self.tr("DXF or DWG floor plan"), fileFilter=CAD_FILTER))
        self.addParameter(QgsProcessingParameterFile("LAYER_RULES", self.tr("Layer rules (JSON, optional)"),
                                                     extension="json", optional=True))
        self.addParameter(QgsProcessingParameterEnum("UNITS", self.tr("Drawing units"), [self.tr(u) for u in UNITS],
                                                     defaultValue=0))
        self.addParameter(QgsProcessingParameterNumber("RESOLUTION", self.tr("Raster resolution (m/px)"),
                                                       QgsProcessingParameterNumber.Type.Double, 0.044, False, 0.005, 1.0))
        self.addParameter(QgsProcessingParameterNumber(
            "TOPOLOGY_CELL", self.tr("Cell size of the skeleton and merges (m; 0 = the raster's cells)"),
            QgsProcessingParameterNumber.Type.Double, segmentation.TOPOLOGY_RESOLUTION, True, 0.0, 10.0))
        self.addParameter(QgsProcessingParameterNumber("DOOR_WIDTH", self.tr("Widest door (m)"),
                                                       QgsProcessingParameterNumber.Type.Double, 2.8, False, 0.3, 20))
        self.addParameter(QgsProcessingParameterNumber("CORRIDOR_WIDTH", self.tr("Corridor width (m)"),
                                                       QgsProcessingParameterNumber.Type.Double, 8.0, False, 0.3, 50))
        self.addParameter(QgsProcessingParameterNumber("MIN_AREA", self.tr("Merge areas smaller than (m²)"),
                                                       QgsProcessingParameterNumber.Type.Double, 10.0, False, 0, 1000))
        self.addParameter(QgsProcessingParameterBoolean("INCLUDE_DOORS",
                                                        self.tr("Close doorways (rasterize door layers)"), False))
        add_plan_parameters(self)  # PLAN / PLAN_EXTENT: which plan of a whole sheet (cad_sheet)
        self.addParameter(QgsProcessingParameterBoolean(
            "NAMES", self.tr("Room names, numbers and types from the drawing's texts"), True))
        self.addParameter(QgsProcessingParameterFile("NAME_RULES", self.tr("Name rules (JSON, optional)"),
                                                     extension="json", optional=True))
        self.addParameter(QgsProcessingParameterString("LEVEL", self.tr("Level"), "1"))
        self.addParameter(QgsProcessingParameterNumber("HEIGHT", self.tr("Floor height (m)"),
                                                       QgsProcessingParameterNumber.Type.Double, 3.2, False, 0.1, 100))
        self.addParameter(QgsProcessingParameterPoint("ANCHOR", self.tr("Position of the drawing origin"),
                                                      optional=True))
        self.addParameter(QgsProcessingParameterNumber("ROTATION", self.tr("Rotation (degrees clockwise from north)"),
                                                       QgsProcessingParameterNumber.Type.Double, 0.0, False, -360, 360))
        self.addParameter(QgsProcessingParameterEnum("VARIANT", self.tr("osmAG variant"), VARIANTS, defaultValue=0))
        self.addParameter(QgsProcessingParameterFileDestination("OUTPUT", self.tr("osmAG file"),
                                                                self.tr("OpenStreetMap XML (*.osm)")))
        self.addParameter(QgsProcessingParameterFeatureSink(
            "OUTPUT_AREAS", self.tr("Areas (to show on the map)"), QgsProcessing.SourceType.TypeVectorPolygon,
            optional=True, createByDefault=True))
        self.addParameter(QgsProcessingParameterFeatureSink(
            "OUTPUT_PASSAGES", self.tr("Passages (to show on the map)"), QgsProcessing.SourceType.TypeVectorLine,
            optional=True, createByDefault=True))
        self.addParameter(QgsProcessingParameterFileDestination("PREVIEW", self.tr("Preview image"),
                                                                self.tr("PNG image (*.png)"), optional=True,
                                                                createByDefault=False))
        for key, label in (("AREA_COUNT", "Areas"), ("PASSAGE_COUNT", "Passages")):
            self.addOutput(QgsProcessingOutputNumber(key, self.tr(label)))

    def anchor_lonlat(self, parameters, context):
        """The ANCHOR point in WGS84 (lon, lat), or (None, None) when not given."""
        if parameters.get("ANCHOR") in (None, ""):
            return None, None
        point = self.parameterAsPoint(parameters, "ANCHOR", context)
        crs = self.parameterAsPointCrs(parameters, "ANCHOR", context)
        wgs84 = QgsCoordinateReferenceSystem("EPSG:4326")
        if crs.isValid() and crs != wgs84:
            point = QgsCoordinateTransform(crs, wgs84, context.transformContext()).transform(point)
        return point.x(), point.y()

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        units = UNITS[self.parameterAsEnum(parameters, "UNITS", context)]
        lon, lat = self.anchor_lonlat(parameters, context)
        out = self.parameterAsFileOutput(parameters, "OUTPUT", context)
        preview = self.parameterAsFileOutput(parameters, "PREVIEW", context) or None
        if not out:
            raise QgsProcessingException(self.tr("OUTPUT: give the .osm file to write"))
        stats = self.call(
            feedback, pipeline.convert_dxf,
            self.parameterAsFile(parameters, "INPUT", context), out, preview_png=preview,
            rules=self.parameterAsFile(parameters, "LAYER_RULES", context) or None,
            units=None if units == "auto" else units,
            include_doors=self.parameterAsBool(parameters, "INCLUDE_DOORS", context),
            plan=plan_argument(self, parameters, context),
            resolution=self.parameterAsDouble(parameters, "RESOLUTION", context),
            topology_resolution=(None if parameters.get("TOPOLOGY_CELL") in (None, "")
                                 else self.parameterAsDouble(parameters, "TOPOLOGY_CELL", context)),
            door_width=self.parameterAsDouble(parameters, "DOOR_WIDTH", context),
            corridor_width=self.parameterAsDouble(parameters, "CORRIDOR_WIDTH", context),
            min_area=self.parameterAsDouble(parameters, "MIN_AREA", context),
            level=self.parameterAsString(parameters, "LEVEL", context).strip() or "1",
            height=self.parameterAsDouble(parameters, "HEIGHT", context),
            anchor_lon=lon, anchor_lat=lat,
            rotation_deg=self.parameterAsDouble(parameters, "ROTATION", context),
            variant=VARIANTS[self.parameterAsEnum(parameters, "VARIANT", context)],
            names=self.parameterAsBool(parameters, "NAMES", context),
            name_rules=self.parameterAsFile(parameters, "NAME_RULES", context) or None,
        )
        # the written file, as styled layers in WGS84 (GUI runs load them into the project)
        adest = pdest = None
        if any(parameters.get(k) not in (None, "") for k in ("OUTPUT_AREAS", "OUTPUT_PASSAGES")):
            adest, pdest, _, _, _, _ = osmag_to_sinks(self, parameters, context, feedback, out,
                                                     QgsCoordinateReferenceSystem("EPSG:4326"),
                                                     "OUTPUT_AREAS", "OUTPUT_PASSAGES")
        timing = ", ".join(f"{k} {v:.2f} s" for k, v in stats["timings"].items())
        feedback.pushInfo(self.tr("Stage times: {}").format(timing))
        result = {"OUTPUT": out, "AREA_COUNT": stats["areas"], "PASSAGE_COUNT": stats["passages"],
                  "OUTPUT_AREAS": adest, "OUTPUT_PASSAGES": pdest}
        if preview:
            result["PREVIEW"] = preview
        return result
