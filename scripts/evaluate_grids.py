#!/usr/bin/env python3
"""Score the Area Graph segmentation on every map of ../shared/data/grid_gt (``make evaluate``).

Each map is segmented twice: with the door / corridor widths of maps.csv (defaults where a value is
missing) and with the default widths. Prints recall, precision, MCC and F1 per map and the means.
Usage: evaluate_grids.py [--data DIR] [--previews DIR] [--maps NAME ...]
"""
import argparse
import csv
import os
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from algorithms import segmentation  # noqa: E402
from algorithms.evaluate import evaluate, read_gt_image  # noqa: E402
from algorithms.raster_io import read_grid  # noqa: E402


def load_maps(data: Path):
    rows = []
    with open(data / "maps.csv", newline="", encoding="utf-8") as fh:
        for row in csv.DictReader(fh):
            def num(key, default):
                v = (row.get(key) or "").strip()
                return float(v) if v else default
            rows.append(dict(name=row["map"], resolution=num("resolution_m_per_px", 0.05),
                             door=num("widest_door_m", segmentation.DEFAULT_DOOR_WIDTH),
                             corridor=num("narrowest_corridor_m", segmentation.DEFAULT_CORRIDOR_WIDTH)))
    return rows


def run(data: Path, previews=None, only=None, out=sys.stdout):
    results = []
    for m in load_maps(data):
        if only and m["name"] not in only:
            continue
        grid = read_grid(str(data / "input" / f"{m['name']}.png"), resolution=m["resolution"])
        gt = read_gt_image(str(data / "gt" / f"{m['name']}.png"))
        for setting, dw, cw in (("maps.csv", m["door"], m["corridor"]),
                                ("default", segmentation.DEFAULT_DOOR_WIDTH, segmentation.DEFAULT_CORRIDOR_WIDTH)):
            t = time.perf_counter()
            ag = segmentation.segment(grid, door_width=dw, corridor_width=cw)
            dt = time.perf_counter() - t
            ev = evaluate(ag.labels, gt)
            figures = {k: ev[k] for k in ("recall", "precision", "mcc", "f1", "n_gt")}
            results.append(dict(map=m["name"], setting=setting, door=dw, corridor=cw, seconds=dt,
                                areas=len(ag.areas), **figures))
            if previews:
                from algorithms.preview import render_preview
                render_preview(grid, ag, os.path.join(previews, f"seg_{m['name']}_{setting.replace('.', '_')}.png"))
    hdr = (f"{'map':22s} {'widths':9s} {'door':>5s} {'corr':>5s} {'areas':>5s} {'gt':>3s} {'recall':>6s} "
           f"{'prec':>6s} {'MCC':>6s} {'F1':>6s} {'s':>5s}")
    print(hdr, file=out)
    print("-" * len(hdr), file=out)
    for r in results:
        print(f"{r['map']:22s} {r['setting']:9s} {r['door']:5.2f} {r['corridor']:5.2f} {r['areas']:5d} {r['n_gt']:3d} "
              f"{r['recall']:6.3f} {r['precision']:6.3f} {r['mcc']:6.3f} {r['f1']:6.3f} {r['seconds']:5.2f}", file=out)
    print("-" * len(hdr), file=out)
    for setting in ("maps.csv", "default", None):
        sel = [r for r in results if setting is None or r["setting"] == setting]
        if not sel:
            continue
        mean = {k: sum(r[k] for r in sel) / len(sel) for k in ("recall", "precision", "mcc", "f1")}
        print(f"{'mean':22s} {setting or 'all':9s} {'':5s} {'':5s} {'':5s} {'':3s} {mean['recall']:6.3f} "
              f"{mean['precision']:6.3f} {mean['mcc']:6.3f} {mean['f1']:6.3f}", file=out)
    return results


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", default=str(REPO.parent / "shared" / "data" / "grid_gt"))
    ap.add_argument("--previews", default=None, help="write overlay pictures into this folder")
    ap.add_argument("--maps", nargs="*", default=None)
    args = ap.parse_args(argv)
    data = Path(args.data)
    if not (data / "maps.csv").is_file():
        print(f"no grid_gt data at {data}", file=sys.stderr)
        return 2
    results = run(data, args.previews, args.maps)
    mccs = [r["mcc"] for r in results]
    ok = sum(mccs) / len(mccs) >= 0.85 and min(mccs) >= 0.60
    print(f"target (mean MCC >= 0.85, every map >= 0.60): {'met' if ok else 'NOT met'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
