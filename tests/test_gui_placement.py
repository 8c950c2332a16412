"""Placing a plan on the basemap by hand: gestures (pure), the map tools driven by synthetic mouse events on
an offscreen canvas, control points with a live Helmert RMS, and the placement saved with the project."""
import math

import pytest

from .conftest import plugin_package

LON, LAT = 121.5900, 31.1800  # somewhere in Shanghai


def _math():
    plugin_package()
    from cad2osmag.ui import placement_math

    return placement_math


def _dist(a, b):
    from algorithms.georef import geodesic_distance

    return float(geodesic_distance(a[0], a[1], b[0], b[1]))


# ---------------------------------------------------------------------------------------- pure gestures
def test_move_keeps_rotation_and_scale_and_carries_the_grabbed_point():
    pm = _math()
    p = pm.Placement(LON, LAT, 30.0, 1.0)
    grab = p.to_wgs84(10.0, 5.0)
    target = (grab[0] + 0.0002, grab[1] - 0.0001)
    q = pm.moved(p, grab, target)
    assert q.rotation_deg == pytest.approx(30.0) and q.scale == pytest.approx(1.0)
    assert _dist(q.to_wgs84(10.0, 5.0), target) < 1e-3  # millimetre
    # the whole plan is translated: another point moved by the same ground distance
    d1 = _dist(p.to_wgs84(0, 0), q.to_wgs84(0, 0))
    d2 = _dist(p.to_wgs84(40, 20), q.to_wgs84(40, 20))
    assert d1 == pytest.approx(d2, abs=1e-3)


def test_rotate_about_the_pivot_by_the_turn_of_the_handle():
    pm = _math()
    from algorithms.georef import azimuth

    p = pm.Placement(LON, LAT, 0.0, 1.0)
    pivot_cad = (20.0, 10.0)
    pivot = p.to_wgs84(*pivot_cad)
    handle = p.to_wgs84(20.0, 40.0)  # 30 m north of the pivot
    # a point 30 m from the pivot at azimuth 25 degrees
    frame = pm.Placement(pivot[0], pivot[1], 25.0)
    end = frame.to_wgs84(0.0, 30.0)
    assert azimuth(*pivot, *end) == pytest.approx(25.0, abs=1e-6)
    q = pm.rotated(p, pivot_cad, handle, end)
    assert q.rotation_deg == pytest.approx(25.0, abs=1e-3)  # meridian convergence pivot vs anchor: 1e-4 deg
    assert _dist(q.to_wgs84(*pivot_cad), pivot) < 1e-3
    snapped = pm.rotated(p, pivot_cad, handle, end, snap_deg=4).rotation_deg
    assert snapped == pytest.approx(24.0)


def test_scale_handle_sets_ground_metres_per_drawing_metre():
    pm = _math()
    p = pm.Placement(LON, LAT, 10.0, 1.0)
    pivot_cad = (0.0, 0.0)
    start = p.to_wgs84(30.0, 0.0)
    end = p.to_wgs84(33.0, 0.0)  # 10 % further out
    q = pm.scaled(p, pivot_cad, start, end)
    assert q.scale == pytest.approx(1.1, rel=1e-6)
    assert q.rotation_deg == pytest.approx(10.0)
    assert _dist(q.to_wgs84(0, 0), p.to_wgs84(0, 0)) < 1e-3
    assert _dist(q.to_wgs84(0, 0), q.to_wgs84(10, 0)) == pytest.approx(11.0, abs=1e-3)


def test_fit_from_control_points_recovers_a_known_placement_and_reports_rms():
    pm = _math()
    truth = pm.Placement(LON, LAT, 47.0, 1.0)
    cad = [(0, 0), (40, 0), (40, 25), (0, 25)]
    gcps = [pm.Gcp(x, y, *truth.to_wgs84(x, y)) for x, y in cad]
    p = pm.fitted(gcps)
    assert p.rotation_deg == pytest.approx(47.0, abs=1e-6)
    assert p.scale == pytest.approx(1.0, abs=1e-7)
    assert _dist((p.anchor_lon, p.anchor_lat), (LON, LAT)) < 1e-3
    assert p.rms < 1e-3 and all(g.residual < 1e-3 for g in p.gcps)
    # one point picked 2 m off: the RMS says so
    lon, lat = pm.Placement(gcps[2].lon, gcps[2].lat).to_wgs84(2.0, 0.0)  # 2 m east
    bad = gcps[:2] + [pm.Gcp(40, 25, lon, lat)] + gcps[3:]
    q = pm.fitted(bad)
    assert 0.4 < q.rms < 2.0
    assert max(g.residual for g in q.gcps) == pytest.approx(q.gcps[2].residual)


def test_placement_gives_the_parameters_of_georeference_and_dxftoosmag():
    pm = _math()
    p = pm.Placement(LON, LAT, 12.5, 1.02)
    g = p.georeference_parameters()
    assert g["ANCHOR"] == f"{LON:.10f},{LAT:.10f} [EPSG:4326]"
    assert g["ROTATION"] == 12.5 and g["SCALE"] == 1.02 and g["CAD_ANCHOR_X"] == 0.0 and g["MODE"] == 0
    assert p.dxftoosmag_parameters() == {"ANCHOR": g["ANCHOR"], "ROTATION": 12.5}
    assert pm.Placement.from_json(p.to_json()) == p


def _rect_segments(cx, cy, w, h, angle_deg):
    """The 4 edges (x0, y0, x1, y1) of a w x h rectangle centred on (cx, cy) turned by angle_deg (CCW)."""
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    pts = [(cx + x * c - y * s, cy + x * s + y * c) for x, y in
           ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))]
    return [(*pts[i], *pts[(i + 1) % 4]) for i in range(4)]


def test_dominant_directions_of_walls_fold_right_angles_and_ignore_clutter():
    pm = _math()
    import random

    rng = random.Random(1)
    segs = _rect_segments(0, 0, 40, 20, 27.0) + _rect_segments(5, 3, 6, 4, 117.0)  # same walls mod 90
    segs += [(x, y, x + 0.3 * math.cos(t), y + 0.3 * math.sin(t))  # short furniture-like clutter
             for x, y, t in ((rng.uniform(-20, 20), rng.uniform(-10, 10), rng.uniform(0, 6.3)) for _ in range(200))]
    ang, length = pm.cad_directions(segs)
    dirs = pm.dominant_directions(ang, length)
    assert dirs and dirs[0] == pytest.approx(27.0, abs=0.2)
    # two buildings at different angles: both found, the longer first; a direction near 0 wraps to 89.x
    segs2 = _rect_segments(0, 0, 60, 30, 10.0) + _rect_segments(100, 0, 30, 20, -0.4)
    d2 = pm.dominant_directions(*pm.cad_directions(segs2))
    assert d2[0] == pytest.approx(10.0, abs=0.2) and d2[1] == pytest.approx(89.6, abs=0.2)
    assert pm.dominant_directions([], []) == []


def test_ground_directions_and_rotation_snap_to_building_edges():
    pm = _math()
    # a footprint whose long edge runs at azimuth 20 deg (a plan rotated by 20 deg with its walls along x, y)
    truth = pm.Placement(LON, LAT, 20.0, 1.0)
    ring = [truth.to_wgs84(x, y) for x, y in ((0, 0), (30, 0), (30, 12), (0, 12))]
    segs = [(*ring[i], *ring[(i + 1) % 4]) for i in range(4)]
    az, length = pm.ground_directions(segs)
    assert length.sum() == pytest.approx(84.0, abs=0.01)
    targets = pm.dominant_directions(az, length)
    assert targets[0] == pytest.approx(20.0, abs=0.05)
    # the plan's walls are along the CAD axes (direction 0): rotated by 18.2 deg it snaps to 20
    rot, hit = pm.snap_rotation(18.2, 0.0, targets)
    assert rot == pytest.approx(20.0, abs=0.05) and hit == pytest.approx(targets[0])
    rot, hit = pm.snap_rotation(291.5, 0.0, targets)  # 290 = 20 mod 90 as well
    assert rot == pytest.approx(290.0, abs=0.05) and hit is not None
    rot, hit = pm.snap_rotation(26.0, 0.0, targets)  # too far: unchanged
    assert rot == pytest.approx(26.0) and hit is None
    # a plan drawn at 27 deg in the CAD frame lies along azimuth 20 when rotated by 47 (+/- 90)
    assert pm.plan_ground_direction(47.0, 27.0) == pytest.approx(20.0)
    rot, _ = pm.snap_rotation(45.5, 27.0, targets)
    assert rot == pytest.approx(47.0, abs=0.05)
    assert pm.snap_rotation(12.0, None, targets) == (12.0, None)
    assert pm.snap_rotation(12.0, 0.0, []) == (12.0, None)


# ---------------------------------------------------------------------------------------- on a canvas
@pytest.fixture()
def plan_canvas(qgis_app, qgis_new_project):
    from qgis.core import QgsCoordinateReferenceSystem, QgsFeature, QgsGeometry, QgsPointXY, QgsProject, QgsVectorLayer
    from qgis.gui import QgsMapCanvas

    plugin_package()
    from cad2osmag.ui.placement import PlanOverlay
    from cad2osmag.ui.placement_math import Placement

    QgsProject.instance().removeEntry("cad2osmag", "placement")  # qgis_new_project keeps custom entries
    walls = QgsVectorLayer("LineString", "floor-1", "memory")
    feats = []
    for (x0, y0), (x1, y1) in [((0, 0), (40, 0)), ((40, 0), (40, 20)), ((40, 20), (0, 20)), ((0, 20), (0, 0)),
                               ((20, 0), (20, 20))]:
        f = QgsFeature()
        f.setGeometry(QgsGeometry.fromPolylineXY([QgsPointXY(x0, y0), QgsPointXY(x1, y1)]))
        feats.append(f)
    walls.dataProvider().addFeatures(feats)
    canvas = QgsMapCanvas()
    canvas.resize(800, 600)
    canvas.setDestinationCrs(QgsCoordinateReferenceSystem("EPSG:3857"))
    overlay = PlanOverlay.from_layer(walls, project=QgsProject.instance())
    QgsProject.instance().addMapLayer(overlay.layer)
    placement = Placement(LON, LAT, 0.0, 1.0)
    overlay.update_layer(placement)
    from qgis.core import QgsCoordinateTransform

    ext = QgsCoordinateTransform(overlay.layer.crs(), canvas.mapSettings().destinationCrs(),
                                 QgsProject.instance()).transformBoundingBox(overlay.layer.extent())
    ext.scale(2.0)
    canvas.setExtent(ext)
    canvas.show()
    yield canvas, overlay, placement
    canvas.close()


def _pixel(canvas, lonlat):
    from qgis.core import QgsCoordinateReferenceSystem, QgsCoordinateTransform, QgsPointXY, QgsProject

    tr = QgsCoordinateTransform(QgsCoordinateReferenceSystem("EPSG:4326"), canvas.mapSettings().destinationCrs(),
                                QgsProject.instance())
    p = canvas.getCoordinateTransform().transform(tr.transform(QgsPointXY(*lonlat)))
    return p.x(), p.y()


def _lonlat(canvas, px):
    from qgis.core import QgsCoordinateReferenceSystem, QgsCoordinateTransform, QgsProject

    tr = QgsCoordinateTransform(canvas.mapSettings().destinationCrs(), QgsCoordinateReferenceSystem("EPSG:4326"),
                                QgsProject.instance())
    p = tr.transform(canvas.getCoordinateTransform().toMapCoordinates(int(round(px[0])), int(round(px[1]))))
    return p.x(), p.y()


def _drag(tool, canvas, start_px, end_px, steps=4, modifiers=None, button=None):
    from qgis.gui import QgsMapMouseEvent
    from qgis.PyQt.QtCore import QEvent, QPoint, Qt

    button = button or Qt.MouseButton.LeftButton
    mods = modifiers or Qt.KeyboardModifier.NoModifier

    def ev(kind, px, btn, btns):
        return QgsMapMouseEvent(canvas, kind, QPoint(int(round(px[0])), int(round(px[1]))), btn, btns, mods)

    tool.canvasPressEvent(ev(QEvent.Type.MouseButtonPress, start_px, button, button))
    for i in range(1, steps + 1):
        t = i / steps
        px = (start_px[0] + t * (end_px[0] - start_px[0]), start_px[1] + t * (end_px[1] - start_px[1]))
        tool.canvasMoveEvent(ev(QEvent.Type.MouseMove, px, Qt.MouseButton.NoButton, button))
    tool.canvasReleaseEvent(ev(QEvent.Type.MouseButtonRelease, end_px, button, Qt.MouseButton.NoButton))


def test_dragging_the_plan_moves_it_with_the_mouse(plan_canvas):
    from cad2osmag.ui.placement import PlacementMapTool

    canvas, overlay, placement = plan_canvas
    tool = PlacementMapTool(canvas, overlay, placement)
    canvas.setMapTool(tool)
    seen = []
    tool.placementChanged.connect(seen.append)
    start = _pixel(canvas, placement.to_wgs84(10.0, 10.0))  # inside the plan, away from the handles
    assert tool.hit_mode(canvas.getCoordinateTransform().toMapCoordinates(int(start[0]), int(start[1]))) == "move"
    end = (start[0] + 120, start[1] + 45)
    _drag(tool, canvas, start, end)
    assert len(seen) == 1
    p = seen[0]
    assert p.rotation_deg == pytest.approx(0.0) and p.scale == pytest.approx(1.0)
    # the grabbed drawing point is under the mouse (within a pixel)
    mupp_m = canvas.mapUnitsPerPixel() * math.cos(math.radians(LAT))
    assert _dist(p.to_wgs84(10.0, 10.0), _lonlat(canvas, end)) < 1.5 * mupp_m
    # moved east and south by the dragged pixels
    assert p.anchor_lon > placement.anchor_lon and p.anchor_lat < placement.anchor_lat
    assert _dist((p.anchor_lon, p.anchor_lat), (placement.anchor_lon, placement.anchor_lat)) == pytest.approx(
        math.hypot(120, 45) * mupp_m, rel=0.02)
    # the temporary layer follows
    e = overlay.layer.extent()
    assert e.xMinimum() == pytest.approx(p.anchor_lon, abs=1e-7)
    assert tool.placement is p


def test_dragging_the_round_handle_rotates_the_plan_about_its_centre(plan_canvas):
    from cad2osmag.ui.placement import PlacementMapTool
    from qgis.PyQt.QtCore import Qt

    canvas, overlay, placement = plan_canvas
    tool = PlacementMapTool(canvas, overlay, placement)
    canvas.setMapTool(tool)
    pivot = _pixel(canvas, placement.to_wgs84(*overlay.centre))
    handle = _pixel(canvas, placement.to_wgs84(*overlay.rotate_handle))
    assert tool.hit_mode(canvas.getCoordinateTransform().toMapCoordinates(int(handle[0]), int(handle[1]))) == "rotate"
    r = math.hypot(handle[0] - pivot[0], handle[1] - pivot[1])
    # screen y points down: 35 degrees clockwise on screen
    a = math.radians(35.0)
    end = (pivot[0] + r * math.sin(a), pivot[1] - r * math.cos(a))
    seen = []
    tool.placementChanged.connect(seen.append)
    _drag(tool, canvas, handle, end)
    p = seen[-1]
    assert p.rotation_deg == pytest.approx(35.0, abs=0.5)
    assert p.scale == pytest.approx(1.0)
    # the centre of the plan stayed where it was
    assert _dist(p.to_wgs84(*overlay.centre), placement.to_wgs84(*overlay.centre)) < 1e-3
    # Shift snaps to whole degrees
    tool.set_placement(placement)
    _drag(tool, canvas, handle, end, modifiers=Qt.KeyboardModifier.ShiftModifier)
    assert tool.placement.rotation_deg == pytest.approx(round(tool.placement.rotation_deg), abs=1e-9)
    assert tool.placement.rotation_deg == pytest.approx(35.0, abs=1.0)


def test_rotation_snaps_to_the_edges_of_building_footprints_on_the_map(plan_canvas):
    """OSM-like building footprints (a polygon layer in web mercator) around the plan, the long side at
    azimuth 20 deg: a turn of the handle to 18.4 deg ends at 20.0; a turn to 30 deg stays 30 (too far);
    Shift (whole degrees) wins over the snap; with the snap off nothing moves."""
    from qgis.core import (QgsCoordinateReferenceSystem, QgsCoordinateTransform, QgsFeature, QgsGeometry,
                           QgsPointXY, QgsProject, QgsVectorLayer)
    from qgis.PyQt.QtCore import Qt

    from cad2osmag.ui.placement import PlacementMapTool, building_edge_directions
    from cad2osmag.ui.placement_math import Placement

    canvas, overlay, placement = plan_canvas
    truth = Placement(LON, LAT, 20.0, 1.0)
    to_merc = QgsCoordinateTransform(QgsCoordinateReferenceSystem("EPSG:4326"),
                                     QgsCoordinateReferenceSystem("EPSG:3857"), QgsProject.instance())
    buildings = QgsVectorLayer("Polygon?crs=EPSG:3857", "buildings", "memory")
    feats = []
    for x0, y0, w, h in ((-2, -1, 44, 22), (50, 0, 12, 30)):  # the building and a neighbour, same grid
        ring = [to_merc.transform(QgsPointXY(*truth.to_wgs84(x, y)))
                for x, y in ((x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h), (x0, y0))]
        f = QgsFeature()
        f.setGeometry(QgsGeometry.fromPolygonXY([ring]))
        feats.append(f)
    buildings.dataProvider().addFeatures(feats)
    QgsProject.instance().addMapLayer(buildings)
    canvas.setLayers([overlay.layer, buildings])
    assert overlay.cad_direction == pytest.approx(0.0, abs=0.3) or overlay.cad_direction == pytest.approx(90, abs=0.3)
    targets = building_edge_directions(canvas, placement, overlay)
    assert targets and targets[0] == pytest.approx(20.0, abs=0.05)

    tool = PlacementMapTool(canvas, overlay, placement)
    canvas.setMapTool(tool)
    pivot = _pixel(canvas, placement.to_wgs84(*overlay.centre))
    handle = _pixel(canvas, placement.to_wgs84(*overlay.rotate_handle))
    r = math.hypot(handle[0] - pivot[0], handle[1] - pivot[1])

    def turn_to(deg, **kw):
        tool.set_placement(placement)
        a = math.radians(deg)
        _drag(tool, canvas, handle, (pivot[0] + r * math.sin(a), pivot[1] - r * math.cos(a)), **kw)
        return tool.placement

    p = turn_to(18.4)
    assert p.rotation_deg == pytest.approx(20.0, abs=0.05) and tool.snapped == pytest.approx(20.0, abs=0.05)
    assert _dist(p.to_wgs84(*overlay.centre), placement.to_wgs84(*overlay.centre)) < 1e-3  # centre kept
    p = turn_to(-68.5)  # 291.5 = 21.5 modulo 90: the plan turned the other way round snaps too
    assert p.rotation_deg == pytest.approx(290.0, abs=0.05)
    p = turn_to(30.0)
    assert p.rotation_deg == pytest.approx(30.0, abs=0.5) and tool.snapped is None
    p = turn_to(18.4, modifiers=Qt.KeyboardModifier.ShiftModifier)
    assert p.rotation_deg == pytest.approx(round(p.rotation_deg), abs=1e-9) and round(p.rotation_deg) in (18, 19)
    tool.snap_to_buildings = False
    p = turn_to(18.4)
    assert p.rotation_deg == pytest.approx(18.4, abs=0.5) and abs(p.rotation_deg - 20.0) > 1.0
    QgsProject.instance().removeMapLayer(buildings.id())


def test_dragging_the_square_handle_scales_the_plan(plan_canvas):
    from cad2osmag.ui.placement import PlacementMapTool

    canvas, overlay, placement = plan_canvas
    tool = PlacementMapTool(canvas, overlay, placement)
    pivot = _pixel(canvas, placement.to_wgs84(*overlay.centre))
    handle = _pixel(canvas, placement.to_wgs84(*overlay.scale_handle))
    end = (pivot[0] + 1.2 * (handle[0] - pivot[0]), pivot[1] + 1.2 * (handle[1] - pivot[1]))
    _drag(tool, canvas, handle, end)
    assert tool.placement.scale == pytest.approx(1.2, abs=0.02)
    assert tool.placement.rotation_deg == pytest.approx(0.0, abs=1e-6)


def test_control_point_clicks_fit_the_plan_and_show_the_rms(plan_canvas):
    from cad2osmag.ui.placement import GcpMapTool
    from cad2osmag.ui.placement_math import Placement

    canvas, overlay, placement = plan_canvas
    truth = Placement(LON + 0.0001, LAT + 0.00005, 20.0, 1.0)  # where the building really is
    tool = GcpMapTool(canvas, overlay, placement)
    rms_seen = []
    tool.gcpsChanged.connect(lambda g: rms_seen.append(tool.rms))
    for cad in [(0.0, 0.0), (40.0, 0.0), (40.0, 20.0)]:
        drawing_px = _pixel(canvas, tool.placement.to_wgs84(*cad))  # where the plan is drawn now
        world_px = _pixel(canvas, truth.to_wgs84(*cad))
        _drag(tool, canvas, drawing_px, drawing_px, steps=0)
        assert tool.pending_cad is not None
        _drag(tool, canvas, world_px, world_px, steps=0)
        assert tool.pending_cad is None
    assert len(tool.gcps) == 3
    assert rms_seen[0] is None and rms_seen[-1] is not None  # the RMS appears from the second pair on
    mupp_m = canvas.mapUnitsPerPixel() * math.cos(math.radians(LAT))
    assert tool.rms < 1.5 * mupp_m  # clicks are accurate to a pixel
    assert tool.placement.rotation_deg == pytest.approx(20.0, abs=0.5)
    assert tool.placement.scale == pytest.approx(1.0, abs=0.02)
    assert _dist(tool.placement.to_wgs84(20, 10), truth.to_wgs84(20, 10)) < 2 * mupp_m
    # removing a point refits; below 2 points there is no RMS
    tool.remove(0)
    tool.remove(0)
    assert tool.rms is None and len(tool.gcps) == 1


def test_placement_is_saved_with_the_project_and_restored(qgis_app, qgis_new_project, tmp_path):
    from qgis.core import QgsProject

    plugin_package()
    from cad2osmag.ui.placement import load_placement, save_placement
    from cad2osmag.ui.placement_math import Gcp, Placement

    p = Placement(LON, LAT, 33.0, 0.998, [Gcp(0, 0, LON, LAT, 0.01), Gcp(10, 0, LON + 1e-4, LAT, 0.02)], 0.015)
    save_placement(p)
    path = str(tmp_path / "building.qgz")
    assert QgsProject.instance().write(path)
    QgsProject.instance().clear()
    assert load_placement() is None
    assert QgsProject.instance().read(path)
    assert load_placement() == p


def test_placement_panel_loads_a_plan_and_follows_the_tools(plan_canvas):
    from cad2osmag.ui.placement import load_placement
    from cad2osmag.ui.placement_dock import PlacementWidget
    from qgis.core import QgsFeature, QgsGeometry, QgsPointXY, QgsVectorLayer

    canvas, _, _ = plan_canvas
    widget = PlacementWidget(canvas)
    walls = QgsVectorLayer("LineString", "floor-2", "memory")
    f = QgsFeature()
    f.setGeometry(QgsGeometry.fromPolylineXY([QgsPointXY(0, 0), QgsPointXY(30, 0), QgsPointXY(30, 12)]))
    walls.dataProvider().addFeatures([f])
    widget.load_layer(walls)
    assert canvas.mapTool() is widget.move_tool and widget.move_button.isChecked()
    assert "30.0 × 12.0 m" in widget.plan_label.text()
    widget.rot_spin.setValue(15.0)
    assert widget.placement.rotation_deg == pytest.approx(15.0)
    assert load_placement().rotation_deg == pytest.approx(15.0)
    start = _pixel(canvas, widget.placement.to_wgs84(5.0, 5.0))
    _drag(widget.move_tool, canvas, start, (start[0] + 50, start[1]))
    assert widget.lon_spin.value() == pytest.approx(widget.placement.anchor_lon)
    assert widget.placement.anchor_lon > widget.lon_spin.minimum()
    assert load_placement() == widget.placement
    widget.gcp_button.setChecked(True)
    assert canvas.mapTool() is widget.gcp_tool
    assert widget.rms_label.text().startswith("RMS: –")
    widget.remove_overlay()


def test_plugin_menu_opens_the_placement_panel(qgis_iface, qgis_app, qgis_new_project):
    plugin = plugin_package().classFactory(qgis_iface)
    plugin.initGui()
    try:
        labels = [a.text() for a in plugin.actions]
        assert "Place a floor plan on the map…" in labels
        dock = plugin.show_placement()
        assert dock.widget.load_button.text() == "Load floor plan…"
        assert plugin.show_placement() is dock
    finally:
        plugin.unload()
    assert plugin.placement_dock is None


def test_panel_loads_the_sample_building_through_extractstructure_and_saves_a_screenshot(
        provider, plan_canvas, tmp_path, repo_root):
    from algorithms.sample_building import generate_building
    from cad2osmag.ui.placement_dock import PlacementWidget

    canvas, old_overlay, _ = plan_canvas
    from qgis.core import QgsProject

    QgsProject.instance().removeMapLayer(old_overlay.layer.id())
    sample = generate_building(str(tmp_path), floors=1, seed=0)
    widget = PlacementWidget(canvas)
    widget.resize(420, 640)
    overlay = widget.load_file(sample["dxf"][0])
    assert overlay is not None, widget.plan_label.text()
    assert len(overlay.cad_lines) > 100
    b = overlay.cad_box
    assert 20 < b.width() < 200 and 10 < b.height() < 200  # metres
    # the plan's centre is at the centre of the canvas it was loaded into, north up
    assert widget.placement.rotation_deg == pytest.approx(0.0)
    start = (400, 300)
    tool = widget.move_tool
    handle = canvas.getCoordinateTransform().transform(tool.handle_points()["rotate"])
    pivot = canvas.getCoordinateTransform().transform(tool.handle_points()["pivot"])
    r = math.hypot(handle.x() - pivot.x(), handle.y() - pivot.y())
    _drag(tool, canvas, (handle.x(), handle.y()), (pivot.x() + r * math.sin(math.radians(-20)),
                                                    pivot.y() - r * math.cos(math.radians(-20))))
    assert widget.rot_spin.value() == pytest.approx(340.0, abs=0.5)
    _drag(tool, canvas, start, (start[0] + 60, start[1] - 30))
    assert widget.rot_spin.value() == pytest.approx(340.0, abs=0.5)
    # screenshots for the README
    art = repo_root / "tests" / "artifacts"
    art.mkdir(parents=True, exist_ok=True)
    canvas.setLayers([overlay.layer])  # QGIS's own canvas follows the layer tree; a bare canvas does not
    canvas.refresh()
    canvas.waitWhileRendering()
    tool.refresh_decorations()
    canvas.grab().save(str(art / "placement_canvas.png"))
    widget.grab().save(str(art / "placement_panel.png"))
    assert (art / "placement_canvas.png").stat().st_size > 1000
    widget.remove_overlay()
