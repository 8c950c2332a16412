"""Batch processing: QGIS's batch dialog on every algorithm, and dxftoosmagbatch converting a folder of floors
in parallel worker processes, reporting per file, one bad file never stopping the others."""
import csv
import os

import pytest

from algorithms import osmag
from algorithms.sample_building import generate_building

from .conftest import plugin_package
from .qgis_inprocess import run_alg_inprocess
from .qgis_process import run_alg

ANCHOR = (121.5906, 31.1790)


@pytest.fixture(scope="module")
def floors_folder(tmp_path_factory):
    """Three sample floors plus a file that only pretends to be a DXF (named to sort last)."""
    folder = tmp_path_factory.mktemp("floors")
    sample = generate_building(str(folder), floors=3, seed=2)
    (folder / "zz-broken.dxf").write_text("this is not a drawing\n")
    (folder / "notes.txt").write_text("not matched by the pattern\n")
    return folder, sample


def test_floor_files_are_matched_case_insensitively_in_natural_order(tmp_path):
    plugin_package()
    from cad2osmag.processing_provider.alg_dxf_to_osmag_batch import floor_files

    for n in ("floor-10.DXF", "floor-2.dxf", "floor-1.dxf", "readme.txt", "plan.dwg"):
        (tmp_path / n).write_text("x")
    assert [os.path.basename(p) for p in floor_files(str(tmp_path), "*.dxf")] == [
        "floor-1.dxf", "floor-2.dxf", "floor-10.DXF"]
    assert len(floor_files(str(tmp_path), "*.dxf; *.dwg")) == 4


def _run(alg_id, params):
    return run_alg_inprocess(alg_id, params)


@pytest.mark.slow  # three floors through the whole pipeline (about 40 s on 2 cores)
def test_folder_batch_converts_every_floor_in_parallel_and_reports_the_bad_file(provider, floors_folder, tmp_path):
    folder, sample = floors_folder
    out = tmp_path / "out"
    report = tmp_path / "report.csv"
    res, ok, fb = _run("cad2osmag:dxftoosmagbatch", {
        "FOLDER": str(folder), "PATTERN": "*.dxf", "FIRST_LEVEL": 1, "ANCHOR": f"{ANCHOR[0]},{ANCHOR[1]} [EPSG:4326]",
        "ROTATION": 15.0, "WORKERS": 0, "MERGE": True, "OUTPUT_FOLDER": str(out), "REPORT": str(report)})
    assert ok, "\n".join(fb.lines)
    assert res["SUCCEEDED"] == 3 and res["FAILED"] == 1
    log = "\n".join(fb.lines)
    assert f"4 files, {min(os.cpu_count(), 4)} parallel processes" in log
    assert "zz-broken.dxf: failed:" in log
    rows = list(csv.DictReader(open(report, encoding="utf-8")))
    assert [os.path.basename(r["file"]) for r in rows] == [os.path.basename(p) for p in sample["dxf"]] + [
        "zz-broken.dxf"]
    assert [r["status"] for r in rows] == ["ok", "ok", "ok", "failed"]
    assert rows[3]["message"] and not os.path.exists(out / "zz-broken.osm")
    for k, path in enumerate(sample["dxf"], 1):
        osm = out / (os.path.splitext(os.path.basename(path))[0] + ".osm")
        areas, passages, root, _ = osmag.read_osmag(str(osm))
        assert root == pytest.approx(ANCHOR, abs=1e-8)
        assert {a.tags.get("level") for a in areas} == {str(k)}
        assert int(rows[k - 1]["areas"]) >= 15 and len(passages) >= 15
    assert (out / "building.osm").is_file()


def test_folder_batch_without_a_matching_file_says_so(provider, tmp_path):
    res, ok, fb = _run("cad2osmag:dxftoosmagbatch", {"FOLDER": str(tmp_path), "PATTERN": "*.dxf",
                                                     "OUTPUT_FOLDER": str(tmp_path / "o")})
    assert not ok
    assert any("no file in" in line for line in fb.lines)


def test_batch_dialog_opens_for_every_algorithm_and_runs_three_files(provider, qgis_iface, floors_folder, tmp_path):
    """QGIS's own batch dialog (processing.gui.BatchAlgorithmDialog): every algorithm gets a batch table,
    and three rows of extractstructure run and write their outputs."""
    import qgis.utils

    qgis.utils.iface = qgis_iface
    from processing.gui.BatchAlgorithmDialog import BatchAlgorithmDialog
    from processing.tools import dataobjects

    for alg in provider.algorithms():
        dialog = BatchAlgorithmDialog(alg.create())
        panel = dialog.mainWidget()
        assert panel.batchRowCount() >= 1, alg.id()
        dialog.close()
    folder, sample = floors_folder
    dialog = BatchAlgorithmDialog(provider.algorithm("extractstructure").create())
    panel = dialog.mainWidget()
    panel.addRow(3 - panel.batchRowCount())
    assert panel.batchRowCount() == 3
    panel.checkLoadLayersOnCompletion.setChecked(False)
    context = dataobjects.createContext()
    outs = []
    for row, dxf in enumerate(sample["dxf"]):
        panel.wrappers[row][panel.parameter_to_column["INPUT"]].setParameterValue(dxf, context)
        for name in ("WALLS", "TEXTS"):
            path = str(tmp_path / f"{name.lower()}-{row + 1}.gpkg")
            panel.tblParameters.cellWidget(row + 1, panel.parameter_to_column[name]).setValue(path)
            outs.append(path)
    params = [panel.parametersForRow(r, warnOnInvalid=False)[0] for r in range(3)]
    assert [p["INPUT"] for p in params] == sample["dxf"]
    dialog.runAlgorithm()
    from qgis.core import QgsApplication, QgsVectorLayer

    # the dialog's progress proxy task lives as long as the dialog's feedback (a signal connection keeps
    # it); in a test session nothing closes the dialog's feedback, so end the task, or exitQgis waits for it
    from qgis.core import QgsProxyProgressTask
    from qgis.PyQt import sip

    for task in QgsApplication.taskManager().tasks():
        if task.description().startswith("Batch Processing"):
            sip.cast(task, QgsProxyProgressTask).finalize(True)
    QgsApplication.processEvents()

    for path in outs:
        layer = QgsVectorLayer(path, "x", "ogr")
        assert layer.isValid() and layer.featureCount() > 10, path
    dialog.close()


@pytest.mark.slow
@pytest.mark.qgis_process
def test_folder_batch_headless(floors_folder, tmp_path):
    folder, sample = floors_folder
    _, res, log = run_alg("dxftoosmagbatch", {"FOLDER": str(folder), "OUTPUT_FOLDER": str(tmp_path / "o"),
                                              "ANCHOR": f"{ANCHOR[0]},{ANCHOR[1]} [EPSG:4326]", "WORKERS": 2,
                                              "FIRST_LEVEL": 0, "REPORT": str(tmp_path / "r.csv")})
    assert res["SUCCEEDED"] == 3 and res["FAILED"] == 1
    assert "zz-broken.dxf" in log
    areas, _, _, _ = osmag.read_osmag(str(tmp_path / "o" / (os.path.splitext(os.path.basename(sample["dxf"][0]))[0]
                                                           + ".osm")))
    assert {a.tags.get("level") for a in areas} == {"0"}
