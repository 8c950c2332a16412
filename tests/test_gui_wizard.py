"""The guided conversion (ui/convert_wizard.py) stepped through headless on the sample building: files and
their layers, settings in metres, placement by dragging, conversion as a QgsTask, styled floors on the map.
Screenshots of every page go to tests/artifacts/ (the README's images)."""
import math
import os
import time

import pytest

from algorithms import osmag
from algorithms.sample_building import generate_building

from .conftest import plugin_package


def _wait(predicate, timeout=300):
    from qgis.core import QgsApplication

    t0 = time.time()
    while not predicate():
        QgsApplication.processEvents()
        time.sleep(0.05)
        assert time.time() - t0 < timeout, "timed out"



def _drag(canvas, tool, a, b):
    """A left-button drag from canvas pixel a to b, delivered to the map tool as QGIS would."""
    from qgis.gui import QgsMapMouseEvent
    from qgis.PyQt.QtCore import QEvent, QPoint, Qt

    for kind, p, btn, btns in ((QEvent.Type.MouseButtonPress, a, Qt.MouseButton.LeftButton,
                                Qt.MouseButton.LeftButton),
                               (QEvent.Type.MouseMove, b, Qt.MouseButton.NoButton, Qt.MouseButton.LeftButton),
                               (QEvent.Type.MouseButtonRelease, b, Qt.MouseButton.LeftButton,
                                Qt.MouseButton.NoButton)):
        e = QgsMapMouseEvent(canvas, kind, QPoint(int(p[0]), int(p[1])), btn, btns, Qt.KeyboardModifier.NoModifier)
        {QEvent.Type.MouseButtonPress: tool.canvasPressEvent, QEvent.Type.MouseMove: tool.canvasMoveEvent,
         QEvent.Type.MouseButtonRelease: tool.canvasReleaseEvent}[kind](e)

def test_wizard_converts_two_floors_placed_by_dragging(provider, qgis_iface, qgis_new_project, tmp_path, repo_root):
    from qgis.core import QgsCoordinateReferenceSystem, QgsProject, QgsRectangle
    from qgis.gui import QgsMapCanvas
    from qgis.PyQt.QtCore import Qt

    from cad2osmag.ui.convert_wizard import ConvertWizard
    from cad2osmag.ui.placement import load_placement

    art = repo_root / "tests" / "artifacts"
    art.mkdir(parents=True, exist_ok=True)
    QgsProject.instance().removeEntry("cad2osmag", "placement")  # qgis_new_project keeps custom entries
    sample = generate_building(str(tmp_path / "dxf"), floors=2, seed=4)
    canvas = QgsMapCanvas()
    canvas.resize(700, 500)
    canvas.setDestinationCrs(QgsCoordinateReferenceSystem("EPSG:3857"))
    canvas.setExtent(QgsRectangle(13535000, 3656000, 13535300, 3656200))  # Shanghai, web mercator
    canvas.show()
    wiz = ConvertWizard(canvas)
    wiz.show()

    # 1. files and their layers
    page = wiz.files_page
    page.add_files(sample["dxf"])
    assert page.paths() == sample["dxf"] and page.isComplete()
    assert page.layers.rowCount() >= 3
    kept = {page.layers.item(r, 0).text(): page.layers.item(r, 2).text() for r in range(page.layers.rowCount())}
    assert any(v == "yes" for v in kept.values()) and any(v == "no" for v in kept.values())
    wiz.grab().save(str(art / "wizard_1_files.png"))
    wiz.next()

    # 2. settings in metres
    s = wiz.settings_page
    assert wiz.currentPage() is s
    assert s.resolution.value() == pytest.approx(0.044) and s.door_width.suffix() == " m"
    s.first_level.setValue(0)
    s.min_area.setValue(8.0)
    s.resolution.setValue(0.05)
    task = s.preview()
    assert task is not None and not s.preview_button.isEnabled()
    _wait(lambda: s.preview_button.isEnabled())
    assert len(s.canvas.layers()) == 4, s.preview_status.text()
    n_preview = int(s.preview_status.text().split()[0])
    assert n_preview >= 15
    assert s.preview_layers[3].rasterUnitsPerPixelX() == pytest.approx(0.05)
    s.canvas.refresh()
    s.canvas.waitWhileRendering()
    wiz.grab().save(str(art / "wizard_2_settings.png"))
    wiz.next()

    # 3. placement: the first floor's walls over the map, dragged and turned with the mouse
    panel = wiz.placement_page.panel
    assert panel.overlay is not None and canvas.mapTool() is panel.move_tool
    tool = panel.move_tool
    before = panel.placement
    ct = canvas.getCoordinateTransform()

    def drag(a, b):
        _drag(canvas, tool, a, b)

    centre = ct.transform(tool.handle_points()["pivot"])
    drag((centre.x() - 30, centre.y() + 10), (centre.x() + 10, centre.y() - 20))
    handle = ct.transform(tool.handle_points()["rotate"])
    pivot = ct.transform(tool.handle_points()["pivot"])
    r = math.hypot(handle.x() - pivot.x(), handle.y() - pivot.y())
    drag((handle.x(), handle.y()), (pivot.x() + r * math.sin(math.radians(12)), pivot.y() - r * math.cos(math.radians(12))))
    placed = panel.placement
    assert placed.rotation_deg == pytest.approx(12.0, abs=0.6)
    assert placed.anchor_lon != pytest.approx(before.anchor_lon, abs=1e-9)
    assert load_placement() == placed  # saved with the project
    assert panel.rot_spin.value() == pytest.approx(placed.rotation_deg, abs=1e-3)  # 3 decimals shown
    canvas.setLayers([panel.overlay.layer])
    canvas.refresh()
    canvas.waitWhileRendering()
    wiz.grab().save(str(art / "wizard_3_placement.png"))
    canvas.grab().save(str(art / "wizard_3_canvas.png"))
    wiz.next()

    # 4. convert both floors as a task, merged building too, styled layers added
    run = wiz.run_page
    out = tmp_path / "out"
    run.folder.setText(str(out))
    assert not run.isComplete()
    task = run.start()
    assert task is not None and run.cancel_button.isEnabled()
    _wait(lambda: run.run_button.isEnabled())
    assert run.done, run.log.toPlainText()
    assert run.progress.value() == 100
    for k, dxf in enumerate(sample["dxf"]):
        osm = out / (os.path.splitext(os.path.basename(dxf))[0] + ".osm")
        areas, passages, root, _ = osmag.read_osmag(str(osm))
        assert root == pytest.approx((placed.anchor_lon, placed.anchor_lat), abs=1e-9)
        assert {a.tags.get("level") for a in areas if a.type != "structure"} == {str(k)}
        assert len(areas) >= 15
    assert (out / "building.osm").is_file()
    names = sorted(layer.name() for layer in QgsProject.instance().mapLayers().values())
    assert sum(n.endswith(" areas") for n in names) == 2 and sum(n.endswith(" passages") for n in names) == 2
    styled = [layer for layer in QgsProject.instance().mapLayers().values() if layer.name().endswith(" areas")]
    assert all(layer.renderer().type() == "categorizedSymbol" for layer in styled)
    wiz.grab().save(str(art / "wizard_4_done.png"))

    # 5. names and types: rename one room, make another a corridor, export again
    wiz.next()
    names = wiz.names_page
    assert wiz.currentPage() is names
    n_areas = sum(len(osmag.read_osmag(str(out / (os.path.splitext(os.path.basename(d))[0] + ".osm")))[0])
                  for d in sample["dxf"])
    assert names.table.rowCount() == n_areas
    rooms = [r for r in range(names.table.rowCount()) if names.table.cellWidget(r, 3).currentText() == "room"]
    names.table.item(rooms[0], 2).setText("Server room")
    names.table.cellWidget(rooms[1], 3).setCurrentText("corridor")
    renamed_id, level = names.table.item(rooms[0], 1).text(), names.table.item(rooms[0], 0).text()
    retyped_id = names.table.item(rooms[1], 1).text()
    task = names.save()
    _wait(lambda: names.save_button.isEnabled())
    assert "2 areas changed" in names.status.text(), names.status.text()
    k = int(level)
    osm = out / (os.path.splitext(os.path.basename(sample["dxf"][k]))[0] + ".osm")
    areas, _, root, _ = osmag.read_osmag(str(osm))
    assert root == pytest.approx((placed.anchor_lon, placed.anchor_lat), abs=1e-9)
    assert "Server room" in {a.name for a in areas}
    assert sum(a.type == "corridor" for a in areas) >= 1
    building, _, _, _ = osmag.read_osmag(str(out / "building.osm"))
    assert "Server room" in {a.name for a in building}
    assert renamed_id != retyped_id
    wiz.grab().save(str(art / "wizard_5_names.png"))
    canvas.setLayers([layer for layer in QgsProject.instance().mapLayers().values()
                      if layer.name().endswith(("areas", "passages"))])
    canvas.refresh()
    canvas.waitWhileRendering()
    canvas.grab().save(str(art / "wizard_4_canvas.png"))
    wiz.done(0)
    assert canvas.mapTool() is not tool
    canvas.close()


def test_wizard_task_can_be_canceled(provider, qgis_new_project, tmp_path):
    from cad2osmag.ui.convert_wizard import AlgorithmsTask
    from qgis.core import QgsApplication, QgsTask

    sample = generate_building(str(tmp_path / "dxf"), floors=2, seed=5)
    steps = [("cad2osmag:dxftoosmag", {"INPUT": p, "OUTPUT": str(tmp_path / f"f{k}.osm")})
             for k, p in enumerate(sample["dxf"])]
    task = AlgorithmsTask("cancel me", steps)
    QgsApplication.taskManager().addTask(task)
    _wait(lambda: task.status() == QgsTask.TaskStatus.Running)
    task.cancel()
    _wait(lambda: task.status() in (QgsTask.TaskStatus.Terminated, QgsTask.TaskStatus.Complete))
    assert task.status() == QgsTask.TaskStatus.Terminated
    assert not (tmp_path / "f1.osm").exists()


def test_wizard_lists_the_plans_of_a_sheet_and_passes_the_pick_as_plan(provider, qgis_new_project, tmp_path,
                                                                        repo_root):
    """A whole sheet (floor plan + enlarged stair detail, titled): the plans are listed with their titles,
    the main plan is pre-selected, picking the detail or drawing an extent changes PLAN everywhere."""
    from qgis.core import QgsCoordinateReferenceSystem, QgsProject, QgsRectangle
    from qgis.gui import QgsMapCanvas
    from qgis.PyQt.QtCore import Qt

    from algorithms.sample_building import generate_delivered
    from cad2osmag.ui.convert_wizard import ConvertWizard

    QgsProject.instance().removeEntry("cad2osmag", "placement")
    out = generate_delivered(str(tmp_path), sheet=True, name="sheet")
    canvas = QgsMapCanvas()
    canvas.resize(600, 400)
    canvas.setDestinationCrs(QgsCoordinateReferenceSystem("EPSG:3857"))
    canvas.setExtent(QgsRectangle(13535000, 3656000, 13535300, 3656200))
    wiz = ConvertWizard(canvas)
    wiz.show()
    page = wiz.files_page
    path = out["dxf"]
    assert page.plan_parameter(path) == ""  # before the sheet is read: the algorithms' main plan
    page.add_files([path])
    _wait(lambda: page.plans_ready(path), timeout=240)
    assert page.plans.rowCount() == 2, page.plan_status.text()
    assert page.plans.item(0, 1).text() == "plan" and page.plans.item(1, 1).text() == "detail"
    assert "平面图" in page.plans.item(0, 3).text() and "详图" in page.plans.item(1, 3).text()
    assert page.plans.item(0, 2).text() == "40 × 25 m"
    assert [i.row() for i in page.plans.selectionModel().selectedRows()] == [0]  # the main plan, pre-selected
    assert page.plan_parameter(path) == "0" and "[0]" in page.plan_status.text()
    assert len(page.sheet_canvas.layers()) == 2  # plan rectangles over the whole sheet's lines
    page.sheet_canvas.refresh()
    page.sheet_canvas.waitWhileRendering()
    art = repo_root / "tests" / "artifacts"
    art.mkdir(parents=True, exist_ok=True)
    assert wiz.grab().save(str(art / "wizard_1_plans.png"))
    # a click inside the detail's rectangle on the sheet picks it (then the main plan, clicked, again)
    from qgis.core import QgsPointXY

    x0, y0, x1, y1 = out["detail_extent"]
    page._click_tool.canvasClicked.emit(QgsPointXY((x0 + x1) / 2, (y0 + y1) / 2), Qt.MouseButton.LeftButton)
    assert page.plan_parameter(path) == "1"
    page._click_tool.canvasClicked.emit(QgsPointXY(10, 10), Qt.MouseButton.LeftButton)
    assert page.plan_parameter(path) == "0"
    # the user picks the stair detail in the list: every algorithm of the wizard gets PLAN=1
    page.pick_plan(1)
    assert page.plan_parameter(path) == "1" and "detail" in page.plan_status.text()
    wiz.run_page.folder.setText(str(tmp_path / "out"))
    steps = wiz.run_page.steps()
    assert steps[0][0] == "cad2osmag:dxftoosmag" and steps[0][1]["PLAN"] == "1"
    wiz.next()
    wiz.next()  # placement: the detail's lines are the plan placed
    panel = wiz.placement_page.panel
    x0, y0, x1, y1 = out["detail_extent"]
    b = panel.overlay.cad_box
    assert b.xMinimum() >= x0 - 1 and b.xMaximum() <= x1 + 1 and b.width() < 10
    # back to the files: an extent drawn over the sheet (the tool's signal) becomes PLAN
    wiz.back()
    wiz.back()
    page.extent_button.setChecked(True)
    page._extent_map_tool.extentChanged.emit(QgsRectangle(-1, -1, 20, 26))
    assert not page.extent_button.isChecked()
    assert page.plan_parameter(path) == "-1.000,-1.000,20.000,26.000"
    assert not page.plans.selectionModel().selectedRows()
    assert wiz.run_page.steps()[0][1]["PLAN"] == "-1.000,-1.000,20.000,26.000"
    wiz.next()
    wiz.next()
    b = panel.overlay.cad_box
    assert b.xMaximum() <= 22 and b.width() > 15  # the west part of the floor plan only
    wiz.done(0)
    canvas.close()


@pytest.mark.slow
def test_wizard_converts_a_dwg_sheet_placed_on_the_satellite_basemap(provider, qgis_new_project, tmp_path,
                                                                     repo_root, shared_data, monkeypatch):
    """Done when: a DWG sheet as delivered (SIST-F1.dwg: 150+ layers, frames, bound xrefs) through the GUI:
    its plans listed with the main one pre-selected (another extent changes PLAN), the settings preview,
    the plan dragged and turned over the satellite basemap, the conversion, the styled, named floor on the
    map. No network here: the basemap layer is in the project, its tiles are not fetched."""
    from qgis.core import QgsCoordinateReferenceSystem, QgsProject, QgsRectangle
    from qgis.gui import QgsMapCanvas
    from qgis.PyQt.QtCore import Qt

    from cad2osmag.ui.convert_wizard import ConvertWizard
    from cad2osmag.ui.placement import load_placement

    dwg = shared_data / "dwg" / "sist-original" / "SIST-F1.dwg"
    if not dwg.is_file():
        pytest.skip(f"{dwg} is missing")
    art = repo_root / "tests" / "artifacts"
    art.mkdir(parents=True, exist_ok=True)
    QgsProject.instance().removeEntry("cad2osmag", "placement")
    canvas = QgsMapCanvas()
    canvas.resize(700, 500)
    canvas.setDestinationCrs(QgsCoordinateReferenceSystem("EPSG:3857"))
    canvas.setExtent(QgsRectangle(13535000, 3656000, 13535400, 3656300))  # Shanghai, web mercator
    canvas.show()
    wiz = ConvertWizard(canvas)
    wiz.show()

    # 1. the DWG is accepted, its layers and the plans on the sheet are listed, the main plan pre-selected
    page = wiz.files_page
    path = str(dwg)
    from qgis.PyQt.QtWidgets import QFileDialog

    filters = []

    def chooser(*args):
        filters.append(args[3])
        return ([path], args[3]) if len(filters) == 1 else (path, args[3])

    monkeypatch.setattr(QFileDialog, "getOpenFileNames", staticmethod(chooser))
    monkeypatch.setattr(QFileDialog, "getOpenFileName", staticmethod(chooser))
    page.add_button.click()  # *Add files…*: the chooser offers DWG files
    assert "*.dwg" in filters[0] and page.paths() == [path]
    assert page.layers.rowCount() > 150  # listlayers on the DWG
    _wait(lambda: page.plans_ready(path), timeout=600)
    assert page.plans.rowCount() >= 1 and page.plans.item(0, 1).text() == "plan", page.plan_status.text()
    assert page.plans.item(0, 0).text().endswith("★")
    assert [i.row() for i in page.plans.selectionModel().selectedRows()] == [0]
    assert page.plan_parameter(path) == "0"
    w, h = (float(v) for v in page.plans.item(0, 2).text().replace(" m", "").split(" × "))
    assert 150 < w < 200 and 120 < h < 170  # the floor, not the sheet with its frame
    page.sheet_canvas.refresh()
    page.sheet_canvas.waitWhileRendering()
    assert wiz.grab().save(str(art / "wizard_dwg_1_plans.png"))
    # another choice (an extent drawn over the sheet) changes PLAN, the main plan can be picked back
    page.pick_extent(QgsRectangle(1300, -10, 1400, 150))
    assert page.plan_parameter(path) == "1300.000,-10.000,1400.000,150.000"
    wiz.run_page.folder.setText(str(tmp_path / "out"))
    assert wiz.run_page.steps()[0][1]["PLAN"] == "1300.000,-10.000,1400.000,150.000"
    page.pick_plan(0)
    assert page.plan_parameter(path) == "0"
    wiz.next()

    # 2. settings and the preview of the areas (coarser pixels: the floor is 178 x 149 m)
    s = wiz.settings_page
    s.resolution.setValue(0.08)
    s.preview()
    _wait(lambda: s.preview_button.isEnabled(), timeout=900)
    assert len(s.canvas.layers()) == 4, s.preview_status.text()
    assert int(s.preview_status.text().split()[0]) >= 40
    s.canvas.refresh()
    s.canvas.waitWhileRendering()
    assert wiz.grab().save(str(art / "wizard_dwg_2_settings.png"))
    wiz.next()

    # 3. placement over the satellite basemap: drag, then turn
    panel = wiz.placement_page.panel
    assert panel.overlay is not None and canvas.mapTool() is panel.move_tool
    assert 150 < panel.overlay.cad_box.width() < 200
    panel.load_button.click()  # the panel's own *Load floor plan…* takes the DWG too
    assert "*.dwg" in filters[1] and panel.plan_label.text().startswith("SIST-F1:"), panel.plan_label.text()
    tool_changed = panel.move_tool
    assert canvas.mapTool() is tool_changed
    panel.sat_button.click()
    sat = [lyr for lyr in QgsProject.instance().mapLayers().values() if lyr.name() == "Esri World Imagery"]
    assert len(sat) == 1 and sat[0].isValid() and "World_Imagery" in sat[0].source()
    tool = panel.move_tool
    ct = canvas.getCoordinateTransform()

    def drag(a, b):
        _drag(canvas, tool, a, b)

    before = panel.placement
    centre = ct.transform(tool.handle_points()["pivot"])
    drag((centre.x() - 40, centre.y() + 10), (centre.x() + 20, centre.y() - 25))
    handle = ct.transform(tool.handle_points()["rotate"])
    pivot = ct.transform(tool.handle_points()["pivot"])
    r = math.hypot(handle.x() - pivot.x(), handle.y() - pivot.y())
    drag((handle.x(), handle.y()), (pivot.x() + r * math.sin(math.radians(-15)),
                                    pivot.y() - r * math.cos(math.radians(-15))))
    placed = panel.placement
    assert placed.rotation_deg == pytest.approx(345.0, abs=0.6)
    assert placed.anchor_lon != pytest.approx(before.anchor_lon, abs=1e-9)
    assert load_placement() == placed
    canvas.setLayers([panel.overlay.layer])  # the satellite tiles cannot be fetched here
    canvas.refresh()
    canvas.waitWhileRendering()
    assert wiz.grab().save(str(art / "wizard_dwg_3_placement.png"))
    wiz.next()

    # 4. convert: the styled floor, named, on the map
    run = wiz.run_page
    out = tmp_path / "out"
    run.start()
    _wait(lambda: run.run_button.isEnabled(), timeout=1800)
    assert run.done, run.log.toPlainText()
    areas, passages, root, _ = osmag.read_osmag(str(out / "SIST-F1.osm"))
    assert root == pytest.approx((placed.anchor_lon, placed.anchor_lat), abs=1e-9)
    assert len(areas) >= 40 and len(passages) >= 40
    layers = {lyr.name(): lyr for lyr in QgsProject.instance().mapLayers().values()}
    assert {"SIST-F1 areas", "SIST-F1 passages"} <= set(layers)
    area_layer = layers["SIST-F1 areas"]
    assert area_layer.renderer().type() == "categorizedSymbol" and area_layer.labelsEnabled()
    named = [f["name"] for f in area_layer.getFeatures() if f["name"]]
    assert len(named) >= 10, named  # room names read from the sheet's texts and attributes
    assert {f["osmAG:areatype"] for f in area_layer.getFeatures()} >= {"room", "corridor", "stairs"}
    ext = area_layer.extent()
    lon, lat = placed.to_wgs84(*panel.overlay.centre)  # the floor lies where the plan was dragged to
    assert ext.xMinimum() < lon < ext.xMaximum() and ext.yMinimum() < lat < ext.yMaximum()
    assert ext.width() < 0.003 and ext.height() < 0.003  # about 180 x 150 m
    assert wiz.grab().save(str(art / "wizard_dwg_4_done.png"))
    canvas.setLayers([layers["SIST-F1 passages"], area_layer])
    canvas.setExtent(canvas.mapSettings().layerExtentToOutputExtent(area_layer, ext))
    canvas.refresh()
    canvas.waitWhileRendering()
    assert canvas.grab().save(str(art / "wizard_dwg_4_canvas.png"))
    wiz.next()
    assert wiz.names_page.table.rowCount() == len(areas)
    wiz.done(0)
    canvas.close()
