"""Missing Python packages: the plugin still loads, lists every algorithm, says what is missing and
offers to install it (deps.py). Packages are hidden by a meta path finder in a subprocess, as on a
QGIS whose Python lacks them."""
import importlib
import json
import os
import stat
import subprocess
import sys
import textwrap

import pytest

from .conftest import REPO, plugin_package

def deps_module():
    plugin_package()
    return importlib.import_module("cad2osmag.deps")


HIDE = textwrap.dedent('''
    import sys

    class Hide:
        """Acts as if these packages were not installed."""
        names = set(filter(None, "{names}".split(",")))

        def find_spec(self, fullname, path=None, target=None):
            if fullname.split(".")[0] in self.names:
                raise ModuleNotFoundError(f"No module named {{fullname!r}}", name=fullname)
            return None

    sys.meta_path.insert(0, Hide())
''')

PROBE = textwrap.dedent('''
    import json, os, sys, importlib.util
    sys.path.insert(0, {repo!r})
    from qgis.core import QgsApplication
    app = QgsApplication([], True)
    QgsApplication.initQgis()
    sys.path.append(os.path.join(QgsApplication.pkgDataPath(), "python", "plugins"))
    from processing.core.Processing import Processing
    Processing.initialize()
    from qgis.gui import QgsMessageBar
    from qgis.PyQt.QtWidgets import QMainWindow, QLabel

    class Iface:
        def __init__(self):
            self.window = QMainWindow()
            self.bar = QgsMessageBar(self.window)
        def mainWindow(self): return self.window
        def messageBar(self): return self.bar
        def addToolBarIcon(self, a): pass
        def removeToolBarIcon(self, a): pass
        def addPluginToMenu(self, m, a): pass
        def removePluginMenu(self, m, a): pass

    spec = importlib.util.spec_from_file_location("cad2osmag", os.path.join({repo!r}, "__init__.py"),
                                                  submodule_search_locations=[{repo!r}])
    pkg = importlib.util.module_from_spec(spec); sys.modules["cad2osmag"] = pkg; spec.loader.exec_module(pkg)
    iface = Iface()
    plugin = pkg.classFactory(iface)
    plugin.initGui()
    provider = QgsApplication.processingRegistry().providerById("cad2osmag")
    out = {{"algorithms": {{}}, "bar": []}}
    for alg in provider.algorithms():
        ok, msg = alg.canExecute()
        out["algorithms"][alg.name()] = {{"can": ok, "msg": msg, "help": alg.shortHelpString()[:400]}}
    for item in iface.bar.items():
        out["bar"].append(" ".join(w.text() for w in item.findChildren(QLabel)) + " " + item.text()
                          + " " + item.title())
    import processing
    from qgis.core import QgsProcessingException
    try:
        processing.run("cad2osmag:extractstructure", {{"INPUT": "/nonexistent.dxf", "OUTPUT": "memory:"}})
        out["run"] = "ran"
    except QgsProcessingException as exc:
        out["run"] = "QgsProcessingException: " + str(exc)
    except Exception as exc:
        out["run"] = type(exc).__name__ + ": " + str(exc)
    plugin.unload()
    print("JSON" + json.dumps(out))
    QgsApplication.exitQgis()
''')


def run_probe(tmp_path, hidden=()):
    script = tmp_path / "probe.py"
    script.write_text(HIDE.format(names=",".join(hidden)) + PROBE.format(repo=str(REPO)), encoding="utf-8")
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    proc = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=300, env=env,
                          stdin=subprocess.DEVNULL)
    line = next((ln for ln in proc.stdout.splitlines() if ln.startswith("JSON")), None)
    assert line, f"probe failed ({proc.returncode}):\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    return json.loads(line[4:]), proc.stderr


# --- pure functions ---------------------------------------------------------------------------------
def test_every_runtime_requirement_is_known():
    deps = deps_module()
    pinned = {line.split("==")[0].strip().lower() for line in (REPO / "requirements.txt").read_text().splitlines()
              if "==" in line and not line.startswith("#")}
    pip_names = {d.pip.split(">")[0].split("=")[0].lower() for d in deps.DEPENDENCIES}
    for name in ("numpy", "scipy", "opencv-python-headless", "shapely", "pyproj", "ezdxf", "ezdwg"):
        assert name in pinned and name in pip_names, name


def test_static_requirements_follow_the_plugin_imports():
    deps = deps_module()
    extract = deps.static_requirements(str(REPO / "processing_provider" / "alg_extract_structure.py"))
    assert "ezdxf" in extract  # through algorithms.cad_import, imported inside a function
    whole = deps.static_requirements(str(REPO / "processing_provider" / "alg_dxf_to_osmag.py"))
    assert {"ezdxf", "shapely", "cv2", "scipy"} <= set(whole)
    assert "ezdxf" not in deps.static_requirements(str(REPO / "processing_provider" / "alg_evaluate_segmentation.py"))


def test_pip_command_installs_into_the_user_site_and_holds_numpy(tmp_path):
    deps = deps_module()
    constraints = deps.write_constraints()
    try:
        assert open(constraints).read().startswith("numpy==")
        wanted = [deps.BY_MODULE["ezdxf"], deps.BY_MODULE["cv2"]]
        cmd = deps.pip_command(wanted, python="/usr/bin/python3", constraints_path=constraints)
    finally:
        os.remove(constraints)
    assert cmd[:4] == ["/usr/bin/python3", "-m", "pip", "install"]
    assert "--user" in cmd and cmd[cmd.index("--constraint") + 1] == constraints
    assert cmd[-2:] == ["ezdxf>=1.1", "opencv-python-headless>=4.8"]
    # Debian 12/13 mark their Python as externally managed: pip --user needs the override there
    assert ("--break-system-packages" in cmd) == deps.externally_managed()
    assert "ezdxf>=1.1" in deps.manual_command(wanted)


def test_python_executable_is_a_python_not_qgis():
    exe = deps_module().python_executable()
    assert exe and os.access(exe, os.X_OK)
    out = subprocess.run([exe, "-c", "import sys; print(sys.version_info[:2])"], capture_output=True, text=True)
    assert out.stdout.strip() == str(sys.version_info[:2])


def test_nothing_is_missing_here():
    assert deps_module().missing() == []


# --- the plugin without its packages ----------------------------------------------------------------
@pytest.fixture(scope="module")
def probes(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("deps")
    complete, _ = run_probe(tmp)
    hidden, err = run_probe(tmp, hidden=("ezdxf", "shapely"))
    return complete, hidden, err


def test_without_ezdxf_and_shapely_every_algorithm_is_still_listed(probes):
    complete, hidden, err = probes
    assert len(complete["algorithms"]) >= 10
    assert set(hidden["algorithms"]) == set(complete["algorithms"])
    assert "Traceback" not in err and "ModuleNotFoundError" not in err
    assert all(a["can"] for a in complete["algorithms"].values())
    assert complete["bar"] == []


def test_algorithms_that_need_them_say_what_is_missing(probes):
    _, hidden, _ = probes
    algs = hidden["algorithms"]
    for name in ("extractstructure", "dxftoosmag"):
        assert not algs[name]["can"], name
        assert "ezdxf" in algs[name]["msg"] and "restart QGIS" in algs[name]["msg"]
        assert "Missing Python packages" in algs[name]["help"]
    # shapely is imported at module level by the pipeline: the class still exists and names it
    assert "shapely" in algs["dxftoosmag"]["msg"]
    # every other algorithm is blocked only by what it can import (shapely, through base.from_qgs)
    for name, alg in algs.items():
        if not alg["can"]:
            assert "shapely" in alg["msg"] or "ezdxf" in alg["msg"], name


def test_running_one_gives_a_clear_message_not_a_traceback(probes):
    _, hidden, _ = probes
    assert hidden["run"].startswith("QgsProcessingException"), hidden["run"]
    assert "ezdxf" in hidden["run"] and "ModuleNotFoundError" not in hidden["run"]


def test_the_message_bar_names_the_missing_packages(probes):
    _, hidden, _ = probes
    assert len(hidden["bar"]) == 1
    text = hidden["bar"][0]
    assert "ezdxf" in text and "shapely" in text and "Missing Python packages" in text


# --- the installer --------------------------------------------------------------------------------
def fake_python(tmp_path, body):
    path = tmp_path / "python3"
    path.write_text("#!/bin/sh\n" + body, encoding="utf-8")
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return str(path)


@pytest.fixture
def gui_iface(qgis_app):
    from qgis.gui import QgsMessageBar
    from qgis.PyQt.QtWidgets import QMainWindow

    class Iface:
        def __init__(self):
            self.window = QMainWindow()
            self.bar = QgsMessageBar(self.window)

        def mainWindow(self):  # noqa: N802
            return self.window

        def messageBar(self):  # noqa: N802
            return self.bar

    return Iface()


def bar_text(iface):
    from qgis.PyQt.QtWidgets import QLabel

    item = iface.bar.currentItem()
    return " ".join([item.title(), item.text()] + [w.text() for w in item.findChildren(QLabel)])


def test_install_reports_progress_then_asks_to_restart(gui_iface, tmp_path):
    from qgis.core import Qgis

    deps = deps_module()
    py = fake_python(tmp_path, 'echo "Collecting ezdxf>=1.1"; echo "Installing collected packages: ezdxf"; '
                               'echo "Successfully installed ezdxf-1.3.5"; echo "$@" > "$(dirname "$0")/args"\n')
    inst = deps.DependencyInstaller(gui_iface, [deps.BY_MODULE["ezdxf"]], python=py)
    inst.offer()
    assert "ezdxf" in bar_text(gui_iface)
    inst.start()
    assert inst.state == "running" and inst.progress_bar is not None
    assert inst.wait(30000)
    assert inst.state == "done", inst.output
    assert inst.progress_bar is None or True
    assert gui_iface.bar.currentItem().level() == Qgis.MessageLevel.Success
    assert "Restart QGIS" in bar_text(gui_iface)
    args = (tmp_path / "args").read_text().split()
    assert args[:3] == ["-m", "pip", "install"] and "--user" in args and "ezdxf>=1.1" in args
    assert inst.constraints is None  # the temporary constraints file is removed


def test_install_failure_is_reported_clearly(gui_iface, tmp_path):
    from qgis.core import Qgis

    deps = deps_module()
    py = fake_python(tmp_path, 'echo "Collecting ezdxf>=1.1"; '
                               'echo "ERROR: No matching distribution found for ezdxf>=1.1"; exit 1\n')
    inst = deps.DependencyInstaller(gui_iface, [deps.BY_MODULE["ezdxf"]], python=py)
    inst.start()
    assert inst.wait(30000)
    assert inst.state == "failed"
    assert gui_iface.bar.currentItem().level() == Qgis.MessageLevel.Critical
    text = bar_text(gui_iface)
    assert "No matching distribution found for ezdxf" in text and "Details" in text
    details = inst.details_text()
    assert "pip install --user" in details and "ezdxf>=1.1" in details
    assert any("No matching distribution" in line for line in inst.output)


def test_install_without_python_says_so(gui_iface, tmp_path):
    deps = deps_module()
    inst = deps.DependencyInstaller(gui_iface, [deps.BY_MODULE["ezdxf"]], python=str(tmp_path / "no-python"))
    inst.start()
    inst.wait(10000)
    from qgis.PyQt.QtCore import QCoreApplication

    QCoreApplication.processEvents()
    assert inst.state == "failed"
    assert "Could not start Python" in bar_text(gui_iface)


def test_pyproj_comes_from_the_distribution_on_linux(monkeypatch):
    deps = deps_module()
    monkeypatch.setattr(deps.sys, "platform", "linux")
    wanted = [deps.BY_MODULE["pyproj"], deps.BY_MODULE["ezdxf"]]
    cmd = deps.pip_command(wanted, python="python3")
    assert "ezdxf>=1.1" in cmd and not any(c.startswith("pyproj") for c in cmd)
    assert "apt install python3-pyproj" in deps.missing_message(wanted)
    monkeypatch.setattr(deps.sys, "platform", "win32")
    assert "pyproj>=3.4" in deps.pip_command(wanted, python="python.exe")
    assert "apt" not in deps.missing_message(wanted)
