#!/usr/bin/env python3
"""Per-stage benchmark: wall time and peak memory of every pipeline stage on real data.

Each stage listed in ``benchmarks/bench_*.py`` (``STAGES = [(name, func), ...]``) runs in a fresh
subprocess, in file order, sharing one work folder so a stage reads what the previous one wrote. The
stage function times itself (imports excluded); peak memory is the subprocess's maximum resident set
size, reported both in total and above the baseline after imports.

    .venv/bin/python scripts/bench.py [--write docs/benchmarks.md] [--only cad,segment]
"""
import argparse
import datetime
import importlib
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ORDER = ["bench_cad", "bench_segment", "bench_refine_export", "bench_pipeline"]  # pipeline order; others follow
TARGETS = {  # stage name -> (max wall s, max peak MB) from the issues
    "cad_import+rasterize": (3.0, 1024),
    "segment": (5.0, 1536),
    "refine+export": (1.0, None),
    "whole floor DXF -> osmAG": (35.0, None),  # the reference tool per floor
}


def discover(only=None):
    mods = sorted(p.stem for p in (ROOT / "benchmarks").glob("bench_*.py"))
    mods = [m for m in ORDER if m in mods] + [m for m in mods if m not in ORDER]
    if only:
        mods = [m for m in mods if any(o in m for o in only)]
    return mods


def run_stage(module, index, work, shared):
    """Child process: import, note the baseline RSS, run one stage, print a JSON line."""
    sys.path.insert(0, str(ROOT))
    mod = importlib.import_module(f"benchmarks.{module}")
    name, func = mod.STAGES[index]
    base_kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    t0 = time.perf_counter()
    result = func(Path(work), Path(shared)) or {}
    total = time.perf_counter() - t0
    peak_kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    out = {"stage": name, "module": module, "wall_s": float(result.get("wall_s", total)),
           "detail": result.get("detail", ""), "peak_mb": peak_kb / 1024.0,
           "baseline_mb": base_kb / 1024.0}
    print("BENCH-RESULT " + json.dumps(out))


def machine_line():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo", encoding="utf-8"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "?"
    return (f"{os.cpu_count()} cores, {cpu}, Python {platform.python_version()}, commit {commit}, "
            f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--write", help="Markdown file to (re)write with the results")
    ap.add_argument("--only", help="comma-separated substrings of benchmark modules to run")
    ap.add_argument("--work", help="work folder (default: a temporary one)")
    ap.add_argument("--shared", default=str(ROOT.parent / "shared" / "data"))
    ap.add_argument("--run-stage", nargs=4, metavar=("MODULE", "INDEX", "WORK", "SHARED"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.run_stage:
        m, i, w, s = args.run_stage
        run_stage(m, int(i), w, s)
        return 0
    if not Path(args.shared).is_dir():
        print(f"real data folder {args.shared} is missing", file=sys.stderr)
        return 2
    work = Path(args.work or tempfile.mkdtemp(prefix="cad2osmag-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    rows, failed = [], False
    for module in discover(args.only.split(",") if args.only else None):
        mod = importlib.import_module(f"benchmarks.{module}") if str(ROOT) in sys.path else None
        if mod is None:
            sys.path.insert(0, str(ROOT))
            mod = importlib.import_module(f"benchmarks.{module}")
        for index, (name, _) in enumerate(mod.STAGES):
            proc = subprocess.run([sys.executable, __file__, "--run-stage", module, str(index), str(work),
                                   args.shared], capture_output=True, text=True)
            line = next((ln for ln in proc.stdout.splitlines() if ln.startswith("BENCH-RESULT ")), None)
            if proc.returncode != 0 or line is None:
                failed = True
                err = (proc.stderr.strip().splitlines() or ["no output"])[-1]
                rows.append({"stage": name, "module": module, "wall_s": float("nan"), "peak_mb": float("nan"),
                             "baseline_mb": float("nan"), "detail": f"FAILED: {err}"})
            else:
                rows.append(json.loads(line[len("BENCH-RESULT "):]))
            r = rows[-1]
            print(f"{r['stage']:<28} {r['wall_s']:8.3f} s  peak {r['peak_mb']:8.1f} MB  {r['detail']}", flush=True)
    if args.write:
        write_markdown(Path(args.write), rows)
        print(f"wrote {args.write}")
    return 1 if failed else 0


def write_markdown(path, rows):
    lines = ["# Benchmarks", "",
             "Written by `make bench` (scripts/bench.py): every stage runs in its own process on real data from",
             "`../shared/data`; wall time excludes imports; peak memory is the process's maximum resident set",
             "size (total, and above the baseline after imports).", "",
             f"Machine: {machine_line()}", "",
             "| stage | wall (s) | peak RSS (MB) | above baseline (MB) | target | details |",
             "| --- | ---: | ---: | ---: | --- | --- |"]
    for r in rows:
        target = TARGETS.get(r["stage"])
        tgt = "" if target is None else f"≤ {target[0]} s" + (f", ≤ {target[1]} MB" if target[1] else "")
        lines.append(f"| {r['stage']} | {r['wall_s']:.3f} | {r['peak_mb']:.0f} | "
                     f"{r['peak_mb'] - r['baseline_mb']:.0f} | {tgt} | {r['detail']} |")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    sys.exit(main())
