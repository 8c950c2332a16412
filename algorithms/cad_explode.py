"""Block explosion and flattening: every entity of model space, INSERTs exploded recursively with their
transforms, curves flattened to a chord tolerance, texts (TEXT, MTEXT, ATTRIB) kept with their position,
in drawing units. See cad_import for the conventions."""
from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

import numpy as np

from .cad_read import _layer_states, _read_doc
from .cad_units import CHORD_TOL, _header_unit
from .errors import InputError

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
SYMBOL_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE", "ARC")  # what is kept when hidden (``_Hidden``)


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


SPLINE_MAX_SPAN = 1e9  # control-point extent / tolerance beyond which a spline is not subdivided


def _spline_points(e, tol: float) -> np.ndarray:
    """A SPLINE flattened to ``tol``; its control polygon when that fails or when a control point is not finite
    or lies so far away (a damaged number, e.g. -2e266 in a byte-flipped DWG) that the adaptive subdivision
    would never end: it halves the chord until it is within ``tol`` of the curve, 2^log2(span/tol) pieces
    (found by fuzzing A-A3-10-08.dwg: the import hung). The far points are then left out with the other
    non-finite / beyond-1e15-m coordinates (cad_import)."""
    cp = np.array([(v[0], v[1]) for v in e.control_points], dtype=np.float64).reshape(-1, 2)
    if np.isfinite(cp).all() and (len(cp) == 0 or float(np.ptp(cp, axis=0).max()) <= SPLINE_MAX_SPAN * max(tol, 1e-12)):
        try:
            return np.array([(v.x, v.y) for v in e.flattening(tol)], dtype=np.float64)
        except Exception:
            pass
    return cp


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
    pts = np.empty((len(t), 2))  # as np.column_stack, without its overhead (thousands of arcs)
    with np.errstate(invalid="ignore", over="ignore"):  # inf/NaN radius of a damaged file: dropped with a warning later
        pts[:, 0] = cx + r * np.cos(t)
        pts[:, 1] = cy + r * np.sin(t)
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
    xy = getattr(bpath, "xy", None)
    if xy is not None:  # a DWG hatch path (cad_dwg.PolylinePath): flattened points, no bulges
        v = np.array(xy, dtype=np.float64).reshape(-1, 2)
        return [v] if len(v) >= 2 else []
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
    # texts: (x, y, text, height, rotation_deg, layer, etype, blocks, tag); ``blocks`` as for ``block`` below
    texts: List[tuple] = field(default_factory=list)
    # the chain of block names a piece was exploded from, outermost first, joined by BLOCK_SEP ("" = model space)
    block: List[str] = field(default_factory=list)
    counts: List[tuple] = field(default_factory=list)  # (layer, etype, n) for entities without geometry
    xrefs: List[str] = field(default_factory=list)
    # texts on frozen / off layers (same tuples as ``texts``): kept apart, room names may still use them
    hidden_texts: List[tuple] = field(default_factory=list)

    # drawn with a dashed/dash-dot linetype (by entity or by layer): projection lines, see ``is_dashed_linetype``
    dashed: List[bool] = field(default_factory=list)
    # the lines, polylines and arcs AutoCAD does not show (``_Hidden``): never drawn, read by ``kept_symbols``
    hidden: Optional["_Hidden"] = None

    def add(self, coords, layer, etype, closed=False, filled=False, width=0.0, block="", dashed=False):
        self.dashed.append(dashed)
        self.block.append(block)
        self.coords.append(coords)
        self.layer.append(layer)
        self.etype.append(etype)
        self.closed.append(closed)
        self.filled.append(filled)
        self.width.append(width)

    def __len__(self):
        return len(self.coords)

    def hidden_part(self) -> "_Hidden":
        """``hidden``, created when first needed."""
        if self.hidden is None:
            self.hidden = _Hidden()
        return self.hidden

    def extend(self, src: "_Pieces", idx: Sequence[int], coords: Iterable[np.ndarray], layers: Sequence[str],
               width_scale: float = 1.0, chain: str = "") -> None:
        """Append the pieces ``idx`` of ``src`` with ``coords`` and ``layers`` (their new geometry and layers),
        widths scaled by ``width_scale``, block chains under ``chain``."""
        self.coords.extend(coords)
        self.layer.extend(layers)
        self.etype.extend(src.etype[i] for i in idx)
        self.closed.extend(src.closed[i] for i in idx)
        self.filled.extend(src.filled[i] for i in idx)
        self.width.extend(src.width[i] * width_scale if src.width[i] else 0.0 for i in idx)
        self.block.extend(_chain_name(chain, src.block[i]) for i in idx)
        self.dashed.extend(src.dashed[i] for i in idx)

    def select(self, idx: Sequence[int]) -> "_Pieces":
        """The pieces ``idx`` (everything else shared: texts, counts, xrefs, hidden texts and pieces)."""
        out = _Pieces(texts=self.texts, counts=self.counts, xrefs=self.xrefs, hidden_texts=self.hidden_texts,
                      hidden=self.hidden)
        out.extend(self, idx, [self.coords[i] for i in idx], [self.layer[i] for i in idx])
        return out


class _Hidden:
    """The lines, polylines and arcs (``SYMBOL_TYPES``) a block (or the model space) holds but AutoCAD does not
    show: on an off / frozen layer (their own or the one they take), or inside an INSERT on a frozen layer.
    The exploder keeps them in its one walk as cheaply as it can: references to the entities (flattened only
    when read), the placements of the hidden parts of the blocks placed here (one per INSERT, not one per
    piece), and the pieces it flattened already. ``flat`` reads them, in the block's coordinates, only for a
    drawing whose stair / lift symbols are needed (``kept_symbols``)."""

    def __init__(self):
        self.pieces = _Pieces()  # flattened already: pieces hidden by the layer they take (layer "0" of an off INSERT)
        self.refs: List[tuple] = []  # (exploder, entity, type, layer, tolerance): on an off / frozen layer of
        # their own, or an INSERT hidden whole (frozen layer)
        self.placed: List[tuple] = []  # (_Hidden of a block, A, t, layer, block name): the blocks placed here
        self._flat: Optional[_Pieces] = None

    def __bool__(self) -> bool:
        return bool(self.pieces.coords or self.refs or self.placed)

    def flat(self) -> _Pieces:
        """The hidden pieces, flattened and placed (cached: a block's hidden part is shared by its inserts)."""
        if self._flat is None:
            self._flat = _Pieces()  # a block that hides an INSERT of itself: its own hidden part is empty inside
            out = _Pieces()
            out.extend(self.pieces, range(len(self.pieces)), self.pieces.coords, self.pieces.layer)
            for ex, e, et, layer, tol in self.refs:
                ex.hidden_entity(e, et, layer, tol, out)
            for sub, A, t, layer, name in self.placed:
                _transform_pieces(sub.flat(), A, t, layer, out, _any_layer, name)
            self._flat = out
        return self._flat


BLOCK_SEP = "\x1f"

# linetype names of projection / overhead / hidden lines (ACAD, ISO, Italian 'tratto', Chinese '虚线', ...)
DASHED_LINETYPE_WORDS = ("dash", "hidden", "center", "centre", "phantom", "acad_iso", "iso0", "iso1", "tratt",
                         "divide", "dot", "punt", "strich", "trazo", "虚", "点划", "点画", "pointill", "tiret")
DASHABLE_TYPES = ("LINE", "LWPOLYLINE", "POLYLINE", "ARC", "SPLINE", "ELLIPSE")


def is_dashed_linetype(name: str) -> bool:
    """A linetype drawn broken (dashed, dash-dot, hidden, centre, phantom, ISO patterns): projection lines."""
    low = (name or "").strip().lower()
    if not low or low in ("continuous", "bylayer", "byblock", "solid"):
        return False
    return any(w in low for w in DASHED_LINETYPE_WORDS)


def linetype_has_gaps(doc, name: str) -> bool:
    """The linetype table entry ``name`` of ``doc`` has a pattern with gaps (a dashed line whatever its name);
    False when the table or the entry is missing (DWG documents without a linetype table)."""
    try:
        lt = doc.linetypes.get(name)
        pattern = lt.simplified_line_pattern() if lt is not None else ()
    except Exception:
        return False
    return len(pattern) >= 2 and any(float(v) > 1e-9 for v in pattern[1::2])


def _chain_name(name: str, inner: str) -> str:
    return f"{name}{BLOCK_SEP}{inner}" if inner else name


def innermost_block(chain: str) -> str:
    """The innermost named block of a chain (anonymous blocks such as ``*U12`` only when nothing else)."""
    if not chain:
        return ""
    parts = chain.split(BLOCK_SEP)
    named = [p for p in parts if not p.startswith("*")]
    return named[-1] if named else parts[-1]


def _transform_pieces(src: _Pieces, A: np.ndarray, t: np.ndarray, layer: str, dst: _Pieces,
                      layer_ok, name: str = "") -> None:
    """Append ``src`` transformed by x' = A @ x + t to ``dst``; layer "0" takes ``layer``. The pieces
    ``layer_ok`` refuses go to ``dst.hidden`` when they are ``SYMBOL_TYPES``; ``src.hidden`` is placed there."""
    n = len(src.coords)
    if n:
        lens = np.fromiter((len(c) for c in src.coords), dtype=np.int64, count=n)
        allc = np.concatenate(src.coords, axis=0) @ A.T + t
        ends = np.cumsum(lens).tolist()
        lens = lens.tolist()
        s = math.sqrt(abs(float(np.linalg.det(A))))
        # the pieces kept (layer_ok once per layer and type), appended list by list: a block inserted
        # hundreds of times made this per-piece loop a tenth of the explosion
        ok_of: Dict[Tuple[str, str], bool] = {}
        keep, lays, gone, gone_lays = [], [], [], []
        for i, (lay, et) in enumerate(zip(src.layer, src.etype)):
            if lay == "0":
                lay = layer
            ok = ok_of.get((lay, et))
            if ok is None:
                ok = ok_of[(lay, et)] = bool(layer_ok(lay, et))
            if ok:
                keep.append(i)
                lays.append(lay)
            elif et in SYMBOL_TYPES:  # hidden by the layer it takes (an INSERT on an off layer)
                gone.append(i)
                gone_lays.append(lay)
        if keep:
            dst.extend(src, keep, (allc[ends[i] - lens[i]:ends[i]] for i in keep), lays, s, name)
        if gone:
            dst.hidden_part().pieces.extend(src, gone, (allc[ends[i] - lens[i]:ends[i]] for i in gone), gone_lays, s,
                                            name)
    if src.hidden:
        dst.hidden_part().placed.append((src.hidden, A, t, layer, name))
    for src_texts, dst_texts in ((src.texts, dst.texts), (src.hidden_texts, dst.hidden_texts)):
        if not src_texts:
            continue
        s = math.sqrt(abs(float(np.linalg.det(A))))
        rot = math.degrees(math.atan2(A[1, 0], A[0, 0]))
        for (x, y, text, h, r, lay, et, blocks, tag) in src_texts:
            if lay == "0":
                lay = layer
            if not layer_ok(lay, et):
                continue
            p = A @ np.array((x, y)) + t
            dst_texts.append((float(p[0]), float(p[1]), text, h * s, (r + rot) % 360.0, lay, et,
                              _chain_name(name, blocks), tag))
    for (lay, et, k) in src.counts:
        dst.counts.append((layer if lay == "0" else lay, et, k))
    dst.xrefs.extend(src.xrefs)


def _any_layer(layer: str, etype: str) -> bool:
    return True


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


# DXF R2000/R2004 (and older) store characters outside the file's code page as escapes that ezdxf
# leaves in the text: \U+697C (Unicode) and \M+n8C9E (a double-byte character of an Asian code page n).
_UNICODE_ESCAPE = re.compile(r"\\U\+([0-9A-Fa-f]{4})")
_MIF_ESCAPE = re.compile(r"\\M\+([1-5])([0-9A-Fa-f]{4})")
_MIF_CODEPAGES = {"1": "cp932", "2": "cp950", "3": "cp949", "4": "johab", "5": "gbk"}


def _mif_char(m) -> str:
    try:
        return bytes.fromhex(m.group(2)).decode(_MIF_CODEPAGES[m.group(1)])
    except (UnicodeDecodeError, LookupError, ValueError):
        return m.group(0)


def decode_escapes(txt: str) -> str:
    """Text with DXF \\U+XXXX and \\M+nXXXX escapes turned into the characters they stand for."""
    if "\\" not in txt:
        return txt
    txt = _UNICODE_ESCAPE.sub(lambda m: chr(int(m.group(1), 16)), txt)
    return _MIF_ESCAPE.sub(_mif_char, txt)


def _mtext_plain(e) -> str:
    try:
        txt = e.plain_text()
    except Exception:
        txt = _MTEXT_FALLBACK.sub(" ", e.text)
    return " ".join(decode_escapes(str(txt)).split())


def _text_plain(e) -> str:
    try:
        txt = e.plain_text()
    except Exception:
        txt = e.dxf.text
    return " ".join(decode_escapes(str(txt)).split())


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
        self._layer_lt: Dict[str, str] = {}  # layer -> its linetype name (``_dashed``)
        self._lt_broken: Dict[str, bool] = {}  # linetype name -> its pattern has gaps (``_broken_pattern``)
        self._lt_dashed: Dict[str, bool] = {}  # linetype name -> ``_dashed``'s answer

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
        if not self._keep_layer(layer) and et not in HIDDEN_TEXT_TYPES:
            if et == "INSERT":
                if OFF_INSERT_SHOWS_OWN_LAYERS and self.visible(layer, frozen_only=True):
                    # an INSERT on an *off* (not frozen) layer: AutoCAD hides only what inherits that layer
                    # (the block's layer-0 entities, dropped by ``_inherited_ok``); its own-layer ones stay
                    self._insert(e, layer, out)
                    return
                self._hidden_insert(e, layer, out)
            elif et in SYMBOL_TYPES:  # a line AutoCAD hides: kept apart, stair / lift evidence (kept_symbols)
                out.hidden_part().refs.append((self, e, et, layer, self.tol))
            return
        if et in DASHABLE_TYPES:
            n0 = len(out.coords)
            self._entity(e, et, layer, out)
            if len(out.coords) > n0 and self._dashed(e, layer):
                out.dashed[n0:] = [True] * (len(out.coords) - n0)
            return
        self._entity(e, et, layer, out)

    def _dashed(self, e, layer: str) -> bool:
        """The entity's linetype (its layer's for BYLAYER) is a dashed / dash-dot / hidden one."""
        try:
            lt = str(e.dxf.get("linetype", "BYLAYER") or "BYLAYER")
            if lt.upper() == "BYLAYER":
                cache = self._layer_lt
                if layer not in cache:
                    try:
                        cache[layer] = str(self.doc.layers.get(layer).dxf.get("linetype", "") or "")
                    except Exception:
                        cache[layer] = ""
                lt = cache[layer]
            got = self._lt_dashed.get(lt)
            if got is None:  # one answer per linetype name (the word search per entity was a tenth of it)
                got = self._lt_dashed[lt] = bool(is_dashed_linetype(lt) or self._broken_pattern(lt))
            return got
        except Exception:
            return False

    def _broken_pattern(self, lt: str) -> bool:
        """A linetype whose name says nothing ('RAYITAS', 'LINEA2') but whose pattern has gaps is broken too."""
        key = (lt or "").strip().lower()
        if not key or key in ("continuous", "bylayer", "byblock", "solid"):
            return False
        cache = self._lt_broken
        if key not in cache:
            cache[key] = linetype_has_gaps(self.doc, lt)
        return cache[key]

    def _entity(self, e, et: str, layer: str, out: _Pieces) -> None:
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
            xy = _spline_points(e, tol)
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
                                  float(e.dxf.get("rotation", 0.0)), layer, et, "", ""))
        elif et == "MTEXT":
            txt = _mtext_plain(e)
            if txt:
                p = e.dxf.insert
                try:
                    rot = float(e.get_rotation())
                except Exception:
                    rot = float(e.dxf.get("rotation", 0.0))
                out.texts.append((float(p[0]), float(p[1]), txt, float(e.dxf.get("char_height", 1.0)), rot,
                                  layer, et, "", ""))
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

    def _hidden_insert(self, e, layer, out, texts: bool = True) -> None:
        """An INSERT AutoCAD hides whole (on a frozen layer, or on an off one with ``OFF_INSERT_SHOWS_OWN_LAYERS``
        switched off): kept in ``out.hidden`` (stair / lift evidence, exploded when read); with ``texts``, the
        texts of a small block (an annotation group: a callout with its leader) are kept as hidden texts."""
        out.hidden_part().refs.append((self, e, "INSERT", layer, self.tol))
        if not texts:
            return
        blk = self.doc.blocks.get(e.dxf.get("name", ""))
        try:
            small = blk is not None and len(blk) <= HIDDEN_BLOCK_MAX
        except TypeError:
            small = False
        if small:
            tmp = _Pieces()
            self._insert(e, layer, tmp, hidden=True)
            out.hidden_texts.extend(tmp.texts + tmp.hidden_texts)

    def hidden_entity(self, e, et: str, layer: str, tol: float, out: _Pieces) -> None:
        """A hidden entity kept by ``_Hidden.refs``, flattened at ``tol`` into ``out``: its lines, polylines and
        arcs, those of the whole block for an INSERT. A broken entity, or a block too large to explode
        (``MAX_EXPLODED``), gives nothing: it is evidence only."""
        saved, self.tol = self.tol, tol
        try:
            if et != "INSERT":
                self._entity(e, et, layer, out)
                return
            if self.doc.blocks.get(e.dxf.get("name", "")) is None:
                return
            tmp = _Pieces()
            self._insert(e, layer, tmp, hidden=True)
            sym = [i for i, t in enumerate(tmp.etype) if t in SYMBOL_TYPES]
            out.extend(tmp, sym, [tmp.coords[i] for i in sym], [tmp.layer[i] for i in sym])
            if tmp.hidden:
                flat = tmp.hidden.flat()
                out.extend(flat, range(len(flat)), flat.coords, flat.layer)
        except Exception:
            return
        finally:
            self.tol = saved

    def _insert(self, e, layer, out, hidden: bool = False):
        name = e.dxf.name
        if not hidden and not self.visible(layer, frozen_only=True) and (layer != "0" or self._top_frozen_zero()):
            self._hidden_insert(e, layer, out, texts=False)
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
        for d in offsets:
            _transform_pieces(blk, A, t + d, layer, out, self._inherited_ok, name)
            # attributes are stored in the parent's coordinates already (a MINSERT shifts them per copy)
            for a in attribs:
                alay = a.dxf.get("layer", "0") or "0"
                if alay == "0":
                    alay = layer
                txt = _text_plain(a)
                if txt:
                    p = a.dxf.insert
                    if (a.dxf.get("halign", 0) or a.dxf.get("valign", 0)) and a.dxf.hasattr("align_point"):
                        p = a.dxf.align_point
                    out.texts.append((float(p[0]) + d[0], float(p[1]) + d[1], txt, float(a.dxf.get("height", 1.0)),
                                      float(a.dxf.get("rotation", 0.0)), alay, "ATTRIB", name,
                                      str(a.dxf.get("tag", "") or "")))

    def _top_frozen_zero(self) -> bool:
        """An INSERT on a frozen layer "0" is hidden whole at the top level (model space); inside a block
        layer "0" is the parent INSERT's layer, decided when that INSERT is placed."""
        return OFF_INSERT_SHOWS_OWN_LAYERS and not self.stack

    def _inherited_ok(self, layer, etype) -> bool:
        return etype in HIDDEN_TEXT_TYPES or self._keep_layer(layer)



# Layer visibility of block contents, as AutoCAD shows it (ezdxf's drawing add-on agrees for *off*: an INSERT's
# visibility "depends only on the invisible flag, the layer state has no effect", and its layer-0 entities take
# its layer): an INSERT on an *off* layer hides only the block entities that inherit that layer (those on layer
# "0", nested INSERTs on "0" included); entities on their own layers stay visible when those layers are on and
# thawed. An INSERT on a *frozen* layer hides the whole block, nested contents included. False: the old rule
# (an INSERT on an off layer dropped whole, like a frozen one). On by default since session 7 (T10c): on the
# filtered SIST floors it shows what AutoCAD shows (F1's curtain walls and glass lift, F2's E1 wing walls, F4's
# columns). It was off while F1's newly shown glass lift, its only anchor, registered F1 74 m off in the fusion;
# building._few_anchor_fit_rejected now checks a fit on < 3 anchors against the outline fit and
# building.shaft_targets lets a floor with a few anchors take its neighbours' shafts: 37 vertical passages
# either way, F1 within 4 mm of where the rule off puts it.
OFF_INSERT_SHOWS_OWN_LAYERS = True

HIDDEN_TEXT_TYPES = ("TEXT", "MTEXT", "ATTRIB")  # texts are read on every layer, then split by visibility
HIDDEN_BLOCK_MAX = 50  # a block inserted on a frozen / off layer gives its texts when it is this small


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


def _explode(path: str, tol_du: float, progress, doc=None, repairs=None, states=None) -> _Raw:
    if doc is None:
        doc, repairs = _read_doc(path, progress)
    if states is None:
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
    shown = [visible(lay) for lay in out.layer]
    if not all(shown):
        gone = [i for i, (ok, et) in enumerate(zip(shown, out.etype)) if not ok and et in SYMBOL_TYPES]
        if gone:
            out.hidden_part().pieces.extend(out, gone, [out.coords[i] for i in gone], [out.layer[i] for i in gone])
        out = out.select([i for i, ok in enumerate(shown) if ok])
    # texts on frozen / off layers are not drawn: kept apart (a sheet often freezes the annotation layer of
    # one wing, e.g. the stair callouts or room names of a bound xref; stage 5 may still name rooms by them)
    out.hidden_texts = out.hidden_texts + [t for t in out.texts if not visible(t[5])]
    out.texts = [t for t in out.texts if visible(t[5])]
    return _Raw(doc, path, out, states, _header_unit(doc), list(repairs or []), ex.warnings, tol_du, n)



# ------------------------------------------------------------------- stair / lift symbols the drawing hides
LIFT_DOOR_CLS = "lift door"  # CadGeometry.cls of the lines of a lift-named block (an elevator door symbol)
HIDDEN_SYMBOL_CLS = "hidden"  # CadGeometry.cls of a stair / lift line on a hidden layer


def _lift_block(name: str, rules) -> bool:
    """A block named like a lift ('Elevator - Single Side Open - 54_w x 96_h', 'X$0$电梯门'): the lift keywords
    of the layer rules, on the block name without its bound-xref prefix."""
    from .layer_rules import keyword_in, meaningful_part

    low = meaningful_part(name).lower()
    words = next((w for k, w in rules.kinds if k == "elevator"), [])
    return any(keyword_in(w, low) for w in words)


def kept_symbols(pieces: _Pieces, rules, scale: float, extent=None):
    """Stair and lift symbols a drawing holds but does not show, read from what the exploder kept (``pieces``
    of ``_explode``), as ``CadGeometry`` (metres, kind "stair" / "elevator"): its hidden lines, polylines and
    arcs (``_Hidden``: on an off / frozen layer, their own or the one they take, or inside an INSERT on
    a frozen layer) on stair / lift layers by the layer rules (``cls`` = ``HIDDEN_SYMBOL_CLS``); and those of
    lift-named blocks ('Elevator - Single Side Open ...', elevator door symbols, ``cls`` = ``LIFT_DOOR_CLS``),
    shown or not. A plan reduced to its structure by turning layers off keeps its stair treads and lift cars
    there: evidence of which area is a stair or a lift, never walls (nothing here is rasterized). ``extent``
    (xmin, ymin, xmax, ymax, metres): only symbols whose mean point is within it (+ 1 m)."""
    from .model import CadGeometry

    lift_name: Dict[str, bool] = {}
    lift_chain: Dict[str, bool] = {"": False}
    kind_of: Dict[str, Optional[str]] = {}

    def lift_named(name: str) -> bool:
        if name not in lift_name:
            lift_name[name] = _lift_block(name, rules)
        return lift_name[name]

    def in_lift_block(chain: str) -> bool:
        if chain not in lift_chain:
            lift_chain[chain] = any(lift_named(b) for b in chain.split(BLOCK_SEP))
        return lift_chain[chain]

    geoms = []
    for src, hidden in ((pieces, False), (pieces.hidden.flat() if pieces.hidden else _Pieces(), True)):
        for c, layer, et, closed, chain in zip(src.coords, src.layer, src.etype, src.closed, src.block):
            if et not in SYMBOL_TYPES:
                continue
            lift = in_lift_block(chain)
            if not lift:
                if not hidden:
                    continue
                if layer not in kind_of:
                    kind_of[layer] = rules.classify(layer)[0]
                kind = kind_of[layer]
                if kind not in ("stair", "elevator"):
                    continue
            if len(c) < 2 or not np.isfinite(c).all():
                continue
            if closed and len(c) > 2:  # a closed polyline as a ring
                c = np.vstack([c, c[:1]])
            xy = c * scale
            if extent is not None:
                cx, cy = xy.mean(axis=0)
                if not (extent[0] - 1 <= cx <= extent[2] + 1 and extent[1] - 1 <= cy <= extent[3] + 1):
                    continue
            geoms.append(CadGeometry(layer=layer, kind="elevator" if lift else kind, coords=xy, entity="LINE",
                                     cls=LIFT_DOOR_CLS if lift else HIDDEN_SYMBOL_CLS))
    return geoms


def hidden_symbols(doc, states, rules, scale: float, extent=None):
    """``kept_symbols`` of the document ``doc`` (layer ``states`` as ``cad_read._layer_states`` reads them),
    exploded at the import's chord tolerance for ``scale`` (metres per drawing unit)."""
    raw = _explode(getattr(doc, "filename", None) or "drawing", CHORD_TOL / scale, None, doc=doc, states=states)
    return kept_symbols(raw.pieces, rules, scale, extent)
