"""Python packages the plugin needs that QGIS does not ship: find the missing ones, keep the plugin
loadable without them, and offer to install them into QGIS's own Python.

QGIS users install the plugin from a ZIP into a QGIS whose Python has numpy and GDAL but usually not
ezdxf, OpenCV, shapely 2, scipy, pyproj or a DWG reader. Then:

* ``missing()`` names what is absent (cheap: ``find_spec`` and distribution metadata, no import);
* ``import_algorithm_module()`` imports a ``processing_provider/alg_*.py`` module even when a package it
  imports at module level is missing (the missing package is replaced by an inert stand-in for the
  duration of that import), and ``guard_algorithm()`` turns its class into one that is still listed
  but says what is missing (``canExecute``, help text, parameter check, run) instead of raising;
* ``notify_missing(iface)`` (the single call from plugin.py) shows a message bar naming the missing
  packages with an "Install" button: pip installs them into the user site of QGIS's Python, with
  progress, a clear failure message, and asks to restart QGIS when done.

Nothing here imports a dependency; qgis/PyQt are imported only inside the functions that need them.
"""
from __future__ import annotations

import ast
import importlib
import importlib.util
import os
import re
import shutil
import sys
import sysconfig
import tempfile
import types
from dataclasses import dataclass
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

PLUGIN_DIR = os.path.dirname(os.path.abspath(__file__))
LOG_TAG = "cad2osmag"


@dataclass(frozen=True)
class Dependency:
    module: str          # import name
    pip: str             # pip requirement (lower bound only: pip picks what fits this Python and numpy)
    purpose: str         # what it is for, in the user's words
    dist: str = ""       # distribution name whose version is checked against min_version
    min_version: str = ""
    optional: bool = False  # the plugin works without it, only some inputs need it
    # On Linux, a package that must be the distribution's build (pip's wheel bundles a library that
    # clashes with the one QGIS links) is named here and left out of the pip command.
    linux_package: str = ""


DEPENDENCIES: Tuple[Dependency, ...] = (
    Dependency("numpy", "numpy", "arrays (ships with QGIS)"),
    Dependency("shapely", "shapely>=2.0", "geometry", dist="shapely", min_version="2.0"),
    Dependency("scipy", "scipy>=1.10", "segmentation"),
    Dependency("cv2", "opencv-python-headless>=4.8", "rasterization and segmentation"),
    Dependency("ezdxf", "ezdxf>=1.1", "reading DXF files"),
    # the pyproj wheel bundles its own PROJ, whose C++ symbols clash with the PROJ QGIS loads on Linux
    # (qgis_process aborts with std::bad_alloc); Windows (OSGeo4W) and macOS QGIS ship pyproj already
    Dependency("pyproj", "pyproj>=3.4", "coordinate reference systems", linux_package="python3-pyproj"),
    Dependency("ezdwg", "ezdwg>=0.17", "reading DWG files", optional=True),
)
BY_MODULE: Dict[str, Dependency] = {d.module: d for d in DEPENDENCIES}


# --- what is missing ------------------------------------------------------------------------------
def _version_tuple(text: str) -> Tuple[int, ...]:
    parts = []
    for piece in re.split(r"[.+-]", text):
        m = re.match(r"\d+", piece)
        if not m:
            break
        parts.append(int(m.group()))
    return tuple(parts)


def is_available(dep: Dependency) -> bool:
    """True when ``dep`` can be imported (and is recent enough), without importing it."""
    try:
        if importlib.util.find_spec(dep.module) is None:
            return False
    except (ImportError, ValueError):  # a broken install or a finder that refuses the name
        return False
    if dep.min_version and dep.dist:
        try:
            from importlib.metadata import PackageNotFoundError, version
        except ImportError:  # pragma: no cover - Python < 3.8
            return True
        try:
            found = version(dep.dist)
        except PackageNotFoundError:
            return True  # importable but without metadata (e.g. a vendored copy): trust it
        return _version_tuple(found) >= _version_tuple(dep.min_version)
    return True


def missing(include_optional: bool = True) -> List[Dependency]:
    return [d for d in DEPENDENCIES if (include_optional or not d.optional) and not is_available(d)]


def _on_linux() -> bool:
    return sys.platform.startswith("linux")


def pip_installable(deps: Sequence[Dependency]) -> List[Dependency]:
    return [d for d in deps if not (d.linux_package and _on_linux())]


def system_packages(deps: Sequence[Dependency]) -> List[str]:
    return [d.linux_package for d in deps if d.linux_package and _on_linux()]


def missing_message(deps: Sequence[Dependency]) -> str:
    names = ", ".join(f"{d.pip.split('>')[0]} ({d.purpose})" for d in deps)
    text = f"Missing Python packages: {names}."
    system = system_packages(deps)
    if system:
        text += (f" Install {', '.join(system)} with your distribution's package manager "
                 f"(e.g. sudo apt install {' '.join(system)}), not with pip.")
    return text


# --- the pip command -------------------------------------------------------------------------------
_PYTHON = []


def python_executable() -> Optional[str]:
    """The interpreter QGIS embeds, as a program pip can run. sys.executable is QGIS itself on Windows
    and macOS, and may be some other python3 found on PATH (pyenv...) on Linux: a candidate counts
    only when it runs on the same installation (same base prefix and version) as QGIS's Python."""
    if _PYTHON:
        return _PYTHON[0]
    ver = f"{sys.version_info.major}.{sys.version_info.minor}"
    candidates = []
    for base in (sys.exec_prefix, sys.base_exec_prefix):
        candidates += [os.path.join(base, "python.exe"), os.path.join(base, "python3.exe"),
                       os.path.join(base, "bin", f"python{ver}"), os.path.join(base, "bin", "python3")]
    exe = sys.executable or ""
    if re.match(r"python[\d.]*(\.exe)?$", os.path.basename(exe), re.IGNORECASE):
        candidates.append(exe)
    for name in (f"python{ver}", "python3", "python"):
        found = shutil.which(name)
        if found:
            candidates.append(found)
    existing = []
    for path in candidates:
        if path and path not in existing and os.path.isfile(path) and os.access(path, os.X_OK):
            existing.append(path)
    want = (os.path.realpath(sys.base_prefix), ver)
    for path in existing:
        try:
            import subprocess

            out = subprocess.run([path, "-c", "import os, sys; print(os.path.realpath(sys.base_prefix)); "
                                  "print('%d.%d' % sys.version_info[:2])"],
                                 capture_output=True, text=True, timeout=20,
                                 creationflags=getattr(subprocess, "CREATE_NO_WINDOW", 0))  # Windows: no console
        except (OSError, subprocess.SubprocessError):
            continue
        if tuple(out.stdout.split()) == want:
            _PYTHON.append(path)
            return path
    _PYTHON.append(existing[0] if existing else None)  # asked once per session
    return _PYTHON[0]


def externally_managed() -> bool:
    """PEP 668 marker (Debian 12+, Ubuntu 23.04+, Fedora...): pip refuses --user without an override."""
    stdlib = sysconfig.get_paths().get("stdlib") or ""
    return os.path.isfile(os.path.join(stdlib, "EXTERNALLY-MANAGED"))


def pip_command(deps: Sequence[Dependency], python: Optional[str] = None,
                constraints_path: Optional[str] = None) -> List[str]:
    """``python -m pip install --user ...`` for ``deps``. numpy is held at the version QGIS runs (its
    GDAL bindings are built against it) through ``constraints_path``."""
    python = python or python_executable() or "python3"
    cmd = [python, "-m", "pip", "install", "--user", "--disable-pip-version-check", "--no-input",
           "--upgrade-strategy", "only-if-needed"]
    if externally_managed():
        cmd.append("--break-system-packages")
    if constraints_path:
        cmd += ["--constraint", constraints_path]
    cmd += [d.pip for d in pip_installable(deps)]
    return cmd


def write_constraints() -> Optional[str]:
    """A pip constraints file holding numpy at the installed version (None when numpy is absent)."""
    try:
        from importlib.metadata import PackageNotFoundError, version

        numpy_version = version("numpy")
    except Exception:  # noqa: BLE001 - no numpy metadata: nothing to hold
        return None
    fd, path = tempfile.mkstemp(prefix="cad2osmag-constraints-", suffix=".txt")
    with os.fdopen(fd, "w", encoding="utf-8") as fh:
        fh.write(f"numpy=={numpy_version}\n")
    return path


def manual_command(deps: Sequence[Dependency]) -> str:
    """The command a user can paste into a shell (OSGeo4W shell on Windows) to do the same."""
    cmd = pip_command(deps)
    cmd[0] = "python" if sys.platform.startswith("win") else (python_executable() or "python3")
    return " ".join(f'"{c}"' if (" " in c or ">" in c or "<" in c) else c for c in cmd)


# --- loading algorithm modules without their dependencies --------------------------------------
class _Inert:
    """Stands for anything from a missing package while a module is imported: attributes, calls,
    items and subclassing all give inert objects; using it for real raises nothing until the
    algorithm runs, which ``guard_algorithm`` prevents."""

    def __init__(self, name="missing"):
        object.__setattr__(self, "_name", name)

    def __getattr__(self, item):
        if item.startswith("__") and item.endswith("__"):
            raise AttributeError(item)
        return _Inert(f"{self._name}.{item}")

    def __call__(self, *args, **kwargs):
        return _Inert(f"{self._name}()")

    def __getitem__(self, item):
        return _Inert(f"{self._name}[]")

    def __iter__(self):
        return iter(())

    def __bool__(self):
        return False

    def __mro_entries__(self, bases):
        return (object,)

    def __repr__(self):
        return f"<missing {self._name}>"


class _StandInModule(types.ModuleType):
    def __getattr__(self, item):
        if item.startswith("__") and item.endswith("__"):
            raise AttributeError(item)
        return _Inert(f"{self.__name__}.{item}")


class _StandInFinder:
    """A meta path finder that hands out stand-in modules for the missing top-level packages and
    records which of them were asked for."""

    def __init__(self, names: Iterable[str]):
        self.names = set(names)
        self.used = set()

    def find_spec(self, fullname, path=None, target=None):
        top = fullname.split(".")[0]
        if top not in self.names:
            return None
        self.used.add(top)
        return importlib.util.spec_from_loader(fullname, self, is_package=True)

    def create_module(self, spec):
        module = _StandInModule(spec.name)
        module.__path__ = []
        return module

    def exec_module(self, module):
        pass


def import_algorithm_module(name: str, missing_deps: Optional[Sequence[Dependency]] = None):
    """Import the module ``name``; returns (module, [Dependency it could not import]).

    A module that imports a missing package at module level is imported once more with stand-ins for
    the missing packages, so that its algorithm class exists and can be listed; every module imported
    during that second attempt is then forgotten again, so that nothing keeps a stand-in once the
    packages are installed."""
    try:
        return importlib.import_module(name), []
    except ImportError as exc:
        failed = (getattr(exc, "name", None) or "").split(".")[0]
        deps = list(missing_deps if missing_deps is not None else missing())
        names = {d.module for d in deps}
        if failed in BY_MODULE:
            names.add(failed)
        if failed not in names:
            raise
    before = set(sys.modules)
    finder = _StandInFinder(names)
    for mod_name in [m for m in sys.modules if m.split(".")[0] in names]:
        sys.modules.pop(mod_name, None)  # half-imported leftovers of the failed attempt
    sys.meta_path.insert(0, finder)
    try:
        module = importlib.import_module(name)
    finally:
        sys.meta_path.remove(finder)
        for mod_name in set(sys.modules) - before:
            if mod_name != name:
                sys.modules.pop(mod_name, None)
        sys.modules.pop(name, None)
    used = [BY_MODULE[n] for n in sorted(finder.used) if n in BY_MODULE]
    return module, used


def static_requirements(module_file: str, package_root: str = PLUGIN_DIR) -> List[str]:
    """Dependency modules that ``module_file`` may import, directly or through the plugin's own
    modules, at module level or inside functions (AST scan, nothing is imported)."""
    seen, found, todo = set(), set(), [os.path.abspath(module_file)]
    while todo:
        path = todo.pop()
        if path in seen or not os.path.isfile(path):
            continue
        seen.add(path)
        try:
            with open(path, encoding="utf-8") as fh:
                tree = ast.parse(fh.read(), path)
        except (OSError, SyntaxError):
            continue
        here = os.path.dirname(path)
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    top = alias.name.split(".")[0]
                    if top in BY_MODULE:
                        found.add(top)
            elif isinstance(node, ast.ImportFrom):
                if node.level == 0:
                    top = (node.module or "").split(".")[0]
                    if top in BY_MODULE:
                        found.add(top)
                    continue
                base = here
                for _ in range(node.level - 1):
                    base = os.path.dirname(base)
                if not os.path.abspath(base).startswith(os.path.abspath(package_root)):
                    continue
                parts = (node.module or "").split(".") if node.module else []
                target = os.path.join(base, *parts)
                todo += [target + ".py", os.path.join(target, "__init__.py")]
                for alias in node.names:  # from . import cad_import
                    todo.append(os.path.join(target, alias.name + ".py"))
    return sorted(found)


def guard_algorithm(cls, module_file: str, failed_imports: Sequence[Dependency],
                    missing_deps: Sequence[Dependency]):
    """A subclass of the algorithm class ``cls`` that is listed as usual but, when packages it needs
    are missing, says which instead of raising: ``canExecute`` is False (required ones), the help
    starts with the list, the parameter check fails with it and a run raises a clean
    QgsProcessingException. Returns ``cls`` itself when nothing it needs is missing."""
    from qgis.core import QgsProcessingException

    missing_names = {d.module for d in missing_deps}
    needed = set(static_requirements(module_file)) | {d.module for d in failed_imports}
    lacking = [BY_MODULE[n] for n in sorted(needed & missing_names)]
    if not lacking:
        return cls
    blocking = [d for d in lacking if not d.optional] or (list(failed_imports) and lacking)
    text = (missing_message(lacking) + " Install them from the message bar shown when QGIS starts, or "
            "run: " + manual_command(lacking) + " — then restart QGIS.")

    def message(self):
        return QCoreApplicationTranslate(text)

    def canExecute(self):  # noqa: N802
        if blocking:
            return False, message(self)
        return True, ""

    def shortHelpString(self):  # noqa: N802
        return f"<p><b>{message(self)}</b></p>" + (cls.shortHelpString(self) or "")

    def checkParameterValues(self, parameters, context):  # noqa: N802
        if blocking:
            return False, message(self)
        return cls.checkParameterValues(self, parameters, context)

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        if blocking:
            raise QgsProcessingException(message(self))
        try:
            return cls.processAlgorithm(self, parameters, context, feedback)
        except ImportError as exc:
            if (getattr(exc, "name", "") or "").split(".")[0] in BY_MODULE:
                raise QgsProcessingException(message(self)) from exc
            raise

    def createInstance(self):  # noqa: N802
        return type(self)()

    attrs = dict(canExecute=canExecute, shortHelpString=shortHelpString,
                 checkParameterValues=checkParameterValues, processAlgorithm=processAlgorithm,
                 createInstance=createInstance, MISSING_PACKAGES=tuple(d.pip for d in lacking),
                 __module__=cls.__module__)
    return type(cls.__name__, (cls,), attrs)


def QCoreApplicationTranslate(text):  # noqa: N802
    from qgis.PyQt.QtCore import QCoreApplication

    return QCoreApplication.translate("cad2osmag.deps", text)


def log(message: str, level: str = "Warning"):
    try:
        from qgis.core import Qgis, QgsMessageLog

        QgsMessageLog.logMessage(message, LOG_TAG, getattr(Qgis.MessageLevel, level))
    except Exception:  # noqa: BLE001 - outside QGIS
        print(f"[{LOG_TAG}] {message}", file=sys.stderr)


# --- the desktop side: message bar and pip in a QProcess -------------------------------------
def tr(text):
    return QCoreApplicationTranslate(text)


_NOTIFIER = None  # keeps the installer (and its QProcess) alive while it runs


def notify_missing(iface, deps: Optional[Sequence[Dependency]] = None):
    """The single call from plugin.py: when packages are missing, a message bar names them and offers
    to install them. Returns the installer (None when nothing is missing or there is no GUI)."""
    global _NOTIFIER
    deps = list(missing() if deps is None else deps)
    if not deps:
        return None
    log(missing_message(deps) + " Install with: " + manual_command(deps))
    if iface is None or not hasattr(iface, "messageBar"):
        return None
    _NOTIFIER = DependencyInstaller(iface, deps)
    _NOTIFIER.offer()
    return _NOTIFIER


class DependencyInstaller:
    """Message bar offer -> pip in a QProcess with a progress bar -> success (restart) or failure."""

    def __init__(self, iface, deps: Sequence[Dependency], python: Optional[str] = None):
        self.iface = iface
        self.deps = list(deps)
        self.python = python
        self.process = None
        self.output: List[str] = []
        self.item = None
        self.progress_bar = None
        self.state = "offered"  # offered -> running -> done | failed
        self.constraints = None

    # message bar helpers
    def _bar(self):
        return self.iface.messageBar()

    def _push(self, widget, level, duration=0):
        bar = self._bar()
        if self.item is not None:
            try:
                bar.popWidget(self.item)
            except (RuntimeError, TypeError):
                pass
        self.item = widget
        bar.pushWidget(widget, level, duration)

    def offer(self):
        from qgis.core import Qgis
        from qgis.PyQt.QtWidgets import QPushButton

        bar = self._bar()
        required = [d for d in self.deps if not d.optional]
        names = ", ".join(d.pip.split(">")[0] for d in self.deps)
        system = system_packages(self.deps)
        text = tr("Missing Python packages: {}.").format(names)
        text += " " + (tr("The algorithms that need them will not run.") if required
                       else tr("DWG files cannot be read."))
        if system:
            text += " " + tr("Install {} from your distribution.").format(", ".join(system))
        if not hasattr(bar, "createMessage"):  # a minimal iface (test doubles): text only
            bar.pushMessage("cad2osmag", text, Qgis.MessageLevel.Warning, 0)
            return None
        widget = bar.createMessage("cad2osmag", text)
        if pip_installable(self.deps):
            button = QPushButton(tr("Install"), widget)
            button.clicked.connect(self.start)
            widget.layout().addWidget(button)
        details = QPushButton(tr("Details…"), widget)
        details.clicked.connect(self.show_details)
        widget.layout().addWidget(details)
        self._push(widget, Qgis.MessageLevel.Warning)
        return widget

    def details_text(self) -> str:
        text = missing_message(self.deps)
        if pip_installable(self.deps):
            text += "\n\n" + tr("“Install” runs this command in QGIS's own Python (user site); you can run it "
                                 "yourself (on Windows in the OSGeo4W Shell), then restart QGIS:\n\n{}").format(
                manual_command(self.deps))
        return text

    def show_details(self):
        from qgis.PyQt.QtCore import Qt
        from qgis.PyQt.QtWidgets import QMessageBox

        box = QMessageBox(self.iface.mainWindow())
        box.setIcon(QMessageBox.Icon.Information)
        box.setWindowTitle(tr("cad2osmag: missing Python packages"))
        box.setText(self.details_text())
        box.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)  # copy the command
        if self.output:
            box.setDetailedText("\n".join(self.output))
        box.exec()

    def command(self) -> List[str]:
        self.constraints = self.constraints or write_constraints()
        return pip_command(self.deps, self.python, self.constraints)

    def start(self):
        """Run pip in a QProcess; progress is shown in the message bar, the UI stays responsive."""
        from qgis.core import Qgis
        from qgis.PyQt.QtCore import QProcess
        from qgis.PyQt.QtWidgets import QProgressBar

        if self.state == "running" or not pip_installable(self.deps):
            return
        cmd = self.command()
        self.output = ["$ " + " ".join(cmd)]
        self.state = "running"
        bar = self._bar()
        widget = bar.createMessage("cad2osmag", tr("Installing {}…").format(
            ", ".join(d.pip.split(">")[0] for d in pip_installable(self.deps))))
        self.progress_bar = QProgressBar(widget)
        self.progress_bar.setMaximumWidth(250)
        self.progress_bar.setRange(0, len(pip_installable(self.deps)) * 2 + 1)  # collecting + installing per package
        self.progress_bar.setValue(0)
        widget.layout().addWidget(self.progress_bar)
        self._push(widget, Qgis.MessageLevel.Info)

        self.process = QProcess()
        self.process.setProcessChannelMode(QProcess.ProcessChannelMode.MergedChannels)
        self.process.readyReadStandardOutput.connect(self._read)
        self.process.finished.connect(self._finished)
        self.process.errorOccurred.connect(self._error)
        self.process.start(cmd[0], cmd[1:])

    def _read(self):
        data = bytes(self.process.readAllStandardOutput()).decode("utf-8", "replace")
        for line in data.splitlines():
            line = line.rstrip()
            if not line:
                continue
            self.output.append(line)
            if self.progress_bar is not None and (line.startswith("Collecting") or line.startswith("Installing")
                                                  or line.startswith("Requirement already satisfied")):
                self.progress_bar.setValue(min(self.progress_bar.maximum() - 1, self.progress_bar.value() + 1))

    def _error(self, error):
        from qgis.PyQt.QtCore import QProcess

        if error == QProcess.ProcessError.FailedToStart:
            self.output.append(f"cannot start {self.command()[0]}")
            self._failed(tr("Could not start Python ({}).").format(self.command()[0]))

    def _finished(self, exit_code, status=None):
        from qgis.PyQt.QtCore import QProcess

        self._read()
        if status == QProcess.ExitStatus.CrashExit and exit_code == 0:
            exit_code = -1
        if self.constraints:
            try:
                os.remove(self.constraints)
            except OSError:
                pass
            self.constraints = None
        if self.state != "running":
            return
        if exit_code == 0:
            self._succeeded()
        else:
            errors = [ln for ln in self.output[1:] if ln.startswith("ERROR") or "error:" in ln.lower()]
            last = errors[-1] if errors else (self.output[-1] if len(self.output) > 1 else "")
            self._failed(last or tr("pip stopped with exit code {}.").format(exit_code))

    def _succeeded(self):
        from qgis.core import Qgis

        self.state = "done"
        log("installed " + ", ".join(d.pip for d in self.deps) + "\n" + "\n".join(self.output), "Info")
        text = tr("Installed {}. Restart QGIS to use the CAD to osmAG algorithms.").format(
            ", ".join(d.pip for d in pip_installable(self.deps)))
        system = system_packages(self.deps)
        if system:
            text += " " + tr("Still needed from your distribution: {}.").format(", ".join(system))
        widget = self._bar().createMessage("cad2osmag", text)
        self._push(widget, Qgis.MessageLevel.Success)

    def _failed(self, reason: str):
        from qgis.core import Qgis
        from qgis.PyQt.QtWidgets import QPushButton

        self.state = "failed"
        log("installing " + ", ".join(d.pip for d in self.deps) + " failed:\n" + "\n".join(self.output), "Critical")
        widget = self._bar().createMessage("cad2osmag", tr(
            "Installing the Python packages failed: {} Details… has pip's output and the command to run by "
            "hand.").format(reason.strip()))
        details = QPushButton(tr("Details…"), widget)
        details.clicked.connect(self.show_details)
        widget.layout().addWidget(details)
        self._push(widget, Qgis.MessageLevel.Critical)

    def wait(self, msecs: int = 600000) -> bool:
        """Block until pip ends (tests, headless use)."""
        if self.process is None:
            return True
        from qgis.PyQt.QtCore import QCoreApplication

        ok = self.process.waitForFinished(msecs)
        QCoreApplication.processEvents()
        return ok
