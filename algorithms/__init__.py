"""cad2osmag pipeline: plain Python (numpy/scipy/opencv/shapely/ezdxf/pyproj), no qgis import.

Every stage lives here once; ``processing_provider`` only maps QGIS parameters, layers and
feedback onto these functions, so the whole pipeline runs and is tested without QGIS.
"""
