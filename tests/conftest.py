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
