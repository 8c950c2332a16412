#!/usr/bin/env python3
"""Score the Area Graph segmentation on a folder of robot maps with ground truth (``make evaluate``).

The folder is laid out like ../shared/data/grid_gt: ``input/NAME.png`` (occupancy grid: black =
occupied, white = free, grey = unknown), optionally ``input_raw/NAME.png`` (the map as recorded),
``gt/NAME.png`` (one colour per ground-truth room) and optionally ``maps.csv`` (columns ``map``,
``resolution_m_per_px``, ``widest_door_m``, ``narrowest_corridor_m``; without it every map in
``gt/`` is scored at ``--resolution``). Each map is segmented with the default widths and, where
maps.csv gives widths, with those too. Prints recall, precision, MCC and F1 per map and the means;
with ``--out DIR`` writes ``scores.csv`` and side-by-side pictures (input | ground truth |
segmentation | errors) of the ``--worst`` lowest-scoring maps. ``--rotate DEG ...`` scores each map (and
its ground truth) turned by those angles too: a SLAM map is rarely aligned with the axes. ``--shift DX,DY ...``
scores each map moved by whole pixels too (padded on the left and top with what lies outside it): a map
lands anywhere in its raster, and no figure should depend on where.
Usage: evaluate_grids.py [--data DIR] [--out DIR] [--raw] [--worst N] [--maps NAME ...] [--rotate DEG ...]
                         [--shift DX,DY ...]
"""
import argparse
import csv
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from algorithms import segmentation  # noqa: E402
from algorithms.errors import InputError  # noqa: E402
from algorithms.evaluate import evaluate, gt_rooms, read_gt_image  # noqa: E402
from algorithms.raster_io import border_value, read_grid, rotate_raster  # noqa: E402

MEAN_TARGET = 0.90
MAP_TARGET = 0.75


def load_maps(data: Path, resolution: float = 0.05):
    """Maps of a grid_gt-like folder: dicts name, resolution, door, corridor, widths_given."""
    rows = []
    if (data / "maps.csv").is_file():
        with open(data / "maps.csv", newline="", encoding="utf-8") as fh:
            for row in csv.DictReader(fh):
                def num(key, default):
                    v = (row.get(key) or "").strip()
                    return float(v) if v else default
                given = any((row.get(k) or "").strip() for k in ("widest_door_m", "narrowest_corridor_m"))
                rows.append(dict(name=row["map"].strip(), resolution=num("resolution_m_per_px", resolution),
                                 door=num("widest_door_m", segmentation.DEFAULT_DOOR_WIDTH),
                                 corridor=num("narrowest_corridor_m", segmentation.DEFAULT_CORRIDOR_WIDTH),
                                 widths_given=given))
    else:
        for p in sorted((data / "gt").glob("*.png")):
            rows.append(dict(name=p.stem, resolution=resolution, door=segmentation.DEFAULT_DOOR_WIDTH,
                             corridor=segmentation.DEFAULT_CORRIDOR_WIDTH, widths_given=False))
    return rows


def _read_map(path: Path, resolution: float):
    """The occupancy grid of a map image; recorded maps saved in colour (a tinted trace drawn over
    the grey map) are read as their grey level."""
    try:
        return read_grid(str(path), resolution=resolution)
    except InputError as exc:
        if "colour image" not in str(exc):
            raise
    import cv2

    from algorithms.model import OccupancyGrid
    from algorithms.raster_io import _classify

    img = cv2.imread(str(path), cv2.IMREAD_GRAYSCALE)
    return OccupancyGrid(_classify(img), 0.0, img.shape[0] * resolution, float(resolution))


def rotate_map(grid, gt: np.ndarray, degrees: float):
    """The occupancy grid and its ground-truth image turned together by ``degrees`` counter-clockwise
    (``raster_io.rotate_raster``: nearest neighbour, padded with what lies outside each)."""
    from algorithms.model import OccupancyGrid

    data = rotate_raster(grid.data, degrees)[0]
    return (OccupancyGrid(data, 0.0, data.shape[0] * grid.resolution, grid.resolution),
            rotate_raster(gt, degrees)[0])


def shift_map(grid, gt: np.ndarray, dx: int, dy: int):
    """The occupancy grid and its ground-truth image moved ``dx`` px right and ``dy`` px down together:
    padded on the left and top with what lies outside each (the value most common on its border)."""
    from algorithms.model import OccupancyGrid

    def pad(img):
        out = np.empty((img.shape[0] + dy, img.shape[1] + dx) + img.shape[2:], img.dtype)
        out[...] = border_value(img)
        out[dy:, dx:] = img
        return out

    data = pad(grid.data)
    return OccupancyGrid(data, 0.0, data.shape[0] * grid.resolution, grid.resolution), pad(gt)


def _colours(n: int, seed: int = 7) -> np.ndarray:
    rng = np.random.default_rng(seed)
    col = rng.integers(60, 240, size=(n + 1, 3)).astype(np.uint8)
    col[0] = 255
    return col


def side_by_side(grid, gt_img: np.ndarray, labels: np.ndarray, ev: dict, path: str, title: str = "") -> None:
    """PNG: occupancy | ground truth | segmentation | errors (per ground-truth room, its best segment:
    green = right, red = segment spilling out of the room (merged), blue = room missed by the segment
    (split or uncovered))."""
    import cv2

    from algorithms.model import FREE, UNKNOWN

    occ = np.full(labels.shape + (3,), 0, np.uint8)
    occ[grid.data == FREE] = 255
    occ[grid.data == UNKNOWN] = 160
    seg = _colours(int(labels.max()))[labels]
    seg[(labels == 0) & (grid.data != FREE)] = 0
    seg[(labels == 0) & (grid.data == FREE)] = 230
    gtr = gt_rooms(gt_img)
    err = np.full(labels.shape + (3,), 255, np.uint8)
    err[grid.data != FREE] = 0
    for r in ev["rooms"]:
        room = gtr == r["gt"]
        s = labels == r["segment"] if r["segment"] else np.zeros_like(room)
        err[room & s] = (90, 200, 90)
        err[room & ~s] = (60, 90, 230)
        err[s & ~room & (gtr > 0)] = (230, 60, 60)
    panels = [occ, np.ascontiguousarray(gt_img[:, :, :3]), seg, err]
    sep = np.full((labels.shape[0], 6, 3), 255, np.uint8)
    img = np.concatenate(sum(([p, sep] for p in panels), [])[:-1], axis=1)
    if title:
        bar = np.full((28, img.shape[1], 3), 255, np.uint8)
        cv2.putText(bar, title, (6, 20), cv2.FONT_HERSHEY_SIMPLEX, 0.6, (0, 0, 0), 1, cv2.LINE_AA)
        img = np.concatenate([bar, img], axis=0)
    from algorithms.io_utils import atomic_path

    with atomic_path(path) as tmp:
        if not cv2.imwrite(tmp, np.ascontiguousarray(img[:, :, ::-1])):
            raise InputError(f"cannot write '{path}'")


def run(data: Path, out_dir=None, only=None, raw=False, worst=3, resolution=0.05, out=sys.stdout,
        settings=("maps.csv", "default"), angles=(0,), shifts=((0, 0),)):
    results = []
    kept = {}
    for m in load_maps(data, resolution):
        if only and m["name"] not in only:
            continue
        src = data / ("input_raw" if raw and (data / "input_raw" / f"{m['name']}.png").is_file() else "input")
        grid0 = _read_map(src / f"{m['name']}.png", m["resolution"])
        gt0 = read_gt_image(str(data / "gt" / f"{m['name']}.png"))
        runs = []
        if "maps.csv" in settings and m["widths_given"]:
            runs.append(("maps.csv", m["door"], m["corridor"]))
        if "default" in settings:
            runs.append(("default", segmentation.DEFAULT_DOOR_WIDTH, segmentation.DEFAULT_CORRIDOR_WIDTH))
        for angle, (sx, sy), (setting, dw, cw) in ((a, s_, r) for a in angles for s_ in shifts for r in runs):
            grid, gt = rotate_map(grid0, gt0, angle) if angle % 360 else (grid0, gt0)
            if sx or sy:
                grid, gt = shift_map(grid, gt, sx, sy)
            t = time.perf_counter()
            ag = segmentation.segment(grid, door_width=dw, corridor_width=cw)
            dt = time.perf_counter() - t
            ev = evaluate(ag.labels, gt)
            figures = {k: ev[k] for k in ("recall", "precision", "mcc", "f1", "n_gt")}
            results.append(dict(map=m["name"], setting=setting, angle=angle, shift=f"{sx},{sy}", door=dw, corridor=cw, seconds=dt,
                                areas=len(ag.areas), **figures))
            if out_dir and setting == "default":
                key = m["name"] + (f"_rot{angle:g}" if angle % 360 else "") + (f"_shift{sx}_{sy}" if sx or sy else "")
                kept[key] = (ev["mcc"], grid, gt, ag.labels, ev)
    turned = any(a % 360 for a in angles)
    moved = any(any(s_) for s_ in shifts)
    hdr = (f"{'map':22s} {'widths':9s} " + (f"{'deg':>4s} " if turned else "") + (f"{'shift':>5s} " if moved else "")
           + f"{'door':>5s} {'corr':>5s} "
           f"{'areas':>5s} {'gt':>3s} {'recall':>6s} "
           f"{'prec':>6s} {'MCC':>6s} {'F1':>6s} {'s':>5s}")
    print(hdr, file=out)
    print("-" * len(hdr), file=out)
    for r in results:
        print(f"{r['map']:22s} {r['setting']:9s} " + (f"{r['angle']:4g} " if turned else "")
              + (f"{r['shift']:>5s} " if moved else "") + f"{r['door']:5.2f} {r['corridor']:5.2f} {r['areas']:5d} {r['n_gt']:3d} "
              f"{r['recall']:6.3f} {r['precision']:6.3f} {r['mcc']:6.3f} {r['f1']:6.3f} {r['seconds']:5.2f}", file=out)
    print("-" * len(hdr), file=out)
    for setting, angle, (sx, sy) in ((s_, a, d) for s_ in ("maps.csv", "default") for a in angles for d in shifts):
        sel = [r for r in results if r["setting"] == setting and r["angle"] == angle and r["shift"] == f"{sx},{sy}"]
        if not sel:
            continue
        mean = {k: sum(r[k] for r in sel) / len(sel) for k in ("recall", "precision", "mcc", "f1")}
        print(f"{'mean':22s} {setting:9s} " + (f"{angle:4g} " if turned else "")
              + (f"{f'{sx},{sy}':>5s} " if moved else "") + f"{'':5s} {'':5s} {'':5s} {'':3s} {mean['recall']:6.3f} "
              f"{mean['precision']:6.3f} {mean['mcc']:6.3f} {mean['f1']:6.3f}   (worst "
              f"{min(r['mcc'] for r in sel):.3f})", file=out)
    if moved:  # the spread of each map's MCC over the shifts (what a map's figure owes to where it lies)
        for setting, angle in ((s_, a) for s_ in ("maps.csv", "default") for a in angles):
            for name in dict.fromkeys(r["map"] for r in results):
                v = [r["mcc"] for r in results if r["setting"] == setting and r["angle"] == angle and r["map"] == name]
                if len(v) > 1:
                    print(f"{'spread':8s} {name:22s} {setting:9s} " + (f"{angle:4g} " if turned else "")
                          + f"{min(v):.3f}-{max(v):.3f} ({max(v) - min(v):.3f}, mean {sum(v) / len(v):.3f})", file=out)
    if out_dir:
        os.makedirs(out_dir, exist_ok=True)
        with open(os.path.join(out_dir, "scores.csv"), "w", newline="", encoding="utf-8") as fh:
            w = csv.DictWriter(fh, fieldnames=list(results[0].keys()) if results else ["map"])
            w.writeheader()
            w.writerows(results)
        for name, (mcc, grid, gt, labels, ev) in sorted(kept.items(), key=lambda kv: kv[1][0])[:worst]:
            p = os.path.join(out_dir, f"worst_{name}.png")
            side_by_side(grid, gt, labels, ev, p, f"{name}  MCC {mcc:.3f}  (input | ground truth | segmentation | "
                                                  "errors: green right, red merged in, blue split off/missed)")
            print(f"picture: {p}", file=out)
    return results


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", default=str(REPO.parent / "shared" / "data" / "grid_gt"),
                    help="folder laid out like grid_gt (input/, gt/, optional input_raw/ and maps.csv)")
    ap.add_argument("--out", default=None, help="write scores.csv and pictures of the worst maps into this folder")
    ap.add_argument("--previews", dest="out", help=argparse.SUPPRESS)
    ap.add_argument("--worst", type=int, default=3, help="pictures of this many lowest-scoring maps (default 3)")
    ap.add_argument("--raw", action="store_true", help="segment input_raw/ (as recorded, with unknown space)")
    ap.add_argument("--resolution", type=float, default=0.05, help="m/px where maps.csv gives none (default 0.05)")
    ap.add_argument("--maps", nargs="*", default=None)
    ap.add_argument("--rotate", nargs="*", type=float, default=None, metavar="DEG",
                    help="also score every map and its ground truth turned by these angles (counter-clockwise, "
                         "degrees); 0 is always scored; the target is judged on the unturned maps")
    ap.add_argument("--shift", nargs="*", default=None, metavar="DX,DY",
                    help="also score every map moved by these whole pixels (padded on the left and top; "
                         "'2' is '2,2'); no shift is always scored; the target is judged on the maps as they are")
    args = ap.parse_args(argv)
    try:
        shifts = [(0, 0)] + [d for d in ((int(t.split(",")[0]), int(t.split(",")[-1])) for t in (args.shift or []))
                             if any(d)]
    except ValueError:
        print(f"--shift takes whole pixels DX,DY (or one number for both), not {args.shift}", file=sys.stderr)
        return 2
    if any(v < 0 for d in shifts for v in d):
        print("--shift takes pixels >= 0 (the map is padded on the left and top)", file=sys.stderr)
        return 2
    data = Path(args.data)
    if not (data / "gt").is_dir() or not (data / "input").is_dir():
        print(f"no grid_gt-like data at {data} (need input/ and gt/)", file=sys.stderr)
        return 2
    try:
        angles = [0.0] + [a for a in (args.rotate or []) if a % 360]
        results = run(data, args.out, args.maps, args.raw, args.worst, args.resolution, angles=angles, shifts=shifts)
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    sel = [r["mcc"] for r in results if r["setting"] == "default" and r["angle"] == 0 and r["shift"] == "0,0"]
    if not sel:
        print("no map scored", file=sys.stderr)
        return 2
    ok = sum(sel) / len(sel) >= MEAN_TARGET and min(sel) >= MAP_TARGET
    print(f"target with default widths (mean MCC >= {MEAN_TARGET}, every map >= {MAP_TARGET}): "
          f"{'met' if ok else 'NOT met'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
