"""Area Graph segmentation of an occupancy grid (pipeline stage 3).

After Hou, Yuan and Schwertfeger, "Area Graph: Generation of Topological Maps using the Voronoi
Diagram" (ICAR 2019), with the dynamic alpha of the CAD-to-osmAG paper. Everything is raster based
(numpy / scipy.ndimage / OpenCV / GDAL) and runs in a few seconds on multi-million pixel floors.

Steps (``AreaGraph.stats`` keeps the wall time of each):

``interior``
    Building envelope. A disk of radius ``envelope_gap / 2`` rolled through the free space from
    outside the image marks everything it can reach as *open to the outside*; facade openings
    narrower than ``envelope_gap`` (doors, glazing, drawing gaps) are therefore bridged. Space open
    to the outside is still inside where there is evidence (``building_interior``): the footprint
    of the plan (what a disk of ``FOOTPRINT_FACTOR`` x ``envelope_gap`` cannot reach, where it opens
    onto a real room through a doorway and is a space of its own: halls and porticoes open between
    wings, bites of the disk into rooms behind undrawn windows) and room-name points
    (``inside_points``: the space holding a name is inside at the smallest footprint scale that
    encloses it). Claimed space is closed at the chord between the facade wall ends. Only space
    without evidence that is open to the outside is outside; it is never an area. Unknown cells
    are never free. ``door_hints`` (doorways found in the drawing) are kept free.
``skeleton``
    Clearance (Euclidean distance to the nearest wall) and the skeleton of the free space as a
    graph (``skeleton.skeleton_graph``): the space is thinned to its one-pixel medial axis -- the
    generalised Voronoi diagram of the walls -- peeling pixels in order of clearance with
    topology-preserving (Guo-Hall) thinning; nodes are its junctions and dead ends (with their
    clearance), edges the pixel chains between them (length, min / max clearance). Dead-end
    branches shorter than ``prune`` metres are removed, round after round, merging the nodes left
    with two branches. Obstacle specks up to ``SPECK_M2`` (sensor noise, clutter) and free-standing
    furniture (``_furniture``: compact solid blobs 1-3.5 m long touching no wall; doors are gaps in
    walls) are ignored here so that they make no branches or narrowings (they stay holes in the
    areas). Enclosed pockets narrower than ``2 x POCKET_CLEARANCE_M`` everywhere (inside furniture
    outlines, wall cavities) are no space.
``regions``
    Topology graph: one region per skeleton edge, split where a clearance valley crosses it. The
    valleys are the borders of the clearance *basins*: every free pixel climbs the clearance by
    steepest ascent to a local maximum and the pixels reaching the same maximum form a basin, so
    basin borders cross the skeleton at its clearance minima -- the narrowings at doors. Every free
    pixel joins the closest skeleton edge piece of its basin (Euclidean; where the closest piece lies
    behind a wall the pixels are grown into from the neighbouring regions instead). A basin no kept
    skeleton edge runs through (its maximum lay only on pruned branches, or on none) has no region
    of its own: its pixels join the neighbouring regions.
``graph``
    Two regions are neighbours when they touch; the adjacency carries the *saddle*, the largest
    clearance along the shared border (half the width of the opening between them).
``merge``
    Merge tree over the region graph, strongest connections (largest saddle) first:

    1. what belongs together whatever the widths: a region whose clearance peak rises less than
       ``MIN_RISE_M`` above the saddle is no space of its own (a stretch of corridor between two
       junctions, a wall bump); where the opening is at least the alpha-disk radius
       ``R = sqrt(alpha)`` px, alpha = ceil((min(door, corridor) + delta)^2 / (4 r^2)), the disk
       sweeps from one region into the other, so they are one room (alpha-shape room detection);
    2. doors: an opening no wider than ``door_width + delta`` that is clearly narrower than the
       space behind it (saddle < ``NARROWING`` x the larger peak of the two pass-1 groups) keeps
       the split -- this also finds the rooms too narrow for the alpha disk. Anything else merges:
       nothing justifies a split;
    3. corridors: long groups (length >= ``PASS3_ELONGATION`` x their mean width) join the
       corridor-shaped groups they touch even through narrowings (fire doors, clutter).

    Areas whose outline is mostly open to the outside (exterior recesses the envelope disk could
    not enter) are dropped; a label split in pieces keeps its largest piece, the rest goes to the
    neighbour it touches most. Type: ``corridor`` when area >= ``CORRIDOR_ELONGATION`` x (2 x max
    clearance)^2, else ``room``.
``polygons``
    Exact pixel-edge outlines of the label raster (GDAL Polygonize), so neighbouring areas share
    their border vertices exactly.
``passages``
    One passage per connected piece of the border between two areas: the segment between the two
    ends of the shared border (where it meets walls), its length is the passage width. Door hints
    the segmentation missed (the areas on both sides are not joined) become passages too.
``components``
    Connected components of the area graph: every area's ``component`` (0 = the largest by
    area); the others are logged with their area ids, names and size, so no room is silently
    orphaned (``assign_components``, ``report_components``).
"""
from __future__ import annotations

import contextlib
import math
import os
import threading
import time
from typing import Dict, List, Optional, Tuple

import numpy as np

from . import kernels
from .errors import InputError
from .model import FREE, OCCUPIED, UNKNOWN, Area, AreaGraph, OccupancyGrid, Passage
from .progress import Progress, ensure
from .skeleton import SkeletonGraph, nearest_seed_regions, skeleton_graph  # noqa: F401  (re-exported)

DEFAULT_DOOR_WIDTH = 2.8
DEFAULT_CORRIDOR_WIDTH = 8.0
DEFAULT_DELTA = 0.1
DEFAULT_PRUNE = 0.25
DEFAULT_ENVELOPE_GAP = 4.0  # widest facade opening (m) bridged when looking for the building interior
NARROWING = 0.6  # an opening narrower than this fraction of the space behind it is a door
MIN_RISE_M = 0.25  # a region whose clearance peak rises less than this above the opening to a neighbour is a bump
SPECK_M2 = 0.1  # m2: obstacle blobs up to this size inside the space (noise, clutter) make no narrowings
CORRIDOR_MERGE = True
MIN_CORRIDOR_OPENING_M = 0.15  # corridors do not join through slits narrower than this (x 2)
PASS3_ELONGATION = 8.0  # length >= 8 x mean width: a corridor, whatever narrowings it has
CORRIDOR_ELONGATION = 4.0  # area / (2 * max clearance)^2 above which an area is a corridor
MIN_INTERIOR_COMPONENT_M2 = 1.0  # smaller free pockets inside the envelope are dropped
OUTSIDE_CONTACT = 0.35  # areas whose outline is open to the outside for this fraction are exterior recesses
FOOTPRINT_FACTOR = 3.0  # footprint of the plan: openings up to 3 x ENVELOPE_GAP are bridged for evidence
CLAIM_FACTOR = 1.5  # space claimed at footprint scale D is at most (1.5 D)^2 (larger: landscape, sheet gaps)
BITE_CONTACT = 0.3  # a piece whose outline runs along interior space for this fraction is a bite into a room
DEEP_SPACE = 0.3  # a piece with area >= this x chord^2 of its opening is a space (hall, porch), not a corner
MIN_CONTACT_M = 0.5  # space open to the outside must open onto the interior this wide (a doorway) to be claimed
POCKET_CLEARANCE_M = 0.3  # enclosed free pockets narrower than 0.6 m everywhere are no rooms
FREE_STANDING = True
CLUTTER_M2 = 4.0  # free-standing compact obstacles up to this area (minimum rectangle) ...
CLUTTER_EXTENT_M = 3.5  # ... this length ...
CLUTTER_SOLID = 0.6  # ... and solid: filled outline >= 0.6 x its minimum rectangle (not L / U wall pieces)
CLUTTER_THICK_M = 0.3  # ... at least this thick (not wall stubs) ...
CLUTTER_MIN_LENGTH_M = 1.0  # ... and at least this long (tables, desks, shelves; columns frame openings) make no doors
MIN_PASSAGE_M = 0.2  # shorter extra contacts between two areas that also touch elsewhere are no passage


# --------------------------------------------------------------------------- parameters
def compute_alpha(door_width: float, corridor_width: float, delta: float, resolution: float) -> int:
    """Dynamic alpha (squared pixel radius of the probe disk), equation (4) of the paper."""
    return int(math.ceil((min(door_width, corridor_width) + delta) ** 2 / (4.0 * resolution ** 2)))


def _check_inputs(grid: OccupancyGrid, door_width: float, corridor_width: float, delta: float,
                  prune: float) -> Tuple[np.ndarray, int]:
    data = np.asarray(grid.data)
    if data.ndim != 2:
        raise InputError(f"the occupancy grid has shape {data.shape}; it must be a single-band 2-D raster "
                         "(convert multi-band images to one grey band first)")
    if data.size == 0:
        raise InputError("the occupancy grid is empty (0 pixels)")
    res = grid.resolution
    if res is None or not np.isfinite(res) or not res > 0:
        raise InputError(f"the raster has no valid resolution ({res!r}); give RESOLUTION in metres per pixel")
    for name, val in (("DOOR_WIDTH", door_width), ("CORRIDOR_WIDTH", corridor_width)):
        if not (np.isfinite(val) and val > 0):
            raise InputError(f"{name} must be a positive width in metres, got {val!r}")
    if not (np.isfinite(delta) and delta >= 0):
        raise InputError(f"DELTA must be >= 0 metres, got {delta!r}")
    if not (np.isfinite(prune) and prune >= 0):
        raise InputError(f"PRUNE must be >= 0 metres, got {prune!r}")
    alpha = compute_alpha(door_width, corridor_width, delta, res)
    if alpha < 2:
        raise InputError(f"alpha = {alpha} px^2 is smaller than 2 at {res:g} m/px: the raster is too coarse for "
                         f"openings of {min(door_width, corridor_width) + delta:g} m; rasterize at a finer "
                         "resolution or check RESOLUTION")
    if 2.0 * math.sqrt(alpha) > max(data.shape):
        raise InputError(f"alpha = {alpha} px^2 (a {2 * math.sqrt(alpha) * res:.3g} m probe disk) is larger than the "
                         f"map ({data.shape[1]} x {data.shape[0]} px at {res:g} m/px): check RESOLUTION "
                         "(is it in metres per pixel?) or DOOR_WIDTH / CORRIDOR_WIDTH")
    if not np.any(data == FREE):
        raise InputError("the occupancy grid has no free cell (it is all occupied or unknown); "
                         "free space must be 0 in cad2osmag rasters, and light (white) in images, ROS maps "
                         "and other tools' GeoTIFFs; invert the raster if its free space is dark")
    return data, alpha


# --------------------------------------------------------------------------- helpers
def _threads_on() -> bool:
    """Whether independent raster passes of one floor run on two threads (``_Background``): not on a
    one-CPU machine, nor with ``CAD2OSMAG_THREADS=1`` in the environment, nor in a process-pool worker
    while the pool's conversions keep every CPU busy (``share_cpus``)."""
    if os.environ.get("CAD2OSMAG_THREADS", "").strip() == "1":
        return False
    cpus = _cpus()
    running = _POOL.get("running")
    return cpus > 1 and (running is None or running.value < cpus)


_POOL: dict = {}


def share_cpus(running) -> None:
    """Make this process a worker of a pool that shares the CPUs: ``running`` (a ``multiprocessing.Value``
    of type 'i', shared by the pool's workers) counts the pool's conversions running now (``busy_cpu``). A
    worker's segmentation then runs its second thread only while fewer conversions than CPUs run, i.e. once
    another worker has no floor left (the last floors of a building), never beside a busy worker on every
    CPU. The output is the same either way (``_Background``)."""
    _POOL["running"] = running


@contextlib.contextmanager
def busy_cpu():
    """Count the conversion run inside as one busy CPU of this worker's pool (``share_cpus``); nothing
    outside a pool."""
    running = _POOL.get("running")
    if running is None:
        yield
        return
    with running.get_lock():
        running.value += 1
    try:
        yield
    finally:
        with running.get_lock():
            running.value -= 1


def _cpus() -> int:
    """The CPUs this process may run on (its affinity where the system tells it, else the machine's)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


_TRIM: dict = {}


def _release_thread_memory() -> None:
    """Give the memory a finished helper thread freed back to the system (glibc keeps it in the thread's
    own malloc arena, where the main thread's arrays cannot reuse it: SIST-F5.dwg's segmentation peaked
    ~150 MB higher). ``malloc_trim`` where the C library has it (Linux), nothing elsewhere."""
    if "fn" not in _TRIM:
        fn = None
        try:
            import ctypes
            import ctypes.util

            libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
            fn = libc.malloc_trim
            fn.argtypes = [ctypes.c_size_t]
            fn.restype = ctypes.c_int
        except (OSError, AttributeError):
            fn = None
        _TRIM["fn"] = fn
    if _TRIM["fn"] is not None:
        _TRIM["fn"](0)


class _Background:
    """``fn()`` computed on a helper thread while the caller goes on (OpenCV, numpy's whole-array
    operations and the compiled kernels release the GIL, so the two cores work on one floor at once);
    ``result()`` waits for it and returns its value or raises its exception. ``fn`` must only read
    arrays no one writes meanwhile, and never touch ``progress``: its result is then the one a call
    in line would give (deterministic). Runs in line when threads are off (``_threads_on``)."""

    def __init__(self, fn):
        self._value = self._error = None
        self._thread = None
        if not _threads_on():
            self._run(fn)
            return
        self._thread = threading.Thread(target=self._run, args=(fn,), name="cad2osmag-raster", daemon=True)
        self._thread.start()

    def _run(self, fn):
        try:
            self._value = fn()
        except BaseException as e:  # re-raised in the caller's thread by result()
            self._error = e

    def result(self):
        if self._thread is not None:
            self._thread.join()
            self._thread = None
            _release_thread_memory()
        if self._error is not None:
            raise self._error
        return self._value


def _edt(mask: np.ndarray) -> np.ndarray:
    """Euclidean distance (px, float32) of every True pixel to the nearest False pixel: the correctly
    rounded float32 square root of the exact squared distance, on any number of OpenCV threads."""
    import cv2

    dist = cv2.distanceTransform(mask.view(np.uint8) if mask.dtype == bool else mask.astype(np.uint8),
                                 cv2.DIST_L2, cv2.DIST_MASK_PRECISE)
    if cv2.getNumThreads() <= 1:
        dist = _exact_root(dist)
    return dist


def _edt_upto(mask: np.ndarray, radii) -> np.ndarray:
    """``_edt(mask)`` for use as thresholds only (``dist > r`` for ``r`` in ``radii``), computed as two
    row strips on two threads (``_Background``), each grown by ``max(radii) + 2`` rows. The same
    comparisons as on ``_edt(mask)``: a pixel whose background pixel is within max(radii) + 1 has
    it inside its strip (OpenCV counts nothing beyond the image as background), a pixel farther out is
    as far or farther in its strip. Distances beyond max(radii) + 1 are not those of the whole raster
    (a strip does not see it all), so the result is for these comparisons only; as for the other windowed
    transforms, the strips run only when no radius lies within 1e-4 of a pixel distance (``_tie_free``);
    otherwise, with threads off or on a short raster, the whole."""
    radii = [float(r) for r in radii]
    m = int(math.ceil(max(radii))) + 2
    rows = mask.shape[0]
    if not (_threads_on() and rows >= 6 * m and mask.size >= 1 << 20 and all(_tie_free(r) for r in radii)):
        return _edt(mask)
    return _edt_strips(mask, m, checked=False)


SPLIT_MARGIN = 192  # rows by which each strip of ``_edt_split`` reaches into the other half


def _edt_split(mask: np.ndarray) -> np.ndarray:
    """``_edt(mask)``, the same values bit for bit, computed as two row strips on two threads
    (``_Background``) that reach ``SPLIT_MARGIN`` rows into each other's half. Both transforms give the
    correctly rounded root of the exact squared distance (``_edt``), so a pixel has its whole-raster value
    when its nearest background pixel lies inside its strip; that is certain where the strip's distance is
    at most the distance to the strip's far edge (OpenCV counts nothing beyond the image as background),
    and checked for every row of both halves: a half that fails (a hall wider than the margin on the
    split row) is computed again on the whole raster. Whole with threads off or on a short raster."""
    rows = mask.shape[0]
    m = SPLIT_MARGIN
    if not (_threads_on() and rows >= 6 * m and mask.size >= 1 << 20):  # (small images: OpenCV's IPP path)
        return _edt(mask)
    out = _edt_strips(mask, m, checked=True)
    return out if out is not None else _edt(mask)


def _edt_strips(mask: np.ndarray, m: int, checked: bool) -> Optional[np.ndarray]:
    """``_edt`` of the two row halves of ``mask``, each computed on a strip reaching ``m`` rows into the other
    half (the lower one on the second core, ``_Background``). ``checked``: every row must hold its
    whole-raster values (its largest distance within its strip's far edge), else None."""
    rows = mask.shape[0]
    mid = rows // 2
    low = _Background(lambda: _edt(mask[mid - m:]))
    out = np.empty(mask.shape, np.float32)
    high = _edt(mask[:mid + m])
    # row r of the upper half is exact when its largest distance is at most mid + m - r (its far edge)
    ok = not checked or bool(np.all(high[:mid].max(axis=1) <= np.arange(mid + m, m, -1, dtype=np.float32)))
    out[:mid] = high[:mid]
    del high
    below = low.result()
    # row mid + i of the lower half: its far (upper) edge is m + i rows away
    ok = ok and (not checked or bool(np.all(below[m:].max(axis=1)
                                            <= np.arange(m, m + rows - mid, dtype=np.float32) + 1)))
    out[mid:] = below[m:]
    del below
    return out if ok else None


def _exact_root(dist: np.ndarray) -> np.ndarray:
    """``dist`` (float32 Euclidean pixel distances, within an ulp) as the correctly rounded square roots
    of their integer squares. Single-threaded OpenCV (one core, ``cv2.setNumThreads(1)``) runs another
    transform (IPP's) whose roots are an ulp off on about one pixel in ten (7.0000005 for 7): the
    clearance ties and the area labels then differed from a multi-threaded run's (SIST-F3: 19 pixels,
    3514 vs 3508 regions). Exact up to 1448 px (an ulp off is then less than 0.5 in the square), within
    an ulp beyond."""
    sq = np.square(dist, dtype=np.float64)
    np.rint(sq, out=sq)
    np.sqrt(sq, out=sq)
    return sq.astype(np.float32)


def _outside_centres(dist_padded: np.ndarray, rc: float) -> np.ndarray:
    """Centres (padded frame) of the disks of radius ``rc`` px that can roll in from outside the image."""
    return _corner_component((dist_padded > rc).view(np.uint8))


def _corner_component(mask: np.ndarray) -> np.ndarray:
    """The 8-connected component of the set pixels of ``mask`` (uint8 0/1, overwritten) holding pixel (0, 0),
    or nothing: a flood fill from the corner (it visits only that component, a labelling the whole raster)."""
    import cv2

    if not mask[0, 0]:
        return np.zeros(mask.shape, bool)
    cv2.floodFill(mask, None, (0, 0), 2, loDiff=0, upDiff=0, flags=8 | cv2.FLOODFILL_FIXED_RANGE)
    return mask == 2


def _reach(centres: np.ndarray, rc: float, pad: int) -> np.ndarray:
    """Pixels within ``rc`` of an outside disk centre (unpadded frame): swept by the rolling disk.

    Every pixel beyond the bounding box of the non-centres is a centre, so the transform runs on
    that box grown by a pixel only (a nearest centre beyond it has one as near on the box's rim:
    clamp it onto the rim), with the same exact distances; the rest is reached."""
    non = ~centres
    rows, cols = non.shape
    rr = np.flatnonzero(non.any(axis=1))
    if len(rr) == 0:
        return np.ones((rows - 2 * pad, cols - 2 * pad), bool)
    cc = np.flatnonzero(non.any(axis=0))
    ra, rb = max(int(rr[0]) - 1, 0), min(int(rr[-1]) + 2, rows)
    ca, cb = max(int(cc[0]) - 1, 0), min(int(cc[-1]) + 2, cols)
    reach = np.ones((rows, cols), bool)
    reach[ra:rb, ca:cb] = ~(_edt(np.ascontiguousarray(non[ra:rb, ca:cb])) > rc)
    return reach[pad:-pad, pad:-pad]


def _coarse_reach(passable: np.ndarray, rc: float, target_px: float = 32.0) -> np.ndarray:
    """``_reach`` of a large disk (radius ``rc`` px) computed on a raster coarsened so that the
    radius is about ``target_px`` cells (a cell is passable only when all its pixels are), then
    brought back to full resolution and grown by a cell: exact to a cell, which the chord closure
    absorbs."""
    import cv2

    f = max(1, int(rc // target_px))
    rows, cols = passable.shape
    if f > 1:
        rr, cc = -(-rows // f), -(-cols // f)
        big = np.ones((rr * f, cc * f), bool)
        big[:rows, :cols] = passable
        coarse = big.reshape(rr, f, cc, f).all(axis=(1, 3))
    else:
        coarse = passable
    r = rc / f
    pad = int(math.ceil(r)) + 2
    reach = _reach(_outside_centres(_edt(np.pad(coarse, pad, mode="constant", constant_values=True)), r), r, pad)
    if f > 1:
        reach = cv2.resize(reach.view(np.uint8), (cc * f, rr * f), interpolation=cv2.INTER_NEAREST)[:rows, :cols]
        # coarse walls are up to a cell thicker: grow the reach back by a cell (it only decides which
        # pixels already open to the outside are candidates, so it cannot cross into enclosed rooms)
        reach = cv2.dilate(np.ascontiguousarray(reach), np.ones((2 * f + 1, 2 * f + 1), np.uint8)).view(bool)
    return reach


def _opens_onto(lab: np.ndarray, n: int, lab0: np.ndarray, n0: int, big0: np.ndarray, min_contact: int,
                pairs=None) -> np.ndarray:
    """Which candidate pieces (``lab`` 1..n-1) open onto the enclosed interior: pieces and interior
    pockets (``lab0`` 1..n0-1) touching along at least ``min_contact`` pixel edges are linked, and a
    piece is kept when its links reach an interior component that is a real space (``big0``), not a
    corner the outside disk left (the pieces of a portico between pillars reach the rooms through
    the strip along its back wall and through each other)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    # the pieces are 4-connected components of the candidates, so they never touch each other:
    # only piece-pocket contacts link them
    ca, cb = [], []
    for src, nb, _ in (_boundary_pairs(lab) if pairs is None else pairs):
        b = lab0.ravel()[nb]
        m = b > 0
        ca.append(lab.ravel()[src[m]])
        cb.append(b[m])
    ca = np.concatenate(ca).astype(np.int64)
    cb = np.concatenate(cb).astype(np.int64)
    if len(ca) == 0:
        return np.zeros(n, bool)
    pair, cnt = np.unique(ca * n0 + cb, return_counts=True)
    pair = pair[cnt >= min_contact]
    ea, eb = pair // n0, pair % n0
    g = coo_matrix((np.ones(len(pair)), (ea, n + eb)), shape=(n + n0, n + n0))
    _, comp = connected_components(g, directed=False)
    good = np.zeros(comp.max() + 1, bool)
    good[comp[n + np.flatnonzero(big0)]] = True
    keep = good[comp[:n]]
    keep[0] = False
    return keep


def _boundary_pairs(lab: np.ndarray):
    """The 4-neighbour pairs leaving the pieces of ``lab`` (> 0): yields (flat index of the piece
    pixel, flat index of its neighbour outside the piece, direction) for the four directions. Only
    the pieces' boundary pixels are visited (fast on large rasters with small pieces)."""
    import cv2

    rows, cols = lab.shape
    m = (lab > 0).view(np.uint8)
    inner = cv2.erode(m, np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]], np.uint8), borderType=cv2.BORDER_CONSTANT,
                      borderValue=0)
    bd = np.flatnonzero((m & (1 - inner)).ravel())
    r, c = np.divmod(bd, cols)
    flat = lab.ravel()
    for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
        ok = (r + dr >= 0) & (r + dr < rows) & (c + dc >= 0) & (c + dc < cols)
        src = bd[ok]
        nb = src + dr * cols + dc
        keep = flat[nb] != flat[src]
        yield src[keep], nb[keep], (dr, dc)


def _space_shaped(lab: np.ndarray, n: int, interior0: np.ndarray, out_free: np.ndarray, pairs=None,
                  area: Optional[np.ndarray] = None) -> np.ndarray:
    """Which candidate pieces are spaces rather than corners of the outside: a piece is kept when it
    is a bite of the outside disk into a room (at least ``BITE_CONTACT`` of its outline runs along
    ``interior0``, the enclosed rooms) or when it is deep behind its opening (area >= ``DEEP_SPACE`` x chord^2,
    the chord measured across its cut to the outside): halls and porches between wings are, the
    triangle the footprint disk leaves in a concave corner of the outside (a courtyard corner
    in front of a door) is not."""
    total = np.zeros(n, np.int64)
    contact = np.zeros(n, np.int64)
    cols = lab.shape[1]
    big = max(lab.shape) + 1
    cmin = np.full((n, 2), big, np.int64)
    cmax = np.full((n, 2), -1, np.int64)
    flat = lab.ravel()
    i0 = interior0.ravel()
    of = out_free.ravel()
    for src, nb, _ in (_boundary_pairs(lab) if pairs is None else pairs):
        ids = flat[src]
        total += np.bincount(ids, minlength=n)
        contact += np.bincount(ids[i0[nb]], minlength=n)
        cut = of[nb]
        if cut.any():
            rc = np.stack(np.divmod(src[cut], cols), 1)
            np.minimum.at(cmin, ids[cut], rc)
            np.maximum.at(cmax, ids[cut], rc)
    area = (np.bincount(flat, minlength=n) if area is None else area).astype(np.float64)  # (``area``: pixels per piece)
    span = np.where(cmax[:, :1] >= 0, cmax - cmin + 1, 0).astype(np.float64)
    chord2 = (span ** 2).sum(axis=1)
    ok = (contact >= BITE_CONTACT * np.maximum(total, 1)) | (area >= DEEP_SPACE * chord2)
    ok[0] = False
    return ok


def _chord_pockets(claimed: np.ndarray, free_out: np.ndarray, max_chord: float = 0.0) -> np.ndarray:
    """Close claimed space at the chord of its openings, not at the arc of the rolling disk.

    The disk that stopped at an opening leaves an arc-shaped cut between ``claimed`` and the
    remaining outside free space ``free_out``; the convex hull of each cut piece is the lens
    between the arc and the chord joining the two facade wall ends. Returns the free pixels of
    those lenses (to be claimed too). ``max_chord`` > 0: only cut pieces at most that long (px)."""
    import cv2

    full = np.zeros(claimed.shape, bool)
    if not claimed.any():
        return full
    # everything happens within a pixel of the claimed space: work on its box grown by two pixels
    r0, r1, c0, c1 = _bbox(claimed)
    box = (slice(max(r0 - 2, 0), min(r1 + 3, claimed.shape[0])), slice(max(c0 - 2, 0), min(c1 + 3, claimed.shape[1])))
    claimed, free_out = np.ascontiguousarray(claimed[box]), free_out[box]
    cut = free_out & (cv2.dilate(claimed.view(np.uint8), np.ones((3, 3), np.uint8)).view(bool))
    n, lab, st, _ = cv2.connectedComponentsWithStats(cut.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    out = np.zeros(claimed.shape, np.uint8)
    for k in range(1, n):
        if st[k, cv2.CC_STAT_AREA] < 3:
            continue
        x0, y0, w, h = (int(v) for v in st[k, :4])
        if max_chord > 0 and math.hypot(w, h) > max_chord:
            continue
        rr, cc = np.nonzero(lab[y0:y0 + h, x0:x0 + w] == k)
        pts = np.stack([cc + x0, rr + y0], axis=1).astype(np.int32)
        cv2.fillConvexPoly(out, cv2.convexHull(pts), 1)
    full[box] = out.view(bool) & free_out
    return full


MOUTH_RAYS = 720  # rays cast from a room name still outside to find the facades around it
MOUTH_JUMP_M = 1.0  # a ray seeing this much (and 20 %) further than its neighbour passes a wall end


def _mouth_rays(outside: np.ndarray, c: int, r: int, reach_px: float, n: int = MOUTH_RAYS):
    """Cast ``n`` rays from pixel (c, r) through ``outside`` (free space still open to the outside).
    Returns (d, ux, uy): the distance (px) at which each ray first meets anything else (a wall, the
    enclosed interior), inf when it runs ``reach_px`` or leaves the image first, and the directions."""
    rows, cols = outside.shape
    ang = np.arange(n) * (2.0 * math.pi / n)
    ux, uy = np.cos(ang), np.sin(ang)
    t = (np.arange(1, int(2 * reach_px) + 1, dtype=np.float32) * 0.5)
    d = np.full(n, np.inf)
    for s in range(0, n, 90):  # in chunks: 90 rays x 2 * reach samples
        x = np.floor(c + 0.5 + ux[s:s + 90, None] * t[None, :]).astype(np.int32)
        y = np.floor(r + 0.5 + uy[s:s + 90, None] * t[None, :]).astype(np.int32)
        inside = (x >= 0) & (x < cols) & (y >= 0) & (y < rows)
        ok = np.zeros(x.shape, bool)
        ok[inside] = outside[y[inside], x[inside]]
        blocked = inside & ~ok
        stop = np.where(blocked.any(1), blocked.argmax(1), len(t))
        gone = np.where((~inside).any(1), (~inside).argmax(1), len(t))
        hit = stop < gone
        d[s:s + 90][hit] = t[stop[hit]]
    return d, ux, uy


def _mouth_chords(d: np.ndarray, ux: np.ndarray, uy: np.ndarray, jump_px: float, max_chord_px: float,
                  reach_px: float):
    """The mouths of the space around a ray origin (``_mouth_rays``): from every wall end the rays see past
    (a ray reaches 20 % and ``jump_px`` further than its neighbour, or nothing; not at the ray's reach),
    the shortest chord across the window to a point the rays hit on the other side, less than 180
    degrees on, at most ``max_chord_px`` long, across the rays (at least 30 degrees off the ray to the
    wall end: no chord along a ray to what lies behind the end) and with every ray between passing
    beyond it (the chord never cuts the space). A gap between two facades closes corner to corner, or
    from a building corner square across to the facade that runs on. Returns (ray a, ray b) pairs."""
    n = len(d)
    fin = np.isfinite(d)
    dd = np.where(fin, d, 1e12)
    near = fin & (d < 0.95 * reach_px)
    up = near & (np.roll(dd, -1) > 1.2 * dd + jump_px)
    down = near & (np.roll(dd, 1) > 1.2 * dd + jump_px)
    px, py = dd * ux, dd * uy
    k = np.arange(2, n // 2)
    chords = set()
    for a0, step in [(a, 1) for a in np.flatnonzero(up)] + [(b, -1) for b in np.flatnonzero(down)]:
        cand = (a0 + step * k) % n
        ax, ay = px[a0], py[a0]
        ex, ey = px[cand] - ax, py[cand] - ay
        length = np.hypot(ex, ey)
        ok = fin[cand] & (length <= max_chord_px) & (length > 0)
        # across the rays: the chord makes at least 30 degrees with the ray to the wall end
        with np.errstate(divide="ignore", invalid="ignore"):
            ok &= np.abs(ux[a0] * ey - uy[a0] * ex) >= 0.5 * length
        if not ok.any():
            continue
        # rays strictly between: distance along ray i to the chord line, (A x E) / (u_i x E)
        cidx = np.flatnonzero(ok)
        kk = k[cidx]
        ii = (a0 + step * np.arange(1, kk.max())[None, :]) % n  # rays 1 .. k-1 on
        between = np.arange(1, kk.max())[None, :] < kk[:, None]
        exs, eys = ex[cidx, None], ey[cidx, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            tt = (ax * eys - ay * exs) / (ux[ii] * eys - uy[ii] * exs)
        valid = np.all(~between | (dd[ii] >= tt - 2.0), axis=1)
        if not valid.any():
            continue
        best = cidx[valid][np.argmin(length[cidx][valid])]
        b0 = int(cand[best])
        chords.add((int(a0), b0) if step == 1 else (b0, int(a0)))
    return sorted(chords)


def _claim_between_facades(outside: np.ndarray, c: int, r: int, resolution: float, reach_m: float,
                           max_chord_m: float, max_area_m2: float) -> Optional[np.ndarray]:
    """The space holding a room name that stays open to the outside at every scale (a passage,
    arcade or covered walkway between two buildings, a courtyard strip between wings): closed at the
    chords joining the facing wall ends nearest to the name (``_mouth_chords``), not by a disk. Returns
    the pixels of ``outside`` in it (a bool mask of ``outside``'s shape), or None when the chords do not
    close it within ``reach_m`` or it stays larger than ``max_area_m2`` (open land, a forecourt, a name
    in a field or before one facade)."""
    import cv2

    reach = reach_m / resolution
    d, ux, uy = _mouth_rays(outside, c, r, reach)
    if not np.isfinite(d).any():
        return None
    chords = _mouth_chords(d, ux, uy, MOUTH_JUMP_M / resolution, max_chord_m / resolution, reach)
    if not chords:
        return None
    # between two facades, open at both ends: two mouths on opposite sides of the name (directions to
    # their midpoints at least 120 degrees apart); the corner of an L, a bay before one facade or a kiosk
    # in a field has one mouth or none
    mid = np.array([[d[a] * ux[a] + d[b] * ux[b], d[a] * uy[a] + d[b] * uy[b]] for a, b in chords])
    mid /= np.maximum(np.hypot(mid[:, 0], mid[:, 1]), 1e-9)[:, None]
    if not (mid @ mid.T <= math.cos(math.radians(120.0)) + 1e-9).any():
        return None
    rows, cols = outside.shape
    m = int(math.ceil(reach)) + 4
    x0, y0, x1, y1 = max(0, c - m), max(0, r - m), min(cols, c + m + 1), min(rows, r + m + 1)
    win = outside[y0:y1, x0:x1].copy().view(np.uint8)
    for a, b in chords:
        # from wall end to wall end, a few pixels into the walls on both sides (no leak past the ends)
        ex, ey = d[b] * ux[b] - d[a] * ux[a], d[b] * uy[b] - d[a] * uy[a]
        ln = math.hypot(ex, ey) or 1.0
        ex, ey = 3.0 * ex / ln, 3.0 * ey / ln
        pa = (int(round(c + 0.5 + d[a] * ux[a] - ex - x0)), int(round(r + 0.5 + d[a] * uy[a] - ey - y0)))
        pb = (int(round(c + 0.5 + d[b] * ux[b] + ex - x0)), int(round(r + 0.5 + d[b] * uy[b] + ey - y0)))
        cv2.line(win, pa, pb, 0, thickness=3)
    if not win[r - y0, c - x0]:
        return None
    _, lab = cv2.connectedComponents(win, connectivity=4, ltype=cv2.CV_32S)
    piece = lab == lab[r - y0, c - x0]
    if piece[0, :].any() or piece[-1, :].any() or piece[:, 0].any() or piece[:, -1].any():
        return None  # not closed within reach (or open to the image edge)
    if piece.sum() * resolution ** 2 > max_area_m2:
        return None
    out = np.zeros(outside.shape, bool)
    out[y0:y1, x0:x1] = piece
    return out


MOUTH_REACH = 3.0  # x footprint gap: rays from a name look this far for the facades around it
MOUTH_CHORD = 2.0  # x footprint gap: widest mouth closed (the largest disk scale passes wider ones)
MOUTH_AREA = 2.0  # (x footprint gap)^2: largest space closed at its mouths (the largest scale's limit)


def _claim_names_between_facades(outside: np.ndarray, open_pts, resolution: float, fgap: float, check=None):
    """``_claim_between_facades`` for every room name no disk scale enclosed (pixel (col, row) points):
    returns (the names still outside, the pixels claimed)."""
    got = np.zeros(outside.shape, bool)
    rest = []
    for c, r in open_pts:
        if check is not None:
            check()
        if got[r, c]:
            continue
        piece = _claim_between_facades(outside & ~got, c, r, resolution, MOUTH_REACH * fgap, MOUTH_CHORD * fgap,
                                       (MOUTH_AREA * fgap) ** 2)
        if piece is None:
            rest.append((c, r))
        else:
            got |= piece
    return rest, got


BAY_STEP_M = 0.25  # the mouth of a named bay is searched in steps of this half-width
BAY_CELL_PX = 10.0  # the search runs on cells so that the smallest disk is about this many cells wide


def _ring4(mask: np.ndarray) -> np.ndarray:
    """The pixels 4-adjacent to ``mask`` outside it."""
    import cv2

    return cv2.dilate(mask.view(np.uint8), cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3))).view(bool) & ~mask


MOUTH_BULGE = 0.25  # a bulge beyond a mouth's chord is cut off when it is at most this share of the space


def _straight_mouths(region: np.ndarray, rest: np.ndarray, pts) -> np.ndarray:
    """Close ``region`` (a named space cut out of open space, ``_claim_named_bays``) at the straight chord of each
    cut: every connected run of ``rest`` pixels along the region (a cut from one wall, column or facade end to
    the next) is replaced by the segment between its two ends, and what lies beyond it -- no name in it, at
    most ``MOUTH_BULGE`` of the region -- is left out (the cut runs midway between the named space and the rest
    of the outside, and bulges beyond the columns of a mouth)."""
    import cv2

    cut = _ring4(rest) & region
    n, lab, st, _ = cv2.connectedComponentsWithStats(cut.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    if n < 2:
        return region
    bar = np.zeros(region.shape, np.uint8)
    for k in range(1, n):
        if st[k, cv2.CC_STAT_AREA] < 3:
            continue
        x0, y0, w, h = (int(v) for v in st[k, :4])
        rr, cc = np.nonzero(lab[y0:y0 + h, x0:x0 + w] == k)
        xy = np.stack([cc + x0, rr + y0], axis=1)
        a = xy[np.argmax(((xy - xy[0]) ** 2).sum(axis=1))]  # the two ends: the farthest pair, in two sweeps
        b = xy[np.argmax(((xy - a) ** 2).sum(axis=1))]
        cv2.line(bar, (int(a[0]), int(a[1])), (int(b[0]), int(b[1])), 1, thickness=2)
    inner = region & ~bar.view(bool)
    m, parts, pst, _ = cv2.connectedComponentsWithStats(inner.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    if m < 3:
        return region
    named = {int(parts[r, c]) for c, r in pts if 0 <= r < region.shape[0] and 0 <= c < region.shape[1]}
    total = int(region.sum())
    drop = np.zeros(m, bool)
    for k in range(1, m):
        drop[k] = k not in named and pst[k, cv2.CC_STAT_AREA] <= MOUTH_BULGE * total
    if not drop.any() or drop[1:].all():
        return region
    out = region & ~drop[parts]
    # the chord's own pixels stay with the space they close
    return out & (~bar.view(bool) | (cv2.dilate((out & ~bar.view(bool)).view(np.uint8), np.ones((3, 3), np.uint8)) > 0))


def _claim_named_bays(piece: np.ndarray, outside: np.ndarray, pts, resolution: float, t_lo: float, t_hi: float,
                      check=None) -> np.ndarray:
    """The named part of a space open to the outside that a footprint disk cannot enter but that is too
    large to be claimed whole (an atrium gallery between two wings, a court, a bay that opens through a
    colonnade onto a terrace or the land around): cut at its mouth.

    ``piece``: the space (bool mask); ``outside``: the free space open to the outside (the piece included);
    ``pts``: (col, row) room-name points in the piece; ``t_lo`` / ``t_hi``: the smallest / largest mouth
    half-width (px) looked for. For a growing disk radius t (``BAY_STEP_M``), the union of the disks of
    radius t that fit in the piece falls apart at the openings narrower than 2 t; the first t at which the
    part holding a name no longer touches the rest of the outside is its mouth. The named space is then the
    piece's pixels geodesically nearer to that part than to the other parts and to the rest of the outside
    (the cut runs through the mouth), and it is claimed when its outline is open for at most
    ``OUTSIDE_CONTACT`` (a space the building closes but for its mouth; a forecourt before one facade or a
    field cut at the disk's size is open around most of its outline). Returns the claimed pixels."""
    import cv2

    from .semantics import _geodesic_regions

    got_all = np.zeros(piece.shape, bool)
    if not piece.any() or not len(pts):
        return got_all
    r0, r1, c0, c1 = _bbox(piece)
    f = max(1, int(t_lo // BAY_CELL_PX))  # the search on cells of f x f pixels
    m = 2 * f
    ya, yb, xa, xb = max(r0 - m, 0), min(r1 + 1 + m, piece.shape[0]), max(c0 - m, 0), min(c1 + 1 + m, piece.shape[1])
    pf = np.ascontiguousarray(piece[ya:yb, xa:xb])
    of = outside[ya:yb, xa:xb]
    rim = _ring4(of & ~pf) & pf  # piece pixels touching the rest of the outside through free space
    h, w = -(-(yb - ya) // f), -(-(xb - xa) // f)

    def cells(a: np.ndarray, majority: bool) -> np.ndarray:
        big = np.zeros((h * f, w * f), bool)
        big[:yb - ya, :xb - xa] = a
        v = big.reshape(h, f, w, f)
        return v.mean(axis=(1, 3)) >= 0.5 if majority else v.any(axis=(1, 3))

    def pixels(a: np.ndarray) -> np.ndarray:
        return cv2.resize(a.view(np.uint8), (w * f, h * f), interpolation=cv2.INTER_NEAREST)[:yb - ya, :xb - xa].view(bool)

    rn = cells(rim, False)
    sp = cells(pf, True) | rn
    todo = sorted({(min((c - xa) // f, w - 1), min((r - ya) // f, h - 1)) for c, r in pts})
    step = BAY_STEP_M / resolution / f
    t = t_lo / f
    clear = _edt(sp)
    got = np.zeros(pf.shape, bool)
    while todo and t <= t_hi / f:
        if check is not None:
            check()
        core = clear > t
        if not core.any():
            break
        opened = ~(_edt(~core) > t) & sp
        n, comp = cv2.connectedComponents(opened.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
        open_comp = np.zeros(n, bool)
        open_comp[np.unique(comp[rn & opened])] = True
        open_comp[0] = True
        mine: Dict[int, list] = {}
        rr = int(math.ceil(t)) + 1
        for c, r in todo:  # the part a name lies in, or the one most of the disks around it belong to
            win = comp[max(r - rr, 0):r + rr + 1, max(c - rr, 0):c + rr + 1]
            k = int(comp[r, c]) if comp[r, c] else (int(np.bincount(win[win > 0]).argmax()) if (win > 0).any() else 0)
            if k and not open_comp[k]:
                mine.setdefault(k, []).append((c, r))
        if mine:
            markers = np.zeros(sp.shape, np.int32)
            markers[comp > 0] = 2
            markers[np.isin(comp, list(mine))] = 1
            markers[rn & ~opened] = 2
            reg = (_geodesic_regions(markers, sp) == 1) & sp
            # back on pixels: the slivers the cells left out go to the nearer side
            mk = np.zeros(pf.shape, np.int32)
            mk[pixels(sp & ~reg) & pf] = 2
            mk[pixels(reg) & pf] = 1
            mk[got] = 0
            full = (_geodesic_regions(mk, pf & ~got, max_iter=4 * f + 4) == 1) & pf & ~got
            full = _straight_mouths(full, of & ~full, [(c - xa, r - ya) for c, r in pts])
            ring = _ring4(full)
            if full.any() and (ring & of).sum() <= OUTSIDE_CONTACT * ring.sum():
                got |= full
                sp &= ~reg
                clear = _edt(sp)
            done = {p for v in mine.values() for p in v}
            todo = [p for p in todo if p not in done]
        t += step
    got_all[ya:yb, xa:xb] = got
    return got_all


def building_interior(free: np.ndarray, resolution: float, envelope_gap: float = DEFAULT_ENVELOPE_GAP,
                      unknown: Optional[np.ndarray] = None, inside_points=None,
                      footprint_gap: Optional[float] = None, info: Optional[dict] = None,
                      footprint: bool = False, progress=None, boundary: Optional[np.ndarray] = None
                      ) -> Tuple[np.ndarray, np.ndarray]:
    """Free space inside the building envelope.

    Returns ``(interior_free, envelope)``: ``envelope`` is everything that is not outside, walls
    included; ``interior_free`` its free pixels without pockets smaller than
    ``MIN_INTERIOR_COMPONENT_M2``.

    *Open to the outside* is what a disk of diameter ``envelope_gap`` reaches rolling in from
    outside the image through free (or ``unknown``: unexplored, no evidence of a building) space.
    Space open to the outside is still inside when there is evidence of it:

    * facade openings narrower than ``envelope_gap`` close at the chord between their wall ends,
      not at the arc of the disk (no bites into the rooms behind them);
    * with ``footprint``, the footprint of the plan: space that a disk of diameter ``footprint_gap`` (default
      ``FOOTPRINT_FACTOR`` x ``envelope_gap``) cannot reach -- halls, porches and loggias open
      between two wings, facades whose windows are not drawn -- and that opens onto the enclosed
      interior (a doorway, at least ``MIN_CONTACT_M`` of contact), so that landscape pockets
      bounded only by walls stay outside;
    * ``inside_points`` ((x, y) pixel coordinates, col/row, of room-name texts): the space holding
      one is inside whatever its facade, at the smallest footprint scale (x1, x2) that encloses it;
      a name no scale encloses (the disk enters, or the piece joins the land around) that stands
      between two facades open at both ends -- a passage or covered walkway between two buildings --
      is inside up to the chords of its two mouths (``_claim_between_facades``: from each wall end the
      rays from the name see past, the shortest chord across to the other side; at most
      ``MOUTH_CHORD`` x the footprint gap long, the space at most (``MOUTH_AREA`` x the gap)^2).

    Claimed space enclosed at the footprint scale D is at most (``CLAIM_FACTOR`` x D)^2, at the
    larger scale at most D^2: larger pockets are forecourts, the street or the gap between two
    drawings of a sheet.

    Claimed space is closed at the chord between the two facade wall ends of its opening, never
    at the arc of the rolling disk (no bites). ``info`` (a dict) receives figures for the log.
    ``progress`` is checked for cancel between the raster passes.
    """
    import cv2

    check = progress.check if progress is not None else (lambda: None)
    info = {} if info is None else info
    passable = free if unknown is None else (free | unknown)
    if boundary is not None:  # boundary evidence (``supported_boundary``): the disk does not cross it
        passable = passable & ~boundary
    rc0 = max(1.0, envelope_gap / 2.0 / resolution)
    fgap = FOOTPRINT_FACTOR * envelope_gap if footprint_gap is None else float(footprint_gap)
    scales = [rc0]
    if fgap > envelope_gap:
        rcf = fgap / 2.0 / resolution
        # a disk wider than the map proves nothing: larger scales are not used
        scales += [r for r in (rcf, 2.0 * rcf) if 2.0 * r <= max(free.shape)]
    # the envelope and the footprint scale exactly (their arcs decide bites), larger scales coarsely
    pad = int(math.ceil(scales[1] if len(scales) > 1 else rc0)) + 2
    shared = info.pop("_free_dist", None)  # supported_boundary's transform of the same free space, if any
    reuse = (shared is not None and shared.get("free") is free and unknown is None and shared["pad"] == pad
             and shared["rc0"] == rc0 and shared.get("radii") == scales[:2])
    # the footprint disk's reach (the loop below needs it first with ``footprint``) depends only on the
    # transform: computed on the second core while this one goes on with the envelope (``_Background``)
    def start_far(d):
        return (_Background(lambda: _reach(_outside_centres(d, scales[1]), scales[1], pad))
                if footprint and len(scales) > 1 else None)

    if reuse and boundary is None:
        dist = shared["dist"]
        far = start_far(dist)
        reach0 = shared["reach"] if "reach" in shared else _reach(shared["centres"], rc0, pad)
    elif reuse and boundary.any() and _tie_free(rc0) and _tie_free(scales[1] if len(scales) > 1 else rc0):
        # the kept lines are walls for the disk: the same transform, updated near them
        dist, reach0 = _with_lines(shared, boundary, scales[1] if len(scales) > 1 else rc0)
        far = start_far(dist)
    else:
        # compared with the envelope and the footprint radius only (_outside_centres)
        dist = _edt_upto(np.pad(passable, pad, mode="constant", constant_values=True), scales[:2])
        check()
        far = start_far(dist)
        reach0 = _reach(_outside_centres(dist, rc0), rc0, pad)
    del shared
    check()
    interior0 = free & ~reach0
    # what the disk leaves in the corners of the outside (up to rc0^2: corners of 50 degrees and more)
    # is no interior a doorway could open onto
    n0, lab0, st0, _ = cv2.connectedComponentsWithStats(interior0.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    big0 = st0[:, cv2.CC_STAT_AREA] >= rc0 * rc0
    big0[0] = False
    # facade openings narrower than the envelope gap close at their chord, not at the disk's arc
    claimed = _chord_pockets(big0[lab0], free & reach0, max_chord=2.2 * rc0)
    if claimed.any():
        interior0 = interior0 | claimed
        n0, lab0, st0, _ = cv2.connectedComponentsWithStats(interior0.view(np.uint8), connectivity=4,
                                                            ltype=cv2.CV_32S)
        big0 = st0[:, cv2.CC_STAT_AREA] >= rc0 * rc0
        big0[0] = False
    pts = np.zeros((0, 2), np.int64)
    if inside_points is not None and len(inside_points):
        pts = np.rint(np.asarray(inside_points, dtype=np.float64).reshape(-1, 2) - 0.5).astype(np.int64)
        ok = (pts[:, 0] >= 0) & (pts[:, 0] < free.shape[1]) & (pts[:, 1] >= 0) & (pts[:, 1] < free.shape[0])
        pts = pts[ok]
    open_pts = [tuple(p) for p in pts.tolist() if free[p[1], p[0]] and reach0[p[1], p[0]]]
    info["inside_points"] = int(len(pts))
    info["inside_points_open"] = len(open_pts)
    claimed_pts = 0
    min_contact = max(1, int(round(MIN_CONTACT_M / resolution)))
    for k, rc in enumerate(scales[1:]):
        if not open_pts and (k > 0 or not footprint):
            break
        check()
        if k == 0 and far is not None:
            reach = far.result()
        else:
            reach = _reach(_outside_centres(dist, rc), rc, pad) if k == 0 else _coarse_reach(passable, rc)
        check()
        if k == 0:
            del dist
            far = None
        cand = free & reach0 & ~reach & ~claimed
        if not cand.any():
            continue
        # the sizes from the labelling's statistics (a bincount of the raster costs more than the stats)
        n, lab, st, _ = cv2.connectedComponentsWithStats(cand.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
        size = st[:, cv2.CC_STAT_AREA].astype(np.int64)
        del st
        keep = np.zeros(n, bool)
        if k == 0 and not footprint:
            keep[:] = False
        elif k == 0:  # footprint: keep what opens onto the enclosed interior and is a space of its own
            pairs = list(_boundary_pairs(lab))  # (``pairs``: the pieces' outline, walked once for both tests)
            keep = (_opens_onto(lab, n, lab0, n0, big0, min_contact, pairs)
                    & _space_shaped(lab, n, big0[lab0], free & reach, pairs, size))
        # a space proven enclosed by a disk of diameter D is believed up to (CLAIM_FACTOR x D)^2:
        # larger ones are the gaps between drawings on a sheet, forecourts, the street
        small = size <= ((CLAIM_FACTOR if k == 0 else 1.0) * 2.0 * rc) ** 2
        rest = []
        large: Dict[int, list] = {}
        for c, r in open_pts:
            if lab[r, c] > 0 and small[lab[r, c]]:
                keep[lab[r, c]] = True
                claimed_pts += 1
            elif lab[r, c] > 0:  # enclosed but too large: the named part, cut at its mouth (_claim_named_bays)
                large.setdefault(int(lab[r, c]), []).append((c, r))
            else:  # not enclosed at this scale: the next scale, then the mouths, may
                rest.append((c, r))
        for lid, lpts in large.items():
            bay = _claim_named_bays(lab == lid, free & reach0 & ~claimed, lpts, resolution, rc0, rc, check)
            if bay.any():
                claimed |= bay
                info["named_bays_m2"] = info.get("named_bays_m2", 0.0) + float(bay.sum()) * resolution ** 2
            for c, r in lpts:
                if bay[r, c]:
                    claimed_pts += 1
                else:
                    rest.append((c, r))
        open_pts = rest
        keep[0] = False
        keep &= small
        if not keep.any():
            continue
        got = keep[lab]
        got |= _chord_pockets(got, free & reach0 & ~claimed & ~got)
        claimed |= got
    if open_pts and len(scales) > 1:  # names no disk encloses: a space between two facades closes at its mouths
        before = len(open_pts)
        open_pts, got = _claim_names_between_facades(free & reach0 & ~claimed, open_pts, resolution, fgap, check)
        claimed |= got
        info["inside_points_between_facades"] = before - len(open_pts)
        claimed_pts += before - len(open_pts)
    info["inside_points_claimed"] = claimed_pts
    info["inside_points_outside"] = len(open_pts)
    info["claimed_px"] = int(claimed.sum())
    info["claimed"] = claimed
    info["inside_pixels"] = pts
    envelope = ~reach0 | claimed
    interior = free & envelope
    # drop tiny pockets (exterior corners the disk could not reach, drawing slivers)
    n, lab, st, _ = cv2.connectedComponentsWithStats(interior.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    min_px = MIN_INTERIOR_COMPONENT_M2 / resolution ** 2
    small = st[:, cv2.CC_STAT_AREA] < min_px
    small[0] = True
    if small[1:].all() and n > 1:  # a map smaller than the threshold: keep its largest part
        small[1 + int(np.argmax(st[1:, cv2.CC_STAT_AREA]))] = False
    interior &= ~small[lab]
    return interior, envelope


BOUNDARY_MIN_WIDTH_M = 1.0  # space closed by projection lines must be this wide somewhere to be a space


def supported_boundary(free: np.ndarray, boundary: np.ndarray, resolution: float,
                       envelope_gap: float = DEFAULT_ENVELOPE_GAP, inside_points=None, info: Optional[dict] = None
                       ) -> Optional[np.ndarray]:
    """The part of the boundary evidence (projection / dash-dot lines, ``rasterize.boundary_mask``) that
    closes a space of the building: a corridor open on one side or at its ends, closed only by such a line.

    Space that the envelope disk (diameter ``envelope_gap``) reaches without the lines and cannot reach with
    them is kept inside when it holds a room name (``inside_points``, pixel col/row) or opens onto the
    enclosed interior through a doorway (``MIN_CONTACT_M``) and is a space someone walks in (at least
    ``BOUNDARY_MIN_WIDTH_M`` wide somewhere, at most (CLAIM_FACTOR x FOOTPRINT_FACTOR x envelope_gap)^2):
    an eave line 0.5 m outside a facade, or lines in the landscape, close nothing. Returns the boundary
    pixels along the kept spaces (for ``building_interior(boundary=...)``), or None; ``info["space"]`` gets
    the kept spaces (claimed space: not dropped as an exterior pocket)."""
    import cv2

    if boundary is None or not boundary.any():
        return None
    rc0 = max(1.0, envelope_gap / 2.0 / resolution)
    if not (_tie_free(rc0) and _tie_free(0.5 * BOUNDARY_MIN_WIDTH_M / resolution)):
        return _supported_boundary_whole(free, boundary, resolution, envelope_gap, inside_points, info)
    # the envelope disk on the free space alone: computed with building_interior's padding and handed to
    # it (``info["_free_dist"]``), which needs the same distance transform when no line is kept
    pad = _envelope_pad(free.shape, resolution, envelope_gap)
    # compared with rc0 here and with building_interior's radii there only
    radii = _exact_scales(free.shape, resolution, envelope_gap)
    dist_a = _edt_upto(np.pad(free, pad, mode="constant", constant_values=True), radii)
    out_a = _outside_centres(dist_a, rc0)
    shared = {"free": free, "pad": pad, "rc0": rc0, "dist": dist_a, "centres": out_a, "radii": radii}
    if info is not None:
        info["_free_dist"] = shared
    # the lines take away the disk centres within rc0 of them: the distance to the free space's walls
    # and lines is the smaller of the two distances
    near = _near(np.pad(boundary, pad, mode="constant", constant_values=False), rc0)
    if not (near & out_a).any():  # no disk from outside comes within rc0 of a line: they close nothing
        return None
    centres_b = (dist_a > rc0) & ~near
    del near
    out_b = _corner_component(centres_b.view(np.uint8))
    del centres_b
    if not (out_a & ~out_b).any():  # the lines stop no disk from outside: they close nothing
        return None
    reach_a = _reach(out_a, rc0, pad)
    shared["reach"] = reach_a
    reach_b = _reach_without(reach_a, out_a, out_b, rc0, pad)
    del out_b
    rows, cols = free.shape
    walk = free & ~boundary
    cand = walk & reach_a & ~reach_b
    if not cand.any():
        return None
    n, lab = cv2.connectedComponents(cand.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    # the widest clearance of each piece: the distance transform on the pieces' box (a ring of non-piece
    # pixels around it keeps it exact)
    r0, r1, c0, c1 = _bbox(cand)
    ya, yb, xa, xb = max(r0 - 1, 0), min(r1 + 2, rows), max(c0 - 1, 0), min(c1 + 2, cols)
    box = np.zeros((yb - ya + 2, xb - xa + 2), bool)
    box[1:-1, 1:-1] = cand[ya:yb, xa:xb]
    clearance = _edt(box)[1:-1, 1:-1]
    sub = lab[ya:yb, xa:xb]
    inside = sub > 0
    widest = np.zeros(n)
    np.maximum.at(widest, sub[inside], clearance[inside])
    return _kept_lines(free, boundary, resolution, envelope_gap, inside_points, info, n, lab, reach_a, widest)


def _tie_free(r: float) -> bool:
    """True when no pixel distance (the square root of an integer) lies within 1e-4 of ``r``: OpenCV's
    distance transform is exact to about 1e-6 but not bit-identical between a window and the whole
    raster, so the windowed shortcuts are taken only where a comparison with ``r`` cannot tip."""
    k = int(round(r * r))
    return all(abs(math.sqrt(j) - r) > 1e-4 for j in (max(k - 1, 0), k, k + 1))


def _supported_boundary_whole(free, boundary, resolution, envelope_gap, inside_points, info):
    """supported_boundary on whole-raster transforms (where a radius sits on a pixel distance)."""
    import cv2

    rc0 = max(1.0, envelope_gap / 2.0 / resolution)
    pad = int(math.ceil(rc0)) + 2
    reach_a = _reach(_outside_centres(_edt(np.pad(free, pad, mode="constant", constant_values=True)), rc0), rc0,
                     pad)
    walk = free & ~boundary
    reach_b = _reach(_outside_centres(_edt(np.pad(walk, pad, mode="constant", constant_values=True)), rc0), rc0,
                     pad)
    cand = walk & reach_a & ~reach_b
    if not cand.any():
        return None
    n, lab = cv2.connectedComponents(cand.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    clearance = _edt(cand)
    widest = np.zeros(n)
    np.maximum.at(widest, lab.ravel(), clearance.ravel())
    return _kept_lines(free, boundary, resolution, envelope_gap, inside_points, info, n, lab, reach_a, widest)


def _kept_lines(free, boundary, resolution, envelope_gap, inside_points, info, n, lab, reach_a, widest):
    """The end of supported_boundary: which candidate pieces (``lab``, 1..n-1) are kept, and the lines
    along them."""
    import cv2

    rc0 = max(1.0, envelope_gap / 2.0 / resolution)
    interior0 = free & ~reach_a
    n0, lab0, st0, _ = cv2.connectedComponentsWithStats(interior0.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    big0 = st0[:, cv2.CC_STAT_AREA] >= rc0 * rc0
    big0[0] = False
    keep = np.zeros(n, bool)
    if n0 > 1 and big0.any():
        keep = _opens_onto(lab, n, lab0, n0, big0, max(1, int(round(MIN_CONTACT_M / resolution))))
    keep &= widest >= 0.5 * BOUNDARY_MIN_WIDTH_M / resolution
    if inside_points is not None and len(inside_points):
        pts = np.rint(np.asarray(inside_points, dtype=np.float64).reshape(-1, 2) - 0.5).astype(np.int64)
        ok = (pts[:, 0] >= 0) & (pts[:, 0] < free.shape[1]) & (pts[:, 1] >= 0) & (pts[:, 1] < free.shape[0])
        keep[lab[pts[ok, 1], pts[ok, 0]]] = True
    size = np.bincount(lab.ravel(), minlength=n)
    keep &= size * resolution ** 2 <= (CLAIM_FACTOR * FOOTPRINT_FACTOR * envelope_gap) ** 2
    keep[0] = False
    if not keep.any():
        return None
    space = keep[lab]
    if info is not None:
        info["space"] = space
    near = cv2.dilate(space.view(np.uint8), np.ones((5, 5), np.uint8)) > 0
    out = boundary & near
    return out if out.any() else None


def _reach_without(reach_a: np.ndarray, out_a: np.ndarray, out_b: np.ndarray, rc: float, pad: int) -> np.ndarray:
    """``_reach(out_b, rc, pad)`` from ``reach_a = _reach(out_a, rc, pad)`` when ``out_b`` is a subset of
    ``out_a`` (padded frame): the reach changes only within rc of the removed centres, where it is
    recomputed from the centres within reach of that window."""
    removed = out_a & ~out_b
    reach_b = reach_a.copy()
    if not removed.any():
        return reach_b
    rows, cols = reach_a.shape
    r0, r1, c0, c1 = _bbox(removed)
    m = int(math.ceil(rc)) + 1
    ra, rb, ca, cb = max(r0 - m, pad), min(r1 + 1 + m, rows + pad), max(c0 - m, pad), min(c1 + 1 + m, cols + pad)
    if ra < rb and ca < cb:
        w = m + 2
        wa, wb, wc, wd = max(ra - w, 0), min(rb + w, out_b.shape[0]), max(ca - w, 0), min(cb + w, out_b.shape[1])
        e = _edt(~out_b[wa:wb, wc:wd])[ra - wa:rb - wa, ca - wc:cb - wc]
        reach_b[ra - pad:rb - pad, ca - pad:cb - pad] = ~(e > rc)
    return reach_b


def _with_lines(shared: dict, lines: np.ndarray, rc_max: float):
    """building_interior's padded transform and envelope reach of ``free & ~lines`` from those of ``free``
    (``shared``, from supported_boundary): the distance to the lines is computed on their box grown by
    ``rc_max`` + 1 and is the smaller one there; farther out both distances exceed rc_max, the largest
    radius it is compared with (the transform is exact up to rc_max + 1, which is all it is used for)."""
    pad, rc0 = shared["pad"], shared["rc0"]
    lp = np.pad(lines, pad, mode="constant", constant_values=False)
    dist = shared["dist"].copy()
    r0, r1, c0, c1 = _bbox(lp)
    m = int(math.ceil(rc_max)) + 1
    ya, yb, xa, xb = max(r0 - m, 0), min(r1 + 1 + m, lp.shape[0]), max(c0 - m, 0), min(c1 + 1 + m, lp.shape[1])
    np.minimum(dist[ya:yb, xa:xb], _edt(~lp[ya:yb, xa:xb]), out=dist[ya:yb, xa:xb])
    del lp
    out_b = _outside_centres(dist, rc0)
    reach_a = shared["reach"] if "reach" in shared else _reach(shared["centres"], rc0, pad)
    return dist, _reach_without(reach_a, shared["centres"], out_b, rc0, pad)


def _bbox(mask: np.ndarray) -> Tuple[int, int, int, int]:
    """(first row, last row, first col, last col) of the True pixels of a non-empty mask."""
    rows = np.flatnonzero(mask.any(axis=1))
    cols = np.flatnonzero(mask.any(axis=0))
    return int(rows[0]), int(rows[-1]), int(cols[0]), int(cols[-1])


def _near(mask: np.ndarray, r: float) -> np.ndarray:
    """Pixels within ``r`` px (exact Euclidean distance <= r) of a True pixel of ``mask``: the distance
    transform on the box of the True pixels grown by r (no pixel farther out can be that near)."""
    out = np.zeros(mask.shape, bool)
    if not mask.any():
        return out
    r0, r1, c0, c1 = _bbox(mask)
    m = int(math.ceil(r)) + 1
    ya, yb, xa, xb = max(r0 - m, 0), min(r1 + 1 + m, mask.shape[0]), max(c0 - m, 0), min(c1 + 1 + m, mask.shape[1])
    out[ya:yb, xa:xb] = ~(_edt(~mask[ya:yb, xa:xb]) > r)
    return out


def _envelope_pad(shape, resolution: float, envelope_gap: float, footprint_gap: Optional[float] = None) -> int:
    """The padding of building_interior's distance transform (the largest exactly computed disk + 2)."""
    return int(math.ceil(max(_exact_scales(shape, resolution, envelope_gap, footprint_gap)))) + 2


def _exact_scales(shape, resolution: float, envelope_gap: float, footprint_gap: Optional[float] = None):
    """The disk radii (px) building_interior compares its padded transform with: the envelope's and,
    when the footprint scale fits the map, the footprint's."""
    rc0 = max(1.0, envelope_gap / 2.0 / resolution)
    fgap = FOOTPRINT_FACTOR * envelope_gap if footprint_gap is None else float(footprint_gap)
    scales = [rc0]
    if fgap > envelope_gap:
        rcf = fgap / 2.0 / resolution
        scales += [r for r in (rcf, 2.0 * rcf) if 2.0 * r <= max(shape)]
    return scales[:2]


def _narrow_pockets(space: np.ndarray, dist: np.ndarray, resolution: float) -> Optional[np.ndarray]:
    """Enclosed free pockets too narrow for anyone to enter (clearance below ``POCKET_CLEARANCE_M``
    everywhere): the inside of furniture outlines, wall cavities, ducts. Not rooms: they become
    obstacle. None when there are none."""
    import cv2

    n, lab = cv2.connectedComponents(space.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
    if n <= 2:
        return None
    top = np.zeros(n)
    inside = lab > 0  # the background's top is never used
    np.maximum.at(top, lab[inside], dist[inside].astype(np.float64))
    narrow = (top - 0.5) * resolution < POCKET_CLEARANCE_M
    narrow[0] = False
    if narrow[1:].all():
        return None
    if not narrow.any():
        return None
    return narrow[lab]


def _furniture(lab: np.ndarray, st: np.ndarray, resolution: float, candidates: np.ndarray) -> np.ndarray:
    """Which obstacle blobs (components ``lab`` with stats ``st``) stand free in the space like
    furniture: compact (the minimum-area rectangle ``CLUTTER_MIN_LENGTH_M`` to ``CLUTTER_EXTENT_M``
    long, at most ``CLUTTER_M2`` in area and at least ``CLUTTER_THICK_M`` thick -- a wall stub between
    two gaps is thinner; a column is shorter and, like a wall, frames openings), solid (filled outline
    >= ``CLUTTER_SOLID`` x the rectangle: not an L or U of wall pieces) and away from the map border.
    Outlined furniture (a closed contour) counts by its outline."""
    import cv2

    rows, cols = lab.shape
    out = np.zeros(len(st), bool)
    ext = np.maximum(st[:, cv2.CC_STAT_WIDTH], st[:, cv2.CC_STAT_HEIGHT]) * resolution
    border = ((st[:, cv2.CC_STAT_LEFT] == 0) | (st[:, cv2.CC_STAT_TOP] == 0)
              | (st[:, cv2.CC_STAT_LEFT] + st[:, cv2.CC_STAT_WIDTH] >= cols)
              | (st[:, cv2.CC_STAT_TOP] + st[:, cv2.CC_STAT_HEIGHT] >= rows))
    # a rectangle up to CLUTTER_EXTENT_M long has a bounding box up to sqrt(2) x that on a side
    cand = (candidates & ~border & (ext <= CLUTTER_EXTENT_M * 1.42)
            & (st[:, cv2.CC_STAT_AREA] * resolution ** 2 <= CLUTTER_M2))
    cand[0] = False
    for k in np.nonzero(cand)[0].tolist():
        x, y, w, h = (int(v) for v in st[k, :4])
        blob = (lab[y:y + h, x:x + w] == k).astype(np.uint8)
        rr, cc = np.nonzero(blob)
        (_, _), (rw, rh), _ = cv2.minAreaRect(np.stack([cc, rr], axis=1).astype(np.float32))
        short, long_ = (min(rw, rh) + 1) * resolution, (max(rw, rh) + 1) * resolution
        if not (CLUTTER_MIN_LENGTH_M <= long_ <= CLUTTER_EXTENT_M and short * long_ <= CLUTTER_M2
                and short >= CLUTTER_THICK_M):
            continue
        # solid (or an outline closed around its inside), not an L / U of wall pieces
        contours, _ = cv2.findContours(blob, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
        filled = cv2.drawContours(np.zeros_like(blob), contours, -1, 1, thickness=-1)
        out[k] = filled.sum() * resolution ** 2 >= CLUTTER_SOLID * short * long_
    return out


def _without_specks(interior: np.ndarray, resolution: float) -> np.ndarray:
    """The space with obstacle specks (non-free blobs smaller than ``SPECK_M2`` lying inside it:
    sensor noise, clutter) and free-standing furniture (``_furniture``, when ``FREE_STANDING``)
    counted as space: they make no narrowings."""
    import cv2

    n, lab, st, _ = cv2.connectedComponentsWithStats((~interior).view(np.uint8), connectivity=8,
                                                     ltype=cv2.CV_32S)
    small = st[:, cv2.CC_STAT_AREA] * resolution ** 2 <= SPECK_M2
    small[0] = False
    if FREE_STANDING:
        small |= _furniture(lab, st, resolution, ~small)
    if not small.any():
        return interior
    return interior | small[lab]


def _cells(free: np.ndarray, dist: Optional[np.ndarray] = None) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Clearance and its basins. Returns (clearance px float32, basins int32, peak per basin).

    Every free pixel climbs the clearance by steepest ascent (8-neighbourhood) to a local maximum
    (a plateau of the GVD ridge); the pixels that reach the same maximum form one cell. Pointer
    jumping makes this a handful of vectorised passes.
    """
    import cv2

    if dist is None:
        dist = _edt(free)
    rows, cols = free.shape
    # steepest ascent pointer of every pixel (itself when no neighbour is strictly higher); the first
    # direction wins a tie. Within the bounding box of the free pixels, one pixel of margin (no pixel
    # outside it is free, and a non-free pixel is never higher than a free one).
    rr = np.flatnonzero(free.any(axis=1))
    cc = np.flatnonzero(free.any(axis=0))
    cells = np.zeros((rows, cols), np.int32)
    if len(rr) == 0:
        return dist, cells, np.zeros(1, np.float64)
    # even offsets: OpenCV numbers components by 2 x 2 pixel blocks, so the maxima get the numbers
    # they get on the whole raster
    r0, r1 = max(int(rr[0]) - 1, 0) // 2 * 2, min(int(rr[-1]) + 2, rows)
    c0, c1 = max(int(cc[0]) - 1, 0) // 2 * 2, min(int(cc[-1]) + 2, cols)
    R, C = r1 - r0, c1 - c0
    dbox = np.ascontiguousarray(dist[r0:r1, c0:c1])
    peaks = (dbox >= cv2.dilate(dbox, np.ones((3, 3), np.uint8))) & free[r0:r1, c0:c1]
    n, markers = cv2.connectedComponents(peaks.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    peak_val = np.zeros(n, np.float64)
    peak_val[markers[peaks]] = dbox[peaks]
    del peaks
    from . import kernels

    nb = kernels.get()
    if nb is not None:  # the same pointers and roots in one compiled pass (kernels.py)
        cells[r0:r1, c0:c1] = nb.ascent_basins(dbox, np.ascontiguousarray(free[r0:r1, c0:c1]), markers)
        return dist, cells, peak_val
    padded = cv2.copyMakeBorder(dbox, 1, 1, 1, 1, cv2.BORDER_CONSTANT,
                                value=-1.0)
    best = padded[1:R + 1, 1:C + 1].copy()
    step = np.zeros((R, C), np.int32)
    better = np.empty((R, C), bool)
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            if dr == 0 and dc == 0:
                continue
            nb = padded[1 + dr:R + 1 + dr, 1 + dc:C + 1 + dc]
            np.greater(nb, best, out=better)
            np.maximum(best, nb, out=best)
            np.copyto(step, np.int32(dr * C + dc), where=better)
    del best, padded, better
    free_box = free[r0:r1, c0:c1]
    flat_free = np.flatnonzero(free_box.ravel()).astype(np.int32)
    pos = np.full(R * C, -1, np.int32)
    pos[flat_free] = np.arange(len(flat_free), dtype=np.int32)
    parent = pos[flat_free + step.ravel()[flat_free]]
    del step, pos
    while True:
        grand = parent[parent]
        if np.array_equal(grand, parent):
            break
        parent = grand
    box = np.zeros(R * C, np.int32)
    box[flat_free] = markers.ravel()[flat_free[parent]]
    cells[r0:r1, c0:c1] = box.reshape(R, C)
    return dist, cells, peak_val


def _edge_regions(skel: SkeletonGraph, space: np.ndarray, dist: np.ndarray, progress=None, cells=None):
    """The regions of the topology graph. Returns (regions int32, peak clearance px per region,
    number of clearance basins).

    The skeleton edges are split where a clearance valley crosses them -- the borders of the
    basins of ``_cells``, i.e. the clearance minima along the edge, the narrowings at doors -- and
    every free pixel joins the closest edge piece of its own basin (Euclidean, grown through free
    space where the closest piece lies behind a wall). A basin no kept skeleton edge runs through
    (its clearance maximum lay only on pruned branches, or on none) has no region of its own: its
    pixels join the neighbouring regions. ``cells``: ``_cells(space, dist)`` when already computed.
    """
    _, basins, basin_peak = _cells(space, dist) if cells is None else cells
    if progress is not None:
        progress.check()
    er = skel.edge_raster(lone_nodes=True).ravel()
    skp = np.flatnonzero(er)
    key = er[skp].astype(np.int64) * (len(basin_peak) + 1) + basins.ravel()[skp]
    _, inv = np.unique(key, return_inverse=True)  # pieces in edge order, then basin order
    seeds = np.zeros(space.shape, np.int32)
    seeds.ravel()[skp] = inv + 1
    del er, skp, key, inv
    regions = nearest_seed_regions(seeds, space, zones=basins, progress=progress)
    rest = (regions == 0) & (basins > 0)
    if rest.any():
        _, inv = np.unique(basins[rest], return_inverse=True)
        regions[rest] = int(regions.max()) + 1 + inv.astype(np.int32)
    n = int(regions.max())
    peak = np.zeros(n + 1)
    inside = regions > 0
    np.maximum.at(peak, regions[inside], dist[inside].astype(np.float64))
    return regions, peak, len(basin_peak) - 1


def _neighbour_pairs(labels: np.ndarray, dist: Optional[np.ndarray] = None):
    """All 4-neighbour pixel pairs with two different non-zero labels.

    Returns (lo, hi, value, axis, row, col): labels of the pair (lo < hi), min clearance of the two
    pixels (if ``dist`` is given), axis 0 for vertical neighbours (row, col) / (row+1, col), axis 1
    for horizontal neighbours (row, col) / (row, col+1).
    """
    from . import kernels

    nb = kernels.get()
    if nb is not None:  # the same pairs in the same order from one compiled scan (kernels.py)
        d = np.zeros((1, 1), np.float32) if dist is None else dist
        return nb.neighbour_pairs(labels, d, dist is not None)
    out = []
    for axis in (0, 1):
        if axis == 0:
            a, b = labels[:-1, :], labels[1:, :]
        else:
            a, b = labels[:, :-1], labels[:, 1:]
        m = (a != b) & (a > 0) & (b > 0)
        rr, cc = np.nonzero(m)
        la, lb = a[rr, cc], b[rr, cc]
        if dist is not None:
            if axis == 0:
                v = np.minimum(dist[rr, cc], dist[rr + 1, cc])
            else:
                v = np.minimum(dist[rr, cc], dist[rr, cc + 1])
        else:
            v = np.zeros(len(rr), np.float32)
        out.append((np.minimum(la, lb), np.maximum(la, lb), v, np.full(len(rr), axis, np.int8), rr, cc))
    return tuple(np.concatenate([o[i] for o in out]) for i in range(6))


def _cell_graph(cells: np.ndarray, dist: np.ndarray):
    """Edges of the cell adjacency graph: (lo, hi, saddle px, border length px)."""
    lo, hi, v, _, _, _ = _neighbour_pairs(cells, dist)
    if len(lo) == 0:
        return (np.zeros(0, np.int64),) * 2 + (np.zeros(0),) * 2
    key = lo.astype(np.int64) * (int(cells.max()) + 1) + hi
    order = np.lexsort((v, key))
    key, v = key[order], v[order]
    last = np.r_[key[1:] != key[:-1], True]
    first = np.r_[True, key[1:] != key[:-1]]
    starts = np.nonzero(first)[0]
    counts = np.diff(np.r_[starts, len(key)])
    k = key[last]
    n1 = int(cells.max()) + 1
    return k // n1, k % n1, v[last].astype(np.float64), counts.astype(np.float64)


class _UnionFind:
    def __init__(self, n: int):
        self.parent = list(range(n))

    def find(self, a: int) -> int:
        p = self.parent
        root = a
        while p[root] != root:
            root = p[root]
        while p[a] != root:
            p[a], a = root, p[a]
        return root


def _merge_cells(n: int, peak: np.ndarray, lo, hi, saddle, *, r_alpha: float, door_half: float,
                 min_rise: float, cell_area: Optional[np.ndarray] = None, corridor_opening: float = 3.0
                 ) -> np.ndarray:
    """Merge tree over the region ("cell") graph (see the module doc). All values in px. Returns a
    lookup table cell -> group representative.

    Pass 1 (strongest connections first) merges what belongs together whatever the widths: cells
    whose peak rises less than ``min_rise`` above their saddle (no space of their own) and cells the
    alpha disk sweeps between (saddle >= R). Pass 2 then judges every remaining opening
    against the significant spaces on both sides from pass 1: a door-sized opening clearly narrower
    than the space behind it keeps the split, anything else merges. Pass 3 joins touching
    corridor-shaped groups (``PASS3_ELONGATION``) through any opening wider than
    ``corridor_opening``.
    """
    order = np.lexsort((hi, lo, -saddle))  # strongest first; ties broken by ids (deterministic)
    # one pass over the edges as Python lists (no numpy scalar per access), strongest first
    edges = list(zip(np.asarray(lo)[order].tolist(), np.asarray(hi)[order].tolist(),
                     np.asarray(saddle, dtype=np.float64)[order].tolist()))
    uf = _UnionFind(n)
    gpeak = [float(x) for x in peak]
    for li, hj, s in edges:
        a, b = uf.find(li), uf.find(hj)
        if a == b:
            continue
        pa, pb = gpeak[a], gpeak[b]
        if s >= r_alpha or min(pa, pb) - s < min_rise:
            keep, gone = (a, b) if a < b else (b, a)
            uf.parent[gone] = keep
            gpeak[keep] = max(pa, pb)
    base = [uf.find(i) for i in range(n)]
    bpeak = [gpeak[base[i]] for i in range(n)]
    for li, hj, s in edges:
        a, b = uf.find(li), uf.find(hj)
        if a == b:
            continue
        pa, pb = bpeak[li], bpeak[hj]
        if s <= door_half and s < NARROWING * max(pa, pb):
            continue  # door-like narrowing
        keep, gone = (a, b) if a < b else (b, a)
        uf.parent[gone] = keep
    if cell_area is not None and CORRIDOR_MERGE:
        # pass 3: corridors are not split by narrowings: join touching corridor-shaped groups
        # width of a group = twice its area-weighted mean cell peak (a wide junction or bay does
        # not make a corridor look like a room)
        garea = np.zeros(n)
        gpk = np.zeros(n)
        roots = np.array([uf.find(i) for i in range(n)])
        np.add.at(garea, roots, cell_area)
        np.add.at(gpk, roots, cell_area * peak)
        garea, gpk = garea.tolist(), gpk.tolist()

        def corridor(g):
            half = gpk[g] / garea[g] if garea[g] > 0 else 0.0
            return garea[g] >= PASS3_ELONGATION * (2.0 * max(half, 1.0)) ** 2

        for li, hj, s in edges:
            a, b = uf.find(li), uf.find(hj)
            if a == b or s < corridor_opening or not (corridor(a) and corridor(b)):
                continue
            keep, gone = (a, b) if a < b else (b, a)
            uf.parent[gone] = keep
            garea[keep] += garea[gone]
            gpk[keep] += gpk[gone]
    return np.array([uf.find(i) for i in range(n)], np.int64)


def _single_pieces(labels: np.ndarray) -> np.ndarray:
    """Make every label one 4-connected piece: smaller pieces go to the other label they touch
    most (8-neighbourhood), or to no area when they touch none."""
    import cv2

    for _ in range(3):
        extra = []
        for lab_id, sl in enumerate(kernels.find_objects(labels), start=1):
            if sl is None:
                continue
            sub = labels[sl] == lab_id
            n, cl, st, _ = cv2.connectedComponentsWithStats(sub.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
            if n <= 2:
                continue
            big = 1 + int(np.argmax(st[1:, cv2.CC_STAT_AREA]))
            # work in the bounding box grown by one pixel
            r0, r1 = max(sl[0].start - 1, 0), min(sl[0].stop + 1, labels.shape[0])
            c0, c1 = max(sl[1].start - 1, 0), min(sl[1].stop + 1, labels.shape[1])
            box = (slice(r0, r1), slice(c0, c1))
            for k in range(1, n):
                if k != big:
                    m = np.zeros((r1 - r0, c1 - c0), bool)
                    m[sl[0].start - r0:sl[0].stop - r0, sl[1].start - c0:sl[1].stop - c0] = cl == k
                    extra.append((lab_id, box, m))
        if not extra:
            break
        for lab_id, box, m in extra:
            sub = labels[box]
            ring = cv2.dilate(m.view(np.uint8), np.ones((3, 3), np.uint8)).view(bool) & ~m
            neigh = sub[ring]
            neigh = neigh[(neigh > 0) & (neigh != lab_id)]
            if len(neigh):
                vals, cnt = np.unique(neigh, return_counts=True)
                sub[m] = vals[np.argmax(cnt)]
            else:
                sub[m] = 0
    return labels


def _drop_outside_pockets(labels: np.ndarray, outside: np.ndarray, group_peak: np.ndarray,
                          claimed: Optional[np.ndarray] = None, inside_pixels=None):
    """Remove areas that are mostly open to the outside (exterior recesses the envelope disk could
    not reach) and renumber the rest 1..n in the same order. Areas with evidence of being inside
    are kept: those holding an inside point (a room name) and those mostly made of space claimed
    on evidence (``claimed``). Returns (labels, peaks, dropped px)."""
    n = int(labels.max())
    if n == 0 or not outside.any():
        return labels, group_peak, 0
    total = np.zeros(n + 1, np.int64)
    open_ = np.zeros(n + 1, np.int64)
    # the 4-neighbour pairs (p, p + step) of the flat raster whose labels differ; outside pixels carry no
    # label, so every labelled-outside pair is one of them
    flat = np.ascontiguousarray(labels).ravel()
    out_flat = np.ascontiguousarray(outside).ravel()
    cols = labels.shape[1]
    for step in (cols, 1):
        diff = flat[:-step] != flat[step:]
        if step == 1:
            diff[cols - 1::cols] = False  # no pair from the end of a row to the start of the next
        idx = np.flatnonzero(diff)
        del diff
        a, b = flat[idx], flat[idx + step]
        oa, ob = out_flat[idx], out_flat[idx + step]
        total += np.bincount(a, minlength=n + 1) + np.bincount(b, minlength=n + 1)
        open_ += np.bincount(a[(a > 0) & ob], minlength=n + 1) + np.bincount(b[(b > 0) & oa], minlength=n + 1)
    drop = open_ >= OUTSIDE_CONTACT * np.maximum(total, 1)
    if claimed is not None and claimed.any():
        size = np.bincount(labels.ravel(), minlength=n + 1)
        got = np.bincount(labels[claimed], minlength=n + 1)
        drop &= ~(got >= 0.5 * np.maximum(size, 1))
    if inside_pixels is not None and len(inside_pixels):
        drop[labels[inside_pixels[:, 1], inside_pixels[:, 0]]] = False
    drop[0] = False
    if not drop.any():
        return labels, group_peak, 0
    keep_ids = np.nonzero(~drop[1:])[0] + 1
    lut = np.zeros(n + 1, np.int32)
    lut[keep_ids] = np.arange(1, len(keep_ids) + 1, dtype=np.int32)
    dropped_px = int(np.count_nonzero(drop[labels]))
    return lut[labels], np.r_[0.0, group_peak[keep_ids]], dropped_px


# --------------------------------------------------------------------------- laser-ray spikes
RAY_SPIKES = True
RAY_UNKNOWN_SHARE = 0.5  # an area bordering unknown space for this share of its outline ...
RAY_WIDTH_M = 0.3  # ... and narrower than this on average (2 x area / outline) is a fan of laser rays


def _drop_ray_spikes(labels: np.ndarray, data: np.ndarray, group_peak: np.ndarray, resolution: float,
                     stats: dict):
    """Laser rays through doors and windows are no space. On a recorded map the rays that passed a
    window or a door leave thin spikes of free space in the unknown beyond it; where they fan out
    from the opening they form an area of their own. An area narrower on average than a person
    (``RAY_WIDTH_M``, mean width 2 x area / outline length: near the opening the rays overlap, so its
    widest disk says little) whose outline borders unknown space for ``RAY_UNKNOWN_SHARE`` of its
    length is such a fan: it is no area (its cells stay free, unlabelled).
    Only on recorded maps whose walls are occupied cells (``_observed_walls``: where walls are drawn
    grey every area borders unknown); grids without unknown cells (every CAD raster) are unchanged by
    construction. Returns (labels,
    group_peak); ``stats["ray_spikes_m2"]``."""
    n = int(labels.max())
    unknown = data == UNKNOWN
    if n == 0 or not unknown.any():
        return labels, group_peak
    pk = np.zeros(n + 1)
    pk[:min(n + 1, len(group_peak))] = group_peak[:n + 1]
    total = np.zeros(n + 1, np.int64)
    unk = np.zeros(n + 1, np.int64)
    for axis in (0, 1):
        a, b = (labels[:-1, :], labels[1:, :]) if axis == 0 else (labels[:, :-1], labels[:, 1:])
        ua, ub = (unknown[:-1, :], unknown[1:, :]) if axis == 0 else (unknown[:, :-1], unknown[:, 1:])
        diff = a != b
        total += np.bincount(a[diff], minlength=n + 1) + np.bincount(b[diff], minlength=n + 1)
        unk += np.bincount(a[(a > 0) & ub], minlength=n + 1) + np.bincount(b[(b > 0) & ua], minlength=n + 1)
    # mean width of an area: 2 x area / outline length (a fan of 0.15 m rays: about 0.15 m)
    size = np.bincount(labels.ravel(), minlength=n + 1)
    thin = 2.0 * size / np.maximum(total, 1) * resolution < RAY_WIDTH_M
    drop = thin & (unk >= RAY_UNKNOWN_SHARE * np.maximum(total, 1))
    drop[0] = False
    if not drop.any():
        return labels, group_peak
    keep_ids = np.nonzero(~drop[1:])[0] + 1
    lut = np.zeros(n + 1, np.int32)
    lut[keep_ids] = np.arange(1, len(keep_ids) + 1, dtype=np.int32)
    stats["ray_spikes_m2"] = float(np.count_nonzero(drop[labels])) * resolution ** 2
    return lut[labels], np.r_[0.0, pk[keep_ids]]


# --------------------------------------------------------------------------- cluttered borders
CLUTTER_BORDERS = True
BORDER_LENGTH = 0.8  # a border at least this x as long as the widest disk of both areas is wide is no door ...
BORDER_CONTINUOUS = 0.5  # ... when it is one border: free along this share of its extent (not scattered contacts)


def _border_extent(labels: np.ndarray, boxes: np.ndarray, root: np.ndarray, a: int, b: int):
    """Pixel pairs on the border of areas ``a`` and ``b`` (labels mapped through ``root``: joined
    areas count as one) and their extent (px, the diagonal of the border's bounding box), measured
    where the two areas' bounding boxes (``boxes`` rows r0, r1, c0, c1 per root) overlap."""
    r0, r1 = max(max(boxes[a, 0], boxes[b, 0]) - 1, 0), min(boxes[a, 1], boxes[b, 1]) + 1
    c0, c1 = max(max(boxes[a, 2], boxes[b, 2]) - 1, 0), min(boxes[a, 3], boxes[b, 3]) + 1
    if r1 - r0 < 2 or c1 - c0 < 2:
        return 0.0, 0.0
    sub = root[labels[r0:r1, c0:c1]]
    ia, ib = sub == a, sub == b
    rows, cols = [], []
    for x, y in ((ia[:-1, :], ib[1:, :]), (ib[:-1, :], ia[1:, :]), (ia[:, :-1], ib[:, 1:]), (ib[:, :-1], ia[:, 1:])):
        rr, cc = np.nonzero(x & y)
        rows.append(rr)
        cols.append(cc)
    n_across = len(rows[0]) + len(rows[1])  # pairs one above the other: border steps running along x
    rr, cc = np.concatenate(rows), np.concatenate(cols)
    if len(rr) == 0:
        return 0.0, 0.0
    # a staircase border along a diagonal has a pair per step in x and one per step in y: its length is
    # the hypotenuse of the two counts, not their sum
    return float(math.hypot(n_across, len(rr) - n_across)), float(math.hypot(np.ptp(rr) + 1.0, np.ptp(cc) + 1.0))


def _join_cluttered_borders(labels: np.ndarray, cell_label: np.ndarray, lo, hi, border, group_peak: np.ndarray,
                            stats: dict):
    """Furniture standing in an opening makes no door. The merge judges an opening by its widest
    gap (the saddle: the largest disk that passes); a table, a row of columns or scan clutter across
    a room narrows every gap, so the room comes out in pieces split through the furniture. The width
    of an opening is its free length: two areas whose shared border is at least as long as the widest
    disk in either of them is wide (``BORDER_LENGTH``: a door is narrower than the room it opens) and
    is one border (free along ``BORDER_CONTINUOUS`` of its extent, not contacts scattered along a
    wall) are one space. Border lengths come from the region graph (``lo``, ``hi``, ``border`` of
    ``_cell_graph``, regions -> areas by ``cell_label``); only the candidates are measured on the
    raster. Returns (labels, group_peak); ``stats["clutter_borders_joined"]``."""

    t = time.perf_counter()
    n = int(labels.max()) + 1
    joined = 0
    if n > 2 and len(lo):
        ga = cell_label[np.asarray(lo, np.int64)].astype(np.int64)
        gb = cell_label[np.asarray(hi, np.int64)].astype(np.int64)
        w = np.asarray(border, np.float64)
        pk = np.zeros(n)
        pk[:min(n, len(group_peak))] = group_peak[:n]
        uf = _UnionFind(n)
        done = set()
        boxes = None
        for _ in range(32):
            root = np.array([uf.find(k) for k in range(n)], np.int64)
            ra, rb = root[ga], root[gb]
            m = (ra != rb) & (ra > 0) & (rb > 0)
            x, y = np.minimum(ra[m], rb[m]), np.maximum(ra[m], rb[m])
            key, inv = np.unique(x * n + y, return_inverse=True)
            cnt = np.bincount(inv, weights=w[m], minlength=len(key))
            a, b = key // n, key % n
            cand = np.flatnonzero(cnt >= BORDER_LENGTH * 2.0 * np.maximum(pk[a], pk[b]))
            cand = [i for i in cand[np.argsort(-cnt[cand], kind="stable")].tolist()
                    if (int(a[i]), int(b[i])) not in done]
            if not cand:
                break
            # measured on the raster: the areas as they are now (members of joined groups included);
            # the bounding box of a joined group is the union of its members'
            if boxes is None:
                boxes = np.zeros((n, 4), np.int64)
                for k, sl in enumerate(kernels.find_objects(labels), start=1):
                    if sl is not None and k < n:
                        boxes[k] = (sl[0].start, sl[0].stop, sl[1].start, sl[1].stop)
                boxes[0] = (0, 0, 0, 0)
            gb_ = boxes.copy()
            for k in range(1, n):
                r = root[k]
                if r != k and boxes[k, 1] > boxes[k, 0]:
                    if gb_[r, 1] > gb_[r, 0]:
                        gb_[r, 0], gb_[r, 2] = min(gb_[r, 0], boxes[k, 0]), min(gb_[r, 2], boxes[k, 2])
                        gb_[r, 1], gb_[r, 3] = max(gb_[r, 1], boxes[k, 1]), max(gb_[r, 3], boxes[k, 3])
                    else:
                        gb_[r] = boxes[k]
            touched = set()
            for i in cand:
                p, q = int(a[i]), int(b[i])
                if p in touched or q in touched:
                    continue  # border lengths changed: judged again in the next round
                done.add((p, q))
                c, ext = _border_extent(labels, gb_, root, p, q)
                if c < BORDER_LENGTH * 2.0 * max(pk[p], pk[q]) or c < BORDER_CONTINUOUS * ext:
                    continue
                uf.parent[q] = p
                pk[p] = max(pk[p], pk[q])
                joined += 1
                touched.update((p, q))
            if not touched:
                break
            done = {d for d in done if d[0] not in touched and d[1] not in touched}  # their borders grew
        if joined:
            labels, group_peak = _relabel_joined(uf, n, labels, pk)
    stats["clutter_borders_joined"] = float(joined)
    stats["clutter_borders_s"] = time.perf_counter() - t
    return labels, group_peak


def _relabel_joined(uf, n: int, labels: np.ndarray, pk: np.ndarray):
    """Labels renumbered 1.. after groups were joined in ``uf`` (0 stays 0), and each new group's peak
    clearance (the largest of its members')."""
    root = np.array([uf.find(k) for k in range(n)], np.int64)
    reps = np.unique(root[1:])
    lut = np.zeros(n, np.int32)
    lut[reps] = np.arange(1, len(reps) + 1, dtype=np.int32)
    lut = lut[root]
    lut[0] = 0
    newpk = np.zeros(len(reps) + 1)
    np.maximum.at(newpk, lut, pk)
    return lut[labels], newpk


# --------------------------------------------------------------------------- wall-line openings
WALL_CUTS = True
WALL_MIN_M = 1.0  # a wall face is a straight run of at least this length (not clutter, not scan noise)
FACE_FOLLOW = 1.0  # a wall face is followed this x WALL_MIN_M beyond its Hough segment's end
CUT_MIN_M = 0.5  # gaps in a wall line narrower than this are scan gaps, not openings
CUT_RATIO = 0.8  # an opening in a wall line is a door when it is narrower than this x both spaces along the line
CUT_DEPTH = 0.5  # ... and both spaces reach at least this x the opening's width behind it
WALLS_OBSERVED = True  # wall lines run along occupied cells only (not along unknown space) ...
OBSERVED_SHARE = 0.1  # ... unless less than this share of the space's border is occupied (walls drawn grey)
CUT_MIN_ROOM_M = 1.0  # ... and both are at least a (1 m)^2 space (and CUT_DEPTH x the opening squared)


FACE_FRAME = True  # the wall faces' Hough runs in the frame of the face pixels' bounding box, not the image's ...
FACE_PHASES = 2  # ... once per offset 0 .. FACE_PHASES - 1 px of that frame in x and y, the faces of all kept
# (a short ragged face reaches the Hough's minimum length at one rounding of rho and not at the next; one frame
# alone: intel_map 0.763, mean over seven angles 0.892; a 2 x 2 block: 0.821, 0.902; docs/segmentation.md)


def _wall_faces(space: np.ndarray, resolution: float, occupied: Optional[np.ndarray] = None) -> np.ndarray:
    """Straight wall faces (Hough segments of obstacle pixels next to free space), (n, 4): x1, y1, x2, y2 in
    px (float64 with ``FACE_FIT``, else int32). With ``occupied``, only observed obstacles make faces (``_observed_walls``).
    ``cv2.HoughLinesP`` rounds rho = x cos t + y sin t from the origin of the image it is given, so the
    faces found (which bin reaches the threshold first, where its segment stops) depend on where the map
    lies in its raster (intel_map padded by 0-3 px: MCC 0.758-0.831). With ``FACE_FRAME`` it is given the
    face pixels' bounding box: the same faces wherever the map lies (its points, their order and the
    accumulator are those of the box; the sampling's random sequence is fixed). A short scanned face
    (1-1.5 m, ragged) reaches ``minLineLength`` at one rounding of rho and not at the next, so the Hough
    runs on ``FACE_PHASES`` x ``FACE_PHASES`` frames (the box moved by 0 .. FACE_PHASES - 1 px) and the
    faces of all are kept (sorted, each once)."""
    import cv2

    k = np.ones((3, 3), np.uint8)
    face = (~space if occupied is None else occupied) & cv2.dilate(space.view(np.uint8), k).view(bool)
    min_len = max(4, int(round(WALL_MIN_M / resolution)))
    img = face.view(np.uint8) * np.uint8(255)
    frames = [(0, 0, img)]
    if FACE_FRAME:
        x, y, w, h = cv2.boundingRect(img)
        if w == 0 or h == 0:
            return np.zeros((0, 4), np.int32)
        frames = []
        for p in range(max(1, int(FACE_PHASES))):
            for q in range(max(1, int(FACE_PHASES))):
                box = np.zeros((h + q, w + p), np.uint8)
                box[q:, p:] = img[y:y + h, x:x + w]
                frames.append((x - p, y - q, box))
    out = []
    for x0, y0, im in frames:
        segs = cv2.HoughLinesP(im, 1, np.pi / 180, threshold=max(3, int(0.7 * min_len)), minLineLength=min_len,
                               maxLineGap=2)
        if segs is not None:
            out.append(segs.reshape(-1, 4).astype(np.int32) + np.array([x0, y0, x0, y0], np.int32))
    if not out:
        return np.zeros((0, 4), np.int32)
    segs = np.concatenate(out)
    segs = np.unique(segs, axis=0) if len(out) > 1 else segs
    return _fit_faces(segs, face) if FACE_FIT else segs


FACE_FIT = False  # each face's line is fitted to the face pixels along its Hough segment (not the 1-deg bin) ...
FACE_FIT_PX = 1.0  # ... those within this distance of the segment's line (a straight face's staircase: +-0.5 px)
# (off: exact on clean staircases (turned synthetic offices 18/20 -> 19/20), but on recorded maps it follows the
# scan's ragged pixels: mean MCC over seven angles 0.902 -> 0.898, input_raw/ at 0 deg 0.911 -> 0.900; docs)


def _fit_faces(segs: np.ndarray, face: np.ndarray) -> np.ndarray:
    """The Hough segments ``segs`` (n, 4) with their line fitted (total least squares) to the face pixels
    within ``FACE_FIT_PX`` of it between its ends: float64 (n, 4), the ends projected onto the fitted line.
    The Hough angle is a 1-deg bin and its rho a rounded pixel: the line continued across an opening from a
    face at an angle drifts by a pixel per metre and passes the far jamb or cuts a sliver. Segments with
    fewer than half their length in face pixels keep their Hough line."""
    rows, cols = face.shape
    out = segs.astype(np.float64)
    for i, (x1, y1, x2, y2) in enumerate(segs.tolist()):
        c0, c1 = max(min(x1, x2) - 2, 0), min(max(x1, x2) + 3, cols)
        r0, r1 = max(min(y1, y2) - 2, 0), min(max(y1, y2) + 3, rows)
        yy, xx = np.nonzero(face[r0:r1, c0:c1])
        if len(xx) < 3:
            continue
        px, py = xx + (c0 - x1), yy + (r0 - y1)  # relative to the first end
        dx, dy = x2 - x1, y2 - y1
        ll = math.hypot(dx, dy)
        if ll == 0:
            continue
        ex, ey = dx / ll, dy / ll
        mx = my = 0.0
        fitted = False
        for width in (1.5 * FACE_FIT_PX, FACE_FIT_PX):  # about the Hough line, then about the first fit
            t = px * ex + py * ey
            near = (np.abs((py - my) * ex - (px - mx) * ey) <= width) & (t >= -1.0) & (t <= ll + 1.0)
            if near.sum() < max(3, 0.5 * ll):
                break
            qx, qy = px[near].astype(np.float64), py[near].astype(np.float64)
            mx, my = qx.mean(), qy.mean()
            w, v = np.linalg.eigh(np.cov(np.stack([qx - mx, qy - my])))
            ex, ey = (v[:, 1] if v[:, 1] @ (dx, dy) >= 0 else -v[:, 1]).tolist()
            fitted = True
        if not fitted:
            continue
        for j, (ax, ay) in enumerate(((0.0, 0.0), (float(dx), float(dy)))):
            tt = (ax - mx) * ex + (ay - my) * ey
            out[i, 2 * j] = x1 + mx + ex * tt
            out[i, 2 * j + 1] = y1 + my + ey * tt
    return out


def _observed_walls(data: np.ndarray, space: np.ndarray) -> Optional[np.ndarray]:
    """Obstacles a wall line can run along: the occupied cells (not the space). Unknown cells are not
    walls: on a recorded map the unknown wedge behind an open door leaf or a desk is where the laser
    did not see, and its straight edges continued across a room cut it diagonally. None when the
    grid has no unknown cells, and when hardly any of the space's border is occupied (a map that
    draws its walls in grey: there the unknown cells are the walls)."""
    import cv2

    if not WALLS_OBSERVED:
        return None
    unknown = data == UNKNOWN
    if not unknown.any():
        return None
    border = ~space & cv2.dilate(space.view(np.uint8), np.ones((3, 3), np.uint8)).view(bool)
    n_border = int(np.count_nonzero(border))
    if n_border == 0 or np.count_nonzero(border & ~unknown) < OBSERVED_SHARE * n_border:
        return None
    return ~space & ~unknown


FACE_JOG_PX = 1  # a scanned wall face jogs sideways by this many px: it is followed through the jog


def _face_jog(on_wall: np.ndarray, side: np.ndarray, xs, ys, ux, uy, wall: np.ndarray, space: np.ndarray,
              jog_px: int = FACE_JOG_PX):
    """Follow a scanned wall face through sideways jogs of ``FACE_JOG_PX``: a recorded wall is not one
    straight pixel line (intel_map's east-room wall steps 1 px twice in 1.8 m), so the Hough segment
    stops at the first step and the line continued from there runs inside the wall. Along the line a
    pixel is on the wall when the line pixel or one within the jog sideways is wall, and beside space
    when space lies within 1.5 + jog px on either side (a corner, where the wall turns, has wall on
    both sides for longer: it still ends the face)."""
    rows, cols = space.shape
    j = int(jog_px)
    on = on_wall.copy()
    sd = side.copy()
    for off in range(1, j + 1):
        for sgn in (-off, off):
            sx = np.clip(np.rint(xs - uy * sgn).astype(np.int64), 0, cols - 1)
            sy = np.clip(np.rint(ys + ux * sgn).astype(np.int64), 0, rows - 1)
            on |= wall[sy, sx]
        for sgn in (-1.5 - off, 1.5 + off):
            sx = np.clip(np.rint(xs - uy * sgn).astype(np.int64), 0, cols - 1)
            sy = np.clip(np.rint(ys + ux * sgn).astype(np.int64), 0, rows - 1)
            sd |= space[sy, sx]
    return on, sd


WALL_ENDS = True  # a wall line is continued from where a wall ends (a jamb), not from a corner ...
END_THICK_M = 0.6  # ... where obstacle runs on across the line for longer than a wall is thick
END_STRIP = False  # ... measured across a strip behind the end, not along single pixel rays (turned maps) ...
END_STRIP_PX = 3  # ... this many px deep: a pixel staircase (a face at an angle) cannot end the run early
# (off: it removes the cuts across a corridor from its corners on turned maps, but those are rejected by the
# judge anyway, and intel_map at 0 deg loses 0.831 -> 0.796; docs/segmentation.md)


def _wall_ends(wall: np.ndarray, resolution: float, ends, dirs, k) -> np.ndarray:
    """Whether the face that ends at each candidate opening ends as a wall does at a doorway (a jamb:
    across the line, the obstacle at its last pixels is at most ``END_THICK_M`` thick) rather than
    turning a corner (the obstacle runs on across the line: the outline of a block or the corner of
    a room, whose line continued cuts open space: lab_d, a 1.6 m pier's face continued 3.3 m
    across a hall)."""
    rows, cols = wall.shape
    ux, uy = dirs[:, :1], dirs[:, 1:]
    tmax = int(math.ceil(END_THICK_M / resolution))
    off = np.arange(0, tmax + 2, dtype=np.float64)
    kk = np.asarray(k, np.float64)[:, None]
    back = np.arange(1.0, (END_STRIP_PX if END_STRIP else 2) + 1.0)[None, :]
    bx = ends[:, :1] + ux * (kk - back)
    by = ends[:, 1:] + uy * (kk - back)
    thick = 0
    for sgn in (-1.0, 1.0):
        sx = np.clip(np.rint(bx[:, :, None] - uy[:, :, None] * sgn * off).astype(np.int64), 0, cols - 1)
        sy = np.clip(np.rint(by[:, :, None] + ux[:, :, None] * sgn * off).astype(np.int64), 0, rows - 1)
        w = wall[sy, sx]
        if END_STRIP:  # across a strip END_STRIP_PX deep behind the end: obstacle where any of its pixels is
            w = w.any(axis=1)
        run = np.argmin(w, axis=-1)  # contiguous obstacle from the line outwards
        run[w.all(axis=-1)] = w.shape[-1]
        thick = thick + run
    return (thick if END_STRIP else thick.min(axis=1)) <= tmax + 1


JAMB_CUTS = False  # openings also run from a wall's end across to the next obstacle, square to the wall


def _jamb_openings(space: np.ndarray, wall: np.ndarray, ends, dirs, k, min_px: float, max_px: float, seen: set,
                   resolution: float):
    """Openings from a wall's end (a jamb) square to the wall: from the wall's last pixel, across
    the free space beside it to the next obstacle (``min_px`` .. ``max_px`` long). A room open onto
    a corridor beside the end of a wall (intel_map's corner room: the wall between it and the next
    room ends where the corridor turns, and the room's open side runs from that end to the block
    opposite) has its opening there, not along the wall's line. Judged like every wall-line opening
    (``_judge_opening``). Returns entries as ``_wall_line_openings``."""
    rows, cols = space.shape
    ux, uy = dirs[:, :1], dirs[:, 1:]
    last = np.asarray(k, np.float64)[:, None] - 1.0
    px = ends[:, :1] + ux * last
    py = ends[:, 1:] + uy * last
    thick_px = int(math.ceil(END_THICK_M / resolution)) + 1
    t = np.arange(1, int(math.ceil(max_px)) + thick_px + 3, dtype=np.float64)[None, :]
    out = []
    for sgn in (-1.0, 1.0):
        nx, ny = -uy * sgn, ux * sgn
        xs = np.rint(px + nx * t).astype(np.int64)
        ys = np.rint(py + ny * t).astype(np.int64)
        inb = (xs >= 0) & (xs < cols) & (ys >= 0) & (ys < rows)
        xs, ys = np.clip(xs, 0, cols - 1), np.clip(ys, 0, rows - 1)
        # through the wall's own thickness first (the face may be either of its two faces)
        w = wall[ys, xs] & inb
        skip = np.argmin(w, axis=1)
        rr = np.arange(len(skip))
        fr = space[ys, xs] & inb & (np.arange(t.shape[1])[None, :] >= skip[:, None])
        after = np.where(np.arange(t.shape[1])[None, :] < skip[:, None], True, fr)
        stop = np.argmin(after, axis=1)
        ok = (~after.all(axis=1) & (skip <= thick_px) & fr[rr, skip] & (stop > skip) & inb[rr, stop]
              & wall[ys[rr, stop], xs[rr, stop]])
        _add_runs(out, seen, xs, ys, np.flatnonzero(ok), skip, stop, ny[:, 0], nx[:, 0], min_px, max_px)
    return out


SAME_OPENING_PX = 3.5  # two candidate openings that touch or cross, with every end this close (px) to the other,
# are one opening seen from its two jambs (a face at an angle gives several Hough segments, 1 deg apart, whose
# lines cross in the gap and cut slivers between them); parallel lines a wall's thickness apart stay two


def _point_segment_px(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance of the points ``p`` (n, 2) from the segments ``a``-``b`` (n, 2 each)."""
    d = b - a
    ll = np.maximum((d * d).sum(axis=1), 1e-12)
    t = np.clip(((p - a) * d).sum(axis=1) / ll, 0.0, 1.0)
    return np.hypot(*(a + d * t[:, None] - p).T)


def _same_opening(key, out) -> int:
    """Which of ``out``'s openings the opening ``key`` (x0, y0, x1, y1) is (``SAME_OPENING_PX``: the two
    segments touch or cross (1 px) and every end of each lies within ``SAME_OPENING_PX`` of the other),
    -1 for none."""
    if not out or not SAME_OPENING_PX:
        return -1
    other = np.array([o[0] for o in out], np.float64)
    a2, b2 = other[:, :2], other[:, 2:]
    a1 = np.broadcast_to(np.array(key[:2], np.float64), a2.shape)
    b1 = np.broadcast_to(np.array(key[2:], np.float64), a2.shape)
    ends = np.stack([_point_segment_px(a1, a2, b2), _point_segment_px(b1, a2, b2),
                     _point_segment_px(a2, a1, b1), _point_segment_px(b2, a1, b1)], axis=1)
    # segments touch or cross: an end of one near the other, or the ends of one on both sides of the other
    def side(p, a, b):
        return np.sign((b[:, 0] - a[:, 0]) * (p[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (p[:, 0] - a[:, 0]))
    cross = (side(a1, a2, b2) * side(b1, a2, b2) <= 0) & (side(a2, a1, b1) * side(b2, a1, b1) <= 0)
    touch = cross | (ends.min(axis=1) <= 1.0)
    hit = np.flatnonzero(touch & (ends.max(axis=1) <= SAME_OPENING_PX))
    return int(hit[0]) if len(hit) else -1


def _add_runs(out, seen, xs, ys, rows, starts, stops, u, v, min_px: float, max_px: float) -> None:
    """Append to ``out`` the free runs ``xs/ys[i, starts[i]:stops[i]]`` of the sampled rays ``rows`` as
    ((x0, y0, x1, y1), length px, (u[i], v[i])), those between ``min_px`` and ``max_px`` long and not yet in
    ``seen`` either way round (the wall-line openings and the jamb openings share this)."""
    for i in rows.tolist():
        s0, st = int(starts[i]), int(stops[i])
        key = (int(xs[i, s0]), int(ys[i, s0]), int(xs[i, st - 1]), int(ys[i, st - 1]))
        run = math.hypot(key[2] - key[0], key[3] - key[1]) + 1.0
        if run < min_px or run > max_px:
            continue
        if key in seen or (key[2], key[3], key[0], key[1]) in seen:
            continue
        same = _same_opening(key, out)
        if same >= 0:  # one opening seen from both jambs: the longer run (the shorter one may stop short)
            if run > out[same][1]:
                seen.add(key)
                out[same] = (key, run, (float(u[i]), float(v[i])))
            continue
        seen.add(key)
        out.append((key, run, (float(u[i]), float(v[i]))))


GAP_SIDE_PX = 1  # a wall line meets the wall beyond an opening within this many px beside it (a face at an angle:
GAP_SIDE_FROM_PX = 3  # its pixels step by 1 px) ... counted from this far past the face's end (not its own jamb)


def _wall_line_openings(space: np.ndarray, labels: np.ndarray, resolution: float, max_cut_m: float,
                        occupied: Optional[np.ndarray] = None, jambs: bool = False, jog_px: int = 0):
    """Openings in wall lines: a wall face that ends in free space is continued along its own line
    to the next obstacle; runs of free space between ``CUT_MIN_M`` and ``max_cut_m`` long are
    candidate openings. Returns a list of ((x0, y0, x1, y1) px ends of the free run, length px,
    unit direction (dy, dx)). ``labels`` is unused (kept for the call signature). ``occupied``: the
    observed obstacles (``_observed_walls``); without it every non-space pixel can be a wall."""
    segs = _wall_faces(space, resolution, occupied)
    wall = ~space if occupied is None else occupied
    rows, cols = space.shape
    max_px = max_cut_m / resolution
    min_px = CUT_MIN_M / resolution
    if len(segs) == 0:
        return []
    # every segment end, pointing away from the segment (end 2 then end 1 of each segment)
    p1 = segs[:, :2].astype(np.float64)
    p2 = segs[:, 2:].astype(np.float64)
    length = np.hypot(*(p2 - p1).T)
    ok = length > 0
    p1, p2, length = p1[ok], p2[ok], length[ok]
    u = (p2 - p1) / length[:, None]
    ends = np.stack([p2, p1], axis=1).reshape(-1, 2)
    dirs = np.stack([u, -u], axis=1).reshape(-1, 2)
    ux, uy = dirs[:, :1], dirs[:, 1:]

    def sample(x0, y0, t):
        xs = np.rint(x0 + ux * t).astype(np.int64)
        ys = np.rint(y0 + uy * t).astype(np.int64)
        inb = (xs >= 0) & (xs < cols) & (ys >= 0) & (ys < rows)
        return np.clip(xs, 0, cols - 1), np.clip(ys, 0, rows - 1), inb

    # follow the wall face to its end (Hough segments stop short, by less than a wall length):
    # obstacle pixels along the line with free space beside them; an obstacle pixel with none beside
    # it is a corner (the wall turns)
    t_face = np.arange(0, int(math.ceil(FACE_FOLLOW * WALL_MIN_M / resolution)) + 1, dtype=np.float64)[None, :]
    xs, ys, inb = sample(ends[:, :1], ends[:, 1:], t_face)
    side = np.zeros(xs.shape, bool)
    for sgn in (-1.5, 1.5):
        sx = np.clip(np.rint(xs - uy * sgn).astype(np.int64), 0, cols - 1)
        sy = np.clip(np.rint(ys + ux * sgn).astype(np.int64), 0, rows - 1)
        side |= space[sy, sx]
    on_wall = wall[ys, xs]
    if jog_px:  # scanned maps: faces step sideways (``_face_jog``)
        on_wall, side = _face_jog(on_wall, side, xs, ys, ux, uy, wall, space, jog_px)
    along_face = on_wall & side & inb
    k = np.argmin(along_face, axis=1)
    rr = np.arange(len(k))
    valid = ~along_face.all(axis=1) & inb[rr, k] & space[ys[rr, k], xs[rr, k]]
    if WALL_ENDS and valid.any():
        valid &= _wall_ends(wall, resolution, ends, dirs, k)
    face_end = valid.copy()
    # then the gap: free pixels along the line up to the next obstacle
    t = np.arange(0, int(math.ceil(max_px)) + 6, dtype=np.float64)[None, :]
    x0 = ends[:, :1] + ux * k[:, None]
    y0 = ends[:, 1:] + uy * k[:, None]
    xs, ys, inb = sample(x0, y0, t)
    fr = space[ys, xs] & inb  # sensor specks inside the space do not end a gap
    if GAP_SIDE_PX:  # the wall beyond the gap within a pixel beside the line ends it too (``GAP_SIDE_PX``)
        far = t >= GAP_SIDE_FROM_PX
        for sgn in range(-GAP_SIDE_PX, GAP_SIDE_PX + 1):
            if sgn:
                sx = np.clip(np.rint(xs - uy * sgn).astype(np.int64), 0, cols - 1)
                sy = np.clip(np.rint(ys + ux * sgn).astype(np.int64), 0, rows - 1)
                fr &= ~(wall[sy, sx] & far)
    stop = np.argmin(fr, axis=1)
    # no obstacle within reach (open space, not a gap in a wall line) or the map ends first
    valid &= ~fr.all(axis=1) & inb[rr, stop] & (stop > 0)
    out = []
    seen = set()
    _add_runs(out, seen, xs, ys, np.flatnonzero(valid), np.zeros(len(stop), np.int64), stop, dirs[:, 1], dirs[:, 0],
              min_px, max_px)
    if jambs:  # also the openings square to the wall from its end (``_wall_line_doors``' second pass)
        return out, _jamb_openings(space, wall, ends[face_end], dirs[face_end], k[face_end], min_px, max_px,
                                   seen, resolution)
    return out


BLOCK_CUTS = True  # a wall line that ends on a free-standing block continues beyond it to the next obstacle ...
BLOCK_EXTENT_M = 3.5  # ... a block: an obstacle component at most this long and wide, away from the map border


def _block_extensions(space: np.ndarray, wall: np.ndarray, openings, resolution: float, max_cut_m: float) -> dict:
    """Where a wall-line opening ends on a free-standing block (an obstacle component no longer than
    ``BLOCK_EXTENT_M`` either way, not touching the map border: a cabinet, a table drawn as an
    outline, a scanned U of furniture), the room is not closed there: it meets the space it opens
    onto again around the block (intel_map's bottom-left corner room). The wall's line continues
    through the block to the next obstacle beyond it; that free run (at most ``max_cut_m``) is cut
    with the opening, so cut + block + cut span wall to wall. The opening itself is judged as before
    (its own run). Returns {opening index: (x0, y0, x1, y1) of the continuation}."""
    import cv2

    if not BLOCK_CUTS or not openings:
        return {}
    rows, cols = wall.shape
    n, comp, st, _ = cv2.connectedComponentsWithStats(wall.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    ext_px = BLOCK_EXTENT_M / resolution
    x0s, y0s = st[:, cv2.CC_STAT_LEFT], st[:, cv2.CC_STAT_TOP]
    x1s, y1s = x0s + st[:, cv2.CC_STAT_WIDTH], y0s + st[:, cv2.CC_STAT_HEIGHT]
    block = ((st[:, cv2.CC_STAT_WIDTH] <= ext_px) & (st[:, cv2.CC_STAT_HEIGHT] <= ext_px) & (x0s > 0) & (y0s > 0)
             & (x1s < cols) & (y1s < rows))
    block[0] = False
    max_px = max_cut_m / resolution
    reach = int(math.ceil(max_px + 1.5 * ext_px)) + 4
    t = np.arange(1, reach, dtype=np.float64)
    out = {}
    for i, (key, _, (uy, ux)) in enumerate(openings):
        xs = np.rint(key[2] + ux * t).astype(np.int64)
        ys = np.rint(key[3] + uy * t).astype(np.int64)
        inb = (xs >= 0) & (xs < cols) & (ys >= 0) & (ys < rows)
        if not inb[0]:
            continue
        xs, ys = np.clip(xs, 0, cols - 1), np.clip(ys, 0, rows - 1)
        c = int(comp[ys[0], xs[0]])
        if c == 0 or not block[c]:
            continue
        mine = (comp[ys, xs] == c) & inb
        last = int(np.flatnonzero(mine).max())  # through the block (and any space inside its outline)
        after = space[ys[last + 1:], xs[last + 1:]] & inb[last + 1:]
        if len(after) == 0 or not after[0] or after.all():
            continue
        stop = int(np.argmin(after))
        j = last + 1 + stop
        if not inb[j] or stop > max_px or comp[ys[j], xs[j]] == c:
            continue
        out[i] = (int(xs[last + 1]), int(ys[last + 1]), int(xs[j - 1]), int(ys[j - 1]))
    return out


def _judge_opening(comp: np.ndarray, find, key, run: float, ux: float, uy: float, roots, min_area: float):
    """Whether an opening (cut ``key`` = x0, y0, x1, y1 in ``comp``'s frame, ``run`` px long, along
    (ux, uy)) is a door between the pieces ``roots``: measured in the band up to ``run`` behind the
    opening on each side, the space is wider along the wall line than the opening / ``CUT_RATIO``,
    reaches ``CUT_DEPTH`` x ``run`` behind it and covers ``CUT_DEPTH`` x ``run``^2 (and ``min_area``),
    and on at least one side it reaches beyond both ends of the opening. Returns None (no door) or,
    per piece, whether it reaches beyond both ends (runs along the wall)."""
    x0, y0, x1, y1 = key
    m = int(math.ceil(run)) + 2
    r0, r1 = max(min(y0, y1) - m, 0), min(max(y0, y1) + m + 1, comp.shape[0])
    c0, c1 = max(min(x0, x1) - m, 0), min(max(x0, x1) + m + 1, comp.shape[1])
    sub = comp[r0:r1, c0:c1]
    ids = np.unique(sub)
    root_of = np.zeros(int(ids.max()) + 1, np.int64)
    root_of[ids] = [find(int(k)) if k else 0 for k in ids.tolist()]
    rsub = root_of[sub]
    mx, my = (x0 + x1) / 2.0 - c0, (y0 + y1) / 2.0 - r0
    half = run / 2.0 + (1.0 / CUT_RATIO - 1.0) / 2.0 * run
    behind_both = []
    for root in roots:
        yy, xx = np.nonzero(rsub == root)
        if len(yy) < 4:
            return None
        dx, dy = xx - mx, yy - my
        a = dx * ux + dy * uy
        b = np.abs(dy * ux - dx * uy)
        band = b <= run
        if band.sum() < max(CUT_DEPTH * run * run, min_area, 4):
            return None
        lo, hi = np.percentile(a[band], (2.0, 98.0))
        if run > CUT_RATIO * (hi - lo) or np.percentile(b[band], 98.0) < CUT_DEPTH * run:
            return None
        behind_both.append(bool(lo <= -half and hi >= half))
    # a wall runs on both sides of a door, behind it on at least one side (a corridor along the wall);
    # a corridor cut across has space beyond only one end of the cut on either side (a recess)
    return behind_both if any(behind_both) else None


SLIVERS_APART = True  # an opening that touches two spaces and slivers (pieces < CUT_MIN_ROOM_M^2 between near cuts)
# is judged between the two spaces (it was rejected unjudged, its pieces joined: a turned office's three lines)


def _split_at_wall_openings(labels: np.ndarray, space: np.ndarray, resolution: float, max_cut_m: float,
                            dist: np.ndarray, peaks: dict, grown: dict, occupied: Optional[np.ndarray] = None,
                            openings=None, jog_px: int = 0, extensions=None, rejoined: Optional[list] = None):
    """Rooms open to a corridor (or to each other) through an opening wider than a door but in a
    wall line: the wall's own line continued across the opening cuts the area in two when the
    opening is clearly narrower than the spaces on both sides measured along the line
    (``CUT_RATIO``) and both reach behind it (``CUT_DEPTH``). A side corridor is as wide as its mouth (no cut:
    corridors are not split at junctions); a wall line continued across a corridor cuts a stretch
    no longer than the corridor is wide (no cut). Openings are judged, the pieces on both sides of
    a rejected one joined, and the rest judged again. Returns (labels, number of pieces cut off);
    ``peaks`` gets the clearance peak (px, from ``dist``) of every area cut or new, ``grown`` the
    largest clearance of the slivers other areas received. Pieces cut off with no space of their own join the
    area they open onto (``PIECES_REJOIN``; the new ids stay consecutive), and ``rejoined`` gets their number."""
    import cv2

    if openings is None:
        openings = _wall_line_openings(space, labels, resolution, max_cut_m, occupied, jog_px=jog_px)
    if not openings:
        return labels, 0
    cut_id = np.zeros(labels.shape, np.int32)
    for i, (key, _, _) in enumerate(openings, start=1):
        cv2.line(cut_id, key[:2], key[2:], i, 1, lineType=8)
    n_open = len(openings)
    ext_parent = {}
    for i, e in (extensions or {}).items():  # beyond a free-standing block (``_block_extensions``): cut with
        ext_parent[n_open + 1 + i] = i + 1  # its opening, but the opening is judged by its own pieces
        cv2.line(cut_id, e[:2], e[2:], n_open + 1 + i, 1, lineType=8)
    cut = (cut_id > 0) & (labels > 0)
    groups = np.unique(labels[cut])
    next_id = int(labels.max()) + 1
    kept_cuts = 0
    min_area = (CUT_MIN_ROOM_M / resolution) ** 2
    objs = kernels.find_objects(labels)
    for g in groups.tolist():
        sl = objs[g - 1]
        if sl is None:
            continue
        mine = labels[sl] == g
        gcut = cut[sl] & mine
        n, comp = cv2.connectedComponents((mine & ~gcut).view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
        if n <= 2:
            continue
        # which pieces each opening separates (4-neighbours of its pixels)
        cid = cut_id[sl] * gcut
        pad = np.pad(comp, 1)
        rr, cc = np.nonzero(cid)
        ids = cid[rr, cc]
        nbs = np.concatenate([pad[rr + 1 + dr, cc + 1 + dc] for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1))])
        oid = np.tile(ids, 4)
        m = (nbs > 0) & (oid <= n_open)
        pair_keys = np.unique(oid[m].astype(np.int64) * (n + 1) + nbs[m])
        pairs = {}
        for o, p in zip((pair_keys // (n + 1)).tolist(), (pair_keys % (n + 1)).tolist()):
            pairs.setdefault(o, set()).add(p)
        del pad
        # size and clearance peak of every piece (both add up when pieces are joined): a piece is
        # corridor-shaped when its area is >= CORRIDOR_ELONGATION x (2 x peak)^2, as for the area types
        p_area = np.bincount(comp.ravel(), minlength=n).astype(np.float64)
        p_peak = np.zeros(n)
        np.maximum.at(p_peak, comp.ravel(), dist[sl].ravel().astype(np.float64))
        off = np.array([sl[1].start, sl[0].start, sl[1].start, sl[0].start])
        uf = _UnionFind(n)
        cands = [(o, sorted(p)) for o, p in pairs.items()]
        accepted = set()
        for _ in range(6):  # judge the openings, join across the rejected ones, judge again
            changed = False
            for o, ps in cands:
                roots = sorted({uf.find(p) for p in ps})
                if len(roots) < 2:
                    accepted.discard(o)
                    continue
                if SLIVERS_APART and len(roots) > 2:  # the slivers between near cuts are no side of the opening
                    big = [r for r in roots if p_area[r] >= min_area]
                    roots = big + [r for r in roots if p_area[r] < min_area] if len(big) == 2 else roots
                key, run, (uy, ux) = openings[o - 1]
                flags = None
                if len(roots) == 2 or (SLIVERS_APART and len(roots) > 2 and p_area[roots[2]] < min_area):
                    flags = _judge_opening(comp, uf.find, tuple((np.array(key) - off).tolist()), run, ux, uy, roots[:2],
                                           min_area)
                    if flags is None and (o - 1) in (extensions or {}):  # the free run beyond the block
                        e = np.array(extensions[o - 1]) - off
                        h, w = comp.shape
                        if e[[0, 2]].min() >= 0 and e[[0, 2]].max() < w and e[[1, 3]].min() >= 0 and e[[1, 3]].max() < h:
                            flags = _judge_opening(comp, uf.find, tuple(e.tolist()),
                                                   math.hypot(e[2] - e[0], e[3] - e[1]) + 1.0, ux, uy, roots[:2],
                                                   min_area)
                # the space entered through the door (not running along the wall on both sides of
                # it) is a room: corridors are not cut at their junctions
                room = [p_area[r] < CORRIDOR_ELONGATION * (2.0 * p_peak[r]) ** 2 for r in roots[:2]]
                good = flags is not None and any(room) and all(rm for rm, f in zip(room, flags) if not f)
                if good:
                    accepted.add(o)
                else:
                    accepted.discard(o)
                    for r in roots[1:]:
                        a, b = uf.find(r), uf.find(roots[0])
                        if a != b:
                            keep, gone = min(a, b), max(a, b)
                            uf.parent[gone] = keep
                            p_area[keep] += p_area[gone]
                            p_peak[keep] = max(p_peak[keep], p_peak[gone])
                    changed = True
            if not changed:
                break
        if not accepted:
            continue
        # the area is cut only along the openings kept
        acc_ids = list(accepted) + [e for e, o in ext_parent.items() if o in accepted]
        acc = np.isin(cid, np.fromiter(acc_ids, np.int64))
        n2, comp2, st2, _ = cv2.connectedComponentsWithStats((mine & ~acc).view(np.uint8), connectivity=4,
                                                             ltype=cv2.CV_32S)
        if n2 <= 2:
            continue
        areas2 = st2[1:, cv2.CC_STAT_AREA]
        keep = 1 + int(np.argmax(areas2))
        sub = labels[sl]
        changed_ids = [g]
        for k in range(1, n2):
            if k == keep or areas2[k - 1] < min_area:
                continue
            sub[comp2 == k] = next_id
            changed_ids.append(next_id)
            next_id += 1
            kept_cuts += 1
        # what is left of the area apart from its largest piece (slivers, the cut pixels) goes to
        # the area it touches most (as ``_single_pieces``, only here)
        gw = tuple(slice(max(x.start - 1, 0), x.stop + 1) for x in sl)
        win = labels[gw]
        nk, ck, sk, _ = cv2.connectedComponentsWithStats((win == g).view(np.uint8), connectivity=4,
                                                         ltype=cv2.CV_32S)
        if nk > 2:
            big = 1 + int(np.argmax(sk[1:, cv2.CC_STAT_AREA]))
            k3 = np.ones((3, 3), np.uint8)
            for k in range(1, nk):
                if k == big:
                    continue
                m = ck == k
                ring = cv2.dilate(m.view(np.uint8), k3).view(bool) & ~m
                neigh = win[ring]
                neigh = neigh[(neigh > 0) & (neigh != g)]
                if len(neigh):
                    vals, cnt = np.unique(neigh, return_counts=True)
                    h = int(vals[np.argmax(cnt)])
                    win[m] = h
                    grown[h] = max(grown.get(h, 0.0), float(dist[gw][m].max()))
        for lid in changed_ids:
            peaks[lid] = float(dist[sl][labels[sl] == lid].max())
        if PIECES_REJOIN:
            n_join = _rejoin_pieces_without_space(labels, gw, changed_ids, dist, MIN_RISE_M / resolution, peaks, grown)
            kept_cuts -= n_join
            next_id -= n_join
            if rejoined is not None:
                rejoined.append(n_join)
    return labels, kept_cuts


PIECES_REJOIN = True  # a piece a wall-line door cut off with no space of its own joins the area it opens onto ...
# (the merge's pass 1 for the pieces the cut made: the merge had given it to the side of the door; SIST-F4.dwg's
# lift lobby, 2 x 2 cells: the strip between the lift door and the car symbol, cut off the lobby, was an area)


def _rejoin_pieces_without_space(labels: np.ndarray, gw, changed_ids, dist: np.ndarray, min_rise: float,
                                 peaks: dict, grown: dict) -> int:
    """The merge's first rule for the pieces an accepted wall-line door cut off: a piece whose clearance peak
    rises less than ``min_rise`` (px) above the saddle (largest clearance along the shared border, as
    ``_neighbour_pairs`` measures it) to an area other than the ones cut from the same area is no space of its
    own: it joins that area (the one of the largest saddle). A room's front strip that the merge gave to the
    corridor before the door's cut is the room's again. ``gw``: the window of the cut area grown by one pixel;
    ``changed_ids[0]`` is the largest piece (kept), the others the new ones (consecutive ids); ``peaks`` and
    ``grown`` follow the pieces. The new pieces left keep consecutive ids from ``changed_ids[1]`` on. Returns
    the number of pieces joined."""
    new = changed_ids[1:]
    if not new:
        return 0
    win = labels[gw]
    dwin = np.ascontiguousarray(dist[gw], dtype=np.float32)
    cut_from = np.fromiter(changed_ids, np.int64)
    pairs = None
    kept = []
    for lid in new:
        if pairs is None:  # (again after a join: the joined piece's border is its new area's)
            pairs = _neighbour_pairs(np.ascontiguousarray(win), dwin)[:3]
        lo, hi, val = pairs
        other = np.where(lo == lid, hi, np.where(hi == lid, lo, 0))
        m = (other > 0) & ~np.isin(other, cut_from)
        if m.any():
            nb = other[m]
            hs, inv = np.unique(nb, return_inverse=True)
            saddle = np.full(len(hs), -np.inf)
            np.maximum.at(saddle, inv, val[m].astype(np.float64))
            j = int(np.argmax(saddle))  # the largest saddle, the smallest id on a tie
            if peaks[lid] - saddle[j] < min_rise:
                h = int(hs[j])
                win[win == lid] = h
                grown.pop(lid, None)  # the clearance of slivers it received is not carried over (its peak is)
                grown[h] = max(grown.get(h, 0.0), peaks.pop(lid))
                pairs = None
                continue
        kept.append(lid)
    for nid, lid in enumerate(kept, start=new[0]):  # the pieces left renumbered in order: no unused ids
        if nid != lid:
            win[win == lid] = nid
            peaks[nid] = peaks.pop(lid)
            if lid in grown:
                grown[nid] = grown.pop(lid)
    return len(new) - len(kept)


def _wall_line_doors(labels: np.ndarray, space: np.ndarray, dist: np.ndarray, resolution: float,
                     max_cut_m: float, group_peak: np.ndarray, stats: dict, occupied: Optional[np.ndarray] = None,
                     scanned: bool = False, openings=None):
    """``_split_at_wall_openings`` on the merged labels; new areas get their clearance peak.
    Returns (labels, group_peak). ``openings``: ``_wall_line_openings`` of the space, when already found
    (``_prefetch_wall_lines``)."""
    t = time.perf_counter()
    peaks: dict = {}
    grown: dict = {}
    jog = FACE_JOG_PX if scanned else 0  # CAD rasters draw exact lines: only scanned faces jog
    jamb_ops = None
    if openings is None:
        openings = _wall_line_openings(space, labels, resolution, max_cut_m, occupied, jambs=JAMB_CUTS, jog_px=jog)
    if JAMB_CUTS:
        openings, jamb_ops = openings
    ext = _block_extensions(space, ~space if occupied is None else occupied, openings, resolution,
                            max_cut_m) if scanned else None
    rejoined: list = []
    labels, n_cuts = _split_at_wall_openings(labels, space, resolution, max_cut_m, dist, peaks, grown, occupied,
                                             openings=openings, extensions=ext, rejoined=rejoined)
    stats["block_cuts"] = float(len(ext or ()))
    stats["wall_line_doors"] = float(n_cuts)
    if jamb_ops:  # after the wall lines: a jamb's cut across a corridor is judged with the rooms already apart
        jext = _block_extensions(space, ~space if occupied is None else occupied, jamb_ops, resolution,
                                 max_cut_m) if scanned else None
        labels, n_jambs = _split_at_wall_openings(labels, space, resolution, max_cut_m, dist, peaks, grown,
                                                  occupied, openings=jamb_ops, extensions=jext, rejoined=rejoined)
        stats["jamb_doors"] = float(n_jambs)
    if peaks or grown:
        top = max(list(peaks) + list(grown))
        if top >= len(group_peak):
            group_peak = np.r_[group_peak, np.zeros(top + 1 - len(group_peak))]
        for lid, v in grown.items():
            group_peak[lid] = max(group_peak[lid], v)
        for lid, v in peaks.items():
            group_peak[lid] = max(v, grown.get(lid, 0.0))
    stats["wall_line_pieces_rejoined"] = float(sum(rejoined))
    stats["wall_line_s"] = time.perf_counter() - t
    return labels, group_peak

def _prefetch_wall_lines(data: np.ndarray, space: np.ndarray, resolution: float, max_cut_m: float, scanned: bool):
    """(``_observed_walls``, ``_wall_line_openings`` as ``_wall_line_doors`` finds them, or None without
    ``WALL_CUTS``): they depend on the space only, not on the labels, so segment finds them on the second
    core beside the skeleton."""
    occupied = _observed_walls(data, space)
    if not WALL_CUTS:
        return occupied, None
    jog = FACE_JOG_PX if scanned else 0
    return occupied, _wall_line_openings(space, None, resolution, max_cut_m, occupied, jambs=JAMB_CUTS, jog_px=jog)


# --------------------------------------------------------------------------- corridor loops
CORRIDOR_LOOPS = True  # scanned maps: pieces that lead from a corridor back to it around a loop are corridor
LOOP_PIECES = 6  # ... a chain of at most this many pieces ...
LOOP_DETOUR = 1.5  # ... whose way from the corridor back to it is this x shorter than the way round in the corridor
LOOP_TRAVERSE = 1.5  # ... and every piece of which is passed along its length: its openings this x its width apart
LOOP_STEP_M = 0.2  # grid step of the way-round (geodesic) distance in the corridor
LOOP_CORE_M = END_THICK_M  # ... or the loop goes round a core thicker than a wall (a ring cut into even pieces)
LOOP_MAX_CHAINS = 5000  # chains judged per corridor at most (bounds the time on dense area graphs)


def _geodesic_from(mask: np.ndarray, start, step: int):
    """Geodesic distances (px) inside ``mask`` from ``start`` (row, col) on a grid coarsened to
    ``step`` px (a coarse cell is inside when any of its pixels is: the coarse mask stays connected,
    and a wall thinner than a step may be crossed, which only shortens a way). Returns a function
    (row, col) -> distance."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import dijkstra

    h, w = mask.shape
    hc, wc = -(-h // step), -(-w // step)
    pad = np.zeros((hc * step, wc * step), np.float32)
    pad[:h, :w] = mask
    coarse = pad.reshape(hc, step, wc, step).max(axis=(1, 3)) > 0
    idx = -np.ones((hc, wc), np.int64)
    nodes = np.flatnonzero(coarse.ravel())
    idx.ravel()[nodes] = np.arange(len(nodes))
    rows, cols, wts = [], [], []
    for dr, dc, wgt in ((0, 1, 1.0), (1, 0, 1.0), (1, 1, math.sqrt(2.0)), (1, -1, math.sqrt(2.0))):
        a = idx[0:hc - dr, max(0, -dc):wc - max(0, dc)]
        b = idx[dr:hc, max(0, dc):wc - max(0, -dc)]
        m = (a >= 0) & (b >= 0)
        rows.append(a[m])
        cols.append(b[m])
        wts.append(np.full(int(m.sum()), wgt * step))
    n = len(nodes)
    if n == 0:
        return lambda r, c: math.inf
    g = coo_matrix((np.concatenate(wts), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n)).tocsr()
    ys, xs = np.divmod(nodes, wc)

    def snap(r, c):
        d2 = (ys - r / step) ** 2 + (xs - c / step) ** 2
        k = int(np.argmin(d2))
        return k, math.sqrt(float(d2[k])) * step

    s, off = snap(*start)
    dist = dijkstra(g, directed=False, indices=s)

    def at(r, c):
        k, off2 = snap(r, c)
        return float(dist[k]) + off + off2

    return at


def _border_pieces(rr: np.ndarray, cc: np.ndarray, min_px: float):
    """Centres (row, col) of the separate pieces of a border given by its pixel pairs (pieces
    within 2 px of each other are one), largest first; pieces shorter than ``min_px`` are left out."""
    import cv2

    r0, c0 = int(rr.min()), int(cc.min())
    img = np.zeros((int(rr.max()) - r0 + 5, int(cc.max()) - c0 + 5), np.uint8)
    img[rr - r0 + 2, cc - c0 + 2] = 1
    n, lab = cv2.connectedComponents(cv2.dilate(img, np.ones((5, 5), np.uint8)), connectivity=8)
    if n <= 2:
        return [(float(rr.mean()), float(cc.mean()))]
    k = lab[rr - r0 + 2, cc - c0 + 2]
    cnt = np.bincount(k, minlength=n)
    ys = np.bincount(k, weights=rr.astype(np.float64), minlength=n)
    xs = np.bincount(k, weights=cc.astype(np.float64), minlength=n)
    return [(ys[i] / cnt[i], xs[i] / cnt[i]) for i in np.argsort(-cnt, kind="stable").tolist()
            if i > 0 and cnt[i] >= min_px]


def _encloses_core(labels: np.ndarray, c: int, path, objs, min_px: float) -> bool:
    """Whether area ``c`` and the chain ``path`` together go round something thicker than a wall that
    ``c`` alone does not enclose (free space of other areas and obstacles alike): a new hole whose
    largest inscribed disk has a radius of at least ``min_px``."""
    import cv2
    from scipy import ndimage as ndi

    sls = [objs[k - 1] for k in [c] + list(path)]
    r0, r1 = min(x[0].start for x in sls), max(x[0].stop for x in sls)
    c0, c1 = min(x[1].start for x in sls), max(x[1].stop for x in sls)
    sub = labels[r0:r1, c0:c1]
    mine = sub == c
    both = mine | np.isin(sub, np.asarray(path, sub.dtype))
    new = ndi.binary_fill_holes(both) & ~ndi.binary_fill_holes(mine) & ~both
    if not new.any():
        return False
    d = cv2.distanceTransform(np.pad(new, 1).view(np.uint8), cv2.DIST_L2, 5)
    return float(d.max()) >= min_px


def _join_corridor_loops(labels: np.ndarray, group_peak: np.ndarray, resolution: float,
                         stats: dict):
    """Corridors are not cut into pieces by clutter. On a scanned map a corridor ring (or a corridor
    running round a block) comes out in pieces where a box, a jutting corner or a junction's wide
    clearance peak narrows it. A chain of up to ``LOOP_PIECES`` areas that leaves a corridor-shaped
    area (``CORRIDOR_ELONGATION``, as the area types) and comes back to the *same* area -- or one
    area meeting it at two separate places -- is the rest of that corridor's loop when

    * the way round inside the corridor between the chain's two ends is at least ``LOOP_DETOUR`` x
      the way through the chain (opening to opening): the chain is a shortcut of the corridor's
      loop; or the corridor and the chain together go round a core thicker than a wall
      (``LOOP_CORE_M``, a new hole of that width: a ring cut into even pieces, none holding most of
      it). A room with two doors onto one corridor is neither (the way along the corridor is as
      short; only a wall lies between them), and
    * every piece is passed along its length: its two openings are at least ``LOOP_TRAVERSE`` x its
      widest disk (2 x clearance peak) apart, farther than the diagonal of a square room that wide
      (sqrt 2): a row of offices or cubicles entered one from the next is visited, not passed along.

    Borders shorter than ``MIN_PASSAGE_M`` are no openings. Returns (labels, group_peak);
    ``stats["corridor_loops_joined"]`` (pieces joined)."""
    from scipy import ndimage as ndi

    t = time.perf_counter()
    n = int(labels.max()) + 1
    joined = 0
    if n > 3:
        lo, hi, _, _, rr, cc = _neighbour_pairs(labels, None)
        lo, hi = lo.astype(np.int64), hi.astype(np.int64)
        key = lo * n + hi
        order = np.argsort(key, kind="stable")
        key, rr, cc = key[order], rr[order], cc[order]
        starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
        stops = np.r_[starts[1:], len(key)]
        min_border = max(2.0, MIN_PASSAGE_M / resolution)
        border = {}  # (a, b) -> [(y, x) centre of each separate piece of their border, largest first]
        nbrs: Dict[int, set] = {}
        for s0, s1 in zip(starts.tolist(), stops.tolist()):
            if s1 - s0 < min_border:
                continue
            a, b = divmod(int(key[s0]), n)
            pieces = _border_pieces(rr[s0:s1], cc[s0:s1], min_border)
            if not pieces:
                continue
            border[(a, b)] = border[(b, a)] = pieces
            nbrs.setdefault(a, set()).add(b)
            nbrs.setdefault(b, set()).add(a)
        area = np.bincount(labels.ravel(), minlength=n).astype(np.float64)
        pk = np.zeros(n)
        pk[:min(n, len(group_peak))] = group_peak[:n]
        pk = np.maximum(pk, 1.0)

        def corridor_shaped(a_sum, peak):
            return a_sum >= CORRIDOR_ELONGATION * (2.0 * peak) ** 2

        uf = _UnionFind(n)
        objs = ndi.find_objects(labels)
        step = max(1, int(round(LOOP_STEP_M / resolution)))
        taken = set()
        for c in sorted(range(1, n), key=lambda k: -area[k]):
            if c in taken or c not in nbrs or not corridor_shaped(area[c], pk[c]) or objs[c - 1] is None:
                continue
            ends = nbrs[c]
            geo = {}
            sl = objs[c - 1]
            found = []

            def walk(path):
                last = path[-1]
                if (len(path) >= 2 and last in ends and path[0] < last) or \
                        (len(path) == 1 and len(border[(c, last)]) >= 2):  # one piece met at two places
                    found.append(list(path))
                if len(path) >= LOOP_PIECES or len(found) >= LOOP_MAX_CHAINS:
                    return
                for nb in sorted(nbrs.get(last, ())):
                    if nb != c and nb not in path and nb not in taken:
                        walk(path + [nb])

            for first in sorted(ends):
                if first not in taken and len(found) < LOOP_MAX_CHAINS:
                    walk([first])
            found.sort(key=len)  # the shortest chains first
            before = joined
            for path in found:
                if any(p in taken for p in path):
                    continue
                pts = [border[(c, path[0])][0]] + [border[(p, q)][0] for p, q in zip(path[:-1], path[1:])]
                if len(path) == 1:  # the piece of the border farthest from the first
                    far = border[(c, path[0])][1:]
                    pts.append(far[int(np.argmax([math.hypot(y - pts[0][0], x - pts[0][1]) for y, x in far]))])
                else:
                    pts.append(border[(path[-1], c)][0])
                legs = [math.hypot(p[0] - q[0], p[1] - q[1]) for p, q in zip(pts[:-1], pts[1:])]
                if any(leg < LOOP_TRAVERSE * 2.0 * pk[x] for leg, x in zip(legs, path)):
                    continue  # a room visited (doors at most its diagonal apart), not a stretch of corridor
                through = sum(legs)
                if path[0] not in geo:  # from the largest piece of the border with the first piece
                    y0, x0 = pts[0]
                    geo[path[0]] = _geodesic_from(labels[sl] == c, (y0 - sl[0].start, x0 - sl[1].start), step)
                y1, x1 = pts[-1]
                around = geo[path[0]](y1 - sl[0].start, x1 - sl[1].start)
                if around < LOOP_DETOUR * through and not _encloses_core(labels, c, path, objs,
                                                                         LOOP_CORE_M / 2.0 / resolution):
                    continue
                for p in path:
                    uf.parent[uf.find(p)] = uf.find(c)
                    taken.add(p)
                joined += len(path)
            if joined > before:
                taken.add(c)
        if joined:
            labels, group_peak = _relabel_joined(uf, n, labels, pk)
    stats["corridor_loops_joined"] = float(joined)
    stats["corridor_loops_s"] = time.perf_counter() - t
    return labels, group_peak


# --------------------------------------------------------------------------- partition lines
PARTITION_LINES = True  # scanned maps: a wall line continued across the ends of partitions that stop on it
PARTITION_ENDS = 2  # ... at least this many partition ends along the line prove the missing wall


def _partition_chains(space: np.ndarray, wall: np.ndarray, openings, resolution: float, max_cut_m: float):
    """Wall lines continued across partition ends. From the end of each wall-line opening the line
    runs on through the obstacle it meets when that obstacle is a partition's end: along the line no
    thicker than a wall (``END_THICK_M``) and, across the line, wall running on to one side and space
    on the other (the partition comes from one side and stops on the line). Returns a list of
    (runs, ends): the free runs (x0, y0, x1, y1 px) of the line from the opening on, and the number of
    partition ends crossed."""
    rows, cols = space.shape
    tmax = int(math.ceil(END_THICK_M / resolution))
    max_px = max_cut_m / resolution
    out = []

    def inside(xi, yi):
        return 0 <= xi < cols and 0 <= yi < rows

    for key, _, (uy, ux) in openings:
        runs = [tuple(key)]
        x, y = float(key[2]), float(key[3])
        ends = 0
        for _ in range(8):
            def at(tt):
                return int(round(x + ux * tt)), int(round(y + uy * tt))
            t = 1
            xi, yi = at(t)
            if not inside(xi, yi) or not wall[yi, xi]:
                break
            while inside(xi, yi) and wall[yi, xi] and t <= tmax + 1:
                t += 1
                xi, yi = at(t)
            if not inside(xi, yi) or t > tmax + 1 or not space[yi, xi]:
                break  # thicker than a wall along the line (a block, a wall met side-on) or the map ends
            mx, my = x + ux * t / 2.0, y + uy * t / 2.0
            kinds = []
            for sgn in (-1.0, 1.0):
                pts = [(int(round(mx - uy * sgn * o)), int(round(my + ux * sgn * o))) for o in range(0, tmax + 1)]
                if not all(inside(px, py) for px, py in pts):
                    kinds.append("edge")
                elif all(wall[py, px] for px, py in pts):
                    kinds.append("wall")
                else:
                    kinds.append("space" if space[pts[-1][1], pts[-1][0]] else "other")
            if sorted(kinds) != ["space", "wall"]:
                break
            ends += 1
            s0 = t
            while inside(xi, yi) and space[yi, xi]:
                t += 1
                xi, yi = at(t)
            if not inside(xi, yi) or t - s0 > max_px:
                break
            runs.append((int(round(x + ux * s0)), int(round(y + uy * s0)), int(round(x + ux * (t - 1))),
                         int(round(y + uy * (t - 1)))))
            x, y = x + ux * (t - 1), y + uy * (t - 1)
        if ends >= PARTITION_ENDS:
            last = runs[-1]
            ext = _block_extensions(space, wall, [(last, math.hypot(last[2] - last[0], last[3] - last[1]), (uy, ux))],
                                    resolution, max_cut_m) if BLOCK_CUTS else {}
            if ext:  # the line ends on a free-standing block: it runs on beyond it (``_block_extensions``)
                runs.append(ext[0])
            out.append((runs, ends))
    return out


def _cut_partition_lines(labels: np.ndarray, space: np.ndarray, dist: np.ndarray, resolution: float,
                         max_cut_m: float, group_peak: np.ndarray, stats: dict, occupied=None):
    """Rooms open onto a corridor over their whole side. A row of rooms whose partitions all stop on
    one line, the corridor's wall continued (intel_map's two rooms west of its south-west corridor),
    has no door-sized opening: each room is as wide as its opening, so the wall-line judge keeps it
    with the corridor (a bay). Several partition ends on one line prove the missing wall: a wall
    line continued across at least ``PARTITION_ENDS`` partition ends (``_partition_chains``) cuts
    the area it crosses along all its runs; every piece cut off that is room-shaped (less than
    ``CORRIDOR_ELONGATION`` x (2 x its clearance peak)^2 and at least ``CUT_MIN_ROOM_M`` squared)
    becomes an area, the largest piece stays the area. Returns (labels, group_peak);
    ``stats["partition_line_rooms"]``."""
    import cv2

    t0 = time.perf_counter()
    wall = ~space if occupied is None else occupied
    openings = _wall_line_openings(space, labels, resolution, max_cut_m, occupied, jog_px=FACE_JOG_PX)
    chains = _partition_chains(space, wall, openings, resolution, max_cut_m) if openings else []
    new_rooms = 0
    min_area = (CUT_MIN_ROOM_M / resolution) ** 2
    next_id = int(labels.max()) + 1
    peaks = {}
    for runs, _ in chains:
        line = np.zeros(labels.shape, np.uint8)
        for r in runs:
            cv2.line(line, r[:2], r[2:], 1, 1, lineType=8)
        line = line.view(bool)
        for g in np.unique(labels[line & (labels > 0)]).tolist():
            rr, cc = np.nonzero(labels == g)
            r0, r1, c0, c1 = rr.min(), rr.max() + 1, cc.min(), cc.max() + 1
            mine = labels[r0:r1, c0:c1] == g
            n, comp, st, _ = cv2.connectedComponentsWithStats((mine & ~line[r0:r1, c0:c1]).view(np.uint8),
                                                              connectivity=4, ltype=cv2.CV_32S)
            if n <= 2:
                continue
            big = 1 + int(np.argmax(st[1:, cv2.CC_STAT_AREA]))
            sub = labels[r0:r1, c0:c1]
            for k in range(1, n):
                a = float(st[k, cv2.CC_STAT_AREA])
                if k == big or a < min_area:
                    continue
                m = comp == k
                pk = float(dist[r0:r1, c0:c1][m].max())
                if a >= CORRIDOR_ELONGATION * (2.0 * pk) ** 2:
                    continue
                sub[m] = next_id
                peaks[next_id] = pk
                next_id += 1
                new_rooms += 1
    if peaks:
        labels = _single_pieces(labels)
        top = max(peaks)
        if top >= len(group_peak):
            group_peak = np.r_[group_peak, np.zeros(top + 1 - len(group_peak))]
        for lid, v in peaks.items():
            group_peak[lid] = v
    stats["partition_line_rooms"] = float(new_rooms)
    stats["partition_line_s"] = time.perf_counter() - t0
    return labels, group_peak


# --------------------------------------------------------------------------- vector output
def label_polygons(labels: np.ndarray, grid: OccupancyGrid) -> Dict[int, object]:
    """Exact pixel-edge outline of every label (4-connected), as shapely Polygons in world metres."""
    import shapely
    from osgeo import gdal, gdal_array, ogr

    gdal.UseExceptions()
    # the label raster itself, no copy, is the band and its own mask (label 0: no area)
    arr = np.ascontiguousarray(labels, dtype=np.int32)
    ds = gdal_array.OpenArray(arr)
    ds.SetGeoTransform(grid.geotransform)
    band = ds.GetRasterBand(1)
    ods = ogr.GetDriverByName("Memory").CreateDataSource("areas")
    layer = ods.CreateLayer("areas")
    layer.CreateField(ogr.FieldDefn("id", ogr.OFTInteger))
    gdal.Polygonize(band, band, layer, 0, [])
    polys: Dict[int, object] = {}
    for feat in layer:
        lid = int(feat.GetField(0))
        geom = shapely.from_wkb(bytes(feat.GetGeometryRef().ExportToWkb()))
        if lid not in polys or geom.area > polys[lid].area:
            polys[lid] = geom
    return polys


def _passage_segments(labels: np.ndarray, grid: OccupancyGrid):
    """For each pair of touching labels, the connected pieces of their shared pixel-edge border.

    Returns a list of (a, b, (c0, r0), (c1, r1), length_px) with the two border ends in pixel-corner
    coordinates.
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    lo, hi, _, axis, rr, cc = _neighbour_pairs(labels)
    if len(lo) == 0:
        return []
    # border edge endpoints as pixel corners (col, row)
    # vertical neighbours (r,c)/(r+1,c): horizontal edge from (c, r+1) to (c+1, r+1)
    # horizontal neighbours (r,c)/(r,c+1): vertical edge from (c+1, r) to (c+1, r+1)
    c0 = np.where(axis == 0, cc, cc + 1)
    r0 = np.where(axis == 0, rr + 1, rr)
    c1 = c0 + np.where(axis == 0, 1, 0)
    r1 = r0 + np.where(axis == 0, 0, 1)
    ncols = labels.shape[1] + 1
    nmax = int(labels.max()) + 1
    pair = lo.astype(np.int64) * nmax + hi
    # nodes are (pair, corner) so that borders of different pairs never join
    k0 = pair * ((labels.shape[0] + 1) * ncols) + r0.astype(np.int64) * ncols + c0
    k1 = pair * ((labels.shape[0] + 1) * ncols) + r1.astype(np.int64) * ncols + c1
    nodes, inv = np.unique(np.concatenate([k0, k1]), return_inverse=True)
    m = len(k0)
    e0, e1 = inv[:m], inv[m:]
    g = coo_matrix((np.ones(m), (e0, e1)), shape=(len(nodes), len(nodes)))
    ncomp, comp = connected_components(g, directed=False)
    degree = np.bincount(np.concatenate([e0, e1]), minlength=len(nodes))
    node_pair = nodes // ((labels.shape[0] + 1) * ncols)
    node_rc = nodes % ((labels.shape[0] + 1) * ncols)
    node_r, node_c = node_rc // ncols, node_rc % ncols
    edge_comp = comp[e0]
    comp_len = np.bincount(edge_comp, minlength=ncomp)
    out = []
    order = np.argsort(comp, kind="stable")
    comp_sorted = comp[order]
    bounds = np.searchsorted(comp_sorted, np.arange(ncomp + 1))
    for k in range(ncomp):
        idx = order[bounds[k]:bounds[k + 1]]
        p = int(node_pair[idx[0]])
        ends = idx[degree[idx] == 1]
        if len(ends) < 2:  # closed loop (an area enclosed by another) or odd junction: farthest points
            ends = idx
        pts = np.stack([node_c[ends], node_r[ends]], axis=1).astype(np.float64)
        if len(pts) > 2:
            # farthest pair (ends are few; loops are rare and get subsampled)
            if len(pts) > 400:
                pts = pts[np.linspace(0, len(pts) - 1, 400).astype(int)]
            d2 = ((pts[:, None, :] - pts[None, :, :]) ** 2).sum(-1)
            i, j = np.unravel_index(int(np.argmax(d2)), d2.shape)
            pts = pts[[i, j]]
        a, b = p // nmax, p % nmax
        (ca, ra), (cb, rb) = pts[0], pts[1]
        # canonical direction for determinism
        if (rb, cb) < (ra, ca):
            (ca, ra), (cb, rb) = (cb, rb), (ca, ra)
        out.append((int(a), int(b), (float(ca), float(ra)), (float(cb), float(rb)), float(comp_len[k])))
    return out


def build_passages(labels: np.ndarray, grid: OccupancyGrid) -> List[Passage]:
    from shapely.geometry import LineString

    segs = _passage_segments(labels, grid)
    by_pair: Dict[Tuple[int, int], list] = {}
    for a, b, p0, p1, n in segs:
        by_pair.setdefault((a, b), []).append((p0, p1, n))
    passages: List[Passage] = []
    min_px = MIN_PASSAGE_M / grid.resolution
    for (a, b) in sorted(by_pair):
        pieces = by_pair[(a, b)]
        width_px = [math.hypot(p1[0] - p0[0], p1[1] - p0[1]) for p0, p1, _ in pieces]
        keep = [i for i, w in enumerate(width_px) if w >= min_px]
        if not keep:
            keep = [int(np.argmax(width_px))]
        for i in sorted(keep, key=lambda i: (pieces[i][0][1], pieces[i][0][0])):
            p0, p1, _ = pieces[i]
            x0, y0 = grid.pixel_to_world(p0[0], p0[1])
            x1, y1 = grid.pixel_to_world(p1[0], p1[1])
            passages.append(Passage(id=len(passages) + 1, from_id=a, to_id=b,
                                    line=LineString([(float(x0), float(y0)), (float(x1), float(y1))])))
    return passages


def hint_passages(labels: np.ndarray, grid: OccupancyGrid, door_hints, passages: List[Passage],
                  probe_m: float = 1.0) -> List[Passage]:
    """Passages for door hints that segmentation missed: for each hint (jamb-to-jamb segment), the
    first area met on each side along the normal through its middle (up to ``probe_m``); when the
    two areas differ and no passage joins them yet, a passage along the hint is added (tag
    ``cad2osmag:source=door_hint``). Returns the added passages (ids continue ``passages``)."""
    from shapely.geometry import LineString

    have = {(min(p.from_id, p.to_id), max(p.from_id, p.to_id)) for p in passages}
    next_id = max((p.id for p in passages), default=0) + 1
    rows, cols = labels.shape
    steps = np.arange(1, int(probe_m / grid.resolution) + 1) * grid.resolution
    out: List[Passage] = []
    for h in door_hints or ():
        a = np.array((h.x0, h.y0), float)
        b = np.array((h.x1, h.y1), float)
        L = float(np.hypot(*(b - a)))
        if not (np.isfinite(L) and L > 0):
            continue
        u = (b - a) / L
        nrm = np.array((-u[1], u[0]))
        mid = (a + b) / 2.0
        side = []
        for sgn in (1.0, -1.0):
            pts = mid[None, :] + sgn * steps[:, None] * nrm[None, :]
            c, r = grid.world_to_pixel(pts[:, 0], pts[:, 1])
            c, r = np.floor(c).astype(np.int64), np.floor(r).astype(np.int64)
            ok = (c >= 0) & (c < cols) & (r >= 0) & (r < rows)
            lab = labels[r[ok], c[ok]]
            lab = lab[lab > 0]
            side.append(int(lab[0]) if len(lab) else 0)
        x, y = side
        if x == 0 or y == 0 or x == y or (min(x, y), max(x, y)) in have:
            continue
        have.add((min(x, y), max(x, y)))
        out.append(Passage(id=next_id, from_id=min(x, y), to_id=max(x, y),
                           line=LineString([tuple(a), tuple(b)]), tags={"cad2osmag:source": "door_hint"}))
        next_id += 1
    return out


def assign_components(areas: List[Area], passages: List[Passage]) -> List[dict]:
    """Connected components of the area graph (areas joined by passages). Sets ``Area.component``
    (0 = the largest by area, then by decreasing area) and returns one dict per component:
    ``{"component", "ids", "names", "area_m2", "share"}``."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    if not areas:
        return []
    index = {a.id: i for i, a in enumerate(areas)}
    e = [(index[p.from_id], index[p.to_id]) for p in passages if p.from_id in index and p.to_id in index]
    n = len(areas)
    g = coo_matrix((np.ones(len(e)), ([x for x, _ in e], [y for _, y in e])), shape=(n, n))
    _, comp = connected_components(g, directed=False)
    sizes = np.bincount(comp, weights=[a.area for a in areas])
    first = np.full(len(sizes), n)
    np.minimum.at(first, comp, np.arange(n))
    order = sorted(range(len(sizes)), key=lambda k: (-sizes[k], first[k]))
    rank = {k: i for i, k in enumerate(order)}
    total = float(sizes.sum()) or 1.0
    out = []
    for k in order:
        members = [areas[i] for i in np.flatnonzero(comp == k)]
        for a in members:
            a.component = rank[k]
        out.append({"component": rank[k], "ids": [a.id for a in members], "names": [a.name for a in members if a.name],
                    "area_m2": float(sizes[k]), "share": float(sizes[k]) / total})
    return out


# Spaces the drawing really closes (issue 8, item 6): not orphaned rooms but wall cavities, ducts and shafts.
CAVITY_WIDTH = 1.0  # metres: mean width (2 * area / perimeter) under which a closed space is a cavity or duct
SHAFT_WORDS = ("shaft", "duct", "riser", "chase", "cavedio", "cavedi", "ducto", "schacht", "gaine", "井", "烟道",
               "风道", "管道间", "шахт")


def closed_spaces(areas: List[Area], passages: List[Passage], name_points=()) -> List[int]:
    """Ids of the areas the drawing closes on all sides that are no room: an area no passage touches (a
    component of its own, not the largest) that holds no room-name text except a shaft word
    (``SHAFT_WORDS``: 井, shaft, duct, cavedio...) and either is named a shaft or is too narrow for a room
    or corridor (mean width 2 * area / perimeter under ``CAVITY_WIDTH``: the inside of a wall drawn as two
    lines, a duct). ``name_points``: (x, y, text) of the drawing's room names and numbers. They stay areas
    and components of their own; the connectivity figure counts them out."""
    from shapely.geometry import Point

    touched = {i for p in passages for i in (p.from_id, p.to_id)}
    pts = [(Point(x, y), str(t).lower()) for x, y, t in name_points]
    out = []
    for a in areas:
        if a.id in touched or a.component == 0 or a.polygon is None or a.polygon.is_empty or a.type == "structure":
            continue
        inside = [t for pt, t in pts if a.polygon.intersects(pt)]
        shaft = [t for t in inside if any(w in t for w in SHAFT_WORDS)]
        if len(shaft) != len(inside):
            continue  # a room name: an orphaned room, never counted out
        narrow = 2.0 * a.polygon.area / max(a.polygon.length, 1e-9) < CAVITY_WIDTH
        if shaft or narrow:
            out.append(a.id)
    return sorted(out)


# Roofs of lower parts drawn on an upper floor's plan (issue 8, item 6): the plan of a 5th floor shows the roof of
# the 4-storey block beside it, labelled as a roof and with its drainage falls; no door of the floor leads there.
ROOF_WORDS = ("屋面", "屋顶", "roof", "tetto", "tetti", "copertura", "cubierta", "azotea", "toiture", "flachdach",
              "dachfläche", "кровл")  # Latin and Cyrillic words match at a word start ('architetto' is no roof)
ROOF_SLOPES = 3  # drainage falls ('2%', 'i=1%') marked in one area that make it a roof (a ramp carries one or two)
ROOF_SHARE = 0.5  # a component whose roof areas hold this share of its area is a roof with its rooftop structures
_SLOPE_RE = None
_ROOF_RE = None


def _is_slope(text: str) -> bool:
    global _SLOPE_RE
    if _SLOPE_RE is None:
        import re

        _SLOPE_RE = re.compile(r"^\s*(i\s*=\s*)?\d{1,2}(\.\d+)?\s*[%‰]\s*$", re.IGNORECASE)
    return bool(_SLOPE_RE.match(text))


def _is_roof_word(text: str) -> bool:
    """A roof word in ``text`` (lower case): CJK words anywhere, the others at the start of a word."""
    global _ROOF_RE
    if _ROOF_RE is None:
        import re

        cjk = [w for w in ROOF_WORDS if not w.isascii() and not any("а" <= ch <= "я" for ch in w)]
        other = [w for w in ROOF_WORDS if w not in cjk]
        _ROOF_RE = re.compile("|".join([re.escape(w) for w in cjk] + [r"(?<!\w)" + re.escape(w) for w in other]))
    return bool(_ROOF_RE.search(text))


def roof_spaces(areas: List[Area], passages: List[Passage], texts=(), closed_ids=()) -> List[int]:
    """Ids of the areas of orphaned components that are roofs of lower parts of the building, drawn on this
    floor's plan: outside the largest component, no passage from it reaches the largest component, and
    roof areas -- holding a roof word (``ROOF_WORDS``: 屋面, roof, tetto, cubierta, toiture...) or at least
    ``ROOF_SLOPES`` drainage falls ('2%', 'i=1%') -- hold at least ``ROOF_SHARE`` of the component's area
    (the rest are rooftop structures reached across the roof: stair heads, lift machine rooms). ``texts``:
    the drawing's texts (``CadText`` or (x, y, text)). They stay areas; the connectivity figure counts
    them out like closed spaces, since a roof is no floor space. An orphaned room, even next to a roof,
    is never counted out: its component must be mostly roof."""
    from shapely import STRtree
    from shapely.geometry import Point

    closed = set(closed_ids)
    cand = [a for a in areas if a.component != 0 and a.id not in closed and a.polygon is not None
            and not a.polygon.is_empty and a.type != "structure"]
    if not cand:
        return []
    pts, words = [], []
    for t in texts or ():
        x, y, s = (t.x, t.y, t.text) if hasattr(t, "text") else t
        low = str(s).strip().lower()
        roof, slope = _is_roof_word(low), _is_slope(low)
        if (roof or slope) and np.isfinite(x) and np.isfinite(y):
            pts.append(Point(float(x), float(y)))
            words.append(roof)
    if not pts:
        return []
    tree = STRtree(pts)
    roof_area: Dict[int, float] = {}
    total: Dict[int, float] = {}
    members: Dict[int, List[int]] = {}
    for a in cand:
        hits = tree.query(a.polygon, predicate="intersects")
        is_roof = any(words[i] for i in hits) or sum(1 for i in hits if not words[i]) >= ROOF_SLOPES
        total[a.component] = total.get(a.component, 0.0) + a.area
        members.setdefault(a.component, []).append(a.id)
        if is_roof:
            roof_area[a.component] = roof_area.get(a.component, 0.0) + a.area
    out = []
    for c, r in roof_area.items():
        if r >= ROOF_SHARE * total[c]:
            out.extend(members[c])
    return sorted(out)


# Exterior ground closed by the drawing (issue 8, item 6): terraces and landscape outside the facade, cut into
# pieces by planters, low walls and paving edges drawn on kept layers. They hold no room name (at most the codes
# of the windows drawn outside the facade, a note), no door of the floor leads there, and they lie outside the
# building: beyond the outline of the floor's main (largest) component. A doorless room inside the facade is
# inside that outline and stays an orphan; a named space is never exterior.
OUTDOOR_SHARE = 0.5  # share of an orphaned component's area outside the main component's outline that makes it exterior
OUTDOOR_NAMES = 3  # room names the main component must hold: only a drawing that names its rooms says by silence
# that a space is none (a cleaned file with no names keeps its unnamed wings as orphans, never exterior)


def outdoor_spaces(areas: List[Area], passages: List[Passage], name_points=(), closed_ids=()) -> List[int]:
    """Ids of the areas of orphaned components that are exterior ground (terraces, landscape between planters)
    rather than floor: a component other than the largest (no passage reaches it from the main one), none of
    whose areas holds a room name or number (``name_points``: (x, y, text) of the names, see
    ``semantics.room_names_only``) and at least ``OUTDOOR_SHARE`` of whose area lies outside the outline of
    the main component (the convex hull of its areas: the facade and the space the building's wings enclose
    count as inside). Only on a drawing that names its rooms: the main component holds at least
    ``OUTDOOR_NAMES`` of the names (on a drawing without names, an unnamed wing is no evidence of anything
    and stays an orphan). ``closed_ids``: areas already counted out (closed spaces, roofs), never listed again.
    They stay areas; the connectivity figure counts them out."""
    from shapely import STRtree
    from shapely.geometry import Point
    from shapely.ops import unary_union

    closed = set(closed_ids)
    main = [a.polygon for a in areas if a.component == 0 and a.polygon is not None and not a.polygon.is_empty
            and a.type != "structure"]
    cand = [a for a in areas if a.component != 0 and a.id not in closed and a.polygon is not None
            and not a.polygon.is_empty and a.type != "structure"]
    if not main or not cand:
        return []
    hull = unary_union([p.convex_hull for p in main]).convex_hull
    pts = [Point(float(x), float(y)) for x, y, _t in name_points if np.isfinite(x) and np.isfinite(y)]
    tree = STRtree(pts) if pts else None
    if tree is None:
        return []
    in_main = set()
    for p in main:
        in_main.update(int(i) for i in tree.query(p, predicate="intersects"))
    if len(in_main) < OUTDOOR_NAMES:
        return []
    total: Dict[int, float] = {}
    outside: Dict[int, float] = {}
    named = set()
    members: Dict[int, List[int]] = {}
    for a in cand:
        c = a.component
        members.setdefault(c, []).append(a.id)
        total[c] = total.get(c, 0.0) + a.polygon.area
        if len(tree.query(a.polygon, predicate="intersects")):
            named.add(c)
        try:
            out_area = a.polygon.difference(hull).area
        except Exception:  # a GEOS topology error on a degenerate piece: measure on the repaired polygon
            from shapely.validation import make_valid

            out_area = make_valid(a.polygon).buffer(0).difference(hull).area
        outside[c] = outside.get(c, 0.0) + out_area
    out = []
    for c, ids in members.items():
        if c not in named and total[c] > 0 and outside[c] >= OUTDOOR_SHARE * total[c]:
            out.extend(ids)
    return sorted(out)


OPEN_FRONT = 1.5 * DEFAULT_ENVELOPE_GAP  # metres: one stretch of outline open to the outside wider than any
# facade opening the envelope closes at its chord (narrower than the gap; a corner of a facade whose windows
# are not drawn, office.dxf's stairwell: 4.1 m), so space that was claimed open, not a room behind a window
OPEN_RING_PX = 4  # pixels: how far beyond an area's outline the ring looks for the outside (through free pixels)
OPEN_SLIVER_PX = 3  # pixels: free slivers this thin between a simplified outline and the walls are the area's


def _grow_into_slivers(lab: np.ndarray, passable: np.ndarray, rounds: int) -> np.ndarray:
    """``lab`` (area ids, 0 for none) grown ``rounds`` times into the passable pixels of no area, each such
    pixel taking the largest id among its 8 neighbours of the previous round (synchronous rounds): the free
    slivers between a simplified outline and its walls belong to the area (``open_ground_spaces``). On 16
    bits when the ids fit (cv2's max filter; float32 before, 1.6x slower, same ids), float32 otherwise."""
    import cv2

    k3 = np.ones((3, 3), np.uint8)
    top = int(lab.max(initial=0))
    out = lab.astype(np.uint16 if top < 65536 else np.float32)  # float32 is exact for ids below 2**24
    for _ in range(rounds):
        grow = passable & (out == 0)
        np.copyto(out, cv2.dilate(out, k3), where=grow)
    return out


def open_ground_spaces(areas: List[Area], passages: List[Passage], grid: OccupancyGrid, name_points=(),
                       closed_ids=(), door_hints=(), min_front: float = OPEN_FRONT,
                       info: Optional[dict] = None) -> List[int]:
    """Ids of the areas of orphaned components that are ground open to the outside: a covered porch between
    pillars and a roof edge, a yard under an overhang, a strip outside the facade between two exterior steps.
    A component other than the largest (no passage reaches it from the main one), none of whose areas holds
    a room name or number (``name_points``: (x, y, text)) or was named from a text nearby (tag
    ``label_texts``), that no door hint touches, and whose outline meets
    the outside directly -- free space that belongs to no area and reaches the raster border, with no wall
    or line in between -- along one stretch of at least ``min_front`` metres (1.5 x the envelope gap: the
    envelope closes every facade opening narrower than its gap at the chord, so a room whose door, window
    or facade corner was left out meets the outside over such chords only, each under 4 m). Such space was
    claimed open (footprint, roof-edge lines) and is reached from the outside only: the drawing itself says
    it is no room of the floor, whether or not the drawing names its rooms (``outdoor_spaces`` needs names).
    A named space is never counted out.
    ``closed_ids``: areas already counted out, never listed again. They stay areas. ``info`` (a dict) gets
    ``fronts``: {component: metres of its longest stretch open to the outside} of the components measured."""
    import cv2
    from scipy import ndimage
    from shapely import STRtree
    from shapely.geometry import LineString, Point

    from .model import OCCUPIED
    from .rasterize import ring_px

    closed = set(closed_ids)
    usable = [a for a in areas if a.polygon is not None and not a.polygon.is_empty and a.type != "structure"]
    cand = [a for a in usable if a.component != 0 and a.id not in closed]
    if not cand or grid is None:
        return []
    members: Dict[int, List[Area]] = {}
    for a in cand:
        members.setdefault(a.component, []).append(a)
    pts = [Point(float(x), float(y)) for x, y, _t in name_points if np.isfinite(x) and np.isfinite(y)]
    tree = STRtree(pts) if pts else None
    hint_lines = [LineString([(h.x0, h.y0), (h.x1, h.y1)]) for h in door_hints or ()
                  if np.isfinite([h.x0, h.y0, h.x1, h.y1]).all() and (h.x0, h.y0) != (h.x1, h.y1)]
    htree = STRtree(hint_lines) if hint_lines else None
    keep: Dict[int, List[Area]] = {}
    for c, lst in members.items():
        if any(a.tags.get("label_texts") for a in lst) or (
                tree is not None and any(len(tree.query(a.polygon, predicate="intersects")) for a in lst)):
            continue  # a name or number (or one the names stage gave it): a room, orphaned or not, is never counted out
        if htree is not None and any(len(htree.query(a.polygon.buffer(0.3), predicate="intersects")) for a in lst):
            continue  # a doorway drawn at it: part of the building whose passage was missed, an orphan
        keep[c] = lst
    if not keep:
        return []
    lab = np.zeros(grid.shape, np.int32)
    # every area's exterior filled (sub-pixel, as rasterize.repaint_polygon), the first area in order winning a
    # pixel two fills cover: painted straight into the raster from the last one to the first
    for a in reversed(usable):
        for part in reversed(list(getattr(a.polygon, "geoms", [a.polygon]))):
            if part.geom_type == "Polygon" and not part.is_empty:
                cv2.fillPoly(lab, [ring_px(part.exterior, grid)], int(a.id), shift=3)
    passable = grid.data != OCCUPIED
    cross = cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3))  # 4-connected steps: a ring OPEN_RING_PX deep
    # the pixels the areas hold once grown into their slivers (_grow_into_slivers, whose ids are needed near the
    # measured components only): a pixel is reached in as many 8-neighbour rounds through passable pixels
    held = (lab > 0).view(np.uint8)
    k3 = np.ones((3, 3), np.uint8)
    pass8 = passable.view(np.uint8)
    for _ in range(OPEN_SLIVER_PX):
        held = held | (cv2.dilate(held, k3) & pass8)
    free0 = pass8 & (held ^ 1)
    n, outside = cv2.connectedComponents(free0, connectivity=4, ltype=cv2.CV_32S)
    border = np.unique(np.concatenate([outside[0], outside[-1], outside[:, 0], outside[:, -1]]))
    border = border[border > 0]
    if not len(border):
        return []
    is_out = np.zeros(n, bool)
    is_out[border] = True
    res = float(grid.resolution)
    rows, cols = grid.shape
    out = []
    for c, lst in keep.items():
        ids = np.array([a.id for a in lst])
        x0, y0, x1, y1 = np.array([a.polygon.bounds for a in lst]).T
        (ca, cb), (ra, rb) = grid.world_to_pixel(np.array([x0.min(), x1.max()]), np.array([y1.max(), y0.min()]))
        m = OPEN_RING_PX + 2
        c0, c1 = max(int(ca) - m, 0), min(int(cb) + m + 1, cols)
        r0, r1 = max(int(ra) - m, 0), min(int(rb) + m + 1, rows)
        if c1 <= c0 or r1 <= r0:
            continue
        # the grown ids in the window: grown on it widened by the rounds (a pixel's id comes from at most that far)
        g = OPEN_SLIVER_PX
        gr0, gc0 = max(r0 - g, 0), max(c0 - g, 0)
        sub = _grow_into_slivers(lab[gr0:min(r1 + g, rows), gc0:min(c1 + g, cols)],
                                 passable[gr0:min(r1 + g, rows), gc0:min(c1 + g, cols)], g)
        mine = np.isin(sub[r0 - gr0:r1 - gr0, c0 - gc0:c1 - gc0], ids).view(np.uint8)
        pw = passable[r0:r1, c0:c1].view(np.uint8)
        grown = mine
        for _ in range(OPEN_RING_PX):  # the ring beyond the outline, through free pixels only (never a wall)
            grown = cv2.dilate(grown, cross) & (grown | pw)
        ring = grown.astype(bool) & ~mine.astype(bool)
        contact = ring & is_out[outside[r0:r1, c0:c1]]
        # the ring is OPEN_RING_PX deep where the outline meets the outside: a run's pixels / depth ~ its length,
        # less the ring's and the slivers' spread around each end of it
        runs, nr = ndimage.label(contact, structure=np.ones((3, 3), bool))
        front = 0.0
        if nr:
            px = np.bincount(runs[contact], minlength=nr + 1)[1:]
            front = max(0.0, float(px.max()) * res / OPEN_RING_PX - 2.0 * (OPEN_RING_PX + OPEN_SLIVER_PX) * res)
        if info is not None:
            info.setdefault("fronts", {})[int(c)] = front
        if front >= min_front:
            out.extend(int(i) for i in ids)
    return sorted(out)


def connected_share(areas: List[Area], closed_ids=()) -> float:
    """The largest component's share of the floor area, counting out ``closed_ids`` (``closed_spaces``)."""
    closed = set(closed_ids)
    sizes: Dict[int, float] = {}
    for a in areas:
        if a.id not in closed and a.type != "structure":
            sizes[a.component] = sizes.get(a.component, 0.0) + a.area
    total = sum(sizes.values())
    return max(sizes.values()) / total if total else 1.0


def report_components(components: List[dict], progress, stage: str = "segmentation") -> None:
    """Log the components of the area graph: every one but the largest, with ids, names and size."""
    if len(components) <= 1:
        if components:
            progress.info(f"{stage}: the area graph is connected (one component)")
        return
    progress.warning(f"{stage}: the area graph has {len(components)} connected components; the largest holds "
                     f"{components[0]['share']:.1%} of the area. The others (field 'component' of the areas) "
                     "are rooms no passage reaches: closed shafts or ducts, or doorways the drawing closes")
    for c in components[1:]:
        ids = ", ".join(str(i) for i in c["ids"][:12]) + (" ..." if len(c["ids"]) > 12 else "")
        names = f" ({', '.join(c['names'][:5])})" if c["names"] else ""
        progress.info(f"  component {c['component']}: areas {ids}{names}, {c['area_m2']:.1f} m2")


def room_name_points(texts, rules=None) -> np.ndarray:
    """(x, y) metres of the texts that name or number a room, as an (n, 2) array: the classification of
    stage 5 (``semantics.classify_text``: dimensions, elevations, codes, titles... are not names)."""
    from .semantics import room_name_points as named

    pts = [(x, y) for x, y, _ in named(texts, rules)]
    return np.asarray(pts, dtype=np.float64).reshape(-1, 2)


# --------------------------------------------------------------------------- topology on coarser cells
def _topology_default(default: float = 0.088) -> float:
    """``CAD2OSMAG_TOPOLOGY_CELL`` from the environment (metres, >= 0), else ``default``."""
    try:
        v = float(os.environ.get("CAD2OSMAG_TOPOLOGY_CELL", default))
    except ValueError:
        return default
    return v if math.isfinite(v) and v >= 0 else default


TOPOLOGY_RESOLUTION = _topology_default()  # metres (0.088 = 2 x 0.044): the skeleton, regions and merges work on
# cells of about this size (a whole multiple of the raster's cells, which then only trace the outlines and passages);
# 0 = all on the raster's own cells (the output before session 10). CAD2OSMAG_TOPOLOGY_CELL overrides it.


def topology_scale(resolution: float, door_width: float = DEFAULT_DOOR_WIDTH,
                   corridor_width: float = DEFAULT_CORRIDOR_WIDTH, delta: float = DEFAULT_DELTA,
                   cell: Optional[float] = None) -> int:
    """How many raster cells (per side) one cell of the segmentation's topology steps covers: ``cell``
    (default ``TOPOLOGY_RESOLUTION``, metres) / ``resolution`` rounded down; 1 when that is finer than the
    raster, when ``cell`` is 0, or when coarser cells are too coarse for the openings (alpha < 2 px^2)."""
    cell = TOPOLOGY_RESOLUTION if cell is None else float(cell)
    if not (np.isfinite(cell) and cell > 0 and resolution > 0):
        return 1
    k = int(math.floor(cell / resolution + 1e-6))
    while k > 1 and compute_alpha(door_width, corridor_width, delta, resolution * k) < 2:
        k -= 1
    return max(k, 1)


def _pool_max(img: np.ndarray, k: int) -> np.ndarray:
    """The largest value of every k x k cell of ``img`` (bool or uint8); the last row / column of cells may
    hang over the raster: they see its edge pixels repeated."""
    rows, cols = img.shape
    R, C = -(-rows // k), -(-cols // k)
    if (R * k, C * k) != (rows, cols):
        img = np.pad(img, ((0, R * k - rows), (0, C * k - cols)), mode="edge")
    out = img[0::k, 0::k].copy()
    for i in range(k):
        for j in range(k):
            if i or j:
                np.maximum(out, img[i::k, j::k], out=out)
    return out


_CODES = np.full(256, OCCUPIED, np.uint8)  # every value but free and unknown is occupied
_CODES[FREE] = FREE
_CODES[UNKNOWN] = UNKNOWN


def coarsen_grid(grid: OccupancyGrid, k: int, opened: Optional[np.ndarray] = None) -> OccupancyGrid:
    """``grid`` on cells of k x k pixels (same top-left corner): a cell is occupied when any of its pixels is,
    else unknown when any is, else free; the pixels of ``opened`` (door openings) count as free. Walls never
    open on the coarser cells (a wall one pixel thick stays closed); the free space shrinks by less than a
    cell at each wall face."""
    codes = _CODES[np.asarray(grid.data, dtype=np.uint8)]
    if opened is not None:
        codes[opened] = FREE
    return OccupancyGrid(_pool_max(codes, k), grid.origin_x, grid.origin_y, grid.resolution * k, grid.crs_wkt)


def _upsample(coarse_labels: np.ndarray, k: int, rows: int, cols: int) -> np.ndarray:
    """Every cell's label on its k x k pixels, (rows, cols) int32, written in place (the last row and column of
    cells may be cut by the raster's edge: no k x k copy cropped afterwards, ~55 MB on a SIST floor)."""
    out = np.empty((rows, cols), np.int32)
    rf, cf = rows // k, cols // k
    it = out.itemsize
    whole = np.lib.stride_tricks.as_strided(out, shape=(rf, k, cf, k), strides=(k * cols * it, cols * it, k * it, it))
    whole[...] = coarse_labels[:rf, None, :cf, None].astype(np.int32, copy=False)
    if cf * k < cols:  # the cut column of cells
        out[:rf * k, cf * k:] = np.repeat(coarse_labels[:rf, cf], k)[:, None]
    if rf * k < rows:  # the cut row of cells
        out[rf * k:, :] = np.repeat(coarse_labels[rf, :], k)[None, :cols]
    return out


def refine_labels(coarse_labels: np.ndarray, coarse: OccupancyGrid, grid: OccupancyGrid, k: int,
                  opened: Optional[np.ndarray] = None) -> np.ndarray:
    """The area labels of ``coarse`` (``grid`` on k x k cells, :func:`coarsen_grid`) on the pixels of
    ``grid``: every pixel of a labelled cell (all free) takes its label, and the free pixels of the cells at
    wall faces (cells holding an occupied or unknown pixel) take the label of a 4-neighbour, growing k pixels
    from the labelled cells (the largest label on a tie). Free pixels of free cells the segmentation left
    outside every area stay outside."""
    rows, cols = grid.shape
    C = coarse_labels.shape[1]
    labels = _upsample(coarse_labels, k, rows, cols)
    # the pixels of the cells at wall faces (cells not free) that are free themselves
    cells = np.flatnonzero(np.asarray(coarse.data).ravel() != FREE)
    cr, cc = np.divmod(cells, C)
    fr = (cr[:, None] * k + np.arange(k)[None, :]).repeat(k, axis=1).ravel()
    fc = np.tile(cc[:, None] * k + np.arange(k)[None, :], (1, k)).ravel()
    inside = (fr < rows) & (fc < cols)
    todo = fr[inside] * cols + fc[inside]
    free = np.asarray(grid.data).ravel()[todo] == FREE
    if opened is not None:
        free |= opened.ravel()[todo]
    todo = todo[free]
    flat = labels.ravel()
    todo = todo[flat[todo] == 0]
    r, c = np.divmod(todo, cols)
    for _ in range(k):
        if not len(todo):
            break
        best = np.zeros(len(todo), flat.dtype)
        for ok, step in ((r > 0, -cols), (r < rows - 1, cols), (c > 0, -1), (c < cols - 1, 1)):
            np.maximum(best, np.where(ok, flat[np.where(ok, todo + step, todo)], 0), out=best)
        got = best > 0
        flat[todo[got]] = best[got]
        todo, r, c = todo[~got], r[~got], c[~got]
    return labels


def segment(grid: OccupancyGrid, door_width: float = DEFAULT_DOOR_WIDTH,
            corridor_width: float = DEFAULT_CORRIDOR_WIDTH, delta: float = DEFAULT_DELTA,
            prune: float = DEFAULT_PRUNE, progress: Optional[Progress] = None,
            envelope_gap: float = DEFAULT_ENVELOPE_GAP, inside_points=None, door_hints=None,
            footprint: bool = False, boundary: Optional[np.ndarray] = None,
            topology_resolution: Optional[float] = None) -> AreaGraph:
    """Segment the free space of ``grid`` into an Area Graph.

    Returns an ``AreaGraph`` whose areas carry exact pixel-edge polygons (world metres), whose
    passages are 2-point lines across the openings between touching areas, ``labels`` (int32
    raster of area ids on the grid, 0 outside areas), ``skeleton`` (the pruned skeleton graph,
    ``skeleton.SkeletonGraph``, on the grid) and ``stats`` (per-step seconds, alpha, interior
    area, skeleton_nodes / _edges / _junctions / _dead_ends / _pruned, regions...). Raises
    ``InputError`` for unusable input.

    ``inside_points``: (x, y) world metres of room-name texts, evidence that the space holding each
    is inside the building whatever its facade (``building_interior``). ``footprint``: the plan's
    footprint is evidence too (``FOOTPRINT_FACTOR``; for CAD plans, whose outline is drawn: on a
    robot map the free space beside the rooms is where the scan ended, not a porch). ``door_hints``
    (``model.DoorHint``): doorways found in the drawing; their openings are kept free and they
    become passages where the areas on both sides are not joined otherwise (``hint_passages``).
    Every area gets its ``component`` in the area graph (0 = the largest); ``stats`` has
    ``components`` and ``largest_component_share``, and the other components are logged.
    ``boundary`` (bool mask on the grid, ``rasterize.boundary_mask``): projection / dash-dot lines, boundary
    evidence where they close a space (``supported_boundary``), never walls.
    """
    progress = ensure(progress)
    t_all = time.perf_counter()
    stats: Dict[str, float] = {}
    data, alpha = _check_inputs(grid, door_width, corridor_width, delta, prune)
    from . import kernels

    progress.info(kernels.describe())
    opened = None
    if door_hints:
        from .rasterize import door_opening_mask

        opened = (door_opening_mask(door_hints, data.shape, grid.origin_x, grid.origin_y, grid.resolution)
                  & (data != FREE) & (data != UNKNOWN))
    k = topology_scale(grid.resolution, door_width, corridor_width, delta, cell=topology_resolution)
    work = grid
    if k > 1:
        t = time.perf_counter()
        work = coarsen_grid(grid, k, opened)
        stats["coarsen_s"] = time.perf_counter() - t
        if boundary is not None:
            boundary = _pool_max(boundary, k)  # true where any pixel of the cell is
    stats.update(pixels=float(data.size), topology_scale=float(k))
    # the raster's checks hold for its own cells; coarser cells are checked again (the probe disk against the map)
    checked = (data, alpha) if k == 1 else _check_inputs(work, door_width, corridor_width, delta, prune)
    labels, group_peak, skel = _segment_labels(work, checked, door_width, delta, prune, progress, envelope_gap,
                                               inside_points, opened if k == 1 else None, footprint, boundary,
                                               stats)
    if k > 1:
        t = time.perf_counter()
        labels = refine_labels(labels, work, grid, k, opened)
        stats["fine_labels_s"] = time.perf_counter() - t
    return _area_graph(labels, group_peak, grid, door_hints, skel, work, stats, progress, t_all)


def _segment_labels(grid: OccupancyGrid, checked: Tuple[np.ndarray, int], door_width: float, delta: float,
                    prune: float, progress: Progress, envelope_gap: float, inside_points,
                    opened: Optional[np.ndarray], footprint: bool, boundary: Optional[np.ndarray],
                    stats: Dict[str, float]):
    """The area labels of ``grid`` (steps interior .. merge of :func:`segment`): (labels, clearance peak of
    every label in pixels, skeleton graph). ``checked``: ``_check_inputs`` of ``grid`` (its data and alpha);
    ``opened``: occupied pixels the door hints open."""
    data, alpha = checked
    res = float(grid.resolution)
    r_alpha = math.sqrt(alpha)
    stats.update(alpha_px2=float(alpha), alpha_radius_m=r_alpha * res, resolution=res)
    progress.step(2, f"alpha = {alpha} px^2 (probe disk radius {r_alpha * res:.2f} m at {res:g} m/px)")

    t = time.perf_counter()
    free = data == FREE
    if opened is not None:
        free = free | opened
    pix_pts = None
    if inside_points is not None and len(inside_points):
        xy = np.asarray(inside_points, dtype=np.float64).reshape(-1, 2)
        pix_pts = np.stack(grid.world_to_pixel(xy[:, 0], xy[:, 1]), axis=1)
    # unknown cells are not passable for the envelope disk either: some maps draw walls in grey
    info: dict = {}
    if boundary is not None:
        binfo: dict = {}
        progress.check()
        boundary = supported_boundary(free, boundary, res, envelope_gap, pix_pts, binfo)
        info["_free_dist"] = binfo.pop("_free_dist", None)  # the envelope transform, reused when no line is kept
        stats["boundary_px"] = float(boundary.sum()) if boundary is not None else 0.0
    interior, envelope = building_interior(free, res, envelope_gap, inside_points=pix_pts, info=info,
                                           footprint=footprint, progress=progress, boundary=boundary)
    if boundary is not None:  # space closed by projection lines is claimed: never an exterior pocket
        info["claimed"] = binfo["space"] | boundary | info.get("claimed", np.zeros_like(free))
    del envelope
    stats["claimed_open_m2"] = info.get("claimed_px", 0) * res * res
    stats["inside_points"] = float(info.get("inside_points", 0))
    stats["inside_points_outside"] = float(info.get("inside_points_outside", 0))
    stats["inside_points_between_facades"] = float(info.get("inside_points_between_facades", 0))
    if info.get("inside_points_between_facades"):
        progress.info(f"{info['inside_points_between_facades']} room name(s) between two facades open at both ends "
                      "(a passage between buildings): kept inside up to the chords of the two mouths")
    if info.get("named_bays_m2"):
        stats["named_bays_m2"] = float(info["named_bays_m2"])
        progress.info(f"named space(s) open to the outside through a mouth (a gallery, court or bay): "
                      f"{stats['named_bays_m2']:.1f} m2 kept inside up to the mouth")
    if info.get("claimed_px"):
        progress.info(f"space open to the outside kept inside on evidence (footprint, doorways, "
                      f"{info.get('inside_points_claimed', 0)} room names): {stats['claimed_open_m2']:.1f} m2")
    if info.get("inside_points_outside"):
        progress.warning(f"{info['inside_points_outside']} of {info['inside_points']} room-name points lie in space "
                         "open to the outside at every footprint scale (no wall closes it); they are not areas")
    stats["interior_s"] = time.perf_counter() - t
    stats["free_area_m2"] = float(free.sum()) * res * res
    stats["interior_area_m2"] = float(interior.sum()) * res * res
    if not interior.any():
        raise InputError("no enclosed free space: every free cell is connected to the outside of the map "
                         f"through openings wider than {envelope_gap:g} m (is the plan closed by walls?)")
    progress.step(10, f"building interior: {stats['interior_area_m2']:.1f} m2 of free space "
                      f"(of {stats['free_area_m2']:.1f} m2 free in the raster)")

    t = time.perf_counter()
    space = _without_specks(interior, res) if SPECK_M2 > 0 else interior
    dist = _edt_split(space)  # (on both cores; the same values)
    progress.check()
    pockets = _narrow_pockets(space, dist, res)
    if pockets is not None:
        stats["narrow_pockets_m2"] = float(pockets.sum()) * res * res
        space = space & ~pockets
        interior = interior & ~pockets
        dist[pockets] = 0
    # the clearance basins, the observed walls and the openings in wall lines depend on the space and its
    # clearance only: the second core computes them while this one thins the skeleton
    basins = _Background(lambda: _cells(space, dist))
    scanned = bool((data == UNKNOWN).any())
    max_cut_m = max(door_width + delta, envelope_gap)
    wall_lines = _Background(lambda: _prefetch_wall_lines(data, space, res, max_cut_m, scanned))
    skel = skeleton_graph(space, res, prune=prune, dist=dist, progress=progress)
    stats["skeleton_s"] = time.perf_counter() - t
    stats.update(skeleton_nodes=float(skel.n_nodes), skeleton_edges=float(skel.n_edges),
                 skeleton_junctions=float(skel.junctions), skeleton_dead_ends=float(skel.dead_ends),
                 skeleton_pruned=float(skel.pruned))
    progress.step(30, f"skeleton: {skel.n_nodes} nodes ({skel.junctions} junctions, {skel.dead_ends} dead ends), "
                      f"{skel.n_edges} edges, {skel.pruned} branches shorter than {prune:g} m pruned")

    t = time.perf_counter()
    cells, peak, n_basins = _edge_regions(skel, space, dist, progress=progress, cells=basins.result())
    del basins
    if space is not interior:
        cells[~interior] = 0
    stats["regions_s"] = time.perf_counter() - t
    stats["basins"] = float(n_basins)
    stats["regions"] = float(len(peak) - 1)
    progress.step(40, f"skeleton edge regions: {len(peak) - 1} (in {n_basins} clearance basins)")

    t = time.perf_counter()
    lo, hi, saddle, border = _cell_graph(cells, dist)
    stats["graph_s"] = time.perf_counter() - t
    progress.step(50, f"region graph: {len(lo)} adjacencies")

    t = time.perf_counter()
    # clearances in px measured from pixel centres: a pixel touching a wall has distance 1
    cell_area = np.bincount(cells.ravel(), minlength=len(peak)).astype(np.float64)
    cell_area[0] = 0
    rep = _merge_cells(len(peak), peak - 0.5, lo, hi, saddle - 0.5, r_alpha=r_alpha, cell_area=cell_area,
                       corridor_opening=MIN_CORRIDOR_OPENING_M / res,
                       door_half=(door_width + delta) / 2.0 / res, min_rise=MIN_RISE_M / res)
    # renumber groups deterministically: representatives are the smallest cell id of their group
    # and cell ids follow the raster order of the clearance maxima
    reps = np.unique(rep[1:])
    lut = np.zeros(len(rep), np.int32)
    lut[reps] = np.arange(1, len(reps) + 1, dtype=np.int32)
    cell_label = lut[rep]
    cell_label[0] = 0
    labels = cell_label[cells]
    group_peak = np.zeros(len(reps) + 1)
    np.maximum.at(group_peak, cell_label, peak)
    group_peak[0] = 0
    del cells
    labels = _single_pieces(labels)
    if CLUTTER_BORDERS:
        labels, group_peak = _join_cluttered_borders(labels, cell_label, lo, hi, border, group_peak, stats)
    occupied, openings = wall_lines.result()
    del wall_lines
    if WALL_CUTS:
        labels, group_peak = _wall_line_doors(labels, space, dist, res, max_cut_m, group_peak, stats, occupied,
                                              scanned=scanned, openings=openings)
    labels, group_peak, dropped_px = _drop_outside_pockets(labels, free & ~interior, group_peak,
                                                           info.get("claimed"), info.get("inside_pixels"))
    info.pop("claimed", None)
    if dropped_px:
        stats["interior_area_m2"] -= dropped_px * res * res
        stats["outside_pockets_m2"] = dropped_px * res * res
    if RAY_SPIKES and occupied is not None:  # recorded maps whose walls are occupied
        labels, group_peak = _drop_ray_spikes(labels, data, group_peak, res, stats)
    scanned_map = (CORRIDOR_LOOPS or PARTITION_LINES) and scanned
    if CORRIDOR_LOOPS and scanned_map:  # scanned maps: corridors cut by clutter (CAD: doors);
        # after the outside pockets: no exterior recess is joined to a corridor
        labels, group_peak = _join_corridor_loops(labels, group_peak, res, stats)
    if PARTITION_LINES and WALL_CUTS and scanned_map:  # scanned maps: rooms open over their whole side
        labels, group_peak = _cut_partition_lines(labels, space, dist, res, max_cut_m, group_peak, stats, occupied)
    stats["merge_s"] = time.perf_counter() - t
    progress.step(65, f"merged into {int(labels.max())} areas")
    return labels, group_peak, skel


def _area_graph(labels: np.ndarray, group_peak: np.ndarray, grid: OccupancyGrid, door_hints,
                skel, skel_grid: OccupancyGrid, stats: Dict[str, float], progress: Progress,
                t_all: float) -> AreaGraph:
    """Areas (outlines traced on ``grid``) and passages of the area labels; ``group_peak``: every label's
    clearance peak in pixels of ``skel_grid``, the grid the labels were found on."""
    res = float(skel_grid.resolution)
    t = time.perf_counter()
    polys = label_polygons(labels, grid)
    stats["polygons_s"] = time.perf_counter() - t
    progress.step(85, "area outlines traced")

    t = time.perf_counter()
    passages = build_passages(labels, grid)
    if door_hints:
        extra = hint_passages(labels, grid, door_hints, passages)
        passages += extra
        stats["hint_passages"] = float(len(extra))
        if extra:
            progress.info(f"{len(extra)} passages added from door hints the segmentation missed")
    stats["passages_s"] = time.perf_counter() - t

    ids = sorted(polys)
    areas: List[Area] = []
    for lid in ids:
        mc = group_peak[lid] if lid < len(group_peak) else 1.0
        poly = polys[lid]
        clear_m = max(0.0, (float(mc) - 0.5) * res)
        elong = poly.area / max((2.0 * clear_m) ** 2, res * res)
        typ = "corridor" if elong >= CORRIDOR_ELONGATION else "room"
        areas.append(Area(id=int(lid), polygon=poly, type=typ, max_clearance=clear_m))
    if ids != list(range(1, len(ids) + 1)):  # a label traced no polygon: keep area ids consecutive (1..n)
        remap = np.zeros(int(labels.max()) + 1, dtype=labels.dtype)
        remap[np.asarray(ids, dtype=np.int64)] = np.arange(1, len(ids) + 1, dtype=labels.dtype)
        labels = remap[labels]
        for a in areas:
            a.id = int(remap[a.id])
        kept = []
        for p in passages:
            if p.from_id < len(remap) and p.to_id < len(remap) and remap[p.from_id] and remap[p.to_id]:
                p.from_id, p.to_id = int(remap[p.from_id]), int(remap[p.to_id])
                kept.append(p)
        passages = kept
    comps = assign_components(areas, passages)
    stats["components"] = float(len(comps))
    stats["largest_component_share"] = comps[0]["share"] if comps else 1.0
    report_components(comps, progress, "segmentation")
    stats["areas"] = float(len(areas))
    stats["passages"] = float(len(passages))
    stats["total_s"] = time.perf_counter() - t_all
    progress.step(100, f"{len(areas)} areas ({sum(a.type == 'room' for a in areas)} rooms), "
                       f"{len(passages)} passages, interior {stats['interior_area_m2']:.1f} m2")
    return AreaGraph(areas=areas, passages=passages, labels=labels.astype(np.int32, copy=False), grid=grid,
                     stats=stats, skeleton=skel, skeleton_grid=skel_grid)
