"""cad2osmag:dxftoosmagbatch — every floor plan of a folder to osmAG, one process per core."""
import csv
import fnmatch
import json
import os
import shutil
import subprocess
import sys
import time

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsProcessingException,
    QgsProcessingOutputFolder,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterPoint,
    QgsProcessingParameterString,
)

from .base import Cad2OsmagAlgorithm

WORKER = os.path.join(os.path.dirname(__file__), "batch_worker.py")
PLUGIN_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def worker_python():
    """A Python interpreter for the worker processes: the checkout's venv, else this Python when it is a
    Python (not the QGIS executable), else python3 on the PATH."""
    venv = os.path.join(PLUGIN_DIR, ".venv", "bin", "python")
    if os.path.exists(venv):
        return venv
    if os.path.basename(sys.executable).lower().startswith("python"):
        return sys.executable
    return shutil.which("python3") or shutil.which("python") or sys.executable


def floor_files(folder, patterns):
    """Files of ``folder`` (not recursive) matching any of the ';'-separated patterns, case-insensitive,
    in natural order (floor-2 before floor-10)."""
    import re

    pats = [p.strip().lower() for p in patterns.split(";") if p.strip()] or ["*.dxf"]
    names = [n for n in os.listdir(folder) if os.path.isfile(os.path.join(folder, n))
             and any(fnmatch.fnmatch(n.lower(), p) for p in pats)]

    def key(n):
        return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", n.lower())]

    return [os.path.join(folder, n) for n in sorted(names, key=key)]


class DxfToOsmagBatchAlgorithm(Cad2OsmagAlgorithm):
    NAME = "dxftoosmagbatch"
    DISPLAY_NAME = "Convert a folder of floor plans to osmAG (parallel)"
    GROUP = "Pipeline"
    GROUP_ID = "pipeline"
    HELP = ("Converts every floor plan of FOLDER (files matching PATTERN, e.g. '*.dxf') with the whole "
            "pipeline of 'Convert DXF floor plan to osmAG', several files at once: WORKERS processes "
            "(0 = one per processor core). Each file writes OUTPUT_FOLDER/NAME.osm (NAME: the drawing's file name). A file that fails "
            "(not a drawing, no walls, …) is reported with its reason and never stops the others.\n"
            "FIRST_LEVEL: the level of the first file in natural name order (floor-2 before floor-10); each "
            "next file is one level up. HEIGHT: floor height in metres.\n"
            "Placement, the same for every floor: ANCHOR is where the drawing origin (0, 0) lies (pick it on "
            "the map), ROTATION the direction of the drawing's +y axis in degrees clockwise from north, SCALE "
            "ground metres per drawing metre. Without ANCHOR the placement saved in the project by "
            "'Place a floor plan on the map' is used, if any.\n"
            "RESOLUTION (m/px), DOOR_WIDTH and CORRIDOR_WIDTH (m), MIN_AREA (m²): as in the single-file "
            "algorithm. MERGE also writes OUTPUT_FOLDER/building.osm with every converted floor.\n"
            "REPORT: a CSV with one row per file (file, level, status, areas, passages, seconds, message).\n"
            "Outputs: SUCCEEDED and FAILED, the numbers of floors converted and failed (one bad file never "
            "stops the others), and OUTPUT_FOLDER.")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFile(
            "FOLDER", self.tr("Folder of floor plans"), QgsProcessingParameterFile.Behavior.Folder))
        self.addParameter(QgsProcessingParameterString("PATTERN", self.tr("File name patterns (';' separated)"),
                                                       "*.dxf"))
        self.addParameter(QgsProcessingParameterNumber("FIRST_LEVEL", self.tr("Level of the first file"),
                                                       QgsProcessingParameterNumber.Type.Integer, 1))
        self.addParameter(QgsProcessingParameterNumber("HEIGHT", self.tr("Floor height (m)"),
                                                       QgsProcessingParameterNumber.Type.Double, 3.2, False, 0.5,
                                                       100.0))
        self.addParameter(QgsProcessingParameterPoint("ANCHOR", self.tr("Position of the drawing origin"),
                                                      optional=True))
        self.addParameter(QgsProcessingParameterNumber(
            "ROTATION", self.tr("Rotation (degrees clockwise from north)"), QgsProcessingParameterNumber.Type.Double,
            0.0, False, -360.0, 360.0))
        self.addParameter(QgsProcessingParameterNumber(
            "SCALE", self.tr("Scale (ground metres per drawing metre)"), QgsProcessingParameterNumber.Type.Double,
            1.0, False, 1e-6, 1e6))
        self.addParameter(QgsProcessingParameterNumber("RESOLUTION", self.tr("Raster resolution (m/px)"),
                                                       QgsProcessingParameterNumber.Type.Double, 0.044, False,
                                                       0.005, 1.0))
        self.addParameter(QgsProcessingParameterNumber("DOOR_WIDTH", self.tr("Widest door (m)"),
                                                       QgsProcessingParameterNumber.Type.Double, 2.8, False, 0.01,
                                                       1000.0))
        self.addParameter(QgsProcessingParameterNumber("CORRIDOR_WIDTH", self.tr("Corridor width (m)"),
                                                       QgsProcessingParameterNumber.Type.Double, 8.0, False, 0.01,
                                                       1000.0))
        self.addParameter(QgsProcessingParameterNumber("MIN_AREA", self.tr("Merge areas smaller than (m²)"),
                                                       QgsProcessingParameterNumber.Type.Double, 10.0, False, 0.0,
                                                       1e6))
        self.addParameter(QgsProcessingParameterNumber("WORKERS", self.tr("Parallel processes (0 = every core)"),
                                                       QgsProcessingParameterNumber.Type.Integer, 0, False, 0, 256))
        self.addParameter(QgsProcessingParameterBoolean("MERGE", self.tr("Also merge the floors into building.osm"),
                                                        False))
        self.addParameter(QgsProcessingParameterFolderDestination("OUTPUT_FOLDER", self.tr("Output folder")))
        self.addParameter(QgsProcessingParameterFileDestination("REPORT", self.tr("Report (CSV)"),
                                                                self.tr("CSV files (*.csv)"), optional=True,
                                                                createByDefault=False))
        self.addOutput(QgsProcessingOutputNumber("SUCCEEDED", self.tr("Floors converted")))
        self.addOutput(QgsProcessingOutputNumber("FAILED", self.tr("Floors that failed")))
        self.addOutput(QgsProcessingOutputFolder("OUTPUT_FOLDER", self.tr("Output folder")))

    # ------------------------------------------------------------------------------------------
    def _anchor(self, parameters, context, feedback):
        wgs84 = QgsCoordinateReferenceSystem("EPSG:4326")
        if parameters.get("ANCHOR") not in (None, ""):
            point = self.parameterAsPoint(parameters, "ANCHOR", context)
            crs = self.parameterAsPointCrs(parameters, "ANCHOR", context)
            if crs.isValid() and crs != wgs84:
                point = QgsCoordinateTransform(crs, wgs84, context.transformContext()).transform(point)
            return (point.x(), point.y(), self.parameterAsDouble(parameters, "ROTATION", context),
                    self.parameterAsDouble(parameters, "SCALE", context))
        try:
            from ..ui.placement import load_placement

            saved = load_placement(context.project()) if context.project() is not None else None
        except Exception:  # noqa: BLE001 - no GUI module available: no saved placement
            saved = None
        if saved is not None:
            feedback.pushInfo(self.tr("using the placement saved in the project: {:.7f}, {:.7f}, {:.2f}°").format(
                saved.anchor_lon, saved.anchor_lat, saved.rotation_deg))
            return saved.anchor_lon, saved.anchor_lat, saved.rotation_deg, saved.scale
        return None, None, self.parameterAsDouble(parameters, "ROTATION", context), \
            self.parameterAsDouble(parameters, "SCALE", context)

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        folder = self.parameterAsFile(parameters, "FOLDER", context)
        if not folder or not os.path.isdir(folder):
            raise QgsProcessingException(self.tr("FOLDER: '{}' is not a folder").format(folder))
        files = floor_files(folder, self.parameterAsString(parameters, "PATTERN", context))
        if not files:
            raise QgsProcessingException(self.tr("no file in '{}' matches '{}': check the folder and the pattern")
                                         .format(folder, self.parameterAsString(parameters, "PATTERN", context)))
        out_dir = self.parameterAsString(parameters, "OUTPUT_FOLDER", context)
        os.makedirs(out_dir, exist_ok=True)
        lon, lat, rot, scale = self._anchor(parameters, context, feedback)
        first = self.parameterAsInt(parameters, "FIRST_LEVEL", context)
        common = {
            "anchor_lon": lon, "anchor_lat": lat, "rotation_deg": rot, "scale": scale,
            "height": self.parameterAsDouble(parameters, "HEIGHT", context),
            "resolution": self.parameterAsDouble(parameters, "RESOLUTION", context),
            "door_width": self.parameterAsDouble(parameters, "DOOR_WIDTH", context),
            "corridor_width": self.parameterAsDouble(parameters, "CORRIDOR_WIDTH", context),
            "min_area": self.parameterAsDouble(parameters, "MIN_AREA", context),
        }
        jobs = []
        for k, path in enumerate(files):
            stem = os.path.splitext(os.path.basename(path))[0]
            jobs.append({"dxf": path, "out": os.path.join(out_dir, stem + ".osm"),
                         "kwargs": dict(common, level=str(first + k))})
        workers = self.parameterAsInt(parameters, "WORKERS", context) or (os.cpu_count() or 1)
        workers = max(1, min(workers, len(jobs)))
        feedback.pushInfo(self.tr("{} files, {} parallel processes").format(len(jobs), workers))
        rows = self._run_pool(jobs, workers, feedback)
        ok = [r for r in rows if r["status"] == "ok"]
        if self.parameterAsBool(parameters, "MERGE", context) and ok:
            from ..algorithms import building

            merged = os.path.join(out_dir, "building.osm")
            self.call(feedback, building.merge_floor_files, [r["osm"] for r in ok], merged)
            feedback.pushInfo(self.tr("merged {} floors into {}").format(len(ok), merged))
        report = self.parameterAsFileOutput(parameters, "REPORT", context)
        if report:
            self._write_report(report, rows)
        failed = len(rows) - len(ok)
        if failed:
            feedback.pushWarning(self.tr("{} of {} files failed: {}").format(
                failed, len(rows), ", ".join(os.path.basename(r["file"]) for r in rows if r["status"] != "ok")))
        result = {"OUTPUT_FOLDER": out_dir, "SUCCEEDED": len(ok), "FAILED": failed}
        if report:
            result["REPORT"] = report
        return result

    def _run_pool(self, jobs, workers, feedback):
        """Run the jobs in at most ``workers`` worker processes; cancel kills them. One row per job."""
        python = worker_python()
        pending = list(enumerate(jobs))
        running = {}  # index -> (Popen, start time)
        rows = [None] * len(jobs)
        done = 0
        try:
            while pending or running:
                while pending and len(running) < workers:
                    i, job = pending.pop(0)
                    proc = subprocess.Popen([python, WORKER], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                            stderr=subprocess.PIPE, text=True)
                    proc.stdin.write(json.dumps(job))
                    proc.stdin.close()
                    running[i] = (proc, time.perf_counter())
                    feedback.pushInfo(self.tr("started {} (level {})").format(os.path.basename(job["dxf"]),
                                                                            job["kwargs"]["level"]))
                finished = [i for i, (p, _) in running.items() if p.poll() is not None]
                for i in finished:
                    proc, t0 = running.pop(i)
                    rows[i] = self._row(jobs[i], proc, time.perf_counter() - t0, feedback)
                    done += 1
                    feedback.setProgress(100.0 * done / len(jobs))
                if feedback.isCanceled():
                    raise QgsProcessingException(self.tr("Canceled by the user."))
                if not finished:
                    time.sleep(0.1)
        finally:
            for proc, _ in running.values():
                proc.kill()
                proc.wait()
        return rows

    def _row(self, job, proc, seconds, feedback):
        out, err = proc.stdout.read(), proc.stderr.read()
        name = os.path.basename(job["dxf"])
        result = None
        for line in reversed(out.strip().splitlines()):
            try:
                result = json.loads(line)
                break
            except ValueError:
                continue
        if result is None:
            tail = (err or out).strip().splitlines()[-1:] or [self.tr("exit code {}").format(proc.returncode)]
            result = {"ok": False, "error": self.tr("the worker process ended without a result: {}").format(tail[0])}
        for w in result.get("warnings", []):
            feedback.pushWarning(f"{name}: {w}")
        row = {"file": job["dxf"], "level": job["kwargs"]["level"], "seconds": round(seconds, 2),
               "osm": job["out"], "areas": result.get("areas", ""), "passages": result.get("passages", "")}
        if result.get("ok"):
            row.update(status="ok", message="")
            feedback.pushInfo(self.tr("{}: {} areas, {} passages in {:.1f} s -> {}").format(
                name, row["areas"], row["passages"], seconds, job["out"]))
        else:
            row.update(status="failed", message=result.get("error", ""))
            feedback.reportError(self.tr("{}: failed: {}").format(name, row["message"]), False)
        return row

    @staticmethod
    def _write_report(path, rows):
        from ..algorithms.io_utils import atomic_path

        fields = ["file", "level", "status", "areas", "passages", "seconds", "message", "osm"]
        with atomic_path(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as fh:
            writer = csv.DictWriter(fh, fieldnames=fields)
            writer.writeheader()
            for r in rows:
                writer.writerow({k: r.get(k, "") for k in fields})
