"""DWG read time per sheet: ``python -m benchmarks.dwg_read [FOLDER_OR_FILES...]`` (default: the shared
DWG sheets). Prints a Markdown table: entities in the file, the native read (``cad_dwg.read_dwg``) and
the whole import (``import_dxf``: read + block explosion + layer filter + units) in wall and CPU seconds
(CPU time is what counts on a loaded machine), geometries and texts kept, and what could not be decoded.
``--ezdwg`` adds the time of ezdwg's own high-level ``modelspace().query()`` and ``to_dxf`` for comparison.
"""
import argparse
import glob
import os
import resource
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from algorithms import cad_dwg  # noqa: E402
from algorithms.cad_import import import_dxf  # noqa: E402


def _timed(fn, *args, **kw):
    w, c = time.perf_counter(), time.process_time()
    out = fn(*args, **kw)
    return out, time.perf_counter() - w, time.process_time() - c


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("paths", nargs="*")
    ap.add_argument("--ezdwg", action="store_true", help="also time ezdwg's high-level query and to_dxf")
    args = ap.parse_args(argv)
    paths = args.paths or [str(REPO.parent / "shared" / "data" / "dwg")]
    files = []
    for p in paths:
        files += sorted(glob.glob(os.path.join(p, "**", "*.dwg"), recursive=True)) if os.path.isdir(p) else [p]
    print("| sheet | version | entities in file | read wall / CPU s | import wall / CPU s | geometries kept | "
          "texts (ATTRIB) | undecoded |" + (" ezdwg query / to_dxf s |" if args.ezdwg else ""))
    print("|---|---|---|---|---|---|---|---|" + ("---|" if args.ezdwg else ""))
    import ezdwg

    for f in files:
        ezdwg.clear_decode_caches()  # cold read every time
        (doc, _), rw, rc = _timed(cad_dwg.read_dwg, f)
        n_file = sum(doc.counts.values()) + sum(doc.undecoded.values())
        ezdwg.clear_decode_caches()
        d, iw, ic = _timed(import_dxf, f)
        n_attr = sum(1 for t in d.texts if t.entity == "ATTRIB")
        und = ", ".join(f"{k} {v}" for k, v in sorted(d.undecoded.items())) or "-"
        row = (f"| {os.path.basename(f)} | {doc.release} | {n_file} | {rw:.1f} / {rc:.1f} | {iw:.1f} / {ic:.1f} | "
               f"{len(d.geometries)} | {len(d.texts)} ({n_attr}) | {und} |")
        if args.ezdwg:
            import tempfile

            _, qw, _ = _timed(lambda: list(ezdwg.read(f).modelspace().query()))
            with tempfile.TemporaryDirectory() as tmp:
                _, cw, _ = _timed(ezdwg.to_dxf, f, os.path.join(tmp, "x.dxf"))
            row += f" {qw:.1f} / {cw:.1f} |"
        print(row, flush=True)
    print(f"\npeak RSS {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")


if __name__ == "__main__":
    main()
