"""Run pipeline calls on hostile input in a separate process, so that a hard crash (segfault, a Rust panic
that aborts, the OOM killer), a hang or a memory blow-up is seen and reported instead of killing pytest.

``Isolated`` keeps one spawned worker process (imports paid once) and runs one case at a time in it:
- ``("ok", summary)`` - the call returned; ``summary`` holds a few figures;
- ``("input", message)`` - it raised ``InputError`` (what a user must see);
- ``("error", traceback)`` - any other exception (a bug: a raw traceback would reach the user);
- ``("crash", detail)`` - the worker died (signal / abort); the worker is restarted for the next case;
- ``("timeout", seconds)`` - the case ran longer than its limit; the worker is killed and restarted.
The worker's address space is limited (``MEMORY_LIMIT``) so a runaway allocation becomes a MemoryError
("error") instead of swapping the machine.
"""
from __future__ import annotations

import concurrent.futures as cf
import multiprocessing
import os
import signal
import sys
import traceback

MEMORY_LIMIT = 3 * 1024 ** 3  # bytes of address space in the worker


def _init(repo: str, memory_limit: int) -> None:
    if repo not in sys.path:
        sys.path.insert(0, repo)
    try:
        import resource

        resource.setrlimit(resource.RLIMIT_AS, (memory_limit, memory_limit))
    except (ImportError, ValueError, OSError):  # pragma: no cover - not on Linux
        pass
    import warnings

    warnings.simplefilter("ignore")  # RuntimeWarnings of numpy on NaN input are expected here


def _call(kind: str, args: tuple, kwargs: dict):
    from algorithms.errors import InputError

    try:
        if kind == "import":
            from algorithms.cad_import import import_dxf

            d = import_dxf(*args, **kwargs)
            return ("ok", {"geometries": len(d.geometries), "texts": len(d.texts), "unit": d.unit_name,
                           "repairs": len(d.repairs), "warnings": list(d.warnings)})
        if kind == "inspect":
            from algorithms.cad_import import inspect_dxf

            d = inspect_dxf(*args, **kwargs)
            return ("ok", {"layers": len(d.layers)})
        if kind == "convert":
            from algorithms.pipeline import convert_dxf

            r = convert_dxf(*args, **kwargs)
            return ("ok", {"areas": r["areas"], "passages": r["passages"], "raster": tuple(r["raster_shape"])})
        raise ValueError(f"unknown call {kind}")
    except InputError as exc:
        return ("input", str(exc))
    except MemoryError:
        return ("error", "MemoryError (the input was allowed to allocate more than the worker's limit)\n"
                + traceback.format_exc())
    except BaseException as exc:  # noqa: BLE001 - everything else is a bug to report
        return ("error", f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}")


class Isolated:
    def __init__(self, repo: str, memory_limit: int = MEMORY_LIMIT):
        self.repo, self.memory_limit = str(repo), memory_limit
        self._ex = None
        self.restarts = 0

    def _executor(self):
        if self._ex is None:
            ctx = multiprocessing.get_context("spawn")
            self._ex = cf.ProcessPoolExecutor(max_workers=1, mp_context=ctx, initializer=_init,
                                              initargs=(self.repo, self.memory_limit))
        return self._ex

    def _kill(self):
        ex, self._ex = self._ex, None
        if ex is None:
            return
        for p in list(getattr(ex, "_processes", {}).values()):  # only the worker this object started
            try:
                os.kill(p.pid, signal.SIGKILL)
            except OSError:
                pass
        ex.shutdown(wait=True, cancel_futures=True)
        self.restarts += 1

    def run(self, kind: str, *args, timeout: float = 60.0, **kwargs):
        fut = self._executor().submit(_call, kind, args, kwargs)
        try:
            return fut.result(timeout=timeout)
        except cf.TimeoutError:
            self._kill()
            return ("timeout", timeout)
        except cf.process.BrokenProcessPool as exc:
            codes = [p.exitcode for p in getattr(self._ex, "_processes", {}).values()] if self._ex else []
            self._kill()
            return ("crash", f"worker died ({exc}; exit codes {codes})")

    def close(self):
        if self._ex is not None:
            self._ex.shutdown(wait=True, cancel_futures=True)
            self._ex = None


def leftovers(folder: str, keep=()) -> list:
    """Files in ``folder`` other than ``keep``: partial outputs or temporary files left behind."""
    return sorted(f for f in os.listdir(folder) if f not in set(keep))


def add_block_bomb(doc, levels: int) -> None:
    """Nest ``levels`` blocks of ten copies of the previous one (a single line at the bottom) and insert the
    top one on A-WALL: 10^(levels-1) lines once exploded."""
    prev = None
    for k in range(levels):
        blk = doc.blocks.new(f"L{k}")
        if prev is None:
            blk.add_line((0, 0), (100, 0))
        else:
            for j in range(10):
                blk.add_blockref(prev, (j * 10, 0))
        prev = f"L{k}"
    doc.modelspace().add_blockref(prev, (0, 0), dxfattribs={"layer": "A-WALL"})
