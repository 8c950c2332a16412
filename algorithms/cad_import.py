"""Stage 1: read a DXF, explode blocks, keep the structural layers, flatten curves, convert to metres.

Public API
----------
``import_dxf(path, rules=None, layers=None, units=None, include_doors=False, progress=None) -> CadDrawing``
    Geometries (``CadGeometry``, metres, CAD frame) of the kept layers and every visible text.
``list_layers(path, rules=None, progress=None) -> list[LayerInfo]``
    Every layer with its entity counts after block explosion and what the rules make of it.
``inspect_dxf(path, rules=None, progress=None) -> CadDrawing``
    Same as list_layers but returns the whole drawing summary (layers, units, warnings, repairs).
``layer_kept(info, rules=None, include_doors=False) -> bool``
    Whether import_dxf keeps a layer (``LayerInfo.kept`` is also True for door layers).
``choose_unit(size_du, header_unit) -> (unit, warning or None)``
    The unit plausibility rule on its own.

Damaged files: ``ezdxf.readfile`` first (fast); if it fails, ``ezdxf.recover``; if that fails too (or
a truncated file yields nothing), the file is salvaged in memory (entities with unreadable numbers
dropped, a truncated or broken tail cut, the open section closed) and recovered again. Every repair
is listed in ``CadDrawing.repairs`` and reported as a progress warning.

Conventions
-----------
* Curves (ARC, CIRCLE, bulges, ELLIPSE, SPLINE, hatch edges) are flattened to <= 1 cm chord error.
* A ``CadGeometry`` of a filled entity with holes (a solid HATCH with islands) carries all its rings
  in one ``coords`` array, rings separated by a row of NaN; it is filled with the even-odd rule.
* INSERTs are exploded recursively with their full transform (scale, rotation, mirror, MINSERT
  arrays); an entity on layer "0" inside a block takes the layer of the INSERT. Entities on frozen
  layers are skipped, and so are entities on layers that are off (for an inherited layer "0", the
  INSERT's layer decides). A block inserted on a frozen layer is skipped entirely.
* Units: ``$INSUNITS`` is a hint. The building size (percentile extent of the kept vertices) must be
  5-500 m; otherwise the most plausible of mm / cm / m (and the header unit) is chosen with a
  warning. ``units`` overrides everything.
"""
from __future__ import annotations

import gc
import math
import os
import time
from contextlib import contextmanager
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .cad_classify import (AUX_KIND, DOOR_RADIUS, DOOR_SWEEP, _circle_from_3, boundary_evidence,  # noqa: F401
                           classify_entities, is_projection_line, keep_void_edges, level_marks, split_projection_lines,
                           find_door_swings, swing_candidates)
from .cad_sheet import describe_plans, find_plans, parse_plan
from .cad_explode import (MAX_SEGMENTS_PER_TURN, SKIP_TYPES, TEXT_TYPES, _arc_points, _boundary_rings,  # noqa: F401
                          _bulge_polyline, _chain, _edge_points, _Exploder, _explode, _extrusion, _mtext_plain,
                          _n_segments, _ocs_to_wcs, _Pieces, _Raw, _text_plain, _transform_pieces,
                          BLOCK_SEP, innermost_block)
from .cad_read import _code_kind, _is_truncated, _layer_states, _read_doc, _salvage  # noqa: F401
from .cad_units import (CHORD_TOL, PLAUSIBLE_SIZE, TYPICAL_SIZE, UNIT_SCALES, UNIT_SIZE_PERCENTILES,  # noqa: F401
                        _header_unit, _INSUNITS, _percentile_size, _UNIT_ALIASES, choose_unit, normalize_unit)
from .errors import InputError
from .layer_rules import LayerRules, default_rules, load_rules, meaningful_part
from .model import CadDrawing, CadGeometry, CadText, DoorHint, LayerInfo
from .progress import ensure


def _layer_infos(raw: _Raw, rules: LayerRules, selected: Optional[Dict[str, str]] = None) -> Dict[str, LayerInfo]:
    infos: Dict[str, LayerInfo] = {}
    for name, (frozen, off) in raw.states.items():
        infos[name] = LayerInfo(name=name, frozen=frozen, off=off)

    def get(name):
        info = infos.get(name)
        if info is None:
            info = infos[name] = LayerInfo(name=name)
        return info

    for lay, et in zip(raw.pieces.layer, raw.pieces.etype):
        c = get(lay).counts
        c[et] = c.get(et, 0) + 1
    for t in raw.pieces.texts:
        c = get(t[5]).counts
        c[t[6]] = c.get(t[6], 0) + 1
    for lay, et, k in raw.pieces.counts:
        c = get(lay).counts
        c[et] = c.get(et, 0) + k
    for name, info in infos.items():
        info.matched = meaningful_part(name)
        if selected is not None:
            key = name.lower()
            if key in selected:
                info.kind = selected[key]
                info.rule = "selected in LAYERS"
            else:
                info.kind, info.rule = None, "not in LAYERS"
        else:
            info.kind, info.rule = rules.classify(name)
    return infos



def _kept_mask(raw: _Raw, infos: Dict[str, LayerInfo], rules: LayerRules, include_doors: bool,
               selected: bool) -> List[int]:
    kinds = set(rules.raster_kinds)
    if include_doors:
        kinds.add("door")
    idx = []
    for i, lay in enumerate(raw.pieces.layer):
        info = infos.get(lay)
        if info is None or info.kind is None:
            continue
        if selected or info.kind in kinds:
            idx.append(i)
    return idx


def _nothing_kept_message(path: str, infos: Dict[str, LayerInfo], rules: LayerRules, layers) -> str:
    base = os.path.basename(path)
    with_geom = sorted((i for i in infos.values() if i.counts), key=lambda i: -sum(i.counts.values()))
    desc = "; ".join(f"'{i.name}' ({sum(i.counts.values())} entities{', ' + i.rule if i.rule else ''}"
                     f"{', frozen' if i.frozen else ''}{', off' if i.off else ''})" for i in with_geom[:25])
    if len(with_geom) > 25:
        desc += f"; … and {len(with_geom) - 25} more"
    if layers:
        return (f"none of the LAYERS {list(layers)} holds drawable geometry in '{base}'. The drawing's layers "
                f"with entities are: {desc or 'none'}")
    return (f"the layer filter keeps no geometry of '{base}'. Layers with entities: {desc or 'none'}. "
            "Add a keyword of the wall layer's name to the 'wall' list of a LAYER_RULES JSON file (copy "
            "algorithms/default_layer_rules.json; remove it from 'exclude' if it is listed there), or pick the "
            "wall layers explicitly with LAYERS")


def _fallback_walls(infos: Dict[str, LayerInfo], raw: _Raw) -> Optional[str]:
    """No wall layer matched: promote the unmatched (not excluded) layers with geometry to walls."""
    if any(i.kind == "wall" and not i.frozen and not i.off for i in infos.values()):
        return None
    with_geom = set(raw.pieces.layer)
    cands = [i for i in infos.values() if i.kind is None and i.rule == "no keyword" and i.name in with_geom]
    if not cands:
        return None
    for i in cands:
        i.kind, i.rule = "wall", "fallback: no layer matched a wall keyword"
    names = ", ".join(f"'{i.name}'" for i in sorted(cands, key=lambda i: i.name.lower()))
    return (f"no layer name matched a wall keyword; using every layer that no rule excludes as walls: {names}. "
            "Give LAYERS or a LAYER_RULES file with a keyword of the real wall layers for a cleaner result")


def _resolve_rules(rules) -> LayerRules:
    if rules is None:
        return default_rules()
    if isinstance(rules, LayerRules):
        return rules
    return load_rules(str(rules))


def layer_kept(info: LayerInfo, rules=None, include_doors: bool = False) -> bool:
    """Whether the import keeps a layer's geometry: a raster kind of the rules (doors only when
    asked), not frozen, not off. (``LayerInfo.kept`` is True for door layers too.)"""
    rules = _resolve_rules(rules)
    kinds = set(rules.raster_kinds) | ({"door"} if include_doors else set())
    return info.kind in kinds and not info.frozen and not info.off


@contextmanager
def _gc_paused():
    """The cyclic garbage collector off while the import builds its ~10^5 objects (entities, pieces, arrays,
    none of them garbage): its full passes over them cost 15 % of a sheet's import (SIST-F5.dwg: 0.7 of 4.5
    CPU s). Reference counting still frees everything; the collector runs again afterwards."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()


def list_layers(path: str, rules=None, progress=None) -> List[LayerInfo]:
    """Every layer of the drawing (table + effective layers after explosion), sorted by name."""
    drawing = inspect_dxf(path, rules, progress)
    return sorted(drawing.layers.values(), key=lambda i: i.name.lower())


@_gc_paused()
def inspect_dxf(path: str, rules=None, progress=None) -> CadDrawing:
    """Layers, units and repairs of a drawing without filtering (geometries are not returned)."""
    progress = ensure(progress)
    rules = _resolve_rules(rules)
    raw = _explode(path, 0.01, progress.sub(0, 95))
    infos = _layer_infos(raw, rules)
    warnings = list(raw.warnings)
    xrefs = sorted(set(raw.pieces.xrefs))
    base = os.path.basename(path)
    if not raw.pieces.layer and not raw.pieces.texts:
        raise InputError(f"'{base}' has no geometry and no text in model space"
                         + (f": {_xref_message(xrefs)}" if xrefs else
                            " (the plan may be in a paper-space layout, or the file is damaged)"))
    if xrefs:
        warnings.append(_xref_message(xrefs))
    fallback = _fallback_walls(infos, raw)  # the same choice import_dxf makes, so 'kept' tells the truth
    if fallback:
        warnings.append(fallback)
    for msg in raw.repairs + warnings:  # reported once, here, like import_dxf does
        progress.warning(msg)
    progress.step(100)
    return CadDrawing(path=path, geometries=[], texts=[], layers=infos, unit_name=raw.header_unit,
                      unit_scale=UNIT_SCALES.get(raw.header_unit, 1.0), header_unit=raw.header_unit,
                      warnings=warnings, repairs=raw.repairs, undecoded=dict(getattr(raw.doc, "undecoded", {})))


def _xref_message(xrefs: List[str]) -> str:
    return (f"the drawing references external files {', '.join(xrefs)}; bind them in CAD first (XREF > Bind) "
            "and export the DXF again: their content is not in this DXF")


def _hidden_texts(raw_texts, scale: float, extent, first_id: int) -> List[CadText]:
    """Texts on frozen / off layers as CadTexts (metres), within the kept plan's extent (+ 1 m) when a
    plan was picked on the sheet; ids continue after the visible texts."""
    out: List[CadText] = []
    for t in raw_texts or []:
        x, y = t[0] * scale, t[1] * scale
        if not (math.isfinite(x) and math.isfinite(y)):
            continue
        if extent is not None and not (extent[0] - 1 <= x <= extent[2] + 1 and extent[1] - 1 <= y <= extent[3] + 1):
            continue
        out.append(CadText(x=x, y=y, text=t[2], height=t[3] * scale, rotation=t[4], layer=t[5], entity=t[6],
                           block=innermost_block(t[7]), tag=t[8], id=first_id + len(out)))
    return out


def _callouts_beside_plan(raw_texts, scale: float, extent, first_id: int) -> List[CadText]:
    """Stair / lift detail callouts of frozen / off layers ("E1-ST-01详见建施(A-E-40-01)") hanging just outside
    the kept plan's extent (beyond its 1 m margin, within ``semantics.CALLOUT_REACH``): written at the end of a
    leader drawn out of the plan from the stair they name (SIST-F4: E1-ST-01 2 m below the plan), they are
    the plan's. Only callouts naming a stair or lift code are kept; ids continue after ``first_id``."""
    if extent is None or not raw_texts:
        return []
    from . import semantics

    reach = semantics.CALLOUT_REACH
    x0, y0, x1, y1 = extent
    cand: List[CadText] = []
    for t in raw_texts:
        x, y = t[0] * scale, t[1] * scale
        if not (math.isfinite(x) and math.isfinite(y)):
            continue
        if x0 - 1 <= x <= x1 + 1 and y0 - 1 <= y <= y1 + 1:
            continue  # kept by _hidden_texts
        if not (x0 - reach <= x <= x1 + reach and y0 - reach <= y <= y1 + reach):
            continue
        cand.append(CadText(x=x, y=y, text=t[2], height=t[3] * scale, rotation=t[4], layer=t[5], entity=t[6],
                            block=innermost_block(t[7]), tag=t[8]))
    out: List[CadText] = []
    for lab in semantics.classify_labels(cand) if cand else []:
        code = semantics.type_of_name("", lab.text) if lab.role == "number" and lab.reason == "callout" else None
        if code and code.get("type") in ("stairs", "elevator"):
            for i in lab.ids:
                c = cand[i]
                c.id = first_id + len(out)
                out.append(c)
    return out


def _hidden_symbols(raw, rules, scale, geoms, box, selected, progress) -> List[CadGeometry]:
    """``cad_explode.kept_symbols`` of a drawing that shows no stair or lift symbol (a plan whose stair / lift
    layers were turned off), within the kept plan; nothing when it shows some or the user chose the layers."""
    from .cad_explode import kept_symbols

    if selected is not None or any(g.kind in ("stair", "elevator") for g in geoms):
        return []
    t0 = time.perf_counter()
    out = kept_symbols(raw.pieces, rules, scale, box if isinstance(box, tuple) else None)
    if out:
        n = sum(g.cls != "lift door" for g in out)
        progress.info(f"{n} stair/lift line(s) on hidden layers and {len(out) - n} of lift-named blocks kept as "
                      f"stair/lift evidence (not drawn; {time.perf_counter() - t0:.1f} s)")
    return out


def _sound_pieces(pieces: _Pieces, scale: float) -> _Pieces:
    """The pieces without those ``_unusable`` calls broken (NaN/inf or beyond 1e15 m): for the searches that
    read every layer (folding partitions, counters, stray walls, door swings), whose KD-trees and distances a
    1e308 coordinate of a damaged file would overflow. The same object when nothing is broken."""
    n = len(pieces.coords)
    drawn = [i for i in range(n) if len(pieces.coords[i])]  # an empty piece is sound; one would force the slow path
    bad = _unusable(pieces, drawn, scale)[0]
    if not bad.any():
        return pieces
    broken = {drawn[k] for k in np.flatnonzero(bad)}
    return pieces.select([i for i in range(n) if i not in broken])


def _unusable(pieces: _Pieces, idx: Sequence[int], scale: float) -> Tuple[np.ndarray, np.ndarray]:
    """Per piece of ``idx``, tested on all vertices at once: (broken: it holds a NaN/inf coordinate or one beyond
    1e15 m once scaled (a filled piece's all-NaN rows only separate its rings); overlong: its extent in x or y,
    finite vertices only, once scaled, exceeds MAX_ENTITY_M)."""
    coords = [pieces.coords[i] for i in idx]
    if not coords:
        return np.zeros(0, dtype=bool), np.zeros(0, dtype=bool)
    if not all(c.ndim == 2 and c.shape[1] == 2 and len(c) for c in coords):  # unusual arrays: one at a time
        broken, overlong = [], []
        for i, c in zip(idx, coords):
            sep = np.isnan(c).all(axis=1) if pieces.filled[i] else np.zeros(len(c), bool)
            v = c[~sep]
            broken.append(not bool(np.isfinite(v).all()) or abs(scale) * float(np.abs(v).max(initial=0.0)) > 1e15)
            overlong.append(c.ndim == 2 and c.shape[1] == 2 and len(c) > 0 and _extent(c) * abs(scale) > MAX_ENTITY_M)
        return np.array(broken, dtype=bool), np.array(overlong, dtype=bool)
    lens = np.fromiter((len(c) for c in coords), dtype=np.int64, count=len(coords))
    allc = np.concatenate(coords)
    owner = np.repeat(np.arange(len(coords)), lens)
    filled = np.fromiter((bool(pieces.filled[i]) for i in idx), dtype=bool, count=len(idx))
    with np.errstate(invalid="ignore", over="ignore"):
        sep = filled[owner] & np.isnan(allc).all(axis=1)
        # abs(scale) * max(|v|) > 1e15 of the whole piece <=> of one of its vertices (scaling is monotonic)
        bad = ~sep & (~np.isfinite(allc).all(axis=1) | (abs(scale) * np.abs(allc).max(axis=1) > 1e15))
        starts = np.concatenate(([0], np.cumsum(lens)[:-1]))
        fin = np.where(np.isfinite(allc), allc, np.nan)
        ext = np.nan_to_num(np.fmax.reduceat(fin, starts, axis=0) - np.fmin.reduceat(fin, starts, axis=0),
                            nan=0.0, posinf=0.0).max(axis=1)
    return np.bincount(owner[bad], minlength=len(coords)) > 0, ext * abs(scale) > MAX_ENTITY_M


# No part of a building, nor of a campus site plan, is one entity longer than this: a line of 10^9 m is a
# damaged coordinate or a stray (it would make plan finding sample it metre by metre, gigabytes)
MAX_ENTITY_M = 20_000.0


def _extent(c: np.ndarray) -> float:
    v = c[np.isfinite(c).all(axis=1)]
    return float(np.ptp(v, axis=0).max()) if len(v) else 0.0


def import_dxf(path: str, rules=None, layers: Optional[Sequence[str]] = None, units: Optional[str] = None,
               include_doors: bool = False, fallback_walls: bool = True, drop_door_swings: bool = True,
               plan=None, classify: bool = True, progress=None) -> CadDrawing:
    """Read a DXF or DWG (see ``_import``). A DWG whose decoded entities hold malformed data (a damaged
    file the reader decodes without complaint: wrong vertex arrays, impossible values) is reported as
    damaged with an InputError naming it, never as a raw numpy/Python error."""
    with _gc_paused():
        return _import_checked(path, rules, layers, units, include_doors, fallback_walls, drop_door_swings, plan,
                               classify, progress)


def _import_checked(path, rules, layers, units, include_doors, fallback_walls, drop_door_swings, plan, classify,
                    progress) -> CadDrawing:
    args = (path, rules, layers, units, include_doors, fallback_walls, drop_door_swings, plan, classify, progress)
    if not str(path).lower().endswith(".dwg"):
        return _import(*args)
    try:
        return _import(*args)
    except InputError:  # (an InputError is a ValueError) already says what is wrong
        raise
    except (ValueError, IndexError, OverflowError, ZeroDivisionError) as exc:
        raise InputError(f"'{os.path.basename(path)}' is a damaged DWG: its entities hold malformed data "
                         f"({type(exc).__name__}: {exc}). Open it in a CAD program (AUDIT / RECOVER) and save "
                         "it again, or export it as DXF") from None


def _folding_partitions(p, scale: float, sel, classes: Dict[str, int]) -> list:
    """``cad_classify.folding_partitions`` of the pieces (every layer), within the selected plan."""
    from .cad_classify import folding_partitions

    found = _in_plan(folding_partitions(p, scale), sel)
    if found:
        classes["folding partition"] = len(found)
    return found


def _counters(p, scale: float, rules, geoms, sel, infos) -> list:
    """``cad_classify.counters_from_pieces`` (counters standing wall to wall) and ``stray_wall_partitions``
    (partition walls on layers no rule names), within the selected plan: split lines for names only, like
    folding partitions; not counted in ``classes`` (nothing is left out for them)."""
    from .cad_classify import counters_from_pieces, stray_wall_partitions

    return _in_plan(counters_from_pieces(p, scale, rules, geoms) + stray_wall_partitions(p, infos, scale, rules, geoms),
                    sel)


def _in_plan(lines: list, sel) -> list:
    """The split lines whose middle lies in the selected plan's extent (all of them without a selection)."""
    if sel is None:
        return lines
    x0, y0, x1, y1 = sel.extent
    return [g for g in lines if x0 <= g.coords[:, 0].mean() <= x1 and y0 <= g.coords[:, 1].mean() <= y1]


def _import(path, rules, layers, units, include_doors, fallback_walls, drop_door_swings, plan, classify,
            progress) -> CadDrawing:
    """Read a DXF and return the structural geometry (metres, CAD frame) and every visible text.

    ``rules``: LayerRules, a JSON path, or None for the defaults. ``layers``: explicit layer names
    (case-insensitive) that override the rules. ``units``: "mm", "cm", "m", "inch", "feet" or
    None/"" for automatic. ``include_doors``: also keep door layers (doorways get closed).
    ``fallback_walls``: when no layer matches a wall keyword, keep every layer that no rule excludes
    (generic names such as "Pluma 8" or "4") as walls, with a warning. ``drop_door_swings``: unless
    doors are included, also leave out door swings drawn on other layers (a quarter arc of 0.5-1.6 m
    radius and the leaf hinged at its centre), as found in mixed "doors windows" layers and blocks.
    ``plan``: which group of a whole sheet to keep (cad_sheet): None = the main plan (largest wall
    mass), an index into ``CadDrawing.plans``, or an extent (xmin, ymin, xmax, ymax) in metres (also as
    a string "xmin,ymin,xmax,ymax"). ``classify``: classify entities by block names and geometry
    (cad_classify: door and furniture blocks, door swings -> ``CadDrawing.doors``, pattern hatches,
    free-standing furniture on layer "0"); ``CadDrawing.classes`` counts the classes.
    Raises InputError for anything the user can fix.
    """
    progress = ensure(progress)
    rules = _resolve_rules(rules)
    forced = normalize_unit(units)
    base = os.path.basename(path)
    progress.step(0, f"reading {base}")
    t0 = time.perf_counter()
    timings: Dict[str, float] = {}
    doc, repairs = _read_doc(path, progress)
    timings["read"] = time.perf_counter() - t0
    for r in repairs:
        progress.warning(r)
    header = _header_unit(doc)
    guess = forced or (header if header in UNIT_SCALES else "m")
    tol_du = CHORD_TOL / UNIT_SCALES[guess]
    progress.step(15, "exploding blocks and flattening curves")
    raw = _explode(path, tol_du, progress.sub(15, 70), doc=doc, repairs=repairs)
    if len(doc.modelspace()) == 0:
        raise InputError(f"'{base}' is an empty drawing: its model space has no entities"
                         + (" (the plan may be in a paper-space layout; copy it to model space)"
                            if any(len(l) for l in doc.layouts if l.name != "Model") else ""))
    selected = None
    if layers:
        names = [str(l).strip() for l in layers if str(l).strip()]
        known = {k.lower(): k for k in raw.states}
        known.update({k.lower(): k for k in raw.pieces.layer})
        missing = [n for n in names if n.lower() not in known]
        if missing:
            raise InputError(f"layer(s) {missing} do not exist in '{base}'; its layers are: "
                             f"{', '.join(sorted(known.values(), key=str.lower))}")
        selected = {}
        for n in names:
            kind, _ = rules.classify(known[n.lower()])
            selected[n.lower()] = kind if kind not in (None, "reference") else "wall"
    infos = _layer_infos(raw, rules, selected)
    xrefs = sorted(set(raw.pieces.xrefs))
    warnings = list(raw.warnings)
    if selected is None and fallback_walls:
        msg = _fallback_walls(infos, raw)
        if msg:
            warnings.append(msg)
            progress.warning(msg)
    idx = _kept_mask(raw, infos, rules, include_doors, selected is not None)
    if not idx:
        if xrefs:
            raise InputError(f"'{base}': " + _xref_message(xrefs))
        raise InputError(_nothing_kept_message(path, infos, rules, layers))
    if xrefs:
        warnings.append(_xref_message(xrefs))
    # ---- units
    coords = [raw.pieces.coords[i] for i in idx]
    if forced:
        unit, msg = forced, None
    else:
        # the unit only has to make the size plausible (5-500 m): a coarse, outlier-proof estimate
        unit, msg = choose_unit(_percentile_size(coords, UNIT_SIZE_PERCENTILES), header)
    if msg:
        warnings.append(msg)
        progress.warning(msg)
    scale = UNIT_SCALES[unit]
    if CHORD_TOL / scale < raw.tol * 0.999:  # curves were flattened too coarsely for this unit: redo
        progress.step(70, f"flattening again for {unit}")
        raw = _explode(path, CHORD_TOL / scale, progress.sub(70, 85), doc=doc, repairs=repairs)
        infos = _layer_infos(raw, rules, selected)
        if selected is None and fallback_walls:
            _fallback_walls(infos, raw)
        idx = _kept_mask(raw, infos, rules, include_doors, selected is not None)
    if classify and not include_doors:  # door layers too: their swings become door hints, then they go
        idx = _kept_mask(raw, infos, rules, True, selected is not None)
    timings["explode"] = time.perf_counter() - t0 - timings["read"]
    progress.step(85, "converting to metres")
    p = raw.pieces
    geoms = []
    chains = []
    nonfinite = 0
    dashed_was: Dict[int, str] = {}  # dashed lines on wall layers (projections) -> their layer's kind
    idx = [i for i in idx if len(p.coords[i]) >= 2 or p.filled[i]]
    bad, too_long = _unusable(p, idx, scale)
    overlong = 0
    inner: Dict[str, str] = {}  # block chain -> its innermost block (a chain repeats for every piece)
    for i, broken, long_ in zip(idx, bad, too_long):
        c = p.coords[i]
        if broken:
            # NaN/inf, or a coordinate beyond any building (1e15 m) that overflows downstream
            nonfinite += 1
            continue
        if long_:
            overlong += 1
            continue
        chain = p.block[i]
        block = inner.get(chain)
        if block is None:
            block = inner[chain] = innermost_block(chain)
        geoms.append(CadGeometry(layer=p.layer[i], kind=infos[p.layer[i]].kind, coords=c * scale,
                                 closed=p.closed[i], filled=p.filled[i], width=p.width[i] * scale,
                                 entity=p.etype[i], block=block))
        chains.append(p.block[i])
        if is_projection_line(geoms[-1], p.dashed[i] if i < len(p.dashed) else False):
            dashed_was[len(geoms) - 1] = geoms[-1].kind
            geoms[-1].kind = "boundary"  # dashed on a wall layer: a projection, never a wall (swings still found)
    if overlong:
        msg = (f"left out {overlong} entities longer than {MAX_ENTITY_M / 1000:.0f} km (no part of a building is: a "
               "stray or damaged entity); check the drawing's units and AUDIT it in CAD")
        warnings.append(msg)
        progress.warning(msg)
    if nonfinite:
        msg = (f"left out {nonfinite} entities with coordinates that are not finite numbers (NaN or infinite, "
               "a damaged file or a broken block scale); check the drawing with AUDIT in CAD")
        warnings.append(msg)
        progress.warning(msg)
    n_main = len(geoms)
    if classify and not include_doors and drop_door_swings and selected is None:
        geoms.extend(swing_candidates(p, infos, scale))  # arcs on layers no rule names: door swings only
    texts = [CadText(x=t[0] * scale, y=t[1] * scale, text=t[2], height=t[3] * scale, rotation=t[4],
                     layer=t[5], entity=t[6], block=innermost_block(t[7]), tag=t[8])
             for t in p.texts if math.isfinite(t[0] * scale) and math.isfinite(t[1] * scale)]
    keep_void_edges(geoms, texts, dashed_was)  # a dashed outline around 'void' is the edge of a floor opening
    doors: List[DoorHint] = []
    classes: Dict[str, int] = {}
    t1 = time.perf_counter()
    if classify:
        progress.step(88, "classifying entities (door and furniture blocks, door swings, hatches)")
        weak = {name for name, info in infos.items()
                if info.kind is not None and (info.rule.startswith("fallback") or info.rule.startswith("preserve"))}
        keep, classes, doors = classify_entities(geoms, chains, rules, include_doors, weak, drop_door_swings,
                                                 aux_from=n_main, progress=progress)
        gone = len(geoms) - int(keep.sum())
        geoms = [g for g, k in zip(geoms, keep) if k]
        if gone:
            progress.info("left out " + ", ".join(f"{v} {k}" for k, v in sorted(classes.items())
                                                  if k in ("door", "furniture", "hatch") and v)
                          + " entities found by block name or shape (doorways stay open; set include_doors "
                          f"to close them); {len(doors)} doorways found")
    geoms = [g for g in geoms if g.kind != AUX_KIND]
    if not include_doors and drop_door_swings and not classify:
        swings = set(find_door_swings(geoms))
        geoms = [g for k, g in enumerate(geoms) if k not in swings]
    geoms, projections = split_projection_lines(geoms)
    classes.pop("boundary", None)
    if projections:
        classes["projection"] = len(projections)
    timings["classify"] = time.perf_counter() - t1
    t1 = time.perf_counter()
    progress.step(93, "finding the plan(s) on the sheet")
    plans, gkeep, tkeep, n_frames = find_plans(geoms, texts, rules, plan)
    timings["plans"] = time.perf_counter() - t1
    if n_frames:
        classes["frame"] = n_frames
    sel = next(pl for pl in plans if pl.selected) if any(pl.selected for pl in plans) else None
    real = [pl for pl in plans if pl.kind != "other"]
    if len(real) > 1 or plan is not None:
        msg = (f"the sheet holds {len(real)} plan-like group(s); kept "
               + (f"[{sel.index}] {sel.kind}{' ' + repr(sel.title) if sel.title else ''}" if sel else "the PLAN extent")
               + ". " + describe_plans(plans) + " Give PLAN=<index> or an extent to take another")
        progress.info(msg)
    geoms = [g for g, k in zip(geoms, gkeep) if k]
    marks = level_marks(geoms)
    if any(marks):  # spot-level symbols (NPT, FFL, 标高 blocks): annotation, never walls
        classes["level mark"] = int(sum(marks))
        geoms = [g for g, m in zip(geoms, marks) if not m]
    texts = [t for t, k in zip(texts, tkeep) if k]
    for k, t in enumerate(texts):
        t.id = k
    box = sel.extent if sel is not None else parse_plan(plan)
    hidden = _hidden_texts(p.hidden_texts, scale, box if isinstance(box, tuple) else None, len(texts))
    hidden += _callouts_beside_plan(p.hidden_texts, scale, box if isinstance(box, tuple) else None,
                                    len(texts) + len(hidden))
    if sel is not None:
        x0, y0, x1, y1 = sel.extent
        doors = [d for d in doors if x0 - 1 <= (d.x0 + d.x1) / 2 <= x1 + 1 and y0 - 1 <= (d.y0 + d.y1) / 2 <= y1 + 1]
    boundary = (boundary_evidence(p, infos, scale) if selected is None else []) + projections
    if sel is not None and boundary:
        m = 4.0  # metres (rasterize.BOUNDARY_REACH): a corridor closed by a projection line lies beyond the walls
        x0, y0, x1, y1 = sel.extent
        boundary = [g for g in boundary if g.coords[:, 0].max() >= x0 - m and g.coords[:, 0].min() <= x1 + m
                    and g.coords[:, 1].max() >= y0 - m and g.coords[:, 1].min() <= y1 + m]
    sound = _sound_pieces(p, scale) if selected is None else p
    partitions = _folding_partitions(sound, scale, sel, classes) if selected is None else []
    hidden_syms = _hidden_symbols(raw, rules, scale, geoms, box, selected, progress)
    if selected is None and classify:  # counters closing a space behind them, walls on unnamed layers (task T8)
        partitions += _counters(sound, scale, rules, geoms, sel, infos)
    kept_layers = sorted({g.layer for g in geoms})
    progress.info("CAD import stages: " + ", ".join(f"{k} {v:.1f} s" for k, v in timings.items()))
    progress.step(100, f"{len(geoms)} geometries on {len(kept_layers)} layers, {len(texts)} texts, unit {unit}"
                  + (f", {len(doors)} doorways" if doors else ""))
    return CadDrawing(path=path, geometries=geoms, texts=texts, layers=infos, unit_name=unit, unit_scale=scale,
                      header_unit=header, warnings=warnings, repairs=list(repairs), doors=doors, plans=plans,
                      classes=classes, timings=timings, hidden_texts=hidden, boundary=boundary,
                      undecoded=dict(getattr(doc, "undecoded", {})),  # DWG: types the reader cannot decode
                      partitions=partitions, hidden_symbols=hidden_syms)
