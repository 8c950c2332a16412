#!/usr/bin/env python3
"""Build the plugin archive QGIS's "Install from ZIP" accepts: dist/cad2osmag-<version>.zip with one
top folder ``cad2osmag/``.

The version and the changelog come from one place, metadata.txt (``version=`` and ``changelog=``);
the archive is named after that version. Only what the plugin needs at run time goes in: the root
Python modules, metadata.txt, README, LICENSE, requirements.txt and the folders in SHIPPED_DIRS;
never tests, benchmarks, scripts, caches, .venv, .qgis-profile or out/. Files come from `git ls-files`
when the folder is a git checkout (so nothing untracked slips in), else from the folder itself.

    scripts/package.py [--out DIR]      -> prints the path of the archive
"""
import argparse
import configparser
import os
import subprocess
import sys
import tempfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLUGIN = "cad2osmag"
SHIPPED_DIRS = ("algorithms", "processing_provider", "ui", "i18n", "icons", "models", "styles", "help")
ROOT_FILES = ("metadata.txt", "README.md", "LICENSE", "LICENSE.txt", "COPYING", "requirements.txt")
NEVER = ("__pycache__", ".pyc", ".pyo", ".qgis-profile", ".venv", ".pytest_cache", ".DS_Store", ".aux.xml")
# fixed timestamp: the same sources give the same archive
ZIP_DATE = (2020, 1, 1, 0, 0, 0)


def metadata(root=ROOT):
    cfg = configparser.ConfigParser(interpolation=None)
    cfg.read(os.path.join(root, "metadata.txt"), encoding="utf-8")
    return cfg["general"]


def candidate_files(root=ROOT):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True)
        files = [f for f in out.stdout.decode("utf-8").split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for dirpath, dirnames, filenames in os.walk(root):
            dirnames[:] = [d for d in dirnames if not d.startswith(".")]
            files += [os.path.relpath(os.path.join(dirpath, f), root) for f in filenames]
    return sorted(f.replace(os.sep, "/") for f in files)


def shipped(rel):
    if any(part in rel for part in NEVER):
        return False
    parts = rel.split("/")
    if len(parts) == 1:
        return rel.endswith(".py") or rel in ROOT_FILES
    return parts[0] in SHIPPED_DIRS


def build(out_dir=None, root=ROOT):
    meta = metadata(root)
    version = meta.get("version", "").strip()
    if not version:
        raise SystemExit("metadata.txt has no version=")
    if not meta.get("changelog", "").strip():
        raise SystemExit("metadata.txt has no changelog=")
    out_dir = out_dir or os.path.join(root, "dist")
    os.makedirs(out_dir, exist_ok=True)
    target = os.path.join(out_dir, f"{PLUGIN}-{version}.zip")
    files = [f for f in candidate_files(root) if shipped(f) and os.path.isfile(os.path.join(root, f))]
    for required in ("__init__.py", "metadata.txt", "plugin.py"):
        if required not in files:
            raise SystemExit(f"{required} is missing: not a plugin folder?")
    fd, tmp = tempfile.mkstemp(prefix=f".{PLUGIN}-", suffix=".zip", dir=out_dir)
    os.close(fd)
    try:
        with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as zf:
            for rel in files:
                info = zipfile.ZipInfo(f"{PLUGIN}/{rel}", ZIP_DATE)
                info.external_attr = 0o644 << 16
                info.compress_type = zipfile.ZIP_DEFLATED
                with open(os.path.join(root, rel), "rb") as fh:
                    zf.writestr(info, fh.read())
        os.replace(tmp, target)  # never a half-written archive
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise
    return target, files


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="output folder (default dist/)")
    args = parser.parse_args(argv)
    target, files = build(args.out)
    print(target)
    print(f"{len(files)} files, {os.path.getsize(target) / 1024:.0f} KiB", file=sys.stderr)


if __name__ == "__main__":
    main()
