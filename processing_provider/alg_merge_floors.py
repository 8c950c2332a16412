"""cad2osmag:mergefloors — per-floor osmAG files -> one building file."""
from qgis.core import (
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterMultipleLayers,
    QgsProcessingParameterString,
    QgsProcessing,
)

from ..algorithms import building
from .base import Cad2OsmagAlgorithm


class MergeFloorsAlgorithm(Cad2OsmagAlgorithm):
    NAME = "mergefloors"
    DISPLAY_NAME = "Merge osmAG floors into a building"
    GROUP = "Tools"
    GROUP_ID = "tools"
    HELP = ("Combines osmAG files of single floors, converted with the same anchor, into one building file: "
            "ids are renumbered, one root node is kept, and a building structure area becomes the parent of "
            "every floor outline. Floors are not moved and no vertical passages are added.")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterMultipleLayers("FLOORS", self.tr("osmAG floor files"),
                                                               QgsProcessing.SourceType.TypeFile))
        self.addParameter(QgsProcessingParameterString("NAME", self.tr("Building name"), "Building"))
        self.addParameter(QgsProcessingParameterFileDestination("OUTPUT", self.tr("Building osmAG file"),
                                                                self.tr("OpenStreetMap XML (*.osm)")))
        self.addOutput(QgsProcessingOutputNumber("FLOOR_COUNT", self.tr("Floors")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        value = parameters.get("FLOORS") or []
        paths = [str(v) for v in (value if isinstance(value, (list, tuple)) else str(value).split(";")) if str(v)]
        out = self.parameterAsFileOutput(parameters, "OUTPUT", context)
        if not paths:
            raise QgsProcessingException(self.tr("FLOORS: give at least one osmAG floor file"))
        stats = self.call(feedback, building.merge_floor_files, paths, out,
                          building_name=self.parameterAsString(parameters, "NAME", context).strip() or "Building")
        return {"OUTPUT": out, "FLOOR_COUNT": stats["floors"]}
