"""Shared fixtures. Real data lives in ../shared/data beside the repository (never copied in)."""
import collections
import os
import sys
from pathlib import Path

import pytest

# QGIS (through pytest-qgis) needs a Qt platform; tests never open windows.
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

REPO = Path(__file__).resolve().parents[1]
SHARED_DATA = Path(os.environ.get("CAD2OSMAG_SHARED_DATA", REPO.parent / "shared" / "data"))

# Make the repository importable as the package "cad2osmag" (the plugin folder name) and its
# sub-packages importable directly (``import algorithms``) for the pure-Python tests.
if str(REPO) not in sys.path:
    sys.path.insert(0, str(REPO))


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: real-data or long test (skip with -m 'not slow')")
    config.addinivalue_line("markers", "qgis_process: runs scripts/qgis-process in a subprocess")


def plugin_package():
    """The repository imported as the package 'cad2osmag', as QGIS imports the plugin folder."""
    import importlib.util

    if "cad2osmag" not in sys.modules:
        spec = importlib.util.spec_from_file_location("cad2osmag", REPO / "__init__.py",
                                                      submodule_search_locations=[str(REPO)])
        module = importlib.util.module_from_spec(spec)
        sys.modules["cad2osmag"] = module
        spec.loader.exec_module(module)
    return sys.modules["cad2osmag"]


def headless_qgis():
    """Start a QGIS application without a window for the repository's build scripts (models/build_model.py,
    styles/build_styles.py) and import the repository as the package 'cad2osmag'. Returns (app, package):
    keep ``app`` referenced while QGIS is used."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from qgis.core import QgsApplication

    app = QgsApplication([], False)
    app.initQgis()
    return app, plugin_package()


@pytest.fixture(scope="session")
def shared_data() -> Path:
    if not SHARED_DATA.is_dir():
        pytest.skip(f"real data folder {SHARED_DATA} is missing (expected ../shared/data beside the repo)")
    return SHARED_DATA


@pytest.fixture(scope="session")
def repo_root() -> Path:
    return REPO


# --- one conversion of each shared drawing per test session ------------------------------------------
# Several test files run stages 1-5 (pipeline.process_floor) on the same shared drawing with the same
# arguments (test_real_plans, test_semantics). The first caller converts and pickles the result into a
# folder of this session's temporary directory (shared by the pytest-xdist workers), keyed by the file,
# the arguments and a digest of algorithms/; a lock per key makes a second worker wait for that conversion
# instead of repeating it. Every caller gets its own copy (loaded from disk), so tests cannot alter each
# other's results, and a worker holds no more than the floor it is looking at.
def code_digest() -> str:
    """Digest of the code that a cached result depends on (algorithms/, with its rule and data files)."""
    import hashlib

    h = hashlib.sha256()
    for p in sorted((REPO / "algorithms").rglob("*")):
        if p.is_file() and "__pycache__" not in p.parts:
            h.update(str(p.relative_to(REPO)).encode())
            h.update(p.read_bytes())
    return h.hexdigest()[:16]


class FloorCache:
    """Stages 1-5 of a drawing, once per session, whatever level the callers convert it at.

    The level only names things (``process_floor(level=...)``: the generated ids ``<level>-<area id>`` of
    areas no text names and the floor outline's ``Level <level>``), so the key leaves it out: the first
    caller converts at its level, a caller at another level gets the same floor re-levelled (``relevel``).
    When re-levelling could differ from a conversion at that level (a generated id taken by a drawing's
    name), that level is converted on its own. Stage 1 alone (``import_dxf``) is cached too, and a conversion
    stores its import there: the tests of the import on real sheets read what the conversions read."""

    def __init__(self, folder: Path):
        self.folder = folder
        self.folder.mkdir(parents=True, exist_ok=True)
        self.digest = code_digest()
        self.hits = self.misses = self.relevelled = 0
        self.import_hits = self.import_misses = 0
        from algorithms import cad_import, pipeline

        self._process_floor = pipeline.process_floor  # the real ones (convert_dxf below patches the module's)
        self._import_dxf = cad_import.import_dxf

    @staticmethod
    def _bound(func, path, kwargs) -> dict:
        import inspect

        args = inspect.signature(func).bind(path, **kwargs)
        args.apply_defaults()
        return {k: v for k, v in list(args.arguments.items())[1:] if k != "progress"}

    def _arguments(self, path, kwargs) -> dict:
        return self._bound(self._process_floor, path, kwargs)

    def _key(self, path, given) -> str:
        import hashlib

        st = os.stat(path)
        text = repr((os.path.abspath(path), st.st_size, st.st_mtime_ns, sorted(given.items()), self.digest))
        return f"{Path(path).stem}-{hashlib.sha256(text.encode()).hexdigest()[:16]}"

    def key(self, path, kwargs) -> str:
        """The file (path, size, time), every argument but ``level`` (defaults filled in) and the code digest."""
        return self._key(path, {k: v for k, v in self._arguments(path, kwargs).items() if k != "level"})

    def _entry(self, key, compute, counter):
        """(ok, value, tag) of the cache entry ``key``; if missing, ``compute()`` -> (value, tag) fills it (an
        InputError is kept, with ok False). ``counter``: "" (conversions) or "import_" (imports)."""
        import fcntl
        import pickle

        data = self.folder / f"{key}.pickle"
        with open(self.folder / f"{key}.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            try:
                if data.exists():
                    setattr(self, counter + "hits", getattr(self, counter + "hits") + 1)
                    with open(data, "rb") as fh:
                        return pickle.load(fh)
                setattr(self, counter + "misses", getattr(self, counter + "misses") + 1)
                from algorithms.errors import InputError

                try:
                    entry = (True, *compute())
                except InputError as exc:
                    entry = (False, exc, None)
                tmp = data.with_suffix(f".{os.getpid()}.tmp")
                with open(tmp, "wb") as fh:
                    pickle.dump(entry, fh, protocol=pickle.HIGHEST_PROTOCOL)
                os.replace(tmp, data)
                if entry[0]:  # the caller's copy must be as independent as a loaded one
                    with open(data, "rb") as fh:
                        entry = pickle.load(fh)
                return entry
            finally:
                fcntl.flock(lock, fcntl.LOCK_UN)

    def _load_or_convert(self, key, path, progress, kwargs):
        """(ok, value, level) of the conversion ``key``, converted (``kwargs`` with their level) if missing; its
        import goes through ``import_dxf`` (stored before the pipeline uses it)."""
        from unittest import mock

        from algorithms import cad_import

        def convert():
            with mock.patch.object(cad_import, "import_dxf", self.import_dxf):
                return self._process_floor(str(path), progress=progress, **kwargs), str(kwargs["level"])

        return self._entry(key, convert, "")

    def import_dxf(self, path, progress=None, **kwargs):
        """``cad_import.import_dxf(path, **kwargs)`` (stage 1 alone), once per session; the conversions above
        store theirs here, so a test reading a drawing that a conversion read gets it without reading it again
        (``progress`` is not reported on a hit)."""
        given = self._bound(self._import_dxf, str(path), kwargs)
        key = "import-" + self._key(str(path), given)
        ok, value, _ = self._entry(key, lambda: (self._import_dxf(str(path), progress=progress, **given), None),
                                   "import_")
        if not ok:
            raise value
        return value

    def process_floor(self, path, progress=None, **kwargs):
        """``pipeline.process_floor(path, **kwargs)``, computed once per session (``progress`` is not
        reported on a hit). An InputError is cached and raised again like the real conversion's."""
        args = self._arguments(str(path), kwargs)
        level = str(args["level"])
        key = self.key(str(path), kwargs)
        ok, value, done_at = self._load_or_convert(key, path, progress, args)
        if ok and done_at != level:
            if relevel(value, done_at, level):
                self.relevelled += 1
            else:  # re-levelling could differ from a conversion at this level: convert at it
                ok, value, _ = self._load_or_convert(f"{key}-level-{level}", path, progress, args)
        if not ok:
            raise value
        return value

    def patched(self):
        """A context in which ``pipeline.process_floor`` is this cache's (``pipeline.convert_dxf`` and
        ``building.convert_floors(workers=1)`` run on the cached stages 1-5)."""
        from unittest import mock

        from algorithms import pipeline

        return mock.patch.object(pipeline, "process_floor", self.process_floor)

    def convert_dxf(self, path, out_osm, **kwargs):
        """``pipeline.convert_dxf`` (the osmAG file is written) on the cached stages 1-5."""
        from algorithms import pipeline

        with self.patched():
            return pipeline.convert_dxf(str(path), str(out_osm), **kwargs)


def relevel(floor, old: str, new: str) -> bool:
    """Turn ``floor`` (a ``pipeline.FloorResult`` converted at level ``old``) into the one ``process_floor``
    gives at level ``new``, in place: the level only enters the generated ids of the areas no text names
    (``semantics.auto_id``) and the outline's name. False (``floor`` untouched) when that could differ
    from a conversion at ``new``: a generated id suffixed because a name took it, a drawing's name that
    reads like a generated id, or a new id that a name of the floor takes."""
    import re

    from algorithms import semantics

    areas = [a for a in floor.refined.areas if a.type != "structure"]
    if floor.floor_area is not None and floor.floor_area.name != f"Level {old}":
        return False
    if floor.names is not None:
        auto = [a for a in areas if a.name == semantics.auto_id(old, a.id)]
        if len(auto) != floor.names.auto or any(
                re.fullmatch(re.escape(semantics.auto_id(old, a.id)) + r"-\d+", a.name or "") for a in areas):
            return False
        auto_ids = {id(a) for a in auto}
        others = {semantics._key(a.name) for a in floor.refined.areas if a.name and id(a) not in auto_ids}
        keys = [semantics._key(semantics.auto_id(new, a.id)) for a in auto]
        if len(set(keys)) != len(keys) or others.intersection(keys):
            return False
        for a in auto:
            a.name = semantics.auto_id(new, a.id)
    if floor.floor_area is not None:
        floor.floor_area.name = f"Level {new}"
    return True


@pytest.fixture(scope="session")
def floor_cache(tmp_path_factory) -> FloorCache:
    """Stages 1-5 of a drawing computed once per session: ``floor_cache.process_floor(path, **kwargs)``,
    ``floor_cache.convert_dxf(path, out_osm, **kwargs)``. The folder is the session's, shared by the xdist
    workers (their own temporary directories sit side by side in it); ``CAD2OSMAG_FLOOR_CACHE=<folder>`` keeps
    them across runs (never in CI: a run must pay its own conversions to be measured)."""
    if os.environ.get("CAD2OSMAG_FLOOR_CACHE"):  # a developer's folder kept across runs (keys hold the code digest)
        return FloorCache(Path(os.environ["CAD2OSMAG_FLOOR_CACHE"]))
    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    return FloorCache(root / "floor-cache")


@pytest.fixture()
def provider(qgis_app, qgis_processing):
    """The cad2osmag Processing provider registered in the test QGIS (registered here if the plugin is not)."""
    from qgis.core import QgsApplication

    plugin_package()
    from cad2osmag.processing_provider.provider import Cad2OsmagProvider

    registry = QgsApplication.processingRegistry()
    if registry.providerById("cad2osmag") is None:
        prov = Cad2OsmagProvider()
        registry.addProvider(prov)
        yield prov
        registry.removeProvider(prov)
    else:
        yield registry.providerById("cad2osmag")


# --- per-test CPU, wall and memory record (tests/artifacts/test-times-<worker>.json) -------------------
# The CI machine is shared and loaded, so wall times mislead: CPU seconds of the test process and of the
# subprocesses it waited for (qgis_process, fuzz children) say what a test costs. Setup and teardown
# (the first user of a session fixture pays for it) are counted with the test.
_TIMES = []
_OUTCOMES = {}


def pytest_runtest_logreport(report):
    if report.failed or report.skipped or hasattr(report, "wasxfail"):
        outcome = "xfail" if hasattr(report, "wasxfail") else report.outcome
        _OUTCOMES.setdefault(report.nodeid, outcome)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    import resource
    import time

    own0, wall0 = time.process_time(), time.perf_counter()
    kids0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    yield
    kids1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    _TIMES.append({
        "test": item.nodeid,
        "cpu": round(time.process_time() - own0, 3),
        "child_cpu": round(kids1.ru_utime + kids1.ru_stime - kids0.ru_utime - kids0.ru_stime, 3),
        "wall": round(time.perf_counter() - wall0, 3),
        "maxrss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1),
        "child_maxrss_mb": round(kids1.ru_maxrss / 1024, 1),
        "outcome": _OUTCOMES.pop(item.nodeid, "passed"),
    })
    if len(_TIMES) % 10 == 0:  # a run stopped half-way still leaves its figures
        pytest_sessionfinish(None, None)


def pytest_sessionfinish(session, exitstatus):
    if not _TIMES:
        return
    import json

    worker = os.environ.get("PYTEST_XDIST_WORKER", os.environ.get("CAD2OSMAG_TEST_TIMES_NAME", "main"))
    folder = REPO / "tests" / "artifacts"
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"test-times-{worker}.json"
    tmp = path.with_suffix(".json.tmp")
    tmp.write_text(json.dumps(_TIMES, indent=1))
    os.replace(tmp, path)


# --- heaviest files first on the xdist workers ---------------------------------------------------------
# With `-n 2 --dist loadfile` a test file runs on one worker. pytest-xdist hands the files out by their
# number of tests; handing out the most expensive first instead keeps a long real-data file from running
# alone at the end while the other core idles (longest-processing-time-first). CPU seconds per file from
# the record above (tests/artifacts/test-times-*.json); a file not listed counts as light.
FILE_CPU_SECONDS = {
    # measured 2026-12-02 in one process at load ~20 (own + child CPU s, with the session's shared conversions:
    # the first user of a sheet pays for it), after the level-free floor cache, the import cache and the
    # qgis_process dispatch (README "Tests"). test_real_plans and test_building_dwg first: between them they
    # convert the 13 DXF plans and 8 DWG sheets (~260 CPU s) that eight other files then read from the cache.
    "test_real_plans.py": 260, "test_building_dwg.py": 200,
    "test_qgis_pipeline.py": 128, "test_qgis_cad.py": 116, "test_qgis_dwg.py": 49, "test_semantics.py": 40,
    "test_qgis_osmag.py": 39, "test_qgis_names.py": 35, "test_qgis_segment.py": 30, "test_building.py": 30,
    "test_segmentation_qgis.py": 26, "test_gui_plans.py": 24, "test_qgis_sheet.py": 23, "test_qgis_route.py": 26,
    "test_qgis_merge.py": 22, "test_limits.py": 21, "test_cad_classify_connect.py": 18, "test_fuzz_qgis.py": 17,
    "test_segmentation_real.py": 11,
    # measured 2026-12-01 (-n 2, load 10-14), not changed since
    "test_fuzz_dxf.py": 122, "test_determinism.py": 72, "test_cancel.py": 66,
    "test_dwg.py": 43, "test_package.py": 34, "test_routing.py": 28, "test_batch.py": 24, "test_bench.py": 19,
    "test_pipeline.py": 17,
    # estimated from what they convert (500 DWG mutants; the osmAG authors' client build), and measured
    # 2026-12-02 with the reads cached (55 and 36 CPU s before) the sheet and DXF import checks
    "test_fuzz_dwg.py": 150, "test_osmag_client.py": 60, "test_sheet_real.py": 10, "test_real_dxf.py": 7,
}


class _HeaviestFirst(collections.OrderedDict):
    """xdist's queue of test files: the next file handed out is the most expensive one left."""

    def popitem(self, last=True):
        if last or not self:
            return super().popitem(last)
        scope = max(self, key=lambda s: FILE_CPU_SECONDS.get(Path(s.split("::")[0]).name, 0))
        return scope, self.pop(scope)


try:
    import xdist  # noqa: F401
except ImportError:  # one process: nothing to schedule
    pass
else:
    def pytest_xdist_make_scheduler(config, log):
        if config.getoption("dist") != "loadfile":
            return None
        from xdist.scheduler import LoadFileScheduling

        scheduler = LoadFileScheduling(config, log)
        scheduler.workqueue = _HeaviestFirst()
        return scheduler
