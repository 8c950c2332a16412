"""DWG input: read a .dwg (R13-R2018) with ezdwg straight into the CAD import's structures.

Public API
----------
``read_dwg(path, progress=None) -> (DwgDocument, repairs)``
    The drawing as an object with the small ezdxf-like interface that ``cad_import._Exploder`` and
    ``cad_import._explode`` use (``modelspace()``, ``blocks.get(name)``, ``layers``, ``header``,
    ``layouts``; entities with ``dxftype()``, ``dxf.get()``, ``dxf.hasattr()``, INSERT
    ``matrix44()`` / ``multi_insert()`` / ``attribs``, hatch ``paths``, LWPOLYLINE ``get_points()``,
    TEXT/MTEXT ``plain_text()``...). No temporary DXF is written.
``check_dwg(path) -> str``
    The version code (``AC1018``...) after the checks for empty, foreign, too old / too new and
    password-protected files; raises ``InputError`` with what to do.
``is_dwg(path) -> bool``
    ``.dwg`` extension or a DWG version string at the start of the file.

How it reads
------------
ezdwg's high-level ``Layout.query()`` builds a dict per entity and runs text-recovery heuristics
(7-8 s for a 77k-entity sheet), so the bulk types are taken from ezdwg's native row decoders
(``ezdwg.raw.decode_*``: a few tenths of a second each) and wrapped in light adapter objects:
LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE (2D/3D), SPLINE, ELLIPSE, SOLID, TRACE, 3DFACE, HATCH
(boundaries as ezdwg flattens them), INSERT, MINSERT, ATTRIB, TEXT, MTEXT. Membership (model space /
block / paper space) comes from the entities' owner handles, layers from the layer handles of the
common entity data, extrusions (mirrored arcs and blocks) from ezdwg's write-geometry rows, block base
points from its block rows. Texts arrive as Unicode: ezdwg decodes the drawing's code page (e.g.
ANSI_936 / GBK for Chinese drawings before R2007) and UTF-16 (R2007+).

Dimensions, points, viewports, rays... become count-only entities (they are skipped by the import
like their DXF counterparts). Entity types that ezdwg cannot decode (custom objects such as Tianzheng
``TCH_*``, proxies, tables, ``MLINE``, meshes) are counted per type in ``DwgDocument.undecoded`` and
appear as unsupported entities in the import's warnings. Entities the decoder lost (fewer decoded
rows than the object map lists) are counted as undecoded too.
"""
from __future__ import annotations

import math
import os
import struct
import time
from collections import Counter
from typing import Dict, Iterator, List, Optional, Tuple

import numpy as np

from .cad_read import check_drawing_file
from .errors import InputError
from .progress import ensure

# version code -> release, as in the DWG file header
DWG_VERSIONS = {
    "AC1.2": "R1.2", "AC1.40": "R1.40", "AC1.50": "R2.05", "AC2.10": "R2.10", "AC1001": "R2.2",
    "AC1002": "R2.5", "AC1003": "R2.6", "AC1004": "R9", "AC1006": "R10", "AC1009": "R11/R12",
    "AC1012": "R13", "AC1014": "R14", "AC1015": "R2000", "AC1018": "R2004", "AC1021": "R2007",
    "AC1024": "R2010", "AC1027": "R2013", "AC1032": "R2018",
}
SUPPORTED = ("AC1012", "AC1014", "AC1015", "AC1018", "AC1021", "AC1024", "AC1027", "AC1032")

# object-map type names -> what the import sees (count-only types the import skips anyway)
_COUNT_ONLY = {
    "DIMENSION": "DIMENSION", "DIM_LINEAR": "DIMENSION", "DIM_ALIGNED": "DIMENSION", "DIM_RADIUS": "DIMENSION",
    "DIM_DIAMETER": "DIMENSION", "DIM_ORDINATE": "DIMENSION", "DIM_ANG3PT": "DIMENSION",
    "DIM_ANG2LN": "DIMENSION", "ARC_DIMENSION": "ARC_DIMENSION", "LARGE_RADIAL_DIMENSION": "LARGE_RADIAL_DIMENSION",
    "POINT": "POINT", "VIEWPORT": "VIEWPORT", "RAY": "RAY", "XLINE": "XLINE", "ATTDEF": "ATTDEF",
    "LEADER": "LEADER", "MULTILEADER": "MULTILEADER", "TOLERANCE": "TOLERANCE", "IMAGE": "IMAGE",
    "WIPEOUT": "WIPEOUT", "OLE2FRAME": "OLE2FRAME", "OLEFRAME": "OLEFRAME", "SHAPE": "SHAPE",
    "REGION": "REGION", "3DSOLID": "3DSOLID", "BODY": "BODY", "LONG_TRANSACTION": "LONG_TRANSACTION",
}
# parts of other entities: never entities of a layout on their own
_PARTS = {"BLOCK", "ENDBLK", "SEQEND", "VERTEX_2D", "VERTEX_3D", "VERTEX_MESH", "VERTEX_PFACE",
          "VERTEX_PFACE_FACE", "ATTRIB"}
# decoded here (object-map type name -> import type)
_DECODED = {"LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE_2D", "POLYLINE_3D", "SPLINE", "ELLIPSE", "SOLID",
            "TRACE", "3DFACE", "HATCH", "INSERT", "MINSERT", "TEXT", "MTEXT"}
_XY_TOL = 1e-9


def _looks_like_dxf(head: bytes) -> bool:
    h = head.lstrip()
    return h.startswith(b"AutoCAD Binary DXF") or h.startswith(b"0") or h.startswith(b"999") \
        or b"SECTION" in head[:200].upper()


def is_dwg(path: str) -> bool:
    """A DWG version string at the start of the file, or a ``.dwg`` name on anything that is not a DXF
    (a DXF saved with a .dwg name is read as the DXF it is)."""
    try:
        with open(path, "rb") as fh:
            head = fh.read(256)
    except OSError:
        head = b""
    if head[:2] == b"AC" and (head[2:6].isdigit() or head[2:3] in (b"1", b"2")):
        return True
    if str(path).lower().endswith(".dwg"):
        return not (head and _looks_like_dxf(head))
    return False


def check_dwg(path: str) -> str:
    """Header checks before any decoding; returns the version code."""
    base, _, head = check_drawing_file(path, "DWG", 0x80, "save the drawing again from your CAD program")
    code = head[:6].rstrip(b"\x00").decode("latin-1", "replace")
    if not (head[:2] == b"AC" and (code in DWG_VERSIONS or (len(code) == 6 and code[2:].isdigit()))):
        raise InputError(f"'{base}' is not a DWG file (it does not start with a DWG version code such as "
                         "'AC1018'); choose a drawing saved as .dwg or .dxf by a CAD program")
    release = DWG_VERSIONS.get(code)
    if code not in SUPPORTED:
        if release is not None and code < "AC1012":
            raise InputError(f"'{base}' is a DWG of AutoCAD {release} ({code}), older than the oldest version the "
                             "DWG reader supports (R13); save it as DWG 2000-2018 or export it as DXF")
        raise InputError(f"'{base}' is a DWG of a version the reader does not know ({code}"
                         f"{', AutoCAD ' + release if release else ', newer than AutoCAD 2018 (AC1032)'}); save it as "
                         "'AutoCAD 2018 DWG' or older (or export it as DXF) in your CAD program")
    if code >= "AC1018" and len(head) >= 0x1C:
        security = struct.unpack_from("<I", head, 0x18)[0]
        if security & 0x3:
            raise InputError(f"'{base}' is password-protected (encrypted DWG); open it in your CAD program with its "
                             "password, remove the password (Security options) and save it again")
    return code


# ------------------------------------------------------------------------------------------ adapters
class _Dxf:
    """``entity.dxf``: attribute access, ``get`` and ``hasattr`` over a dict (None = absent)."""

    __slots__ = ("_d",)

    def __init__(self, d: dict):
        self._d = d

    def get(self, key, default=None):
        v = self._d.get(key)
        return default if v is None else v

    def hasattr(self, key) -> bool:
        return self._d.get(key) is not None

    def __getattr__(self, key):
        try:
            v = self._d[key]
        except KeyError:
            raise AttributeError(key) from None
        if v is None:
            raise AttributeError(key)
        return v


class _Entity(_Dxf):
    """An entity is its own ``dxf`` namespace (one object per entity keeps a 77k-entity sheet fast)."""

    __slots__ = ("_type", "_h")

    def __init__(self, etype: str, handle: int, d: dict):
        self._d = d
        self._type = etype
        self._h = handle

    @property
    def dxf(self):
        return self

    @property
    def handle(self) -> str:
        """The DWG handle as ezdxf spells ``dxf.handle``: upper-case hex."""
        return f"{self._h:X}"

    def dxftype(self) -> str:
        return self._type


class _LwPolyline(_Entity):
    __slots__ = ("_pts", "closed")

    def __init__(self, handle, d, pts, closed):
        super().__init__("LWPOLYLINE", handle, d)
        self._pts = pts
        self.closed = closed

    def get_points(self, fmt="xyseb"):
        return self._pts


class _Vertex:
    __slots__ = ("dxf",)

    def __init__(self, d):
        self.dxf = _Dxf(d)


class _Polyline(_Entity):
    __slots__ = ("_mode", "vertices", "is_closed")

    def __init__(self, handle, d, mode, vertices, closed):
        super().__init__("POLYLINE", handle, d)
        self._mode = mode
        self.vertices = vertices
        self.is_closed = closed

    def get_mode(self):
        return self._mode

    def virtual_entities(self):
        return []


class _Spline(_Entity):
    __slots__ = ("control_points", "closed", "_knots", "_weights", "_degree", "_fit")

    def __init__(self, handle, d, degree, closed, knots, ctrl, weights, fit):
        super().__init__("SPLINE", handle, d)
        self.control_points = ctrl
        self.closed = closed
        self._knots, self._weights, self._degree, self._fit = knots, weights, degree, fit

    def flattening(self, tol):
        from ezdxf.math import BSpline, fit_points_to_cad_cv

        if len(self.control_points) >= 2 and self._knots:
            sp = BSpline(self.control_points, order=self._degree + 1, knots=self._knots,
                         weights=self._weights or None)
        elif len(self._fit) >= 2:
            sp = fit_points_to_cad_cv(self._fit)
        else:
            raise ValueError("spline without control or fit points")
        return sp.flattening(tol)


class _Ellipse(_Entity):
    __slots__ = ()

    def flattening(self, tol):
        from ezdxf.math import ConstructionEllipse

        d = self.dxf
        ce = ConstructionEllipse(center=d.center, major_axis=d.major_axis, extrusion=d.get("extrusion", (0, 0, 1)),
                                 ratio=d.ratio, start_param=d.start_param, end_param=d.end_param)
        return ce.flattening(tol)


class _Text(_Entity):
    __slots__ = ()

    def plain_text(self):
        from ezdxf.tools.text import plain_text

        return plain_text(self.dxf.get("text", ""))

    @property
    def is_invisible(self) -> bool:
        return bool(int(self.dxf.get("attribute_flags", 0)) & 1)


class _MText(_Entity):
    __slots__ = ("text",)

    def __init__(self, handle, d):
        super().__init__("MTEXT", handle, d)
        self.text = d.get("text") or ""

    def plain_text(self):
        from ezdxf.tools.text import plain_mtext

        return plain_mtext(self.text, split=False)

    def get_rotation(self):
        return float(self.dxf.get("rotation", 0.0))


class PolylinePath:
    """A hatch boundary as ezdwg flattens it: ``xy``, its (x, y) points (no bulges), which
    ``cad_explode._boundary_rings`` reads as one array; ``vertices`` (x, y, 0.0) as ezdxf's path has them."""

    __slots__ = ("xy",)

    def __init__(self, xy):
        self.xy = xy

    @property
    def vertices(self):
        return [(x, y, 0.0) for x, y in self.xy]


class _Paths:
    __slots__ = ("paths",)

    def __init__(self, paths):
        self.paths = paths


class _Hatch(_Entity):
    __slots__ = ("paths",)

    def __init__(self, handle, d, paths):
        super().__init__("HATCH", handle, d)
        self.paths = _Paths(paths)


def _ocs_axes(extrusion) -> np.ndarray:
    """2x2 map OCS xy -> WCS xy for a (near) z-parallel extrusion: identity, or x mirrored for -z."""
    if extrusion is not None and extrusion[2] < 0 and abs(extrusion[0]) < 1e-9 and abs(extrusion[1]) < 1e-9:
        return np.array(((-1.0, 0.0), (0.0, 1.0)))
    return np.eye(2)


class _Insert(_Entity):
    __slots__ = ("attribs", "_doc")

    def __init__(self, handle, d, doc):
        super().__init__("INSERT", handle, d)
        self.attribs: List[_Text] = []
        self._doc = doc

    def matrix44(self):
        """ezdxf's convention: rows 0/1 = images of the block's x/y axes, row 3 = translation (WCS),
        with the block base point taken off."""
        d = self.dxf
        ex = d.get("extrusion", (0.0, 0.0, 1.0))
        if abs(ex[0]) > 1e-9 or abs(ex[1]) > 1e-9:  # a tilted insert: let ezdxf do the 3D maths
            return self._matrix44_3d()
        rot = math.radians(float(d.get("rotation", 0.0)))
        c, s = math.cos(rot), math.sin(rot)
        sx, sy = float(d.get("xscale", 1.0)), float(d.get("yscale", 1.0))
        M = _ocs_axes(ex)
        A = M @ np.array(((c * sx, -s * sy), (s * sx, c * sy)))
        ins = np.array(d.get("insert", (0.0, 0.0, 0.0))[:2], dtype=np.float64)
        base = np.array(self._doc._base_points.get(d.get("name", "").lower(), (0.0, 0.0))[:2], dtype=np.float64)
        t = M @ ins - A @ base
        m = np.zeros((4, 4))
        m[0, :2] = A[:, 0]
        m[1, :2] = A[:, 1]
        m[2, 2] = 1.0
        m[3, :2] = t
        m[3, 3] = 1.0
        return m

    def _matrix44_3d(self):
        from ezdxf.math import OCS, Matrix44, Vec3

        d = self.dxf
        ocs = OCS(d.extrusion)
        sx, sy, sz = float(d.get("xscale", 1.0)), float(d.get("yscale", 1.0)), float(d.get("zscale", 1.0))
        m = Matrix44.chain(Matrix44.scale(sx, sy, sz), Matrix44.z_rotate(math.radians(float(d.get("rotation", 0.0)))),
                           Matrix44.ucs(ocs.ux, ocs.uy, ocs.uz))
        base = Vec3(self._doc._base_points.get(d.get("name", "").lower(), (0.0, 0.0, 0.0)))
        t = Vec3(ocs.to_wcs(Vec3(d.get("insert", (0, 0, 0))))) - m.transform_direction(base)
        m.set_row(3, (t.x, t.y, t.z, 1.0))
        return np.array([list(m.get_row(i)) for i in range(4)])

    def multi_insert(self) -> Iterator["_Insert"]:
        d = self.dxf._d
        rot = math.radians(float(d.get("rotation") or 0.0))
        c, s = math.cos(rot), math.sin(rot)
        ins = d.get("insert") or (0.0, 0.0, 0.0)
        for r in range(int(d.get("row_count") or 1)):
            for k in range(int(d.get("column_count") or 1)):
                ox, oy = k * float(d.get("column_spacing") or 0.0), r * float(d.get("row_spacing") or 0.0)
                dd = dict(d)
                dd["insert"] = (ins[0] + c * ox - s * oy, ins[1] + s * ox + c * oy, ins[2])
                dd["row_count"] = dd["column_count"] = 1
                one = _Insert(self._h, dd, self._doc)
                one.attribs = self.attribs if (r, k) == (0, 0) else []
                yield one


class _Layer:
    __slots__ = ("dxf", "_frozen", "_off")

    def __init__(self, name, frozen, off):
        self.dxf = _Dxf({"name": name})
        self._frozen, self._off = frozen, off

    def is_frozen(self):
        return self._frozen

    def is_off(self):
        return self._off


class _Layout(list):
    def __init__(self, name, entities=()):
        super().__init__(entities)
        self.name = name


class _BlockRecord:
    """``block_layout.block``: the BLOCK entity (ezdwg gives no xref path for DWG blocks)."""

    def __init__(self, name, base_point, is_xref=False):
        self.is_xref = is_xref
        self.dxf = _Dxf({"name": name, "base_point": base_point, "xref_path": ""})


class _Block(list):
    def __init__(self, name, base_point, entities=()):
        super().__init__(entities)
        self.name = name
        self.block = _BlockRecord(name, base_point)


class _Blocks:
    def __init__(self):
        self._by_key: Dict[str, _Block] = {}

    def add(self, blk: _Block) -> None:
        self._by_key.setdefault(blk.name.lower(), blk)

    def get(self, name, default=None):
        return self._by_key.get(str(name).lower(), default)

    def __contains__(self, name):
        return str(name).lower() in self._by_key

    def __iter__(self):
        return iter(self._by_key.values())

    def __len__(self):
        return len(self._by_key)


class DwgDocument:
    """The subset of an ezdxf Drawing that the CAD import uses, filled from a DWG."""

    def __init__(self, path: str, version: str):
        self.path = path
        self.dxfversion = version
        self.version = version
        self.release = DWG_VERSIONS.get(version, version)
        self.blocks = _Blocks()
        self.layers: List[_Layer] = []
        self.header: Dict[str, object] = {}
        self._msp = _Layout("Model")
        self._paper = _Layout("Layout1")
        self.layouts = [self._msp, self._paper]
        self._base_points: Dict[str, Tuple[float, float, float]] = {}
        self.undecoded: Dict[str, int] = {}  # entity type -> count the reader could not decode
        self.counts: Dict[str, int] = {}  # entity type -> count decoded (all spaces and blocks)
        self.timings: Dict[str, float] = {}
        self.codepage: Optional[int] = None

    def modelspace(self) -> _Layout:
        return self._msp


# ------------------------------------------------------------------------------------------ reading
def _guard(base: str, what: str, fn, *args):
    try:
        return fn(*args)
    except (InputError, KeyboardInterrupt, SystemExit):
        raise
    except BaseException as exc:  # ValueError/OSError on broken files; a Rust panic is a BaseException
        raise InputError(f"'{base}' is a damaged or truncated DWG: its {what} cannot be decoded "
                         f"({type(exc).__name__}: {exc}). Open it in a CAD program (AUDIT / RECOVER) and save it "
                         "again, or export it as DXF") from None


def _soft(fn, *args, default=None):
    try:
        return fn(*args)
    except (KeyboardInterrupt, SystemExit):
        raise
    except BaseException:  # an optional table: the drawing reads without it
        return default


def _unused_block_members(inserts, block_of_handle, placements, model_owners, paper_owners) -> set:
    """Handles of the entities that belong to a block no INSERT / MINSERT of the drawing names (none when the
    references cannot be read): exploding never reaches them, so they need not be built."""
    if inserts is None:
        return set()
    try:
        ins_rows, mins_rows = inserts
        named = {str(r[8]).lower() for r in ins_rows if len(r) > 8 and r[8]}
        named |= {str(r[8][4]).lower() for r in mins_rows if len(r) > 8 and r[8] and r[8][4]}
    except (TypeError, ValueError, IndexError):
        return set()
    idle = {h for h, blk in block_of_handle.items() if blk.name.lower() not in named}
    if not idle:
        return set()
    return {int(h) for h, (mode, owner) in placements.items() if mode not in (1, 2) and owner in idle
            and owner not in model_owners and owner not in paper_owners}


def read_dwg(path: str, progress=None):
    """Read a DWG into a ``DwgDocument``. Returns ``(doc, repairs)`` like ``cad_import._read_doc``."""
    import ezdwg  # the pinned reader (requirements.txt); its native core does the decoding
    from ezdwg import raw

    progress = ensure(progress)
    base = os.path.basename(path)
    version = check_dwg(path)
    t0 = time.perf_counter()
    doc = DwgDocument(path, version)
    repairs: List[str] = []
    p = path

    # ---- object map: every entity's type (for the undecoded report) and the file's integrity
    headers = _guard(base, "object map", raw.list_object_headers_with_type, p)
    etype_of: Dict[int, str] = {int(row[0]): str(row[4]) for row in headers if len(row) >= 6 and row[5] == "E"}
    if not etype_of:
        raise InputError(f"'{base}' holds no entities that the DWG reader can find (a damaged or truncated file, "
                         "or an empty drawing); open it in a CAD program and save it again, or export it as DXF")
    progress.step(5, f"{base}: DWG {doc.release} ({version}), {len(etype_of)} entities")

    # ---- tables
    hv = _soft(raw.decode_header_variables, p, default=None)
    if hv:
        doc.header["$INSUNITS"] = hv[0] if hv[0] is not None else 0
    layer_names = {int(h): str(n) for h, n in _guard(base, "layer table", raw.decode_layer_names, p)}
    states = {}
    try:
        from ezdwg.layers import build_layer_table

        for lay in build_layer_table(p, None):
            states[int(lay.handle)] = (bool(lay.frozen), not bool(lay.on))
    except (KeyboardInterrupt, SystemExit):
        raise
    except BaseException:  # no states: every layer counts as visible
        pass
    seen_names = set()
    for h, name in layer_names.items():
        if name in seen_names:
            continue
        seen_names.add(name)
        fr, off = states.get(h, (False, False))
        doc.layers.append(_Layer(name, fr, off))
    blocks = _guard(base, "block table", raw.decode_write_blocks, p)
    block_of_handle: Dict[int, _Block] = {}
    model_owners, paper_owners = set(), set()
    # anonymous blocks: the block rows say '*U', the block header names '*U12' as INSERTs do
    header_names = {int(h): str(n) for h, n in _soft(raw.decode_block_header_names, p, default=[]) or []}
    for b in blocks:
        h = int(b.get("handle") or 0)
        name = header_names.get(h) or str(b.get("name") or "")
        if not name:
            continue
        up = name.upper()
        if up in ("*MODEL_SPACE", "*MODEL SPACE", "MODELSPACE"):
            model_owners.add(h)
            continue
        if up.startswith("*PAPER_SPACE"):
            paper_owners.add(h)
            continue
        bp = tuple(b.get("base_point") or (0.0, 0.0, 0.0))
        blk = doc.blocks.get(name)
        if blk is None:
            blk = _Block(name, bp)
            doc.blocks.add(blk)
            doc._base_points[name.lower()] = bp
        block_of_handle[h] = blk
    placements = {int(row[0]): (int(row[1]), int(row[2]))
                  for row in _guard(base, "entity placement", raw.decode_entity_placements, p)}
    lname = layer_names.get
    layer_of: Dict[int, str] = {int(row[0]): lname(row[1]) for row in
                                _soft(raw.decode_entity_linetypes, p, default=[]) or [] if lname(row[1]) is not None}
    # (handle, thickness, extrusion, elevation)
    geom = {int(row[0]): row for row in _soft(raw.decode_write_geometry, p, default=[]) or []}
    doc.timings["tables"] = time.perf_counter() - t0
    progress.step(20, "decoding entities")

    counts: Counter = Counter()
    got: set = set()

    def common(h: int) -> dict:
        return {"layer": layer_of.get(h, "0")}

    def extrusion(h: int):
        g = geom.get(h)
        return g[2] if g is not None and g[2] is not None else None

    ents: List[_Entity] = []
    # entities of blocks that no INSERT names (dimension blocks, purged leftovers: SIST-F5 holds 30k of them)
    # are counted but never built: nothing explodes them
    early_inserts = _soft(raw.decode_insert_minsert_entities, p, default=None)
    unused = _unused_block_members(early_inserts, block_of_handle, placements, model_owners, paper_owners)

    def add(e: Optional[_Entity], kind: str, h: Optional[int] = None):
        if e is None or (kind != "INSERT" and e._h in unused):  # counted, not built / kept
            counts[kind] += 1
            got.add(e._h if e is not None else h)
            return
        ents.append(e)
        counts[kind] += 1
        got.add(e._h)

    # LINE / ARC / CIRCLE
    lines, arcs, circles = _guard(base, "lines, arcs and circles", raw.decode_line_arc_circle_entities, p)
    lget = layer_of.get
    for h, sx, sy, sz, ex, ey, ez in lines:
        got.add(h)
        if h not in unused:
            ents.append(_Entity("LINE", h, {"layer": lget(h, "0"), "start": (sx, sy), "end": (ex, ey)}))
    counts["LINE"] += len(lines)
    for h, cx, cy, cz, r, a0, a1 in arcs:
        d = common(h)
        d.update(center=(cx, cy, cz), radius=r, start_angle=math.degrees(a0), end_angle=math.degrees(a1),
                 extrusion=extrusion(h))
        add(_Entity("ARC", h, d), "ARC")
    for h, cx, cy, cz, r in circles:
        d = common(h)
        d.update(center=(cx, cy, cz), radius=r, extrusion=extrusion(h))
        add(_Entity("CIRCLE", h, d), "CIRCLE")
    progress.step(30)
    # LWPOLYLINE
    for h, flags, pts, bulges, widths, cw in _guard(base, "polylines", raw.decode_lwpolyline_entities, p):
        n = len(pts)
        if n == 0:
            continue
        b = list(bulges)[:n] + [0.0] * max(0, n - len(bulges))
        w = list(widths)[:n] + [(0.0, 0.0)] * max(0, n - len(widths))
        rows = [(pts[i][0], pts[i][1], w[i][0], w[i][1], b[i]) for i in range(n)]
        d = common(h)
        d.update(const_width=cw or 0.0, extrusion=extrusion(h))
        add(_LwPolyline(h, d, rows, bool(int(flags) & 0x200)), "LWPOLYLINE")
    # POLYLINE 2D / 3D
    for h, flags, verts in _soft(raw.decode_polyline_2d_with_vertex_data, p, default=[]) or []:
        vs = [_Vertex({"location": (v[0], v[1], v[2]), "start_width": v[3], "end_width": v[4], "bulge": v[5]})
              for v in verts if not (int(v[7]) & 16)]  # flag 16: spline frame control point
        if not vs:
            continue
        d = common(h)
        d["extrusion"] = extrusion(h)
        add(_Polyline(h, d, "AcDb2dPolyline", vs, bool(int(flags) & 1)), "POLYLINE_2D")
    for h, _flags, closed, pts in _soft(raw.decode_polyline_3d_with_vertices, p, default=[]) or []:
        vs = [_Vertex({"location": tuple(v)}) for v in pts]
        if vs:
            add(_Polyline(h, common(h), "AcDb3dPolyline", vs, bool(closed)), "POLYLINE_3D")
    # SPLINE / ELLIPSE
    for h, fl, _tol, knots, ctrl, weights, fit in _soft(raw.decode_spline_entities, p, default=[]) or []:
        _scen, degree, _rat, closed, _per = fl
        add(_Spline(h, common(h), int(degree), bool(closed), list(knots), list(ctrl), list(weights), list(fit)),
            "SPLINE")
    for h, c, major, ex, ratio, p0, p1 in _soft(raw.decode_ellipse_entities, p, default=[]) or []:
        d = common(h)
        d.update(center=c, major_axis=major, extrusion=ex, ratio=ratio, start_param=p0, end_param=p1)
        add(_Ellipse("ELLIPSE", h, d), "ELLIPSE")
    # SOLID / TRACE / 3DFACE
    for kind, fn in (("SOLID", raw.decode_solid_entities), ("TRACE", raw.decode_trace_entities)):
        for h, v0, v1, v2, v3, _th, ex in _soft(fn, p, default=[]) or []:
            d = common(h)
            d.update(vtx0=v0, vtx1=v1, vtx2=v2, vtx3=v3, extrusion=ex)
            add(_Entity(kind, h, d), kind)
    for h, v0, v1, v2, v3, _fl in _soft(raw.decode_3dface_entities, p, default=[]) or []:
        d = common(h)
        d.update(vtx0=v0, vtx1=v1, vtx2=v2, vtx3=v3)
        add(_Entity("3DFACE", h, d), "3DFACE")
    progress.step(45)
    # HATCH (boundaries come flattened to polylines)
    for h, name, solid, _assoc, _elev, ex, paths in _guard(base, "hatches", raw.decode_hatch_entities, p):
        ps = [PolylinePath(pts) for _closed, pts in paths if len(pts) >= 2]
        d = common(h)
        d.update(pattern_name=name, solid_fill=1 if solid else 0, extrusion=ex)
        add(_Hatch(h, d, ps), "HATCH")
    progress.step(55)
    # TEXT / MTEXT
    for h, text, ins, align, ex, metrics, aflags, _style, _owner in _guard(base, "texts", raw.decode_text_entities, p):
        if h in unused:
            add(None, "TEXT", h)
            continue
        d = common(h)
        d.update(text=text or "", insert=ins, align_point=align, extrusion=ex, height=metrics[2],
                 rotation=math.degrees(metrics[3]), halign=aflags[1], valign=aflags[2])
        add(_Text("TEXT", h, d), "TEXT")
    for row in _guard(base, "multiline texts", raw.decode_mtext_entities, p):
        h, text, ins, ex, xdir, _w, th = row[:7]
        if h in unused:
            add(None, "MTEXT", h)
            continue
        d = common(h)
        d.update(text=text or "", insert=ins, extrusion=ex, char_height=th,
                 rotation=math.degrees(math.atan2(xdir[1], xdir[0])) if xdir else 0.0)
        add(_MText(h, d), "MTEXT")
    # INSERT / MINSERT and their ATTRIBs
    ins_rows, mins_rows = (early_inserts if early_inserts is not None else
                           _guard(base, "block references", raw.decode_insert_minsert_entities, p))
    inserts: Dict[int, _Insert] = {}
    nameless = 0
    for rows, kind in ((ins_rows, "INSERT"), (mins_rows, "MINSERT")):
        for row in rows:
            h, px, py, pz, sx, sy, sz, rot, name = row[:9]
            grid = {}
            if kind == "MINSERT":  # the last field: (columns, rows, column spacing, row spacing, name)
                ncol, nrow, csp, rsp, name = name
                grid = dict(column_count=ncol, row_count=nrow, column_spacing=csp, row_spacing=rsp)
            if not name:
                nameless += 1
                got.add(h)
                continue
            d = common(h)
            d.update(name=name, insert=(px, py, pz), xscale=sx, yscale=sy, zscale=sz, rotation=math.degrees(rot),
                     extrusion=extrusion(h), **grid)
            e = _Insert(h, d, doc)
            inserts[h] = e
            add(e, kind)
    n_attr = 0
    for row in _soft(raw.decode_attrib_entities, p, default=[]) or []:
        h, text, tag, _prompt, ins, align, ex, metrics, aflags, flags, _lock, so = row
        owner = so[1] if isinstance(so, tuple) and len(so) > 1 else None
        if owner is None:
            owner = placements.get(int(h), (0, 0))[1]
        parent = inserts.get(int(owner)) if owner else None
        got.add(h)
        if parent is None:
            continue
        d = common(h)
        d.update(text=text or "", tag=tag or "", insert=ins, align_point=align, extrusion=ex, height=metrics[2],
                 rotation=math.degrees(metrics[3]), halign=aflags[1], valign=aflags[2], attribute_flags=flags)
        parent.attribs.append(_Text("ATTRIB", h, d))
        counts["ATTRIB"] += 1
        n_attr += 1
    undecoded: Counter = Counter()
    if nameless:  # reported with the undecoded types, not as a repair: nothing was repaired
        undecoded["INSERT (block name unreadable)"] = nameless
    progress.step(75, "sorting entities into model space and blocks")

    # ---- count-only and undecoded entities (by the object map), so layers and reports see them
    for h, tname in etype_of.items():
        if h in got or tname in _PARTS:
            continue
        if tname in _COUNT_ONLY:
            if h not in unused:
                ents.append(_Entity(_COUNT_ONLY[tname], h, common(h)))
            continue
        undecoded[tname] += 1
        if h not in unused:
            ents.append(_Entity(tname, h, common(h)))  # the import counts and reports it as unsupported
    # ---- membership
    ents.sort(key=lambda e: e._h)
    for e in ents:
        mode, owner = placements.get(e._h, (2, 0))
        if owner in model_owners or (mode == 2):
            doc._msp.append(e)
        elif owner in paper_owners or mode == 1:
            doc._paper.append(e)
        else:
            blk = block_of_handle.get(owner)
            if blk is not None:
                blk.append(e)
            elif owner in inserts or owner == 0:
                doc._msp.append(e)  # placement unknown: keep it visible, as ezdwg does
    # ezdwg keeps decoded tables per path in module caches; the document holds what we need, so release
    # them (a QGIS session reading many sheets must not keep every file's rows alive)
    _soft(ezdwg.clear_decode_caches)
    doc.undecoded = dict(undecoded)
    doc.counts = dict(counts)
    doc.codepage = _soft(_codepage, path)
    doc.timings["read"] = time.perf_counter() - t0
    progress.step(100, f"{base}: {len(doc._msp)} model-space entities, {len(doc.blocks)} blocks, "
                       f"{sum(counts.values())} entities decoded in {doc.timings['read']:.1f} s")
    if undecoded:
        progress.warning(undecoded_message(doc.undecoded))
    return doc, repairs


def undecoded_message(undecoded: Dict[str, int]) -> str:
    parts = ", ".join(f"{n} {t}" for t, n in sorted(undecoded.items(), key=lambda kv: (-kv[1], kv[0])))
    return (f"the DWG reader cannot decode {sum(undecoded.values())} entities ({parts}); they are left out. "
            "Custom objects (e.g. Tianzheng TCH_*) can be exploded or saved as plain AutoCAD entities in the CAD "
            "program first")


def _codepage(path: str) -> Optional[int]:
    with open(path, "rb") as fh:
        head = fh.read(0x20)
    return struct.unpack_from("<H", head, 0x13)[0]
