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

import math
import os
import re
from dataclasses import dataclass, field
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

import numpy as np

from .errors import InputError
from .layer_rules import LayerRules, default_rules, load_rules
from .model import CadDrawing, CadGeometry, CadText, LayerInfo
from .progress import ensure

# ------------------------------------------------------------------------------------------ units
UNIT_SCALES = {"mm": 0.001, "cm": 0.01, "dm": 0.1, "m": 1.0, "km": 1000.0, "inch": 0.0254, "feet": 0.3048}
_INSUNITS = {0: "unitless", 1: "inch", 2: "feet", 4: "mm", 5: "cm", 6: "m", 7: "km", 14: "dm"}
_UNIT_ALIASES = {"millimetre": "mm", "millimeter": "mm", "millimetres": "mm", "millimeters": "mm",
                 "centimetre": "cm", "centimeter": "cm", "centimetres": "cm", "centimeters": "cm",
                 "metre": "m", "meter": "m", "metres": "m", "meters": "m", "in": "inch", "inches": "inch",
                 "ft": "feet", "foot": "feet", "auto": "", "": ""}
PLAUSIBLE_SIZE = (5.0, 500.0)  # metres across a floor
TYPICAL_SIZE = 40.0  # metres; ties between plausible units go to the one closest (log scale) to this
CHORD_TOL = 0.01  # metres
MAX_SEGMENTS_PER_TURN = 1024
# entities a drawing may explode into (nested blocks and MINSERT arrays multiply): a real floor explodes
# into 10^4-10^5; a block bomb or 10^6 copies of one line stop with advice before filling the memory
MAX_EXPLODED = 1_000_000

SKIP_TYPES = {"DIMENSION", "ARC_DIMENSION", "LARGE_RADIAL_DIMENSION", "LEADER", "MLEADER", "MULTILEADER",
              "TOLERANCE", "POINT", "VIEWPORT", "IMAGE", "WIPEOUT", "ATTDEF", "XLINE", "RAY", "REGION",
              "3DSOLID", "BODY", "SURFACE", "OLE2FRAME", "OLEFRAME", "UNDERLAY", "PDFUNDERLAY",
              "DWFUNDERLAY", "DGNUNDERLAY", "ACAD_TABLE", "ACAD_PROXY_ENTITY", "SEQEND", "VERTEX",
              "SHAPE", "MESH", "LIGHT", "SUN", "HELIX"}
TEXT_TYPES = {"TEXT", "MTEXT", "ATTRIB"}


def normalize_unit(units: Optional[str]) -> str:
    if units is None:
        return ""
    u = str(units).strip().lower()
    u = _UNIT_ALIASES.get(u, u)
    if u and u not in UNIT_SCALES:
        raise InputError(f"unknown unit '{units}'; use one of {', '.join(UNIT_SCALES)} (or leave empty for automatic)")
    return u


# ------------------------------------------------------------------------------------------ flattening
def _n_segments(radius: float, sweep: float, tol: float) -> int:
    """Segments so that the sagitta of each chord is <= tol."""
    sweep = abs(sweep)
    if radius <= 0 or sweep <= 0:
        return 1
    if tol >= radius:
        step = math.pi / 2
    else:
        step = 2.0 * math.acos(1.0 - tol / radius)
    step = max(step, 2 * math.pi / MAX_SEGMENTS_PER_TURN)
    return max(2, min(int(math.ceil(sweep / step)), int(MAX_SEGMENTS_PER_TURN * sweep / (2 * math.pi)) + 2))


def _arc_points(cx, cy, r, a0, a1, tol, full=False):
    """Points of a CCW arc from angle a0 to a1 (radians)."""
    if full:
        sweep = 2 * math.pi
    else:
        sweep = (a1 - a0) % (2 * math.pi)
        if sweep < 1e-12:
            sweep = 2 * math.pi
    n = _n_segments(r, sweep, tol)
    t = a0 + np.linspace(0.0, sweep, n + 1)
    pts = np.column_stack((cx + r * np.cos(t), cy + r * np.sin(t)))
    if full:
        pts = pts[:-1]
    return pts


def _bulge_polyline(xy: np.ndarray, bulges: np.ndarray, closed: bool, tol: float) -> np.ndarray:
    """Flatten a polyline with bulges (xy: (N, 2), bulges: (N,))."""
    n = len(xy)
    if n == 0 or not np.any(bulges):
        return xy
    out = []
    last = n if closed else n - 1
    for i in range(last):
        p0 = xy[i]
        p1 = xy[(i + 1) % n]
        b = bulges[i]
        out.append(p0[None, :])
        if b == 0.0:
            continue
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        chord = math.hypot(dx, dy)
        if chord < 1e-12:
            continue
        theta = 4.0 * math.atan(b)  # included angle, signed (positive = CCW)
        r = chord / (2.0 * math.sin(abs(theta) / 2.0))
        # centre: from the chord midpoint, perpendicular, at distance d
        d = r * math.cos(theta / 2.0) * (1.0 if b > 0 else -1.0)
        mx, my = (p0[0] + p1[0]) / 2.0, (p0[1] + p1[1]) / 2.0
        ux, uy = -dy / chord, dx / chord  # left normal
        cx, cy = mx + ux * d, my + uy * d
        a0 = math.atan2(p0[1] - cy, p0[0] - cx)
        m = _n_segments(r, abs(theta), tol)
        t = a0 + np.linspace(0.0, theta, m + 1)[1:-1]
        if len(t):
            out.append(np.column_stack((cx + r * np.cos(t), cy + r * np.sin(t))))
    if not closed:
        out.append(xy[-1][None, :])
    return np.concatenate(out, axis=0)


def _ocs_to_wcs(pts: np.ndarray, extrusion) -> np.ndarray:
    ex = tuple(extrusion) if extrusion is not None else (0.0, 0.0, 1.0)
    if abs(ex[0]) < 1e-9 and abs(ex[1]) < 1e-9:
        if ex[2] >= 0:
            return pts
        out = pts.copy()
        out[:, 0] = -out[:, 0]
        return out
    from ezdxf.math import OCS

    ocs = OCS(ex)
    p3 = [(float(x), float(y), 0.0) for x, y in pts]
    return np.array([(v.x, v.y) for v in ocs.points_to_wcs(p3)], dtype=np.float64)


def _extrusion(e):
    try:
        return e.dxf.extrusion if e.dxf.hasattr("extrusion") else None
    except Exception:  # pragma: no cover - defensive
        return None


def _edge_points(edge, tol: float) -> Optional[np.ndarray]:
    et = type(edge).__name__
    if et == "LineEdge":
        return np.array(((edge.start[0], edge.start[1]), (edge.end[0], edge.end[1])), dtype=np.float64)
    if et == "ArcEdge":  # ezdxf gives the angles in counter-clockwise orientation
        return _arc_points(edge.center[0], edge.center[1], float(edge.radius), math.radians(edge.start_angle),
                           math.radians(edge.end_angle), tol,
                           full=abs(abs(edge.end_angle - edge.start_angle) - 360.0) < 1e-9)
    tool = edge.construction_tool()
    if et == "EllipseEdge":
        return np.array([(v.x, v.y) for v in tool.flattening(tol)], dtype=np.float64)
    if et == "SplineEdge":
        return np.array([(v.x, v.y) for v in tool.flattening(tol)], dtype=np.float64)
    return None


def _chain(pieces: List[np.ndarray], eps: float) -> List[np.ndarray]:
    """Join edge polylines end to start (reversing where needed) into closed rings."""
    rings = []
    todo = [p for p in pieces if p is not None and len(p) >= 2]
    while todo:
        cur = [todo.pop(0)]
        start = cur[0][0]
        end = cur[0][-1]
        while todo and np.hypot(*(end - start)) > eps:
            heads = np.array([p[0] for p in todo])
            tails = np.array([p[-1] for p in todo])
            dh = np.hypot(heads[:, 0] - end[0], heads[:, 1] - end[1])
            dt = np.hypot(tails[:, 0] - end[0], tails[:, 1] - end[1])
            i, j = int(np.argmin(dh)), int(np.argmin(dt))
            if dh[i] <= eps and dh[i] <= dt[j]:
                nxt = todo.pop(i)
            elif dt[j] <= eps:
                nxt = todo.pop(j)[::-1]
            else:
                break
            cur.append(nxt[1:])
            end = nxt[-1]
        ring = np.concatenate(cur, axis=0)
        if len(ring) >= 3:
            rings.append(ring)
    return rings


def _boundary_rings(bpath, tol: float) -> List[np.ndarray]:
    """Closed rings of one HATCH boundary path (edges chained by their end points)."""
    if type(bpath).__name__ == "PolylinePath":
        v = np.array([(p[0], p[1], p[2] if len(p) > 2 else 0.0) for p in bpath.vertices], dtype=np.float64)
        if len(v) < 2:
            return []
        return [_bulge_polyline(v[:, :2], v[:, 2], True, tol)]
    pieces = [_edge_points(ed, tol) for ed in getattr(bpath, "edges", [])]
    pieces = [p for p in pieces if p is not None and len(p) >= 2]
    if not pieces:
        return []
    allp = np.concatenate(pieces)
    eps = max(1e-6 * float(np.max(np.abs(allp))), tol * 0.5)
    return _chain(pieces, eps)


# ------------------------------------------------------------------------------------------ containers
@dataclass
class _Pieces:
    """Flattened geometry of one block (or of the model space), in the block's coordinates."""

    coords: List[np.ndarray] = field(default_factory=list)
    layer: List[str] = field(default_factory=list)
    etype: List[str] = field(default_factory=list)
    closed: List[bool] = field(default_factory=list)
    filled: List[bool] = field(default_factory=list)
    width: List[float] = field(default_factory=list)
    texts: List[tuple] = field(default_factory=list)  # (x, y, text, height, rotation_deg, layer, etype)
    counts: List[tuple] = field(default_factory=list)  # (layer, etype, n) for entities without geometry
    xrefs: List[str] = field(default_factory=list)

    def add(self, coords, layer, etype, closed=False, filled=False, width=0.0):
        self.coords.append(coords)
        self.layer.append(layer)
        self.etype.append(etype)
        self.closed.append(closed)
        self.filled.append(filled)
        self.width.append(width)

    def __len__(self):
        return len(self.coords)


def _transform_pieces(src: _Pieces, A: np.ndarray, t: np.ndarray, layer: str, dst: _Pieces,
                      layer_ok) -> None:
    """Append ``src`` transformed by x' = A @ x + t to ``dst``; layer "0" takes ``layer``."""
    n = len(src.coords)
    if n:
        lens = np.fromiter((len(c) for c in src.coords), dtype=np.int64, count=n)
        allc = np.concatenate(src.coords, axis=0) @ A.T + t
        splits = np.split(allc, np.cumsum(lens)[:-1])
        s = math.sqrt(abs(float(np.linalg.det(A))))
        for i in range(n):
            lay = src.layer[i]
            if lay == "0":
                lay = layer
            if not layer_ok(lay, src.etype[i]):
                continue
            w = src.width[i]
            dst.add(splits[i], lay, src.etype[i], src.closed[i], src.filled[i], w * s if w else 0.0)
    if src.texts:
        s = math.sqrt(abs(float(np.linalg.det(A))))
        rot = math.degrees(math.atan2(A[1, 0], A[0, 0]))
        for (x, y, text, h, r, lay, et) in src.texts:
            if lay == "0":
                lay = layer
            if not layer_ok(lay, et):
                continue
            p = A @ np.array((x, y)) + t
            dst.texts.append((float(p[0]), float(p[1]), text, h * s, (r + rot) % 360.0, lay, et))
    for (lay, et, k) in src.counts:
        dst.counts.append((layer if lay == "0" else lay, et, k))
    dst.xrefs.extend(src.xrefs)


def _minsert_offsets(e, rows: int, cols: int, ex, name: str) -> np.ndarray:
    """WCS translations (x, y) of the copies of a MINSERT grid, as ezdxf's ``multi_insert`` places them
    (offsets in the insert's OCS, rotated with the insert, not scaled; coinciding copies once), without
    building one virtual INSERT per copy (10^6 of them took a minute)."""
    cs = float(e.dxf.get("column_spacing", 0.0) or 0.0)
    rs = float(e.dxf.get("row_spacing", 0.0) or 0.0)
    ncol = cols if cs != 0.0 else 1
    nrow = rows if rs != 0.0 else 1
    if nrow * ncol > MAX_EXPLODED:  # stop before allocating the offsets
        ex._spend(name, nrow * ncol, 1)
    r, c = np.meshgrid(np.arange(nrow, dtype=np.float64), np.arange(ncol, dtype=np.float64), indexing="ij")
    off = np.column_stack([c.ravel() * cs, r.ravel() * rs])  # row-major, like multi_insert
    rot = math.radians(float(e.dxf.get("rotation", 0.0) or 0.0))
    if rot:
        cr, sr = math.cos(rot), math.sin(rot)
        off = off @ np.array(((cr, sr), (-sr, cr)))
    ux, uy = _ocs_axes_2d(_extrusion(e))
    return off[:, :1] * ux + off[:, 1:2] * uy


def _ocs_axes_2d(extrusion):
    """x and y (of WCS) of the OCS axes ux, uy for an extrusion vector."""
    try:
        from ezdxf.math import OCS

        ocs = OCS(extrusion)
        ux, uy = ocs.to_wcs((1.0, 0.0, 0.0)), ocs.to_wcs((0.0, 1.0, 0.0))
        return np.array((ux[0], ux[1]), dtype=np.float64), np.array((uy[0], uy[1]), dtype=np.float64)
    except Exception:
        return np.array((1.0, 0.0)), np.array((0.0, 1.0))


# ------------------------------------------------------------------------------------------ text
_MTEXT_FALLBACK = re.compile(r"\\[A-Za-z][^;\\{}]*;|\\[PpNn~]|[{}]")


def _mtext_plain(e) -> str:
    try:
        txt = e.plain_text()
    except Exception:
        txt = _MTEXT_FALLBACK.sub(" ", e.text)
    return " ".join(str(txt).split())


def _text_plain(e) -> str:
    try:
        txt = e.plain_text()
    except Exception:
        txt = e.dxf.text
    return " ".join(str(txt).split())


# ------------------------------------------------------------------------------------------ exploder
class _Exploder:
    def __init__(self, doc, tol: float, visible_layer, progress=None, total=0):
        self.doc = doc
        self.tol = tol
        self.visible = visible_layer  # name -> bool (not frozen / off)
        self.cache: Dict[str, _Pieces] = {}
        self.stack: List[str] = []
        self.progress = progress
        self.total = max(1, total)
        self.done = 0
        self.warnings: List[str] = []
        self._warned = set()
        self.produced = 0  # entities added by exploding INSERTs (see MAX_EXPLODED)
        self.attribs_per_copy = True  # ezdxf shifts a MINSERT's attributes to every copy

    def _warn_once(self, key, msg):
        if key not in self._warned:
            self._warned.add(key)
            self.warnings.append(msg)

    # layer test used while flattening a block: entities on invisible non-"0" layers are dropped early
    def _keep_layer(self, layer: str) -> bool:
        return layer == "0" or self.visible(layer)

    def block(self, name: str, tol: Optional[float] = None) -> _Pieces:
        """Flattened content of a block in its own coordinates, curves at chord error ``tol`` (block
        units; defaults to the current tolerance), cached per (name, tol)."""
        tol = self.tol if tol is None else tol
        key = (name, tol)
        got = self.cache.get(key)
        if got is not None:
            return got
        if name in self.stack:
            self._warn_once(("cycle", name), f"block '{name}' contains itself; the recursive reference was skipped")
            return _Pieces()
        blk = self.doc.blocks.get(name)
        out = _Pieces()
        if blk is None:
            self._warn_once(("missing", name), f"block '{name}' is referenced but not defined; skipped")
            self.cache[key] = out
            return out
        if blk.block.is_xref:
            path = blk.block.dxf.get("xref_path", "") or name
            out.xrefs.append(path)
            self.cache[key] = out
            return out
        self.stack.append(name)
        saved, self.tol = self.tol, tol
        try:
            self.entities(blk, out, top=False)
        finally:
            self.stack.pop()
            self.tol = saved
        self.cache[key] = out
        return out

    def entities(self, entities: Iterable, out: _Pieces, top: bool) -> None:
        for e in entities:
            if top:
                self.done += 1
                if self.progress is not None and self.done % 2000 == 0:
                    self.progress.step(100.0 * self.done / self.total)
            try:
                self.entity(e, out)
            except InputError:
                raise
            except Exception as exc:  # a broken entity must not stop the import
                et = e.dxftype() if hasattr(e, "dxftype") else type(e).__name__
                self._warn_once(("bad", et), f"skipped a broken {et} entity ({type(exc).__name__}: {exc})")

    def entity(self, e, out: _Pieces) -> None:
        et = e.dxftype()
        layer = e.dxf.get("layer", "0") or "0"
        if not self._keep_layer(layer):
            return
        tol = self.tol
        if et == "LINE":
            s, t = e.dxf.start, e.dxf.end
            out.add(np.array(((s[0], s[1]), (t[0], t[1])), dtype=np.float64), layer, et)
        elif et == "LWPOLYLINE":
            pts = np.array(e.get_points("xyseb"), dtype=np.float64).reshape(-1, 5)
            if len(pts) == 0:
                return
            closed = bool(e.closed)
            xy = _bulge_polyline(pts[:, :2], pts[:, 4], closed, tol)
            xy = _ocs_to_wcs(xy, _extrusion(e))
            w = float(e.dxf.get("const_width", 0.0) or 0.0)
            if w == 0.0:
                w = float(np.max(pts[:, 2:4])) if len(pts) else 0.0
            out.add(xy, layer, et, closed, False, abs(w))
        elif et == "POLYLINE":
            self._polyline(e, layer, out)
        elif et == "ARC":
            c = e.dxf.center
            r = float(e.dxf.radius)
            xy = _arc_points(c[0], c[1], r, math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle), tol)
            out.add(_ocs_to_wcs(xy, _extrusion(e)), layer, et)
        elif et == "CIRCLE":
            c = e.dxf.center
            xy = _arc_points(c[0], c[1], float(e.dxf.radius), 0.0, 0.0, tol, full=True)
            out.add(_ocs_to_wcs(xy, _extrusion(e)), layer, et, True)
        elif et == "ELLIPSE":
            self._ellipse(e, layer, out)
        elif et == "SPLINE":
            try:
                xy = np.array([(v.x, v.y) for v in e.flattening(tol)], dtype=np.float64)
            except Exception:
                xy = np.array([(v[0], v[1]) for v in e.control_points], dtype=np.float64)
            if len(xy) >= 2:
                out.add(xy, layer, et, bool(e.closed))
        elif et in ("SOLID", "TRACE"):
            v = [e.dxf.get(f"vtx{i}") for i in range(4)]
            v = [p for p in v if p is not None]
            if len(v) == 4:
                quad = [v[0], v[1], v[3], v[2]]
                if (v[3][0], v[3][1]) == (v[2][0], v[2][1]):
                    quad = [v[0], v[1], v[2]]
            else:
                quad = v
            xy = _ocs_to_wcs(np.array([(p[0], p[1]) for p in quad], dtype=np.float64), _extrusion(e))
            out.add(xy, layer, et, True, True)
        elif et == "3DFACE":
            v = [e.dxf.get(f"vtx{i}") for i in range(4)]
            xy = np.array([(p[0], p[1]) for p in v if p is not None], dtype=np.float64)
            out.add(xy, layer, et, True, False)
        elif et == "HATCH":
            self._hatch(e, layer, out)
        elif et == "INSERT":
            self._insert(e, layer, out)
        elif et == "TEXT":
            txt = _text_plain(e)
            if txt:
                p = e.dxf.insert
                if (e.dxf.get("halign", 0) or e.dxf.get("valign", 0)) and e.dxf.hasattr("align_point"):
                    p = e.dxf.align_point
                xy = _ocs_to_wcs(np.array([[p[0], p[1]]]), _extrusion(e))[0]
                out.texts.append((float(xy[0]), float(xy[1]), txt, float(e.dxf.get("height", 1.0)),
                                  float(e.dxf.get("rotation", 0.0)), layer, et))
        elif et == "MTEXT":
            txt = _mtext_plain(e)
            if txt:
                p = e.dxf.insert
                try:
                    rot = float(e.get_rotation())
                except Exception:
                    rot = float(e.dxf.get("rotation", 0.0))
                out.texts.append((float(p[0]), float(p[1]), txt, float(e.dxf.get("char_height", 1.0)), rot, layer, et))
        elif et in SKIP_TYPES:
            out.counts.append((layer, et, 1))
        elif et in ("MLINE",):
            for v in e.virtual_entities():
                self.entity(v, out)
        else:
            out.counts.append((layer, et, 1))
            self._warn_once(("type", et), f"entity type {et} is not supported and was ignored")

    def _polyline(self, e, layer, out):
        mode = e.get_mode()
        if mode in ("AcDb2dPolyline", "AcDb3dPolyline"):
            verts = list(e.vertices)
            if not verts:
                return
            pts = np.array([(v.dxf.location[0], v.dxf.location[1], v.dxf.get("bulge", 0.0) or 0.0,
                             v.dxf.get("start_width", 0.0) or 0.0, v.dxf.get("end_width", 0.0) or 0.0)
                            for v in verts], dtype=np.float64)
            closed = bool(e.is_closed)
            if mode == "AcDb2dPolyline":
                xy = _bulge_polyline(pts[:, :2], pts[:, 2], closed, self.tol)
                xy = _ocs_to_wcs(xy, _extrusion(e))
                w = float(e.dxf.get("default_start_width", 0.0) or 0.0)
                w = max(w, float(np.max(pts[:, 3:5])))
            else:
                xy, w = pts[:, :2], 0.0
            out.add(xy, layer, "POLYLINE", closed, False, abs(w))
        else:  # polyface / polygon mesh: outlines of the faces
            for v in e.virtual_entities():
                self.entity(v, out)

    def _ellipse(self, e, layer, out):
        c = np.array(e.dxf.center, dtype=np.float64)[:2]
        major = np.array(e.dxf.major_axis, dtype=np.float64)
        ex = e.dxf.get("extrusion", (0, 0, 1))
        ratio = float(e.dxf.ratio)
        a = float(np.linalg.norm(major[:2])) if abs(major[2]) < 1e-9 else float(np.linalg.norm(major))
        p0, p1 = float(e.dxf.start_param), float(e.dxf.end_param)
        sweep = (p1 - p0) % (2 * math.pi)
        full = sweep < 1e-9 or abs(sweep - 2 * math.pi) < 1e-9
        if full:
            sweep = 2 * math.pi
        if abs(ex[0]) > 1e-9 or abs(ex[1]) > 1e-9 or abs(major[2]) > 1e-9:
            xy = np.array([(v.x, v.y) for v in e.flattening(self.tol)], dtype=np.float64)
        else:
            n = _n_segments(a, sweep, self.tol)
            t = p0 + np.linspace(0.0, sweep, n + 1)
            if full:
                t = t[:-1]
            mj = major[:2]
            mn = np.array((-mj[1], mj[0])) * ratio
            if ex[2] < 0:
                mn = -mn
            xy = c[None, :] + np.cos(t)[:, None] * mj[None, :] + np.sin(t)[:, None] * mn[None, :]
        out.add(xy, layer, "ELLIPSE", full)

    def _hatch(self, e, layer, out):
        solid = bool(e.dxf.get("solid_fill", 0))
        rings = []
        for bpath in e.paths.paths:
            try:
                rings.extend(_boundary_rings(bpath, self.tol))
            except Exception:
                continue
        ex = _extrusion(e)
        rings = [_ocs_to_wcs(r, ex) for r in rings if len(r) >= 3]
        if not rings:
            return
        if solid:
            if len(rings) == 1:
                out.add(rings[0], layer, "HATCH", True, True)
            else:
                sep = np.full((1, 2), np.nan)
                parts = []
                for r in rings:
                    parts.extend((r, sep))
                out.add(np.concatenate(parts[:-1], axis=0), layer, "HATCH", True, True)
        else:
            for r in rings:
                out.add(r, layer, "HATCH", True, False)

    def _spend(self, name: str, copies: int, pieces: int) -> None:
        """Count the entities an INSERT adds and stop before a block bomb or a giant MINSERT array
        (nested blocks multiply) allocates them."""
        self.produced += copies * pieces
        if self.produced > MAX_EXPLODED:
            raise InputError(
                f"exploding the blocks gives more than {MAX_EXPLODED:,} entities (the last INSERT: block '{name}', "
                f"{copies:,} {'copy' if copies == 1 else 'copies'} of {pieces:,} entities): the drawing nests blocks "
                "too deeply, repeats one entity massively or holds a huge MINSERT array; purge or explode those "
                "blocks in CAD (OVERKILL removes duplicates) and export again")

    def _insert(self, e, layer, out):
        name = e.dxf.name
        if layer != "0" and not self.visible(layer, frozen_only=True):
            return
        rows = int(e.dxf.get("row_count", 1) or 1)
        cols = int(e.dxf.get("column_count", 1) or 1)
        offsets = np.zeros((1, 2))
        if rows > 1 or cols > 1:
            offsets = _minsert_offsets(e, rows, cols, self, name)
        m = e.matrix44()
        A = np.array(((m[0, 0], m[1, 0]), (m[0, 1], m[1, 1])), dtype=np.float64)
        t = np.array((m[3, 0], m[3, 1]), dtype=np.float64)
        # an enlarged block needs a finer tolerance in its own units (powers of 2 keep the cache small)
        s = float(np.linalg.norm(A, 2))
        tol = self.tol / (2.0 ** math.ceil(math.log2(s))) if s > 1.0 + 1e-9 else self.tol
        blk = self.block(name, tol)
        self._spend(name, len(offsets), len(blk) + len(blk.texts))
        attribs = [a for a in e.attribs if not (a.is_invisible if hasattr(a, "is_invisible") else False)]
        for k, d in enumerate(offsets):
            _transform_pieces(blk, A, t + d, layer, out, self._inherited_ok)
            # attributes are stored in the parent's coordinates already (a MINSERT shifts them per copy)
            for a in attribs if (k == 0 or self.attribs_per_copy) else ():
                alay = a.dxf.get("layer", "0") or "0"
                if alay == "0":
                    alay = layer
                if not self._keep_layer(alay):
                    continue
                txt = _text_plain(a)
                if txt:
                    p = a.dxf.insert
                    if (a.dxf.get("halign", 0) or a.dxf.get("valign", 0)) and a.dxf.hasattr("align_point"):
                        p = a.dxf.align_point
                    out.texts.append((float(p[0]) + d[0], float(p[1]) + d[1], txt, float(a.dxf.get("height", 1.0)),
                                      float(a.dxf.get("rotation", 0.0)), alay, "ATTRIB"))

    def _inherited_ok(self, layer, etype) -> bool:
        return self._keep_layer(layer)


# ------------------------------------------------------------------------------------------ door swings
DOOR_RADIUS = (0.5, 1.6)  # metres: leaf width of a swing door
DOOR_SWEEP = (80.0, 100.0)  # degrees: a swing arc is (about) a quarter circle


def _circle_from_3(p0, p1, p2):
    ax, ay = p0
    bx, by = p1
    cx, cy = p2
    d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if abs(d) < 1e-12:
        return None
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return ux, uy, math.hypot(ax - ux, ay - uy)


def find_door_swings(geoms: Sequence[CadGeometry]) -> List[int]:
    """Indices of door swing arcs (quarter arcs of 0.5-1.6 m radius) and of the door leaves hinged at
    their centre (a line or thin rectangle from the centre to an end of the arc). On wall layers an arc
    counts as a swing only together with its leaf: a rounded wall corner is a wall."""
    arcs = []  # (index, cx, cy, r, end points)
    for i, g in enumerate(geoms):
        if g.entity not in ("ARC", "LWPOLYLINE", "POLYLINE") or g.kind == "column" or g.closed or len(g.coords) < 5:
            continue
        c = g.coords
        circ = _circle_from_3(c[0], c[len(c) // 2], c[-1])
        if circ is None:
            continue
        cx, cy, r = circ
        if not (DOOR_RADIUS[0] <= r <= DOOR_RADIUS[1]):
            continue
        if np.max(np.abs(np.hypot(c[:, 0] - cx, c[:, 1] - cy) - r)) > 0.02:
            continue
        a = np.unwrap(np.arctan2(c[:, 1] - cy, c[:, 0] - cx))
        sweep = abs(math.degrees(a[-1] - a[0]))
        if DOOR_SWEEP[0] <= sweep <= DOOR_SWEEP[1]:
            arcs.append((i, cx, cy, r, c[0], c[-1]))
    if not arcs:
        return []
    from scipy.spatial import cKDTree

    centres = np.array([(a[1], a[2]) for a in arcs])
    tree = cKDTree(centres)
    arc_set = {a[0] for a in arcs}
    with_leaf = set()
    drop = set()
    for i, g in enumerate(geoms):
        if i in arc_set or g.kind == "column" or g.filled:
            continue
        c = g.coords
        if len(c) < 2 or len(c) > 5 or not np.isfinite(c).all():
            continue
        for k in set(j for lst in tree.query_ball_point(c, 0.16) for j in lst):
            _, cx, cy, r, e0, e1 = arcs[k]
            d = np.hypot(c[:, 0] - cx, c[:, 1] - cy)
            if d.min() > 0.1 * r or not (0.85 * r <= d.max() <= 1.15 * r):
                continue
            far = c[int(np.argmax(d))]
            if min(math.hypot(*(far - e0)), math.hypot(*(far - e1))) <= 0.15 * r:
                drop.add(i)
                with_leaf.add(arcs[k][0])
                break
    drop |= {i for i in arc_set if i in with_leaf or geoms[i].kind != "wall"}
    return sorted(drop)


# ------------------------------------------------------------------------------------------ reading
def _read_doc(path: str, progress):
    """Read a DXF; fall back to ezdxf's recover mode and report what it repaired."""
    import ezdxf
    from ezdxf import recover

    from . import cad_dwg  # DWG input: read straight into the same structures (no temporary DXF)

    if cad_dwg.is_dwg(path):
        return cad_dwg.read_dwg(path, progress)
    if not os.path.exists(path):
        raise InputError(f"DXF file '{path}' does not exist")
    if os.path.isdir(path):
        raise InputError(f"'{path}' is a folder, not a DXF file")
    base = os.path.basename(path)
    with open(path, "rb") as fh:
        head = fh.read(4096)
    if not head.strip():
        raise InputError(f"'{base}' is empty (0 bytes of drawing data); export the plan again as DXF")
    if head[:4] == b"AC10" or head[:6] == b"AC1.40":
        raise InputError(f"'{base}' is a DWG file, not a DXF; convert it to DXF first (e.g. with the ODA File "
                         "Converter, LibreCAD or 'Save As DXF' in your CAD program)")
    if head.startswith(b"AutoCAD Binary DXF"):
        pass  # ezdxf reads binary DXF
    elif b"SECTION" not in head.upper() and b"\n0\n" not in head.replace(b"\r\n", b"\n") \
            and not head.lstrip().startswith(b"0"):
        raise InputError(f"'{base}' is not a DXF file (no DXF group codes found at its start); choose a .dxf "
                         "drawing exported from your CAD program")
    repairs: List[str] = []
    try:
        doc = ezdxf.readfile(path)
        return doc, repairs
    except Exception as first:  # DXFStructureError, UnicodeDecodeError, ValueError...
        first_msg = f"{type(first).__name__}: {first}"
    doc = auditor = None
    rec_msg = ""
    try:
        doc, auditor = recover.readfile(path)
    except Exception as exc:
        rec_msg = f"{type(exc).__name__}: {exc}"
    truncated = _is_truncated(path)
    if doc is None or (truncated and len(doc.modelspace()) == 0):
        salvaged = _salvage(path)
        if salvaged is not None:
            stream, notes = salvaged
            try:
                doc, auditor = recover.read(stream)
                repairs.extend(notes)
            except Exception as exc:
                rec_msg = rec_msg or f"{type(exc).__name__}: {exc}"
    if doc is None:
        raise InputError(f"'{base}' is not a readable DXF file, even in ezdxf's recover mode ({first_msg}; "
                         f"recover: {rec_msg}). Open and re-save it in a CAD program, "
                         "or export it again as DXF")
    if truncated and not repairs:
        repairs.append("the file is truncated: it ends without the DXF end-of-file marker")
    repairs.append(f"the file is damaged ({first_msg}); it was read in ezdxf's recover mode")
    for fix in list(getattr(auditor, "fixes", []))[:20]:
        repairs.append(f"fixed: {getattr(fix, 'message', fix)}")
    for err in list(getattr(auditor, "errors", []))[:20]:
        repairs.append(f"unfixable: {getattr(err, 'message', err)}")
    n_fix, n_err = len(getattr(auditor, "fixes", [])), len(getattr(auditor, "errors", []))
    if n_fix > 20 or n_err > 20:
        repairs.append(f"({n_fix} fixes and {n_err} unfixable errors in total)")
    return doc, repairs


def _is_truncated(path: str) -> bool:
    try:
        with open(path, "rb") as fh:
            fh.seek(max(0, os.path.getsize(path) - 64))
            tail = fh.read()
    except OSError:
        return False
    return b"EOF" not in tail.upper()


_FLOAT_CODES = [(10, 59), (110, 149), (210, 239), (460, 469), (1010, 1059)]
_INT_CODES = [(60, 99), (170, 179), (270, 299), (370, 389), (400, 409), (420, 429), (440, 459), (1060, 1071)]


def _code_kind(code: int) -> str:
    if any(a <= code <= b for a, b in _FLOAT_CODES):
        return "f"
    if any(a <= code <= b for a, b in _INT_CODES):
        return "i"
    return "s"


def _salvage(path: str):
    """Rebuild a damaged ASCII DXF in memory for recover mode: drop every entity (or header variable)
    holding an unreadable number, stop at a broken group structure or at the end of a truncated file,
    and close the open section. Returns ``(stream, notes)`` or None."""
    import io

    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError:
        return None
    if data.startswith(b"AutoCAD Binary DXF"):
        return None
    lines = data.replace(b"\r\n", b"\n").replace(b"\r", b"\n").split(b"\n")
    out: List[bytes] = []
    unit: List[bytes] = []
    unit_bad = False
    dropped, bad_lines = 0, []
    stopped_at = None
    i = 0
    n = len(lines) - 1
    while i < n:
        code_txt, value = lines[i].strip(), lines[i + 1]
        try:
            code = int(code_txt)
        except ValueError:
            stopped_at = i + 1
            break
        if code in (0, 9):  # a new entity / table entry / section marker or header variable
            if unit_bad:
                dropped += 1
            else:
                out.extend(unit)
            unit, unit_bad = [], False
        unit.extend((lines[i], value))
        kind = _code_kind(code)
        if kind != "s":
            try:
                float(value.strip()) if kind == "f" else int(value.strip())
            except ValueError:
                unit_bad = True
                bad_lines.append(i + 2)
        i += 2
    ended = bool(unit) and unit[0].strip() == b"0" and unit[1].strip() == b"EOF"
    if ended and not unit_bad:
        out.extend(unit)
    notes = []
    if dropped or (unit_bad and not ended):
        notes.append(f"dropped {dropped + (1 if unit_bad and not ended else 0)} entities with unreadable numbers "
                     f"(lines {', '.join(map(str, bad_lines[:10]))}{'…' if len(bad_lines) > 10 else ''})")
    if not ended:
        why = (f"its group structure breaks at line {stopped_at}" if stopped_at is not None
               else "it ends without the DXF end-of-file marker")
        notes.append(f"the file is truncated or broken ({why}); what precedes was read, the rest is missing")
        out.extend([b"  0", b"ENDSEC", b"  0", b"EOF"])
    if not notes:
        return None
    return io.BytesIO(b"\n".join(out) + b"\n"), notes


def _layer_states(doc):
    states = {}
    for lay in doc.layers:
        try:
            states[lay.dxf.name] = (bool(lay.is_frozen()), bool(lay.is_off()))
        except Exception:
            continue
    return states


def _header_unit(doc) -> str:
    try:
        code = int(doc.header.get("$INSUNITS", 0) or 0)
    except (TypeError, ValueError):
        code = 0
    return _INSUNITS.get(code, "unitless")


@dataclass
class _Raw:
    doc: object
    path: str
    pieces: _Pieces
    states: Dict[str, Tuple[bool, bool]]
    header_unit: str
    repairs: List[str]
    warnings: List[str]
    tol: float
    n_entities: int


def _explode(path: str, tol_du: float, progress, doc=None, repairs=None) -> _Raw:
    if doc is None:
        doc, repairs = _read_doc(path, progress)
    states = _layer_states(doc)
    lower_states = {k.lower(): v for k, v in states.items()}

    def visible(name: str, frozen_only: bool = False) -> bool:
        st = states.get(name) or lower_states.get(name.lower())
        if st is None:
            return True
        return not st[0] if frozen_only else not (st[0] or st[1])

    msp = doc.modelspace()
    n = len(msp)
    if n > MAX_EXPLODED:
        raise InputError(f"'{os.path.basename(path)}' holds {n:,} entities in model space, more than the "
                         f"{MAX_EXPLODED:,} a floor plan needs: remove duplicates (OVERKILL) or copies in CAD, "
                         "or export only the floor's layers")
    ex = _Exploder(doc, tol_du, visible, progress, n)
    out = _Pieces()
    ex.entities(msp, out, top=True)
    # layer "0" (and any other) at the top level must itself be visible
    keep = [i for i, lay in enumerate(out.layer) if visible(lay)]
    if len(keep) != len(out.layer):
        out = _Pieces(coords=[out.coords[i] for i in keep], layer=[out.layer[i] for i in keep],
                      etype=[out.etype[i] for i in keep], closed=[out.closed[i] for i in keep],
                      filled=[out.filled[i] for i in keep], width=[out.width[i] for i in keep],
                      texts=[t for t in out.texts if visible(t[5])], counts=out.counts, xrefs=out.xrefs)
    else:
        out.texts = [t for t in out.texts if visible(t[5])]
    return _Raw(doc, path, out, states, _header_unit(doc), list(repairs or []), ex.warnings, tol_du, n)


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


UNIT_SIZE_PERCENTILES = (2.0, 98.0)  # a few stray entities far away must not change the unit


def _percentile_size(coords: Sequence[np.ndarray], pct=(0.5, 99.5)) -> float:
    if not coords:
        return 0.0
    allc = np.concatenate(coords, axis=0)
    allc = allc[np.isfinite(allc).all(axis=1)]
    if len(allc) == 0:
        return 0.0
    lo = np.percentile(allc, pct[0], axis=0)
    hi = np.percentile(allc, pct[1], axis=0)
    return float(np.max(hi - lo))


def choose_unit(size_du: float, header_unit: str) -> Tuple[str, Optional[str]]:
    """Pick the unit that makes a floor ``size_du`` drawing units across plausible (5-500 m).

    Returns ``(unit, warning or None)``.
    """
    lo, hi = PLAUSIBLE_SIZE
    cands = ["mm", "cm", "m"]
    if header_unit in UNIT_SCALES and header_unit not in cands:
        cands.append(header_unit)
    if size_du <= 0:
        unit = header_unit if header_unit in UNIT_SCALES else "m"
        return unit, None
    if header_unit in UNIT_SCALES:
        s = size_du * UNIT_SCALES[header_unit]
        if lo <= s <= hi:
            return header_unit, None
    plaus = [u for u in cands if lo <= size_du * UNIT_SCALES[u] <= hi]
    pool = plaus or cands
    best = min(pool, key=lambda u: abs(math.log(size_du * UNIT_SCALES[u] / TYPICAL_SIZE)))
    size_best = size_du * UNIT_SCALES[best]
    if header_unit in UNIT_SCALES:
        s = size_du * UNIT_SCALES[header_unit]
        msg = (f"the header says the drawing is in {header_unit} ($INSUNITS), but that makes the building "
               f"{s:.3g} m across, which is implausible for a floor (expected {lo:g}-{hi:g} m); using {best} "
               f"instead ({size_best:.3g} m across). Set UNITS to override")
    else:
        msg = (f"the drawing has no unit ($INSUNITS unitless); using {best}, which makes the building "
               f"{size_best:.3g} m across. Set UNITS to override")
    if not plaus:
        msg += f" (no unit gives a plausible size: the extent is {size_du:.6g} drawing units)"
    return best, msg


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


def list_layers(path: str, rules=None, progress=None) -> List[LayerInfo]:
    """Every layer of the drawing (table + effective layers after explosion), sorted by name."""
    drawing = inspect_dxf(path, rules, progress)
    return sorted(drawing.layers.values(), key=lambda i: i.name.lower())


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


def import_dxf(path: str, rules=None, layers: Optional[Sequence[str]] = None, units: Optional[str] = None,
               include_doors: bool = False, fallback_walls: bool = True, drop_door_swings: bool = True,
               progress=None) -> CadDrawing:
    """Read a DXF and return the structural geometry (metres, CAD frame) and every visible text.

    ``rules``: LayerRules, a JSON path, or None for the defaults. ``layers``: explicit layer names
    (case-insensitive) that override the rules. ``units``: "mm", "cm", "m", "inch", "feet" or
    None/"" for automatic. ``include_doors``: also keep door layers (doorways get closed).
    ``fallback_walls``: when no layer matches a wall keyword, keep every layer that no rule excludes
    (generic names such as "Pluma 8" or "4") as walls, with a warning. ``drop_door_swings``: unless
    doors are included, also leave out door swings drawn on other layers (a quarter arc of 0.5-1.6 m
    radius and the leaf hinged at its centre), as found in mixed "doors windows" layers and blocks.
    Raises InputError for anything the user can fix.
    """
    progress = ensure(progress)
    rules = _resolve_rules(rules)
    forced = normalize_unit(units)
    base = os.path.basename(path)
    progress.step(0, f"reading {base}")
    doc, repairs = _read_doc(path, progress)
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
    progress.step(85, "converting to metres")
    p = raw.pieces
    geoms = []
    nonfinite = 0
    for i in idx:
        c = p.coords[i]
        if len(c) < 2 and not p.filled[i]:
            continue
        sep = np.isnan(c).all(axis=1) if p.filled[i] else np.zeros(len(c), bool)  # NaN rows separate rings
        v = c[~sep]
        if not bool(np.isfinite(v).all()) or abs(scale) * float(np.abs(v).max(initial=0.0)) > 1e15:
            # NaN/inf, or a coordinate beyond any building (1e15 m) that overflows downstream
            nonfinite += 1
            continue
        geoms.append(CadGeometry(layer=p.layer[i], kind=infos[p.layer[i]].kind, coords=c * scale,
                                 closed=p.closed[i], filled=p.filled[i], width=p.width[i] * scale,
                                 entity=p.etype[i]))
    if not include_doors and drop_door_swings:
        swings = find_door_swings(geoms)
        if swings:
            gone = set(swings)
            geoms = [g for k, g in enumerate(geoms) if k not in gone]
            progress.info(f"left out {len(swings)} door swing arcs and leaves drawn on non-door layers "
                          "(doorways stay open; set include_doors to close them)")
    if nonfinite:
        msg = (f"left out {nonfinite} entities with coordinates that are not finite numbers (NaN or infinite, "
               "a damaged file or a broken block scale); check the drawing with AUDIT in CAD")
        warnings.append(msg)
        progress.warning(msg)
    texts = [CadText(x=t[0] * scale, y=t[1] * scale, text=t[2], height=t[3] * scale, rotation=t[4],
                     layer=t[5], entity=t[6]) for t in p.texts
             if math.isfinite(t[0] * scale) and math.isfinite(t[1] * scale)]
    kept_layers = sorted({g.layer for g in geoms})
    progress.step(100, f"{len(geoms)} geometries on {len(kept_layers)} layers, {len(texts)} texts, unit {unit}")
    return CadDrawing(path=path, geometries=geoms, texts=texts, layers=infos, unit_name=unit, unit_scale=scale,
                      header_unit=header, warnings=warnings, repairs=list(repairs),
                      undecoded=dict(getattr(doc, "undecoded", {})))  # DWG: types the reader cannot decode
