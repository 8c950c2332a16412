#!/usr/bin/env python3
"""Convert every DXF/DWG drawing of a folder and print the quality figures per plan (``make evaluate-cad``).

Per plan: conversion ok, room-name texts inside an area (%), in an area of their own (%), the largest
connected component's share of the floor area (%), areas, passages, named areas, areas holding two
room names (conflicts), stairs / lifts found, semantic accuracy (named areas whose name text lies
inside them, %) and the ignored texts by reason. Totals over the plans with room text at the end.
Nothing is written next to the drawings; the figures can be rerun on any folder.

Usage: evaluate_cad.py [--data DIR ...] [--json FILE] [--files NAME ...] [--misses]
``--misses`` lists, per plan, the room-name texts that miss and why (outside every area, only nearby, in an
area holding another name, in an area named after another text): where to look on a new drawing.
Default data: ../shared/data/dxf/archweb and ../shared/data/dwg (relative to the repository).
Exit status 0 when every plan converted, 1 otherwise.
"""
import argparse
import json
import os
import sys
import time
import traceback
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

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
    args = ap.parse_args(argv)
    folders = args.data or [str(p) for p in DEFAULT_DATA]
    paths = drawings(folders)
    if args.files:
        paths = [p for p in paths if p.name in set(args.files)]
    if not paths:
        print(f"no .dxf or .dwg drawing in {', '.join(map(str, folders))}", file=sys.stderr)
        return 2
    results = []
    for p in paths:
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
