"""Optional compiled kernels for the segmentation's pixel loops (issue 13).

numba, when installed, runs the loops the numpy code does in many full-array passes (the layered
thinning, the steepest-ascent basins, the ring-by-ring region growth) as one compiled loop each.
It is optional: QGIS users' Python may lack it, and then the numpy code runs, with the same
results (every kernel is a transcription of the numpy code: tests/test_kernels.py compares both on
random inputs, tests/test_speed_equivalence.py pins the pipeline's output).

``CAD2OSMAG_NUMBA=0`` in the environment forces the numpy path. ``get()`` returns the kernel module
or None; ``describe()`` the one line the segmentation logs about the path that runs. ``preload()``
starts loading them in a background thread (``import numba`` and the cached kernels: ~0.6 CPU s in a
fresh process, mostly Python), so that the load overlaps work that releases the GIL (OpenCV, numpy);
``get()`` waits for it, so the path that runs never depends on timing.
"""
from __future__ import annotations

import os
import threading
from typing import Optional

import numpy as np

_STATE = {"loaded": False, "module": None, "why": "", "load_s": 0.0, "thread": None}
_LOCK = threading.Lock()


def get():
    """The compiled kernel module (``_kernels_nb``), or None for the numpy path. Waits for a load that
    ``preload`` started (one load per process, whichever thread asks first)."""
    if not _STATE["loaded"]:
        with _LOCK:
            if not _STATE["loaded"]:
                _get_locked()
    return _STATE["module"]


def _get_locked() -> None:
    if os.environ.get("CAD2OSMAG_NUMBA", "1").strip().lower() in ("0", "no", "false", "off"):
        _STATE["why"] = "disabled by CAD2OSMAG_NUMBA=0"
    else:
        try:
            import time

            t0 = time.thread_time()  # this thread's CPU: the load may run beside the conversion (preload)
            mod = _load()
            mod.selftest()
            _STATE["module"] = mod
            _STATE["load_s"] = time.thread_time() - t0
            if _STATE["load_s"] > 3.0:  # it compiled (first use on a machine): ~50 MB of numba's cyclic garbage,
                import gc  # kept while a conversion pauses the collector (pipeline._gc_paused)

                gc.collect()
        except Exception as exc:  # numba missing, a numba that does not fit this numpy, a bad cache
            _STATE["why"] = f"numba not usable ({type(exc).__name__}: {exc})"
    _STATE["loaded"] = True


def preload() -> None:
    """Start loading the kernels in a daemon thread unless they are loaded or loading (returns at once).
    A conversion calls it before the work whose C calls release the GIL (rasterize, segmentation's
    distance transforms and labellings): on a second core the load then costs no wall time."""
    if _STATE["loaded"] or _STATE["thread"] is not None:
        return
    th = threading.Thread(target=get, name="cad2osmag-kernels", daemon=True)
    _STATE["thread"] = th
    th.start()


def _loading() -> bool:
    th = _STATE["thread"]
    return th is not None and th.is_alive() and not _STATE["loaded"]


_MODULE = "cad2osmag_kernels_nb"


def _load():
    """Import ``_kernels_nb.py`` under one fixed top-level name, whatever the package is called
    (``algorithms`` in the tests, ``cad2osmag.algorithms`` in QGIS): numba's cache records the
    module name of every compiled function and imports it again when it loads the cache, so a
    cache written under one name would fail under the other."""
    import importlib.util
    import sys

    mod = sys.modules.get(_MODULE)
    if mod is None:
        import numba  # noqa: F401  (ImportError here: no numba, the numpy path runs)

        path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "_kernels_nb.py")
        spec = importlib.util.spec_from_file_location(_MODULE, path)
        mod = importlib.util.module_from_spec(spec)
        sys.modules[_MODULE] = mod
        try:
            spec.loader.exec_module(mod)
        except BaseException:
            sys.modules.pop(_MODULE, None)
            raise
    return mod


def enabled() -> bool:
    return get() is not None


def describe() -> str:
    """The path the pixel loops take. Does not wait for a load ``preload`` started (the log line says so)."""
    if _loading():
        return ("pixel loops: compiled kernels (numba, loading beside the first steps; the numpy code runs "
                "instead if they fail to load)")
    mod = get()
    if mod is not None:
        import numba

        load = _STATE.get("load_s", 0.0)
        note = (f", compiled on this first use in {load:.0f} s CPU, cached for the next runs" if load > 3.0
                else f", loaded in {load:.2f} s")
        _STATE["noted"] = _STATE.get("noted") or load > 3.0  # said here: compile_note stays silent
        return f"pixel loops: compiled kernels (numba {numba.__version__}{note})"
    return f"pixel loops: numpy ({_STATE['why'] or 'numba not installed'}; install numba for speed)"


def compile_note() -> str:
    """Once per process, after a load that compiled the kernels (the first use on a machine, > 3 CPU s):
    the line that says so. A preloaded conversion logs it after the segmentation, since ``describe``
    said only "loading" then; '' otherwise."""
    load = _STATE.get("load_s", 0.0)
    if _STATE["module"] is None or load <= 3.0 or _STATE.get("noted"):
        return ""
    _STATE["noted"] = True
    return f"pixel loops: the compiled kernels were compiled on this first use in {load:.0f} s CPU, cached for the next runs"


def set_enabled(flag: Optional[bool]) -> None:
    """Tests: force the numpy path (False), the compiled one (True, if numba imports), or go back
    to the environment's choice (None)."""
    th = _STATE["thread"]
    if th is not None:
        th.join()
    _STATE.update(loaded=False, module=None, why="", load_s=0.0, thread=None, noted=False)
    if flag is False:
        _STATE.update(loaded=True, why="disabled")
    elif flag is True:
        old = os.environ.pop("CAD2OSMAG_NUMBA", None)
        try:
            get()
        finally:
            if old is not None:
                os.environ["CAD2OSMAG_NUMBA"] = old


def find_objects(labels):
    """``scipy.ndimage.find_objects(labels)`` for a 2-D int32/int64 label raster: for every label
    1..max, the tuple of (row, column) slices of its bounding box, or None when it is absent. The
    compiled path makes one pass over the raster (scipy's takes several times as long on a floor)."""
    mod = get()
    if mod is None or labels.ndim != 2 or labels.dtype not in (np.int32, np.int64) or labels.size == 0:
        from scipy import ndimage as ndi

        return ndi.find_objects(labels)
    n = int(labels.max())
    if n <= 0:
        return []
    box, seen = mod.label_boxes(labels, n)
    box = box.tolist()
    seen = seen.tolist()
    return [(slice(b[0], b[1]), slice(b[2], b[3])) if ok else None for b, ok in zip(box[1:], seen[1:])]
