"""Run cad2osmag algorithms headless through scripts/qgis-process (a subprocess) in tests.

Each qgis_process start costs ~3.5 CPU s of QGIS start and plugin import, more than most algorithm runs
themselves. So ``run_alg`` spawns qgis_process for the first run of each algorithm in each test file (every
file that tests an algorithm keeps a real command-line run of it, whatever the scheduling) and for every run
with ``check=False`` (the failure paths: exit code and message as the command line gives them); the later
successful runs of the same algorithm in the same file run the same Processing class inside the test's QGIS
(``tests/qgis_inprocess.py``), with its parameters given as the same strings and its results and log returned
as qgis_process returns them. ``CAD2OSMAG_TEST_HEADLESS=1`` in the environment spawns qgis_process for every run.
"""
import json
import os
import sqlite3
import subprocess

from .conftest import REPO

SCRIPT = str(REPO / "scripts" / "qgis-process")

# (test file, algorithm) that ran headless with success in this process
_SPAWNED = set()
# what ran where in this process (tests/test_qgis_cad.py checks the dispatch)
COUNTS = {"headless": 0, "inprocess": 0}


def _headless_always() -> bool:
    return os.environ.get("CAD2OSMAG_TEST_HEADLESS", "").strip().lower() in ("1", "yes", "true", "all")


def _test_file() -> str:
    return os.environ.get("PYTEST_CURRENT_TEST", "").split("::")[0]


def run_alg(alg, params, timeout=600, check=True, headless=None):
    """Run ``cad2osmag:<alg>`` with ``params`` (dict; list values repeat the parameter).

    Returns (returncode, results dict or None, combined output). With ``check`` a non-zero exit fails
    with the tool's output in the message. Headless (qgis_process) or in the test's QGIS: see the module;
    ``headless=True`` always spawns qgis_process.
    """
    key = (_test_file(), alg)
    if check and not headless and key in _SPAWNED and not _headless_always() and _inprocess_ready():
        return _run_inprocess(alg, params)
    args = [SCRIPT, "--json", "run", f"cad2osmag:{alg}", "--"]
    for k, value in params.items():
        for v in (value if isinstance(value, (list, tuple)) else [value]):
            args.append(f"{k}={v}")
    proc = subprocess.run(args, capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)
    COUNTS["headless"] += 1
    output = proc.stdout + proc.stderr
    results = None
    start = proc.stdout.find("{")
    if proc.returncode == 0 and start >= 0:
        try:
            results = json.loads(proc.stdout[start:]).get("results")
        except ValueError:
            results = None
    if check:
        assert proc.returncode == 0, f"cad2osmag:{alg} failed:\n{output[-4000:]}"
    if proc.returncode == 0 and results is not None:
        _SPAWNED.add(key)
    return proc.returncode, results, output


def _inprocess_ready() -> bool:
    """QGIS runs in this process (pytest-qgis starts it) and Processing is initialised."""
    try:
        import sys

        from qgis.core import QgsApplication
    except ImportError:
        return False
    app = QgsApplication.instance()
    if app is None:
        return False
    registry = QgsApplication.processingRegistry()
    if registry.providerById("native") is None:
        plugins = os.path.join(app.pkgDataPath(), "python", "plugins")
        if plugins not in sys.path:
            sys.path.append(plugins)
        from processing.core.Processing import Processing

        Processing.initialize()
    return registry.providerById("native") is not None


def _add_provider():
    """The cad2osmag provider registered for one in-process run when nobody has (the plugin, the ``provider``
    fixture): returns the one added here, which the caller removes again, so that a test loading the plugin
    later registers its own (a provider left behind makes the plugin's a duplicate, deleted by the registry)."""
    from qgis.core import QgsApplication

    registry = QgsApplication.processingRegistry()
    if registry.providerById("cad2osmag") is not None:
        return None
    from .conftest import plugin_package

    plugin_package()
    from cad2osmag.processing_provider.provider import Cad2OsmagProvider

    prov = Cad2OsmagProvider()
    registry.addProvider(prov)
    return prov


def _run_inprocess(alg, params):
    """``run_alg`` inside the test's QGIS: the parameters as the strings qgis_process would get, the results
    through JSON as qgis_process prints them, the log lines as its output. A failed run fails the test with
    its log (only ``check=True`` runs come here)."""
    from .qgis_inprocess import run_alg_inprocess

    from qgis.core import QgsApplication

    values = {k: ([str(x) for x in v] if isinstance(v, (list, tuple)) else str(v)) for k, v in params.items()}
    added = _add_provider()
    try:
        results, ok, feedback = run_alg_inprocess(alg, values)
    finally:
        if added is not None:
            QgsApplication.processingRegistry().removeProvider(added)
    COUNTS["inprocess"] += 1
    output = "\n".join(feedback.lines)
    assert ok, f"cad2osmag:{alg} failed (in the test's QGIS; CAD2OSMAG_TEST_HEADLESS=1 runs it headless):\n" \
               f"{output[-4000:]}"
    results = json.loads(json.dumps(results, default=str))
    return 0, results, output


def gpkg_rows(path, sql):
    """The rows of an SQL query on a GeoPackage an algorithm wrote; ``{t}`` in the query stands for its table."""
    con = sqlite3.connect(str(path))
    try:
        if "{t}" in sql:
            sql = sql.format(t=con.execute("select table_name from gpkg_contents").fetchone()[0])
        return con.execute(sql).fetchall()
    finally:
        con.close()


def gpkg_table(path):
    """The table name of the (first) layer of a GeoPackage."""
    return gpkg_rows(path, "select table_name from gpkg_contents")[0][0]


def layer_rows(path, fields, wkt=False):
    """The given fields of every feature of a vector file's first layer (OGR), plus its WKT if asked."""
    from osgeo import ogr

    ds = ogr.Open(str(path))
    rows = []
    for f in ds.GetLayer(0):
        row = {k: f.GetField(k) for k in fields}
        if wkt:
            row["wkt"] = f.GetGeometryRef().ExportToWkt()
        rows.append(row)
    return rows
