"""cad2osmag:route — shortest route for a robot over an osmAG map (stage 9)."""
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsFeature,
    QgsFeatureSink,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterFile,
    QgsProcessingParameterNumber,
    QgsProcessingParameterPoint,
    QgsProcessingParameterString,
    QgsProject,
    QgsWkbTypes,
)

from ..algorithms import routing
from .alg_georeference import is_cad_frame
from .alg_refine import read_areas, read_passages
from .base import Cad2OsmagAlgorithm, FIELD_DOUBLE, FIELD_INT, FIELD_STRING, make_fields, to_qgs

AVOID_CHOICES = [("none", "nothing"), ("stairs", "stairs (wheelchairs, wheeled robots: lifts only)"),
                 ("elevator", "lifts (evacuation: stairs only)")]
WGS84 = "EPSG:4326"


class RouteAlgorithm(Cad2OsmagAlgorithm):
    NAME = "route"
    DISPLAY_NAME = "Plan a route on an osmAG map"
    GROUP = "Tools"
    GROUP_ID = "tools"
    HELP = ("Shortest route for a round robot of radius ROBOT_RADIUS (metres) over an osmAG map: INPUT, an osmAG file (ours or "
            "any other tool's, semantic or fix-id) or AREAS/PASSAGES layers (e.g. from loadosmag or refine). "
            "START and END are points picked on the canvas (any CRS) with their level (START_LEVEL/END_LEVEL, "
            "needed when floors overlap), or area names (START_NAME/END_NAME). A point up to 1 m outside the "
            "robot's free space is moved into it; farther away is an error. Passages narrower than twice the "
            "radius are closed; inside every area the route is the shortest collision-free path around its "
            "walls. Vertical passages (stairs, lifts) cost VERTICAL_COST metres per level; AVOID leaves out "
            "stairs (lifts only) or lifts and keeps the robot its radius away from them: their doorways are "
            "walls for it (a START or END inside such an area still leaves through its door). The result is a 3-D line (z = level x height) with its length, cost, "
            "levels per vertex and the areas and passages crossed. When no route exists the message names the "
            "separate parts of the map the start and the goal lie in, and the passages too narrow for the robot.\n"
            "Outputs: OUTPUT, the route line; LENGTH (m) and COST (length + vertical cost, m); LEVEL_CHANGES; "
            "START_SNAP and END_SNAP, how far the start and end were moved (m); QUERY_MS, the search time in "
            "milliseconds; AREAS_CROSSED, PASSAGES_CROSSED and LEVELS (the level of every vertex).")

    INPUT = "INPUT"
    AREAS = "AREAS"
    PASSAGES = "PASSAGES"
    START = "START"
    START_LEVEL = "START_LEVEL"
    START_NAME = "START_NAME"
    END = "END"
    END_LEVEL = "END_LEVEL"
    END_NAME = "END_NAME"
    ROBOT_RADIUS = "ROBOT_RADIUS"
    AVOID = "AVOID"
    VERTICAL_COST = "VERTICAL_COST"
    OUTPUT = "OUTPUT"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFile(self.INPUT, self.tr("osmAG file (or give AREAS and PASSAGES)"),
                                                     extension="osm", optional=True))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.AREAS, self.tr("Areas layer (instead of the file)"), [QgsProcessing.SourceType.TypeVectorPolygon],
            optional=True))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.PASSAGES, self.tr("Passages layer"), [QgsProcessing.SourceType.TypeVectorLine], optional=True))
        self.addParameter(QgsProcessingParameterPoint(self.START, self.tr("Start point"), optional=True))
        self.addParameter(QgsProcessingParameterString(self.START_LEVEL, self.tr("Start level"), "", optional=True))
        self.addParameter(QgsProcessingParameterString(self.START_NAME, self.tr("Start area name (instead of a point)"),
                                                       "", optional=True))
        self.addParameter(QgsProcessingParameterPoint(self.END, self.tr("End point"), optional=True))
        self.addParameter(QgsProcessingParameterString(self.END_LEVEL, self.tr("End level"), "", optional=True))
        self.addParameter(QgsProcessingParameterString(self.END_NAME, self.tr("End area name (instead of a point)"),
                                                       "", optional=True))
        self.addParameter(QgsProcessingParameterNumber(
            self.ROBOT_RADIUS, self.tr("Robot radius (m)"), QgsProcessingParameterNumber.Type.Double,
            routing.DEFAULT_ROBOT_RADIUS, False, 0.0, 5.0))
        self.addParameter(QgsProcessingParameterEnum(
            self.AVOID, self.tr("Avoid"), [self.tr(label) for _, label in AVOID_CHOICES], defaultValue=0))
        self.addParameter(QgsProcessingParameterNumber(
            self.VERTICAL_COST, self.tr("Cost of one level of stairs or lift (m)"),
            QgsProcessingParameterNumber.Type.Double, routing.DEFAULT_VERTICAL_COST, False, 0.0, 1e6))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT, self.tr("Route"), QgsProcessing.SourceType.TypeVectorLine))
        for name, label in (("LENGTH", "Route length (m)"), ("COST", "Route cost (length + vertical cost)"),
                            ("LEVEL_CHANGES", "Level changes"), ("START_SNAP", "Start moved by (m)"),
                            ("END_SNAP", "End moved by (m)"), ("QUERY_MS", "Search time (ms)")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))
        for name, label in (("AREAS_CROSSED", "Areas crossed"), ("PASSAGES_CROSSED", "Passages crossed"),
                            ("LEVELS", "Level of every vertex")):
            self.addOutput(QgsProcessingOutputString(name, self.tr(label)))

    # ------------------------------------------------------------------------------------------
    def _load(self, parameters, context, feedback):
        """(RouteMap, output CRS, map->output converter, output CRS->map converter)."""
        from ..algorithms.georef import LocalFrame

        path = self.parameterAsFile(parameters, self.INPUT, context)
        src = self.parameterAsSource(parameters, self.AREAS, context)
        if path:
            rm = self.call(feedback, routing.RouteMap.from_osmag, path)
            frame = rm.frame
            out_crs = QgsCoordinateReferenceSystem(WGS84)

            def to_out(x, y):
                return frame.to_wgs84(x, y)

            def from_out(x, y):
                return frame.from_wgs84(x, y)

            return rm, out_crs, to_out, from_out
        if src is None:
            raise QgsProcessingException(self.tr("give an osmAG file (INPUT) or an AREAS layer (with PASSAGES)"))
        psrc = self.parameterAsSource(parameters, self.PASSAGES, context)
        crs = src.sourceCrs()
        if psrc is not None and psrc.sourceCrs() != crs:
            raise QgsProcessingException(self.tr("PASSAGES is in {} but AREAS is in {}; reproject it first").format(
                psrc.sourceCrs().authid() or "no CRS", crs.authid() or "no CRS"))
        areas = read_areas(src)
        passages = read_passages(psrc, areas) if psrc is not None else []
        if not is_cad_frame(crs) and crs.isGeographic():
            # plan in metres: a local transverse Mercator frame at the layer's centre
            from ..algorithms.georef import transform_geometry
            from .alg_georeference import qgs_crs_to_pyproj

            pcrs = qgs_crs_to_pyproj(crs)
            for a in areas:
                a.polygon = transform_geometry(a.polygon, pcrs, WGS84)
            for p in passages:
                p.line = transform_geometry(p.line, pcrs, WGS84)
            b = [a.polygon.bounds for a in areas]
            frame = LocalFrame(0.5 * (min(x[0] for x in b) + max(x[2] for x in b)),
                               0.5 * (min(x[1] for x in b) + max(x[3] for x in b)))
            for a in areas:
                a.polygon = frame.geometry_from_crs(a.polygon)
            for p in passages:
                p.line = frame.geometry_from_crs(p.line)
            back = QgsCoordinateTransform(QgsCoordinateReferenceSystem(WGS84), crs, QgsProject.instance())
            fwd = QgsCoordinateTransform(crs, QgsCoordinateReferenceSystem(WGS84), QgsProject.instance())

            def to_out(x, y):
                lon, lat = frame.to_wgs84(x, y)
                pts = [back.transform(float(u), float(v)) for u, v in zip(lon, lat)]
                return [p.x() for p in pts], [p.y() for p in pts]

            def from_out(x, y):
                p = fwd.transform(float(x), float(y))
                return frame.from_wgs84(p.x(), p.y())
        else:
            def to_out(x, y):
                return x, y

            def from_out(x, y):
                return x, y
        rm = self.call(feedback, routing.RouteMap, areas, passages)
        return rm, crs, to_out, from_out

    def _end(self, parameters, context, key, level_key, name_key, out_crs, from_out):
        name = (self.parameterAsString(parameters, name_key, context) or "").strip()
        level = (self.parameterAsString(parameters, level_key, context) or "").strip() or None
        if name:
            return name, level
        if parameters.get(key) in (None, ""):
            raise QgsProcessingException(self.tr("{}: give a point or an area name ({})").format(key, name_key))
        pt = self.parameterAsPoint(parameters, key, context, out_crs)
        x, y = from_out(pt.x(), pt.y())
        return (float(x), float(y)), level

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        from shapely.geometry import LineString

        rm, out_crs, to_out, from_out = self._load(parameters, context, feedback)
        start, slev = self._end(parameters, context, self.START, self.START_LEVEL, self.START_NAME, out_crs, from_out)
        goal, glev = self._end(parameters, context, self.END, self.END_LEVEL, self.END_NAME, out_crs, from_out)
        radius = self.parameterAsDouble(parameters, self.ROBOT_RADIUS, context)
        avoid = AVOID_CHOICES[self.parameterAsEnum(parameters, self.AVOID, context)][0]
        vcost = self.parameterAsDouble(parameters, self.VERTICAL_COST, context)
        res = self.call(feedback, rm.route, start, goal, start_level=slev, goal_level=glev, robot_radius=radius,
                        avoid=[] if avoid == "none" else [avoid], vertical_cost=vcost)
        for w in res.warnings:
            feedback.pushWarning(w)
        xs, ys = to_out(res.points[:, 0], res.points[:, 1])
        line = LineString([(float(x), float(y), float(z)) for x, y, z in zip(xs, ys, res.z)])
        fields = make_fields(("length_m", FIELD_DOUBLE), ("cost", FIELD_DOUBLE), ("level_from", FIELD_STRING),
                             ("level_to", FIELD_STRING), ("level_changes", FIELD_INT), ("levels", FIELD_STRING),
                             ("areas", FIELD_STRING), ("passages", FIELD_STRING), ("robot_radius", FIELD_DOUBLE),
                             ("avoid", FIELD_STRING))
        sink, dest = self.parameterAsSink(parameters, self.OUTPUT, context, fields, QgsWkbTypes.Type.LineStringZ,
                                          out_crs)
        if sink is None:
            raise QgsProcessingException(self.invalidSinkError(parameters, self.OUTPUT))
        f = QgsFeature(fields)
        f.setGeometry(to_qgs(line))
        levels = ",".join(res.levels)
        vals = {"length_m": round(res.length, 3), "cost": round(res.cost, 3), "level_from": res.levels[0],
                "level_to": res.levels[-1], "level_changes": res.level_changes, "levels": levels,
                "areas": " > ".join(res.areas), "passages": " > ".join(res.passages), "robot_radius": radius,
                "avoid": avoid}
        for k, v in vals.items():
            f[k] = v
        sink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
        feedback.pushInfo(self.tr("route: {:.2f} m ({} level changes) through {}").format(
            res.length, res.level_changes, " > ".join(res.areas)))
        return {self.OUTPUT: dest, "LENGTH": res.length, "COST": res.cost, "LEVEL_CHANGES": res.level_changes,
                "START_SNAP": res.start_snap, "END_SNAP": res.goal_snap, "QUERY_MS": res.query_ms,
                "AREAS_CROSSED": " > ".join(res.areas), "PASSAGES_CROSSED": " > ".join(res.passages),
                "LEVELS": levels}
