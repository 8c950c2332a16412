"""Writes the shipped QML styles of osmAG layers (styles/osmag_areas.qml, styles/osmag_passages.qml)
from the style built in code (processing_provider/alg_load_osmag.build_osmag_style):

* areas: filled and coloured by ``osmAG:areatype`` (room yellow, corridor blue, stairs orange,
  elevator violet, structure dashed outline), labels on ``name``;
* passages: red lines, vertical passages (``vertical = 'yes'``: between stair / lift areas) thick blue,
  labels on ``name``.

Run from the repository root: ``.venv/bin/python styles/build_styles.py``. The styles are applied when
loadosmag / dxftoosmag load their layers and stored as the default style of GeoPackage outputs; load them
on any osmAG layer with *Layer Properties ▸ Style ▸ Load Style*.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def main():
    sys.path.insert(0, os.path.join(REPO, "tests"))
    sys.path.insert(0, REPO)
    from conftest import headless_qgis  # noqa: E402 - QGIS, and the repository as the package 'cad2osmag'

    app, _ = headless_qgis()  # noqa: F841 - QGIS lives as long as app
    from qgis.core import QgsVectorLayer
    from cad2osmag.processing_provider.alg_load_osmag import build_osmag_style

    layers = {
        "areas": QgsVectorLayer("Polygon?crs=EPSG:4326&field=osm_id:long&field=osmAG:type:string"
                                "&field=osmAG:areatype:string&field=name:string&field=level:string", "a", "memory"),
        "passages": QgsVectorLayer("LineString?crs=EPSG:4326&field=osm_id:long&field=vertical:string"
                                   "&field=osmAG:type:string&field=name:string&field=level:string", "p", "memory"),
    }
    for kind, layer in layers.items():
        build_osmag_style(layer, kind)
        path = os.path.join(HERE, f"osmag_{kind}.qml")
        msg, ok = layer.saveNamedStyle(path)
        print(("wrote " if ok else "FAILED ") + path, "" if ok else msg)
    return 0


if __name__ == "__main__":
    sys.exit(main())
