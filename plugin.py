"""QGIS desktop integration: registers the Processing provider and adds a menu and a toolbar button."""
import os
import sys

from qgis.core import QgsApplication
from qgis.PyQt.QtCore import QCoreApplication, QLocale, QSettings, QTranslator
from qgis.PyQt.QtGui import QIcon
try:  # Qt6 (QGIS 4): QAction lives in QtGui
    from qgis.PyQt.QtGui import QAction
except ImportError:  # Qt5
    from qgis.PyQt.QtWidgets import QAction

PLUGIN_DIR = os.path.dirname(__file__)
ICON_PATH = os.path.join(PLUGIN_DIR, "icons", "icon.svg")
MENU = "&CAD to osmAG"
# The algorithm the toolbar button opens: the whole pipeline when it exists, else the first stage.
MAIN_ALGORITHMS = ("cad2osmag:dxftoosmag", "cad2osmag:extractstructure", "cad2osmag:samplebuilding")


def add_local_venv_to_path():
    """When the plugin runs from a checkout set up by `make install`, make the venv's pinned
    dependencies (ezdxf, opencv, shapely, pyproj...) importable inside QGIS."""
    venv_lib = os.path.join(PLUGIN_DIR, ".venv", "lib",
                            f"python{sys.version_info.major}.{sys.version_info.minor}", "site-packages")
    if os.path.isdir(venv_lib) and venv_lib not in sys.path:
        sys.path.append(venv_lib)


def let_gdal_read_negative_osm_ids():
    """osmAG files use negative ids (new objects, JOSM convention). GDAL's OSM driver refuses them
    with its default custom indexing; without it, QGIS opens them like any OSM file."""
    try:
        from osgeo import gdal
    except ImportError:  # pragma: no cover - GDAL always ships with QGIS
        return
    if gdal.GetConfigOption("OSM_USE_CUSTOM_INDEXING") is None:
        gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", "NO")


class Cad2OsmagPlugin:
    def __init__(self, iface):
        self.iface = iface
        self.provider = None
        self.actions = []
        self.translator = None
        add_local_venv_to_path()
        let_gdal_read_negative_osm_ids()
        self._install_translator()

    def _install_translator(self):
        """Load i18n/cad2osmag_<locale>.qm for the QGIS user locale: the full name first (zh_CN), then the
        language (de). The .qm files are compiled by `make translations`."""
        locale = str(QSettings().value("locale/userLocale", "") or QLocale.system().name())
        for name in (locale, locale[:2]):
            qm = os.path.join(PLUGIN_DIR, "i18n", f"cad2osmag_{name}.qm")
            if name and os.path.exists(qm):
                translator = QTranslator()
                if translator.load(qm):
                    QCoreApplication.installTranslator(translator)
                    self.translator = translator
                    return

    @staticmethod
    def tr(text):
        return QCoreApplication.translate("Cad2OsmagPlugin", text)

    # QGIS calls initProcessing() for plugins with hasProcessingProvider=yes (also in qgis_process)
    def initProcessing(self):  # noqa: N802
        if self.provider is None:
            from .processing_provider.provider import Cad2OsmagProvider

            self.provider = Cad2OsmagProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):  # noqa: N802
        self.initProcessing()
        from . import deps  # missing Python packages: message bar with an "Install" button

        deps.notify_missing(self.iface)
        icon = QIcon(ICON_PATH)
        main = QAction(icon, self.tr("Convert a DXF floor plan to osmAG…"), self.iface.mainWindow())
        main.triggered.connect(self.open_main_algorithm)
        self._add_to_menu(main)
        self.actions.append(main)

        toolbox = QAction(self.tr("Show the CAD to osmAG algorithms"), self.iface.mainWindow())
        toolbox.triggered.connect(self.show_toolbox)
        self._add_to_menu(toolbox)
        self.actions.append(toolbox)

        wizard = QAction(icon, self.tr("Convert a floor plan…"), self.iface.mainWindow())
        wizard.triggered.connect(self.show_convert_wizard)
        self.iface.addToolBarIcon(wizard)  # the toolbar button opens the guided conversion
        self._add_to_menu(wizard)
        self.actions.append(wizard)

        place = QAction(self.tr("Place a floor plan on the map…"), self.iface.mainWindow())
        place.triggered.connect(self.show_placement)
        self._add_to_menu(place)
        self.actions.append(place)
        self.placement_dock = None

        for kind, label in (("osm", self.tr("Add OpenStreetMap basemap")),
                            ("satellite", self.tr("Add satellite imagery basemap"))):
            action = QAction(label, self.iface.mainWindow())
            action.triggered.connect(lambda _checked=False, k=kind: self.add_basemap(k))
            self._add_to_menu(action)
            self.actions.append(action)

    def _add_to_menu(self, action):
        # Vector menu in QGIS; test doubles of QgisInterface may only offer the Plugins menu.
        add = getattr(self.iface, "addPluginToVectorMenu", None) or self.iface.addPluginToMenu
        add(MENU, action)

    def unload(self):
        remove = getattr(self.iface, "removePluginVectorMenu", None) or getattr(self.iface, "removePluginMenu", None)
        for action in self.actions:
            if remove is not None:
                remove(MENU, action)
            self.iface.removeToolBarIcon(action)
        self.actions = []
        if getattr(self, "placement_dock", None) is not None:
            self.placement_dock.widget.remove_overlay()
            remove_dock = getattr(self.iface, "removeDockWidget", None)  # absent from test doubles
            if remove_dock is not None:
                remove_dock(self.placement_dock)
            self.placement_dock.deleteLater()
            self.placement_dock = None
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
        if self.translator is not None:
            QCoreApplication.removeTranslator(self.translator)
            self.translator = None

    # --- actions ------------------------------------------------------------------------------
    def open_main_algorithm(self):
        import processing  # QGIS's Processing plugin

        registry = QgsApplication.processingRegistry()
        for alg_id in MAIN_ALGORITHMS:
            if registry.algorithmById(alg_id) is not None:
                processing.execAlgorithmDialog(alg_id)
                return

    def show_toolbox(self):
        """Show the Processing toolbox filtered on this provider."""
        from qgis.PyQt.QtWidgets import QDockWidget, QLineEdit

        dock = self.iface.mainWindow().findChild(QDockWidget, "ProcessingToolbox")
        if dock is None:
            return
        dock.setVisible(True)
        dock.raise_()
        search = dock.findChild(QLineEdit)
        if search is not None:
            search.setText("cad2osmag")

    def show_convert_wizard(self):
        """The guided conversion (ui/convert_wizard.py), modeless so that the map stays usable."""
        from .ui.convert_wizard import ConvertWizard

        wizard = ConvertWizard(self.iface.mapCanvas(), self.iface.mainWindow())
        wizard.show()
        self._wizard = wizard  # keep it alive while open
        return wizard

    def show_placement(self):
        """The panel that places a floor plan on the basemap by hand (ui/placement_dock.py)."""
        from qgis.PyQt.QtCore import Qt

        from .ui.placement_dock import PlacementDock

        if self.placement_dock is None:
            self.placement_dock = PlacementDock(self.iface)
            self.iface.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.placement_dock)
        self.placement_dock.show()
        self.placement_dock.raise_()
        return self.placement_dock

    def add_basemap(self, kind):
        from .ui import basemaps

        layer = basemaps.add_xyz_basemap(kind)
        if layer is not None:
            self.iface.messageBar().pushInfo("cad2osmag", self.tr("Added basemap “{}”.").format(layer.name()))
