"""XYZ basemaps to place a plan against real imagery (used by the plugin menu).

Creating the layer fetches nothing: tiles are only requested when the map canvas renders them.
"""
from urllib.parse import quote

from qgis.core import QgsProject, QgsRasterLayer

BASEMAPS = {
    # kind: (layer name, tile URL template, max zoom, attribution)
    "osm": ("OpenStreetMap", "https://tile.openstreetmap.org/{z}/{x}/{y}.png", 19,
            "© OpenStreetMap contributors"),
    "satellite": ("Esri World Imagery",
                  "https://server.arcgisonline.com/ArcGIS/rest/services/World_Imagery/MapServer/tile/{z}/{y}/{x}",
                  19, "Esri, Maxar, Earthstar Geographics, and the GIS User Community"),
}
ALIASES = {"openstreetmap": "osm", "osm": "osm", "satellite": "satellite", "esri": "satellite",
           "imagery": "satellite", "aerial": "satellite"}


def xyz_uri(url: str, zmax: int = 19, zmin: int = 0) -> str:
    """Data source URI of the ``wms`` provider for an XYZ tile template."""
    return f"type=xyz&url={quote(url, safe=':/')}&zmax={int(zmax)}&zmin={int(zmin)}&http-header:referer="


def make_xyz_layer(kind: str) -> QgsRasterLayer:
    """A QgsRasterLayer (provider ``wms``, type=xyz) for ``kind`` ('osm' or 'satellite')."""
    key = ALIASES.get(str(kind).strip().lower())
    if key is None:
        raise ValueError(f"unknown basemap {kind!r}; use one of: {', '.join(sorted(BASEMAPS))}")
    name, url, zmax, attribution = BASEMAPS[key]
    layer = QgsRasterLayer(xyz_uri(url, zmax), name, "wms")
    if layer.isValid() and hasattr(layer, "setAttribution"):
        layer.setAttribution(attribution)
    return layer


def add_xyz_basemap(kind: str, project=None):
    """Add the basemap ``kind`` ('osm' = OpenStreetMap standard, 'satellite' = Esri World Imagery) to
    ``project`` (default the current project) at the bottom of the layer tree, so the plan is drawn
    on top. A basemap already in the project is returned instead of being added twice. Returns the
    layer, or None when the ``wms`` provider cannot create it."""
    project = project or QgsProject.instance()
    layer = make_xyz_layer(kind)
    for existing in project.mapLayers().values():
        if existing.providerType() == "wms" and existing.source() == layer.source():
            return existing
    if not layer.isValid():
        return None
    project.addMapLayer(layer, False)
    project.layerTreeRoot().addLayer(layer)
    return layer
