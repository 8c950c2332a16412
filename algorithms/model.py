"""Data passed between pipeline stages.

Coordinates are metres in the drawing's own frame ("CAD frame": x right/east, y up/north) unless a
stage says otherwise. Polygons and lines are shapely 2 geometries.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

# Occupancy raster convention (documented in the README): uint8, 0 = free, 255 = occupied,
# 128 = unknown (robot maps only; unknown is never treated as free space).
FREE = 0
OCCUPIED = 255
UNKNOWN = 128

# Structural categories the layer rules map layers onto.
KINDS = ("wall", "column", "window", "door", "stair", "elevator", "reference", "other")


# --------------------------------------------------------------------------- stage 1: CAD import
@dataclass
class CadGeometry:
    """One flattened piece of drawing geometry, already exploded out of blocks, in metres."""

    layer: str  # effective layer (layer "0" inside a block takes the INSERT's layer)
    kind: str  # one of KINDS, from the layer rules
    coords: np.ndarray  # (N, 2) float64, metres
    closed: bool = False
    filled: bool = False  # solid hatch / SOLID / wide polyline outline: rasterize as a filled polygon
    width: float = 0.0  # constant polyline width in metres (0 = hairline)
    entity: str = ""  # source DXF type, e.g. "LWPOLYLINE"
    block: str = ""  # innermost named block it was exploded from ("" = model space)
    cls: str = ""  # class found by cad_classify: wall | door | window | furniture | hatch | "" (not classified)


@dataclass
class CadText:
    x: float
    y: float
    text: str  # plain text, formatting codes stripped
    height: float  # metres
    rotation: float  # degrees, counter-clockwise
    layer: str
    entity: str = "TEXT"  # TEXT | MTEXT | ATTRIB
    block: str = ""  # name of the (innermost) block the text was exploded from, "" in model space
    tag: str = ""  # ATTRIB tag (e.g. "ROOMNAME"), "" for TEXT/MTEXT
    id: int = -1  # index in CadDrawing.texts, set by the import; stable across reruns of one file


@dataclass
class DoorHint:
    """A doorway found in the drawing (door block or swing arc + leaf): the opening as a segment from
    jamb to jamb, CAD frame metres. Segmentation keeps it open and turns it into a passage when the
    areas on both sides would otherwise not be connected."""

    x0: float
    y0: float
    x1: float
    y1: float
    source: str = ""  # "block:<name>" | "swing" | "layer:<name>"

    @property
    def width(self) -> float:
        return float(np.hypot(self.x1 - self.x0, self.y1 - self.y0))


@dataclass
class PlanInfo:
    """One spatially separate group of structural geometry on a sheet (a plan, half plan or detail)."""

    index: int  # 0 = the plan taken by default (largest wall mass)
    extent: Tuple[float, float, float, float]  # xmin, ymin, xmax, ymax in metres (CAD frame)
    wall_length: float  # metres of wall geometry in the group
    title: str = ""  # the text that titles it, e.g. "三层平面图" or "楼梯放大详图"
    kind: str = "plan"  # plan | detail | legend | other
    selected: bool = False


@dataclass
class LayerInfo:
    name: str
    counts: Dict[str, int] = field(default_factory=dict)  # DXF type -> count after explosion
    kind: Optional[str] = None  # matched category, None when the rules drop the layer
    rule: str = ""  # the keyword that matched
    matched: str = ""  # the meaningful part of the name the rules matched ("A-WALL" of "E1-RI-1F$0$A-WALL")
    frozen: bool = False
    off: bool = False

    @property
    def kept(self) -> bool:
        return self.kind is not None and not self.frozen and not self.off


@dataclass
class CadDrawing:
    path: str
    geometries: List[CadGeometry]
    texts: List[CadText]
    layers: Dict[str, LayerInfo]
    unit_name: str  # unit finally used, e.g. "mm"
    unit_scale: float  # drawing units -> metres
    header_unit: str  # what $INSUNITS said
    warnings: List[str] = field(default_factory=list)
    repairs: List[str] = field(default_factory=list)  # what recover mode fixed
    doors: List["DoorHint"] = field(default_factory=list)  # doorways found (blocks, swings)
    plans: List["PlanInfo"] = field(default_factory=list)  # groups found on the sheet; selected one kept
    classes: Dict[str, int] = field(default_factory=dict)  # entity class counts (wall, door, furniture..)
    undecoded: Dict[str, int] = field(default_factory=dict)  # entity types the reader could not decode
    timings: Dict[str, float] = field(default_factory=dict)  # import stages (read, explode, classify, plans), s
    # texts on frozen / off layers, within the kept plan (ids continue after ``texts``); not drawn, but
    # stage 5 may name an area by them when no visible text names it
    hidden_texts: List[CadText] = field(default_factory=list)
    # projection / dash-dot lines no rule keeps (cad_classify.boundary_evidence): never walls, only a boundary
    # the envelope may not cross (rasterize.boundary_mask -> segmentation.segment(boundary=...))
    boundary: List[CadGeometry] = field(default_factory=list)
    # folding partitions (cad_classify.folding_partitions): lines where a room may be split between two names
    partitions: List[CadGeometry] = field(default_factory=list)
    # stair / lift symbols the drawing holds but does not show (off / frozen layers, lift-named blocks), found when
    # it shows none (cad_explode.kept_symbols): evidence of stair / lift areas only, never drawn or rasterized
    hidden_symbols: List[CadGeometry] = field(default_factory=list)


# --------------------------------------------------------------------------- stage 2: raster
@dataclass
class OccupancyGrid:
    """A north-up occupancy raster. Pixel (row, col) covers
    x in [origin_x + col*res, origin_x + (col+1)*res], y in [origin_y - (row+1)*res, origin_y - row*res].
    """

    data: np.ndarray  # (rows, cols) uint8: FREE / OCCUPIED / UNKNOWN
    origin_x: float  # x of the top-left corner of pixel (0, 0)
    origin_y: float  # y of the top-left corner of pixel (0, 0)
    resolution: float  # metres per pixel
    crs_wkt: str = ""  # empty: the CAD frame (local engineering coordinates)

    @property
    def shape(self) -> Tuple[int, int]:
        return self.data.shape  # type: ignore[return-value]

    @property
    def geotransform(self) -> Tuple[float, float, float, float, float, float]:
        return (self.origin_x, self.resolution, 0.0, self.origin_y, 0.0, -self.resolution)

    @property
    def extent(self) -> Tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax)"""
        rows, cols = self.data.shape
        return (self.origin_x, self.origin_y - rows * self.resolution,
                self.origin_x + cols * self.resolution, self.origin_y)

    def pixel_to_world(self, col, row):
        """Pixel *corner* coordinates (col, row may be fractional; +0.5 gives centres) -> (x, y)."""
        return (self.origin_x + np.asarray(col) * self.resolution,
                self.origin_y - np.asarray(row) * self.resolution)

    def world_to_pixel(self, x, y):
        """(x, y) -> fractional (col, row) of pixel corners."""
        return ((np.asarray(x) - self.origin_x) / self.resolution,
                (self.origin_y - np.asarray(y)) / self.resolution)


# --------------------------------------------------------------------------- stage 3+: area graph
@dataclass
class Area:
    id: int
    polygon: "object"  # shapely Polygon, CAD frame metres
    type: str = "room"  # room | corridor | stairs | elevator | structure
    name: str = ""
    max_clearance: float = 0.0  # metres
    tags: Dict[str, str] = field(default_factory=dict)  # extra osmAG/OSM tags
    ref: str = ""  # room number from the drawing ("A007", "E1-ST-03"), "" when none
    component: int = 0  # connected component of the floor's area graph (0 = the largest)

    @property
    def area(self) -> float:
        return float(self.polygon.area)

    @property
    def perimeter(self) -> float:
        return float(self.polygon.length)


@dataclass
class Passage:
    id: int
    from_id: int
    to_id: int
    line: "object"  # shapely LineString with exactly two points, on the walls at both ends
    name: str = ""
    tags: Dict[str, str] = field(default_factory=dict)

    @property
    def width(self) -> float:
        return float(self.line.length)


@dataclass
class AreaGraph:
    areas: List[Area]
    passages: List[Passage]
    labels: Optional[np.ndarray] = None  # int32 raster of area ids on ``grid`` (0 = no area)
    grid: Optional[OccupancyGrid] = None
    stats: Dict[str, float] = field(default_factory=dict)  # timings (s) and figures for the log
    skeleton: Optional[object] = None  # the skeleton graph segmentation used (skeleton.SkeletonGraph)
    skeleton_grid: Optional[OccupancyGrid] = None  # the grid the skeleton lies on (None: ``grid``)

    def area_by_id(self) -> Dict[int, Area]:
        return {a.id: a for a in self.areas}


def valid_polygon(poly):
    """A polygon that touches or crosses itself (a ring pinched after a coordinate round trip, e.g. through
    lon/lat at 7 decimals, ~1 cm, or a pixel outline meeting itself) is repaired: a ring that passes one
    vertex twice is opened there and stays one ring (:func:`open_ring_pinches`; ``buffer(0)`` would turn the
    loop round a void into a hole, which an osmAG area cannot hold); anything else with ``buffer(0)``, keeping
    the largest part if it splits (the slivers are below a few cm²). A valid polygon is returned as given."""
    if poly is None or getattr(poly, "geom_type", "") != "Polygon" or poly.is_empty or poly.is_valid:
        return poly
    opened = open_ring_pinches(poly)  # a ring touching itself at a vertex stays one ring
    if opened is not None:
        return opened
    fixed = poly.buffer(0)
    if fixed.geom_type == "MultiPolygon":
        fixed = max(fixed.geoms, key=lambda g: g.area)
    return fixed if fixed.geom_type == "Polygon" and not fixed.is_empty else poly


#: how far :func:`open_ring_pinches` moves a repeated vertex into its own corner (metres): well above the
#: precision areas are written with (lon/lat at 10 decimals, ~0.01 mm; 7 decimals, ~1 cm, in other tools'
#: files is covered by the read-side tolerance) and far below anything a robot map resolves
PINCH_OPEN = 0.005


def _inward_offsets(xy: np.ndarray, idx: Sequence[int], dist: float) -> np.ndarray:
    """Points ``dist`` from the vertices ``xy[idx]`` of the open ring ``xy`` (counter-clockwise) along
    the bisector of their corner, into the ring's interior (left of both edges)."""
    n = len(xy)
    out = []
    for i in idx:
        p, x, q = xy[(i - 1) % n], xy[i], xy[(i + 1) % n]
        u1, u2 = x - p, q - x
        u1 = u1 / max(float(np.hypot(*u1)), 1e-300)
        u2 = u2 / max(float(np.hypot(*u2)), 1e-300)
        b = np.array([-u1[1], u1[0]]) + np.array([-u2[1], u2[0]])
        nb = float(np.hypot(*b))
        if nb < 1e-9:  # a spike (the ring turns back on itself): step along its inward side
            b, nb = np.array([-u1[1], u1[0]]), 1.0
        out.append(x + b / nb * dist)
    return np.asarray(out, dtype=float).reshape(-1, 2)


def pinch_indices(ids: Sequence) -> List[int]:
    """Positions of an open ring (a sequence of vertex keys: node ids or coordinate tuples) that repeat
    a vertex met earlier on the ring: the ring touches itself there (a "pinch")."""
    seen = set()
    out = []
    for k, v in enumerate(ids):
        if v in seen:
            out.append(k)
        seen.add(v)
    return out


def open_pinched_ring(xy: np.ndarray, reps: Sequence[int], dist: float = PINCH_OPEN, holes=()) -> Optional[np.ndarray]:
    """The open counter-clockwise ring ``xy`` with its repeated visits ``reps`` (:func:`pinch_indices`)
    moved ``dist`` into their corner, or out of it, whichever gives a valid polygon (with ``holes``); None if
    neither does."""
    from shapely.geometry import Polygon

    xy = np.asarray(xy, dtype=float)
    reps = list(reps)
    # a slit into the area opens into its corner (+), a spike out of it (a zero-width finger: the ring goes
    # out and back along the same nodes) opens the other way (-); each visit may need either
    signs = list(itertools.product((1.0, -1.0), repeat=len(reps))) if len(reps) <= 6 else [(1.0,), (-1.0,)]
    for scale in (1.0, 0.2, 4.0):
        step = _inward_offsets(xy, reps, dist * scale) - xy[reps]
        for sg in signs:
            new = xy.copy()
            new[reps] = xy[reps] + step * np.asarray(sg, float).reshape(-1, 1)
            fixed = Polygon(new, list(holes))
            if fixed.is_valid and not fixed.is_empty:
                return new
    return None


def open_ring_pinches(poly, dist: float = PINCH_OPEN):
    """A polygon whose exterior ring touches itself at a vertex (the ring passes the same point twice, as
    an osmAG way round an atrium void does when its two sides meet at one node) as *one* ring: every
    repeated visit after the first is moved ``dist`` into its own corner (or out of it, for a zero-width
    spike: the ring going out and back along the same nodes), so the loop stays part of the
    exterior instead of becoming a hole (``buffer(0)`` would make it one, and an osmAG area drops holes).
    The first visit keeps its exact position (a node shared with neighbours and passages stays shared).
    Returns the valid polygon, or None when the ring has no such pinch or is still invalid after opening it
    (crossing edges rather than a touch)."""
    from shapely.geometry import Polygon

    if poly is None or getattr(poly, "geom_type", "") != "Polygon" or poly.is_empty:
        return None
    xy = np.asarray(poly.exterior.coords, dtype=float)[:-1, :2]
    if len(xy) < 4:
        return None
    ccw = poly.exterior.is_ccw
    if not ccw:
        xy = xy[::-1]
    reps = pinch_indices([tuple(p) for p in xy.tolist()])
    if not reps:
        return None
    holes = [np.asarray(r.coords)[::-1] if r.is_ccw else np.asarray(r.coords) for r in poly.interiors]
    new = open_pinched_ring(xy, reps, dist, holes)
    if new is None:
        return None
    return Polygon(new if ccw else new[::-1], [list(r.coords) for r in poly.interiors])


class _LabelCell:
    """A cell of :func:`polylabel`'s priority queue: ordered as shapely's ``polylabel`` orders its cells (a
    cell is "less" when its bound on the distance is larger; only ``<`` is used by ``heapq``, so cells with
    equal bounds come out in the same order as there)."""

    __slots__ = ("x", "y", "h", "distance", "max_distance")

    def __init__(self, x: float, y: float, h: float, distance: float):
        self.x, self.y, self.h, self.distance = x, y, h, distance
        self.max_distance = distance + h * 1.4142135623730951  # sqrt(2)

    def __lt__(self, other: "_LabelCell") -> bool:
        return self.max_distance > other.max_distance


def polylabel(polygon, tolerance: float = 1.0):
    """The pole of inaccessibility of ``polygon``: exactly ``shapely.ops.polylabel(polygon, tolerance)``
    (the same grid, cells, queue order and GEOS predicates), but each batch of cells (the first grid, the
    four children of a split) is measured in one vectorised ``contains`` / ``distance`` call instead of one
    Point and four GEOS calls per cell (~8x less CPU on a shaft outline). Raises shapely's
    ``TopologicalError`` for an invalid polygon, as shapely's does."""
    from heapq import heappop, heappush

    import shapely
    from shapely.errors import TopologicalError
    from shapely.geometry import Point

    if not polygon.is_valid:
        raise TopologicalError("Invalid polygon")
    rings = [polygon.exterior] + list(polygon.interiors)

    def signed(xs, ys) -> list:
        pts = shapely.points(np.asarray(xs, float), np.asarray(ys, float))
        inside = shapely.contains(polygon, pts)
        d = shapely.distance(pts, rings[0])
        for ring in rings[1:]:
            d = np.minimum(d, shapely.distance(pts, ring))
        return np.where(inside, d, -d).tolist()

    minx, miny, maxx, maxy = polygon.bounds
    width = maxx - minx
    height = maxy - miny
    cell_size = min(width, height)
    h = cell_size / 2.0
    cx, cy = polygon.centroid.coords[0]
    bx, by = minx + width / 2.0, miny + height / 2
    d_c, d_b = signed([cx, bx], [cy, by])
    best = _LabelCell(bx, by, 0, d_b) if d_b > d_c else _LabelCell(cx, cy, 0, d_c)
    xs, ys = [], []
    x = minx
    while x < maxx:
        y = miny
        while y < maxy:
            xs.append(x + h)
            ys.append(y + h)
            y += cell_size
        x += cell_size
    queue: list = []
    for x, y, d in zip(xs, ys, signed(xs, ys) if xs else []):
        heappush(queue, _LabelCell(x, y, h, d))
    while queue:
        cell = heappop(queue)
        if cell.distance > best.distance:
            best = cell
        if cell.max_distance - best.distance <= tolerance:
            continue
        h = cell.h / 2.0
        xs = [cell.x - h, cell.x + h, cell.x - h, cell.x + h]
        ys = [cell.y - h, cell.y - h, cell.y + h, cell.y + h]
        for x, y, d in zip(xs, ys, signed(xs, ys)):
            heappush(queue, _LabelCell(x, y, h, d))
    return Point(best.x, best.y)
