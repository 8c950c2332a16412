"""cad2osmag:rasterize — structure lines -> occupancy GeoTIFF (0 free / 255 occupied)."""
import numpy as np
from qgis.core import (
    QgsProcessingParameterBoolean,
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterEnum,
    QgsProcessingParameterExtent,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterMultipleLayers,
    QgsProcessingParameterNumber,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterString,
    QgsWkbTypes,
)

from ..algorithms import rasterize as ras
from ..algorithms.errors import InputError
from ..algorithms.model import CadGeometry
from ..algorithms.raster_io import OCCUPANCY_METADATA, write_geotiff
from .base import Cad2OsmagAlgorithm


def _parts(geom):
    """QgsGeometry -> list of (N, 2) arrays, one per line part / polygon ring."""
    out = []
    if geom is None or geom.isNull() or geom.isEmpty():
        return out
    gtype = QgsWkbTypes.geometryType(geom.wkbType())
    if gtype == QgsWkbTypes.GeometryType.LineGeometry:
        lines = geom.asMultiPolyline() if geom.isMultipart() else [geom.asPolyline()]
        for ln in lines:
            if ln:
                out.append(np.array([(p.x(), p.y()) for p in ln], dtype=np.float64))
    elif gtype == QgsWkbTypes.GeometryType.PolygonGeometry:
        polys = geom.asMultiPolygon() if geom.isMultipart() else [geom.asPolygon()]
        for poly in polys:
            for ring in poly:
                if ring:
                    out.append(np.array([(p.x(), p.y()) for p in ring], dtype=np.float64))
    return out


def door_hints_of(source):
    """DOORS line source -> list of DoorHint (first to last vertex of each line)."""
    from ..algorithms.model import DoorHint

    hints = []
    if source is None:
        return hints
    for f in source.getFeatures():
        g = f.geometry()
        if g is None or g.isEmpty():
            continue
        line = g.asPolyline() if not g.isMultipart() else [v for part in g.asMultiPolyline() for v in part]
        if len(line) >= 2:
            hints.append(DoorHint(line[0].x(), line[0].y(), line[-1].x(), line[-1].y(), "layer"))
    return hints


def features_to_geometries(source, feedback=None, transform=None):
    """Rebuild CadGeometry from a WALLS-like layer (fields layer, kind, entity, closed, filled, width are
    used when present; polygons are filled)."""
    names = set(source.fields().names())
    geoms = []
    for feat in source.getFeatures():
        if feedback is not None and feedback.isCanceled():
            break
        g = feat.geometry()
        if transform is not None and g is not None and not g.isNull():
            g = type(g)(g)
            g.transform(transform)
        parts = _parts(g)
        if not parts:
            continue
        is_poly = QgsWkbTypes.geometryType(g.wkbType()) == QgsWkbTypes.GeometryType.PolygonGeometry

        def attr(name, default):
            if name not in names:
                return default
            v = feat[name]
            return default if v is None or (hasattr(v, "isNull") and v.isNull()) else v

        filled = bool(attr("filled", False)) or is_poly
        closed = bool(attr("closed", False)) or is_poly
        width = float(attr("width", 0.0) or 0.0)
        layer = str(attr("layer", ""))
        kind = str(attr("kind", "wall"))
        entity = str(attr("entity", ""))
        if filled and len(parts) > 1:
            sep = np.full((1, 2), np.nan)
            coords = np.concatenate([x for p in parts for x in (p, sep)][:-1], axis=0)
            geoms.append(CadGeometry(layer, kind, coords, closed, True, width, entity))
        else:
            for p in parts:
                geoms.append(CadGeometry(layer, kind, p, closed, filled, width, entity))
    return geoms


class RasterizeAlgorithm(Cad2OsmagAlgorithm):
    NAME = "rasterize"
    DISPLAY_NAME = "Rasterize structure"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Turns structure lines (the WALLS output of 'Extract structure from DXF/DWG', or any line/polygon "
            "layer in metres) into a single-band occupancy GeoTIFF: 0 = free, 255 = occupied (the inverse "
            "of a ROS map_server image, where black is occupied). Hairlines are drawn 0.15 m wide, wide "
            "polylines with their width, filled outlines (solid hatches) filled.\n"
            "The extent is the PERCENTILES (low, high) of all vertices grown to the entities that reach into "
            "them, plus PADDING (a fraction of the building size), so stray entities far away do not blow "
            "up the raster. The origin is snapped to a multiple of RESOLUTION and the geotransform maps "
            "pixels back to the drawing frame exactly.\n"
            "Repair: a closing with a KERNEL x KERNEL square bridges gaps up to about 0.2 m, then an opening "
            "removes isolated specks (components that do not survive the opening and are small). STROKE: the "
            "width in metres hairlines are drawn with (0.15 m).\n"
            "Multi-floor sets: give the structure layers of all floors as FLOOR_LAYERS (and/or a COMMON_EXTENT "
            "in the first floor's frame); every floor rasterized with the same values gets the same grid, "
            "pixel for pixel. Floors drawn with different origins (their extents do not overlap) are "
            "registered by cross-correlation (ALIGN_FLOORS); each raster's geotransform still maps its pixels "
            "onto its own drawing frame, so the origins differ by the floor offset but the pixels line up.\n"
            "A raster above MAX_MPX megapixels stops with an error that suggests a resolution.\n"
            "STAIRS_AS_OBSTACLES: draw stair and lift symbols as walls (off by default: stairs and lifts stay "
            "free space, so they become areas). DOORS (optional): doorway lines (jamb to jamb, the DOORS "
            "output of 'Extract structure') kept open even where a door layer is drawn.\n"
            "Outputs: OCCUPANCY, the GeoTIFF (in the drawing frame, metres); WIDTH and HEIGHT in pixels; "
            "OCCUPIED_SHARE, the share of occupied pixels (0-1).")

    WALLS = "WALLS"
    RESOLUTION = "RESOLUTION"
    PADDING = "PADDING"
    PERCENTILES = "PERCENTILES"
    KERNEL = "KERNEL"
    STROKE = "STROKE"
    MAX_MPX = "MAX_MPX"
    COMMON_EXTENT = "COMMON_EXTENT"
    FLOOR_LAYERS = "FLOOR_LAYERS"
    ALIGN_FLOORS = "ALIGN_FLOORS"
    OCCUPANCY = "OCCUPANCY"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.WALLS, self.tr("Structure lines"), [QgsProcessing.SourceType.TypeVectorLine, QgsProcessing.SourceType.TypeVectorPolygon]))
        self.addParameter(QgsProcessingParameterNumber(
            self.RESOLUTION, self.tr("Resolution (m/pixel)"), QgsProcessingParameterNumber.Type.Double,
            ras.DEFAULT_RESOLUTION, False, 0.001, 10.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.PADDING, self.tr("Padding (fraction of the building size)"), QgsProcessingParameterNumber.Type.Double,
            ras.DEFAULT_PADDING, False, 0.0, 1.0))
        self.addParameter(QgsProcessingParameterString(
            self.PERCENTILES, self.tr("Vertex percentiles for the extent (low, high)"), "0.5, 99.5"))
        self.addParameter(QgsProcessingParameterNumber(
            self.KERNEL, self.tr("Repair kernel (pixels, 0 = no repair)"), QgsProcessingParameterNumber.Type.Integer,
            ras.DEFAULT_KERNEL, False, 0, 51))
        self.addParameter(QgsProcessingParameterNumber(
            self.STROKE, self.tr("Width of hairlines (m)"), QgsProcessingParameterNumber.Type.Double,
            ras.DEFAULT_STROKE, False, 0.0, 5.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.MAX_MPX, self.tr("Pixel budget (megapixels)"), QgsProcessingParameterNumber.Type.Double,
            ras.DEFAULT_MAX_PIXELS / 1e6, False, 0.01, 2000.0))
        self.addParameter(QgsProcessingParameterExtent(
            self.COMMON_EXTENT, self.tr("Common extent for multi-floor sets (optional)"), optional=True))
        self.addParameter(QgsProcessingParameterMultipleLayers(
            self.FLOOR_LAYERS, self.tr("Structure layers of all floors: rasterize on their common extent (optional)"),
            QgsProcessing.SourceType.TypeVectorAnyGeometry, optional=True))
        self.addParameter(QgsProcessingParameterEnum(
            self.ALIGN_FLOORS, self.tr("Register the floors (translation) before building the common grid"),
            options=[self.tr("automatic (only when the floors do not overlap)"), self.tr("yes"), self.tr("no")],
            defaultValue=0))
        self.addParameter(QgsProcessingParameterBoolean(
            "STAIRS_AS_OBSTACLES", self.tr("Draw stair and lift symbols as obstacles"), False))
        self.addParameter(QgsProcessingParameterFeatureSource(
            "DOORS", self.tr("Doorways (jamb-to-jamb lines) kept open (optional)"),
            [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterRasterDestination(self.OCCUPANCY, self.tr("Occupancy raster")))
        self.addOutput(QgsProcessingOutputNumber("WIDTH", self.tr("Raster width (pixels)")))
        self.addOutput(QgsProcessingOutputNumber("HEIGHT", self.tr("Raster height (pixels)")))
        self.addOutput(QgsProcessingOutputNumber("OCCUPIED_SHARE", self.tr("Share of occupied pixels")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        source = self.parameterAsSource(parameters, self.WALLS, context)
        if source is None:
            raise QgsProcessingException(self.tr("The structure layer (WALLS) could not be loaded."))
        res = self.parameterAsDouble(parameters, self.RESOLUTION, context)
        padding = self.parameterAsDouble(parameters, self.PADDING, context)
        kernel = self.parameterAsInt(parameters, self.KERNEL, context)
        stroke = self.parameterAsDouble(parameters, self.STROKE, context)
        max_px = self.parameterAsDouble(parameters, self.MAX_MPX, context) * 1e6
        pct_txt = self.parameterAsString(parameters, self.PERCENTILES, context)
        try:
            pct = tuple(float(v) for v in pct_txt.replace(";", ",").replace("/", ",").split(","))
            if len(pct) != 2:
                raise ValueError
        except ValueError:
            raise QgsProcessingException(self.tr(
                "PERCENTILES must be two numbers such as '0.5, 99.5', got '{}'").format(pct_txt))
        crs = source.sourceCrs()
        if crs.isValid() and crs.isGeographic():
            raise QgsProcessingException(self.tr(
                "The structure layer is in a geographic CRS ({}); rasterize needs metres: use the WALLS output "
                "of 'Extract structure from DXF/DWG' or reproject to a projected CRS first.").format(crs.authid()))

        geoms = features_to_geometries(source, feedback)
        extent = None
        if parameters.get(self.COMMON_EXTENT):
            rect = self.parameterAsExtent(parameters, self.COMMON_EXTENT, context, crs)
            if not rect.isNull() and rect.width() > 0 and rect.height() > 0:
                extent = (rect.xMinimum(), rect.yMinimum(), rect.xMaximum(), rect.yMaximum())
        floor_layers = self.parameterAsLayerList(parameters, self.FLOOR_LAYERS, context) or []
        align = [None, True, False][self.parameterAsEnum(parameters, self.ALIGN_FLOORS, context)]
        if floor_layers:
            sets = []
            for lyr in floor_layers:
                tr = None
                if crs.isValid() and lyr.crs().isValid() and lyr.crs() != crs:
                    tr = QgsCoordinateTransform(lyr.crs(), crs, context.transformContext())
                g = features_to_geometries(lyr, feedback, tr)
                if g:
                    sets.append(g)
            if sets:
                # this floor goes last: its offset comes out of the same registration as the others'
                common, offs = self.call(feedback, ras.common_grid, sets + [geoms], res, padding, pct, kernel,
                                         max_px, stroke, align, extent)
                offset = offs[-1]
                if offset != (0.0, 0.0):
                    feedback.pushInfo(self.tr("This floor is offset by ({:.3f}, {:.3f}) m from the first floor "
                                              "layer").format(*offset))
                extent = ras.floor_extent(common, offset)
        grid = self.call(feedback, ras.rasterize, geoms, resolution=res, padding=padding, percentiles=pct,
                         kernel=kernel, extent=extent, max_pixels=max_px, stroke=stroke,
                         free_kinds=() if self.parameterAsBool(parameters, "STAIRS_AS_OBSTACLES", context)
                         else ras.DEFAULT_FREE_KINDS, door_hints=door_hints_of(
                             self.parameterAsSource(parameters, "DOORS", context)))
        out = self.parameterAsOutputLayer(parameters, self.OCCUPANCY, context)
        wkt = crs.toWkt(QgsCoordinateReferenceSystem.WktVariant.WKT_PREFERRED_GDAL) if crs.isValid() else ""
        try:
            write_geotiff(out, grid.data, grid.origin_x, grid.origin_y, grid.resolution, wkt,
                          metadata=OCCUPANCY_METADATA)
        except (InputError, RuntimeError) as exc:
            raise QgsProcessingException(self.tr("Cannot write the raster '{}': {}").format(out, exc))
        rows, cols = grid.shape
        share = float((grid.data > 0).mean())
        feedback.pushInfo(self.tr("{} x {} px at {} m/px, origin ({:.3f}, {:.3f}), {:.1%} occupied").format(
            cols, rows, grid.resolution, grid.origin_x, grid.origin_y, share))
        return {self.OCCUPANCY: out, "WIDTH": cols, "HEIGHT": rows, "OCCUPIED_SHARE": share}


