"""Optional compiled kernels for the segmentation's pixel loops (issue 13).

numba, when installed, runs the loops the numpy code does in many full-array passes (the layered
thinning, the steepest-ascent basins, the ring-by-ring region growth) as one compiled loop each.
It is optional: QGIS users' Python may lack it, and then the numpy code runs, with the same
results (every kernel is a transcription of the numpy code: tests/test_kernels.py compares both on
random inputs, tests/test_speed_equivalence.py pins the pipeline's output).

An ahead-of-time build of the same kernels (``scripts/build_kernels.py``, run by ``make install``: a plain
extension module beside this file, ``cad2osmag_kernels_aot*.so``) is preferred when it is there and was built
from the current ``_kernels_nb.py``: it loads in a millisecond without importing numba (a fresh process
otherwise spends ~0.6 CPU s on ``import numba`` and the cached kernels, every worker of the building's
process pool too). Arguments outside its built signatures (another dtype) go to the numba kernel.
``CAD2OSMAG_AOT=0`` (or ``AOT = False``) skips it. ``CAD2OSMAG_NUMBA=0`` in the environment forces the numpy
path. ``get()`` returns the kernel module
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


def _off(name: str) -> bool:
    return os.environ.get(name, "1").strip().lower() in ("0", "no", "false", "off")


def _get_locked() -> None:
    if _off("CAD2OSMAG_NUMBA"):
        _STATE["why"] = "disabled by CAD2OSMAG_NUMBA=0"
    else:
        try:
            import time

            t0 = time.thread_time()  # this thread's CPU: the load may run beside the conversion (preload)
            mod = _load_aot() if AOT and not _off("CAD2OSMAG_AOT") else None
            mod = mod if mod is not None else _load()
            _selftest(mod)
            _STATE["module"] = mod
            _STATE["load_s"] = time.thread_time() - t0
            if _STATE["load_s"] > 3.0:  # it compiled (first use on a machine): ~50 MB of numba's cyclic garbage,
                import gc  # kept while a conversion pauses the collector (pipeline._gc_paused)

                gc.collect()
        except Exception as exc:  # numba missing, a numba that does not fit this numpy, a bad cache
            _STATE["why"] = f"numba not usable ({type(exc).__name__}: {exc})"
    _STATE["loaded"] = True


def _selftest(mod) -> None:
    """Call every kernel of ``mod`` once on a tiny input: loads (or compiles) them all, so that a numba, a
    cache or an ahead-of-time build that does not work shows here, where ``get`` falls back to numpy, not
    mid-run."""
    mask = np.zeros((6, 7), np.bool_)
    mask[1:5, 1:6] = True
    dist = np.where(mask, np.float32(1.0), np.float32(0.0)).astype(np.float32)
    dist[2:4, 2:5] = 2.0
    img, pos, bounds = mod.thin_setup(mask, dist)
    luts = np.zeros((2, 256), np.bool_)
    cand = np.empty(len(pos), np.int64)
    flags = np.empty(len(pos), np.bool_)
    mod.thin_layers(img, pos, bounds, 0, len(bounds) - 1, luts, 9, cand, 0, flags)
    mod.thin_rest(img, luts, 9, flags)
    markers = np.zeros((6, 7), np.int32)
    markers[2, 2] = 1
    basins = mod.ascent_basins(dist, mask, markers)
    lab = basins.copy()
    mod.orphan_pieces(lab, markers, mask)
    mod.grow_rounds(lab.ravel(), np.zeros(1, np.int64), 6, 7, np.zeros(1, np.int32), np.zeros(1, np.int64), False)
    mod.grow_rounds(lab.ravel(), np.zeros(1, np.int64), 6, 7, markers.ravel(), np.zeros(2, np.int64), True)
    src, vals = mod.zone_seeds(markers, markers, 0, 6, 0, 7, 1)
    mod.zone_assign(lab, markers, np.zeros((6, 7), np.int32), vals, 0, 0, 1)
    mod.neighbour_pairs(lab, dist, True)
    mod.label_boxes(markers, 1)
    mod.label_boxes(markers[:, 1:], 1)  # a view (the zones' box in nearest_seed_regions): its own signature
    mod.label_boxes(markers.astype(np.int64), 1)


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
AOT = True  # switch: prefer the ahead-of-time build when it is there and current
AOT_MODULE = "cad2osmag_kernels_aot"
# the ahead-of-time build's exports: (name in the extension, kernel of _kernels_nb, numba signature); every
# array argument of layout 'A' where a caller passes views, 'C' elsewhere (the signatures a conversion uses)
_C1, _C2 = "[::1]", "[:, ::1]"
AOT_EXPORTS = (
    ("thin_setup", "thin_setup", f"Tuple((u1{_C1}, i8{_C1}, i8{_C1}))(b1{_C2}, f4{_C2})"),
    ("thin_layers", "thin_layers", f"i8(u1{_C1}, i8{_C1}, i8{_C1}, i8, i8, b1{_C2}, i8, i8{_C1}, i8, b1{_C1})"),
    ("thin_rest", "thin_rest", f"void(u1{_C1}, b1{_C2}, i8, b1{_C1})"),
    ("ascent_basins", "ascent_basins", f"i4{_C2}(f4{_C2}, b1{_C2}, i4{_C2})"),
    ("grow_rounds", "grow_rounds", f"void(i4{_C1}, i8{_C1}, i8, i8, i4{_C1}, i8{_C1}, b1)"),
    ("orphan_pieces", "orphan_pieces", f"b1{_C2}(i4{_C2}, i4{_C2}, b1{_C2})"),
    ("zone_seeds", "zone_seeds", f"Tuple((u1{_C2}, i4{_C1}))(i4[:, :], i4{_C2}, i8, i8, i8, i8, i8)"),
    ("zone_assign", "zone_assign", f"void(i4{_C2}, i4[:, :], i4{_C2}, i4{_C1}, i8, i8, i8)"),
    ("neighbour_pairs", "neighbour_pairs",
     f"Tuple((i4{_C1}, i4{_C1}, f4{_C1}, i1{_C1}, i8{_C1}, i8{_C1}))(i4{_C2}, f4{_C2}, b1)"),
    ("label_boxes_i4", "label_boxes", f"Tuple((i8{_C2}, b1{_C1}))(i4[:, :], i8)"),
    ("label_boxes_i8", "label_boxes", f"Tuple((i8{_C2}, b1{_C1}))(i8[:, :], i8)"),
)


def source_digest() -> str:
    """sha256 of ``_kernels_nb.py`` and of the export table: what an ahead-of-time build was made from."""
    import hashlib

    h = hashlib.sha256()
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "_kernels_nb.py"), "rb") as fh:
        h.update(fh.read())
    h.update(repr(AOT_EXPORTS).encode())
    h.update(np.__version__.encode())
    h.update(_cpu_id().encode())  # the build is for this processor (``target_cpu="host"``)
    return h.hexdigest()


def _cpu_id() -> str:
    """This processor's instruction-set features (Linux: the first ``flags`` line of /proc/cpuinfo), so that a
    build for one processor is never loaded on another; the machine name elsewhere."""
    import platform

    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as fh:
            for line in fh:
                if line.startswith("flags"):
                    return platform.machine() + ":" + " ".join(sorted(line.split(":", 1)[1].split()))
    except OSError:
        pass
    return platform.machine() + ":" + platform.processor()


def aot_paths():
    """(extension path or None, stamp path): the ahead-of-time build beside this file and its stamp (the
    ``source_digest`` it was built from)."""
    import glob
    import importlib.machinery

    here = os.path.dirname(os.path.abspath(__file__))
    found = [p for suf in importlib.machinery.EXTENSION_SUFFIXES
             for p in glob.glob(os.path.join(here, AOT_MODULE + suf))]
    return (found[0] if found else None), os.path.join(here, AOT_MODULE + ".sha256")


def _load_aot():
    """The ahead-of-time build behind the kernel names (``_AotKernels``), or None when it is missing, stale
    (built from another ``_kernels_nb.py`` or numpy) or does not import."""
    import importlib.machinery
    import importlib.util
    import sys

    path, stamp = aot_paths()
    if path is None:
        return None
    try:
        with open(stamp, encoding="ascii") as fh:
            if fh.read().strip() != source_digest():
                return None
        ext = sys.modules.get(AOT_MODULE)
        if ext is None:
            loader = importlib.machinery.ExtensionFileLoader(AOT_MODULE, path)
            spec = importlib.util.spec_from_file_location(AOT_MODULE, path, loader=loader)
            ext = importlib.util.module_from_spec(spec)
            loader.exec_module(ext)
            sys.modules[AOT_MODULE] = ext
    except (OSError, ImportError):
        return None
    return _AotKernels(ext)


_CODES = {"u1": np.uint8, "b1": np.bool_, "i1": np.int8, "i4": np.int32, "i8": np.int64, "f4": np.float32}


def _arg_specs(sig: str):
    """The argument types of an ``AOT_EXPORTS`` signature: per argument (dtype, ndim, C-contiguous) for an
    array, (kind, None, None) for a scalar ('i8' int, 'b1' bool)."""
    import re

    args = sig[sig.rindex("(") + 1:-1]
    out = []
    for a in re.split(r",\s*(?![^\[]*\])", args):
        code, _, dims = a.partition("[")
        if not dims:
            out.append((code, None, None))
        else:
            out.append((np.dtype(_CODES[code]), dims.count(",") + 1, "::1" in dims))
    return tuple(out)


def _fits(specs, args) -> bool:
    """Whether ``args`` are what the built signature reads: the build's wrappers do not check (another dtype
    would be read as the declared one), so every call is checked here."""
    if len(args) != len(specs):
        return False
    for (t, ndim, contiguous), a in zip(specs, args):
        if ndim is None:
            ok = isinstance(a, (bool, np.bool_)) if t == "b1" else (
                isinstance(a, (int, np.integer)) and not isinstance(a, (bool, np.bool_)))
        else:
            ok = (isinstance(a, np.ndarray) and a.dtype == t and a.ndim == ndim and a.flags.aligned
                  and a.flags.writeable and (a.flags.c_contiguous or not contiguous))
        if not ok:
            return False
    return True


class _AotKernels:
    """The ahead-of-time build under ``_kernels_nb``'s names. The build's functions release the GIL as the
    numba kernels do (``nogil``). A call whose arguments fall outside the built signatures (a float64
    clearance, a read-only or strided array where the build reads a contiguous one) runs the numba kernel
    (loaded then), with the same results: the build's own wrappers would read such arguments wrongly."""

    kind = "ahead-of-time build"

    def __init__(self, ext):
        self._ext = ext
        self._jit = None
        self._by_base = {}
        for name, base, sig in AOT_EXPORTS:
            self._by_base.setdefault(base, []).append((getattr(ext, name), _arg_specs(sig)))
        for base in self._by_base:
            setattr(self, base, self._caller(base))

    def _caller(self, base):
        variants = self._by_base[base]

        def call(*args):
            for fn, specs in variants:
                if _fits(specs, args):
                    return fn(*args)
            return getattr(self._numba(), base)(*args)  # no built signature fits: the numba kernel
        call.__name__ = base
        return call

    def _numba(self):
        if self._jit is None:
            self._jit = _load()
        return self._jit


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
        return ("pixel loops: compiled kernels (loading beside the first steps; the numpy code runs "
                "instead if they fail to load)")
    mod = get()
    if isinstance(mod, _AotKernels):
        return f"pixel loops: compiled kernels ({mod.kind}, loaded in {_STATE.get('load_s', 0.0):.3f} s)"
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
