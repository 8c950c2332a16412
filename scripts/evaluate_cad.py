#!/usr/bin/env python3
"""Convert every DXF/DWG drawing of a folder and print the quality figures per plan (``make evaluate-cad``).

Per plan: conversion ok, room-name texts inside an area (%), in an area of their own (%), the largest
connected component's share of the floor area (%), areas, passages, named areas, areas holding two
room names (conflicts), stairs / lifts found, semantic accuracy (named areas whose name text lies
inside them, %) and the ignored texts by reason. Totals over the plans with room text at the end.
Nothing is written next to the drawings; the figures can be rerun on any folder.

Usage: evaluate_cad.py [--data DIR ...] [--json FILE] [--files NAME ...] [--misses] [--rotate DEG] [--mirror]
                       [--scale F] [--shift DX DY]
``--misses`` lists, per plan, the room-name texts that miss and why (outside every area, only nearby, in an
area holding another name, in an area named after another text): where to look on a new drawing.
``--rotate DEG`` / ``--mirror`` / ``--scale F`` convert every drawing turned about its centre (counter-clockwise),
mirrored (x -> -x) and its coordinates multiplied by F (the header unit follows when one fits: m -> cm at 100,
else unitless): unseen drawings come at an angle, mirrored and in mm, cm or m. The transform is applied to the
exploded drawing (as if the model space were one INSERT with that rotation, mirror and scale), DXF and DWG alike.
Default data: ../shared/data/dxf/archweb and ../shared/data/dwg (relative to the repository).
Exit status 0 when every plan converted, 1 otherwise.
"""
import argparse
import contextlib
import json
import math
import os
import sys
import time
import traceback
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

import numpy as np  # noqa: E402

from algorithms import pipeline, semantics  # noqa: E402
from algorithms.errors import InputError  # noqa: E402

DEFAULT_DATA = [REPO.parent / "shared" / "data" / "dxf" / "archweb", REPO.parent / "shared" / "data" / "dwg"]
EXTS = (".dxf", ".dwg")


def drawings(folders):
    out = []
    for folder in folders:
        folder = Path(folder)
        if folder.is_file() and folder.suffix.lower() in EXTS:
            out.append(folder)
            continue
        if not folder.is_dir():
            continue
        for root, _, files in os.walk(folder):
            out.extend(Path(root) / f for f in sorted(files) if f.lower().endswith(EXTS))
    return sorted(out)


def _similarity(deg: float, mirror: bool, scale: float) -> np.ndarray:
    """2x2 matrix: mirror (x -> -x) first, then scale, then turn counter-clockwise by ``deg``."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array(((c, -s), (s, c))) @ np.diag((-scale if mirror else scale, scale))


def _header_after(unit: str, scale: float) -> str:
    """The header unit of a drawing whose coordinates were multiplied by ``scale``: the unit that keeps the
    real size (m -> cm at 100, mm -> m at 0.001), else 'unitless'."""
    from algorithms.cad_units import UNIT_SCALES

    if unit not in UNIT_SCALES:
        return unit
    return next((u for u, f in UNIT_SCALES.items() if math.isclose(f, UNIT_SCALES[unit] / scale, rel_tol=1e-9)),
                "unitless")


@contextlib.contextmanager
def transformed(deg: float = 0.0, mirror: bool = False, scale: float = 1.0, shift=(0.0, 0.0)):
    """While active, every drawing the importer reads is turned by ``deg`` about the median of its geometry,
    mirrored and scaled: the exploded pieces, texts (position, rotation, height), and the hidden stair / lift
    symbols, exactly as an INSERT of the model space with that transform would explode (cad_explode); then moved
    by ``shift`` metres (by the header unit; drawing units when it has none). Nothing changes when the
    transform is the identity. Yields ``forward(xy, unit)``: (n, 2) metres of the last drawing
    read, as delivered (``unit``: metres per drawing unit), in the transformed drawing's frame."""
    from algorithms import cad_explode, cad_import, cad_units

    if not deg % 360 and not mirror and scale == 1.0 and not any(shift):
        yield lambda xy, unit=1.0: np.asarray(xy, np.float64)
        return
    if not (scale > 0 and math.isfinite(scale)):
        raise InputError(f"--scale must be a positive number, got {scale}")
    A = _similarity(deg, mirror, scale)
    rot = math.degrees(math.atan2(A[1, 0], A[0, 0]))
    centre = {}  # path -> (centre, shift) in drawing units: the same for both explodes and the hidden symbols

    def move(xy, c, unit=1.0):  # c: (centre, shift); unit: metres per drawing unit of xy
        return (np.asarray(xy, np.float64) - c[0] * unit) @ A.T + (c[0] + c[1]) * unit

    def turn_texts(texts, c):
        return [(*move((x, y), c), t, h * scale, (r + rot) % 360.0, *rest) for (x, y, t, h, r, *rest) in texts]

    orig_explode, orig_hidden, orig_header = cad_import._explode, cad_explode.hidden_symbols, cad_import._header_unit

    def explode(path, tol_du, *args, **kwargs):
        # curves flattened to the same chord in metres: the drawing's own units are 1 / scale of the new ones
        raw = orig_explode(path, tol_du / scale, *args, **kwargs)
        raw.tol = tol_du
        p = raw.pieces
        if path not in centre:
            pts = np.concatenate([c_[:, :2] for c_ in p.coords if len(c_)] or [np.zeros((1, 2))])
            pts = pts[np.isfinite(pts).all(axis=1)]  # filled pieces separate their rings by NaN rows
            per_unit = cad_units.UNIT_SCALES.get(raw.header_unit, 1.0)
            centre["last"] = centre[path] = (np.median(pts, axis=0) if len(pts) else np.zeros(2),
                                             np.asarray(shift, np.float64) / per_unit)
        c = centre[path]
        p.coords = [np.ascontiguousarray(move(c_[:, :2], c)) if len(c_) else c_ for c_ in p.coords]
        p.width = [w * scale for w in p.width]
        p.texts, p.hidden_texts = turn_texts(p.texts, c), turn_texts(p.hidden_texts, c)
        raw.header_unit = _header_after(raw.header_unit, scale)
        return raw

    def hidden(doc, states, rules, unit, extent=None, **kw):
        c = centre.get("last", (np.zeros(2), np.zeros(2)))
        if extent is not None:  # the box in the drawing's own frame: the bounding box of the turned-back corners
            x0, y0, x1, y1 = extent
            back = ((np.array(((x0, y0), (x1, y0), (x1, y1), (x0, y1))) - (c[0] + c[1]) * unit) @ np.linalg.inv(A).T
                    + c[0] * unit)
            extent = (*back.min(axis=0), *back.max(axis=0))
        out = orig_hidden(doc, states, rules, unit, extent, **kw)
        for g in out:
            g.coords = move(g.coords, c, unit)
        return out

    cad_import._explode, cad_explode.hidden_symbols = explode, hidden
    cad_import._header_unit = lambda doc: _header_after(cad_units._header_unit(doc), scale)

    def forward(xy, unit=1.0):
        return move(np.asarray(xy, np.float64), centre.get("last", (np.zeros(2), np.zeros(2))), unit)

    try:
        yield forward
    finally:
        cad_import._explode, cad_explode.hidden_symbols, cad_import._header_unit = orig_explode, orig_hidden, orig_header


def evaluate_plan(path, **kwargs):
    """Figures for one drawing (a dict); ``ok`` False with ``error`` when the conversion failed."""
    t0 = time.perf_counter()
    try:
        floor = pipeline.process_floor(str(path), **kwargs)
    except InputError as exc:
        return {"plan": Path(path).name, "ok": False, "error": str(exc), "seconds": time.perf_counter() - t0}
    except Exception as exc:  # a raw exception is a bug: report it, keep going
        return {"plan": Path(path).name, "ok": False, "error": f"{type(exc).__name__}: {exc}",
                "traceback": traceback.format_exc(limit=3), "seconds": time.perf_counter() - t0}
    fig = semantics.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    fig.update({"plan": Path(path).name, "ok": True, "seconds": time.perf_counter() - t0,
                "missed": semantics.missed_texts(floor.refined.areas, floor.names)})
    if "largest_component_share" in floor.stats:  # wall cavities, ducts and shafts the drawing closes count out
        fig["largest_component_pct"] = 100.0 * floor.stats["largest_component_share"]
        fig["closed_spaces"] = len(floor.stats.get("closed_spaces", []))
        fig["roof_spaces"] = len(floor.stats.get("roof_spaces", []))  # roofs below the floor count out too
        fig["outdoor_spaces"] = len(floor.stats.get("outdoor_spaces", []))  # terraces outside the facade too
    return fig


def _pct(v):
    return "   -" if v is None else f"{v:5.1f}"


def print_misses(results, out=sys.stdout):
    """The room-name texts that miss, per plan: outside every area, only nearby, in a conflict, or in an
    area named after another text (with the area's name, size and conflicting names)."""
    for r in results:
        if not r.get("ok") or not r.get("missed"):
            continue
        print(f"\n{r['plan']}: {len(r['missed'])} room-name texts miss", file=out)
        for m in r["missed"]:
            where = (f"area {m['area']} '{m['area_name']}' {m['area_m2']} m2" if m["area"] is not None else "no area")
            extra = f", also named: {m['conflict']}" if m["conflict"] else ""
            print(f"  {m['why']:16s} {m['text'][:32]!r:36s} ({m['x']:.1f}, {m['y']:.1f}) {where}{extra}", file=out)


def print_table(results, out=sys.stdout):
    head = (f"{'plan':34s} {'ok':>3s} {'texts':>5s} {'in%':>5s} {'own%':>5s} {'comp%':>5s} {'areas':>5s} "
            f"{'pass':>5s} {'named':>5s} {'confl':>5s} {'st/el':>5s} {'acc%':>5s} {'s':>5s}")
    print(head, file=out)
    print("-" * len(head), file=out)
    for r in results:
        if not r["ok"]:
            print(f"{r['plan'][:34]:34s}  no  {r['error'][:120]}", file=out)
            continue
        print(f"{r['plan'][:34]:34s} {'yes':>3s} {r.get('room_texts', 0):5d} {_pct(r.get('inside_pct'))} "
              f"{_pct(r.get('own_area_pct'))} {_pct(r['largest_component_pct'])} {r['areas']:5d} {r['passages']:5d} "
              f"{r.get('named_areas', 0):5d} {r.get('conflicts', 0):5d} {r['stairs']:2d}/{r['elevators']:<2d} "
              f"{_pct(r.get('semantic_accuracy_pct'))} {r['seconds']:5.1f}", file=out)
    for r in results:
        if r["ok"] and r.get("ignored_by_reason"):
            ign = ", ".join(f"{k} {v}" for k, v in sorted(r["ignored_by_reason"].items(), key=lambda kv: -kv[1]))
            print(f"  {r['plan']}: ignored {r['ignored']} ({ign}); {r.get('outside', 0)} room texts outside "
                  f"every area; {r.get('splits', 0)} areas split"
                  + (f"; {r['hidden_used']} of {r['hidden_texts']} room texts of frozen/off layers named an area"
                     if r.get("hidden_texts") else ""), file=out)
    tot = totals(results)
    print(f"\nplans {tot['plans']}, converted {tot['converted']}; over the {tot['plans_with_text']} plans with room "
          f"text: {tot['room_texts']} room-name texts, {_pct(tot['inside_pct'])} % inside an area, "
          f"{_pct(tot['own_area_pct'])} % naming an area of their own; {tot['named_areas']} named areas, "
          f"{_pct(tot['conflict_pct'])} % holding two names; semantic accuracy {_pct(tot['semantic_accuracy_pct'])} %; "
          f"largest component >= 95 % of the area on {tot['connected']}/{tot['converted']} plans", file=out)
    return tot


def totals(results):
    ok = [r for r in results if r["ok"]]
    wt = [r for r in ok if r.get("room_texts")]
    n = sum(r["room_texts"] for r in wt)
    named = sum(r.get("named_areas", 0) for r in wt)
    inside = sum(r["inside_pct"] * r["room_texts"] / 100.0 for r in wt)
    own = sum(r["own_texts"] for r in wt)
    correct = sum((r.get("semantic_accuracy_pct") or 0.0) * r.get("named_areas", 0) / 100.0 for r in wt)
    return {"plans": len(results), "converted": len(ok), "plans_with_text": len(wt), "room_texts": n,
            "inside_pct": 100.0 * inside / n if n else None, "own_area_pct": 100.0 * own / n if n else None,
            "named_areas": named, "conflict_pct": 100.0 * sum(r.get("conflicts", 0) for r in wt) / named if named else None,
            "semantic_accuracy_pct": 100.0 * correct / named if named else None,
            "connected": sum(r["largest_component_pct"] >= 95.0 for r in ok)}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", nargs="*", default=None, help="folders (or files) of DXF/DWG drawings")
    ap.add_argument("--files", nargs="*", default=None, help="only these file names")
    ap.add_argument("--json", default=None, help="also write the figures as JSON to this file")
    ap.add_argument("--no-names", action="store_true", help="run without the room-name stage")
    ap.add_argument("--misses", action="store_true",
                    help="also list, per plan, the room-name texts that miss (outside, nearby, conflict, not own)")
    ap.add_argument("--rotate", type=float, default=0.0, metavar="DEG",
                    help="turn every drawing by DEG degrees (counter-clockwise) before the conversion")
    ap.add_argument("--mirror", action="store_true", help="mirror every drawing (x -> -x) before the conversion")
    ap.add_argument("--shift", type=float, nargs=2, default=(0.0, 0.0), metavar=("DX", "DY"),
                    help="move every drawing by DX, DY metres (a fraction of a raster cell measures how much the "
                         "figures depend on where the raster's cells fall)")
    ap.add_argument("--scale", type=float, default=1.0, metavar="F",
                    help="multiply every drawing's coordinates by F (the header unit follows where one fits)")
    args = ap.parse_args(argv)
    if not (args.scale > 0 and math.isfinite(args.scale)):
        print(f"--scale must be a positive number, got {args.scale}", file=sys.stderr)
        return 2
    folders = args.data or [str(p) for p in DEFAULT_DATA]
    paths = drawings(folders)
    if args.files:
        paths = [p for p in paths if p.name in set(args.files)]
    if not paths:
        print(f"no .dxf or .dwg drawing in {', '.join(map(str, folders))}", file=sys.stderr)
        return 2
    results = []
    for p in paths:
        with transformed(args.rotate, args.mirror, args.scale, args.shift):
            r = evaluate_plan(p, names=not args.no_names)
        results.append(r)
        print(f"{p.name}: {'ok' if r['ok'] else 'FAILED'} ({r['seconds']:.1f} s)", file=sys.stderr, flush=True)
    tot = print_table(results)
    if args.misses:
        print_misses(results)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump({"plans": results, "totals": tot}, fh, indent=1, ensure_ascii=False, default=str)
    return 0 if all(r["ok"] for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
