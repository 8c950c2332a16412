"""QGIS entry point of the cad2osmag plugin."""


def classFactory(iface):  # noqa: N802 (QGIS API name)
    from .plugin import Cad2OsmagPlugin

    return Cad2OsmagPlugin(iface)
