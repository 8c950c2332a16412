"""One floor conversion in its own process, for ``cad2osmag:dxftoosmagbatch``.

Run as ``python batch_worker.py`` with a JSON job on stdin ({"dxf", "out", "kwargs"}); prints one JSON
line on stdout: {"ok": true, "areas": n, "passages": n, "seconds": s, "warnings": [...]} or
{"ok": false, "error": "..."}. It imports only the plugin's pure-Python pipeline (no qgis), so it runs
in any Python that has the plugin's dependencies, and a crash or a bad file stays in its process.
"""
import importlib.util
import json
import os
import sys
import time

PLUGIN_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE = "cad2osmag_batch"  # a private package name: never clashes with the plugin loaded in QGIS


def _pipeline():
    spec = importlib.util.spec_from_file_location(PACKAGE, os.path.join(PLUGIN_DIR, "__init__.py"),
                                                  submodule_search_locations=[PLUGIN_DIR])
    module = importlib.util.module_from_spec(spec)
    sys.modules[PACKAGE] = module
    spec.loader.exec_module(module)
    from importlib import import_module

    return (import_module(f"{PACKAGE}.algorithms.pipeline"), import_module(f"{PACKAGE}.algorithms.errors"),
            import_module(f"{PACKAGE}.algorithms.progress"))


def run(job):
    pipeline, errors, progress_mod = _pipeline()

    class Collect(progress_mod.Progress):
        def __init__(self):
            self.warnings = []

        def warning(self, message):
            self.warnings.append(str(message))

    progress = Collect()
    t0 = time.perf_counter()
    try:
        stats = pipeline.convert_dxf(job["dxf"], job["out"], progress=progress, **job.get("kwargs", {}))
    except errors.InputError as exc:
        return {"ok": False, "error": str(exc), "warnings": progress.warnings}
    except Exception as exc:  # noqa: BLE001 - reported per file, never stops the batch
        return {"ok": False, "error": f"{type(exc).__name__}: {exc}", "warnings": progress.warnings}
    return {"ok": True, "areas": int(stats.get("areas", 0)), "passages": int(stats.get("passages", 0)),
            "seconds": time.perf_counter() - t0, "warnings": progress.warnings}


def main():
    job = json.loads(sys.stdin.read())
    result = run(job)
    sys.stdout.write("\n" + json.dumps(result) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
