"""*Convert a floor plan…*: one guided conversion that runs the Processing algorithms (no second
implementation) step by step:

1. floor plans: pick DXF/DWG files (several floors at once); the layers of the selected file and whether the
   layer rules keep them (``cad2osmag:listlayers``); the plans found on each sheet (``cad2osmag:listplans``:
   index, kind, size, title), the main plan pre-selected, another one or an extent drawn over the sheet
   picked by the user: the PLAN of every algorithm run for that file;
2. settings in metres: raster resolution, widest door, corridor width, smallest area, first level, floor
   height;
3. placement on the basemap (the *Place the plan on the map* panel, embedded: drag, rotate, scale or
   control points; saved with the project);
4. conversion: one osmAG file per floor (``cad2osmag:dxftoosmag``) or also the merged building
   (``cad2osmag:mergefloors``), run as a QgsTask with progress and cancel; the styled floors are added to
   the map;
5. names and types of the areas in an editable table; saving writes them into the floors' layers and
   exports the osmAG files again (``cad2osmag:exportosmag``, ``mergefloors``).
"""
from __future__ import annotations

import os
from typing import List, Optional

from qgis.core import (
    QgsApplication,
    QgsWkbTypes,
    QgsProcessingContext,
    QgsProcessingFeedback,
    QgsProject,
    QgsTask,
    QgsVectorLayer,
)
from qgis.PyQt.QtCore import QCoreApplication, Qt, pyqtSignal
from qgis.PyQt.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
    QDoubleSpinBox,
    QFileDialog,
    QFormLayout,
    QHeaderView,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QListWidget,
    QProgressBar,
    QPushButton,
    QSpinBox,
    QTableWidget,
    QTableWidgetItem,
    QTextEdit,
    QVBoxLayout,
    QWizard,
    QWizardPage,
)

from .placement_dock import PlacementWidget


def tr(text):
    return QCoreApplication.translate("ConvertWizard", text)


def kind_name(kind: str) -> str:
    """The kind of a group on a sheet (cad_sheet.find_plans), for the user."""
    names = {"plan": tr("plan"), "detail": tr("detail"), "legend": tr("legend"), "other": tr("other")}
    return names.get(kind, kind)


# ====================================================================== running algorithms in a task
class _LogFeedback(QgsProcessingFeedback):
    """Feedback that keeps the algorithm's messages in a list (read by the wizard when the task ends)."""

    def __init__(self, log):
        super().__init__()
        self._log = log

    def pushInfo(self, info):  # noqa: N802
        self._log.append(info)

    def pushWarning(self, warning):  # noqa: N802
        self._log.append("⚠ " + warning)

    def reportError(self, error, fatalError=False):  # noqa: N802, N803
        self._log.append("✖ " + error)


class AlgorithmsTask(QgsTask):
    """Runs a list of (algorithm id, parameters) one after the other in a background thread, with the
    task's progress and cancel wired to the algorithms' feedback. ``results`` / ``errors`` per step.

    Feedback and context objects are made here, in the main thread, and live as long as the task: Qt
    objects must not be created in the worker thread and garbage-collected in another."""

    def __init__(self, description: str, steps):
        super().__init__(description, QgsTask.Flag.CanCancel)
        self.steps = list(steps)
        self.results: List[Optional[dict]] = []
        self.errors: List[str] = []
        self.log: List[str] = []
        self._feedbacks = [_LogFeedback(self.log) for _ in self.steps]
        self._contexts = [QgsProcessingContext() for _ in self.steps]

    def cancel(self):
        for fb in self._feedbacks:
            fb.cancel()
        super().cancel()

    def run(self):
        from qgis.PyQt.QtCore import QThread

        n = max(len(self.steps), 1)
        for k, (alg_id, params) in enumerate(self.steps):
            if self.isCanceled():
                return False
            alg = QgsApplication.processingRegistry().createAlgorithmById(alg_id)
            if alg is None:
                self.errors.append(f"{alg_id}: not available")
                self.results.append(None)
                continue
            feedback, context = self._feedbacks[k], self._contexts[k]
            context.pushToThread(QThread.currentThread())
            feedback.progressChanged.connect(lambda p, k=k: self.setProgress(100.0 * (k + p / 100.0) / n))
            try:
                result, ok = alg.run(params, context, feedback)
            except Exception as exc:  # noqa: BLE001 - reported in the wizard
                result, ok = None, False
                self.log.append("✖ " + str(exc))
            # layers the algorithm opened live in the context's store: free them in this thread, then
            # hand the context back to the main thread, which deletes it with the task
            context.temporaryLayerStore().removeAllMapLayers()
            context.pushToThread(QgsApplication.instance().thread())
            self.results.append(result if ok else None)
            if not ok:
                self.errors.append(f"{os.path.basename(str(params.get('INPUT', alg_id)))}: "
                                   + (self.log[-1] if self.log else "failed"))
            if self.isCanceled():
                return False
        self.setProgress(100.0)
        return not self.errors


# ====================================================================== pages
class FilesPage(QWizardPage):
    def __init__(self, wizard):
        super().__init__()
        self.wiz = wizard
        self.setTitle(tr("1. Floor plans"))
        self.setSubTitle(tr("Pick the DXF/DWG files of the building, one per floor (bottom floor first), "
                            "and check the layers kept as structure and the plan converted on each sheet."))
        lay = QVBoxLayout(self)
        row = QHBoxLayout()
        self.files = QListWidget()
        self.files.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.files.setMaximumHeight(120)
        row.addWidget(self.files, 1)
        buttons = QVBoxLayout()
        self.add_button = QPushButton(tr("Add files…"))
        self.add_button.clicked.connect(self.choose_files)
        self.remove_button = QPushButton(tr("Remove"))
        self.remove_button.clicked.connect(self.remove_selected)
        self.up_button = QPushButton(tr("Up"))
        self.up_button.clicked.connect(lambda: self.move(-1))
        self.down_button = QPushButton(tr("Down"))
        self.down_button.clicked.connect(lambda: self.move(1))
        for b in (self.add_button, self.remove_button, self.up_button, self.down_button):
            buttons.addWidget(b)
        buttons.addStretch(1)
        row.addLayout(buttons)
        lay.addLayout(row)
        self.layers = QTableWidget(0, 4)
        self.layers.setHorizontalHeaderLabels([tr("Layer"), tr("Kind"), tr("Kept"), tr("Entities")])
        self.layers.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.layers.horizontalHeader().setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)  # full xref names
        lay.addWidget(self.layers, 2)
        self.summary = QLabel("")
        lay.addWidget(self.summary)
        # plans on the sheet (cad2osmag:listplans): pick the main plan (pre-selected) or another view, or
        # draw an extent over the sheet; the choice is the PLAN of every algorithm the wizard runs
        plans_label = QLabel(tr("Plans on the sheet: the selected one is converted. The main plan (★) is "
                                "pre-selected; click another in the list or on the sheet, or draw an extent."))
        plans_label.setWordWrap(True)
        lay.addWidget(plans_label)
        row = QHBoxLayout()
        self.plans = QTableWidget(0, 4)
        self.plans.setHorizontalHeaderLabels([tr("Plan"), tr("Kind"), tr("Size"), tr("Title")])
        self.plans.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.plans.horizontalHeader().setStretchLastSection(True)  # the title
        self.plans.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.plans.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.plans.itemSelectionChanged.connect(self._plan_row_picked)
        self.plans.verticalHeader().setVisible(False)
        row.addWidget(self.plans, 1)
        from qgis.gui import QgsMapCanvas

        self.sheet_canvas = QgsMapCanvas()
        self.sheet_canvas.setMinimumSize(240, 180)
        self.sheet_canvas.setCanvasColor(Qt.GlobalColor.white)
        row.addWidget(self.sheet_canvas, 1)
        lay.addLayout(row, 2)
        row = QHBoxLayout()
        self.extent_button = QPushButton(tr("Draw an extent on the sheet"))
        self.extent_button.setCheckable(True)
        self.extent_button.setToolTip(tr("Drag a rectangle over the sheet to convert only what lies in it "
                                         "(e.g. one half of a floor drawn in two parts)."))
        self.extent_button.toggled.connect(self._extent_tool)
        self.plan_status = QLabel("")
        self.plan_status.setWordWrap(True)
        row.addWidget(self.extent_button)
        row.addWidget(self.plan_status, 1)
        lay.addLayout(row)
        import tempfile

        self._tmp = tempfile.mkdtemp(prefix="cad2osmag-plans-")
        self.sheets = {}  # path -> {"plans": [dict], "main": int, "structure": layer, "rects": layer}
        self.choices = {}  # path -> PLAN text chosen by the user
        self.plan_tasks = {}  # path -> running listplans task
        self._filling = False
        self._highlight = None
        self._extent_map_tool = None
        from qgis.gui import QgsMapToolEmitPoint

        self._click_tool = QgsMapToolEmitPoint(self.sheet_canvas)  # a click on a plan's rectangle picks it
        self._click_tool.canvasClicked.connect(self.pick_at)
        self.sheet_canvas.setMapTool(self._click_tool)
        self.files.currentRowChanged.connect(self.show_layers)
        self.files.currentRowChanged.connect(self.show_plans)

    def paths(self) -> List[str]:
        return [self.files.item(i).text() for i in range(self.files.count())]

    def choose_files(self):
        paths, _ = QFileDialog.getOpenFileNames(self, tr("Floor plans"), "",
                                                tr("CAD drawings (*.dxf *.dwg *.DXF *.DWG)"))
        self.add_files(paths)

    def add_files(self, paths):
        for p in paths:
            if p not in self.paths():
                self.files.addItem(p)
        if self.files.currentRow() < 0 and self.files.count():
            self.files.setCurrentRow(0)
        self.completeChanged.emit()

    def remove_selected(self):
        row = self.files.currentRow()
        if row >= 0:
            self.files.takeItem(row)
            self.completeChanged.emit()

    def move(self, delta):
        row = self.files.currentRow()
        new = row + delta
        if row < 0 or not 0 <= new < self.files.count():
            return
        item = self.files.takeItem(row)
        self.files.insertItem(new, item)
        self.files.setCurrentRow(new)

    def show_layers(self, row):
        self.layers.setRowCount(0)
        if row < 0:
            return
        path = self.files.item(row).text()
        alg = QgsApplication.processingRegistry().createAlgorithmById("cad2osmag:listlayers")
        context = QgsProcessingContext()
        res, ok = (alg.run({"INPUT": path, "OUTPUT": "memory:"}, context, QgsProcessingFeedback())
                   if alg is not None else (None, False))
        if not ok:
            self.summary.setText(tr("Cannot read the layers of {}.").format(os.path.basename(path)))
            return
        layer = context.getMapLayer(res["OUTPUT"]) or context.takeResultLayer(res["OUTPUT"])
        feats = list(layer.getFeatures())
        self.layers.setRowCount(len(feats))
        for r, f in enumerate(feats):
            for c, v in enumerate((f["layer"], f["kind"], tr("yes") if f["kept"] else tr("no"), str(f["total"]))):
                self.layers.setItem(r, c, QTableWidgetItem(str(v)))
        self.summary.setText(tr("{}: {} layers, kept: {}").format(os.path.basename(path), len(feats),
                                                                  res.get("KEPT_LAYERS", "")))

    def isComplete(self):  # noqa: N802
        return self.files.count() > 0

    # ------------------------------------------------------------------ plans on the sheet
    def current_path(self) -> Optional[str]:
        row = self.files.currentRow()
        return self.files.item(row).text() if row >= 0 else None

    def plan_parameter(self, path: str) -> str:
        """The PLAN parameter for ``path``: the user's choice (an index or 'xmin,ymin,xmax,ymax' in metres),
        else the main plan's index once the sheet is read, else '' (the algorithms take the main plan)."""
        if path in self.choices:
            return self.choices[path]
        sheet = self.sheets.get(path)
        if sheet is not None and sheet["main"] >= 0:
            return str(sheet["main"])
        return ""

    def show_plans(self, row):
        """The plans of the selected file (read once per file by ``cad2osmag:listplans``, as a task)."""
        self._fill_plans(None)
        path = self.files.item(row).text() if row >= 0 else None
        if path is None:
            return None
        if path in self.sheets:
            self._fill_plans(path)
            return None
        if path in self.plan_tasks:
            return self.plan_tasks[path]
        k = len(self.sheets) + len(self.plan_tasks)
        rects = os.path.join(self._tmp, f"plans_{k}.gpkg")
        lines = os.path.join(self._tmp, f"sheet_{k}.gpkg")
        task = AlgorithmsTask(tr("Finding the plans on {}").format(os.path.basename(path)),
                              [("cad2osmag:listplans", {"INPUT": path, "OUTPUT": rects, "STRUCTURE": lines})])
        task.taskCompleted.connect(lambda: self._plans_read(path, task, rects, lines))
        task.taskTerminated.connect(lambda: self._plans_failed(path, task))
        self.plan_tasks[path] = task
        self.plan_status.setText(tr("Finding the plans on the sheet…"))
        QgsApplication.taskManager().addTask(task)
        return task

    def plans_ready(self, path) -> bool:
        return path in self.sheets

    def _plans_failed(self, path, task):
        self.plan_tasks.pop(path, None)
        self.sheets[path] = {"plans": [], "main": -1, "structure": None, "rects": None,
                             "error": "; ".join(task.errors) or tr("canceled")}
        if path == self.current_path():
            self._fill_plans(path)

    def _plans_read(self, path, task, rects, lines):
        self.plan_tasks.pop(path, None)
        rect_layer = QgsVectorLayer(rects, tr("plans"), "ogr")
        plans = [{name: f[name] for name in ("index", "kind", "title", "width", "height", "wall_length", "main",
                                             "xmin", "ymin", "xmax", "ymax")}
                 for f in rect_layer.getFeatures()]
        plans.sort(key=lambda p: p["index"])
        main = int(task.results[0].get("MAIN_PLAN", -1)) if task.results and task.results[0] else -1
        line_layer = QgsVectorLayer(lines, tr("sheet"), "ogr")
        self._style_sheet(rect_layer, line_layer)
        self.sheets[path] = {"plans": plans, "main": main, "structure": line_layer, "rects": rect_layer}
        if path == self.current_path():
            self._fill_plans(path)

    @staticmethod
    def _style_sheet(rect_layer, line_layer):
        from qgis.core import (QgsFillSymbol, QgsLineSymbol, QgsPalLayerSettings, QgsSingleSymbolRenderer,
                               QgsTextFormat, QgsVectorLayerSimpleLabeling)
        from qgis.PyQt.QtGui import QColor

        rect_layer.setRenderer(QgsSingleSymbolRenderer(QgsFillSymbol.createSimple(
            {"color": "0,0,0,0", "outline_color": "255,140,0", "outline_width": "0.5", "outline_style": "dash"})))
        labels = QgsPalLayerSettings()
        labels.isExpression = True
        labels.fieldName = "'[' || \"index\" || '] ' || \"kind\""
        fmt = QgsTextFormat()
        fmt.setSize(9)
        fmt.setColor(QColor(200, 90, 0))
        labels.setFormat(fmt)
        rect_layer.setLabeling(QgsVectorLayerSimpleLabeling(labels))
        rect_layer.setLabelsEnabled(True)
        line_layer.setRenderer(QgsSingleSymbolRenderer(QgsLineSymbol.createSimple({"color": "60,60,60",
                                                                                   "width": "0.1"})))

    def _fill_plans(self, path):
        """Table and sheet canvas for ``path`` (None: empty), the current choice selected."""
        self._filling = True
        try:
            self.plans.setRowCount(0)
            self.sheet_canvas.setLayers([])
            self._set_highlight(None)
            if path is None or path not in self.sheets:
                return
            sheet = self.sheets[path]
            if sheet.get("error"):
                self.plan_status.setText(tr("Cannot find the plans: {}").format(sheet["error"]))
                return
            plans = sheet["plans"]
            self.plans.setRowCount(len(plans))
            for r, p in enumerate(plans):
                values = (str(p["index"]) + (" ★" if p["main"] else ""), kind_name(p["kind"]),
                          tr("{:.0f} × {:.0f} m").format(p["width"], p["height"]), p["title"] or "")
                for c, v in enumerate(values):
                    self.plans.setItem(r, c, QTableWidgetItem(v))
            self.plans.resizeColumnsToContents()
            layers = [lyr for lyr in (sheet["rects"], sheet["structure"]) if lyr is not None and lyr.isValid()]
            if layers:
                self.sheet_canvas.setDestinationCrs(layers[0].crs())
                self.sheet_canvas.setLayers(layers)
                ext = layers[0].extent()
                ext.scale(1.1)
                self.sheet_canvas.setExtent(ext)
                self.sheet_canvas.refresh()
            choice = self.plan_parameter(path)
            rows = [r for r, p in enumerate(plans) if str(p["index"]) == choice]
            if rows:
                self.plans.selectRow(rows[0])
            self._show_choice(path)
        finally:
            self._filling = False

    def _plan_row_picked(self):
        if self._filling:
            return
        path = self.current_path()
        rows = sorted({i.row() for i in self.plans.selectedIndexes()})
        if path is None or path not in self.sheets or not rows:
            return
        self.choices[path] = str(self.sheets[path]["plans"][rows[0]]["index"])
        self._show_choice(path)

    def pick_plan(self, index: int):
        """Select the plan ``index`` of the current file (as a click in the table does)."""
        path = self.current_path()
        plans = self.sheets.get(path, {}).get("plans", [])
        rows = [r for r, p in enumerate(plans) if p["index"] == index]
        if rows:
            self.plans.selectRow(rows[0])

    def pick_at(self, point, button=None):
        """Pick the smallest plan whose rectangle holds ``point`` (drawing frame) on the sheet canvas."""
        path = self.current_path()
        plans = self.sheets.get(path, {}).get("plans", []) if path else []
        hits = [p for p in plans if p["xmin"] <= point.x() <= p["xmax"] and p["ymin"] <= point.y() <= p["ymax"]]
        if hits:
            self.pick_plan(min(hits, key=lambda p: (p["xmax"] - p["xmin"]) * (p["ymax"] - p["ymin"]))["index"])

    def pick_extent(self, rect):
        """Convert only what lies in ``rect`` (QgsRectangle, metres of the drawing frame) of the current file."""
        path = self.current_path()
        if path is None or rect is None or rect.isEmpty():
            return
        self.choices[path] = "{:.3f},{:.3f},{:.3f},{:.3f}".format(rect.xMinimum(), rect.yMinimum(),
                                                                  rect.xMaximum(), rect.yMaximum())
        self._filling = True
        self.plans.clearSelection()
        self._filling = False
        self.extent_button.setChecked(False)
        self._show_choice(path)

    def _extent_tool(self, on):
        from qgis.gui import QgsMapToolExtent

        if on:
            self._extent_map_tool = QgsMapToolExtent(self.sheet_canvas)
            self._extent_map_tool.extentChanged.connect(self.pick_extent)
            self.sheet_canvas.setMapTool(self._extent_map_tool)
        elif self._extent_map_tool is not None:
            self.sheet_canvas.unsetMapTool(self._extent_map_tool)
            self._extent_map_tool = None
            self.sheet_canvas.setMapTool(self._click_tool)

    def _show_choice(self, path):
        sheet = self.sheets.get(path)
        choice = self.plan_parameter(path)
        if sheet is None:
            return
        n = len(sheet["plans"])
        if not choice:
            self.plan_status.setText(tr("{} group(s) on the sheet and no floor plan among them: pick one, or draw "
                                        "an extent.").format(n))
            self._set_highlight(None)
            return
        if "," in choice:
            box = [float(v) for v in choice.split(",")]
            self.plan_status.setText(tr("Converting the extent {:.1f}, {:.1f} – {:.1f}, {:.1f} m of {} group(s).")
                                     .format(box[0], box[1], box[2], box[3], n))
        else:
            p = next(p for p in sheet["plans"] if str(p["index"]) == choice)
            box = [p["xmin"], p["ymin"], p["xmax"], p["ymax"]]
            self.plan_status.setText(tr("Converting plan [{}] ({}{}) of {} group(s).").format(
                p["index"], kind_name(p["kind"]), (": " + p["title"]) if p["title"] else "", n))
        self._set_highlight(box)

    def _set_highlight(self, box):
        from qgis.core import QgsGeometry, QgsRectangle
        from qgis.gui import QgsRubberBand
        from qgis.PyQt.QtGui import QColor

        if self._highlight is not None:
            self.sheet_canvas.scene().removeItem(self._highlight)
            self._highlight = None
        if box is None:
            return
        band = QgsRubberBand(self.sheet_canvas, QgsWkbTypes.GeometryType.PolygonGeometry)
        band.setColor(QColor(0, 170, 0, 200))
        band.setFillColor(QColor(0, 170, 0, 40))
        band.setWidth(2)
        band.setToGeometry(QgsGeometry.fromRect(QgsRectangle(*box)), None)
        self._highlight = band

    def release(self):
        import shutil

        for task in list(self.plan_tasks.values()):
            task.cancel()  # a sheet still being read when the wizard closes
        self._set_highlight(None)
        self._extent_tool(False)
        self.sheet_canvas.unsetMapTool(self._click_tool)
        self.sheet_canvas.setLayers([])
        self.sheets.clear()
        shutil.rmtree(self._tmp, ignore_errors=True)


class SettingsPage(QWizardPage):
    def __init__(self, wizard):
        super().__init__()
        self.setTitle(tr("2. Segmentation settings (metres)"))
        self.setSubTitle(tr("The defaults suit most buildings. Smaller pixels follow thin walls better but "
                            "take longer."))
        form = QFormLayout(self)

        def spin(value, lo, hi, decimals, suffix, step):
            s = QDoubleSpinBox()
            s.setRange(lo, hi)
            s.setDecimals(decimals)
            s.setSingleStep(step)
            s.setSuffix(suffix)
            s.setValue(value)
            return s

        self.resolution = spin(0.044, 0.005, 1.0, 3, " m/px", 0.005)
        self.door_width = spin(2.8, 0.3, 100.0, 2, " m", 0.1)
        self.corridor_width = spin(8.0, 0.5, 100.0, 2, " m", 0.5)
        self.min_area = spin(10.0, 0.0, 10000.0, 1, " m²", 1.0)
        self.height = spin(3.2, 0.5, 100.0, 2, " m", 0.1)
        self.first_level = QSpinBox()
        self.first_level.setRange(-20, 200)
        self.first_level.setValue(1)
        form.addRow(tr("Raster resolution"), self.resolution)
        form.addRow(tr("Widest door"), self.door_width)
        form.addRow(tr("Corridor width"), self.corridor_width)
        form.addRow(tr("Merge areas smaller than"), self.min_area)
        form.addRow(tr("Level of the first floor"), self.first_level)
        form.addRow(tr("Floor height"), self.height)
        from qgis.gui import QgsMapCanvas

        self.preview_button = QPushButton(tr("Preview the areas of the first floor"))
        self.preview_button.clicked.connect(self.preview)
        self.preview_status = QLabel("")
        form.addRow(self.preview_button, self.preview_status)
        self.canvas = QgsMapCanvas()
        self.canvas.setMinimumHeight(260)
        form.addRow(self.canvas)
        self.wiz = wizard
        self.task = None
        self.preview_layers = []
        import tempfile

        self._tmp = tempfile.mkdtemp(prefix="cad2osmag-preview-")

    def preview(self):
        """extractstructure -> rasterize -> segment on the first floor with these settings, as a task; the
        walls, the occupancy raster and the areas are shown in the page's own canvas (drawing frame)."""
        paths = self.wiz.files_page.paths()
        if not paths:
            return None
        d = self._tmp
        walls, occ = os.path.join(d, "walls.gpkg"), os.path.join(d, "occupancy.tif")
        areas, passages = os.path.join(d, "areas.gpkg"), os.path.join(d, "passages.gpkg")
        plan = self.wiz.files_page.plan_parameter(paths[0])
        steps = [("cad2osmag:extractstructure", {"INPUT": paths[0], "PLAN": plan, "WALLS": walls,
                                                 "TEXTS": os.path.join(d, "texts.gpkg")}),
                 ("cad2osmag:rasterize", {"WALLS": walls, "RESOLUTION": self.resolution.value(), "OCCUPANCY": occ}),
                 ("cad2osmag:segment", {"INPUT": occ, "DOOR_WIDTH": self.door_width.value(),
                                        "CORRIDOR_WIDTH": self.corridor_width.value(), "STRUCTURE": walls,
                                        "AREAS": areas, "PASSAGES": passages,
                                        "LABELS": os.path.join(d, "labels.tif")})]
        self.canvas.setLayers([])
        self.preview_layers = []
        self.task = AlgorithmsTask(tr("Previewing the segmentation"), steps)
        self.task.taskCompleted.connect(lambda: self._show(walls, occ, areas, passages))
        self.task.taskTerminated.connect(lambda: self.preview_status.setText(
            tr("Preview failed: {}").format("; ".join(self.task.errors) or tr("canceled"))))
        self.preview_button.setEnabled(False)
        self.preview_status.setText(tr("Computing…"))
        self.task.taskTerminated.connect(lambda: self.preview_button.setEnabled(True))
        QgsApplication.taskManager().addTask(self.task)
        return self.task

    def release_preview(self):
        """The preview canvas only points at its layers: drop it from them before they are deleted."""
        import shutil

        self.canvas.setLayers([])
        self.preview_layers = []
        shutil.rmtree(self._tmp, ignore_errors=True)

    def _show(self, walls, occ, areas, passages):
        from qgis.core import (QgsCategorizedSymbolRenderer, QgsFillSymbol, QgsLineSymbol, QgsRasterLayer,
                               QgsRendererCategory, QgsSingleSymbolRenderer)

        from ..processing_provider.alg_load_osmag import AREA_COLOURS

        raster = QgsRasterLayer(occ, "occupancy")
        area_layer = QgsVectorLayer(areas, "areas", "ogr")
        cats = [QgsRendererCategory(k, QgsFillSymbol.createSimple({"color": fill, "outline_color": line,
                                                                   "outline_width": "0.3"}), k)
                for k, (fill, line) in AREA_COLOURS.items() if k != "structure"]
        area_layer.setRenderer(QgsCategorizedSymbolRenderer("type", cats))
        pass_layer = QgsVectorLayer(passages, "passages", "ogr")
        pass_layer.setRenderer(QgsSingleSymbolRenderer(QgsLineSymbol.createSimple({"color": "220,20,20",
                                                                                   "width": "0.8"})))
        wall_layer = QgsVectorLayer(walls, "walls", "ogr")
        wall_layer.setRenderer(QgsSingleSymbolRenderer(QgsLineSymbol.createSimple({"color": "0,0,0",
                                                                                   "width": "0.2"})))
        self.preview_layers = [pass_layer, wall_layer, area_layer, raster]
        self.canvas.setDestinationCrs(area_layer.crs())
        self.canvas.setLayers(self.preview_layers)
        self.canvas.setExtent(raster.extent())
        self.canvas.refresh()
        self.preview_button.setEnabled(True)
        self.preview_status.setText(tr("{} areas, {} passages").format(area_layer.featureCount(),
                                                                     pass_layer.featureCount()))


class PlacementPage(QWizardPage):
    def __init__(self, wizard, canvas):
        super().__init__()
        self.wiz = wizard
        self.setTitle(tr("3. Place the plan on the map"))
        self.setSubTitle(tr("Add a basemap, then drag the plan to its place, turn it with the round handle, or "
                            "click control points (drawing point, then map point). Every floor uses this "
                            "placement."))
        lay = QVBoxLayout(self)
        self.panel = PlacementWidget(canvas, self)
        lay.addWidget(self.panel)

    def initializePage(self):  # noqa: N802
        paths = self.wiz.files_page.paths()
        if not paths:
            return
        wanted = (paths[0], self.wiz.files_page.plan_parameter(paths[0]))
        if self.panel.overlay is None or getattr(self, "_loaded", None) != wanted:
            self.panel.load_file(wanted[0], plan=wanted[1])  # the plan picked on the first page
            self._loaded = wanted

    def cleanupPage(self):  # noqa: N802
        self.panel.deactivate_tools()

    def isComplete(self):  # noqa: N802
        return self.panel.placement is not None


class RunPage(QWizardPage):
    finishedConversion = pyqtSignal(bool)

    def __init__(self, wizard):
        super().__init__()
        self.wiz = wizard
        self.task = None
        self.done = False
        self.setTitle(tr("4. Convert and export"))
        self.setSubTitle(tr("One osmAG file per floor is written to the output folder; the floors are added "
                            "to the map, styled."))
        lay = QVBoxLayout(self)
        row = QHBoxLayout()
        self.folder = QLineEdit()
        browse = QPushButton(tr("…"))
        browse.clicked.connect(self.choose_folder)
        row.addWidget(QLabel(tr("Output folder")))
        row.addWidget(self.folder, 1)
        row.addWidget(browse)
        lay.addLayout(row)
        self.merge = QCheckBox(tr("Also write the merged building (building.osm)"))
        self.merge.setChecked(True)
        self.add_to_map = QCheckBox(tr("Add the styled floors to the map"))
        self.add_to_map.setChecked(True)
        lay.addWidget(self.merge)
        lay.addWidget(self.add_to_map)
        row = QHBoxLayout()
        self.run_button = QPushButton(tr("Convert"))
        self.run_button.clicked.connect(self.start)
        self.cancel_button = QPushButton(tr("Cancel"))
        self.cancel_button.setEnabled(False)
        self.cancel_button.clicked.connect(self.cancel)
        row.addWidget(self.run_button)
        row.addWidget(self.cancel_button)
        lay.addLayout(row)
        self.progress = QProgressBar()
        self.progress.setRange(0, 100)
        lay.addWidget(self.progress)
        self.log = QTextEdit()
        self.log.setReadOnly(True)
        lay.addWidget(self.log, 1)
        self.outputs = []

    def choose_folder(self):
        folder = QFileDialog.getExistingDirectory(self, tr("Output folder"), self.folder.text())
        if folder:
            self.folder.setText(folder)

    def steps(self):
        """(algorithm id, parameters) for every floor, then the merge."""
        w = self.wiz
        s = w.settings_page
        placement = w.placement_page.panel.placement
        out = self.folder.text().strip()
        steps, self.outputs = [], []
        for k, path in enumerate(w.files_page.paths()):
            stem = os.path.splitext(os.path.basename(path))[0]
            osm = os.path.join(out, stem + ".osm")
            params = {"INPUT": path, "PLAN": w.files_page.plan_parameter(path), "OUTPUT": osm,
                      "LEVEL": str(s.first_level.value() + k),
                      "HEIGHT": s.height.value(), "RESOLUTION": s.resolution.value(),
                      "DOOR_WIDTH": s.door_width.value(), "CORRIDOR_WIDTH": s.corridor_width.value(),
                      "MIN_AREA": s.min_area.value(),
                      "OUTPUT_AREAS": os.path.join(out, stem + "_areas.gpkg"),
                      "OUTPUT_PASSAGES": os.path.join(out, stem + "_passages.gpkg")}
            if placement is not None:
                params.update(placement.dxftoosmag_parameters())
            steps.append(("cad2osmag:dxftoosmag", params))
            self.outputs.append(params)
        if self.merge.isChecked() and len(steps) > 1:
            steps.append(("cad2osmag:mergefloors", {"INPUT": [p["OUTPUT"] for p in self.outputs],
                                                   "OUTPUT": os.path.join(out, "building.osm")}))
        return steps

    def start(self):
        out = self.folder.text().strip()
        if not out:
            self.log.append(tr("Choose an output folder first."))
            return None
        os.makedirs(out, exist_ok=True)
        self.done = False
        self.task = AlgorithmsTask(tr("Converting floor plans to osmAG"), self.steps())
        self.task.progressChanged.connect(lambda p: self.progress.setValue(int(p)))
        self.task.taskCompleted.connect(lambda: self.finished(True))
        self.task.taskTerminated.connect(lambda: self.finished(False))
        self.run_button.setEnabled(False)
        self.cancel_button.setEnabled(True)
        self.log.append(tr("Converting {} floor(s)…").format(len(self.outputs)))
        QgsApplication.taskManager().addTask(self.task)
        return self.task

    def cancel(self):
        if self.task is not None:
            self.task.cancel()

    def finished(self, ok):
        task = self.task
        for line in task.log:
            if line.startswith(("⚠", "✖")) or "areas" in line:
                self.log.append(line)
        if ok:
            self.log.append(tr("Done: {} floor(s) written to {}").format(len(self.outputs), self.folder.text()))
            if self.add_to_map.isChecked():
                self.add_layers()
        else:
            self.log.append(tr("Stopped: {}").format("; ".join(task.errors) or tr("canceled")))
        self.progress.setValue(100 if ok else self.progress.value())
        self.run_button.setEnabled(True)
        self.cancel_button.setEnabled(False)
        self.done = ok
        self.completeChanged.emit()
        self.finishedConversion.emit(ok)

    def add_layers(self):
        from ..processing_provider.alg_load_osmag import apply_osmag_style

        project = QgsProject.instance()
        added = []
        for params in self.outputs:
            stem = os.path.splitext(os.path.basename(params["OUTPUT"]))[0]
            for key, kind in (("OUTPUT_PASSAGES", "passages"), ("OUTPUT_AREAS", "areas")):
                layer = QgsVectorLayer(params[key], f"{stem} {kind}", "ogr")
                if layer.isValid():
                    apply_osmag_style(layer, kind)
                    project.addMapLayer(layer)
                    added.append(layer)
        return added

    def isComplete(self):  # noqa: N802
        return self.done


AREA_TYPES = ["room", "corridor", "stairs", "elevator", "structure"]


class NamesPage(QWizardPage):
    """Names and types of the areas of every converted floor, editable; *Save and export again* writes them
    into the floors' area layers and rewrites the osmAG files through ``exportosmag`` (and ``mergefloors``)."""

    def __init__(self, wizard):
        super().__init__()
        self.wiz = wizard
        self.task = None
        self.setTitle(tr("5. Names and types"))
        self.setSubTitle(tr("Correct the name and the type of any area (room, corridor, stairs, elevator, "
                            "structure), then save: the osmAG files are written again."))
        lay = QVBoxLayout(self)
        self.table = QTableWidget(0, 4)
        self.table.setHorizontalHeaderLabels([tr("Level"), tr("Area"), tr("Name"), tr("Type")])

        self.table.horizontalHeader().setSectionResizeMode(2, QHeaderView.ResizeMode.Stretch)
        lay.addWidget(self.table, 1)
        row = QHBoxLayout()
        self.save_button = QPushButton(tr("Save and export again"))
        self.save_button.clicked.connect(self.save)
        self.status = QLabel("")
        row.addWidget(self.save_button)
        row.addWidget(self.status, 1)
        lay.addLayout(row)
        self.rows = []  # (floor params, feature id)

    def initializePage(self):  # noqa: N802
        from qgis.PyQt.QtWidgets import QComboBox

        self.table.setRowCount(0)
        self.rows = []
        for params in self.wiz.run_page.outputs:
            layer = QgsVectorLayer(params["OUTPUT_AREAS"], "areas", "ogr")
            if not layer.isValid():
                continue
            for f in layer.getFeatures():
                r = self.table.rowCount()
                self.table.insertRow(r)
                for c, v in enumerate((params["LEVEL"], str(f["osm_id"]))):
                    item = QTableWidgetItem(v)
                    item.setFlags(item.flags() & ~Qt.ItemFlag.ItemIsEditable)
                    self.table.setItem(r, c, item)
                self.table.setItem(r, 2, QTableWidgetItem(str(f["name"] or "")))
                combo = QComboBox()
                combo.addItems(AREA_TYPES)
                kind = str(f["osmAG:areatype"] or "room")
                if kind not in AREA_TYPES:
                    combo.addItem(kind)
                combo.setCurrentText(kind)
                self.table.setCellWidget(r, 3, combo)
                self.rows.append((params, f.id()))
        self.status.setText(tr("{} areas").format(len(self.rows)))

    def edits(self):
        """{areas layer path: {feature id: (name, type)}} of the rows whose values changed."""
        out = {}
        for r, (params, fid) in enumerate(self.rows):
            out.setdefault(params["OUTPUT_AREAS"], {})[fid] = (self.table.item(r, 2).text().strip(),
                                                               self.table.cellWidget(r, 3).currentText())
        return out

    def save(self):
        changed = 0
        for path, values in self.edits().items():
            layer = QgsVectorLayer(path, "areas", "ogr")
            names = layer.fields().names()
            i_name, i_type = names.index("name"), names.index("osmAG:areatype")
            changes = {}
            for f in layer.getFeatures():
                name, kind = values.get(f.id(), (None, None))
                if name is None or (str(f["name"] or "") == name and str(f["osmAG:areatype"] or "") == kind):
                    continue
                changes[f.id()] = {i_name: name or None, i_type: kind}
            if changes:
                layer.dataProvider().changeAttributeValues(changes)
                changed += len(changes)
        placement = self.wiz.placement_page.panel.placement
        steps = []
        run = self.wiz.run_page
        for params in run.outputs:
            export = {"AREAS": params["OUTPUT_AREAS"], "PASSAGES": params["OUTPUT_PASSAGES"],
                      "LEVEL": params["LEVEL"], "HEIGHT": params["HEIGHT"], "OUTPUT": params["OUTPUT"]}
            if placement is not None:
                export.update({"ANCHOR_LON": placement.anchor_lon, "ANCHOR_LAT": placement.anchor_lat})
            steps.append(("cad2osmag:exportosmag", export))
        if run.merge.isChecked() and len(run.outputs) > 1:
            steps.append(("cad2osmag:mergefloors", {"INPUT": [p["OUTPUT"] for p in run.outputs],
                                                   "OUTPUT": os.path.join(run.folder.text().strip(), "building.osm")}))
        self.task = AlgorithmsTask(tr("Exporting osmAG again"), steps)
        self.task.taskCompleted.connect(lambda: self._finished(True, changed))
        self.task.taskTerminated.connect(lambda: self._finished(False, changed))
        self.save_button.setEnabled(False)
        self.status.setText(tr("Saving {} changed areas…").format(changed))
        QgsApplication.taskManager().addTask(self.task)
        return self.task

    def _finished(self, ok, changed):
        self.save_button.setEnabled(True)
        if ok:
            self.status.setText(tr("{} areas changed; osmAG files written again.").format(changed))
            for layer in QgsProject.instance().mapLayers().values():
                layer.triggerRepaint()
        else:
            self.status.setText(tr("Export failed: {}").format("; ".join(self.task.errors)))


class ConvertWizard(QWizard):
    def __init__(self, canvas, parent=None):
        super().__init__(parent)
        self.setWindowTitle(tr("Convert a floor plan to osmAG"))
        self.setOption(QWizard.WizardOption.NoBackButtonOnLastPage, False)
        self.files_page = FilesPage(self)
        self.settings_page = SettingsPage(self)
        self.placement_page = PlacementPage(self, canvas)
        self.run_page = RunPage(self)
        self.names_page = NamesPage(self)
        for page in (self.files_page, self.settings_page, self.placement_page, self.run_page, self.names_page):
            self.addPage(page)
        self.resize(760, 720)

    def done(self, result):  # noqa: D401 - Qt override
        self.placement_page.panel.remove_overlay()
        self.settings_page.release_preview()
        self.files_page.release()
        super().done(result)
