"""cad2osmag:georeference — place CAD-frame layers on the Earth (stage 6)."""
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsCsException,
    QgsFeature,
    QgsFeatureSink,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterCrs,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterNumber,
    QgsProcessingParameterPoint,
    QgsProject,
)

from ..algorithms.rasterize import is_local_frame
from .base import Cad2OsmagAlgorithm, from_qgs, to_qgs, tr_common

GCP_CAD_X = ("cad_x", "x_cad", "cadx", "sourceX", "source_x", "src_x")
GCP_CAD_Y = ("cad_y", "y_cad", "cady", "sourceY", "source_y", "src_y")


def qgs_crs_to_pyproj(crs):
    """QgsCoordinateReferenceSystem -> something pyproj accepts (authid when known, else WKT)."""
    auth = crs.authid()
    if auth and ":" in auth and not auth.upper().startswith("USER"):
        return auth
    return crs.toWkt(QgsCoordinateReferenceSystem.WktVariant.WKT_PREFERRED) if hasattr(
        QgsCoordinateReferenceSystem, "WKT_PREFERRED") else crs.toWkt()


GCP_RMS_WARNING_M = 0.5  # a fit worse than this is worth a look: a point picked in the wrong place
GCP_SCALE_WARNING = 0.02  # a correct drawing in metres has scale 1; 2 % points at units or bad points


def is_cad_frame(crs):
    """True when a layer is in the CAD frame: no CRS, the local engineering CRS this plugin gives its
    CAD-frame layers ("CAD drawing frame (local, metres)", any local/engineering CRS), or the placeholder
    GeoPackage writes for layers without one ("Undefined geographic SRS" / "Undefined Cartesian SRS")."""
    if crs is None or not crs.isValid():
        return True
    if crs.authid():
        return False
    wkt = crs.toWkt()
    if is_local_frame(wkt) or is_local_frame(crs.toWkt(QgsCoordinateReferenceSystem.WktVariant.WKT_PREFERRED)):
        return True
    text = (crs.description() + " " + wkt).lower()
    return "undefined geographic srs" in text or "undefined cartesian srs" in text


def point_to_lonlat(point, point_crs, context):
    """QgsPointXY in ``point_crs`` -> (lon, lat) in WGS84."""
    wgs = QgsCoordinateReferenceSystem("EPSG:4326")
    if point_crs is None or not point_crs.isValid():
        point_crs = wgs
    if point_crs != wgs:
        tr = QgsCoordinateTransform(point_crs, wgs, context.transformContext() if context else QgsProject.instance())
        try:
            point = tr.transform(point)
        except QgsCsException as exc:
            raise QgsProcessingException(tr_common("the point {}, {} [{}] cannot be converted to "
                                                   "longitude/latitude: {}").format(point.x(), point.y(),
                                                                                    point_crs.authid(), exc))
    return float(point.x()), float(point.y())


class GeoreferenceAlgorithm(Cad2OsmagAlgorithm):
    NAME = "georeference"
    DISPLAY_NAME = "Georeference (place the plan on the map)"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Transforms layers drawn in the CAD frame (metres, no CRS) into a target CRS (default WGS84).\n"
            "Mode 'Anchor': pick ANCHOR on the map canvas (any CRS) for the CAD point CAD_ANCHOR_X/Y "
            "(default the drawing origin); ROTATION is the direction of the plan's +y axis in degrees "
            "clockwise from north, or give ROTATION_POINT (a second map point) for the CAD point "
            "CAD_ROTATION_X/Y and the rotation is computed from the two picked points; SCALE is ground "
            "metres per CAD metre.\n"
            "Mode 'Control points': GCPS is a point layer whose geometry is each point picked against a "
            "basemap and whose fields cad_x, cad_y (or sourceX, sourceY) hold its CAD coordinates; at least "
            "2 points, not all on one line. A least-squares similarity (Helmert) is solved and the "
            "residual of every point and their RMS are reported in metres.\n"
            "FIX_SCALE keeps SCALE during the fit (solves position and rotation only).\n"
            "AREAS and PASSAGES: layers in the CAD frame (metres, no CRS), e.g. the outputs of 'Refine'; "
            "OUTPUT_AREAS and OUTPUT_PASSAGES get them in TARGET_CRS (default WGS84, EPSG:4326) with all "
            "their fields. MODE chooses 'Anchor point + rotation' or 'Control points'. CAD_ANCHOR_X / "
            "CAD_ANCHOR_Y and CAD_ROTATION_X / CAD_ROTATION_Y are CAD coordinates in metres.\n"
            "All conversions go through a transverse Mercator projection centred on the anchor (pyproj/PROJ), "
            "never a flat-earth approximation. Add a basemap (Vector ▸ CAD to osmAG ▸ Add … basemap) to pick "
            "points against real imagery, or drag the plan into place with Vector ▸ CAD to osmAG ▸ Place a floor "
            "plan on the map, whose placement gives ANCHOR, ROTATION and SCALE.\n"
            "Outputs: RMS and RESIDUALS, the control point residuals in metres (overall and per point); FRAME, "
            "the placement as text; ANCHOR_LON and ANCHOR_LAT (degrees), ROTATION_DEG (degrees clockwise from "
            "north) and SCALE_FACTOR of the placement, to reuse for the other floors.")

    AREAS = "AREAS"
    PASSAGES = "PASSAGES"
    MODE = "MODE"
    ANCHOR = "ANCHOR"
    CAD_ANCHOR_X = "CAD_ANCHOR_X"
    CAD_ANCHOR_Y = "CAD_ANCHOR_Y"
    ROTATION = "ROTATION"
    ROTATION_POINT = "ROTATION_POINT"
    CAD_ROTATION_X = "CAD_ROTATION_X"
    CAD_ROTATION_Y = "CAD_ROTATION_Y"
    SCALE = "SCALE"
    GCPS = "GCPS"
    FIX_SCALE = "FIX_SCALE"
    TARGET_CRS = "TARGET_CRS"
    OUTPUT_AREAS = "OUTPUT_AREAS"
    OUTPUT_PASSAGES = "OUTPUT_PASSAGES"
    MODES = ["Anchor point + rotation", "Control points (least squares)"]

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.AREAS, self.tr("Layer in the CAD frame (areas or any)"), [QgsProcessing.SourceType.TypeVectorAnyGeometry]))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.PASSAGES, self.tr("Second layer in the CAD frame (passages)"),
            [QgsProcessing.SourceType.TypeVectorAnyGeometry], optional=True))
        self.addParameter(QgsProcessingParameterEnum(
            self.MODE, self.tr("Mode"), [self.tr(m) for m in self.MODES], defaultValue=0))
        self.addParameter(QgsProcessingParameterPoint(
            self.ANCHOR, self.tr("Anchor: where the CAD anchor point lies on the map"), optional=True))
        self.addParameter(QgsProcessingParameterNumber(
            self.CAD_ANCHOR_X, self.tr("CAD anchor point x (m)"), QgsProcessingParameterNumber.Type.Double, 0.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.CAD_ANCHOR_Y, self.tr("CAD anchor point y (m)"), QgsProcessingParameterNumber.Type.Double, 0.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.ROTATION, self.tr("Rotation of the plan's +y axis (degrees clockwise from north)"),
            QgsProcessingParameterNumber.Type.Double, 0.0, False, -360.0, 360.0))
        self.addParameter(QgsProcessingParameterPoint(
            self.ROTATION_POINT, self.tr("Or: second map point (defines the rotation)"), optional=True))
        self.addParameter(QgsProcessingParameterNumber(
            self.CAD_ROTATION_X, self.tr("CAD x of the second point (m)"), QgsProcessingParameterNumber.Type.Double,
            0.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.CAD_ROTATION_Y, self.tr("CAD y of the second point (m)"), QgsProcessingParameterNumber.Type.Double,
            10.0))
        self.addParameter(QgsProcessingParameterNumber(
            self.SCALE, self.tr("Scale (ground metres per CAD metre)"), QgsProcessingParameterNumber.Type.Double,
            1.0, False, 1e-6, 1e6))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.GCPS, self.tr("Control points (fields cad_x, cad_y)"), [QgsProcessing.SourceType.TypeVectorPoint],
            optional=True))
        self.addParameter(QgsProcessingParameterBoolean(
            self.FIX_SCALE, self.tr("Control points: keep the scale at SCALE (solve rotation and shift only)"),
            False))
        self.addParameter(QgsProcessingParameterCrs(self.TARGET_CRS, self.tr("Target CRS"), "EPSG:4326", optional=True))
        self.addParameter(QgsProcessingParameterFeatureSink(self.OUTPUT_AREAS, self.tr("Georeferenced layer")))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_PASSAGES, self.tr("Georeferenced second layer"), optional=True))
        self.addOutput(QgsProcessingOutputNumber("RMS", self.tr("RMS of control point residuals (m)")))
        self.addOutput(QgsProcessingOutputString("RESIDUALS", self.tr("Residual per control point (m)")))
        self.addOutput(QgsProcessingOutputString("FRAME", self.tr("Anchor, rotation, scale of the placement")))
        self.addOutput(QgsProcessingOutputNumber("ANCHOR_LON", self.tr("Anchor longitude")))
        self.addOutput(QgsProcessingOutputNumber("ANCHOR_LAT", self.tr("Anchor latitude")))
        self.addOutput(QgsProcessingOutputNumber("ROTATION_DEG", self.tr("Rotation (deg)")))
        self.addOutput(QgsProcessingOutputNumber("SCALE_FACTOR", self.tr("Scale")))

    # ------------------------------------------------------------------------------------------
    def _frame(self, parameters, context, feedback):
        from ..algorithms.georef import LocalFrame, fit_gcps, rotation_from_two_points

        mode = self.parameterAsEnum(parameters, self.MODE, context)
        scale = self.parameterAsDouble(parameters, self.SCALE, context)
        rms, residuals = 0.0, ""
        if mode == 1:
            gsrc = self.parameterAsSource(parameters, self.GCPS, context)
            if gsrc is None:
                raise QgsProcessingException(self.tr("Mode 'Control points' needs the GCPS point layer"))
            names = gsrc.fields().names()
            fx = next((n for n in GCP_CAD_X if n in names), None)
            fy = next((n for n in GCP_CAD_Y if n in names), None)
            if fx is None or fy is None:
                raise QgsProcessingException(self.tr(
                    "GCPS needs fields with the CAD coordinates of each point: cad_x and cad_y (found: {})"
                ).format(", ".join(names)))
            idf = next((n for n in ("id", "name", "gcp") if n in names), None)
            cad, world, ids = [], [], []
            for f in gsrc.getFeatures():
                gid = str(f[idf]) if idf else str(f.id())
                g = f.geometry()
                if g is None or g.isNull() or g.isEmpty():
                    raise QgsProcessingException(self.tr("control point {} has no geometry").format(gid))
                p = g.asPoint() if not g.isMultipart() else g.asMultiPoint()[0]
                try:
                    cx, cy = float(f[fx]), float(f[fy])
                except (TypeError, ValueError):
                    raise QgsProcessingException(self.tr("control point {} has no numeric {} / {}").format(
                        gid, fx, fy))
                cad.append((cx, cy))
                world.append((p.x(), p.y()))
                ids.append(gid)
            gcrs = gsrc.sourceCrs()
            if is_cad_frame(gcrs):
                raise QgsProcessingException(self.tr("GCPS has no CRS: its points must be picked on a map"))
            fixed = scale if self.parameterAsBool(parameters, self.FIX_SCALE, context) else None
            frame, res, rms = self._guard(fit_gcps, cad, world, qgs_crs_to_pyproj(gcrs), ids=ids,
                                          fixed_scale=fixed)
            for gid, r in zip(ids, res):
                feedback.pushInfo(self.tr("control point {}: residual {:.4f} m").format(gid, float(r)))
            feedback.pushInfo(self.tr("RMS of residuals: {:.4f} m ({} points)").format(rms, len(ids)))
            worst = max(range(len(ids)), key=lambda i: float(res[i])) if len(ids) else None
            if rms > GCP_RMS_WARNING_M and worst is not None:
                feedback.pushWarning(self.tr(
                    "The control points do not fit a similarity transform well (RMS {:.2f} m, worst point {} off by "
                    "{:.2f} m): check that each point's CAD x/y match where it was picked").format(
                        rms, ids[worst], float(res[worst])))
            if fixed is None and abs(frame.scale - 1.0) > GCP_SCALE_WARNING:
                feedback.pushWarning(self.tr(
                    "The fitted scale is {:.4f} (the plan would be stretched by {:+.1%}): check the drawing units "
                    "or the control points, or set FIX_SCALE").format(frame.scale, frame.scale - 1.0))
            residuals = "; ".join(f"{gid}={float(r):.4f}" for gid, r in zip(ids, res))
        else:
            anchor_crs = self.parameterAsPointCrs(parameters, self.ANCHOR, context)
            if parameters.get(self.ANCHOR) in (None, ""):
                raise QgsProcessingException(self.tr(
                    "Mode 'Anchor' needs ANCHOR: pick the point on the map canvas where the CAD anchor point lies"))
            pt = self.parameterAsPoint(parameters, self.ANCHOR, context, anchor_crs)
            lon, lat = point_to_lonlat(pt, anchor_crs, context)
            cad_anchor = (self.parameterAsDouble(parameters, self.CAD_ANCHOR_X, context),
                          self.parameterAsDouble(parameters, self.CAD_ANCHOR_Y, context))
            rot = self.parameterAsDouble(parameters, self.ROTATION, context)
            if parameters.get(self.ROTATION_POINT) not in (None, ""):
                rcrs = self.parameterAsPointCrs(parameters, self.ROTATION_POINT, context)
                rp = self.parameterAsPoint(parameters, self.ROTATION_POINT, context, rcrs)
                rlon, rlat = point_to_lonlat(rp, rcrs, context)
                cad_rot = (self.parameterAsDouble(parameters, self.CAD_ROTATION_X, context),
                           self.parameterAsDouble(parameters, self.CAD_ROTATION_Y, context))
                rot = self._guard(rotation_from_two_points, (lon, lat), (rlon, rlat), cad_anchor, cad_rot)
                feedback.pushInfo(self.tr("rotation from the two picked points: {:.4f} degrees").format(rot))
            frame = self._guard(LocalFrame, lon, lat, rot, scale, cad_anchor)
        return frame, rms, residuals

    @staticmethod
    def _guard(func, *args, **kwargs):
        """Call a georef function, turning InputError into QgsProcessingException."""
        from ..algorithms.errors import InputError

        try:
            return func(*args, **kwargs)
        except InputError as exc:
            raise QgsProcessingException(str(exc))

    def _transform(self, source, frame, target, feedback, what):
        from ..algorithms.errors import InputError

        crs = source.sourceCrs()
        if not is_cad_frame(crs):
            raise QgsProcessingException(self.tr(
                "{} is already georeferenced ({}); this algorithm places layers in the CAD frame (the outputs of "
                "the segment and refine algorithms). Use 'Reproject layer' to change the CRS of a placed layer."
            ).format(what, crs.authid() or crs.description()))
        feats = []
        total = max(source.featureCount(), 1)
        for i, f in enumerate(source.getFeatures()):
            if feedback.isCanceled():
                raise QgsProcessingException(self.tr("Canceled by the user."))
            g = from_qgs(f.geometry())
            out = QgsFeature(f)
            if g is not None:
                try:
                    out.setGeometry(to_qgs(frame.geometry_to_crs(g, target)))
                except InputError as exc:
                    raise QgsProcessingException(self.tr("{} feature {}: {}").format(what, f.id(), exc))
            feats.append(out)
            feedback.setProgress(100.0 * (i + 1) / total)
        return feats

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        src = self.parameterAsSource(parameters, self.AREAS, context)
        if src is None:
            raise QgsProcessingException(self.tr("AREAS: the input layer cannot be opened"))
        psrc = self.parameterAsSource(parameters, self.PASSAGES, context)
        tcrs = self.parameterAsCrs(parameters, self.TARGET_CRS, context)
        if not tcrs.isValid():  # not given (qgis_process does not apply CRS defaults): WGS84
            tcrs = QgsCoordinateReferenceSystem("EPSG:4326")
        frame, rms, residuals = self._frame(parameters, context, feedback)
        feedback.pushInfo(self.tr("placement: {}").format(repr(frame)))
        target = qgs_crs_to_pyproj(tcrs)
        feats = self._transform(src, frame, target, feedback, "AREAS")
        pfeats = self._transform(psrc, frame, target, feedback, "PASSAGES") if psrc is not None else None
        # everything computed: create the outputs
        sink, dest = self.parameterAsSink(parameters, self.OUTPUT_AREAS, context, src.fields(), src.wkbType(), tcrs)
        for f in feats:
            sink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        result = {self.OUTPUT_AREAS: dest}
        if pfeats is not None:
            psink, pdest = self.parameterAsSink(parameters, self.OUTPUT_PASSAGES, context, psrc.fields(),
                                                psrc.wkbType(), tcrs)
            if psink is not None:
                for f in pfeats:
                    psink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
                result[self.OUTPUT_PASSAGES] = pdest
        result.update({"RMS": rms, "RESIDUALS": residuals, "FRAME": repr(frame),
                       "ANCHOR_LON": frame.anchor_lon, "ANCHOR_LAT": frame.anchor_lat,
                       "ROTATION_DEG": frame.rotation_deg, "SCALE_FACTOR": frame.scale})
        return result
