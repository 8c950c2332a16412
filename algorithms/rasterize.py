"""Stage 2: rasterize structural geometry into an occupancy grid (0 free / 255 occupied).

Public API
----------
``rasterize(geometries, resolution=0.044, padding=0.03, percentiles=(0.5, 99.5), kernel=5,
extent=None, max_pixels=60e6, stroke=0.15, progress=None) -> OccupancyGrid``
``geometry_bounds(geometries, percentiles=(0.5, 99.5)) -> (xmin, ymin, xmax, ymax)``
``common_extent(geometry_sets, padding=0.03, percentiles=(0.5, 99.5)) -> (xmin, ymin, xmax, ymax)``
``grid_for_extent(extent, resolution, max_pixels=60e6) -> (origin_x, origin_y, rows, cols)``
``floor_grids(geometry_sets, resolution=0.044, ..., align=None, extent=None) -> (grids, offsets)``
    Several floors on one common grid (same shape; pixel (r, c) is the same place on every floor).
    Floors drawn with different origins are registered first (``floor_offsets``: translation by FFT
    cross-correlation of anti-aliased coarse rasters, about 1 cm); floor k's geotransform still maps
    onto its own CAD frame (origin_k = common origin - offset_k, offsets rounded to the resolution).
``common_grid(...) -> (extent, offsets)`` and ``floor_extent(extent, offset)``: the same in two steps,
    for callers that rasterize one floor at a time (the Processing algorithm).

Raster convention: uint8, 0 = free, 255 = occupied (``algorithms.model``); this is the inverse of a
ROS map_server image (where black = occupied), ``raster_io`` converts when writing ROS maps.
The geotransform is ``(origin_x, res, 0, origin_y, 0, -res)`` in the CAD frame (metres), with the
origin snapped to a multiple of the resolution so that rasters of several floors rasterized on a
common extent line up pixel for pixel.

Drawing: hairlines get a physical stroke width (``stroke`` metres, and at least the repair kernel so
that single-line walls survive the opening), wide polylines their own width, filled entities (solid
hatches, SOLIDs) are filled with the even-odd rule (NaN rows separate rings).

Repair: closing with a ``kernel`` x ``kernel`` rectangle (bridges gaps of about kernel*res, plus the
stroke's round caps: 0.2 m at the defaults), then an opening with the same kernel used as a speck
filter: a connected component of occupied pixels survives when any part of it survives the opening
(opening by reconstruction) or when it spans more than 2*kernel pixels, so that thin diagonal walls
are kept while isolated specks are removed.
"""
from __future__ import annotations

import math
from typing import Iterable, List, Optional, Sequence, Tuple

import numpy as np

from .errors import InputError
from .model import FREE, OCCUPIED, CadGeometry, OccupancyGrid
from .progress import ensure

# The drawing's own frame as a CRS: a local engineering CRS in metres (QGIS 3.22 accepts this WKT2;
# GDAL stores it as LOCAL_CS in GeoTIFFs). ``OccupancyGrid.crs_wkt`` stays "" for this frame in the
# pipeline; use ``is_local_frame`` to recognise either form.
LOCAL_FRAME_NAME = "CAD drawing frame (local, metres)"
LOCAL_FRAME_WKT = (
    f'ENGCRS["{LOCAL_FRAME_NAME}",EDATUM["CAD drawing origin"],CS[Cartesian,2],'
    'AXIS["drawing x (E)",east,ORDER[1],LENGTHUNIT["metre",1]],'
    'AXIS["drawing y (N)",north,ORDER[2],LENGTHUNIT["metre",1]]]')
LOCAL_FRAME_WKT1 = (f'LOCAL_CS["{LOCAL_FRAME_NAME}",LOCAL_DATUM["CAD drawing origin",32767],UNIT["metre",1],'
                    'AXIS["Easting",EAST],AXIS["Northing",NORTH]]')


def is_local_frame(wkt: str) -> bool:
    """True for "" (no CRS) and for the local drawing frame written by this plugin."""
    return not wkt or LOCAL_FRAME_NAME in wkt or wkt.lstrip().upper().startswith(("LOCAL_CS", "ENGCRS"))


DEFAULT_RESOLUTION = 0.044
DEFAULT_PADDING = 0.03
DEFAULT_PERCENTILES = (0.5, 99.5)
DEFAULT_KERNEL = 5
DEFAULT_MAX_PIXELS = 60e6
MIN_OCCUPIED_SHARE = 0.0005  # a floor plan's walls cover a few percent of its raster, never 0.05 %
DEFAULT_FREE_KINDS = ("stair", "elevator")  # symbols inside stair and lift areas, not obstacles
DEFAULT_STROKE = 0.15  # metres: drawn width of a hairline
SHIFT = 4  # cv2 sub-pixel bits
_ONE = 1 << SHIFT
_LIMIT = float(2 ** 30 // _ONE)  # keep int32 pixel coordinates far from overflow


def _all_vertices(geometries: Sequence[CadGeometry]) -> np.ndarray:
    arrs = [g.coords for g in geometries if len(g.coords)]
    if not arrs:
        return np.zeros((0, 2))
    allc = np.concatenate(arrs, axis=0)
    return allc[np.isfinite(allc).all(axis=1)]


def geometry_bounds(geometries: Sequence[CadGeometry], percentiles=DEFAULT_PERCENTILES, grow: bool = True
                    ) -> Tuple[float, float, float, float]:
    """Percentile bounds (xmin, ymin, xmax, ymax) of every vertex, robust against stray entities,
    grown (``grow``) to the full extent of the entities that reach into them."""
    v = _all_vertices(geometries)
    if len(v) == 0:
        raise InputError("there is no geometry to rasterize (the wall layer is empty); check the layer "
                         "selection of the CAD import")
    lo_p, hi_p = float(percentiles[0]), float(percentiles[1])
    if not (0.0 <= lo_p < hi_p <= 100.0):
        raise InputError(f"percentiles must be two numbers 0 <= low < high <= 100, got {percentiles}")
    lo = np.percentile(v, lo_p, axis=0)
    hi = np.percentile(v, hi_p, axis=0)
    box = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
    return _grow_to_touching(geometries, box) if grow else box


BOUNDARY_REACH = 4.0  # metres: projection lines this close to the drawing's bounds widen the raster to hold them


def _grow_to_boundary(boundary: Sequence[CadGeometry], box, reach: float = BOUNDARY_REACH):
    """Grow ``box`` to hold the boundary evidence lines (kind "boundary") lying within ``reach`` of it: a
    corridor closed only by a projection line lies beyond the walls' bounds."""
    x0, y0, x1, y1 = box
    for g in boundary:
        c = g.coords[np.isfinite(g.coords).all(axis=1)]
        if not len(c):
            continue
        mn, mx = c.min(axis=0), c.max(axis=0)
        if mx[0] < box[0] - reach or mn[0] > box[2] + reach or mx[1] < box[1] - reach or mn[1] > box[3] + reach:
            continue
        if mn[0] < box[0] - reach or mx[0] > box[2] + reach or mn[1] < box[1] - reach or mx[1] > box[3] + reach:
            continue  # reaching far beyond the plan: an axis, a site line
        x0, y0, x1, y1 = min(x0, mn[0]), min(y0, mn[1]), max(x1, mx[0]), max(y1, mx[1])
    return (float(x0), float(y0), float(x1), float(y1))


def _grow_to_touching(geometries: Sequence[CadGeometry], box, max_growth: float = 0.5):
    """Extend a percentile box to the full bounds of every geometry that reaches into it.

    Percentiles of vertices cut off sparse but real parts of a building (a long wing drawn with few
    long lines); entities that touch the core box are part of the building, strays far away are not.
    Growth is capped at ``max_growth`` times the box size on each side.
    """
    xmin, ymin, xmax, ymax = box
    arrs = [g.coords for g in geometries if len(g.coords)]
    if not arrs:
        return box
    # per-geometry bounds in one pass over all vertices (NaN separators ignored, as by nanmin)
    lens = np.array([len(c) for c in arrs])
    starts = np.r_[0, np.cumsum(lens)[:-1]]
    allc = np.concatenate(arrs, axis=0).astype(np.float64, copy=False)
    with np.errstate(invalid="ignore"):
        mn = np.fmin.reduceat(allc, starts, axis=0)
        mx = np.fmax.reduceat(allc, starts, axis=0)
    two = np.flatnonzero(lens == 2)
    if len(two):  # two vertices: min()/max() of Python (a NaN first vertex wins)
        a, b = allc[starts[two]], allc[starts[two] + 1]
        mn[two] = np.where(b < a, b, a)
        mx[two] = np.where(b > a, b, a)
    touch = (mx[:, 0] >= xmin) & (mn[:, 0] <= xmax) & (mx[:, 1] >= ymin) & (mn[:, 1] <= ymax)
    if not touch.any():
        return box
    w, h = xmax - xmin, ymax - ymin
    nx0 = max(float(mn[touch, 0].min()), xmin - max_growth * w)
    ny0 = max(float(mn[touch, 1].min()), ymin - max_growth * h)
    nx1 = min(float(mx[touch, 0].max()), xmax + max_growth * w)
    ny1 = min(float(mx[touch, 1].max()), ymax + max_growth * h)
    return (min(nx0, xmin), min(ny0, ymin), max(nx1, xmax), max(ny1, ymax))


def pad_extent(extent, padding: float) -> Tuple[float, float, float, float]:
    """Grow an extent by ``padding`` times its larger side on every side (3 % by default)."""
    xmin, ymin, xmax, ymax = extent
    pad = float(padding) * max(xmax - xmin, ymax - ymin, 0.0)
    return (xmin - pad, ymin - pad, xmax + pad, ymax + pad)


def common_extent(geometry_sets: Iterable[Sequence[CadGeometry]], padding: float = DEFAULT_PADDING,
                  percentiles=DEFAULT_PERCENTILES) -> Tuple[float, float, float, float]:
    """Union of the percentile bounds of several drawings (floors), padded once."""
    boxes = [geometry_bounds(g, percentiles) for g in geometry_sets]
    if not boxes:
        raise InputError("common_extent needs at least one drawing")
    b = np.array(boxes)
    union = (float(b[:, 0].min()), float(b[:, 1].min()), float(b[:, 2].max()), float(b[:, 3].max()))
    return pad_extent(union, padding)


def suggest_resolution(width: float, height: float, max_pixels: float) -> float:
    r = math.sqrt(max(width * height, 1e-12) / max_pixels) * 1.05
    mag = 10 ** math.floor(math.log10(r))
    return math.ceil(r / mag * 100) / 100 * mag


def grid_for_extent(extent, resolution: float, max_pixels: float = DEFAULT_MAX_PIXELS):
    """Snap an extent outward to multiples of ``resolution``: (origin_x, origin_y, rows, cols)."""
    if not (resolution > 0 and math.isfinite(resolution)):
        raise InputError(f"resolution must be a positive number of metres per pixel, got {resolution}")
    xmin, ymin, xmax, ymax = (float(v) for v in extent)
    if not all(math.isfinite(v) for v in (xmin, ymin, xmax, ymax)) or xmax <= xmin or ymax <= ymin:
        raise InputError(f"invalid extent {extent}: it needs xmin < xmax and ymin < ymax")
    eps = 1e-6
    c0 = math.floor(xmin / resolution + eps)
    c1 = math.ceil(xmax / resolution - eps)
    r0 = math.floor(ymin / resolution + eps)
    r1 = math.ceil(ymax / resolution - eps)
    cols, rows = max(1, c1 - c0), max(1, r1 - r0)
    if rows * cols > max_pixels:
        w, h = xmax - xmin, ymax - ymin
        raise InputError(
            f"the raster would be {cols} x {rows} = {rows * cols / 1e6:.1f} Mpx, more than the budget of "
            f"{max_pixels / 1e6:.0f} Mpx: the extent is {w:.1f} m x {h:.1f} m (x {xmin:.2f}..{xmax:.2f}, "
            f"y {ymin:.2f}..{ymax:.2f}) at {resolution} m/px. Use a resolution of at least "
            f"{suggest_resolution(w, h, max_pixels):.3g} m/px, raise the pixel budget, convert one plan of the sheet "
            "at a time (select its layers or give an extent), or check the drawing's units and stray entities far "
            "from the building")
    return c0 * resolution, r1 * resolution, rows, cols


BYTES_PER_PIXEL = 50  # peak memory of the whole pipeline per raster pixel (measured: 44 B/px, 2.5-10 Mpx)


def available_memory() -> Optional[int]:
    """Bytes of memory available to this process (Linux MemAvailable), None when unknown."""
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return None


def check_memory(rows: int, cols: int, resolution: float) -> None:
    """Raise InputError (nothing allocated yet) when the pipeline on a rows x cols raster would need more
    memory than the machine has available."""
    avail = available_memory()
    need = rows * cols * BYTES_PER_PIXEL
    if avail is not None and need > avail:
        fit = resolution * math.sqrt(need / avail) * 1.05
        raise InputError(
            f"a {cols} x {rows} px raster ({rows * cols / 1e6:.1f} Mpx at {resolution} m/px) needs about "
            f"{need / 2 ** 30:.1f} GB of memory to segment, more than the {avail / 2 ** 30:.1f} GB available: use "
            f"a coarser resolution (at least {fit:.3g} m/px), convert one plan of the sheet at a time (select its "
            "layers or give an extent), check the drawing's units, or close other programs")


def _split_rings(c: np.ndarray) -> List[np.ndarray]:
    if not np.isnan(c).any():
        return [c]
    bad = np.isnan(c).any(axis=1)
    idx = np.flatnonzero(bad)
    parts = np.split(c, idx)
    return [p[~np.isnan(p).any(axis=1)] for p in parts if len(p[~np.isnan(p).any(axis=1)])]


def _to_px(c: np.ndarray, ox: float, oy: float, res: float) -> np.ndarray:
    """World -> cv2 fixed-point pixel coordinates (pixel centres at integers)."""
    col = (c[:, 0] - ox) / res - 0.5
    row = (oy - c[:, 1]) / res - 0.5
    pts = np.empty((len(c), 2), dtype=np.float64)
    pts[:, 0] = np.clip(col, -_LIMIT, _LIMIT)
    pts[:, 1] = np.clip(row, -_LIMIT, _LIMIT)
    return np.rint(pts * _ONE).astype(np.int32)


def cv_thickness(width_px: float) -> int:
    """cv2 ``thickness`` whose drawn width (always odd: 1, 3, 5... px) is closest to ``width_px``."""
    n = max(1, 2 * int(round((float(width_px) - 1.0) / 2.0)) + 1)
    return 1 if n == 1 else n - 1


def draw_geometries(img: np.ndarray, geometries: Sequence[CadGeometry], ox: float, oy: float, res: float,
                    hairline_px: int, progress=None, antialias: bool = False) -> None:
    import cv2

    lt = cv2.LINE_AA if antialias else cv2.LINE_8

    by_thickness = {}
    filled = []
    n = len(geometries)
    for i, g in enumerate(geometries):
        c = g.coords
        if len(c) == 0:
            continue
        if g.filled and len(c) >= 3:
            filled.append(g)
            continue
        t = hairline_px if g.width <= 0 else max(hairline_px, cv_thickness(g.width / res))
        lst = by_thickness.setdefault(t, ([], []))
        for ring in _split_rings(c):
            if len(ring) == 1:
                ring = np.vstack((ring, ring))
            (lst[0] if (g.closed and len(ring) >= 3) else lst[1]).append(ring)
        if progress is not None and i % 5000 == 4999:
            progress.step(80.0 * i / n)
    # one pixel conversion of all rings at once (per-ring calls were most of this step's time)
    rings = [r for closed, opened in by_thickness.values() for r in closed + opened]
    if rings:
        px = np.split(_to_px(np.concatenate(rings), ox, oy, res), np.cumsum([len(r) for r in rings])[:-1])
        k = 0
        for closed, opened in by_thickness.values():
            for lst in (closed, opened):
                lst[:] = px[k:k + len(lst)]
                k += len(lst)
    for t, (closed, opened) in by_thickness.items():
        if closed:
            cv2.polylines(img, closed, True, OCCUPIED, thickness=t, lineType=lt, shift=SHIFT)
        if opened:
            cv2.polylines(img, opened, False, OCCUPIED, thickness=t, lineType=lt, shift=SHIFT)
    for g in filled:
        rings = [_to_px(r, ox, oy, res) for r in _split_rings(g.coords) if len(r) >= 3]
        if rings:
            cv2.fillPoly(img, rings, OCCUPIED, lineType=lt, shift=SHIFT)
            # the outline too, so thin filled slivers do not vanish
            cv2.polylines(img, rings, True, OCCUPIED, thickness=1, lineType=lt, shift=SHIFT)


REPAIR_BOXES = 2000  # specks looked at one by one in their boxes up to this many (more: one whole-raster pass)


def repair(img: np.ndarray, kernel: int) -> np.ndarray:
    """Closing then opening-by-reconstruction with a kernel x kernel rectangle (see module doc)."""
    import cv2

    k = int(kernel)
    if k <= 1:
        return img
    se = cv2.getStructuringElement(cv2.MORPH_RECT, (k, k))
    closed = cv2.morphologyEx(img, cv2.MORPH_CLOSE, se, borderType=cv2.BORDER_CONSTANT, borderValue=0)
    opened = cv2.morphologyEx(closed, cv2.MORPH_OPEN, se, borderType=cv2.BORDER_CONSTANT, borderValue=0)
    closed = cv2.threshold(closed, 0, OCCUPIED, cv2.THRESH_BINARY)[1]  # every occupied value is OCCUPIED
    n, labels, stats, _ = cv2.connectedComponentsWithStats(closed, connectivity=8)
    if n <= 1:
        return closed
    # a piece spanning more than 2 kernels is kept; a smaller one only when the opening left some of it: such
    # pieces are specks, each looked at in its own box (not the whole raster: ~0.1 s on a SIST floor)
    span = np.maximum(stats[:, cv2.CC_STAT_WIDTH], stats[:, cv2.CC_STAT_HEIGHT])
    small = np.flatnonzero(span[1:] <= 2 * k) + 1
    if len(small) > REPAIR_BOXES:  # a speckled drawing: one pass over the raster beats that many boxes
        keep = span > 2 * k
        keep[labels[opened > 0]] = True
        keep[0] = False
        return np.where(keep, OCCUPIED, FREE).astype(np.uint8)[labels]
    for i in small:
        x, y, w, h = (int(v) for v in stats[i, :4])
        box = (slice(y, y + h), slice(x, x + w))
        piece = labels[box] == i
        if not (opened[box][piece] > 0).any():
            closed[box][piece] = FREE
    return closed


DOOR_CLEAR_DEPTH = 0.6  # metres across a door hint that are kept free (walls up to this thick)
DOOR_JAMB_INSET = 0.05  # metres kept occupied at each jamb, so the jambs stay walls


def _door_segments(door_hints):
    """(a, b, length, unit direction) of every usable door hint: finite, 0.3-4 m jamb to jamb (shorter or
    longer is no doorway: a misread block)."""
    for h in door_hints or ():
        a = np.array((h.x0, h.y0), float)
        b = np.array((h.x1, h.y1), float)
        if not (np.isfinite(a).all() and np.isfinite(b).all()):
            continue
        L = float(np.hypot(*(b - a)))
        if not 0.3 <= L <= 4.0:
            continue
        yield a, b, L, (b - a) / L


def door_opening_mask(door_hints, shape, origin_x: float, origin_y: float, resolution: float,
                      depth: float = DOOR_CLEAR_DEPTH) -> np.ndarray:
    """Boolean mask of the door openings of ``door_hints`` (``model.DoorHint``, jamb-to-jamb
    segments in metres): a rectangle ``depth`` deep centred on each segment, inset by
    ``DOOR_JAMB_INSET`` at both jambs. Hints shorter than 0.3 m or longer than 4 m are ignored
    (no doorway; a misread block)."""
    import cv2

    mask = np.zeros(shape, np.uint8)
    for a, b, L, u in _door_segments(door_hints):
        nrm = np.array((-u[1], u[0])) * depth / 2.0
        a2, b2 = a + u * DOOR_JAMB_INSET, b - u * DOOR_JAMB_INSET
        quad = np.array([a2 + nrm, b2 + nrm, b2 - nrm, a2 - nrm])
        cv2.fillConvexPoly(mask, _to_px(quad, origin_x, origin_y, resolution), 1, lineType=cv2.LINE_8, shift=SHIFT)
    return mask.view(bool)


DOOR_MAX_WALL = 1.2  # metres: a door hint opens a wall up to this thick (thick masonry, two walls at a joint)
DOOR_ROOM_RUN = 0.3  # metres of free space behind a wall that count as the room beyond it (a cavity is thinner)


def deepen_openings(img: np.ndarray, door_hints, origin_x: float, origin_y: float, resolution: float,
                    depth: float = DOOR_CLEAR_DEPTH, max_wall: float = DOOR_MAX_WALL,
                    room_run: float = DOOR_ROOM_RUN) -> np.ndarray:
    """Mask of what a door hint must also clear when its wall is thicker than ``depth``: door blocks are
    inserted at one face of the wall, and thick masonry or two walls side by side (a joint, with a thin
    cavity between) stay closed behind a ``depth``-deep opening. On each side of each hint, walk along the
    normal from ``depth / 2``: while occupied pixels lie across the opening (or a free run thinner than
    ``room_run``, a cavity), the wall goes on; the first free run of ``room_run`` is the room, and the
    opening is cleared up to it. Nothing is added when no room is met within ``max_wall`` of the hint."""
    import cv2

    mask = np.zeros(img.shape, np.uint8)
    rows, cols = img.shape
    steps = np.arange(depth / 2.0, max_wall + room_run + resolution, resolution / 2.0)
    need = max(1, int(round(room_run / (resolution / 2.0))))
    for a, b, L, u in _door_segments(door_hints):
        nrm = np.array((-u[1], u[0]))
        a2, b2 = a + u * DOOR_JAMB_INSET, b - u * DOOR_JAMB_INSET
        across = a2[None, :] + np.linspace(0.2, 0.8, 5)[:, None] * (b2 - a2)[None, :]  # inner 60 % of the width
        for sgn in (1.0, -1.0):
            pts = across[None, :, :] + sgn * steps[:, None, None] * nrm[None, None, :]
            c = np.floor((pts[..., 0] - origin_x) / resolution).astype(np.int64)
            r = np.floor((origin_y - pts[..., 1]) / resolution).astype(np.int64)
            inside = (c >= 0) & (c < cols) & (r >= 0) & (r < rows)
            occ = np.ones(c.shape, bool)
            occ[inside] = img[r[inside], c[inside]] > 0
            blocked = occ.any(axis=1)
            if not blocked[0] and not blocked[: need].any():
                continue  # the room starts at the default opening: nothing to deepen
            free_run, end = 0, None
            for k, bl in enumerate(blocked):
                free_run = 0 if bl else free_run + 1
                if free_run >= need:
                    end = k - need + 1
                    break
            if end is None or steps[end] > max_wall:
                continue  # no room within a wall's thickness: not a doorway through this wall
            d = steps[end] + resolution
            quad = np.array([a2, b2, b2 + sgn * d * nrm, a2 + sgn * d * nrm])
            cv2.fillConvexPoly(mask, _to_px(quad, origin_x, origin_y, resolution), 1, lineType=cv2.LINE_8,
                               shift=SHIFT)
    return mask.view(bool)


def rasterize(geometries: Sequence[CadGeometry], resolution: float = DEFAULT_RESOLUTION,
              padding: float = DEFAULT_PADDING, percentiles=DEFAULT_PERCENTILES, kernel: int = DEFAULT_KERNEL,
              extent: Optional[Sequence[float]] = None, max_pixels: float = DEFAULT_MAX_PIXELS,
              stroke: float = DEFAULT_STROKE, free_kinds: Sequence[str] = DEFAULT_FREE_KINDS,
              door_hints=None, progress=None) -> OccupancyGrid:
    """Rasterize geometries (metres) into an occupancy grid.

    Geometries whose kind is in ``free_kinds`` (by default stair treads and lift symbols) count for
    the extent but are not drawn: a stair run or a lift car is the area a robot's map needs, its
    enclosure is drawn on wall layers. Pass ``free_kinds=()`` to draw them as obstacles.

    ``extent`` (xmin, ymin, xmax, ymax), when given, is used as is (no percentiles, no padding),
    snapped outward to the resolution: use it with ``common_extent`` for multi-floor sets.

    ``door_hints`` (``model.DoorHint``: doorways found by the CAD import) are kept open: their
    openings are cleared after the repair (``door_opening_mask``), whatever door leaves or wall
    hatches were drawn across them.
    """
    progress = ensure(progress)
    if not (resolution and resolution > 0):
        raise InputError(f"resolution must be a positive number of metres per pixel, got {resolution}")
    if kernel is None or int(kernel) < 0:
        raise InputError(f"kernel must be a non-negative number of pixels, got {kernel}")
    if padding is None or padding < 0:
        raise InputError(f"padding must be >= 0 (a fraction of the building size), got {padding}")
    geometries = [g for g in geometries if len(g.coords)]
    if extent is None:
        walls = [g for g in geometries if g.kind != "boundary"]
        box = geometry_bounds(walls or geometries, percentiles)
        if len(walls) < len(geometries) and walls:
            box = _grow_to_boundary([g for g in geometries if g.kind == "boundary"], box)
        extent = pad_extent(box, padding)
        # at least one stroke of margin so walls at the border are not cut
        m = 2 * max(stroke, resolution * max(int(kernel), 1))
        extent = (extent[0] - m, extent[1] - m, extent[2] + m, extent[3] + m)
    elif not geometries:
        raise InputError("there is no geometry to rasterize (the wall layer is empty)")
    ox, oy, rows, cols = grid_for_extent(extent, resolution, max_pixels)
    check_memory(rows, cols, resolution)  # before allocating: segmentation needs ~50 bytes per pixel
    progress.step(5, f"raster {cols} x {rows} px at {resolution} m/px")
    img = np.zeros((rows, cols), dtype=np.uint8)
    hair = cv_thickness(stroke / resolution)
    free_kinds = set(free_kinds or ())
    # boundary evidence (kind "boundary", ``boundary_mask``) counts for the extent, never drawn: no walls
    draw_geometries(img, [g for g in geometries if g.kind not in free_kinds and g.kind != "boundary"], ox, oy,
                    resolution, hair,
                    progress.sub(5, 70))
    progress.step(70, "closing gaps and removing specks")
    img = repair(img, int(kernel))
    if door_hints:
        opening = door_opening_mask(door_hints, img.shape, ox, oy, resolution)
        opening |= deepen_openings(img, door_hints, ox, oy, resolution)
        progress.info(f"{len(door_hints)} door hints kept open ({int(np.count_nonzero(opening & (img > 0)))} "
                      "occupied pixels cleared)")
        img[opening] = FREE
    share = float(np.count_nonzero(img)) / img.size
    if share < MIN_OCCUPIED_SHARE:
        raise InputError(
            f"the raster is practically empty ({share:.3%} occupied over {cols * resolution:.0f} m x "
            f"{rows * resolution:.0f} m): the extent is stretched by entities far from the building or by a "
            "wrong unit; check UNITS, remove stray entities, or give an explicit extent")
    progress.step(100)
    return OccupancyGrid(img, ox, oy, float(resolution))


# ------------------------------------------------------------------------------------------ floor sets
def _bounds_area(b):
    return max(b[2] - b[0], 0.0) * max(b[3] - b[1], 0.0)


def _overlap(a, b) -> float:
    """Intersection over the smaller box."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    if w <= 0 or h <= 0:
        return 0.0
    return w * h / max(min(_bounds_area(a), _bounds_area(b)), 1e-12)


def floors_share_frame(geometry_sets, percentiles=DEFAULT_PERCENTILES, min_overlap: float = 0.5) -> bool:
    """True when every floor's bounds overlap the first floor's (a shared drawing frame is plausible)."""
    boxes = [geometry_bounds(g, percentiles) for g in geometry_sets]
    return all(_overlap(boxes[0], b) >= min_overlap for b in boxes[1:])


def floor_offsets(geometry_sets, reference: int = 0, resolution: float = 0.2, percentiles=DEFAULT_PERCENTILES,
                  progress=None) -> List[Tuple[float, float]]:
    """Translation (dx, dy) in metres that brings each floor into the reference floor's frame.

    For floor sets drawn with different origins (same orientation and scale): each floor is rasterized
    at ``resolution`` on its own bounds, walls blurred, and the peak of the FFT cross-correlation with
    the reference floor (refined to sub-pixel by a parabola) gives the shift. Accuracy is about a
    tenth of ``resolution`` (walls are drawn anti-aliased).
    """
    import cv2

    progress = ensure(progress)
    sets = list(geometry_sets)
    boxes = [geometry_bounds(g, percentiles) for g in sets]
    w = max(b[2] - b[0] for b in boxes)
    h = max(b[3] - b[1] for b in boxes)
    cols = int(math.ceil(1.3 * w / resolution)) + 8
    rows = int(math.ceil(1.3 * h / resolution)) + 8
    cols, rows = cv2.getOptimalDFTSize(cols), cv2.getOptimalDFTSize(rows)
    if rows * cols > 64e6:
        raise InputError(f"the floors are too large ({w:.0f} m x {h:.0f} m) to align at {resolution} m/px")
    imgs, origins = [], []
    for k, (g, b) in enumerate(zip(sets, boxes)):
        progress.step(80.0 * k / len(sets))
        ox = math.floor(b[0] / resolution) * resolution - 4 * resolution
        oy = math.ceil(b[3] / resolution) * resolution + 4 * resolution
        img = np.zeros((rows, cols), np.uint8)
        hair = cv_thickness(max(0.3, 2 * resolution) / resolution)
        draw_geometries(img, g, ox, oy, resolution, hair, antialias=True)
        f = cv2.GaussianBlur(img.astype(np.float32) / 255.0, (0, 0), 1.5)
        imgs.append(f - f.mean())
        origins.append((ox, oy))
    ref = np.fft.rfft2(imgs[reference])
    out = []
    for k in range(len(sets)):
        if k == reference:
            out.append((0.0, 0.0))
            continue
        corr = np.fft.irfft2(ref * np.conj(np.fft.rfft2(imgs[k])), s=imgs[k].shape)
        r, c = np.unravel_index(int(np.argmax(corr)), corr.shape)

        def sub(a, b, cc):  # parabola through three samples
            den = a - 2 * b + cc
            return 0.0 if abs(den) < 1e-12 else 0.5 * (a - cc) / den

        dr = sub(corr[(r - 1) % rows, c], corr[r, c], corr[(r + 1) % rows, c])
        dc = sub(corr[r, (c - 1) % cols], corr[r, c], corr[r, (c + 1) % cols])
        sr = (r if r < rows // 2 else r - rows) + dr  # ref(r, c) ~ img_k(r - sr, c - sc)
        sc = (c if c < cols // 2 else c - cols) + dc
        (oxr, oyr), (oxk, oyk) = origins[reference], origins[k]
        # world_ref(r, c) = world_k(r - sr, c - sc) + d
        dx = (oxr - oxk) + sc * resolution
        dy = (oyr - oyk) - sr * resolution
        out.append((float(dx), float(dy)))
    progress.step(100)
    return out


def shift_geometries(geometries: Sequence[CadGeometry], dx: float, dy: float) -> List[CadGeometry]:
    from dataclasses import replace

    d = np.array((dx, dy))
    return [replace(g, coords=g.coords + d) for g in geometries]


def common_grid(geometry_sets, resolution: float = DEFAULT_RESOLUTION, padding: float = DEFAULT_PADDING,
                percentiles=DEFAULT_PERCENTILES, kernel: int = DEFAULT_KERNEL, max_pixels: float = DEFAULT_MAX_PIXELS,
                stroke: float = DEFAULT_STROKE, align: Optional[bool] = None, extent=None, progress=None):
    """The common grid of a floor set: ``(extent, offsets)``.

    ``extent`` is snapped to ``resolution`` in the first floor's frame; floor k is rasterized with
    ``floor_extent(extent, offsets[k])``. ``align``: None = register the floors (``floor_offsets``)
    only when their bounds do not overlap (floors drawn with different origins), True = always,
    False = never (a shared frame is assumed). Offsets are rounded to multiples of ``resolution`` so
    that each floor's geotransform still maps its pixels exactly onto its own CAD frame.
    """
    progress = ensure(progress)
    sets = [list(g) for g in geometry_sets]
    if not sets:
        raise InputError("a floor set needs at least one floor")
    if align is None:
        align = len(sets) > 1 and not floors_share_frame(sets, percentiles)
        if align:
            progress.warning("the floors do not overlap: they are drawn with different origins; registering "
                             "them by cross-correlation (translation only)")
    if align and len(sets) > 1:
        offs = floor_offsets(sets, 0, percentiles=percentiles, progress=progress.sub(0, 90))
        offs = [(round(dx / resolution) * resolution, round(dy / resolution) * resolution) for dx, dy in offs]
        for k, (dx, dy) in enumerate(offs):
            if k:
                progress.info(f"floor {k + 1}: offset ({dx:.3f}, {dy:.3f}) m to the first floor's frame")
    else:
        offs = [(0.0, 0.0)] * len(sets)
    if extent is None:
        moved = [shift_geometries(g, dx, dy) for g, (dx, dy) in zip(sets, offs)]
        extent = common_extent(moved, padding, percentiles)
        m = 2 * max(stroke, resolution * max(int(kernel), 1))
        extent = (extent[0] - m, extent[1] - m, extent[2] + m, extent[3] + m)
    ox, oy, rows, cols = grid_for_extent(extent, resolution, max_pixels)
    progress.step(100)
    return (ox, oy - rows * resolution, ox + cols * resolution, oy), offs


def floor_extent(extent, offset):
    """The common extent (first floor's frame) expressed in a floor's own frame."""
    dx, dy = offset
    return (extent[0] - dx, extent[1] - dy, extent[2] - dx, extent[3] - dy)


def floor_grids(geometry_sets, resolution: float = DEFAULT_RESOLUTION, padding: float = DEFAULT_PADDING,
                percentiles=DEFAULT_PERCENTILES, kernel: int = DEFAULT_KERNEL, max_pixels: float = DEFAULT_MAX_PIXELS,
                stroke: float = DEFAULT_STROKE, align: Optional[bool] = None, extent=None, progress=None):
    """Rasterize several floors on one common grid: same shape, and pixel (r, c) is the same place on
    every floor. Returns ``(grids, offsets)``; see ``common_grid`` for ``align`` and ``extent``."""
    progress = ensure(progress)
    sets = [list(g) for g in geometry_sets]
    ext, offs = common_grid(sets, resolution, padding, percentiles, kernel, max_pixels, stroke, align, extent,
                            progress.sub(0, 30))
    shape = None
    grids = []
    for k, (g, off) in enumerate(zip(sets, offs)):
        progress.step(30 + 70.0 * k / len(sets), f"floor {k + 1} of {len(sets)}")
        grid = rasterize(g, resolution, padding, percentiles, kernel, floor_extent(ext, off), max_pixels, stroke)
        if shape is None:
            shape = grid.shape
        elif grid.shape != shape:  # float noise in snapping a shifted extent: force the common shape
            fixed = np.zeros(shape, np.uint8)
            rr, cc = min(shape[0], grid.shape[0]), min(shape[1], grid.shape[1])
            fixed[:rr, :cc] = grid.data[:rr, :cc]
            grid = OccupancyGrid(fixed, grid.origin_x, grid.origin_y, grid.resolution)
        grids.append(grid)
    progress.step(100)
    return grids, offs


def boundary_mask(geometries: Sequence[CadGeometry], grid: "OccupancyGrid") -> Optional[np.ndarray]:
    """Boundary evidence (``CadDrawing.boundary``: projection / dash-dot lines) as a 1-pixel boolean mask on
    ``grid`` (None when there is none). Never drawn into the occupancy raster: the lines are no walls, only
    a boundary the envelope disk may not cross (``segmentation.segment(boundary=...)``)."""
    import cv2

    if not geometries:
        return None
    img = np.zeros(grid.shape, np.uint8)
    rings = [r if len(r) > 1 else np.vstack((r, r)) for g in geometries for r in _split_rings(g.coords) if len(r)]
    if not rings:
        return None
    px = np.split(_to_px(np.concatenate(rings), grid.origin_x, grid.origin_y, grid.resolution),
                  np.cumsum([len(r) for r in rings])[:-1])
    cv2.polylines(img, px, False, 1, thickness=1, lineType=cv2.LINE_8, shift=SHIFT)
    mask = img > 0
    return mask if mask.any() else None


def ring_px(ring, grid: OccupancyGrid) -> np.ndarray:
    """A ring's vertices as the (col, row) pixel-corner coordinates of ``grid`` with 3 fractional bits, as
    ``cv2.fillPoly(..., shift=3)`` takes them."""
    xs, ys = np.asarray(ring.coords).T
    c, r = grid.world_to_pixel(xs, ys)
    return np.round(np.column_stack((c, r)) * 8).astype(np.int32)


def repaint_polygon(labels: np.ndarray, grid: OccupancyGrid, polygon, new_id: int, old_id: Optional[int] = None,
                    mask: Optional[np.ndarray] = None) -> None:
    """Set to ``new_id`` the pixels of the label raster ``labels`` (on ``grid``) inside ``polygon``'s exterior
    (sub-pixel filled, as ``cv2.fillPoly`` with 3 fractional bits) that hold ``old_id``, or, given ``mask`` (a
    boolean raster like ``labels``), where ``mask`` is true; only the polygon's window is touched (a mask of the
    whole raster per polygon was most of the cost of repainting carved or split areas)."""
    import cv2

    rows, cols = labels.shape
    pts = ring_px(polygon.exterior, grid)
    c0, r0 = max(int(pts[:, 0].min()) >> 3, 0), max(int(pts[:, 1].min()) >> 3, 0)
    c1, r1 = min((int(pts[:, 0].max()) >> 3) + 2, cols), min((int(pts[:, 1].max()) >> 3) + 2, rows)
    if c1 <= c0 or r1 <= r0:
        return
    m = np.zeros((r1 - r0, c1 - c0), np.uint8)
    cv2.fillPoly(m, [pts - np.array([c0 << 3, r0 << 3], np.int32)], 1, shift=3)
    win = labels[r0:r1, c0:c1]
    sel = mask[r0:r1, c0:c1] if mask is not None else (win == old_id)
    win[sel & m.astype(bool)] = new_id
