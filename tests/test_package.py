"""`make package`: the plugin archive QGIS's "Install from ZIP" accepts, installed into a fresh QGIS
profile and enabled headless (qgis_process), with and without the plugin's Python packages."""
import configparser
import os
import re
import shutil
import subprocess
import sys
import textwrap
import zipfile

import pytest

from .conftest import REPO

sys.path.insert(0, str(REPO / "scripts"))
import package  # noqa: E402  (scripts/package.py)


def qgis_process_binary():
    for path in ("/usr/bin/qgis_process.bin", shutil.which("qgis_process") or ""):
        if path and os.access(path, os.X_OK):
            return path
    pytest.skip("qgis_process is not installed")


def algorithm_names():
    names = set()
    for path in (REPO / "processing_provider").glob("alg_*.py"):
        names |= set(re.findall(r'^\s+NAME = "(\w+)"', path.read_text(encoding="utf-8"), re.M))
    return names


@pytest.fixture(scope="module")
def archive(tmp_path_factory):
    out = tmp_path_factory.mktemp("dist")
    target, _files = package.build(str(out))
    return target


def test_archive_is_named_after_the_metadata_version(archive):
    version = package.metadata()["version"].strip()
    assert re.fullmatch(r"\d+\.\d+\.\d+", version)
    assert os.path.basename(archive) == f"cad2osmag-{version}.zip"


def test_metadata_changelog_describes_the_current_version():
    meta = package.metadata()
    assert meta["changelog"].strip().startswith(meta["version"].strip())


def test_archive_has_one_plugin_folder_and_only_runtime_files(archive):
    with zipfile.ZipFile(archive) as zf:
        names = zf.namelist()
        assert zf.testzip() is None
        packed_meta = zf.read("cad2osmag/metadata.txt").decode("utf-8")
    assert names and all(n.startswith("cad2osmag/") for n in names)
    rel = {n[len("cad2osmag/"):] for n in names}
    for required in ("__init__.py", "plugin.py", "deps.py", "metadata.txt", "icons/icon.svg",
                     "algorithms/__init__.py", "algorithms/default_layer_rules.json",
                     "processing_provider/provider.py", "processing_provider/base.py", "ui/__init__.py",
                     "algorithms/default_name_rules.json", "processing_provider/batch_worker.py",
                     "models/cad_to_osmag.model3", "styles/osmag_areas.qml", "styles/osmag_passages.qml",
                     "i18n/cad2osmag_de.qm", "i18n/cad2osmag_zh_CN.qm"):
        assert required in rel, required
    # every module and rule file the plugin has (tracked by git, or on disk outside a checkout) is shipped
    sources = set(package.candidate_files(str(REPO)))
    for folder in ("algorithms", "processing_provider", "ui"):
        for path in (REPO / folder).iterdir():
            name = f"{folder}/{path.name}"
            if path.suffix in (".py", ".json") and name in sources:
                assert name in rel, path
    for n in rel:
        top = n.split("/")[0]
        assert top not in ("tests", "benchmarks", "scripts", "docs", ".ci", ".venv", ".qgis-profile", "out",
                           "dist"), n
        assert "__pycache__" not in n and not n.endswith(".pyc"), n
        assert n not in ("Makefile", "requirements-dev.txt", "pytest.ini", ".gitignore"), n
    assert packed_meta == (REPO / "metadata.txt").read_text(encoding="utf-8")


def test_the_same_sources_give_the_same_archive(archive, tmp_path):
    again, _ = package.build(str(tmp_path))
    with open(archive, "rb") as a, open(again, "rb") as b:
        assert a.read() == b.read()


def fresh_profile(tmp_path, archive):
    """Unpack the archive into a new QGIS settings folder and enable the plugin, as Install from ZIP does."""
    config = tmp_path / "qgis-config"
    plugins = config / "profiles" / "default" / "python" / "plugins"
    plugins.mkdir(parents=True)
    with zipfile.ZipFile(archive) as zf:
        zf.extractall(plugins)
    ini = config / "profiles" / "default" / "QGIS" / "QGIS3.ini"
    ini.parent.mkdir(parents=True)
    ini.write_text("[PythonPlugins]\ncad2osmag=true\n", encoding="utf-8")
    return config


def venv_site():
    import sysconfig

    return sysconfig.get_paths()["purelib"]


def qgis_process(config, *args, pythonpath=(), timeout=300):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "QGIS_PLUGINPATH")}
    env.update(QT_QPA_PLATFORM="offscreen", QGIS_CUSTOM_CONFIG_PATH=str(config),
               XDG_RUNTIME_DIR=os.environ.get("XDG_RUNTIME_DIR", f"/tmp/runtime-{os.getuid()}"))
    os.makedirs(env["XDG_RUNTIME_DIR"], mode=0o700, exist_ok=True)
    if pythonpath:
        env["PYTHONPATH"] = os.pathsep.join(pythonpath)
    proc = subprocess.run([qgis_process_binary(), *args], capture_output=True, text=True, timeout=timeout,
                          env=env, stdin=subprocess.DEVNULL)
    return proc.returncode, proc.stdout + proc.stderr


@pytest.mark.qgis_process
def test_archive_installs_into_a_fresh_profile_and_runs_headless(archive, tmp_path):
    config = fresh_profile(tmp_path, archive)
    rc, out = qgis_process(config, "list", pythonpath=[venv_site()])
    assert rc == 0, out[-3000:]
    listed = set(re.findall(r"cad2osmag:(\w+)", out))
    models = {path.stem for path in (REPO / "models").glob("*.model3")}  # the shipped models are listed too
    assert models and listed == algorithm_names() | models and len(listed) >= 10
    rc, out = qgis_process(config, "plugins", pythonpath=[venv_site()])
    assert re.search(r"^\*\s+cad2osmag\s*$", out, re.M), out[-2000:]
    # the unpacked copy runs an algorithm end to end
    target = tmp_path / "sample"
    rc, out = qgis_process(config, "run", "cad2osmag:samplebuilding", "--", f"OUTPUT_FOLDER={target}", "FLOORS=1",
                           pythonpath=[venv_site()])
    assert rc == 0, out[-3000:]
    assert list(target.glob("*.dxf")), out[-2000:]


HIDE_EZDXF = textwrap.dedent('''
    import sys

    class _Hide:
        def find_spec(self, fullname, path=None, target=None):
            if fullname.split(".")[0] in ("ezdxf", "shapely"):
                raise ModuleNotFoundError(f"No module named {fullname!r}", name=fullname)
            return None

    sys.meta_path.insert(0, _Hide())
''')


@pytest.mark.qgis_process
def test_archive_without_its_packages_lists_everything_and_says_what_is_missing(archive, tmp_path):
    config = fresh_profile(tmp_path, archive)
    hide = tmp_path / "hide"
    hide.mkdir()
    (hide / "sitecustomize.py").write_text(HIDE_EZDXF, encoding="utf-8")
    rc, out = qgis_process(config, "list", pythonpath=[str(hide), venv_site()])
    assert rc == 0, out[-3000:]
    models = {path.stem for path in (REPO / "models").glob("*.model3")}
    assert set(re.findall(r"cad2osmag:(\w+)", out)) == algorithm_names() | models
    assert "Traceback" not in out
    rc, out = qgis_process(config, "run", "cad2osmag:samplebuilding", "--", f"OUTPUT_FOLDER={tmp_path / 's'}",
                           pythonpath=[str(hide), venv_site()])
    assert "Missing Python packages" in out and "ezdxf" in out and "pip install --user" in out, out[-3000:]
    assert "Traceback" not in out and "ModuleNotFoundError" not in out, out[-3000:]
    assert not (tmp_path / "s").exists() or not list((tmp_path / "s").iterdir())
