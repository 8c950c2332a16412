"""Shared fixtures. Real data lives in ../shared/data beside the repository (never copied in)."""
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
    })


def pytest_sessionfinish(session, exitstatus):
    if not _TIMES:
        return
    import json

    worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
    folder = REPO / "tests" / "artifacts"
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"test-times-{worker}.json"
    tmp = path.with_suffix(".json.tmp")
    tmp.write_text(json.dumps(_TIMES, indent=1))
    os.replace(tmp, path)
