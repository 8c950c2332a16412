"""The *Place the plan on the map* panel: load a floor over a basemap, move/rotate/scale it with the mouse
or with control points, see the Helmert RMS live; the placement is saved with the project."""
from __future__ import annotations

import os

from qgis.core import QgsCoordinateReferenceSystem, QgsProject
from qgis.PyQt.QtCore import QCoreApplication, Qt, pyqtSignal
from qgis.PyQt.QtWidgets import (
    QAbstractItemView,
    QButtonGroup,
    QCheckBox,
    QDockWidget,
    QDoubleSpinBox,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from . import basemaps
from .placement import (
    GcpMapTool,
    PlacementMapTool,
    PlanOverlay,
    initial_placement,
    load_placement,
    save_placement,
    structure_layer,
)
from .placement_math import Placement


def tr(text):
    return QCoreApplication.translate("PlacementDock", text)


class PlacementWidget(QWidget):
    """The panel's contents (also embedded in the conversion wizard)."""

    placementChanged = pyqtSignal(object)

    def __init__(self, canvas, parent=None, project=None):
        super().__init__(parent)
        self.canvas = canvas
        self.project = project or QgsProject.instance()
        self.overlay = None
        self.placement = None
        self.move_tool = None
        self.gcp_tool = None
        self._previous_tool = None
        self._updating = False

        lay = QVBoxLayout(self)
        row = QHBoxLayout()
        self.load_button = QPushButton(tr("Load floor plan…"))
        self.load_button.clicked.connect(self.choose_file)
        self.osm_button = QPushButton(tr("OSM basemap"))
        self.osm_button.clicked.connect(lambda: self.add_basemap("osm"))
        self.sat_button = QPushButton(tr("Satellite basemap"))
        self.sat_button.clicked.connect(lambda: self.add_basemap("satellite"))
        for b in (self.load_button, self.osm_button, self.sat_button):
            row.addWidget(b)
        lay.addLayout(row)
        self.plan_label = QLabel(tr("No plan loaded."))
        self.plan_label.setWordWrap(True)
        lay.addWidget(self.plan_label)

        row = QHBoxLayout()
        self.move_button = QPushButton(tr("Move / rotate / scale"))
        self.move_button.setToolTip(tr("Drag the plan to move it, the round handle to rotate it (Shift: whole "
                                       "degrees), the square handle to scale it."))
        self.gcp_button = QPushButton(tr("Control points"))
        self.gcp_button.setToolTip(tr("Click a point of the drawing, then the same point on the basemap; repeat "
                                      "(right click cancels a half pair)."))
        self.tool_group = QButtonGroup(self)
        for b in (self.move_button, self.gcp_button):
            b.setCheckable(True)
            self.tool_group.addButton(b)
            row.addWidget(b)
        self.move_button.toggled.connect(lambda on: on and self.activate_tool("move"))
        self.gcp_button.toggled.connect(lambda on: on and self.activate_tool("gcp"))
        lay.addLayout(row)

        form = QFormLayout()
        self.lon_spin = self._spin(-180, 180, 8, " °")
        self.lat_spin = self._spin(-85, 85, 8, " °")
        self.rot_spin = self._spin(-360, 360, 3, " °")
        self.scale_spin = self._spin(0.001, 1000, 5, "")
        self.scale_spin.setValue(1.0)
        form.addRow(tr("Drawing origin longitude"), self.lon_spin)
        form.addRow(tr("Drawing origin latitude"), self.lat_spin)
        form.addRow(tr("Rotation (clockwise from north)"), self.rot_spin)
        form.addRow(tr("Scale (ground m per drawing m)"), self.scale_spin)
        lay.addLayout(form)
        for s in (self.lon_spin, self.lat_spin, self.rot_spin, self.scale_spin):
            s.valueChanged.connect(self._spins_edited)

        self.snap_edges = QCheckBox(tr("Snap the rotation to building edges (polygon layers on the map, within 3°)"))
        self.snap_edges.setToolTip(tr("Load building footprints (e.g. OpenStreetMap buildings) as a vector layer: "
                                      "while you turn the plan, its walls snap to their edges. Shift turns in "
                                      "whole degrees instead."))
        self.snap_edges.setChecked(True)
        self.snap_edges.toggled.connect(self._snap_toggled)
        lay.addWidget(self.snap_edges)
        self.fix_scale = QCheckBox(tr("Control points: keep the scale (solve position and rotation only)"))
        lay.addWidget(self.fix_scale)
        self.gcp_table = QTableWidget(0, 5)
        self.gcp_table.setHorizontalHeaderLabels([tr("Drawing x (m)"), tr("Drawing y (m)"), tr("Longitude"),
                                                  tr("Latitude"), tr("Residual (m)")])
        self.gcp_table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.gcp_table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        lay.addWidget(self.gcp_table)
        row = QHBoxLayout()
        self.rms_label = QLabel(tr("RMS: – (add at least 2 control points)"))
        self.remove_button = QPushButton(tr("Remove point"))
        self.remove_button.clicked.connect(self.remove_selected_gcp)
        row.addWidget(self.rms_label, 1)
        row.addWidget(self.remove_button)
        lay.addLayout(row)
        self.note = QLabel(tr("The placement is saved with the project and used for every floor of the building."))
        self.note.setWordWrap(True)
        lay.addWidget(self.note)
        lay.addStretch(1)

    @staticmethod
    def _spin(lo, hi, decimals, suffix):
        s = QDoubleSpinBox()
        s.setRange(lo, hi)
        s.setDecimals(decimals)
        s.setSuffix(suffix)
        s.setKeyboardTracking(False)
        return s

    # ------------------------------------------------------------------ loading
    def add_basemap(self, kind):
        layer = basemaps.add_xyz_basemap(kind, self.project)
        if layer is not None and not self.project.crs().isValid():
            self.project.setCrs(QgsCoordinateReferenceSystem("EPSG:3857"))
        return layer

    def choose_file(self):
        path, _ = QFileDialog.getOpenFileName(self, tr("Floor plan"), "", tr("CAD drawings (*.dxf *.dwg *.DXF *.DWG)"))
        if path:
            self.load_file(path)

    def load_file(self, path, plan=None):
        """Structure lines of a DXF/DWG (through cad2osmag:extractstructure) over the map; ``plan`` is the
        PLAN of a whole sheet (an index or 'xmin,ymin,xmax,ymax'; None / '' = the main plan)."""
        try:
            layer = structure_layer(path, plan=plan)
        except Exception as exc:  # noqa: BLE001 - shown to the user, the panel stays usable
            self.plan_label.setText(tr("Cannot load {}: {}").format(os.path.basename(path), exc))
            return None
        return self.load_layer(layer)

    def load_layer(self, layer):
        """Any layer in the CAD frame (metres) as the plan to place."""
        self.remove_overlay()
        self.overlay = PlanOverlay.from_layer(layer, project=self.project)
        self.project.addMapLayer(self.overlay.layer)
        if not self.canvas.mapSettings().destinationCrs().isValid():
            self.canvas.setDestinationCrs(QgsCoordinateReferenceSystem("EPSG:3857"))
        self.set_placement(initial_placement(self.canvas, self.overlay, self.project), save=False)
        b = self.overlay.cad_box
        self.plan_label.setText(tr("{}: {} lines, {:.1f} × {:.1f} m").format(
            layer.name(), len(self.overlay.cad_lines), b.width(), b.height()))
        self.zoom_to_plan()
        self.move_button.setChecked(True)
        self.activate_tool("move")
        return self.overlay

    def zoom_to_plan(self):
        from qgis.core import QgsCoordinateTransform

        ext = QgsCoordinateTransform(self.overlay.layer.crs(), self.canvas.mapSettings().destinationCrs(),
                                     self.project).transformBoundingBox(self.overlay.layer.extent())
        ext.scale(1.4)
        self.canvas.setExtent(ext)
        self.canvas.refresh()

    def remove_overlay(self):
        self.deactivate_tools()
        if self.overlay is not None and self.project.mapLayer(self.overlay.layer.id()) is not None:
            self.project.removeMapLayer(self.overlay.layer.id())
        self.overlay = None

    # ------------------------------------------------------------------ tools
    def activate_tool(self, which):
        if self.overlay is None or self.placement is None:
            return None
        current = self.canvas.mapTool()
        if current is not None and current not in (self.move_tool, self.gcp_tool):
            self._previous_tool = current  # given back when the plan is removed
        if which == "gcp":
            if self.gcp_tool is None:
                self.gcp_tool = GcpMapTool(self.canvas, self.overlay, self.placement)
                self.gcp_tool.placementChanged.connect(lambda p: self.set_placement(p, from_tool=True))
                self.gcp_tool.gcpsChanged.connect(self.show_gcps)
            self.gcp_tool.placement = self.placement
            self.gcp_tool.fix_scale = self.fix_scale.isChecked()
            tool = self.gcp_tool
        else:
            if self.move_tool is None:
                self.move_tool = PlacementMapTool(self.canvas, self.overlay, self.placement,
                                                  snap_to_buildings=self.snap_edges.isChecked())
                self.move_tool.placementChanged.connect(self._moved_by_tool)
            self.move_tool.placement = self.placement
            tool = self.move_tool
        self.canvas.setMapTool(tool)
        return tool

    def deactivate_tools(self):
        for t in (self.move_tool, self.gcp_tool):
            if t is not None:
                t.deactivate()
                self.canvas.unsetMapTool(t)
        self.move_tool = self.gcp_tool = None
        if self._previous_tool is not None:
            try:
                self.canvas.setMapTool(self._previous_tool)
            except RuntimeError:
                pass
            self._previous_tool = None

    # ------------------------------------------------------------------ the placement
    def set_placement(self, placement: Placement, save=True, from_tool=False):
        self.placement = placement
        if self.overlay is not None and not from_tool:
            self.overlay.update_layer(placement)
        for t in (self.move_tool, self.gcp_tool):
            if t is not None and t.placement is not placement:
                t.set_placement(placement, redraw_layer=False)
        self._updating = True
        try:
            self.lon_spin.setValue(placement.anchor_lon)
            self.lat_spin.setValue(placement.anchor_lat)
            self.rot_spin.setValue(placement.rotation_deg)
            self.scale_spin.setValue(placement.scale)
        finally:
            self._updating = False
        self.show_gcps(placement.gcps)
        if save:
            save_placement(placement, self.project)
        self.placementChanged.emit(placement)

    def _snap_toggled(self, on):
        if self.move_tool is not None:
            self.move_tool.snap_to_buildings = bool(on)

    def _moved_by_tool(self, placement):
        self.set_placement(placement, from_tool=True)
        tool = self.move_tool
        if tool is not None and tool.snapped is not None:
            self.note.setText(tr("Rotation snapped to the building edges at {:.1f}° (modulo 90°).").format(
                tool.snapped))
        else:
            self.note.setText(tr("The placement is saved with the project and used for every floor of the building."))

    def _spins_edited(self):
        if self._updating or self.placement is None:
            return
        p = Placement(self.lon_spin.value(), self.lat_spin.value(), self.rot_spin.value() % 360.0,
                      self.scale_spin.value(), list(self.placement.gcps), None)
        self.set_placement(p)

    def show_gcps(self, gcps):
        self.gcp_table.setRowCount(len(gcps))
        for r, g in enumerate(gcps):
            values = [f"{g.cad_x:.3f}", f"{g.cad_y:.3f}", f"{g.lon:.8f}", f"{g.lat:.8f}",
                      "–" if g.residual is None else f"{g.residual:.3f}"]
            for c, v in enumerate(values):
                item = QTableWidgetItem(v)
                item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
                self.gcp_table.setItem(r, c, item)
        tool = self.gcp_tool
        error = getattr(tool, "error", None) if tool is not None else None
        rms = tool.rms if tool is not None else (self.placement.rms if self.placement else None)
        if error:
            self.rms_label.setText(tr("Cannot fit: {}").format(error))
        elif len(gcps) >= 2 and rms is not None:
            self.rms_label.setText(tr("RMS: {:.3f} m ({} points)").format(rms, len(gcps)))
        else:
            self.rms_label.setText(tr("RMS: – (add at least 2 control points)"))

    def remove_selected_gcp(self):
        rows = sorted({i.row() for i in self.gcp_table.selectedIndexes()}, reverse=True)
        if self.gcp_tool is None or not rows:
            return
        for r in rows:
            self.gcp_tool.remove(r)

    def closeEvent(self, event):  # noqa: N802
        self.deactivate_tools()
        super().closeEvent(event)


class PlacementDock(QDockWidget):
    def __init__(self, iface, parent=None):
        super().__init__(tr("Place the plan on the map"), parent or iface.mainWindow())
        self.setObjectName("Cad2OsmagPlacementDock")
        self.widget = PlacementWidget(iface.mapCanvas(), self)
        self.setWidget(self.widget)
        saved = load_placement()
        if saved is not None:
            self.widget.placement = saved
            self.widget.set_placement(saved, save=False)
