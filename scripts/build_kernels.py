#!/usr/bin/env python3
"""Build the segmentation's compiled kernels ahead of time (``make install`` runs it; ``make kernels`` alone).

numba compiles ``algorithms/_kernels_nb.py`` once per machine into its cache, but every fresh process still
pays ``import numba`` and the cache's load (~0.6 CPU s, numba's typing set-up): each conversion started by
``qgis_process``, each worker of the building's process pool. This script compiles the same kernels with
numba's ahead-of-time compiler (``numba.pycc``) into a plain extension module beside them
(``algorithms/cad2osmag_kernels_aot*.so``, not in git, not in the plugin archive: it is this machine's
build), with the signatures of ``kernels.AOT_EXPORTS``, releasing the GIL as the numba kernels do, and writes
the ``kernels.source_digest`` it was built from into ``cad2osmag_kernels_aot.sha256``; ``kernels.get``
loads it only when that digest matches (a changed ``_kernels_nb.py`` falls back to numba until rebuilt).

Without numba (or a C compiler) it says so and exits 0: the numba and numpy paths still run.
"""
import importlib.util
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    sys.path.insert(0, str(ROOT))
    from algorithms import kernels

    try:
        import numba.pycc.compiler as pycc_compiler
        from numba.core.compiler import Flags
        from numba.pycc import CC
    except ImportError as exc:
        print(f"[kernels] not built: numba's ahead-of-time compiler is not available ({exc}); "
              "the numba or numpy path runs")
        return 0

    class _NoGilFlags(Flags):  # the exported wrappers release the GIL around the kernel (numba's nogil=True)
        def __init__(self, *a, **k):
            super().__init__(*a, **k)
            self.release_gil = True

    pycc_compiler.Flags = _NoGilFlags
    spec = importlib.util.spec_from_file_location(kernels._MODULE, str(ROOT / "algorithms" / "_kernels_nb.py"))
    mod = importlib.util.module_from_spec(spec)
    sys.modules[kernels._MODULE] = mod
    spec.loader.exec_module(mod)
    out_dir = ROOT / "algorithms"
    old, stamp = kernels.aot_paths()
    with tempfile.TemporaryDirectory(prefix="cad2osmag-kernels-") as tmp:
        cc = CC(kernels.AOT_MODULE)
        cc.output_dir = tmp
        cc.target_cpu = "host"  # this machine's instruction set, as numba's own kernels (the stamp says which)
        for name, base, sig in kernels.AOT_EXPORTS:
            cc.export(name, sig)(getattr(mod, base).py_func)
        t0 = time.perf_counter()
        try:
            cc.compile()
        except Exception as exc:  # no C compiler, a numba that cannot build: the numba path stays
            print(f"[kernels] not built ({type(exc).__name__}: {exc}); the numba or numpy path runs")
            return 0
        built = [p for p in Path(tmp).iterdir() if p.name.startswith(kernels.AOT_MODULE)]
        if len(built) != 1:
            print(f"[kernels] not built: the compiler wrote {[p.name for p in built]}")
            return 0
        if os.path.exists(stamp):
            os.remove(stamp)  # no stamp while the module changes: a process starting now takes numba
        if old is not None and Path(old).name != built[0].name:
            os.remove(old)
        target = out_dir / built[0].name
        part = out_dir / (built[0].name + ".part")
        shutil.copyfile(built[0], part)
        os.replace(part, target)
    tmp_stamp = stamp + ".part"
    with open(tmp_stamp, "w", encoding="ascii") as fh:
        fh.write(kernels.source_digest() + "\n")
    os.replace(tmp_stamp, stamp)
    print(f"[kernels] built {target.relative_to(ROOT)} in {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
