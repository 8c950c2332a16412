"""cad2osmag:segment — Area Graph segmentation of an occupancy grid (stage 3)."""
import os

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsFeature,
    QgsFeatureSink,
    QgsField,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterNumber,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterRasterLayer,
    QgsWkbTypes,
)

from ..algorithms import segmentation
from ..algorithms.errors import InputError
from .alg_refine import area_fields, passage_fields
from .base import Cad2OsmagAlgorithm, FIELD_DOUBLE, FIELD_INT, make_fields, to_qgs

ROS_EXTENSIONS = (".yaml", ".yml")


def _area_fields():
    """The shared AREAS fields (see alg_refine) plus the perimeter segmentation reports."""
    fields = area_fields()
    fields.append(QgsField("perimeter_m", FIELD_DOUBLE))
    return fields


def _is_cad_raster(path):
    """True for an occupancy GeoTIFF written by cad2osmag (a rasterized CAD plan)."""
    if not str(path).lower().endswith((".tif", ".tiff")):
        return False
    from osgeo import gdal

    from ..algorithms.raster_io import OCCUPANCY_TAG

    ds = gdal.Open(str(path))
    return ds is not None and OCCUPANCY_TAG in (ds.GetMetadata() or {})


def _texts_and_doors(texts, doors):
    """Optional TEXTS (points with a 'text' field) and DOORS (lines) sources -> (inside points
    (n, 2) or None, list of DoorHint)."""
    import numpy as np

    from ..algorithms.model import CadText
    from .alg_rasterize import door_hints_of

    pts = None
    if texts is not None:
        names = texts.fields().names()
        field = "text" if "text" in names else (names[0] if names else None)
        cad = []
        for f in texts.getFeatures():
            g = f.geometry()
            if g is None or g.isEmpty():
                continue
            p = g.asPoint() if not g.isMultipart() else g.asMultiPoint()[0]
            txt = str(f[field]) if field is not None and f[field] is not None else ""
            cad.append(CadText(p.x(), p.y(), txt, 0.0, 0.0, ""))
        pts = segmentation.room_name_points(cad)
    return (None if pts is None else np.asarray(pts)), door_hints_of(doors)


class SegmentAlgorithm(Cad2OsmagAlgorithm):
    NAME = "segment"
    DISPLAY_NAME = "Segment occupancy grid into an Area Graph"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Area Graph segmentation (Hou et al. 2019) with the dynamic alpha of the CAD-to-osmAG method. "
            "INPUT is the output of 'Rasterize', or any occupancy grid: a GeoTIFF, a PNG/PGM image with "
            "RESOLUTION (m/px), or a ROS map.yaml (its resolution, origin, negate and thresholds are used; "
            "unknown cells are never free). Only the free space inside the building envelope is segmented: "
            "facade openings narrower than ENVELOPE_GAP are bridged, outside space is never an area; the "
            "log reports the interior area. alpha = ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / "
            "(4 r^2)) px^2 is the probe disk: spaces it sweeps through an opening are one room; door-sized "
            "narrowings that are clearly narrower than the space behind them separate rooms (this also "
            "finds rooms too narrow for the disk); corridor cells merge where nothing justifies a split; "
            "the free space is thinned to its skeleton (generalised Voronoi diagram), dead-end branches shorter "
            "than PRUNE are removed, and every skeleton edge (split at the narrowings) starts as one region. "
            "Outputs: AREAS (exact pixel-edge polygons: id, "
            "type room/corridor, area, perimeter, max clearance), PASSAGES (a segment across every "
            "opening between two areas, ends on the walls: from, to, width), LABELS (area ids on the "
            "input grid, 0 outside areas) and, when asked for, SKELETON (one line per skeleton edge: id, "
            "length, min and max clearance). Space open to the outside is still inside where there is evidence: "
            "the plan's footprint (openings up to 3 x ENVELOPE_GAP, closed at the chord between the facade wall "
            "ends, where it opens onto the interior through a doorway) and the optional TEXTS (room names, from "
            "'Extract structure': the space holding one is never outside). FOOTPRINT: by default the footprint is "
            "used for rasters made by 'Rasterize' (CAD plans), not for images and ROS maps (robot maps, whose free "
            "space beside the rooms is where the scan ended). The optional DOORS (jamb-to-jamb "
            "lines) are kept open and become passages where the segmentation missed them. Every area has a "
            "'component' field: its connected component in the area graph (0 = the largest); the log lists the "
            "others (rooms no passage reaches). STRUCTURE (optional): the structure lines of the drawing (WALLS of "
            "'Extract structure'); stair and lift symbols in them type their areas stairs/elevator. TOPOLOGY_CELL "
            "(0.088 m): the skeleton, regions and merges work on cells of about this size (the largest whole "
            "multiple of the raster's cell not above it; a cell is free only when all its pixels are, so walls "
            "never open), the outlines and passages are traced on the raster's own cells; 0 = everything on the "
            "raster's cells (about twice as slow on a 0.044 m CAD raster).\n"
            "Figures: AREA_COUNT, ROOM_COUNT, CORRIDOR_COUNT, PASSAGE_COUNT; INTERIOR_AREA_M2, the free area "
            "inside the building (m²); COMPONENTS and LARGEST_COMPONENT_SHARE (share of the area in the largest "
            "component); ALPHA, the probe disk in px²; SECONDS, the segmentation time.")

    INPUT = "INPUT"
    RESOLUTION = "RESOLUTION"
    DOOR_WIDTH = "DOOR_WIDTH"
    CORRIDOR_WIDTH = "CORRIDOR_WIDTH"
    DELTA = "DELTA"
    PRUNE = "PRUNE"
    TOPOLOGY_CELL = "TOPOLOGY_CELL"
    ENVELOPE_GAP = "ENVELOPE_GAP"
    AREAS = "AREAS"
    PASSAGES = "PASSAGES"
    LABELS = "LABELS"
    SKELETON = "SKELETON"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterRasterLayer(
            self.INPUT, self.tr("Occupancy grid (GeoTIFF, PNG/PGM, or ROS map.yaml)")))
        self.addParameter(QgsProcessingParameterNumber(
            self.RESOLUTION, self.tr("Resolution of a plain image (m/px; 0 = from the raster)"),
            QgsProcessingParameterNumber.Type.Double, 0.0, True, 0.0, 100.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.DOOR_WIDTH, self.tr("Widest door (m)"), QgsProcessingParameterNumber.Type.Double,
            segmentation.DEFAULT_DOOR_WIDTH, False, 0.01, 1000.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.CORRIDOR_WIDTH, self.tr("Narrowest corridor (m)"), QgsProcessingParameterNumber.Type.Double,
            segmentation.DEFAULT_CORRIDOR_WIDTH, False, 0.01, 1000.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.DELTA, self.tr("Delta δ added to the width (m)"), QgsProcessingParameterNumber.Type.Double,
            segmentation.DEFAULT_DELTA, False, 0.0, 100.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.PRUNE, self.tr("Prune Voronoi branches shorter than (m)"), QgsProcessingParameterNumber.Type.Double,
            segmentation.DEFAULT_PRUNE, False, 0.0, 100.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.ENVELOPE_GAP, self.tr("Bridge facade openings up to (m)"), QgsProcessingParameterNumber.Type.Double,
            segmentation.DEFAULT_ENVELOPE_GAP, False, 0.1, 1000.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.TOPOLOGY_CELL, self.tr("Cell size of the skeleton and merges (m; 0 = the raster's cells)"),
            QgsProcessingParameterNumber.Type.Double, segmentation.TOPOLOGY_RESOLUTION, True, 0.0, 10.0))
        self.addParameter(QgsProcessingParameterFeatureSource(
            "STRUCTURE", self.tr("Structure lines of the drawing (WALLS of 'Extract structure'), to recognise "
                                 "stairs and lifts"), [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterEnum(
            "FOOTPRINT", self.tr("Use the plan's footprint as evidence of inside space"),
            options=[self.tr("automatic (CAD rasters from 'Rasterize': yes; images and ROS maps: no)"),
                     self.tr("yes"), self.tr("no")], defaultValue=0))
        self.addParameter(QgsProcessingParameterFeatureSource(
            "TEXTS", self.tr("Room names (TEXTS of 'Extract structure'): evidence of inside space"),
            [QgsProcessing.SourceType.TypeVectorPoint], optional=True))
        self.addParameter(QgsProcessingParameterFeatureSource(
            "DOORS", self.tr("Doorways (jamb-to-jamb lines) kept open and made passages"),
            [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.AREAS, self.tr("Areas"), QgsProcessing.SourceType.TypeVectorPolygon))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.PASSAGES, self.tr("Passages"), QgsProcessing.SourceType.TypeVectorLine))
        self.addParameter(QgsProcessingParameterRasterDestination(self.LABELS, self.tr("Area id raster")))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.SKELETON, self.tr("Skeleton (Voronoi graph edges)"), QgsProcessing.SourceType.TypeVectorLine,
            optional=True, createByDefault=False))
        for name, label in (("AREA_COUNT", "Areas"), ("ROOM_COUNT", "Rooms"), ("CORRIDOR_COUNT", "Corridors"),
                            ("PASSAGE_COUNT", "Passages"), ("INTERIOR_AREA_M2", "Free area inside the building (m²)"),
                            ("COMPONENTS", "Connected components of the area graph"),
                            ("LARGEST_COMPONENT_SHARE", "Share of the area in the largest component"),
                            ("ALPHA", "alpha (px²)"), ("SECONDS", "Segmentation time (s)")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))

    def checkParameterValues(self, parameters, context):  # noqa: N802
        # a ROS map.yaml is not a raster QGIS can load: accept it here, read_grid checks it
        value = parameters.get(self.INPUT)
        if isinstance(value, str) and value.lower().endswith(ROS_EXTENSIONS):
            if not os.path.isfile(value):
                return False, self.tr("INPUT: '{}' does not exist").format(value)
            return True, ""
        return super().checkParameterValues(parameters, context)

    def _input_path(self, parameters, context):
        value = parameters.get(self.INPUT)
        if isinstance(value, str) and value.lower().endswith(ROS_EXTENSIONS):
            return value, None
        layer = self.parameterAsRasterLayer(parameters, self.INPUT, context)
        if layer is None:
            raise QgsProcessingException(self.tr("INPUT: the raster cannot be opened"))
        path = layer.source().split("|")[0]
        if not os.path.exists(path):
            raise QgsProcessingException(self.tr("INPUT: '{}' is not a raster file on disk").format(path))
        return path, layer

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        from ..algorithms.raster_io import read_grid, write_geotiff

        path, layer = self._input_path(parameters, context)
        res = self.parameterAsDouble(parameters, self.RESOLUTION, context)
        try:
            grid = read_grid(path, resolution=res if res > 0 else None)
        except InputError as exc:
            raise QgsProcessingException(str(exc))
        if res > 0 and path.lower().endswith((".tif", ".tiff")) and abs(grid.resolution - res) > 1e-9:
            feedback.pushInfo(self.tr("RESOLUTION ignored: the GeoTIFF carries {} m/px").format(grid.resolution))
        feedback.pushInfo(self.tr("Grid {} x {} px at {} m/px").format(grid.shape[1], grid.shape[0], grid.resolution))
        inside_points, door_hints = _texts_and_doors(self.parameterAsSource(parameters, "TEXTS", context),
                                                     self.parameterAsSource(parameters, "DOORS", context))
        if inside_points is not None:
            feedback.pushInfo(self.tr("{} room-name points used as evidence of inside space").format(len(inside_points)))
        choice = self.parameterAsEnum(parameters, "FOOTPRINT", context)
        footprint = choice == 1 or (choice == 0 and _is_cad_raster(path))
        feedback.pushInfo(self.tr("Footprint evidence: {}").format(self.tr("yes") if footprint else self.tr("no")))
        ag = self.call(feedback, segmentation.segment, grid, inside_points=inside_points, door_hints=door_hints,
                       footprint=footprint,
                       door_width=self.parameterAsDouble(parameters, self.DOOR_WIDTH, context),
                       corridor_width=self.parameterAsDouble(parameters, self.CORRIDOR_WIDTH, context),
                       delta=self.parameterAsDouble(parameters, self.DELTA, context),
                       prune=self.parameterAsDouble(parameters, self.PRUNE, context),
                       envelope_gap=self.parameterAsDouble(parameters, self.ENVELOPE_GAP, context),
                       topology_resolution=_topology_cell(self, parameters, context))
        structure = self.parameterAsSource(parameters, "STRUCTURE", context)
        if structure is not None:
            from ..algorithms.area_types import classify_vertical_areas
            from .alg_rasterize import features_to_geometries

            typed = classify_vertical_areas(ag.areas, features_to_geometries(structure, feedback))
            feedback.pushInfo(self.tr("{} stair/lift areas recognised from their symbols").format(len(typed)))
        st = ag.stats
        feedback.pushInfo(self.tr("Interior free area: {:.1f} m² (of {:.1f} m² free in the raster)").format(
            st["interior_area_m2"], st["free_area_m2"]))
        feedback.pushInfo(self.tr("Timing (s): ") + ", ".join(
            f"{k[:-2]} {v:.2f}" for k, v in st.items() if k.endswith("_s")))

        skeleton_lines, extra = None, {}
        if parameters.get(self.SKELETON) not in (None, "") and ag.skeleton is not None:
            skeleton_lines = ag.skeleton.edge_lines((ag.skeleton_grid or grid).geotransform)
        feedback.pushInfo(self.tr("Skeleton: {} nodes, {} edges, {} branches shorter than PRUNE pruned").format(
            int(st["skeleton_nodes"]), int(st["skeleton_edges"]), int(st["skeleton_pruned"])))

        # everything computed: now create the outputs
        if grid.crs_wkt:
            crs = QgsCoordinateReferenceSystem.fromWkt(grid.crs_wkt)
        elif layer is not None and layer.crs().isValid():
            crs = layer.crs()
        else:
            crs = QgsCoordinateReferenceSystem()
        labels_path = self.parameterAsOutputLayer(parameters, self.LABELS, context)
        if not labels_path.lower().endswith((".tif", ".tiff")):
            labels_path = os.path.splitext(labels_path)[0] + ".tif"
        afields, pfields = _area_fields(), passage_fields()
        sink_a, dest_a = self.parameterAsSink(parameters, self.AREAS, context, afields, QgsWkbTypes.Type.Polygon, crs)
        if sink_a is None:
            raise QgsProcessingException(self.invalidSinkError(parameters, self.AREAS))
        sink_p, dest_p = self.parameterAsSink(parameters, self.PASSAGES, context, pfields, QgsWkbTypes.Type.LineString,
                                              crs)
        if sink_p is None:
            raise QgsProcessingException(self.invalidSinkError(parameters, self.PASSAGES))
        for a in ag.areas:
            f = QgsFeature(afields)
            f.setGeometry(to_qgs(a.polygon))
            f["id"] = int(a.id)
            f["type"] = a.type
            f["name"] = a.name or None
            f["max_clearance"] = round(float(a.max_clearance), 4)
            f["area_m2"] = float(a.area)
            f["perimeter_m"] = float(a.perimeter)
            f["component"] = int(a.component)
            if not sink_a.addFeature(f, QgsFeatureSink.Flag.FastInsert):
                raise QgsProcessingException(self.tr("cannot write area {}").format(a.id))
        for p in ag.passages:
            f = QgsFeature(pfields)
            f.setGeometry(to_qgs(p.line))
            f["id"] = int(p.id)
            f["from_id"] = int(p.from_id)
            f["to_id"] = int(p.to_id)
            f["name"] = p.name or None
            f["width_m"] = float(p.width)
            if not sink_p.addFeature(f, QgsFeatureSink.Flag.FastInsert):
                raise QgsProcessingException(self.tr("cannot write passage {}").format(p.id))
        if skeleton_lines is not None:
            sfields = make_fields(("id", FIELD_INT), ("length_m", FIELD_DOUBLE), ("min_clearance_m", FIELD_DOUBLE),
                                  ("max_clearance_m", FIELD_DOUBLE))
            sink_s, dest_s = self.parameterAsSink(parameters, self.SKELETON, context, sfields,
                                                  QgsWkbTypes.Type.LineString, crs)
            if sink_s is not None:
                sk = ag.skeleton
                for j, line in enumerate(skeleton_lines):
                    f = QgsFeature(sfields)
                    f.setGeometry(to_qgs(line))
                    f["id"] = j + 1
                    f["length_m"] = round(float(sk.edge_length_m[j]), 4)
                    f["min_clearance_m"] = round(float(sk.edge_min_clearance_m[j]), 4)
                    f["max_clearance_m"] = round(float(sk.edge_max_clearance_m[j]), 4)
                    if not sink_s.addFeature(f, QgsFeatureSink.Flag.FastInsert):
                        raise QgsProcessingException(self.tr("cannot write skeleton edge {}").format(j + 1))
                extra[self.SKELETON] = dest_s
        write_geotiff(labels_path, ag.labels, grid.origin_x, grid.origin_y, grid.resolution,
                      crs.toWkt() if crs.isValid() else grid.crs_wkt, nodata=None)
        n_rooms = sum(a.type == "room" for a in ag.areas)
        feedback.pushInfo(self.tr("{} areas ({} rooms, {} corridors), {} passages").format(
            len(ag.areas), n_rooms, len(ag.areas) - n_rooms, len(ag.passages)))
        return {
            **extra,
            self.AREAS: dest_a,
            self.PASSAGES: dest_p,
            self.LABELS: labels_path,
            "AREA_COUNT": len(ag.areas),
            "ROOM_COUNT": n_rooms,
            "CORRIDOR_COUNT": sum(a.type == "corridor" for a in ag.areas),
            "PASSAGE_COUNT": len(ag.passages),
            "INTERIOR_AREA_M2": float(st["interior_area_m2"]),
            "COMPONENTS": int(st.get("components", 1)),
            "LARGEST_COMPONENT_SHARE": float(st.get("largest_component_share", 1.0)),
            "ALPHA": float(st["alpha_px2"]),
            "SECONDS": float(st["total_s"]),
        }


def _topology_cell(alg, parameters, context):
    """TOPOLOGY_CELL in metres, None (the default) when not given."""
    if parameters.get(alg.TOPOLOGY_CELL) in (None, ""):
        return None
    return alg.parameterAsDouble(parameters, alg.TOPOLOGY_CELL, context)
