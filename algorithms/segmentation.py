"""Area Graph segmentation of an occupancy grid (pipeline stage 3).

After Hou, Yuan and Schwertfeger, "Area Graph: Generation of Topological Maps using the Voronoi
Diagram" (ICAR 2019), with the dynamic alpha of the CAD-to-osmAG paper. Everything is raster based
(numpy / scipy.ndimage / OpenCV / GDAL) and runs in a few seconds on multi-million pixel floors.

Steps (``AreaGraph.stats`` keeps the wall time of each):

``interior``
    Building envelope. A disk of radius ``envelope_gap / 2`` rolled through the free space from
    outside the image marks everything it can reach as *outside*; facade openings narrower than
    ``envelope_gap`` (doors, glazing, drawing gaps) are therefore bridged and the interior is the
    rest of the free space. Outside space is never an area. Unknown cells are never free.
``skeleton``
    Clearance (Euclidean distance to the nearest wall) and the skeleton of the free space as a
    graph (``skeleton.skeleton_graph``): the space is thinned to its one-pixel medial axis -- the
    generalised Voronoi diagram of the walls -- peeling pixels in order of clearance with
    topology-preserving (Guo-Hall) thinning; nodes are its junctions and dead ends (with their
    clearance), edges the pixel chains between them (length, min / max clearance). Dead-end
    branches shorter than ``prune`` metres are removed, round after round, merging the nodes left
    with two branches. Obstacle specks up to ``SPECK_M2`` (sensor noise, clutter) are ignored here
    so that they make no branches or narrowings (they stay holes in the areas).
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
    ends of the shared border (where it meets walls), its length is the passage width.
"""
from __future__ import annotations

import math
import time
from typing import Dict, List, Optional, Tuple

import numpy as np

from .errors import InputError
from .model import FREE, Area, AreaGraph, OccupancyGrid, Passage
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
def _edt(mask: np.ndarray) -> np.ndarray:
    """Euclidean distance (px, float32) of every True pixel to the nearest False pixel."""
    import cv2

    return cv2.distanceTransform(mask.view(np.uint8) if mask.dtype == bool else mask.astype(np.uint8),
                                 cv2.DIST_L2, cv2.DIST_MASK_PRECISE)


def building_interior(free: np.ndarray, resolution: float, envelope_gap: float = DEFAULT_ENVELOPE_GAP,
                      unknown: Optional[np.ndarray] = None) -> Tuple[np.ndarray, np.ndarray]:
    """Free space inside the building envelope.

    Returns ``(interior_free, envelope)``: ``envelope`` is everything a disk of diameter
    ``envelope_gap`` cannot reach from outside the image through free (or ``unknown``: unexplored,
    no evidence of a building) space, walls included; ``interior_free`` its free pixels without
    pockets smaller than ``MIN_INTERIOR_COMPONENT_M2``.
    """
    import cv2

    rc = max(1.0, envelope_gap / 2.0 / resolution)
    pad = int(math.ceil(rc)) + 2
    passable = free if unknown is None else (free | unknown)
    padded = np.pad(passable, pad, mode="constant", constant_values=True)
    dist = _edt(padded)
    centers = (dist > rc).view(np.uint8)
    n, lab = cv2.connectedComponents(centers, connectivity=8, ltype=cv2.CV_32S)
    outside_id = lab[0, 0]
    if outside_id == 0:  # cannot happen with the padding, kept for safety
        envelope = np.ones(free.shape, bool)
    else:
        not_centers = (lab != outside_id).view(np.uint8)
        reach = _edt(not_centers)[pad:-pad, pad:-pad]
        envelope = reach > rc  # outside = within rc of an outside disk centre
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


def _without_specks(interior: np.ndarray, resolution: float) -> np.ndarray:
    """The space with obstacle specks (non-free blobs smaller than ``SPECK_M2`` lying inside it:
    sensor noise, clutter) counted as space: they make no narrowings."""
    import cv2

    n, lab, st, _ = cv2.connectedComponentsWithStats((~interior).view(np.uint8), connectivity=8,
                                                     ltype=cv2.CV_32S)
    small = st[:, cv2.CC_STAT_AREA] * resolution ** 2 <= SPECK_M2
    small[0] = False
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
    local_max = cv2.dilate(dist, np.ones((3, 3), np.uint8))
    peaks = (dist >= local_max) & free
    n, markers = cv2.connectedComponents(peaks.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    peak_val = np.zeros(n, np.float64)
    peak_val[markers[peaks]] = dist[peaks]
    # steepest ascent pointer of every pixel (itself when no neighbour is strictly higher)
    padded = np.pad(dist, 1, mode="constant", constant_values=-1.0)
    best = dist.copy()
    step = np.zeros(free.shape, np.int32)
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            if dr == 0 and dc == 0:
                continue
            nb = padded[1 + dr:rows + 1 + dr, 1 + dc:cols + 1 + dc]
            better = nb > best
            best[better] = nb[better]
            step[better] = dr * cols + dc
    del best, padded, local_max
    flat_free = np.flatnonzero(free.ravel())
    pos = np.full(rows * cols, -1, np.int64)
    pos[flat_free] = np.arange(len(flat_free))
    parent = pos[flat_free + step.ravel()[flat_free]]
    del step, pos
    while True:
        grand = parent[parent]
        if np.array_equal(grand, parent):
            break
        parent = grand
    cells = np.zeros(rows * cols, np.int32)
    cells[flat_free] = markers.ravel()[flat_free[parent]]
    return dist, cells.reshape(rows, cols), peak_val


def _edge_regions(skel: SkeletonGraph, space: np.ndarray, dist: np.ndarray):
    """The regions of the topology graph. Returns (regions int32, peak clearance px per region,
    number of clearance basins).

    The skeleton edges are split where a clearance valley crosses them -- the borders of the
    basins of ``_cells``, i.e. the clearance minima along the edge, the narrowings at doors -- and
    every free pixel joins the closest edge piece of its own basin (Euclidean, grown through free
    space where the closest piece lies behind a wall). A basin no kept skeleton edge runs through
    (its clearance maximum lay only on pruned branches, or on none) has no region of its own: its
    pixels join the neighbouring regions.
    """
    _, basins, basin_peak = _cells(space, dist)
    er = skel.edge_raster(lone_nodes=True).ravel()
    skp = np.flatnonzero(er)
    key = er[skp].astype(np.int64) * (len(basin_peak) + 1) + basins.ravel()[skp]
    _, inv = np.unique(key, return_inverse=True)  # pieces in edge order, then basin order
    seeds = np.zeros(space.shape, np.int32)
    seeds.ravel()[skp] = inv + 1
    del er, skp, key, inv
    regions = nearest_seed_regions(seeds, space, zones=basins)
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
    uf = _UnionFind(n)
    gpeak = [float(x) for x in peak]
    for i in order.tolist():
        a, b, s = uf.find(int(lo[i])), uf.find(int(hi[i])), float(saddle[i])
        if a == b:
            continue
        pa, pb = gpeak[a], gpeak[b]
        if s >= r_alpha or min(pa, pb) - s < min_rise:
            keep, gone = (a, b) if a < b else (b, a)
            uf.parent[gone] = keep
            gpeak[keep] = max(pa, pb)
    base = [uf.find(i) for i in range(n)]
    bpeak = [gpeak[base[i]] for i in range(n)]
    for i in order.tolist():
        a, b, s = uf.find(int(lo[i])), uf.find(int(hi[i])), float(saddle[i])
        if a == b:
            continue
        pa, pb = bpeak[int(lo[i])], bpeak[int(hi[i])]
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

        for i in order.tolist():
            a, b, s = uf.find(int(lo[i])), uf.find(int(hi[i])), float(saddle[i])
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
    from scipy import ndimage as ndi

    for _ in range(3):
        extra = []
        for lab_id, sl in enumerate(ndi.find_objects(labels), start=1):
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


def _drop_outside_pockets(labels: np.ndarray, outside: np.ndarray, group_peak: np.ndarray):
    """Remove areas that are mostly open to the outside (exterior recesses the envelope disk could
    not reach) and renumber the rest 1..n in the same order. Returns (labels, peaks, dropped px)."""
    n = int(labels.max())
    if n == 0 or not outside.any():
        return labels, group_peak, 0
    total = np.zeros(n + 1, np.int64)
    open_ = np.zeros(n + 1, np.int64)
    for axis in (0, 1):
        a, b = (labels[:-1, :], labels[1:, :]) if axis == 0 else (labels[:, :-1], labels[:, 1:])
        oa, ob = (outside[:-1, :], outside[1:, :]) if axis == 0 else (outside[:, :-1], outside[:, 1:])
        diff = a != b
        total += np.bincount(a[diff], minlength=n + 1) + np.bincount(b[diff], minlength=n + 1)
        open_ += np.bincount(a[(a > 0) & ob], minlength=n + 1) + np.bincount(b[(b > 0) & oa], minlength=n + 1)
    drop = open_ >= OUTSIDE_CONTACT * np.maximum(total, 1)
    drop[0] = False
    if not drop.any():
        return labels, group_peak, 0
    keep_ids = np.nonzero(~drop[1:])[0] + 1
    lut = np.zeros(n + 1, np.int32)
    lut[keep_ids] = np.arange(1, len(keep_ids) + 1, dtype=np.int32)
    dropped_px = int(np.isin(labels, np.nonzero(drop)[0]).sum())
    return lut[labels], np.r_[0.0, group_peak[keep_ids]], dropped_px


# --------------------------------------------------------------------------- vector output
def label_polygons(labels: np.ndarray, grid: OccupancyGrid) -> Dict[int, object]:
    """Exact pixel-edge outline of every label (4-connected), as shapely Polygons in world metres."""
    import shapely
    from osgeo import gdal, ogr

    gdal.UseExceptions()
    rows, cols = labels.shape
    drv = gdal.GetDriverByName("MEM")
    ds = drv.Create("", cols, rows, 1, gdal.GDT_Int32)
    ds.SetGeoTransform(grid.geotransform)
    band = ds.GetRasterBand(1)
    band.WriteArray(labels.astype(np.int32, copy=False))
    mds = drv.Create("", cols, rows, 1, gdal.GDT_Byte)
    mds.GetRasterBand(1).WriteArray((labels > 0).view(np.uint8))
    ods = ogr.GetDriverByName("Memory").CreateDataSource("areas")
    layer = ods.CreateLayer("areas")
    layer.CreateField(ogr.FieldDefn("id", ogr.OFTInteger))
    gdal.Polygonize(band, mds.GetRasterBand(1), layer, 0, [])
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


# --------------------------------------------------------------------------- main entry
def segment(grid: OccupancyGrid, door_width: float = DEFAULT_DOOR_WIDTH,
            corridor_width: float = DEFAULT_CORRIDOR_WIDTH, delta: float = DEFAULT_DELTA,
            prune: float = DEFAULT_PRUNE, progress: Optional[Progress] = None,
            envelope_gap: float = DEFAULT_ENVELOPE_GAP) -> AreaGraph:
    """Segment the free space of ``grid`` into an Area Graph.

    Returns an ``AreaGraph`` whose areas carry exact pixel-edge polygons (world metres), whose
    passages are 2-point lines across the openings between touching areas, ``labels`` (int32
    raster of area ids on the grid, 0 outside areas), ``skeleton`` (the pruned skeleton graph,
    ``skeleton.SkeletonGraph``, on the grid) and ``stats`` (per-step seconds, alpha, interior
    area, skeleton_nodes / _edges / _junctions / _dead_ends / _pruned, regions...). Raises
    ``InputError`` for unusable input.
    """
    progress = ensure(progress)
    t_all = time.perf_counter()
    stats: Dict[str, float] = {}
    data, alpha = _check_inputs(grid, door_width, corridor_width, delta, prune)
    res = float(grid.resolution)
    r_alpha = math.sqrt(alpha)
    stats.update(alpha_px2=float(alpha), alpha_radius_m=r_alpha * res, resolution=res,
                 pixels=float(data.size))
    progress.step(2, f"alpha = {alpha} px^2 (probe disk radius {r_alpha * res:.2f} m at {res:g} m/px)")

    t = time.perf_counter()
    free = data == FREE
    # unknown cells are not passable for the envelope disk either: some maps draw walls in grey
    interior, envelope = building_interior(free, res, envelope_gap)
    del envelope
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
    dist = _edt(space)
    skel = skeleton_graph(space, res, prune=prune, dist=dist)
    stats["skeleton_s"] = time.perf_counter() - t
    stats.update(skeleton_nodes=float(skel.n_nodes), skeleton_edges=float(skel.n_edges),
                 skeleton_junctions=float(skel.junctions), skeleton_dead_ends=float(skel.dead_ends),
                 skeleton_pruned=float(skel.pruned))
    progress.step(30, f"skeleton: {skel.n_nodes} nodes ({skel.junctions} junctions, {skel.dead_ends} dead ends), "
                      f"{skel.n_edges} edges, {skel.pruned} branches shorter than {prune:g} m pruned")

    t = time.perf_counter()
    cells, peak, n_basins = _edge_regions(skel, space, dist)
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
    labels, group_peak, dropped_px = _drop_outside_pockets(labels, free & ~interior, group_peak)
    if dropped_px:
        stats["interior_area_m2"] -= dropped_px * res * res
        stats["outside_pockets_m2"] = dropped_px * res * res
    stats["merge_s"] = time.perf_counter() - t
    progress.step(65, f"merged into {int(labels.max())} areas")

    t = time.perf_counter()
    polys = label_polygons(labels, grid)
    stats["polygons_s"] = time.perf_counter() - t
    progress.step(85, "area outlines traced")

    t = time.perf_counter()
    passages = build_passages(labels, grid)
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
    stats["areas"] = float(len(areas))
    stats["passages"] = float(len(passages))
    stats["total_s"] = time.perf_counter() - t_all
    progress.step(100, f"{len(areas)} areas ({sum(a.type == 'room' for a in areas)} rooms), "
                       f"{len(passages)} passages, interior {stats['interior_area_m2']:.1f} m2")
    return AreaGraph(areas=areas, passages=passages, labels=labels.astype(np.int32, copy=False), grid=grid,
                     stats=stats, skeleton=skel)
