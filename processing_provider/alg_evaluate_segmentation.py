"""cad2osmag:evaluatesegmentation — score an area id raster against a ground-truth colour image."""
import csv
import os

from qgis.core import (
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterRasterLayer,
)

from ..algorithms import evaluate as ev
from ..algorithms.errors import InputError
from ..algorithms.io_utils import atomic_write
from .base import Cad2OsmagAlgorithm


class EvaluateSegmentationAlgorithm(Cad2OsmagAlgorithm):
    NAME = "evaluatesegmentation"
    DISPLAY_NAME = "Evaluate segmentation against ground truth"
    GROUP = "Tools"
    GROUP_ID = "tools"
    HELP = ("Compares the LABELS raster of 'Segment' (area ids, 0 = none) with a ground-truth image of the same "
            "size that paints every room in its own colour (black walls, white or grey outside). For every "
            "ground-truth room the predicted area with the largest overlap is its match: recall and "
            "precision of that match, the Matthews correlation coefficient (MCC) of the two masks over the "
            "annotated and segmented pixels (weighted by room area), and the F1 score of rooms matched one "
            "to one at IoU >= 0.5.\n"
            "LABELS: the area id raster written by 'Segment' (one integer per pixel).\n"
            "GROUND_TRUTH: a PNG, BMP or TIFF image with exactly the raster's width and height in pixels.\n"
            "MIN_ROOM_PX: ground-truth colours covering fewer pixels than this are antialiasing or labels, "
            "not rooms, and are ignored (pixels; at 0.05 m/px, 40 px are 0.1 m²).\n"
            "REPORT (optional): a CSV with one row per ground-truth room (colour, pixels, matched area, "
            "recall, precision, IoU).\n"
            "Outputs: MCC, F1, mean RECALL and PRECISION (0-1), the number of ground-truth rooms (GT_ROOMS), "
            "predicted areas (PREDICTED_AREAS) and rooms matched at IoU >= 0.5 (MATCHED).")

    LABELS = "LABELS"
    GROUND_TRUTH = "GROUND_TRUTH"
    MIN_ROOM_PX = "MIN_ROOM_PX"
    REPORT = "REPORT"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterRasterLayer(self.LABELS, self.tr("Area id raster (LABELS of Segment)")))
        self.addParameter(QgsProcessingParameterFile(
            self.GROUND_TRUTH, self.tr("Ground-truth colour image"), fileFilter="Images (*.png *.bmp *.tif *.tiff)"))
        self.addParameter(QgsProcessingParameterNumber(
            self.MIN_ROOM_PX, self.tr("Ignore ground-truth colours covering fewer pixels than"),
            QgsProcessingParameterNumber.Type.Integer, ev.MIN_ROOM_PX, False, 1))
        self.addParameter(QgsProcessingParameterFileDestination(
            self.REPORT, self.tr("Per-room report"), "CSV files (*.csv)", optional=True, createByDefault=False))
        for name, label in (("MCC", "MCC (area-weighted)"), ("F1", "F1 at IoU >= 0.5"), ("RECALL", "Mean recall"),
                            ("PRECISION", "Mean precision"), ("GT_ROOMS", "Ground-truth rooms"),
                            ("PREDICTED_AREAS", "Predicted areas"), ("MATCHED", "Rooms matched at IoU >= 0.5")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        layer = self.parameterAsRasterLayer(parameters, self.LABELS, context)
        if layer is None:
            raise QgsProcessingException(self.tr("LABELS: the raster cannot be opened"))
        labels_path = layer.source().split("|")[0]
        gt_path = self.parameterAsFile(parameters, self.GROUND_TRUTH, context)
        if not gt_path or not os.path.isfile(gt_path):
            raise QgsProcessingException(self.tr("GROUND_TRUTH: '{}' does not exist").format(gt_path))
        min_px = self.parameterAsInt(parameters, self.MIN_ROOM_PX, context)
        try:
            res = ev.evaluate_files(labels_path, gt_path, min_room_px=min_px)
        except InputError as exc:
            raise QgsProcessingException(str(exc))
        feedback.pushInfo(self.tr("{} ground-truth rooms, {} predicted areas").format(res["n_gt"], res["n_pred"]))
        feedback.pushInfo(self.tr("recall {:.3f}  precision {:.3f}  MCC {:.3f}  F1 {:.3f}").format(
            res["recall"], res["precision"], res["mcc"], res["f1"]))
        report = self.parameterAsFileOutput(parameters, self.REPORT, context)
        out = {}
        if report:
            with atomic_write(report) as fh:
                w = csv.writer(fh, lineterminator="\n")
                w.writerow(["gt_room", "pixels", "segment", "recall", "precision", "iou", "mcc"])
                for r in res["rooms"]:
                    w.writerow([r["gt"], r["pixels"], r["segment"], f"{r['recall']:.4f}", f"{r['precision']:.4f}",
                                f"{r['iou']:.4f}", f"{r['mcc']:.4f}"])
            out[self.REPORT] = report
        out.update({"MCC": res["mcc"], "F1": res["f1"], "RECALL": res["recall"], "PRECISION": res["precision"],
                    "GT_ROOMS": res["n_gt"], "PREDICTED_AREAS": res["n_pred"], "MATCHED": res["matched"]})
        return out

