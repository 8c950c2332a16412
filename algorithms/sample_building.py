"""Built-in sample building: a deterministic, realistic multi-floor DXF set with ground truth.

``generate_building`` writes one DXF per floor (``<name>-F<k>.dxf``, AutoCAD R2018, millimetres,
``$INSUNITS = 4``) plus its ground truth (``<name>-F<k>.gt.geojson``, metres in the drawing frame).
The drawings imitate what architects deliver, so that every later stage can be tested on them:

* A 40 x 25 m office floor. Walls on ``A-WALL`` drawn as outlines (closed LWPOLYLINEs or LINE
  pairs) of real thickness: exterior 300 mm, corridor walls 200 mm, partitions 150 mm; the
  concrete core (stair and lift) walls are 200 mm with a SOLID hatch. Columns on ``A-COLS``.
* Doors: a gap in the wall plus a door BLOCK (leaf LINE + swing ARC on layer "0") inserted on
  ``A-DOOR`` with rotation and, where the hinge side demands it, mirroring (x scale -1).
  Single doors 0.8-1.0 m, a 1.8 m double door from the hall to the corridor, and a 1.8 m main
  entrance on floor 1. Windows on ``A-GLAZ``: exterior wall gaps with 2-3 glazing lines.
* A stair core (``A-STAIR``: treads, stringers, walking-line arrow) and a lift shaft (``A-FLOR-EVTR``,
  car rectangle with a cross) at identical coordinates on every floor.
* A central corridor (1.8-2.4 m; the width varies by floor and may step once along the floor),
  offices on both sides, an open hall of about 12 x 11 m ("Hall"), a WC block, an office that
  wraps around the core.
* Part of the north offices is an ``OFFICE_MODULE`` block (front wall and partition on layer "0",
  a nested door block on ``A-DOOR`` and nested workstation blocks on ``A-FURN``) inserted on
  ``A-WALL`` with rotation 180 or mirrored.
* Furniture blocks on ``A-FURN`` (a WORKSTATION block nests DESK and CHAIR), WC fittings on
  ``P-SANR-FIXT``, DIMENSION entities on ``A-ANNO-DIMS``, a title on ``A-ANNO-TITL``, far-reaching
  grid axes with bubbles on ``S-GRID``, floor pattern hatches on ``A-FLOR-PATT``.
* Room names on ``A-ANNO-TEXT`` as TEXT, as MTEXT with formatting codes (``{\\fArial|b1;Office}
  105``, ``Meeting\\PRoom 105``) and, for a few rooms, as the NAME ATTRIB of a ``ROOM_TAG`` block.

Ground truth (one GeoJSON FeatureCollection per floor, coordinates in metres = mm / 1000):

* ``{"kind": "room", "name", "areatype": room|corridor|stairs|elevator, "level"}`` Polygons: the
  free floor space bounded by the wall faces (columns cut out). **Door openings belong to neither
  side**: a room polygon is closed by the straight line joining the two jamb corners on its own
  wall face, so the strip of floor inside the wall thickness of an opening is in no polygon.
* ``{"kind": "door", "from", "to", "width", "level"}`` LineStrings: the segment across an opening
  on the midline of the wall thickness, its endpoints on the jambs. ``to`` is ``"outside"`` for
  the main entrance.
* ``{"kind": "anchor", "name": "Stair A" | "Lift 1", "areatype", "level"}`` Points.
* ``{"kind": "envelope", "level"}`` the building outline polygon.

Names equal the DXF text once formatting codes are removed and a paragraph break (``\\P``) is
read as a single space ("Meeting\\PRoom 105" -> "Meeting Room 105").

The room polygons are computed, not typed in: free space = interior minus every wall, column and
door-opening rectangle; each connected component must contain exactly one room label, which the
generator checks, so the ground truth is consistent with the drawing by construction.
"""
from __future__ import annotations

import json
import math
import os
import random
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

from shapely.geometry import LineString, Point, Polygon, box, shape
from shapely.ops import unary_union

from .errors import InputError
from .io_utils import atomic_path, atomic_write
from .progress import ensure

# --------------------------------------------------------------------------- fixed dimensions (mm)
WIDTH = 40000
DEPTH = 25000
T_EXT = 300  # exterior walls
T_COR = 200  # corridor walls
T_PART = 150  # partitions
T_CORE = 200  # stair / lift enclosure
X0, X1 = T_EXT, WIDTH - T_EXT  # interior faces of the exterior walls
Y0, Y1 = T_EXT, DEPTH - T_EXT
Y_CN = 14000  # corridor north face (fixed: the north offices and the core hang on it)
Y_NZ = Y_CN + T_COR  # north zone starts here
MODULE_BAY = 3900  # pitch of the OFFICE_MODULE block
MODULE_DOOR = 900

# Core (identical on every floor and for every seed)
STAIR = (16200, Y_NZ, 19200, 20000)  # free space inside the enclosure
LIFT = (19400, Y_NZ, 21600, 16600)
NW_END = 16000  # west face of the stair enclosure wall
WRAP_EAST = 25000  # east boundary of the office wrapping the core (partition 25000..25150)
WC_BOX = (25150, Y_NZ, 28150, Y1)
NE_START = 28300  # east face of the WC partition

GRID_X = [200, 8100, 16100, 24000, 31900, 39800]
GRID_Y = [200, 7000, 19000, 24800]
GRID_X_LABELS = ["1", "2", "3", "4", "5", "6"]
GRID_Y_LABELS = ["A", "B", "C", "D"]

LAYERS = [
    # name, ACI colour, linetype
    ("A-WALL", 7, "Continuous"),
    ("A-COLS", 8, "Continuous"),
    ("A-DOOR", 3, "Continuous"),
    ("A-GLAZ", 4, "Continuous"),
    ("A-STAIR", 6, "Continuous"),
    ("A-FLOR-EVTR", 6, "Continuous"),  # AIA name for lift cars (A-ELEV means elevations in AIA)
    ("A-WALL-PATT", 8, "Continuous"),
    ("A-FURN", 9, "Continuous"),
    ("P-SANR-FIXT", 5, "Continuous"),
    ("A-FLOR-PATT", 252, "Continuous"),
    ("A-ANNO-TEXT", 2, "Continuous"),
    ("A-ANNO-DIMS", 1, "Continuous"),
    ("A-ANNO-TITL", 7, "Continuous"),
    ("S-GRID", 1, "CENTER"),
]

LIFT_LAYER = "A-FLOR-EVTR"
# MTEXT room labels as CAD programs write them: font/bold switch, alignment + relative height,
# colour + italic font with pitch flags. Plain text of each: "<head> <tail>".
MTEXT_FORMATS = [
    "{{\\fArial|b1;{head}}} {tail}",
    "\\A1;{{\\H1.2x;{head}}} {tail}",
    "{{\\C1;\\fArial|b0|i1|c0|p34;{head} {tail}}}",
]
DOOR_BLOCKS = {800: "DOOR_800", 900: "DOOR_900", 1000: "DOOR_1000"}
DOUBLE_DOOR_BLOCK = "DOOR_DBL_1800"
OUTSIDE = "outside"


# --------------------------------------------------------------------------- plan description
@dataclass
class Door:
    orient: str  # "h": the wall runs along x (opening spans x); "v": along y
    a0: float  # start of the opening along the wall
    width: float
    lo: float  # wall faces across the wall (y for "h", x for "v")
    hi: float
    swing: int  # +1: the leaf opens towards +y / +x, -1 towards -y / -x
    hinge: int = 0  # 0: hinge at a0, 1: at a0 + width
    block: Optional[str] = None  # None: not drawn as a block (lift doors) or drawn by a module
    kind: str = "door"

    def opening(self) -> Polygon:
        if self.orient == "h":
            return box(self.a0, self.lo, self.a0 + self.width, self.hi)
        return box(self.lo, self.a0, self.hi, self.a0 + self.width)

    def midline(self) -> Tuple[Tuple[float, float], Tuple[float, float]]:
        m = 0.5 * (self.lo + self.hi)
        if self.orient == "h":
            return (self.a0, m), (self.a0 + self.width, m)
        return (m, self.a0), (m, self.a0 + self.width)

    def probes(self) -> Tuple[Tuple[float, float], Tuple[float, float]]:
        """Points just outside both wall faces, in the middle of the opening."""
        c = self.a0 + 0.5 * self.width
        if self.orient == "h":
            return (c, self.lo - 100), (c, self.hi + 100)
        return (self.lo - 100, c), (self.hi + 100, c)


@dataclass
class Room:
    name: str
    areatype: str
    label: Tuple[float, float]  # a point inside, where the name text goes
    style: str = "text"  # text | mtext_bold | mtext_para | tag
    furniture: str = ""  # office | meeting | hall | wc | ""
    box: Optional[Tuple[float, float, float, float]] = None  # rectangle for furniture placement
    fmt: int = 0  # which of MTEXT_FORMATS a "mtext_bold" label uses


@dataclass
class ModuleInsert:
    x: float  # insertion point x (y is always Y_CN)
    mirrored: bool


@dataclass
class Window:
    orient: str  # "h" (south / north facade) or "v" (west / east facade)
    a0: float
    width: float
    lo: float
    hi: float


@dataclass
class FloorPlan:
    level: int
    walls: Dict[str, List[Polygon]] = field(default_factory=dict)  # group -> rectangles
    columns: List[Polygon] = field(default_factory=list)
    doors: List[Door] = field(default_factory=list)  # top-level doors (drawn as blocks)
    module_doors: List[Door] = field(default_factory=list)  # doors inside OFFICE_MODULE inserts
    windows: List[Window] = field(default_factory=list)
    rooms: List[Room] = field(default_factory=list)
    modules: List[ModuleInsert] = field(default_factory=list)
    corridor_widths: Tuple[float, float] = (2000, 2000)
    jog_x: Optional[float] = None


# --------------------------------------------------------------------------- module block geometry
def _module_local():
    """OFFICE_MODULE in block coordinates: origin on the corridor face, the bay spans x 0..B and the
    office extends to -y (a south-side office). Returns (wall rectangles, door spec, desk points)."""
    b = MODULE_BAY
    depth = Y1 - Y_NZ
    a = b - T_PART - 300 - MODULE_DOOR  # door near the partition end
    walls = [
        box(0, -T_COR, a, 0),
        box(a + MODULE_DOOR, -T_COR, b, 0),
        box(b - T_PART, -T_COR - depth, b, -T_COR),
    ]
    door = Door("h", a, MODULE_DOOR, -T_COR, 0, swing=-1, hinge=1, block=DOOR_BLOCKS[MODULE_DOOR])
    desks = [((b - T_PART) / 2.0 - 100, -T_COR - depth + 1100, 180.0),
             ((b - T_PART) / 2.0 - 100, -T_COR - depth + 3700, 0.0)]
    return walls, door, desks


def _module_transform(m: ModuleInsert):
    """Block -> world for an OFFICE_MODULE insert on the north side of the corridor.
    Rotation 180 maps (x, y) -> (X - x, Y - y); mirrored (x scale -1, rotation 180) -> (X + x, Y - y)."""
    if m.mirrored:
        return lambda x, y: (m.x + x, Y_CN - y)
    return lambda x, y: (m.x - x, Y_CN - y)


def _xf_box(poly: Polygon, f) -> Polygon:
    xs, ys = zip(*[f(x, y) for x, y in poly.exterior.coords])
    return box(min(xs), min(ys), max(xs), max(ys))


def _xf_door(d: Door, f, mirrored: bool) -> Door:
    (ax, ay), (bx, by) = f(d.a0, d.lo), f(d.a0 + d.width, d.hi)
    return Door("h", min(ax, bx), d.width, min(ay, by), max(ay, by), swing=-d.swing, hinge=d.hinge,
                block=None)


# --------------------------------------------------------------------------- layout
def _r50(v: float) -> int:
    return int(round(v / 50.0)) * 50


def _split(rng: random.Random, a: float, b: float, target: float, min_w: float = 3000) -> List[float]:
    """Partition centre lines that split the free span a..b (wall faces) into rooms of about
    ``target`` interior width, with some jitter. Returns the partition centres (without a and b)."""
    span = b - a
    n = max(1, int(round((span + T_PART) / (target + T_PART))))
    while n > 1 and (span - (n - 1) * T_PART) / n < min_w:
        n -= 1
    widths = [1.0 + rng.uniform(-0.18, 0.18) for _ in range(n)]
    total = sum(widths)
    free = span - (n - 1) * T_PART
    centres, x = [], a
    for w in widths[:-1]:
        x += free * w / total
        c = _r50(x + T_PART / 2.0)
        for gx in GRID_X:  # a partition ending next to a column would leave a sliver: use the column
            if abs(c - gx) < 450:
                c = gx
        centres.append(c)
        x = centres[-1] + T_PART / 2.0
    return centres


def _plan_floor(level: int, seed: int) -> FloorPlan:
    rng = random.Random(seed * 7919 + level * 104729)
    p = FloorPlan(level=level)
    walls: Dict[str, List[Polygon]] = {"exterior": [], "interior": [], "core": []}

    # ---- corridor widths (may step once along the floor)
    w_choices = [1800, 2000, 2200, 2400]
    w1 = rng.choice(w_choices)
    w2 = w1 if rng.random() < 0.4 else rng.choice([w for w in w_choices if w != w1])
    p.corridor_widths = (w1, w2)

    # ---- south zone: offices | hall | offices
    if level == 1:
        hall_w, hall_x0 = 12000, 14000
    else:
        hall_w = rng.choice([11400, 12000, 12600])
        hall_x0 = _r50(rng.uniform(9000, 39700 - 9000 - hall_w))
    hall_x1 = hall_x0 + hall_w
    target = 4400 if level == 1 else 3700
    west_c = _split(rng, X0, hall_x0 - T_PART, target)
    east_c = _split(rng, hall_x1 + T_PART, X1, target)
    south_c = west_c + [hall_x0 - T_PART / 2.0] + [hall_x1 + T_PART / 2.0] + east_c
    # the corridor steps at one partition (only if the widths differ)
    jog = rng.choice(south_c) if w1 != w2 else None
    p.jog_x = jog

    def ys_top(x: float) -> float:  # south face of the corridor at x
        return Y_CN - (w1 if (jog is None or x < jog) else w2)

    # corridor south wall
    if jog is None:
        walls["interior"].append(box(X0, Y_CN - w1 - T_COR, X1, Y_CN - w1))
    else:
        walls["interior"].append(box(X0, Y_CN - w1 - T_COR, jog + T_PART / 2, Y_CN - w1))
        walls["interior"].append(box(jog - T_PART / 2, Y_CN - w2 - T_COR, X1, Y_CN - w2))
    for c in south_c:
        top = Y_CN - min(w1, w2) if c == jog else ys_top(c) - T_COR
        walls["interior"].append(box(c - T_PART / 2, Y0, c + T_PART / 2, top))

    # south rooms (interior x ranges)
    edges = [X0] + [c for c in south_c] + [X1]
    south_rooms = []
    for i in range(len(edges) - 1):
        xa = edges[i] + (T_PART / 2 if i > 0 else 0)
        xb = edges[i + 1] - (T_PART / 2 if i + 1 < len(edges) - 1 else 0)
        south_rooms.append((xa, xb))

    # ---- north zone
    k_nw = rng.choice([2, 3])
    k_ne = rng.choice([1, 2])
    p1 = NW_END - k_nw * MODULE_BAY  # west face of the first module partition
    for i in range(k_nw):
        p.modules.append(ModuleInsert(x=p1 + (i + 1) * MODULE_BAY, mirrored=False))
    for j in range(k_ne):
        p.modules.append(ModuleInsert(x=NE_START + j * MODULE_BAY, mirrored=True))
    ne_end = NE_START + k_ne * MODULE_BAY  # east face of the last mirrored partition
    # corridor north wall where no module supplies it
    for xa, xb in ((X0, p1), (NW_END, NE_START), (ne_end, X1)):
        walls["interior"].append(box(xa, Y_CN, xb, Y_NZ))
    # core walls
    sx0, sy0, sx1, sy1 = STAIR
    lx0, ly0, lx1, ly1 = LIFT
    walls["core"] += [
        box(sx0 - T_CORE, Y_NZ, sx0, Y1),  # stair west wall, continues to the facade
        box(sx0 - T_CORE, sy1, sx1 + T_CORE, sy1 + T_CORE),  # stair north
        box(sx1, Y_NZ, sx1 + T_CORE, sy1),  # stair east = lift west
        box(sx1, ly1, lx1 + T_CORE, ly1 + T_CORE),  # lift north
        box(lx1, Y_NZ, lx1 + T_CORE, ly1),  # lift east
    ]
    walls["interior"] += [
        box(WRAP_EAST, Y_NZ, WRAP_EAST + T_PART, Y1),
        box(WC_BOX[2], Y_NZ, WC_BOX[2] + T_PART, Y1),
    ]
    # module walls in world coordinates (they are drawn by the block, but they are solids)
    mod_walls, mod_door, _ = _module_local()
    module_solids = []
    for m in p.modules:
        f = _module_transform(m)
        module_solids += [_xf_box(w, f) for w in mod_walls]
        p.module_doors.append(_xf_door(mod_door, f, m.mirrored))
    walls["module"] = module_solids

    # ---- exterior walls and columns
    outer = box(0, 0, WIDTH, DEPTH)
    walls["exterior"].append(outer.difference(box(X0, Y0, X1, Y1)))
    cs = 400
    col_pts = [(gx, gy) for gx in GRID_X for gy in (GRID_Y[0], GRID_Y[-1])]
    col_pts += [(GRID_X[0], gy) for gy in GRID_Y[1:-1]] + [(GRID_X[-1], gy) for gy in GRID_Y[1:-1]]
    for gx, gy in col_pts:
        x0 = min(max(gx - cs / 2, 0), WIDTH - cs)
        y0 = min(max(gy - cs / 2, 0), DEPTH - cs)
        p.columns.append(box(x0, y0, x0 + cs, y0 + cs))

    # ---- doors
    door_w = lambda: rng.choice([800, 900, 900, 1000])  # noqa: E731
    hall_index = len(west_c) + 1
    for i, (xa, xb) in enumerate(south_rooms):
        top = ys_top(0.5 * (xa + xb))
        if i == hall_index:
            a0 = _r50(0.5 * (xa + xb) - 900 + rng.uniform(-2000, 2000))
            p.doors.append(Door("h", a0, 1800, top - T_COR, top, swing=-1, hinge=0,
                                block=DOUBLE_DOOR_BLOCK))
            continue
        w = door_w()
        if rng.random() < 0.5:
            a0 = xa + rng.choice([300, 400, 500])
        else:
            a0 = xb - rng.choice([300, 400, 500]) - w
        p.doors.append(Door("h", a0, w, top - T_COR, top, swing=-1, hinge=rng.randint(0, 1),
                            block=DOOR_BLOCKS[w]))
    if level == 1:  # main entrance, centred on the hall
        xa, xb = south_rooms[hall_index]
        p.doors.append(Door("h", 0.5 * (xa + xb) - 900, 1800, 0, T_EXT, swing=1, hinge=0,
                            block=DOUBLE_DOOR_BLOCK, kind="entrance"))
    # one connecting door between two neighbouring south offices (in a partition: rotated 90/270)
    pairs = [i for i in range(len(south_rooms) - 1)
             if hall_index not in (i, i + 1) and south_c[i] != jog]
    if pairs:
        i = rng.choice(pairs)
        c = south_c[i]
        w = rng.choice([800, 900])
        a0 = _r50(Y0 + 1500 + rng.uniform(0, 2500))
        p.doors.append(Door("v", a0, w, c - T_PART / 2, c + T_PART / 2, swing=rng.choice([-1, 1]),
                            hinge=rng.randint(0, 1), block=DOOR_BLOCKS[w]))
    # north: first room, core, wrap office, WC, last room
    w = door_w()
    p.doors.append(Door("h", _r50(X0 + 0.5 * (p1 - X0) - w / 2), w, Y_CN, Y_NZ, swing=1,
                        hinge=rng.randint(0, 1), block=DOOR_BLOCKS[w]))
    p.doors.append(Door("h", 17000, 1000, Y_CN, Y_NZ, swing=1, hinge=0, block=DOOR_BLOCKS[1000]))
    p.doors.append(Door("h", 20050, 900, Y_CN, Y_NZ, swing=1, hinge=0, block=None, kind="lift"))
    p.doors.append(Door("h", 22600, 1000, Y_CN, Y_NZ, swing=1, hinge=1, block=DOOR_BLOCKS[1000]))
    p.doors.append(Door("h", 25500, 900, Y_CN, Y_NZ, swing=1, hinge=0, block=DOOR_BLOCKS[900]))
    w = door_w()
    p.doors.append(Door("h", _r50(ne_end + T_PART + 0.5 * (X1 - ne_end - T_PART) - w / 2), w, Y_CN, Y_NZ,
                        swing=1, hinge=rng.randint(0, 1), block=DOOR_BLOCKS[w]))

    # ---- windows (gaps in the exterior wall, avoiding columns, partitions and doors)
    def facade_windows(orient: str, lo: float, hi: float, spans, blocked):
        for a, b in spans:
            # free intervals of [a, b] minus blocked
            cuts = sorted((max(a, u), min(b, v)) for u, v in blocked if v > a and u < b)
            cur = a
            free = []
            for u, v in cuts:
                if u > cur:
                    free.append((cur, u))
                cur = max(cur, v)
            if cur < b:
                free.append((cur, b))
            for u, v in free:
                u, v = u + 350, v - 350
                span = v - u
                if span < 1200:
                    continue
                n = max(1, int(span // 3600))
                step = span / n
                for k in range(n):
                    ww = min(2400, step - 600)
                    if ww < 1000:
                        continue
                    c = u + step * (k + 0.5)
                    p.windows.append(Window(orient, _r50(c - ww / 2), _r50(ww), lo, hi))

    col_x = [(c.bounds[0] - 100, c.bounds[2] + 100) for c in p.columns]
    col_y = [(c.bounds[1] - 100, c.bounds[3] + 100) for c in p.columns]
    south_block = col_x + [(d.a0 - 300, d.a0 + d.width + 300) for d in p.doors if d.kind == "entrance"]
    facade_windows("h", 0, T_EXT, south_rooms, south_block)
    north_spans = [(X0, p1)]
    north_spans += [(m.x - MODULE_BAY + T_PART, m.x) for m in p.modules if not m.mirrored]
    north_spans += [(sx0, WRAP_EAST), (WC_BOX[0], WC_BOX[2])]  # wrap-around office, WC
    north_spans += [(m.x, m.x + MODULE_BAY - T_PART) for m in p.modules if m.mirrored]
    north_spans += [(ne_end, X1)]
    facade_windows("h", DEPTH - T_EXT, DEPTH, north_spans, col_x)
    side_spans = [(Y0, ys_top(X0) - T_COR), (Y_NZ, Y1)]
    facade_windows("v", 0, T_EXT, side_spans, col_y)
    side_spans = [(Y0, ys_top(X1) - T_COR), (Y_NZ, Y1)]
    facade_windows("v", WIDTH - T_EXT, WIDTH, side_spans, col_y)
    for x_lo, x_hi, top in ((0, T_EXT, ys_top(X0)), (WIDTH - T_EXT, WIDTH, ys_top(X1))):
        p.windows.append(Window("v", top + 300, Y_CN - top - 600, x_lo, x_hi))  # corridor ends
    p.walls = walls

    # ---- rooms and names
    numbered: List[Tuple[str, Tuple[float, float], Tuple[float, float, float, float]]] = []
    for i, (xa, xb) in enumerate(south_rooms):
        top = ys_top(0.5 * (xa + xb)) - T_COR
        bx = (xa, Y0, xb, top)
        if i == hall_index:
            p.rooms.append(Room("Hall", "room", (0.5 * (xa + xb), 0.5 * (Y0 + top) + 1500),
                                style="mtext_bold", furniture="hall", box=bx))
        else:
            numbered.append(("S", (0.5 * (xa + xb), 0.5 * (Y0 + top)), bx))
    north_boxes = [("N", (X0, Y_NZ, p1, Y1))]
    north_boxes += [("M", (m.x - MODULE_BAY + T_PART, Y_NZ, m.x, Y1)) for m in p.modules if not m.mirrored]
    north_boxes.append(("W", (sx0, sy1 + T_CORE, WRAP_EAST, Y1)))
    north_boxes += [("M", (m.x, Y_NZ, m.x + MODULE_BAY - T_PART, Y1)) for m in p.modules if m.mirrored]
    north_boxes.append(("N", (ne_end, Y_NZ, X1, Y1)))
    for side, bx in north_boxes:
        if side == "W":
            numbered.append((side, (0.5 * (sx0 + lx1), 22400), bx))
        else:
            numbered.append((side, (0.5 * (bx[0] + bx[2]), 0.5 * (bx[1] + bx[3])), bx))
    widths = [b[2] - b[0] for _, _, b in numbered]
    meeting = {i for i, w in enumerate(widths) if w >= 7000}
    if not meeting:
        meeting = {max(range(len(widths)), key=lambda i: widths[i])}
    plain_idx = [i for i in range(len(numbered)) if i not in meeting]
    rng.shuffle(plain_idx)
    styles = {i: "tag" for i in plain_idx[:2]}  # two room-tag blocks with a NAME attribute
    styles.update({i: "mtext_bold" for i in plain_idx[2:6]})
    for n, (side, pt, bx) in enumerate(numbered):
        number = f"{level}{n + 1:02d}"
        if n in meeting:
            p.rooms.append(Room(f"Meeting Room {number}", "room", pt, style="mtext_para",
                                furniture="meeting", box=bx))
        else:
            p.rooms.append(Room(f"Office {number}", "room", pt, style=styles.get(n, "text"),
                                furniture={"W": "office_wrap", "M": ""}.get(side, "office"), box=bx,
                                fmt=rng.randrange(len(MTEXT_FORMATS))))
    p.rooms.append(Room("WC", "room", (0.5 * (WC_BOX[0] + WC_BOX[2]), 17000), style="text",
                        furniture="wc", box=WC_BOX))
    p.rooms.append(Room("Stair A", "stairs", (0.5 * (sx0 + sx1), 0.5 * (sy0 + sy1) - 600), style="text"))
    p.rooms.append(Room("Lift 1", "elevator", (0.5 * (lx0 + lx1), 0.5 * (ly0 + ly1) - 300),
                        style="mtext_bold"))
    cx = 10500 if (jog is None or abs(jog - 10500) > 1000) else 30500
    p.rooms.append(Room("Corridor", "corridor", (cx, Y_CN - 900), style="text"))
    return p


# --------------------------------------------------------------------------- ground truth
def _solids(p: FloorPlan) -> List[Polygon]:
    out: List[Polygon] = []
    for group in ("exterior", "interior", "core", "module"):
        out += p.walls.get(group, [])
    out += p.columns
    return out


def _gt_features(p: FloorPlan):
    """Room polygons (mm), door lines (mm) and their names; raises RuntimeError if the plan leaks."""
    solids = unary_union(_solids(p))
    all_doors = p.doors + p.module_doors
    closed = unary_union([solids] + [d.opening() for d in all_doors])
    free = box(X0, Y0, X1, Y1).difference(closed)
    comps = list(free.geoms) if hasattr(free, "geoms") else [free]
    rooms = []
    used = set()
    for r in p.rooms:
        pt = Point(r.label)
        hits = [i for i, c in enumerate(comps) if c.contains(pt)]
        if len(hits) != 1 or hits[0] in used:
            raise RuntimeError(f"sample building: label of {r.name!r} is not in exactly one free region")
        used.add(hits[0])
        poly = _canonical(comps[hits[0]])
        rooms.append((r, poly))
    left = [c for i, c in enumerate(comps) if i not in used]
    if left:
        raise RuntimeError(f"sample building: {len(left)} unlabeled free regions, e.g. {left[0].bounds}")

    def name_at(xy):
        pt = Point(xy)
        for r, poly in rooms:
            if poly.contains(pt):
                return r.name
        return OUTSIDE

    doors = []
    for d in all_doors:
        a, b = d.probes()
        na, nb = name_at(a), name_at(b)
        if na == nb:
            raise RuntimeError(f"sample building: door at {d.midline()} joins {na!r} to itself")
        if na == OUTSIDE or na == "Corridor":  # "to": the outside, else the corridor when it is one side
            na, nb = nb, na
        doors.append((d, na, nb))
    return rooms, doors


def _canonical_ring(coords, ccw: bool) -> List[Tuple[float, float]]:
    """Drop repeated and collinear vertices (exact: coordinates are whole millimetres), orient the
    ring and start it at its lowest-left vertex, so equal shapes always give equal coordinates."""
    pts = [(float(x), float(y)) for x, y in list(coords)[:-1]]
    changed = True
    while changed and len(pts) > 3:
        changed = False
        out = []
        n = len(pts)
        for i in range(n):
            a, b, c = pts[i - 1], pts[i], pts[(i + 1) % n]
            cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            if b == a or abs(cross) < 1e-6:
                changed = True
                continue
            out.append(b)
        pts = out
    area2 = sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts)))
    if (area2 > 0) != ccw:
        pts.reverse()
    k = min(range(len(pts)), key=lambda i: (pts[i][1], pts[i][0]))
    pts = pts[k:] + pts[:k]
    return pts + [pts[0]]


def _canonical(poly: Polygon) -> Polygon:
    holes = sorted((_canonical_ring(r.coords, ccw=False) for r in poly.interiors), key=lambda r: r[0])
    return Polygon(_canonical_ring(poly.exterior.coords, ccw=True), holes)


def _ring_m(coords) -> List[List[float]]:
    return [[round(x / 1000.0, 6), round(y / 1000.0, 6)] for x, y in coords]


def _poly_m(poly: Polygon):
    return [_ring_m(poly.exterior.coords)] + [_ring_m(r.coords) for r in poly.interiors]


def _write_ground_truth(path: str, p: FloorPlan, rooms, doors) -> None:
    feats = []
    for r, poly in rooms:
        feats.append({"type": "Feature",
                      "properties": {"kind": "room", "name": r.name, "areatype": r.areatype,
                                     "level": p.level},
                      "geometry": {"type": "Polygon", "coordinates": _poly_m(poly)}})
    for d, na, nb in doors:
        a, b = d.midline()
        feats.append({"type": "Feature",
                      "properties": {"kind": "door", "from": na, "to": nb,
                                     "width": round(d.width / 1000.0, 6), "level": p.level},
                      "geometry": {"type": "LineString", "coordinates": _ring_m([a, b])}})
    for r, poly in rooms:
        if r.areatype in ("stairs", "elevator"):
            c = poly.centroid
            feats.append({"type": "Feature",
                          "properties": {"kind": "anchor", "name": r.name, "areatype": r.areatype,
                                         "level": p.level},
                          "geometry": {"type": "Point", "coordinates": _ring_m([(c.x, c.y)])[0]}})
    feats.append({"type": "Feature", "properties": {"kind": "envelope", "level": p.level},
                  "geometry": {"type": "Polygon",
                               "coordinates": _poly_m(box(0, 0, WIDTH, DEPTH))}})
    fc = {"type": "FeatureCollection", "name": os.path.basename(path), "features": feats}
    with atomic_write(path) as fh:
        json.dump(fc, fh, indent=1)
        fh.write("\n")


# --------------------------------------------------------------------------- DXF writing
def _new_doc():
    import ezdxf

    doc = ezdxf.new("R2018", setup=["linetypes"])
    # ezdxf stamps the creation time here; a fixed marker keeps the output reproducible
    doc.ezdxf_metadata()["CREATED_BY_EZDXF"] = f"{ezdxf.__version__} @ cad2osmag sample building"
    doc.header["$INSUNITS"] = 4
    doc.header["$MEASUREMENT"] = 1
    doc.header["$LUNITS"] = 2
    doc.header["$LUPREC"] = 0
    doc.header["$ATTMODE"] = 1
    doc.styles.add("ARIAL", font="arial.ttf")
    for name, color, lt in LAYERS:
        doc.layers.add(name, color=color, linetype=lt)
    return doc


def _define_blocks(doc) -> None:
    for width, name in DOOR_BLOCKS.items():
        blk = doc.blocks.new(name, base_point=(0, 0))
        blk.add_line((0, 0), (0, width), dxfattribs={"layer": "0"})
        blk.add_arc((0, 0), width, 0, 90, dxfattribs={"layer": "0"})
    blk = doc.blocks.new(DOUBLE_DOOR_BLOCK, base_point=(0, 0))
    blk.add_line((0, 0), (0, 900), dxfattribs={"layer": "0"})
    blk.add_arc((0, 0), 900, 0, 90, dxfattribs={"layer": "0"})
    blk.add_line((1800, 0), (1800, 900), dxfattribs={"layer": "0"})
    blk.add_arc((1800, 0), 900, 90, 180, dxfattribs={"layer": "0"})

    blk = doc.blocks.new("DESK_1600", base_point=(0, 0))
    blk.add_lwpolyline([(-800, 0), (800, 0), (800, 800), (-800, 800)], close=True)
    blk.add_line((-300, 700), (300, 700))  # monitor
    blk = doc.blocks.new("CHAIR", base_point=(0, 0))
    blk.add_lwpolyline([(-250, -250), (250, -250), (250, 200), (-250, 200)], close=True)
    blk.add_line((-250, -300), (250, -300))  # back rest
    blk = doc.blocks.new("WORKSTATION", base_point=(0, 0))
    blk.add_blockref("DESK_1600", (0, 0))
    blk.add_blockref("CHAIR", (0, -350))
    blk = doc.blocks.new("TABLE_MEETING", base_point=(0, 0))
    blk.add_lwpolyline([(-1800, -600), (1800, -600), (1800, 600), (-1800, 600)], close=True)
    for k in range(4):
        x = -1350 + 900 * k
        blk.add_blockref("CHAIR", (x, -900))
        blk.add_blockref("CHAIR", (x, 900), dxfattribs={"rotation": 180})
    blk = doc.blocks.new("WC_PAN", base_point=(0, 0))
    blk.add_lwpolyline([(-250, 0), (250, 0), (250, 180), (-250, 180)], close=True)
    blk.add_ellipse((0, 450), major_axis=(0, 270), ratio=0.75)
    blk = doc.blocks.new("WASHBASIN", base_point=(0, 0))
    blk.add_lwpolyline([(-300, 0), (300, 0), (300, 450), (-300, 450)], close=True)
    blk.add_circle((0, 220), 150)

    blk = doc.blocks.new("ROOM_TAG", base_point=(0, 0))
    blk.add_lwpolyline([(-1200, -300), (1200, -300), (1200, 300), (-1200, 300)], close=True)
    blk.add_attdef("NAME", (0, 0), text="ROOM", dxfattribs={
        "height": 220, "style": "ARIAL", "halign": 1, "valign": 2, "align_point": (0, 0)})

    # OFFICE_MODULE: walls on layer 0 (they take the insert's A-WALL), nested door and furniture
    walls, door, desks = _module_local()
    blk = doc.blocks.new("OFFICE_MODULE", base_point=(0, 0))
    for i, w in enumerate(walls):
        pts = list(w.exterior.coords)[:-1]
        if i == 2:  # the long partition as a pair of lines plus end caps
            for a, b in zip(pts, pts[1:] + pts[:1]):
                blk.add_line(a, b, dxfattribs={"layer": "0"})
        else:
            blk.add_lwpolyline(pts, close=True, dxfattribs={"layer": "0"})
    ins, rot, sx = _door_insert(door)
    blk.add_blockref(door.block, ins, dxfattribs={"layer": "A-DOOR", "rotation": rot, "xscale": sx})
    for x, y, r in desks:
        blk.add_blockref("WORKSTATION", (x, y), dxfattribs={"layer": "A-FURN", "rotation": r})


def _door_insert(d: Door):
    """Insertion point, rotation and x scale of a door block for door ``d``. The block has its hinge
    at the origin, the opening along +x and the open leaf along +y."""
    face = d.hi if d.swing > 0 else d.lo
    along = d.a0 if d.hinge == 0 else d.a0 + d.width
    sgn = 1 if d.hinge == 0 else -1
    if d.orient == "h":
        ins, u, n = (along, face), (sgn, 0), (0, d.swing)
    else:
        ins, u, n = (face, along), (0, sgn), (d.swing, 0)
    cross = u[0] * n[1] - u[1] * n[0]
    if cross > 0:
        return ins, math.degrees(math.atan2(u[1], u[0])) % 360, 1
    return ins, math.degrees(math.atan2(-u[1], -u[0])) % 360, -1


def _add_poly_outline(msp, poly: Polygon, layer: str, as_lines: bool) -> None:
    rings = [poly.exterior] + list(poly.interiors)
    for ring in rings:
        pts = [(round(x, 3), round(y, 3)) for x, y in list(ring.coords)[:-1]]
        if as_lines:
            for a, b in zip(pts, pts[1:] + pts[:1]):
                msp.add_line(a, b, dxfattribs={"layer": layer})
        else:
            msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": layer})


def _add_solid_hatch(msp, poly: Polygon, layer: str, color: int = 256) -> None:
    h = msp.add_hatch(color=color, dxfattribs={"layer": layer})
    h.paths.add_polyline_path([(x, y) for x, y in list(poly.exterior.coords)[:-1]], is_closed=True,
                              flags=1)
    for ring in poly.interiors:
        h.paths.add_polyline_path([(x, y) for x, y in list(ring.coords)[:-1]], is_closed=True, flags=0)


def _pieces(geom) -> List[Polygon]:
    geoms = list(geom.geoms) if hasattr(geom, "geoms") else [geom]
    geoms = [g for g in geoms if g.area > 1.0]
    return sorted(geoms, key=lambda g: (round(g.bounds[0]), round(g.bounds[1]), round(g.area)))


def _draw_floor(doc, p: FloorPlan, rooms_gt, rng: random.Random) -> None:
    msp = doc.modelspace()
    openings = unary_union([d.opening() for d in p.doors] + [box(*_win_box(w)) for w in p.windows])

    # walls: exterior (closed polylines), interior (alternately polylines and line pairs), core (hatched)
    ext = unary_union(p.walls["exterior"]).difference(openings)
    for poly in _pieces(ext):
        _add_poly_outline(msp, poly, "A-WALL", as_lines=False)
        h = msp.add_hatch(dxfattribs={"layer": "A-WALL-PATT"})  # masonry hatch of the facade walls
        h.set_pattern_fill("ANSI31", scale=20)
        h.paths.add_polyline_path(list(poly.exterior.coords)[:-1], is_closed=True, flags=1)
    inner = unary_union(p.walls["interior"]).difference(openings)
    for i, poly in enumerate(_pieces(inner)):
        _add_poly_outline(msp, poly, "A-WALL", as_lines=(i % 2 == 1))
    core = unary_union(p.walls["core"]).difference(openings)
    for poly in _pieces(core):
        _add_poly_outline(msp, poly, "A-WALL", as_lines=False)
        _add_solid_hatch(msp, poly, "A-WALL")
    for m in p.modules:
        msp.add_blockref("OFFICE_MODULE", (m.x, Y_CN), dxfattribs={
            "layer": "A-WALL", "rotation": 180, "xscale": -1 if m.mirrored else 1})
    for c in p.columns:
        _add_poly_outline(msp, c, "A-COLS", as_lines=False)
        _add_solid_hatch(msp, c, "A-COLS")

    # doors
    for d in p.doors:
        if d.block is not None:
            ins, rot, sx = _door_insert(d)
            msp.add_blockref(d.block, ins, dxfattribs={"layer": "A-DOOR", "rotation": rot, "xscale": sx})
        else:  # lift: two sliding leaves in the opening
            y = d.lo + 60
            half = d.width / 2.0
            msp.add_line((d.a0, y), (d.a0 + half + 50, y), dxfattribs={"layer": "A-DOOR"})
            msp.add_line((d.a0 + half - 50, y + 50), (d.a0 + d.width, y + 50), dxfattribs={"layer": "A-DOOR"})

    # windows: 2 or 3 glazing lines plus sill lines at the jambs
    for w in p.windows:
        n = 3 if (int(w.a0) // 50) % 2 == 0 else 2
        offs = [0.3, 0.5, 0.7] if n == 3 else [0.4, 0.6]
        for o in offs:
            t = w.lo + o * (w.hi - w.lo)
            a, b = ((w.a0, t), (w.a0 + w.width, t)) if w.orient == "h" else ((t, w.a0), (t, w.a0 + w.width))
            msp.add_line(a, b, dxfattribs={"layer": "A-GLAZ"})
        for s in (w.a0, w.a0 + w.width):
            a, b = ((s, w.lo), (s, w.hi)) if w.orient == "h" else ((w.lo, s), (w.hi, s))
            msp.add_line(a, b, dxfattribs={"layer": "A-GLAZ"})

    _draw_stair_and_lift(msp)
    _draw_furniture(msp, p, rng)
    _draw_annotations(doc, msp, p, rooms_gt)
    # drawing extents (grid bubbles and title block included) and a model-space view on them
    lo, hi = (-5000.0, -8500.0, 0.0), (WIDTH + 5000.0, DEPTH + 5000.0, 0.0)
    msp.dxf.extmin, msp.dxf.extmax = lo, hi  # ezdxf copies these into $EXTMIN / $EXTMAX on save
    msp.dxf.limmin, msp.dxf.limmax = lo[:2], hi[:2]
    doc.set_modelspace_vport(height=1.05 * (hi[1] - lo[1]),
                             center=(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])))


def _win_box(w: Window):
    if w.orient == "h":
        return (w.a0, w.lo, w.a0 + w.width, w.hi)
    return (w.lo, w.a0, w.hi, w.a0 + w.width)


def _draw_stair_and_lift(msp) -> None:
    sx0, sy0, sx1, sy1 = STAIR
    lay = {"layer": "A-STAIR"}
    gap = 200
    xm = 0.5 * (sx0 + sx1)
    fl_w = xm - gap / 2 - sx0
    y_start, y_end, tread = sy0 + 1500, sy1 - 1200, 275
    n = int((y_end - y_start) // tread)
    y_end = y_start + n * tread
    for k in range(n + 1):
        y = y_start + k * tread
        msp.add_line((sx0, y), (xm - gap / 2, y), dxfattribs=lay)
        msp.add_line((xm + gap / 2, y), (sx1, y), dxfattribs=lay)
    # stringers / handrails around the eye
    msp.add_lwpolyline([(xm - gap / 2, y_start), (xm - gap / 2, y_end), (xm + gap / 2, y_end),
                        (xm + gap / 2, y_start)], close=True, dxfattribs=lay)
    # walking line with arrow: up the west flight, across the landing, down the east flight
    xa, xb = sx0 + fl_w / 2, xm + gap / 2 + fl_w / 2
    msp.add_lwpolyline([(xa, y_start - 300), (xa, y_end + 500), (xb, y_end + 500), (xb, y_start)],
                       dxfattribs=lay)
    msp.add_lwpolyline([(xb - 150, y_start + 250), (xb, y_start), (xb + 150, y_start + 250)], dxfattribs=lay)
    msp.add_circle((xa, y_start - 300), 60, dxfattribs=lay)
    msp.add_text("UP", height=200, dxfattribs={"layer": "A-STAIR", "style": "ARIAL"}).set_placement(
        (xa + 120, y_start + 100))
    # lift: car with a cross, counterweight
    lx0, ly0, lx1, ly1 = LIFT
    lay = {"layer": LIFT_LAYER}
    c0, c1 = (lx0 + 150, ly0 + 250), (lx1 - 150, ly1 - 350)
    msp.add_lwpolyline([c0, (c1[0], c0[1]), c1, (c0[0], c1[1])], close=True, dxfattribs=lay)
    msp.add_line(c0, c1, dxfattribs=lay)
    msp.add_line((c1[0], c0[1]), (c0[0], c1[1]), dxfattribs=lay)
    msp.add_lwpolyline([(lx0 + 400, ly1 - 250), (lx1 - 400, ly1 - 250), (lx1 - 400, ly1 - 80),
                        (lx0 + 400, ly1 - 80)], close=True, dxfattribs=lay)


def _draw_furniture(msp, p: FloorPlan, rng: random.Random) -> None:
    furn = {"layer": "A-FURN"}
    for r in p.rooms:
        if not r.box or not r.furniture:
            continue
        x0, y0, x1, y1 = r.box
        if r.furniture == "office":
            wdt = x1 - x0
            n = 1 if wdt < 3400 else 2
            south = y0 < Y_CN
            yd = (y0 + 1100) if south else (y1 - 1100)
            rot = 180 if south else 0
            for k in range(n):
                x = x0 + wdt * (k + 0.5) / n
                msp.add_blockref("WORKSTATION", (x, yd), dxfattribs={**furn, "rotation": rot})
            if (y1 - y0) > 8000 and rng.random() < 0.7:
                msp.add_blockref("WORKSTATION", (x0 + wdt / 2, (y0 + y1) / 2 + (800 if south else -800)),
                                 dxfattribs={**furn, "rotation": 180 - rot})
        elif r.furniture == "office_wrap":
            for k in range(2):
                msp.add_blockref("WORKSTATION", (STAIR[0] + 1200 + 1900 * k, Y1 - 1100),
                                 dxfattribs={**furn, "rotation": 0})
        elif r.furniture == "meeting":
            msp.add_blockref("TABLE_MEETING", ((x0 + x1) / 2, (y0 + y1) / 2 + 1500),
                             dxfattribs={**furn, "rotation": 90 if (x1 - x0) < 6000 else 0})
        elif r.furniture == "hall":
            cx = (x0 + x1) / 2
            msp.add_lwpolyline([(cx - 2000, y1 - 2600), (cx + 2000, y1 - 2600), (cx + 2000, y1 - 1800),
                                (cx - 2000, y1 - 1800)], close=True, dxfattribs=furn)  # counter
            for k in range(3):
                msp.add_circle((x0 + 1500 + 1200 * k, y0 + 2500), 400, dxfattribs=furn)  # lounge tables
            hatch = msp.add_hatch(dxfattribs={"layer": "A-FLOR-PATT"})
            hatch.set_pattern_fill("ANSI37", scale=150, angle=45)
            hatch.paths.add_polyline_path([(x0 + 1000, y0 + 1000), (x1 - 1000, y0 + 1000),
                                           (x1 - 1000, y0 + 5000), (x0 + 1000, y0 + 5000)], is_closed=True)
        elif r.furniture == "wc":
            fx = {"layer": "P-SANR-FIXT"}
            for k in range(4):
                y = y1 - 700 - 1500 * k
                msp.add_blockref("WC_PAN", (x1, y), dxfattribs={**fx, "rotation": 90})
                msp.add_line((x1 - 1400, y - 750), (x1, y - 750), dxfattribs=fx)  # cubicle partition
            for k in range(2):
                msp.add_blockref("WASHBASIN", (x0, y0 + 2400 + 900 * k), dxfattribs={**fx, "rotation": 270})
            hatch = msp.add_hatch(dxfattribs={"layer": "A-FLOR-PATT"})
            hatch.set_pattern_fill("NET", scale=60)
            hatch.paths.add_polyline_path([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], is_closed=True)


def _mtext_content(r: Room) -> str:
    if r.style == "mtext_para":
        head, _, tail = r.name.partition(" ")
        return head + "\\P" + tail
    head, _, tail = r.name.rpartition(" ") if r.name[-1].isdigit() else (r.name, "", "")
    if not tail:
        return "{\\fArial|b1;" + r.name + "}"
    return MTEXT_FORMATS[r.fmt % len(MTEXT_FORMATS)].format(head=head, tail=tail)


def _draw_annotations(doc, msp, p: FloorPlan, rooms_gt) -> None:
    txt = {"layer": "A-ANNO-TEXT", "style": "ARIAL"}
    for r in p.rooms:
        x, y = r.label
        if r.style == "text":
            msp.add_text(r.name, height=250, dxfattribs=txt).set_placement(
                (x, y), align=_text_align("MIDDLE_CENTER"))
        elif r.style in ("mtext_bold", "mtext_para"):
            mt = msp.add_mtext(_mtext_content(r), dxfattribs={**txt, "char_height": 250})
            mt.set_location((x, y), attachment_point=5)
        elif r.style == "tag":
            ref = msp.add_blockref("ROOM_TAG", (x, y), dxfattribs={"layer": "A-ANNO-TEXT"})
            ref.add_auto_attribs({"NAME": r.name})
            for att in ref.attribs:
                att.dxf.layer = "A-ANNO-TEXT"
    # grid axes with bubbles
    g = {"layer": "S-GRID"}
    ext_lo, ext_hi = -4000, 4000
    for gx, lab in zip(GRID_X, GRID_X_LABELS):
        msp.add_line((gx, ext_lo), (gx, DEPTH + ext_hi), dxfattribs=g)
        for yy in (ext_lo - 500, DEPTH + ext_hi + 500):
            msp.add_circle((gx, yy), 500, dxfattribs=g)
            msp.add_text(lab, height=400, dxfattribs={**g, "style": "ARIAL"}).set_placement(
                (gx, yy), align=_text_align("MIDDLE_CENTER"))
    for gy, lab in zip(GRID_Y, GRID_Y_LABELS):
        msp.add_line((ext_lo, gy), (WIDTH + ext_hi, gy), dxfattribs=g)
        for xx in (ext_lo - 500, WIDTH + ext_hi + 500):
            msp.add_circle((xx, gy), 500, dxfattribs=g)
            msp.add_text(lab, height=400, dxfattribs={**g, "style": "ARIAL"}).set_placement(
                (xx, gy), align=_text_align("MIDDLE_CENTER"))
    # dimensions: axis spacing and overall length along the south facade, depth along the west
    ov = {"dimtxt": 250, "dimasz": 200, "dimexo": 150, "dimexe": 150, "dimgap": 80, "dimdec": 0}
    dattr = {"layer": "A-ANNO-DIMS"}
    for a, b in zip(GRID_X, GRID_X[1:]):
        msp.add_linear_dim(base=(0, -2000), p1=(a, 0), p2=(b, 0), override=ov, dxfattribs=dattr).render()
    msp.add_linear_dim(base=(0, -3000), p1=(0, 0), p2=(WIDTH, 0), override=ov, dxfattribs=dattr).render()
    msp.add_linear_dim(base=(-2500, 0), p1=(0, 0), p2=(0, DEPTH), angle=90, override=ov,
                       dxfattribs=dattr).render()
    w1, w2 = p.corridor_widths
    msp.add_linear_dim(base=(X0 + 1500, 0), p1=(X0 + 1000, Y_CN - w1), p2=(X0 + 1000, Y_CN), angle=90,
                       override=ov, dxfattribs=dattr).render()
    # title
    ttl = {"layer": "A-ANNO-TITL", "style": "ARIAL"}
    msp.add_text(f"SAMPLE OFFICE BUILDING - LEVEL {p.level} - GENERAL ARRANGEMENT PLAN 1:100",
                 height=600, dxfattribs=ttl).set_placement((0, -7000))
    msp.add_text("cad2osmag synthetic test drawing - dimensions in mm", height=300,
                 dxfattribs=ttl).set_placement((0, -7800))
    msp.add_lwpolyline([(-500, -8500), (WIDTH + 500, -8500), (WIDTH + 500, -6000), (-500, -6000)],
                       close=True, dxfattribs={"layer": "A-ANNO-TITL"})


def _text_align(name: str):
    from ezdxf.enums import TextEntityAlignment

    return getattr(TextEntityAlignment, name)


def _save_deterministic(doc, path: str) -> None:
    import ezdxf

    opts = ezdxf.options
    old = opts.write_fixed_meta_data_for_testing
    opts.write_fixed_meta_data_for_testing = True
    # ezdxf registers some CLASS entries while iterating a set of entity types, so their order follows
    # the process's string hashing; saving once registers them all, then a sorted table is stable.
    classes = doc.classes
    original_export = classes.export_dxf

    def export_sorted(tagwriter):
        classes.classes = dict(sorted(classes.classes.items()))
        original_export(tagwriter)

    classes.export_dxf = export_sorted
    try:
        with atomic_path(path, suffix=".dxf") as tmp:
            doc.saveas(tmp)
    finally:
        opts.write_fixed_meta_data_for_testing = old
        del classes.export_dxf


# --------------------------------------------------------------------------- public API
def generate_building(out_dir: str, floors: int = 3, seed: int = 0, name: str = "sample",
                      progress=None) -> dict:
    """Write ``<out_dir>/<name>-F<k>.dxf`` and ``<name>-F<k>.gt.geojson`` for k = 1..floors.

    Same ``seed`` -> byte-identical files; the stair and lift are at the same coordinates on every
    floor (and for every seed). Returns ``{"dxf": [paths], "ground_truth": [paths], "floors": n,
    "seed": seed, "rooms": [room count per floor], "doors": [door count per floor],
    "names": [[room names] per floor], "anchors": {"Stair A": (x, y), "Lift 1": (x, y)} (metres,
    the shaft centres, the same on every floor), "envelope": (xmin, ymin, xmax, ymax) metres}``.
    """
    progress = ensure(progress)
    try:
        floors = int(floors)
        seed = int(seed)
    except (TypeError, ValueError):
        raise InputError("floors and seed must be integers")
    if not 1 <= floors <= 50:
        raise InputError(f"floors must be between 1 and 50, got {floors}")
    if not name or any(ch in name for ch in "/\\:*?\"<>|"):
        raise InputError(f"invalid file name prefix {name!r}")
    out_dir = os.path.abspath(out_dir)
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot create output folder {out_dir}: {exc}")

    result = {"dxf": [], "ground_truth": [], "floors": floors, "seed": seed, "rooms": [], "doors": [],
              "names": [],
              # same on every floor: where multi-floor fusion can align (metres, centres of the shafts)
              "anchors": {"Stair A": (0.5e-3 * (STAIR[0] + STAIR[2]), 0.5e-3 * (STAIR[1] + STAIR[3])),
                          "Lift 1": (0.5e-3 * (LIFT[0] + LIFT[2]), 0.5e-3 * (LIFT[1] + LIFT[3]))},
              "envelope": (0.0, 0.0, WIDTH / 1000.0, DEPTH / 1000.0)}
    for k in range(1, floors + 1):
        progress.step(100.0 * (k - 1) / floors, f"sample building: floor {k} of {floors}")
        plan = _plan_floor(k, seed)
        rooms, doors = _gt_features(plan)
        doc = _new_doc()
        _define_blocks(doc)
        _draw_floor(doc, plan, rooms, random.Random(seed * 31 + k))
        dxf_path = os.path.join(out_dir, f"{name}-F{k}.dxf")
        gt_path = os.path.join(out_dir, f"{name}-F{k}.gt.geojson")
        _save_deterministic(doc, dxf_path)
        _write_ground_truth(gt_path, plan, rooms, doors)
        result["dxf"].append(dxf_path)
        result["ground_truth"].append(gt_path)
        result["rooms"].append(len(rooms))
        result["doors"].append(len(doors))
        result["names"].append([r.name for r, _ in rooms])
    progress.step(100.0, f"sample building: wrote {floors} floor(s) to {out_dir}")
    return result


def _load(path: str) -> List[dict]:
    with open(path, encoding="utf-8") as fh:
        return json.load(fh)["features"]


def ground_truth_rooms(path: str) -> List[dict]:
    """Rooms of a ground-truth file: dicts with name, areatype, level and polygon (shapely, metres)."""
    return [{"name": f["properties"]["name"], "areatype": f["properties"]["areatype"],
             "level": f["properties"].get("level"), "polygon": shape(f["geometry"])}
            for f in _load(path) if f["properties"].get("kind") == "room"]


def ground_truth_doors(path: str) -> List[dict]:
    """Doors of a ground-truth file: dicts with from, to, width (m), level and line (shapely LineString
    across the opening on the wall midline, metres)."""
    return [{"from": f["properties"]["from"], "to": f["properties"]["to"],
             "width": f["properties"]["width"], "level": f["properties"].get("level"),
             "line": LineString(f["geometry"]["coordinates"])}
            for f in _load(path) if f["properties"].get("kind") == "door"]


def ground_truth_anchors(path: str) -> List[dict]:
    """Stair / lift anchor points: dicts with name, areatype, level and point (shapely, metres)."""
    return [{"name": f["properties"]["name"], "areatype": f["properties"]["areatype"],
             "level": f["properties"].get("level"), "point": shape(f["geometry"])}
            for f in _load(path) if f["properties"].get("kind") == "anchor"]


def ground_truth_envelope(path: str) -> Polygon:
    """The building outline polygon (metres)."""
    for f in _load(path):
        if f["properties"].get("kind") == "envelope":
            return shape(f["geometry"])
    raise InputError(f"{path}: no envelope feature")


# --------------------------------------------------------------------------- drawings as delivered
SHEET_GAP = 12000  # mm between the plan and the views beside it on the sheet variant
DETAIL_SCALE = 2.0  # the enlarged stair detail is drawn at twice the plan's scale (1:50 beside 1:100)


def _to_layer_zero(doc) -> None:
    """Spaghetti: every entity of model space and of every block on layer "0"; the grid axes go (a
    spaghetti plan has no axis layer to leave out, and axes on "0" are not what is being tested)."""
    msp = doc.modelspace()
    for e in list(msp):
        if e.dxf.get("layer", "0") == "S-GRID":
            msp.delete_entity(e)
    for blk in doc.blocks:
        if blk.name.lower().startswith(("*model_space", "*paper_space")):
            continue
        for e in blk:
            e.dxf.layer = "0"
    for e in msp:
        e.dxf.layer = "0"
        if e.dxftype() == "INSERT":
            for a in e.attribs:
                a.dxf.layer = "0"


def _explode_doors(doc) -> None:
    """Door blocks replaced by their loose arcs and leaves (no block name left to tell they are doors)."""
    msp = doc.modelspace()
    for blk in [doc.blocks.get("OFFICE_MODULE")]:
        if blk is None:
            continue
        for e in list(blk):
            if e.dxftype() == "INSERT" and e.dxf.name.upper().startswith("DOOR"):
                for v in e.virtual_entities():
                    blk.add_entity(v)
                blk.delete_entity(e)
    for e in list(msp):
        if e.dxftype() == "INSERT" and e.dxf.name.upper().startswith("DOOR"):
            e.explode()


def _draw_sheet_views(doc, level: int) -> dict:
    """Title frame with title block, an enlarged stair detail and a legend beside the plan (mm)."""
    msp = doc.modelspace()
    sx0, sy0, sx1, sy1 = STAIR
    # enlarged detail of the stair core: its enclosure walls and treads at DETAIL_SCALE, right of the plan
    dx0, dy0 = WIDTH + SHEET_GAP, 2000
    k = DETAIL_SCALE
    t = T_CORE
    outer = [(sx0 - t, sy0 - t), (sx1 + t, sy0 - t), (sx1 + t, sy1 + t), (sx0 - t, sy1 + t)]
    inner = [(sx0, sy0), (sx1, sy0), (sx1, sy1), (sx0, sy1)]

    def place(p):
        return (dx0 + (p[0] - sx0 + t) * k, dy0 + (p[1] - sy0 + t) * k)

    for ring in (outer, inner):
        pts = [place(p) for p in ring]
        # the door side (south) is open between 1/3 and 2/3 of the width
        msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "A-WALL"})
    for j in range(1, 16):
        y = sy0 + 1500 + j * 275
        msp.add_line(place((sx0, y)), place((sx1, y)), dxfattribs={"layer": "A-STAIR"})
    det = (dx0, dy0, dx0 + (sx1 - sx0 + 2 * t) * k, dy0 + (sy1 - sy0 + 2 * t) * k)
    msp.add_text("楼梯放大详图 STAIR A ENLARGED DETAIL 1:50", height=500,
                 dxfattribs={"layer": "A-ANNO-TITL", "style": "ARIAL"}).set_placement((det[0], det[1] - 1500))
    # legend: wall and glazing swatches with labels, titled, on their own layer
    lx0, ly0 = det[0], det[3] + 6000
    msp.add_text("LEGEND", height=500, dxfattribs={"layer": "A-ANNO-TITL", "style": "ARIAL"}).set_placement(
        (lx0, ly0 + 3200))
    for j, (lab, lay) in enumerate((("WALL", "LEGEND-A-WALL"), ("GLAZING", "LEGEND-A-GLAZ"))):
        y = ly0 + 1600 * j
        msp.add_lwpolyline([(lx0, y), (lx0 + 1500, y), (lx0 + 1500, y + 600), (lx0, y + 600)], close=True,
                           dxfattribs={"layer": lay})
        msp.add_text(lab, height=300, dxfattribs={"layer": "A-ANNO-TEXT", "style": "ARIAL"}).set_placement(
            (lx0 + 2000, y + 100))
    # plan title below the plan
    msp.add_text(f"{level}层平面图 LEVEL {level} FLOOR PLAN 1:100", height=800,
                 dxfattribs={"layer": "A-ANNO-TITL", "style": "ARIAL"}).set_placement((0, -5000))
    # the sheet frame (a bare rectangle on layer 0) and the title block (on the frame layer 图框)
    fx0, fy0 = -8000, -14000
    fx1, fy1 = det[2] + 8000, DEPTH + 8000
    msp.add_lwpolyline([(fx0, fy0), (fx1, fy0), (fx1, fy1), (fx0, fy1)], close=True, dxfattribs={"layer": "0"})
    tb = (fx1 - 18000, fy0, fx1, fy0 + 5000)
    if "图框" not in doc.layers:
        doc.layers.add("图框", color=7)
    msp.add_lwpolyline([(tb[0], tb[1]), (tb[2], tb[1]), (tb[2], tb[3]), (tb[0], tb[3])], close=True,
                       dxfattribs={"layer": "图框"})
    for j in range(1, 3):
        msp.add_line((tb[0], tb[1] + j * 1600), (tb[2], tb[1] + j * 1600), dxfattribs={"layer": "图框"})
    msp.add_text("cad2osmag sample sheet", height=600, dxfattribs={"layer": "图框", "style": "ARIAL"}).set_placement(
        (tb[0] + 500, tb[1] + 3500))
    return {"plan_extent": (0.0, 0.0, WIDTH / 1000.0, DEPTH / 1000.0),
            "detail_extent": tuple(v / 1000.0 for v in det),
            "frame": (fx0 / 1000.0, fy0 / 1000.0, fx1 / 1000.0, fy1 / 1000.0)}


def generate_delivered(out_dir: str, seed: int = 0, level: int = 1, spaghetti: bool = False,
                       explode_doors: bool = False, sheet: bool = False, name: str = "delivered") -> dict:
    """One floor of the sample building drawn the way drawings are delivered, for the sheet and
    spaghetti rules of the CAD import (the regular ``generate_building`` output is unchanged):

    * ``spaghetti``: every entity on layer "0" (walls, door blocks, furniture blocks, sanitary fittings,
      floor hatches, texts); grid axes left out;
    * ``explode_doors``: door blocks replaced by loose swing arcs and leaves;
    * ``sheet``: a title frame (bare rectangle on layer 0) with a title block (layer 图框), an enlarged
      stair detail (1:50, walls on A-WALL, titled "楼梯放大详图 …") and a legend (swatches on
      LEGEND-* layers) beside the plan, and a plan title "<n>层平面图 …" below it.

    Writes ``<out_dir>/<name>.dxf`` and its ground truth; returns ``{"dxf", "ground_truth", "rooms",
    "doors", "names", "plan_extent", "detail_extent", "frame"}`` (extents in metres, CAD frame)."""
    try:
        seed, level = int(seed), int(level)
    except (TypeError, ValueError):
        raise InputError("seed and level must be integers")
    if not name or any(ch in name for ch in "/\\:*?\"<>|"):
        raise InputError(f"invalid file name prefix {name!r}")
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    plan = _plan_floor(level, seed)
    rooms, doors = _gt_features(plan)
    doc = _new_doc()
    _define_blocks(doc)
    _draw_floor(doc, plan, rooms, random.Random(seed * 31 + level))
    info = {"plan_extent": (0.0, 0.0, WIDTH / 1000.0, DEPTH / 1000.0)}
    if sheet:
        info = _draw_sheet_views(doc, level)
    if explode_doors:
        _explode_doors(doc)
    if spaghetti:
        _to_layer_zero(doc)
    dxf_path = os.path.join(out_dir, f"{name}.dxf")
    gt_path = os.path.join(out_dir, f"{name}.gt.geojson")
    _save_deterministic(doc, dxf_path)
    _write_ground_truth(gt_path, plan, rooms, doors)
    return {"dxf": dxf_path, "ground_truth": gt_path, "rooms": len(rooms), "doors": len(doors),
            "names": [r.name for r, _ in rooms], **info}

# --------------------------------------------------------------------------- open facades (issue 8, item 5)
OPEN_FACADE_WALL = 0.3  # metres


def open_facade_plan(hall_width: float = 10.0, pillar_pitch: float = 5.0):
    """The layout of ``generate_open_facade`` in metres: ``(walls, rooms, doors, labels)``.

    Two wings of two rooms each (x 0..12 and x 12+w..24+w, y 0..12) flank an entrance hall
    ("HALL DISTRIBUZIONE", ``hall_width`` wide, 12 m deep) that is open to the street on its whole
    south side; behind them runs a 3 m portico corridor ("CORRIDOIO DI DISTRIBUZIONE") whose north
    side is closed only by pillars every ``pillar_pitch`` m (and a dash-dot line in the drawing).
    Every room has a door to the hall or the corridor, the hall one to the corridor: one connected
    floor. ``walls``: shapely geometry of every wall and pillar; ``rooms``: name -> free polygon
    (door openings belong to neither side); ``doors``: list of (name_a, name_b, LineString jamb to
    jamb on the wall midline); ``labels``: name -> (x, y) of its text.
    """
    t = OPEN_FACADE_WALL
    w = float(hall_width)
    xe0, xe1 = 12.0 + w, 24.0 + w  # east wing
    X1 = xe1
    segs = []  # wall midlines (x0, y0, x1, y1)
    segs += [(0, 0, 12, 0), (0, 0, 0, 15), (12, 0, 12, 12),  # west wing: south, west (up to the portico), east
             (xe0, 0, X1, 0), (X1, 0, X1, 15), (xe0, 0, xe0, 12),  # east wing
             (0, 12, X1, 12),  # the corridor's south wall (wings' and hall's north wall)
             (0, 6, 12, 6), (xe0, 6, X1, 6)]  # partitions between the two rooms of each wing
    walls = unary_union([LineString([(a, b), (c, d)]).buffer(t / 2.0, cap_style=3) for a, b, c, d in segs])
    doors = [("AULA 1", "HALL DISTRIBUZIONE", LineString([(12, 2.0), (12, 3.0)])),
             ("UFFICIO 1", "HALL DISTRIBUZIONE", LineString([(xe0, 2.0), (xe0, 3.0)])),
             ("AULA 1", "AULA 2", LineString([(8.0, 6), (9.0, 6)])),
             ("UFFICIO 1", "UFFICIO 2", LineString([(xe0 + 3.0, 6), (xe0 + 4.0, 6)])),
             ("AULA 2", "CORRIDOIO DI DISTRIBUZIONE", LineString([(4.0, 12), (5.0, 12)])),
             ("UFFICIO 2", "CORRIDOIO DI DISTRIBUZIONE", LineString([(X1 - 5.0, 12), (X1 - 4.0, 12)])),
             ("HALL DISTRIBUZIONE", "CORRIDOIO DI DISTRIBUZIONE",
              LineString([(12 + w / 2 - 1.0, 12), (12 + w / 2 + 1.0, 12)]))]
    walls = walls.difference(unary_union([d.buffer(t, cap_style=2) for _, _, d in doors]))
    # pillars of the portico (0.4 m squares) on its open north side, y = 15
    n = max(1, int(round(X1 / pillar_pitch)))
    pillars = [box(X1 * k / n - 0.2, 14.8, X1 * k / n + 0.2, 15.2) for k in range(1, n)]
    walls = unary_union([walls] + pillars)
    rooms = {"AULA 1": box(t / 2, t / 2, 12 - t / 2, 6 - t / 2), "AULA 2": box(t / 2, 6 + t / 2, 12 - t / 2, 12 - t / 2),
             "UFFICIO 1": box(xe0 + t / 2, t / 2, X1 - t / 2, 6 - t / 2),
             "UFFICIO 2": box(xe0 + t / 2, 6 + t / 2, X1 - t / 2, 12 - t / 2),
             "HALL DISTRIBUZIONE": box(12 + t / 2, 0.0, xe0 - t / 2, 12 - t / 2),
             "CORRIDOIO DI DISTRIBUZIONE": box(t / 2, 12 + t / 2, X1 - t / 2, 15.0)}
    rooms = {k: v.difference(walls) for k, v in rooms.items()}
    labels = {"AULA 1": (6.0, 3.0), "AULA 2": (6.0, 9.0), "UFFICIO 1": (xe0 + 6.0, 3.0), "UFFICIO 2": (xe0 + 6.0, 9.0),
              "HALL DISTRIBUZIONE": (12 + w / 2, 6.0), "CORRIDOIO DI DISTRIBUZIONE": (X1 / 2 + 2.5, 13.6)}
    return walls, rooms, doors, labels


def generate_open_facade(out_dir: str, name: str = "open-facade", hall_width: float = 10.0,
                         pillar_pitch: float = 5.0) -> dict:
    """Write ``<out_dir>/<name>.dxf`` (metres, ``$INSUNITS`` = 6) of ``open_facade_plan``: walls and
    pillars as solid hatches with their outlines on ``A-WALL``, the portico's closing line as a
    DASHDOT line on ``A-ANNO-PROJ`` (a projection, not a wall), room names as TEXT on
    ``A-ANNO-TEXT``, a title far outside. Returns ``{"dxf", "rooms" (name -> Polygon), "doors",
    "labels"}``."""
    import ezdxf

    walls, rooms, doors, labels = open_facade_plan(hall_width, pillar_pitch)
    os.makedirs(os.path.abspath(out_dir), exist_ok=True)
    doc = ezdxf.new("R2018", setup=["linetypes"])
    doc.ezdxf_metadata()["CREATED_BY_EZDXF"] = f"{ezdxf.__version__} @ cad2osmag open facade sample"
    doc.header["$INSUNITS"] = 6
    doc.layers.add("A-WALL", color=7)
    doc.layers.add("A-ANNO-PROJ", color=8, linetype="DASHDOT")
    doc.layers.add("A-ANNO-TEXT", color=2)
    doc.layers.add("A-ANNO-TITL", color=2)
    msp = doc.modelspace()
    for poly in _pieces_m(walls):
        _add_solid_hatch(msp, poly, "A-WALL")
        msp.add_lwpolyline(list(poly.exterior.coords)[:-1], close=True, dxfattribs={"layer": "A-WALL"})
    x1 = max(b.bounds[2] for b in rooms.values())
    msp.add_line((0, 15.0), (x1, 15.0), dxfattribs={"layer": "A-ANNO-PROJ", "linetype": "DASHDOT"})
    for text, (x, y) in labels.items():
        msp.add_text(text, height=0.3, dxfattribs={"layer": "A-ANNO-TEXT"}).set_placement(
            (x, y), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    msp.add_text("Open facade sample, scale 1:100", height=0.5,
                 dxfattribs={"layer": "A-ANNO-TITL"}).set_placement((0.0, -6.0))
    path = os.path.join(os.path.abspath(out_dir), f"{name}.dxf")
    _save_deterministic(doc, path)
    return {"dxf": path, "rooms": rooms, "doors": doors, "labels": labels}


def _pieces_m(geom) -> List[Polygon]:
    """Polygon pieces of a geometry in metres, in a stable order."""
    geoms = list(geom.geoms) if hasattr(geom, "geoms") else [geom]
    geoms = [g for g in geoms if g.area > 1e-6]
    return sorted(geoms, key=lambda g: (round(g.bounds[0], 3), round(g.bounds[1], 3), round(g.area, 3)))


# ------------------------------------------------------------------ open stairs and lifts (vertical anchors)
OPEN_ANCHORS_WALL = 0.25  # metres


def open_anchors_plan():
    """The layout of ``generate_open_anchors`` in metres: ``(walls, rooms, stair, lift, labels)``.

    An atrium ("ATRIO", x 0..20, y 0..14) holds an **open stair**: one straight flight of 12 treads (1.4 m
    wide, 0.28 m going) drawn on the stair layer, free-standing in the middle of the atrium with no wall
    around it. North of the atrium runs a corridor ("CORRIDOIO", y 14..16.4, x 0..32) it opens onto through
    a 2 m doorway. North of the corridor, between two offices, a **lift shaft** (2.2 x 2.2 m, walls on
    three sides) opens straight onto the corridor over its whole width: no door, no narrowing; its car is
    drawn with a cross on the lift layer. An office ("UFFICIO EST", x 20..32, y 0..14) beside the atrium has a
    door to the corridor, and two offices north of the corridor one door each. ``stair`` and ``lift`` are
    the ground-truth footprints (the flight's box; the shaft's free inside)."""
    t = OPEN_ANCHORS_WALL
    segs = [(0, 0, 32, 0), (0, 0, 0, 19), (32, 0, 32, 19), (0, 19, 32, 19),  # envelope
            (0, 14, 32, 14), (20, 0, 20, 14),  # corridor's south wall, atrium | office
            (0, 16.4, 32, 16.4),  # corridor's north wall
            (12, 16.4, 12, 19), (14.2, 16.4, 14.2, 19)]  # lift shaft side walls (the shaft is 12..14.2)
    walls = unary_union([LineString([(a, b), (c, d)]).buffer(t / 2.0, cap_style=3) for a, b, c, d in segs])
    doors = [box(9.0, 14 - t, 11.0, 14 + t),  # atrium -> corridor, 2 m
             box(25.0, 14 - t, 26.0, 14 + t),  # east office -> corridor
             box(5.0, 16.4 - t, 6.0, 16.4 + t), box(22.0, 16.4 - t, 23.0, 16.4 + t),  # north offices
             box(12 + t / 2, 16.4 - t, 14.2 - t / 2, 16.4 + t)]  # the lift's open side: the whole shaft width
    walls = walls.difference(unary_union(doors))
    h = t / 2
    rooms = {"ATRIO": box(h, h, 20 - h, 14 - h), "UFFICIO EST": box(20 + h, h, 32 - h, 14 - h),
             "CORRIDOIO": box(h, 14 + h, 32 - h, 16.4 - h), "UFFICIO NORD 1": box(h, 16.4 + h, 12 - h, 19 - h),
             "UFFICIO NORD 2": box(14.2 + h, 16.4 + h, 32 - h, 19 - h)}
    stair = box(9.3, 4.0, 10.7, 4.0 + 12 * 0.28)
    lift = box(12 + h, 16.4 + h, 14.2 - h, 19 - h)
    labels = {"ATRIO": (4.0, 10.0), "UFFICIO EST": (26.0, 7.0), "CORRIDOIO": (20.0, 15.2),
              "UFFICIO NORD 1": (6.0, 17.7), "UFFICIO NORD 2": (23.0, 17.7)}
    return walls, rooms, stair, lift, labels


def _angles(a0: float, a1: float, n: int) -> List[float]:
    return [a0 + (a1 - a0) * k / (n - 1) for k in range(n)]


def generate_open_anchors(out_dir: str, name: str = "open-anchors", curved: bool = False) -> dict:
    """Write ``<out_dir>/<name>.dxf`` (metres, ``$INSUNITS`` = 6) of ``open_anchors_plan``: walls as solid
    hatches with outlines on ``A-WALL``, the open stair's treads and side strings on ``A-STAIR``, the lift
    car (outline and cross) on the lift layer, room names as TEXT on ``A-ANNO-TEXT``. Returns
    ``{"dxf", "rooms", "stair", "lift", "labels"}``. ``curved``: the flight goes on beyond its 12 straight
    treads, turning west through 90° on 12 radial treads between two arc strings (radii 0.6 and 2.0 m round
    (8.7, 7.36)), a free-standing curved flight; ``stair`` is then the whole flight's footprint."""
    import ezdxf

    walls, rooms, stair, lift, labels = open_anchors_plan()
    os.makedirs(os.path.abspath(out_dir), exist_ok=True)
    doc = ezdxf.new("R2018")
    doc.ezdxf_metadata()["CREATED_BY_EZDXF"] = f"{ezdxf.__version__} @ cad2osmag open anchors sample"
    doc.header["$INSUNITS"] = 6
    for layer in ("A-WALL", "A-STAIR", LIFT_LAYER, "A-ANNO-TEXT"):
        doc.layers.add(layer, color=7)
    msp = doc.modelspace()
    for poly in _pieces_m(walls):
        _add_solid_hatch(msp, poly, "A-WALL")
        msp.add_lwpolyline(list(poly.exterior.coords)[:-1], close=True, dxfattribs={"layer": "A-WALL"})
    x0, y0, x1, y1 = stair.bounds
    lay = {"layer": "A-STAIR"}
    for k in range(13):  # 12 goings: 13 nosing lines
        y = y0 + 0.28 * k
        msp.add_line((x0, y), (x1, y), dxfattribs=lay)
    msp.add_line((x0, y0), (x0, y1), dxfattribs=lay)  # strings
    msp.add_line((x1, y0), (x1, y1), dxfattribs=lay)
    if curved:
        cx, cy, r0, r1 = x0 - 0.6, y1, 0.6, 0.6 + (x1 - x0)
        for k in range(1, 13):  # radial treads every 7.5°
            a = math.radians(7.5 * k)
            msp.add_line((cx + r0 * math.cos(a), cy + r0 * math.sin(a)), (cx + r1 * math.cos(a), cy + r1 * math.sin(a)),
                         dxfattribs=lay)
        for r in (r0, r1):  # the strings, as polylines of 5 cm-ish chords
            msp.add_lwpolyline([(cx + r * math.cos(a), cy + r * math.sin(a)) for a in _angles(0.0, math.pi / 2, 25)],
                               dxfattribs=lay)
        arc = [(cx + r1 * math.cos(a), cy + r1 * math.sin(a)) for a in _angles(0.0, math.pi / 2, 60)]
        arc += [(cx + r0 * math.cos(a), cy + r0 * math.sin(a)) for a in _angles(math.pi / 2, 0.0, 60)]
        stair = unary_union([stair, Polygon(arc)])
    lx0, ly0, lx1, ly1 = lift.bounds
    c0, c1 = (lx0 + 0.15, ly0 + 0.25), (lx1 - 0.15, ly1 - 0.15)
    lay = {"layer": LIFT_LAYER}
    msp.add_lwpolyline([c0, (c1[0], c0[1]), c1, (c0[0], c1[1])], close=True, dxfattribs=lay)
    msp.add_line(c0, c1, dxfattribs=lay)
    msp.add_line((c1[0], c0[1]), (c0[0], c1[1]), dxfattribs=lay)
    for text, (x, y) in labels.items():
        msp.add_text(text, height=0.3, dxfattribs={"layer": "A-ANNO-TEXT"}).set_placement(
            (x, y), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    path = os.path.join(os.path.abspath(out_dir), f"{name}.dxf")
    _save_deterministic(doc, path)
    return {"dxf": path, "rooms": rooms, "stair": stair, "lift": lift, "labels": labels}
