"""cad2osmag:samplebuilding — the built-in, deterministic sample building (DXF + ground truth)."""
from qgis.core import (
    QgsProcessingOutputFile,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterString,
)

from ..algorithms import sample_building
from .base import Cad2OsmagAlgorithm


class SampleBuildingAlgorithm(Cad2OsmagAlgorithm):
    NAME = "samplebuilding"
    DISPLAY_NAME = "Generate sample building (DXF)"
    GROUP = "Tools"
    GROUP_ID = "tools"
    HELP = ("Writes a realistic multi-floor office building as DXF files (millimetres, NCS layers, walls "
            "with real thickness, doors as blocks, glazing, a stair core and a lift, room names as TEXT, "
            "MTEXT and ATTRIB, nested blocks on layer 0, furniture and dimensions) together with a "
            "ground-truth GeoJSON per floor (rooms, doors, stair/lift anchors, in metres). The same seed "
            "always gives byte-identical files. Use it to try the pipeline or to score it.\n"
            "FLOORS: number of floors (1-20), one DXF and one ground-truth file each; all floors share the "
            "stair core and the lift, so they stack.\n"
            "SEED: any whole number; it varies the room layout (0 is the layout the README shows).\n"
            "PREFIX: start of the file names: PREFIX-F1.dxf, PREFIX-F1.gt.geojson, …\n"
            "OUTPUT_FOLDER: where the files are written (created when missing).\n"
            "Outputs: FIRST_FLOOR_DXF (the first floor's DXF), DXF_FILES (every DXF, ';' separated), "
            "GROUND_TRUTH_FILES (the ground-truth GeoJSON files, ';' separated) and FLOOR_COUNT (floors written).")

    FLOORS = "FLOORS"
    SEED = "SEED"
    PREFIX = "PREFIX"
    OUTPUT_FOLDER = "OUTPUT_FOLDER"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterNumber(
            self.FLOORS, self.tr("Number of floors"), QgsProcessingParameterNumber.Type.Integer, 3, False, 1, 20))
        self.addParameter(QgsProcessingParameterNumber(
            self.SEED, self.tr("Random seed (layout variations)"), QgsProcessingParameterNumber.Type.Integer, 0,
            False, 0))
        self.addParameter(QgsProcessingParameterString(self.PREFIX, self.tr("File name prefix"), "sample"))
        self.addParameter(QgsProcessingParameterFolderDestination(self.OUTPUT_FOLDER, self.tr("Output folder")))
        self.addOutput(QgsProcessingOutputFile("FIRST_FLOOR_DXF", self.tr("DXF of the first floor")))
        self.addOutput(QgsProcessingOutputString("DXF_FILES", self.tr("All DXF files (semicolon separated)")))
        self.addOutput(QgsProcessingOutputString("GROUND_TRUTH_FILES",
                                                 self.tr("Ground-truth GeoJSON files (semicolon separated)")))
        self.addOutput(QgsProcessingOutputNumber("FLOOR_COUNT", self.tr("Number of floors written")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        floors = self.parameterAsInt(parameters, self.FLOORS, context)
        seed = self.parameterAsInt(parameters, self.SEED, context)
        prefix = self.parameterAsString(parameters, self.PREFIX, context).strip() or "sample"
        folder = self.parameterAsString(parameters, self.OUTPUT_FOLDER, context)
        result = self.call(feedback, sample_building.generate_building, folder, floors=floors, seed=seed,
                           name=prefix)
        for path in result["dxf"]:
            feedback.pushInfo(self.tr("Wrote {}").format(path))
        return {
            self.OUTPUT_FOLDER: folder,
            "FIRST_FLOOR_DXF": result["dxf"][0],
            "DXF_FILES": ";".join(result["dxf"]),
            "GROUND_TRUTH_FILES": ";".join(result["ground_truth"]),
            "FLOOR_COUNT": len(result["dxf"]),
        }
