"""Place a floor plan on the basemap by hand (plugin menu: *Place a floor plan on the map…*).

The floor's structure lines (``cad2osmag:extractstructure``, or any layer in the CAD frame) are shown as a
temporary layer over the OpenStreetMap / satellite basemap. Two map tools change the placement:

* :class:`PlacementMapTool`: drag the plan to move it, drag the round handle above it to rotate it (about
  the plan's centre; its dominant wall direction snaps to the edges of the building footprints shown on the
  map when within 3°; hold Shift for whole degrees instead), drag the square handle at its corner to scale it.
* :class:`GcpMapTool`: click a point of the drawing, then the same point on the basemap; after two pairs
  the Helmert (similarity) fit of ``algorithms.georef.fit_gcps`` places the plan, and its RMS and every
  point's residual are shown live.

The result (:class:`ui.placement_math.Placement`: the drawing origin's lon/lat, the rotation, the scale
and the control points) is saved with the QGIS project (``cad2osmag/placement``) and reused for every
floor of the building: it gives the ANCHOR / ROTATION / SCALE parameters of ``georeference``,
``dxftoosmag`` and ``exportosmag``.
"""
from __future__ import annotations

import os
from typing import List, Optional

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsFeature,
    QgsGeometry,
    QgsLineSymbol,
    QgsPointXY,
    QgsProject,
    QgsRectangle,
    QgsSingleSymbolRenderer,
    QgsVectorLayer,
    QgsWkbTypes,
)
from qgis.gui import QgsMapTool, QgsRubberBand, QgsVertexMarker
from qgis.PyQt.QtCore import QCoreApplication, Qt, pyqtSignal
from qgis.PyQt.QtGui import QColor

from .placement_math import (
    Gcp,
    Placement,
    cad_directions,
    dominant_directions,
    fitted,
    ground_directions,
    moved,
    project_points,
    rotated,
    rotated_to,
    scaled,
    snap_rotation,
)

PROJECT_SCOPE = "cad2osmag"
PROJECT_KEY = "placement"
WGS84 = QgsCoordinateReferenceSystem("EPSG:4326")
HANDLE_TOLERANCE_PX = 10
PREVIEW_MAX_LINES = 3000  # lines drawn while dragging (the layer itself is redrawn on release)
SNAP_MAX_FEATURES = 2000  # building footprints read around the plan for the rotation snap
SNAP_MARGIN = 0.5  # of the plan's size: footprints this far around it count


def tr(text):
    return QCoreApplication.translate("Placement", text)


# ====================================================================== project persistence
def save_placement(placement: Placement, project=None) -> None:
    """Store the placement in the project (saved with the .qgz), for every floor of the building."""
    (project or QgsProject.instance()).writeEntry(PROJECT_SCOPE, PROJECT_KEY, placement.to_json())


def load_placement(project=None) -> Optional[Placement]:
    """The placement saved in the project, or None."""
    text, ok = (project or QgsProject.instance()).readEntry(PROJECT_SCOPE, PROJECT_KEY, "")
    if not ok or not text:
        return None
    try:
        return Placement.from_json(text)
    except (ValueError, TypeError, KeyError):
        return None


# ====================================================================== the plan on the map
class PlanOverlay:
    """The structure lines of one floor (CAD frame, metres) drawn where a :class:`Placement` puts them.

    ``layer`` is a memory layer in WGS84 (exact, through PROJ) that is rewritten when a gesture ends;
    while dragging, a rubber band shows the lines (at most PREVIEW_MAX_LINES) with an affine
    approximation of the placement in the canvas CRS, which is exact to far below a pixel at building
    size."""

    def __init__(self, lines: List[QgsGeometry], name: str = "Plan placement", project=None):
        self.project = project or QgsProject.instance()
        self.cad_lines = [QgsGeometry(g) for g in lines if g is not None and not g.isEmpty()]
        if not self.cad_lines:
            raise ValueError(tr("the plan has no structure lines to show"))
        box = QgsRectangle(self.cad_lines[0].boundingBox())
        for g in self.cad_lines[1:]:
            box.combineExtentWith(g.boundingBox())
        self.cad_box = box
        step = max(1, len(self.cad_lines) // PREVIEW_MAX_LINES)
        self.preview_lines = self.cad_lines[::step]
        self.layer = QgsVectorLayer("MultiLineString?crs=EPSG:4326", name, "memory")
        symbol = QgsLineSymbol.createSimple({"color": "255,0,255", "width": "0.4"})
        self.layer.setRenderer(QgsSingleSymbolRenderer(symbol))
        self.layer.setCustomProperty("cad2osmag/placement_overlay", True)

    @classmethod
    def from_layer(cls, layer: QgsVectorLayer, name: Optional[str] = None, project=None) -> "PlanOverlay":
        return cls([f.geometry() for f in layer.getFeatures()], name or tr("Plan placement: {}").format(layer.name()),
                   project)

    @property
    def cad_direction(self) -> Optional[float]:
        """The plan's dominant wall direction (degrees counter-clockwise from the CAD +x axis, modulo 90), or
        None for a plan without a clear direction; computed once."""
        if not hasattr(self, "_cad_direction"):
            segs = []
            for g in self.cad_lines:
                parts = g.asGeometryCollection() if g.isMultipart() else [g]
                for part in parts:
                    pts = part.asPolyline()
                    segs.extend((a.x(), a.y(), b.x(), b.y()) for a, b in zip(pts, pts[1:]))
            dirs = dominant_directions(*cad_directions(segs)) if segs else []
            self._cad_direction = dirs[0] if dirs else None
        return self._cad_direction

    # CAD reference points of the gestures --------------------------------------------------------
    @property
    def centre(self):
        c = self.cad_box.center()
        return (c.x(), c.y())

    @property
    def rotate_handle(self):
        """Above the middle of the plan's top edge (CAD frame)."""
        b = self.cad_box
        return (b.center().x(), b.yMaximum() + 0.12 * max(b.height(), b.width()))

    @property
    def scale_handle(self):
        b = self.cad_box
        return (b.xMaximum(), b.yMinimum())

    # drawing ------------------------------------------------------------------------------------
    def update_layer(self, placement: Placement) -> None:
        """Rewrite the memory layer with the exact placement (per vertex, through PROJ)."""
        frame = placement.frame()
        feats = []
        for g in self.cad_lines:
            out = QgsGeometry(g)
            xs, ys = [], []
            for v in out.vertices():
                xs.append(v.x())
                ys.append(v.y())
            lon, lat = frame.to_wgs84(xs, ys)
            for i in range(len(xs)):
                out.moveVertex(float(lon[i]), float(lat[i]), i)
            f = QgsFeature()
            f.setGeometry(out)
            feats.append(f)
        provider = self.layer.dataProvider()
        provider.truncate()
        provider.addFeatures(feats)
        self.layer.updateExtents()
        self.layer.triggerRepaint()

    def affine_to(self, placement: Placement, crs: QgsCoordinateReferenceSystem, reference: Placement = None):
        """(a, b, c, d, e, f) with X = a x + b y + c, Y = d x + e y + f mapping CAD metres into ``crs``,
        from three points of the plan (exact at them; computed in ``reference``'s projection when given)."""
        b = self.cad_box
        size = max(b.width(), b.height(), 1.0)
        cx, cy = self.centre
        pts = [(cx, cy), (cx + size, cy), (cx, cy + size)]
        lons, lats = project_points(placement, [p[0] for p in pts], [p[1] for p in pts], reference or placement)
        tr_ = QgsCoordinateTransform(WGS84, crs, self.project)
        world = []
        for lon, lat in zip(lons, lats):
            p = tr_.transform(QgsPointXY(float(lon), float(lat)))
            world.append((p.x(), p.y()))
        (X0, Y0), (X1, Y1), (X2, Y2) = world
        a, d = (X1 - X0) / size, (Y1 - Y0) / size
        bb, e = (X2 - X0) / size, (Y2 - Y0) / size
        return a, bb, X0 - a * cx - bb * cy, d, e, Y0 - d * cx - e * cy


def _apply_affine(geom: QgsGeometry, m) -> QgsGeometry:
    a, b, c, d, e, f = m
    out = QgsGeometry(geom)
    for i, v in enumerate(geom.vertices()):
        out.moveVertex(a * v.x() + b * v.y() + c, d * v.x() + e * v.y() + f, i)
    return out


def _canvas_crs(canvas):
    crs = canvas.mapSettings().destinationCrs()
    return crs if crs.isValid() else WGS84


def _to_lonlat(canvas, point: QgsPointXY, project=None):
    tr_ = QgsCoordinateTransform(_canvas_crs(canvas), WGS84, project or QgsProject.instance())
    p = tr_.transform(point)
    return (p.x(), p.y())


def _from_lonlat(canvas, lonlat, project=None) -> QgsPointXY:
    tr_ = QgsCoordinateTransform(WGS84, _canvas_crs(canvas), project or QgsProject.instance())
    return tr_.transform(QgsPointXY(*lonlat))


# ====================================================================== building edges to snap to
def building_edge_directions(canvas, placement: Placement, overlay: "PlanOverlay", project=None) -> List[float]:
    """Dominant edge azimuths (degrees modulo 90) of the building footprints around the plan: the polygons of
    every vector layer shown on ``canvas`` (e.g. OSM buildings loaded by the user) within half the plan's
    size of it; [] when there are none (a raster basemap only)."""
    from qgis.core import QgsFeatureRequest

    project = project or QgsProject.instance()
    b = overlay.cad_box
    margin = SNAP_MARGIN * max(b.width(), b.height())
    corners = [(b.xMinimum() - margin, b.yMinimum() - margin), (b.xMaximum() + margin, b.yMinimum() - margin),
               (b.xMaximum() + margin, b.yMaximum() + margin), (b.xMinimum() - margin, b.yMaximum() + margin)]
    lons, lats = project_points(placement, [c[0] for c in corners], [c[1] for c in corners], placement)
    area = QgsRectangle(float(min(lons)), float(min(lats)), float(max(lons)), float(max(lats)))
    segs = []
    for layer in canvas.layers():
        if not isinstance(layer, QgsVectorLayer) or layer is overlay.layer or \
                layer.geometryType() != QgsWkbTypes.GeometryType.PolygonGeometry:
            continue
        to_layer = QgsCoordinateTransform(WGS84, layer.crs(), project)
        to_wgs = QgsCoordinateTransform(layer.crs(), WGS84, project)
        try:
            rect = to_layer.transformBoundingBox(area)
        except Exception:  # noqa: BLE001 - a layer whose CRS cannot hold the area: skip it
            continue
        request = QgsFeatureRequest().setFilterRect(rect).setLimit(SNAP_MAX_FEATURES)
        request.setNoAttributes()
        for f in layer.getFeatures(request):
            g = QgsGeometry(f.geometry())
            if g.isEmpty() or g.transform(to_wgs) != 0:
                continue
            polys = g.asMultiPolygon() if g.isMultipart() else [g.asPolygon()]
            for poly in polys:
                for ring in poly:
                    segs.extend((p.x(), p.y(), q.x(), q.y()) for p, q in zip(ring, ring[1:]))
    if not segs:
        return []
    return dominant_directions(*ground_directions(segs))


# ====================================================================== shared map tool state
class _PlacementToolBase(QgsMapTool):
    placementChanged = pyqtSignal(object)  # Placement, at the end of each gesture / fit

    def __init__(self, canvas, overlay: PlanOverlay, placement: Placement):
        super().__init__(canvas)
        self.overlay = overlay
        self.placement = placement
        self.project = overlay.project
        self._items = []

    def set_placement(self, placement: Placement, redraw_layer: bool = True):
        self.placement = placement
        if redraw_layer:
            self.overlay.update_layer(placement)
        self.refresh_decorations()

    def refresh_decorations(self):
        pass

    def _clear_items(self):
        scene = self.canvas().scene()
        for item in self._items:
            scene.removeItem(item)
        self._items = []

    def deactivate(self):
        self._clear_items()
        super().deactivate()


class PlacementMapTool(_PlacementToolBase):
    """Drag to move, drag the round handle to rotate, drag the square handle to scale."""

    def __init__(self, canvas, overlay, placement, allow_scale: bool = True, snap_to_buildings: bool = True):
        super().__init__(canvas, overlay, placement)
        self.allow_scale = allow_scale
        self.snap_to_buildings = snap_to_buildings  # rotation snaps to the footprints' edges on the canvas
        self.snap_targets: List[float] = []  # their directions, read when a rotation starts
        self.snapped = None  # the edge direction the last rotation snapped to, or None
        self.mode = None  # 'move', 'rotate', 'scale' while a button is down
        self._start = None
        self._start_placement = None
        self._preview = None
        self.setCursor(Qt.CursorShape.OpenHandCursor)

    # decorations: outline of the plan's box, the rotate and scale handles ------------------------
    def _canvas_points(self, placement, cad_points, reference=None):
        xs, ys = [c[0] for c in cad_points], [c[1] for c in cad_points]
        lons, lats = project_points(placement, xs, ys, reference or placement)
        return [_from_lonlat(self.canvas(), (float(lo), float(la)), self.project) for lo, la in zip(lons, lats)]

    def handle_points(self, placement=None, reference=None):
        """Canvas-CRS positions of the rotate and scale handles and the pivot."""
        p = placement or self.placement
        names = ("rotate", "scale", "pivot")
        pts = self._canvas_points(p, (self.overlay.rotate_handle, self.overlay.scale_handle, self.overlay.centre),
                                  reference)
        return dict(zip(names, pts))

    def refresh_decorations(self, placement=None, reference=None):
        self._clear_items()
        p = placement or self.placement
        pts = self.handle_points(p, reference)
        b = self.overlay.cad_box
        mid = (b.xMinimum() + b.xMaximum()) / 2
        corners = [(mid, b.yMaximum()), (b.xMinimum(), b.yMaximum()), (b.xMinimum(), b.yMinimum()),
                   (b.xMaximum(), b.yMinimum()), (b.xMaximum(), b.yMaximum()), (mid, b.yMaximum())]
        outline = QgsRubberBand(self.canvas(), QgsWkbTypes.GeometryType.LineGeometry)
        outline.setColor(QColor(255, 140, 0))
        outline.setWidth(1)
        outline.setLineStyle(Qt.PenStyle.DashLine)
        for c in self._canvas_points(p, corners, reference):
            outline.addPoint(c, False)
        outline.addPoint(pts["rotate"], True)
        self._items.append(outline)
        kinds = [("rotate", QgsVertexMarker.IconType.ICON_CIRCLE), ("pivot", QgsVertexMarker.IconType.ICON_CROSS)]
        if self.allow_scale:
            kinds.append(("scale", QgsVertexMarker.IconType.ICON_BOX))
        for name, icon in kinds:
            m = QgsVertexMarker(self.canvas())
            m.setCenter(pts[name])
            m.setIconType(icon)
            m.setIconSize(14)
            m.setPenWidth(3)
            m.setColor(QColor(255, 140, 0))
            self._items.append(m)

    def activate(self):
        super().activate()
        self.refresh_decorations()

    # gestures ------------------------------------------------------------------------------------
    def hit_mode(self, map_point: QgsPointXY) -> str:
        tol = HANDLE_TOLERANCE_PX * self.canvas().mapUnitsPerPixel()
        pts = self.handle_points()
        if pts["rotate"].distance(map_point) <= tol:
            return "rotate"
        if self.allow_scale and pts["scale"].distance(map_point) <= tol:
            return "scale"
        return "move"

    def _gesture(self, end_point: QgsPointXY, modifiers, exact=True) -> Placement:
        start = _to_lonlat(self.canvas(), self._start, self.project)
        end = _to_lonlat(self.canvas(), end_point, self.project)
        p0 = self._start_placement
        if self.mode == "rotate":
            whole = bool(modifiers & Qt.KeyboardModifier.ShiftModifier)
            p = rotated(p0, self.overlay.centre, start, end, 1.0 if whole else None, exact=exact)
            self.snapped = None
            if not whole and self.snap_targets:
                rot, self.snapped = snap_rotation(p.rotation_deg, self.overlay.cad_direction, self.snap_targets)
                if self.snapped is not None:
                    p = rotated_to(p0, self.overlay.centre, rot, exact=exact)
            return p
        if self.mode == "scale":
            return scaled(p0, self.overlay.centre, start, end, exact=exact)
        return moved(p0, start, end, exact=exact)

    def canvasPressEvent(self, event):  # noqa: N802
        if event.button() != Qt.MouseButton.LeftButton:
            return
        self._start = QgsPointXY(event.mapPoint())
        self._start_placement = self.placement
        self.mode = self.hit_mode(self._start)
        self.snapped = None
        self.snap_targets = []
        if self.mode == "rotate" and self.snap_to_buildings:
            self.snap_targets = building_edge_directions(self.canvas(), self.placement, self.overlay, self.project)
        self.setCursor(Qt.CursorShape.ClosedHandCursor)

    def canvasMoveEvent(self, event):  # noqa: N802
        if self.mode is None:
            return
        # while dragging everything is computed in the start placement's projection (no new PROJ objects)
        p = self._gesture(QgsPointXY(event.mapPoint()), event.modifiers(), exact=False)
        self._show_preview(p)
        self.refresh_decorations(p, reference=self._start_placement)

    def canvasReleaseEvent(self, event):  # noqa: N802
        if self.mode is None:
            return
        p = self._gesture(QgsPointXY(event.mapPoint()), event.modifiers())
        self.mode = None
        self._hide_preview()
        self.setCursor(Qt.CursorShape.OpenHandCursor)
        self.set_placement(p)
        self.placementChanged.emit(p)

    def _show_preview(self, placement):
        if self._preview is None:
            self._preview = QgsRubberBand(self.canvas(), QgsWkbTypes.GeometryType.LineGeometry)
            self._preview.setColor(QColor(255, 0, 255, 160))
            self._preview.setWidth(1)
        m = self.overlay.affine_to(placement, _canvas_crs(self.canvas()), reference=self._start_placement)
        parts = [_apply_affine(g, m) for g in self.overlay.preview_lines]
        self._preview.setToGeometry(QgsGeometry.collectGeometry(parts), None)

    def _hide_preview(self):
        if self._preview is not None:
            self.canvas().scene().removeItem(self._preview)
            self._preview = None


class GcpMapTool(_PlacementToolBase):
    """Click a drawing point, then where it lies on the basemap; repeat. From two pairs on the placement
    is the least-squares (Helmert) fit and ``rms`` / each point's residual are updated at every click."""

    gcpsChanged = pyqtSignal(object)  # list of Gcp (residuals filled in once fitted)

    def __init__(self, canvas, overlay, placement, fix_scale: bool = False):
        super().__init__(canvas, overlay, placement)
        self.gcps: List[Gcp] = list(placement.gcps)
        self.pending_cad = None  # CAD point of a pair waiting for its map point
        self.fix_scale = fix_scale
        self.setCursor(Qt.CursorShape.CrossCursor)

    def canvasReleaseEvent(self, event):  # noqa: N802
        if event.button() == Qt.MouseButton.RightButton:
            self.pending_cad = None
            self.refresh_decorations()
            return
        if event.button() != Qt.MouseButton.LeftButton:
            return
        lonlat = _to_lonlat(self.canvas(), QgsPointXY(event.mapPoint()), self.project)
        if self.pending_cad is None:
            self.pending_cad = self.placement.from_wgs84(*lonlat)
        else:
            self.add_pair(self.pending_cad, lonlat)
            self.pending_cad = None
        self.refresh_decorations()

    def add_pair(self, cad_xy, lonlat):
        self.gcps.append(Gcp(float(cad_xy[0]), float(cad_xy[1]), float(lonlat[0]), float(lonlat[1])))
        self.refit()

    def remove(self, index: int):
        del self.gcps[index]
        self.refit()

    def refit(self):
        """Fit when there are >= 2 pairs; a degenerate set (coincident / collinear points) keeps the
        current placement and the message is reported through ``error``."""
        from ..algorithms.errors import InputError

        self.error = None
        if len(self.gcps) >= 2:
            try:
                p = fitted(self.gcps, fixed_scale=self.placement.scale if self.fix_scale else None)
            except InputError as exc:
                self.error = str(exc)
                self.gcpsChanged.emit(self.gcps)
                return
            self.gcps = p.gcps
            self.set_placement(p)
            self.placementChanged.emit(p)
        else:
            self.placement = Placement(self.placement.anchor_lon, self.placement.anchor_lat,
                                       self.placement.rotation_deg, self.placement.scale, list(self.gcps), None)
        self.gcpsChanged.emit(self.gcps)

    @property
    def rms(self):
        return self.placement.rms

    def refresh_decorations(self):
        self._clear_items()
        for g in self.gcps:
            for lonlat, color in ((self.placement.to_wgs84(g.cad_x, g.cad_y), QColor(255, 0, 255)),
                                  ((g.lon, g.lat), QColor(0, 160, 255))):
                m = QgsVertexMarker(self.canvas())
                m.setCenter(_from_lonlat(self.canvas(), lonlat, self.project))
                m.setIconType(QgsVertexMarker.IconType.ICON_X)
                m.setColor(color)
                m.setPenWidth(2)
                self._items.append(m)
        if self.pending_cad is not None:
            m = QgsVertexMarker(self.canvas())
            m.setCenter(_from_lonlat(self.canvas(), self.placement.to_wgs84(*self.pending_cad), self.project))
            m.setIconType(QgsVertexMarker.IconType.ICON_CIRCLE)
            m.setColor(QColor(255, 0, 255))
            m.setPenWidth(2)
            self._items.append(m)


# ====================================================================== loading a floor
def structure_layer(path: str, context=None, feedback=None, plan=None) -> QgsVectorLayer:
    """The structure lines of a DXF/DWG floor, through ``cad2osmag:extractstructure`` (no second
    implementation), as a memory layer in the CAD frame; ``plan``: its PLAN on a whole sheet."""
    from qgis.core import QgsApplication, QgsProcessingContext, QgsProcessingFeedback

    alg = QgsApplication.processingRegistry().createAlgorithmById("cad2osmag:extractstructure")
    if alg is None:
        raise RuntimeError(tr("the CAD to osmAG Processing provider is not loaded"))
    context = context or QgsProcessingContext()
    context.setProject(QgsProject.instance())
    feedback = feedback or QgsProcessingFeedback()
    params = {"INPUT": path, "WALLS": "memory:", "TEXTS": "memory:"}
    if plan not in (None, ""):
        params["PLAN"] = str(plan)
    results, ok = alg.run(params, context, feedback)
    if not ok:
        raise RuntimeError(tr("cannot read the structure of {}").format(os.path.basename(path)))
    layer = context.takeResultLayer(results["WALLS"])
    layer.setName(os.path.splitext(os.path.basename(path))[0])
    return layer


def initial_placement(canvas, overlay: PlanOverlay, project=None) -> Placement:
    """The project's saved placement, else the plan's centre at the centre of the canvas, north up."""
    saved = load_placement(project)
    if saved is not None:
        return saved
    centre = _to_lonlat(canvas, canvas.extent().center(), project)
    if not (-180 <= centre[0] <= 180 and -85 <= centre[1] <= 85) or canvas.extent().isEmpty():
        centre = (0.0, 0.0)
    start = Placement(centre[0], centre[1])
    return moved(start, start.to_wgs84(*overlay.centre), centre)  # the plan's centre at the canvas centre
