#!/usr/bin/env python3
"""``make bench``: the whole pipeline on every real drawing, scaling, speed targets, and a gallery.

Every run is a fresh subprocess (so its peak RSS is its own): CAD import -> rasterize -> segmentation ->
refinement -> room names -> osmAG export, on

* every plan of ``../shared/data/dxf/`` (the five filtered SIST floors and the ArchWeb plans), every sheet of
  ``../shared/data/dwg/`` (the SIST originals and the library) and the three floors of the sample building;
* scaling: one SIST floor at 0.088, 0.044 and 0.022 m/px, and 1..5 SIST floors fused into one building;
* the five SIST floors end to end (conversion in a 2-process pool + fusion).

Per plan: median wall and CPU seconds per stage over the runs, peak RSS, raster size, areas, passages, named
areas, connected components, vertices; a failing plan is a row with its error. Results go to
``docs/benchmarks.md`` (tables) and ``docs/gallery/<plan>.png`` (one picture per plan) with ``--write``.

    .venv/bin/python scripts/bench.py [--write docs/benchmarks.md] [--runs 3] [--only SIST-F5,office]
                                      [--skip-scaling] [--max-repeat-cpu 4] [--jobs N] [--stages]

Every plan runs ``--runs`` times (default 3). ``--max-repeat-cpu``: a plan whose first run takes more CPU
seconds than this is run once only (default: no limit; the table says how many runs each median is over), for a
quick look on a loaded machine;
``--jobs``: plans benchmarked at the same time (default: the number of cores; each run is still its own
process, and CPU seconds barely depend on it; on a machine shared with other work more jobs only take a
larger share of it). The plans of the speed targets (the filtered SIST floors and SIST-F5.dwg) run first,
one at a time with nothing else running: a target is one conversion on the 2-core machine, whose second core
the segmentation uses.
``--stages`` runs the older per-stage micro-benchmarks of ``benchmarks/bench_*.py`` instead.
"""
import argparse
import datetime
import importlib
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STAGES = ["cad_import", "rasterize", "segment", "types", "refine", "names", "outline", "export"]
RESOLUTIONS = [0.088, 0.044, 0.022]
SCALING_FLOOR = "SIST-F5"
TARGETS = [  # (what, limit s, limit MB)
    ("filtered SIST floor DXF -> osmAG (median)", 2.5, 1024),
    ("SIST-F5 original DWG -> osmAG", 20.0, 2048),
    ("five filtered SIST floors -> merged building", 15.0, None),
]


# ------------------------------------------------------------------ children
def child(argv):
    sys.path.insert(0, str(ROOT))
    from benchmarks import plans

    kind, payload = argv[0], json.loads(argv[1])
    if kind == "plan":
        out = plans.run_plan(**payload)
    elif kind == "merge":
        out = plans.run_merge(**payload)
    elif kind == "building":
        out = plans.run_building(**payload)
    else:
        raise SystemExit(f"unknown child {kind}")
    print("BENCH-RESULT " + json.dumps(out, default=float), flush=True)


def spawn(kind, payload, timeout=900):
    t0 = time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, __file__, "--child", kind, json.dumps(payload)], capture_output=True,
                              text=True, timeout=timeout, cwd=str(ROOT))
    except subprocess.TimeoutExpired:
        return {"ok": False, "error": f"timed out after {timeout} s", "wall_s": time.perf_counter() - t0}
    line = next((ln for ln in proc.stdout.splitlines() if ln.startswith("BENCH-RESULT ")), None)
    if line is None:
        err = (proc.stderr.strip().splitlines() or [f"no output, exit status {proc.returncode}"])[-1]
        return {"ok": False, "error": f"process died (exit {proc.returncode}): {err}",
                "wall_s": time.perf_counter() - t0}
    return json.loads(line[len("BENCH-RESULT "):])


# ------------------------------------------------------------------ inputs
def plan_list(shared: Path, work: Path):
    """[(label, group, path, level)] in table order; the sample building is generated into ``work``."""
    sys.path.insert(0, str(ROOT))
    from algorithms.building import level_from_name
    from algorithms.sample_building import generate_building

    out = []
    for group, folder, ext in (("SIST filtered DXF", shared / "dxf" / "sist", ".dxf"),
                               ("ArchWeb DXF", shared / "dxf" / "archweb", ".dxf"),
                               ("SIST original DWG", shared / "dwg" / "sist-original", ".dwg"),
                               ("library DWG", shared / "dwg" / "library", ".dwg")):
        for p in sorted(folder.glob("*" + ext)) if folder.is_dir() else []:
            label = p.stem + (".dwg" if ext == ".dwg" else "")  # SIST-F5 is both a filtered DXF and a DWG
            out.append((label, group, str(p), level_from_name(p.name) or "1"))
    sample = generate_building(str(work / "sample"), floors=3, seed=0)
    for k, p in enumerate(sample["dxf"], start=1):
        out.append((Path(p).stem, "sample building", str(p), str(k)))
    return out


def plan_list_order(plans):
    """The report's order: SIST filtered, ArchWeb, SIST DWG, library, sample (the order of ``plan_list``)."""
    groups = ["SIST filtered DXF", "ArchWeb DXF", "SIST original DWG", "library DWG", "sample building"]
    return sorted(plans, key=lambda p: (groups.index(p[1]) if p[1] in groups else 9, p[0]))


def _target_plan(item) -> bool:
    """A plan whose wall seconds are a speed target's figure (timed alone): the filtered SIST floors, SIST-F5.dwg."""
    return item[1] == "SIST filtered DXF" or item[0] == "SIST-F5.dwg"


def med(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else float("nan")


def summarise(runs):
    ok = [r for r in runs if r.get("ok")]
    if not ok:
        return dict(runs[0], runs=len(runs))
    s = dict(ok[0])
    warm = [r["warm"] for r in ok if (r.get("warm") or {}).get("ok")]
    if warm:  # the second conversion in the same process (plugin loaded): its own medians
        s["warm"] = {"runs": len(warm), "wall_s": med([w["wall_s"] for w in warm]),
                     "cpu_s": med([w["cpu_s"] for w in warm])}
    s.update({"runs": len(ok), "wall_s": med([r["wall_s"] for r in ok]), "cpu_s": med([r["cpu_s"] for r in ok]),
              "peak_mb": max(r["peak_mb"] for r in ok), "walls": [round(r["wall_s"], 2) for r in ok],
              "stages_wall": {k: med([r["stages_wall"].get(k) for r in ok]) for k in STAGES},
              "stages_cpu": {k: med([r["stages_cpu"].get(k) for r in ok]) for k in STAGES},
              "segment_steps": {k: med([r["segment_steps"].get(k) for r in ok]) for k in ok[0]["segment_steps"]}})
    return s


# ------------------------------------------------------------------ main
def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--write", help="Markdown file to (re)write with the results; pictures go to its gallery/")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--max-repeat-cpu", type=float, default=float("inf"))
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--only", help="comma-separated substrings of plan names")
    ap.add_argument("--skip-scaling", action="store_true")
    ap.add_argument("--work", help="work folder (default: a temporary one)")
    ap.add_argument("--shared", default=str(ROOT.parent / "shared" / "data"))
    ap.add_argument("--json", help="also dump all results to this JSON file")
    ap.add_argument("--stages", action="store_true", help="the older per-stage micro-benchmarks")
    ap.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    ap.add_argument("--run-stage", nargs=4, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(args.child)
        return 0
    if args.run_stage or args.stages:
        return stage_main(args)
    shared = Path(args.shared)
    if not shared.is_dir():
        print(f"real data folder {shared} is missing", file=sys.stderr)
        return 2
    work = Path(args.work or tempfile.mkdtemp(prefix="cad2osmag-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    gallery = Path(args.write).parent / "gallery" if args.write else work / "gallery"
    t_start = time.perf_counter()
    plans = plan_list(shared, work)
    if args.only:
        plans = [p for p in plans if any(o.lower() in p[0].lower() for o in args.only.split(","))]
    cost = {"sample building": 0, "ArchWeb DXF": 1, "SIST filtered DXF": 2, "SIST original DWG": 3, "library DWG": 4}
    plans.sort(key=lambda p: (cost.get(p[1], 5), p[0] != "SIST-F5.dwg"))  # table order is restored on writing
    table_order = {p[0] + p[1]: i for i, p in enumerate(plan_list_order(plans))}
    (work / "osm").mkdir(exist_ok=True)
    import threading

    lock = threading.Lock()
    done_rows, done_res = [], {}
    order = table_order

    def progress_write():
        """Rewrite the report after every finished run: a bench stopped early still leaves its tables."""
        if not args.write:
            return
        with lock:
            rows_now = sorted(done_rows, key=lambda r: order[r["label"] + r["group"]])
            res_now = [dict(done_res[r], res=r) for r in RESOLUTIONS if r in done_res]
            write_markdown(Path(args.write), rows_now, {"resolution": res_now, "floors": [], "building": None},
                           time.perf_counter() - t_start, args, pending=len(plans) - len(rows_now))

    def bench_plan(item):
        label, group, path, level = item
        runs = []
        for i in range(args.runs):
            payload = {"path": path, "out_osm": str(work / "osm" / f"{label}.osm"), "level": level,
                       "png": str(gallery / f"{label}.png") if i == 0 else None,
                       "warm": group == "SIST filtered DXF" and i == 0}  # + a second conversion, same process
            r = spawn("plan", payload)
            runs.append(r)
            if not r.get("ok") or (i == 0 and r["cpu_s"] > args.max_repeat_cpu):
                break
        s = summarise(runs)
        s.update(label=label, group=group, path=path)
        if s.get("ok"):
            print(f"{label:22s} {group:18s} {s['runs']} run(s) wall {s['wall_s']:6.2f} s cpu {s['cpu_s']:6.2f} s "
                  f"peak {s['peak_mb']:6.0f} MB  {s['areas']} areas {s['passages']} passages "
                  f"{s['named_areas']} named", flush=True)
        else:
            print(f"{label:22s} {group:18s} FAILED {s.get('error')}", flush=True)
        with lock:
            done_rows.append(s)
        progress_write()
        return s

    # Runs of one plan are serial; plans (and the resolution scaling runs) go ``--jobs`` at a time. On a
    # machine shared with other work this barely changes each run's CPU seconds, which is what we compare.
    import concurrent.futures as cf

    sist = shared / "dxf" / "sist"
    with cf.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        def scale_one(res):
            r = spawn("plan", {"path": str(sist / f"{SCALING_FLOOR}.dxf"), "level": "5", "resolution": res,
                               "out_osm": str(work / f"scale-{res}.osm")})
            with lock:
                done_res[res] = r
            progress_write()
            return r

        def scale(res):
            return ex.submit(scale_one, res)

        # cheap plans first (a bench stopped early has the most rows), the finest raster early so that it
        # overlaps the plans
        # the targets' plans first, one at a time on the otherwise idle machine (their wall seconds are the
        # targets' figures); then the rest ``--jobs`` at a time
        alone = [item for item in plans if _target_plan(item)]
        rest = [item for item in plans if not _target_plan(item)]
        alone_rows = [bench_plan(item) for item in alone]
        plan_futs = [ex.submit(bench_plan, item) for item in rest[:len(rest) // 2]]
        res_futs = {} if args.skip_scaling else {res: scale(res) for res in RESOLUTIONS}
        plan_futs += [ex.submit(bench_plan, item) for item in rest[len(rest) // 2:]]
        rows = sorted(alone_rows + [f.result() for f in plan_futs], key=lambda r: order[r["label"] + r["group"]])
        res_rows = [res_futs[res].result() for res in RESOLUTIONS] if res_futs else []
    scaling = {}
    if not args.skip_scaling:
        for res, r in zip(RESOLUTIONS, res_rows):
            r["res"] = res
            print(f"scaling {SCALING_FLOOR} at {res} m/px: cpu {r.get('cpu_s', 0):.2f} s, {r.get('peak_mb', 0):.0f} MB "
                  f"{r.get('error', '')}", flush=True)
        scaling = run_scaling(shared, work)
        scaling["resolution"] = res_rows
    total = time.perf_counter() - t_start
    if args.json:
        Path(args.json).write_text(json.dumps({"plans": rows, "scaling": scaling}, indent=1, default=float))
    if args.write:
        write_markdown(Path(args.write), rows, scaling, total, args)
        print(f"wrote {args.write} and {gallery}/ ({total / 60:.1f} min)")
    if not args.work:
        import shutil

        shutil.rmtree(work, ignore_errors=True)  # osmAG outputs, the sample building: hundreds of MB
    return 0


def run_scaling(shared: Path, work: Path):
    """Fusion of 1..5 floors (from the plan runs' osmAG files) and the building end to end, one at a time."""
    sist = shared / "dxf" / "sist"
    out = {"resolution": [], "floors": [], "building": None}
    floors = [work / "osm" / f"SIST-F{k}.osm" for k in range(1, 6)]
    if all(f.exists() for f in floors):
        for k in range(1, 6):
            r = spawn("merge", {"osm_paths": [str(f) for f in floors[:k]], "out_osm": str(work / f"merge-{k}.osm")})
            r["k"] = k
            out["floors"].append(r)
            print(f"scaling merge of {k} floors: {r.get('wall_s', 0):.2f} s {r.get('error', '')}", flush=True)
    dxfs = [str(sist / f"SIST-F{k}.dxf") for k in range(1, 6)]
    if all(os.path.exists(p) for p in dxfs):
        out["building"] = spawn("building", {"dxf_paths": dxfs, "out_dir": str(work / "building"), "workers": 2})
        b = out["building"]
        print(f"SIST building end to end: {b.get('wall_s', 0):.2f} s {b.get('error', '')}", flush=True)
    return out


# ------------------------------------------------------------------ report
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
    load = " / ".join(f"{v:.1f}" for v in os.getloadavg())
    return (f"{os.cpu_count()} cores, {cpu}, Python {platform.python_version()}, commit {commit}, "
            f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, load average {load}")


def _f(v, nd=2):
    return "–" if v is None or v != v else f"{v:.{nd}f}"


def _growth(xs, ys):
    """Exponent b of y ~ x^b (least squares in log-log)."""
    import math

    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x and y and x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    den = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / den if den else float("nan")


def _series_table(title, header, align, runs, key, cells):
    """Markdown lines of one scaling series: a title, then a row per run (``cells(run)``); a failed run is its
    ``key`` value and the error."""
    L = ["", title, "", f"| {header} |", f"| {align} |"]
    width = header.count("|") + 1
    for r in runs:
        if r.get("ok"):
            L.append("| " + " | ".join(str(c) for c in cells(r)) + " |")
        else:
            L.append(f"| {r[key]} | failed: {r.get('error', '')[:200]} |" + " |" * (width - 2))
    return L


def write_markdown(path: Path, rows, scaling, total, args, pending=0):
    rel_gallery = "gallery"
    L = ["# Benchmarks", "",
         "Written by `make bench` (`scripts/bench.py`). Every run is a fresh process: the whole pipeline (CAD "
         "import → rasterize → segmentation → refinement → room names → osmAG export) on one drawing. Times are "
         "**medians over the runs** (column *runs*); *wall* is elapsed seconds, *CPU* is the process's CPU "
         "seconds (`time.process_time`, all its threads). The machine is shared (see the load average): "
         "**CPU seconds are the figure to compare across runs and machines**; wall seconds are what a user "
         "waits on this loaded machine. Peak RSS is the run's maximum resident set size (the largest of its runs).",
         "", f"Machine: {machine_line()}. Whole bench: {total / 60:.1f} min. Runs per plan: {args.runs}"
         + (f", once only when the first run took more than {args.max_repeat_cpu:g} CPU s"
            if args.max_repeat_cpu != float("inf") else "")
         + f"; the speed targets' plans (filtered SIST floors, SIST-F5.dwg) one at a time with nothing else "
         f"running, the others {args.jobs} at a time."
         + (f" **Written while the bench was still running: {pending} plans not finished yet, and the "
            f"fusion scaling and the building end to end not run yet.**" if pending else ""), "",
         "## Speed targets", "", "| target | limit | measured (wall) | CPU | peak RSS | met |", "| --- | --- | ---: | ---: | ---: | --- |"]
    by = {r["label"]: r for r in rows}
    sist = [by[f"SIST-F{k}"] for k in range(1, 6) if f"SIST-F{k}" in by and by[f"SIST-F{k}"].get("ok")
            and by[f"SIST-F{k}"]["group"] == "SIST filtered DXF"]
    dwg5 = by.get("SIST-F5.dwg")
    b = (scaling or {}).get("building")

    def target_row(name, lim_s, lim_mb, wall, cpu, mb):
        lim = f"≤ {lim_s:g} s" + (f", ≤ {lim_mb / 1024:g} GB" if lim_mb else "")
        if wall is None:
            L.append(f"| {name} | {lim} | not measured | | | |")
            return
        met_wall = wall <= lim_s and (lim_mb is None or mb <= lim_mb)
        met_cpu = cpu is not None and cpu <= lim_s and (lim_mb is None or mb <= lim_mb)
        met = "yes" if met_wall else ("in CPU time" if met_cpu else "**no**")
        L.append(f"| {name} | {lim} | {_f(wall)} s | {_f(cpu)} s | {_f(mb, 0)} MB | {met} |")

    if sist:
        target_row(TARGETS[0][0], TARGETS[0][1], TARGETS[0][2], med([r["wall_s"] for r in sist]),
                   med([r["cpu_s"] for r in sist]), max(r["peak_mb"] for r in sist))
    else:
        target_row(TARGETS[0][0], TARGETS[0][1], TARGETS[0][2], None, None, None)
    warm = [r["warm"] for r in sist if r.get("warm")]
    if warm:  # never instead of the cold figure: what a QGIS user sees from the second conversion on
        target_row(TARGETS[0][0].replace("(median)", "(median), second conversion in the same process"),
                   TARGETS[0][1], None, med([w["wall_s"] for w in warm]), med([w["cpu_s"] for w in warm]), None)
    if dwg5 and dwg5.get("ok"):
        target_row(TARGETS[1][0], TARGETS[1][1], TARGETS[1][2], dwg5["wall_s"], dwg5["cpu_s"], dwg5["peak_mb"])
    else:
        target_row(TARGETS[1][0], TARGETS[1][1], TARGETS[1][2], None, None, None)
    if b and b.get("ok"):
        target_row(TARGETS[2][0] + f" ({b['workers']} processes)", TARGETS[2][1], TARGETS[2][2], b["wall_s"],
                   b["cpu_s"] / b["workers"], b["peak_mb"])
    else:
        target_row(TARGETS[2][0], TARGETS[2][1], TARGETS[2][2], None, None, None)
    L += ["", "For the building, *CPU* is the CPU seconds of all processes divided by the 2 workers (the wall time "
          "the 2 cores would need unloaded)."]
    if warm:
        fixed = med([r["cpu_s"] - r["warm"]["cpu_s"] for r in sist if r.get("warm")])
        L += ["*Second conversion in the same process* (not the target's figure, which is the fresh process "
              "above): the same floor converted again by the process that converted it first, as in QGIS from the "
              "second conversion on (plugin imported, compiled kernels loaded, first-use imports done); peak RSS "
              f"is the cold run's. A fresh process pays {_f(fixed)} CPU s more (median of the floors): the "
              "fixed per-process cost that every worker of the building's process pool pays once."]
    L += [""]

    L += ["## Every plan", "",
          "| plan | group | runs | wall s (median) | CPU s | peak RSS MB | raster px | areas | passages | named | "
          "components (largest %) | stairs/lifts | vertices | picture |",
          "| --- | --- | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | --- | --- | ---: | --- |"]
    for r in rows:
        if not r.get("ok"):
            err = str(r.get("error", "")).replace("|", "/").replace("\n", " ")[:300]
            L.append(f"| {r['label']} | {r['group']} | {r.get('runs', 1)} | {_f(r.get('wall_s'))} | | "
                     f"{_f(r.get('peak_mb'), 0)} | **failed**: {err} | | | | | | | |")
            continue
        pic = f"[png]({rel_gallery}/{r['label']}.png)"
        L.append(f"| {r['label']} | {r['group']} | {r['runs']} | {_f(r['wall_s'])} | {_f(r['cpu_s'])} | "
                 f"{_f(r['peak_mb'], 0)} | {r['raster'][0]}×{r['raster'][1]} | {r['areas']} | {r['passages']} | "
                 f"{r['named_areas']} | {r['components']} ({_f(r['largest_component_pct'], 0)} %) | "
                 f"{r['stairs']}/{r['elevators']} | {r['vertices']} | {pic} |")
    L += ["", "## Per stage (median seconds, wall / CPU)", "",
          "| plan | " + " | ".join(STAGES) + " | segmentation steps (wall s) |",
          "| --- | " + " | ".join("---:" for _ in STAGES) + " | --- |"]
    for r in rows:
        if not r.get("ok"):
            continue
        cells = [f"{_f(r['stages_wall'].get(k))} / {_f(r['stages_cpu'].get(k))}" for k in STAGES]
        steps = ", ".join(f"{k} {v:.2f}" for k, v in r.get("segment_steps", {}).items() if v == v and v >= 0.05)
        L.append(f"| {r['label']} ({r['group'].split()[0]}) | " + " | ".join(cells) + f" | {steps} |")
    if scaling:
        L += ["", "## Scaling"]
        L += _series_table(f"### Raster size ({SCALING_FLOOR} filtered DXF, one run each)",
                           "m/px | raster px | Mpx | wall s | CPU s | peak RSS MB | segment CPU s | areas | passages",
                           "---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---:", scaling["resolution"], "res",
                           lambda r: [r["res"], f"{r['raster'][0]}×{r['raster'][1]}",
                                      f"{r['raster'][0] * r['raster'][1] / 1e6:.1f}", _f(r["wall_s"]), _f(r["cpu_s"]),
                                      _f(r["peak_mb"], 0), _f(r["stages_cpu"].get("segment")), r["areas"],
                                      r["passages"]])
        ok = [r for r in scaling["resolution"] if r.get("ok")]
        if len(ok) >= 2:
            mp = [r["raster"][0] * r["raster"][1] for r in ok]
            L += ["", f"Growth with pixels (exponent b of cost ∝ pixels^b, log-log fit): CPU b = "
                  f"{_growth(mp, [r['cpu_s'] for r in ok]):.2f}, segmentation CPU b = "
                  f"{_growth(mp, [r['stages_cpu'].get('segment') for r in ok]):.2f}, peak RSS above the baseline b = "
                  f"{_growth(mp, [r['peak_mb'] - r['baseline_mb'] for r in ok]):.2f} (1 = linear in pixels)."]
        if scaling["floors"]:
            L += _series_table("### Floors fused (SIST filtered floors F1..Fk, from this bench's osmAG files, one run "
                               "each)", "floors | wall s | CPU s | peak RSS MB | areas | vertical passages | "
                               "registration RMS m", "---: | ---: | ---: | ---: | ---: | ---: | ---:",
                               scaling["floors"], "k",
                               lambda r: [r["k"], _f(r["wall_s"]), _f(r["cpu_s"]), _f(r["peak_mb"], 0), r["areas"],
                                          r["vertical"], _f(r.get("overall_rms"), 3)])
            ok = [r for r in scaling["floors"] if r.get("ok")]
            if len(ok) >= 2:
                L += ["", f"Growth with floors: CPU b = {_growth([r['k'] for r in ok], [r['cpu_s'] for r in ok]):.2f} "
                      "(cost ∝ floors^b)."]
        if b:
            L += ["", "### The SIST building end to end", ""]
            if b.get("ok"):
                L.append(f"Five filtered SIST floors → one merged building with {b['workers']} worker processes: "
                         f"{_f(b['wall_s'])} s wall (conversion {_f(b['convert_s'])} s, per floor "
                         f"{', '.join(str(x) for x in b['per_floor_s'])} s; fusion {_f(b['merge_s'])} s), "
                         f"{_f(b['cpu_s'])} CPU s in all processes, peak RSS {_f(b['peak_mb'], 0)} MB per process; "
                         f"{b['areas']} areas, {b['vertical']} vertical passages.")
            else:
                L.append(f"failed: {b.get('error')}")
    L += ["", "## Gallery", "",
          "One picture per plan (`docs/gallery/`): walls grey (the occupancy raster), areas coloured by type "
          "(room blue, corridor yellow, stairs red, lift violet; areas counted out of the floor's graph -- roofs below it, exterior ground, closed shafts -- light grey), passages red, names that the default font "
          "can draw (Chinese names are counted in *named* but not drawn).", ""]
    for r in rows:
        if r.get("ok"):
            L.append(f"- [{r['label']} ({r['group']})]({rel_gallery}/{r['label']}.png)")
    path.parent.mkdir(parents=True, exist_ok=True)
    # keep the sections other benchmarks own (make bench-route writes between its markers)
    kept = []
    if path.is_file():
        old = path.read_text(encoding="utf-8")
        for start, end in (("<!-- bench-route:start -->", "<!-- bench-route:end -->"),):
            i, j = old.find(start), old.find(end)
            if 0 <= i < j:
                kept.append(old[i:j + len(end)])
    path.write_text("\n".join(L) + "\n" + "".join("\n" + k + "\n" for k in kept), encoding="utf-8")


# ------------------------------------------------------------------ older per-stage micro-benchmarks
def stage_main(args):
    import resource

    if args.run_stage:
        module, index, work, shared = args.run_stage
        sys.path.insert(0, str(ROOT))
        mod = importlib.import_module(f"benchmarks.{module}")
        name, func = mod.STAGES[int(index)]
        base_kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        t0 = time.perf_counter()
        result = func(Path(work), Path(shared)) or {}
        out = {"stage": name, "wall_s": float(result.get("wall_s", time.perf_counter() - t0)),
               "detail": result.get("detail", ""), "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
               "baseline_mb": base_kb / 1024.0}
        print("BENCH-RESULT " + json.dumps(out))
        return 0
    work = Path(args.work or tempfile.mkdtemp(prefix="cad2osmag-bench-"))
    order = ["bench_cad", "bench_segment", "bench_refine_export", "bench_pipeline"]
    sys.path.insert(0, str(ROOT))
    for module in order:
        mod = importlib.import_module(f"benchmarks.{module}")
        for index, (name, _) in enumerate(mod.STAGES):
            proc = subprocess.run([sys.executable, __file__, "--run-stage", module, str(index), str(work), args.shared],
                                  capture_output=True, text=True)
            line = next((ln for ln in proc.stdout.splitlines() if ln.startswith("BENCH-RESULT ")), None)
            if line is None:
                print(f"{name:<28} FAILED {(proc.stderr.strip().splitlines() or ['no output'])[-1]}")
                continue
            r = json.loads(line[len("BENCH-RESULT "):])
            print(f"{r['stage']:<28} {r['wall_s']:8.3f} s  peak {r['peak_mb']:8.1f} MB  {r['detail']}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
