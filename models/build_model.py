"""Builds models/cad_to_osmag.model3, the graphical model that chains the individual algorithms:

    extractstructure -> rasterize -> segment (typing stairs/lifts from the structure) -> refine -> assignnames
    -> georeference (anchor + rotation + scale) -> exportosmag

Run from the repository root (it registers the provider headless and writes the file):

    .venv/bin/python models/build_model.py

The model is plain XML afterwards: open it in the graphical modeler (Processing ▸ Graphical Modeler ▸ Open)
to change it. The provider adds every ``models/*.model3`` to the toolbox (cad2osmag:cad_to_osmag).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
MODEL_PATH = os.path.join(HERE, "cad_to_osmag.model3")


def build():
    from qgis.core import (
        QgsProcessingModelAlgorithm,
        QgsProcessingModelChildAlgorithm,
        QgsProcessingModelChildParameterSource as Src,
        QgsProcessingModelOutput,
        QgsProcessingModelParameter,
        QgsProcessingParameterFile,
        QgsProcessingParameterNumber,
        QgsProcessingParameterPoint,
        QgsProcessingParameterString,
    )
    from qgis.PyQt.QtCore import QPointF

    # a model's name is also its display name and the last part of its id (cad2osmag:cad_to_osmag)
    model = QgsProcessingModelAlgorithm("cad_to_osmag", "Models", "models")
    model.setHelpContent({
        "ALG_DESC": "The whole conversion of one floor as a graphical model of the individual algorithms: "
                    "extract the structure of the DXF, rasterize it, segment the free space into an Area "
                    "Graph (stairs and lifts typed from the drawing), refine the areas, georeference them "
                    "(the drawing origin at ANCHOR, ROTATION clockwise from north, SCALE) and export osmAG. "
                    "Open it in the graphical modeler to add or change steps.",
        "DXF": "The floor plan (DXF, or DWG as delivered: the main plan of a sheet is converted).",
        "ANCHOR": "Where the drawing origin (0, 0) lies on the map: pick it on a basemap, or use the "
                  "placement of Vector ▸ CAD to osmAG ▸ Place a floor plan on the map.",
        "ROTATION": "Direction of the drawing's +y axis, in degrees clockwise from north.",
        "SCALE": "Ground metres per drawing metre (1 for a correct drawing).",
        "LEVEL": "Level of the floor (osmAG level tag).",
        "RESOLUTION": "Raster resolution in metres per pixel (0.044 m by default).",
        "DOOR_WIDTH": "Widest door in metres (2.8 m, the segment default).",
        "CORRIDOR_WIDTH": "Corridor width in metres (8 m, the segment default).",
        "MIN_AREA": "Areas smaller than this (m²) merge into a neighbour (stairs and lifts are kept).",
        "OSM": "The osmAG file written (.osm).",
    })
    inputs = [
        (QgsProcessingParameterFile("DXF", "DXF or DWG floor plan",
                                    fileFilter="CAD drawings (*.dxf *.DXF *.dwg *.DWG)"), QPointF(120, 60)),
        (QgsProcessingParameterPoint("ANCHOR", "Position of the drawing origin"), QPointF(120, 420)),
        (QgsProcessingParameterNumber("ROTATION", "Rotation (degrees clockwise from north)",
                                      QgsProcessingParameterNumber.Type.Double, 0.0, False, -360.0, 360.0),
         QPointF(120, 470)),
        (QgsProcessingParameterNumber("SCALE", "Scale (ground metres per drawing metre)",
                                      QgsProcessingParameterNumber.Type.Double, 1.0, False, 1e-6, 1e6),
         QPointF(120, 520)),
        (QgsProcessingParameterString("LEVEL", "Level", "1"), QPointF(120, 570)),
        (QgsProcessingParameterNumber("RESOLUTION", "Raster resolution (m/px)",
                                      QgsProcessingParameterNumber.Type.Double, 0.044, False, 0.005, 1.0),
         QPointF(120, 160)),
        (QgsProcessingParameterNumber("DOOR_WIDTH", "Widest door (m)",
                                      QgsProcessingParameterNumber.Type.Double, 2.8, False, 0.01, 1000.0),
         QPointF(120, 230)),
        (QgsProcessingParameterNumber("CORRIDOR_WIDTH", "Narrowest corridor (m)",
                                      QgsProcessingParameterNumber.Type.Double, 8.0, False, 0.01, 1000.0),
         QPointF(120, 280)),
        (QgsProcessingParameterNumber("MIN_AREA", "Merge areas smaller than (m²)",
                                      QgsProcessingParameterNumber.Type.Double, 10.0, False, 0.0, 1000.0),
         QPointF(120, 340)),
    ]
    for definition, pos in inputs:
        mp = QgsProcessingModelParameter(definition.name())
        mp.setPosition(pos)
        model.addModelParameter(definition, mp)

    def child(cid, alg_id, description, pos, params, outputs=()):
        c = QgsProcessingModelChildAlgorithm(alg_id)
        c.setChildId(cid)
        c.setDescription(description)
        c.setPosition(QPointF(*pos))
        for name, src in params.items():
            c.addParameterSources(name, [src])
        outs = {}
        for out_name, model_name, label in outputs:
            o = QgsProcessingModelOutput(model_name, label)
            o.setChildOutputName(out_name)
            o.setChildId(cid)
            o.setPosition(QPointF(pos[0] + 150, pos[1] + 45))
            outs[model_name] = o
        c.setModelOutputs(outs)
        model.addChildAlgorithm(c)
        return cid

    p = Src.fromModelParameter
    o = Src.fromChildOutput
    v = Src.fromStaticValue
    child("extract", "cad2osmag:extractstructure", "Extract structure", (420, 60),
          {"INPUT": p("DXF"), "UNITS": v(0), "INCLUDE_DOORS": v(False),
           "WALLS": v("TEMPORARY_OUTPUT"), "TEXTS": v("TEMPORARY_OUTPUT"), "DOORS": v("TEMPORARY_OUTPUT")})
    child("rasterize", "cad2osmag:rasterize", "Rasterize", (420, 160),
          {"WALLS": o("extract", "WALLS"), "DOORS": o("extract", "DOORS"), "RESOLUTION": p("RESOLUTION"),
           "OCCUPANCY": v("TEMPORARY_OUTPUT")})
    child("segment", "cad2osmag:segment", "Segment (Area Graph)", (420, 260),
          {"INPUT": o("rasterize", "OCCUPANCY"), "DOOR_WIDTH": p("DOOR_WIDTH"),
           "CORRIDOR_WIDTH": p("CORRIDOR_WIDTH"), "STRUCTURE": o("extract", "WALLS"),
           "TEXTS": o("extract", "TEXTS"), "DOORS": o("extract", "DOORS"),
           "AREAS": v("TEMPORARY_OUTPUT"), "PASSAGES": v("TEMPORARY_OUTPUT"), "LABELS": v("TEMPORARY_OUTPUT")})
    child("refine", "cad2osmag:refine", "Refine areas", (420, 360),
          {"AREAS": o("segment", "AREAS"), "PASSAGES": o("segment", "PASSAGES"), "RESOLUTION": p("RESOLUTION"),
           "MIN_AREA": p("MIN_AREA"), "OUTPUT_AREAS": v("TEMPORARY_OUTPUT"),
           "OUTPUT_PASSAGES": v("TEMPORARY_OUTPUT")})
    child("names", "cad2osmag:assignnames", "Room names and types", (420, 410),
          {"AREAS": o("refine", "OUTPUT_AREAS"), "TEXTS": o("extract", "TEXTS"),
           "PASSAGES": o("refine", "OUTPUT_PASSAGES"), "LEVEL": p("LEVEL"),
           "OUTPUT_AREAS": v("TEMPORARY_OUTPUT"), "OUTPUT_PASSAGES": v("TEMPORARY_OUTPUT")})
    child("georef", "cad2osmag:georeference", "Georeference", (420, 460),
          {"AREAS": o("names", "OUTPUT_AREAS"), "PASSAGES": o("names", "OUTPUT_PASSAGES"), "MODE": v(0),
           "ANCHOR": p("ANCHOR"), "ROTATION": p("ROTATION"), "SCALE": p("SCALE"), "CAD_ANCHOR_X": v(0.0),
           "CAD_ANCHOR_Y": v(0.0), "TARGET_CRS": v("EPSG:4326")},
          outputs=[("OUTPUT_AREAS", "Areas", "osmAG areas (WGS84)"),
                   ("OUTPUT_PASSAGES", "Passages", "osmAG passages (WGS84)")])
    child("export", "cad2osmag:exportosmag", "Export osmAG", (420, 560),
          {"AREAS": o("georef", "OUTPUT_AREAS"), "PASSAGES": o("georef", "OUTPUT_PASSAGES"), "LEVEL": p("LEVEL"),
           "VARIANT": v(0), "ANCHOR_LON": o("georef", "ANCHOR_LON"), "ANCHOR_LAT": o("georef", "ANCHOR_LAT")},
          outputs=[("OUTPUT", "OSM", "osmAG file")])
    model.updateDestinationParameters()
    return model


def main():
    sys.path.insert(0, os.path.join(REPO, "tests"))
    sys.path.insert(0, REPO)
    from conftest import headless_qgis  # noqa: E402 - QGIS, and the repository as the package 'cad2osmag'

    app, _ = headless_qgis()  # noqa: F841 - QGIS lives as long as app
    from qgis.core import QgsApplication
    from cad2osmag.processing_provider.provider import Cad2OsmagProvider

    provider = Cad2OsmagProvider(include_models=False)
    QgsApplication.processingRegistry().addProvider(provider)
    model = build()
    ok = model.toFile(MODEL_PATH)
    print(("wrote " if ok else "FAILED to write ") + MODEL_PATH)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
