"""Skeleton (generalised Voronoi diagram) of the free space as a graph, and the regions of its edges.

``thin`` reduces the free space to a one-pixel, 8-connected skeleton that keeps its topology (one
loop around every pillar): the pixels are peeled off in order of their Euclidean clearance
(distance to the nearest wall), one-pixel layer after layer, with the parallel thinning of Guo and
Hall (1989, algorithm A1: a pixel goes only if its removal keeps the topology and it is not a line
end). What is left runs along the ridge of the clearance, midway between the walls: a raster
approximation of the medial axis / generalised Voronoi diagram (the short branches the exact medial
axis sends into every room corner mostly do not appear).

``skeleton_graph`` turns it into a graph: nodes are the junctions (3 or more branches) and dead
ends, with their clearance; edges the pixel chains between them, with length and min / max
clearance. Dead-end branches shorter than ``prune`` metres are removed round after round, and the
nodes left with two branches are merged away, so a small recess in a wall makes no branch.

``nearest_seed_regions`` gives every free pixel the label of the closest skeleton pixel (edge, or
edge piece) without crossing walls, optionally only within a zone: the regions of the topology graph.

Everything is vectorised over pixels (numpy / OpenCV / scipy); Python loops run per clearance layer,
per node, per edge or per zone.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional

import numpy as np

SQRT2 = math.sqrt(2.0)


# --------------------------------------------------------------------------- thinning
def _guo_hall_luts():
    """Deletion tables of the two sub-iterations of Guo-Hall thinning, indexed by the 8-neighbour
    code (bit 0 east, then counter-clockwise: NE, N, NW, W, SW, S, SE)."""
    luts = np.zeros((2, 256), bool)
    for code in range(256):
        x = [(code >> i) & 1 for i in range(8)]  # x[0] = x1 (east) ... x[7] = x8 (south-east)
        X = lambda i: x[(i - 1) % 8]  # noqa: E731  1-based, cyclic
        c = sum((not X(2 * i - 1)) and (X(2 * i) or X(2 * i + 1)) for i in range(1, 5))
        n1 = sum(X(2 * k - 1) or X(2 * k) for k in range(1, 5))
        n2 = sum(X(2 * k) or X(2 * k + 1) for k in range(1, 5))
        n = min(n1, n2)
        if c != 1 or not 2 <= n <= 3:
            continue
        luts[0, code] = ((X(2) or X(3) or not X(8)) and X(1)) == 0
        luts[1, code] = ((X(6) or X(7) or not X(4)) and X(5)) == 0
    return luts


_LUTS = _guo_hall_luts()


def _codes(img: np.ndarray, idx: np.ndarray, width: int) -> np.ndarray:
    """8-neighbour codes of the flat positions ``idx`` of the padded uint8 image ``img``."""
    code = np.zeros(len(idx), np.uint8)
    for bit, off in enumerate((1, 1 - width, -width, -width - 1, -1, width - 1, width, width + 1)):
        code |= img[idx + off] << np.uint8(bit)
    return code


def thin(mask: np.ndarray, dist: Optional[np.ndarray] = None, progress=None) -> np.ndarray:
    """One-pixel, 8-connected skeleton of ``mask`` that keeps its topology.

    Pixels are visited in order of their Euclidean distance ``dist`` to the nearest background pixel
    (computed when not given), one layer of one pixel at a time; inside a layer the two Guo-Hall
    sub-iterations repeat until nothing changes. Pixels a layer could not remove because they were
    not yet on the border are visited again with the next layer; a last round over the whole
    skeleton removes what became removable later. ``progress``: checked for cancel every few layers.
    """
    from .segmentation import _edt

    mask = np.asarray(mask, bool)
    if dist is None:
        dist = _edt(mask)
    rr = np.nonzero(mask.any(axis=1))[0]
    cc = np.nonzero(mask.any(axis=0))[0]
    out = np.zeros(mask.shape, bool)
    if len(rr) == 0:
        return out
    box = (slice(int(rr[0]), int(rr[-1]) + 1), slice(int(cc[0]), int(cc[-1]) + 1))
    out[box] = _thin_box(np.ascontiguousarray(mask[box]), dist[box], progress)
    return out


def _thin_box(mask: np.ndarray, dist: np.ndarray, progress=None) -> np.ndarray:
    rows, cols = mask.shape
    from . import kernels

    nb = kernels.get()
    if nb is not None and mask.any():
        img, pos, bounds = nb.thin_setup(mask, np.ascontiguousarray(dist))
        _thin_compiled(nb, img, pos, bounds, _LUTS, cols + 2, progress)
        return img.reshape(rows + 2, cols + 2)[1:-1, 1:-1].astype(bool)
    width = cols + 2
    img = np.zeros((rows + 2, width), np.uint8)
    img[1:-1, 1:-1] = mask
    img = img.ravel()
    flat = np.flatnonzero(mask.ravel())
    if len(flat) == 0:
        return np.zeros(mask.shape, bool)
    layer = np.floor(dist.ravel()[flat]).astype(np.int32)
    layer = np.minimum(layer, 65535).astype(np.uint16)
    order = np.argsort(layer, kind="stable")
    pos = (flat // cols + 1) * width + (flat % cols + 1)  # padded flat positions
    pos = pos[order]
    bounds = np.searchsorted(layer[order], np.arange(int(layer.max()) + 2))
    del order, flat, layer
    luts = _LUTS
    four = (1, -1, width, -width)

    def sweep(cand):
        while True:
            if progress is not None:
                progress.check()
            removed = 0
            for sub in (0, 1):
                cand = cand[img[cand] == 1]
                if len(cand) == 0:
                    return cand
                gone = luts[sub][_codes(img, cand, width)]
                if gone.any():
                    img[cand[gone]] = 0
                    removed += int(gone.sum())
            if not removed:
                return cand[img[cand] == 1]

    carry = np.zeros(0, np.int64)
    for k in range(len(bounds) - 1):
        cand = pos[bounds[k]:bounds[k + 1]]
        if len(carry):
            cand = np.concatenate([carry, cand])
        if len(cand) == 0:
            continue
        if progress is not None and k % 16 == 0:
            progress.check()
        cand = sweep(cand)
        border = np.zeros(len(cand), bool)
        for off in four:
            border |= img[cand + off] == 0
        carry = cand[~border]
    rest = np.flatnonzero(img)
    sweep(rest)
    return img.reshape(rows + 2, width)[1:-1, 1:-1].astype(bool)


def _thin_compiled(nb, img, pos, bounds, luts, width, progress=None, chunk=64):
    """``_thin_box``'s layer loop as compiled kernels (``kernels``): the same candidates, sweeps and
    carry, ``chunk`` layers per call with a cancel check between calls. ``img`` is thinned in place."""
    cand = np.empty(len(pos), np.int64)
    flags = np.empty(len(pos), np.bool_)
    ncarry = 0
    n_layers = len(bounds) - 1
    bounds = bounds.astype(np.int64)
    for k0 in range(0, n_layers, chunk):
        if progress is not None:
            progress.check()
        ncarry = nb.thin_layers(img, pos, bounds, k0, min(k0 + chunk, n_layers), luts, width, cand, ncarry, flags)
    if progress is not None:
        progress.check()
    nb.thin_rest(img, luts, width, flags)


# --------------------------------------------------------------------------- graph
@dataclass
class SkeletonGraph:
    """The pruned skeleton of a free space as a graph (pixel units unless the name says _m).

    ``node_pixels[i]`` / ``edge_pixels[j]`` are flat raster indices (row * cols + col);
    ``edge_nodes[j]`` = (u, v) node ids (-1, -1 for a closed loop without a node).
    """
    shape: tuple
    resolution: float
    node_pixels: List[np.ndarray]
    node_clearance_m: np.ndarray
    node_degree: np.ndarray
    edge_pixels: List[np.ndarray]
    edge_nodes: np.ndarray
    edge_length_m: np.ndarray
    edge_min_clearance_m: np.ndarray
    edge_max_clearance_m: np.ndarray
    pruned: int = 0
    stats: Dict[str, float] = field(default_factory=dict)

    @property
    def n_nodes(self) -> int:
        return len(self.node_pixels)

    @property
    def n_edges(self) -> int:
        return len(self.edge_pixels)

    @property
    def dead_ends(self) -> int:
        return int((self.node_degree == 1).sum())

    @property
    def junctions(self) -> int:
        return int((self.node_degree >= 3).sum())

    def node_rc(self) -> np.ndarray:
        """(row, col) of every node (the first of its pixels in raster order)."""
        cols = self.shape[1]
        first = np.array([p[0] for p in self.node_pixels], np.int64) if self.node_pixels else np.zeros(0, np.int64)
        return np.stack([first // cols, first % cols], axis=1)

    def edge_raster(self, lone_nodes: bool = False) -> np.ndarray:
        """int32 raster: edge id + 1 on the edge pixels (0 elsewhere, node pixels included). With
        ``lone_nodes`` the nodes without any edge (the whole skeleton of a small round piece of
        space) get the ids after the edges'."""
        out = np.zeros(int(np.prod(self.shape)), np.int32)
        for j, px in enumerate(self.edge_pixels):
            out[px] = j + 1
        if lone_nodes:
            extra = self.n_edges
            for n in np.nonzero(self.node_degree == 0)[0].tolist():
                extra += 1
                out[self.node_pixels[n]] = extra
        return out.reshape(self.shape)

    def edge_path(self, j: int) -> np.ndarray:
        """The pixels of edge ``j`` in order from node u to node v, node pixels at both ends
        included, as an (n, 2) float array of (row, col)."""
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import shortest_path

        cols = self.shape[1]
        u, v = (int(x) for x in self.edge_nodes[j])
        chain = self.edge_pixels[j]
        parts = [chain] + [self.node_pixels[n] for n in {u, v} if n >= 0]
        px = np.unique(np.concatenate(parts))
        r, c = px // cols, px % cols
        src, dst = [], []
        for dr, dc in ((0, 1), (1, -1), (1, 0), (1, 1)):
            tgt = (r + dr) * cols + (c + dc)
            k = np.minimum(np.searchsorted(px, tgt), len(px) - 1)
            hit = (c + dc >= 0) & (c + dc < cols) & (px[k] == tgt)
            src.append(np.nonzero(hit)[0])
            dst.append(k[hit])
        src, dst = np.concatenate(src), np.concatenate(dst)
        def walk(graph, start, targets):
            """pixel indices of a shortest path from ``start`` to the closest (fewest steps) of
            ``targets`` (or to the farthest pixel when ``targets`` is None)"""
            d, pred = shortest_path(graph, directed=False, unweighted=True, indices=start,
                                    return_predecessors=True)
            if targets is None:
                ok = np.nonzero(np.isfinite(d))[0]
                end = int(ok[np.argmax(d[ok])])
            else:
                reach = targets[np.isfinite(d[targets])]
                end = int(reach[np.argmin(d[reach])]) if len(reach) else start
            out = [end]
            while out[-1] != start and pred[out[-1]] >= 0:
                out.append(int(pred[out[-1]]))
            return np.array(out[::-1], np.int64)

        if u == v:
            # a loop (through one node, or a ring with none): cut it open at the node (or at its first
            # pixel) and walk the chain from one side of the cut to the other
            on_node = np.isin(px, self.node_pixels[u] if u >= 0 else chain[:1])
            keep = ~on_node[src] & ~on_node[dst]
            g = coo_matrix((np.ones(int(keep.sum())), (src[keep], dst[keep])), shape=(len(px),) * 2).tocsr()
            ends = np.unique(np.r_[src[on_node[dst] & ~on_node[src]], dst[on_node[src] & ~on_node[dst]]])
            start = int(ends[0]) if len(ends) else int(np.nonzero(~on_node)[0][0])
            node = np.nonzero(on_node)[0][:1]
            order = np.r_[node, walk(g, start, ends[1:] if len(ends) > 1 else None), node]
        else:
            g = coo_matrix((np.ones(len(src)), (src, dst)), shape=(len(px),) * 2).tocsr()
            start = int(np.searchsorted(px, self.node_pixels[u][0] if u >= 0 else chain[0]))
            targets = np.searchsorted(px, self.node_pixels[v]) if v >= 0 else None
            order = walk(g, start, targets)
        path = px[order]
        return np.stack([path // cols, path % cols], axis=1).astype(np.float64)

    def edge_lines(self, geotransform) -> List[object]:
        """Every edge as a shapely LineString in world coordinates (pixel centres), from node u to v."""
        from shapely.geometry import LineString

        x0, dx, rx, y0, ry, dy = geotransform
        out = []
        for j in range(self.n_edges):
            rc = self.edge_path(j)
            cx, cy = rc[:, 1] + 0.5, rc[:, 0] + 0.5
            xy = np.stack([x0 + cx * dx + cy * rx, y0 + cx * ry + cy * dy], axis=1)
            if len(xy) == 1:
                xy = np.vstack([xy, xy])
            out.append(LineString(xy))
        return out


def _chain_lengths(labels: np.ndarray, n: int, idx: Optional[np.ndarray] = None) -> np.ndarray:
    """Length (px) of every 8-connected pixel set of ``labels`` (ids 1..n): steps of 1 between
    4-neighbours, sqrt(2) between diagonal neighbours that share no 4-neighbour in the set.

    The pairs are counted from the labelled pixels (``idx``: their flat indices in raster order, when
    known), not over the whole raster: the skeleton is a few per cent of its box. The same counts as the
    whole-raster comparison (``tests/test_skeleton_speed.py``'s reference), added in the same order."""
    length = np.zeros(n + 1)
    rows, cols = labels.shape
    flat = np.ascontiguousarray(labels).ravel()
    if idx is None:
        idx = np.flatnonzero(flat)
    r, c = np.divmod(idx, cols)
    x = flat[idx]
    down, right, left = r < rows - 1, c < cols - 1, c > 0
    for ok, step, w in ((right, 1, 1.0), (down, cols, 1.0)):
        i = idx[ok]
        xi = x[ok]
        length += w * np.bincount(xi[flat[i + step] == xi], minlength=n + 1)
    for ok, dy, p, q in ((down & right, cols + 1, 1, cols), (down & left, cols - 1, -1, cols)):
        i = idx[ok]
        xi = x[ok]
        same = (flat[i + dy] == xi) & (flat[i + p] != xi) & (flat[i + q] != xi)
        length += SQRT2 * np.bincount(xi[same], minlength=n + 1)
    return length


def skeleton_graph(free_mask: np.ndarray, resolution: float, prune: float = 0.25,
                   dist: Optional[np.ndarray] = None, skeleton: Optional[np.ndarray] = None,
                   progress=None) -> SkeletonGraph:
    """Skeleton graph of the free space ``free_mask`` (True = free) at ``resolution`` m/px.

    Nodes: dead ends and junctions of the thinned skeleton with their clearance in metres (distance
    from the pixel centre to the nearest wall edge, the largest over the node's pixels). Edges: the
    pixel chains between them with their length and min / max clearance in metres. Dead-end branches
    shorter than ``prune`` metres are removed one round after the other (a branch that is the last
    edge of its piece of skeleton stays), merging the nodes left with two branches.
    ``dist`` (Euclidean distance in px of every free pixel to the nearest non-free one, as
    ``cv2.distanceTransform`` gives) and ``skeleton`` may be passed when already computed.
    ``progress`` (``progress.Progress``) is checked for cancel in the long loops.
    """
    import cv2

    from .segmentation import _edt

    free_mask = np.asarray(free_mask, bool)
    shape = free_mask.shape
    if dist is None:
        dist = _edt(free_mask)
    if skeleton is None:
        skeleton = thin(free_mask, dist, progress)
    # work inside the bounding box of the skeleton, one pixel of margin
    rr = np.nonzero(skeleton.any(axis=1))[0]
    cc = np.nonzero(skeleton.any(axis=0))[0]
    if len(rr) == 0:
        r0 = c0 = 0
        R = C = 1
    else:
        r0, c0 = max(int(rr[0]) - 1, 0), max(int(cc[0]) - 1, 0)
        R, C = min(int(rr[-1]) + 2, shape[0]) - r0, min(int(cc[-1]) + 2, shape[1]) - c0
    sk = np.ascontiguousarray(skeleton[r0:r0 + R, c0:c0 + C]).astype(np.uint8)
    nb = cv2.filter2D(sk, cv2.CV_16S, np.ones((3, 3), np.float32), borderType=cv2.BORDER_CONSTANT) - sk
    is_node = (sk > 0) & (nb != 2)
    is_chain = (sk > 0) & ~is_node
    n_nodes, node_lab = cv2.connectedComponents(is_node.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    n_chain, chain_lab = cv2.connectedComponents(is_chain.view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    n_nodes -= 1
    n_chain -= 1
    cols = shape[1]

    # every node and chain pixel is a skeleton pixel: their flat indices (box, raster order) are found once
    sk_idx = np.flatnonzero(sk.ravel())

    def labelled(lab):
        """flat indices (box, raster order) of the labelled pixels of ``lab`` and their labels"""
        ids = lab.ravel()[sk_idx]
        on = ids > 0
        return sk_idx[on], ids[on]

    def groups(lab, n):
        """flat indices (full raster) of the pixels of every label 1..n"""
        idx, ids = labelled(lab)
        order = np.argsort(ids, kind="stable")
        idx, ids = idx[order], ids[order]
        idx = (idx // C + r0) * cols + (idx % C + c0)
        b = np.searchsorted(ids, np.arange(1, n + 2))
        return [idx[b[i]:b[i + 1]] for i in range(n)]

    node_px = groups(node_lab, n_nodes)
    chain_px = groups(chain_lab, n_chain)
    # chain -> the node clusters it touches: the chain labels around every node pixel
    node_idx, nid = labelled(node_lab)
    nr, nc = np.divmod(node_idx, C)
    pairs = set()
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            if dr == 0 and dc == 0:
                continue
            r2, c2 = nr + dr, nc + dc
            ok = (r2 >= 0) & (r2 < R) & (c2 >= 0) & (c2 < C)
            ch = chain_lab[r2[ok], c2[ok]]
            hit = ch > 0
            if hit.any():
                key = ch[hit].astype(np.int64) * (n_nodes + 1) + nid[ok][hit]
                pairs.update(np.unique(key).tolist())
    ends: List[List[int]] = [[] for _ in range(n_chain)]
    for key in sorted(pairs):
        ends[key // (n_nodes + 1) - 1].append(key % (n_nodes + 1) - 1)
    lengths = _chain_lengths(chain_lab, n_chain, labelled(chain_lab)[0])[1:]
    del node_lab, chain_lab, nb, is_node, is_chain, sk
    dflat = dist.ravel()

    # working graph (Python lists; one entry per node / edge)
    e_px: List[Optional[np.ndarray]] = []
    e_uv: List[List[int]] = []
    e_len: List[float] = []
    for j in range(n_chain):
        nn = ends[j]
        if len(nn) == 0:
            u = v = -1
        elif len(nn) == 1:
            u = v = nn[0]
        else:
            u, v = nn[0], nn[1]
        # the steps onto the end nodes
        e_px.append(chain_px[j])
        e_uv.append([u, v])
        e_len.append(float(lengths[j]) + (u >= 0) + (v >= 0))
    n_px: List[Optional[np.ndarray]] = list(node_px)
    # a node with several pixels (a junction blob): its own length is ignored
    incident: List[set] = [set() for _ in range(n_nodes)]
    for j, (u, v) in enumerate(e_uv):
        if u >= 0:
            incident[u].add(j)
            incident[v].add(j)

    def degree(n):
        return sum(2 if e_uv[j][0] == e_uv[j][1] else 1 for j in incident[n])

    prune_px = prune / resolution
    pruned = 0

    def merge_degree2(n):
        """Join the two branches of node ``n`` into one edge."""
        inc = sorted(incident[n])
        if len(inc) != 2:
            return
        j, k = inc
        a = e_uv[j][0] if e_uv[j][1] == n else e_uv[j][1]
        b = e_uv[k][0] if e_uv[k][1] == n else e_uv[k][1]
        e_px[j] = np.concatenate([e_px[j], n_px[n], e_px[k]])
        e_len[j] = e_len[j] + e_len[k]
        e_uv[j] = [a, b]
        incident[b].discard(k)
        incident[b].add(j)
        e_px[k] = None
        incident[n] = set()
        n_px[n] = None

    changed = True
    while changed:
        if progress is not None:
            progress.check()
        changed = False
        # prune: dead-end branches shorter than PRUNE whose other end is a junction
        cut = []
        for j in range(len(e_px)):
            if e_px[j] is None or e_len[j] >= prune_px:
                continue
            u, v = e_uv[j]
            if u < 0 or u == v:
                continue
            du, dv = degree(u), degree(v)
            if (du == 1) != (dv == 1) and max(du, dv) >= 3:
                cut.append(j)
        # never cut every branch of a junction at once: keep the longest of them
        by_junction: Dict[int, list] = {}
        for j in cut:
            u, v = e_uv[j]
            by_junction.setdefault(v if degree(u) == 1 else u, []).append(j)
        for jn, js in sorted(by_junction.items()):
            if len(js) >= degree(jn):
                js = sorted(js, key=lambda j: (-e_len[j], j))[1:]
            for j in js:
                u, v = e_uv[j]
                leaf = u if degree(u) == 1 else v
                incident[u].discard(j)
                incident[v].discard(j)
                e_px[j] = None
                n_px[leaf] = None
                pruned += 1
                changed = True
        for n in range(n_nodes):
            if n_px[n] is not None and len(incident[n]) == 2 and degree(n) == 2:
                merge_degree2(n)
                changed = True
    # an isolated node (a lone pixel, or a ring's only node after merging) stays as it is
    keep_n = [n for n in range(n_nodes) if n_px[n] is not None]
    new_id = {n: i for i, n in enumerate(keep_n)}
    keep_e = [j for j in range(len(e_px)) if e_px[j] is not None]
    node_pixels = [n_px[n] for n in keep_n]
    node_clear = np.array([(float(dflat[p].max()) - 0.5) * resolution for p in node_pixels])
    edge_pixels = [e_px[j] for j in keep_e]
    edge_nodes = np.array([[new_id.get(e_uv[j][0], -1), new_id.get(e_uv[j][1], -1)] for j in keep_e],
                          np.int64).reshape(-1, 2)
    deg = np.zeros(len(keep_n), np.int64)
    for u, v in edge_nodes.tolist():
        if u >= 0:
            deg[u] += 1
            deg[v] += 1
    # clearance from the pixel centre to the wall edge: distance to the nearest wall pixel - 0.5
    emin = np.array([(float(dflat[p].min()) - 0.5) * resolution if len(p) else np.inf for p in edge_pixels])
    emax = np.array([(float(dflat[p].max()) - 0.5) * resolution if len(p) else -np.inf for p in edge_pixels])
    # edges of node pixels only (two adjacent nodes): their clearance is the nodes'
    for i, (u, v) in enumerate(edge_nodes.tolist()):
        if u >= 0:
            emin[i] = min(emin[i], node_clear[u], node_clear[v]) if len(edge_pixels[i]) == 0 else emin[i]
            emax[i] = max(emax[i], node_clear[u], node_clear[v]) if len(edge_pixels[i]) == 0 else emax[i]
    return SkeletonGraph(shape=shape, resolution=float(resolution), node_pixels=node_pixels,
                         node_clearance_m=node_clear, node_degree=deg, edge_pixels=edge_pixels,
                         edge_nodes=edge_nodes, edge_length_m=np.array([e_len[j] for j in keep_e]) * resolution,
                         edge_min_clearance_m=emin, edge_max_clearance_m=emax, pruned=pruned)


# --------------------------------------------------------------------------- regions
ZONES_SPLIT = 64  # nearest_seed_regions: from this many zones with several labels on, two threads share them


def nearest_seed_regions(seeds: np.ndarray, space: np.ndarray, zones: Optional[np.ndarray] = None,
                         fill_zones: bool = True, progress=None) -> np.ndarray:
    """Give every pixel of ``space`` the label of the closest pixel of ``seeds`` (int32, 0 = no
    seed), through free space: the Euclidean nearest seed, except where that seed is only reached
    across a wall (a piece of a label that holds none of its seeds), whose pixels are grown into
    from the neighbouring labels. With ``zones`` (int raster, 0 = none; the seeds of one label lie
    in one zone) a label only takes pixels of its own zone; the zones that hold no seed are then
    grown into from their neighbours (``fill_zones``) or stay 0. Pixels no seed reaches stay 0.
    ``progress`` is checked for cancel in the loops over zones and labels."""
    import cv2

    out = np.zeros(space.shape, np.int32)
    if not (seeds > 0).any():
        return out
    rr = np.nonzero(space.any(axis=1))[0]
    cc = np.nonzero(space.any(axis=0))[0]
    r0, r1, c0, c1 = int(rr[0]), int(rr[-1]) + 1, int(cc[0]), int(cc[-1]) + 1
    sp = space[r0:r1, c0:c1]
    sd = np.where(sp, seeds[r0:r1, c0:c1], np.int32(0)).astype(np.int32, copy=False)
    zn = None if zones is None else zones[r0:r1, c0:c1]
    seed_flat = np.flatnonzero(sd.ravel())
    if zn is None:
        src = (sd == 0).view(np.uint8)
        _, near = cv2.distanceTransformWithLabels(src, cv2.DIST_L2, 5, labelType=cv2.DIST_LABEL_PIXEL)
        lab = np.r_[0, sd.ravel()[seed_flat]].astype(np.int32)[near]
        del near
        lab[~sp] = 0
    label_zone = None
    if zn is not None:
        nz = int(zn.max()) + 1
        label_zone = np.zeros(int(sd.max()) + 1, np.int64)
        label_zone[sd.ravel()[seed_flat]] = zn.ravel()[seed_flat]
        labels_in = np.bincount(label_zone[1:], minlength=nz)
        # a zone with a single label is all that label's
        only = np.zeros(nz, np.int32)
        one = labels_in[label_zone[1:]] == 1
        only[label_zone[1:][one]] = np.nonzero(one)[0] + 1
        only[0] = 0
        lab = only[zn]
        # a zone with several: the closest of its labels
        multi = labels_in > 1
        multi[0] = False
        from . import kernels

        boxes = kernels.find_objects(zn)  # the boxes of the zones with several labels are the same
        nb = kernels.get()
        zs = np.nonzero(multi)[0].tolist()
        if nb is not None:  # the same seed image and label lookup, compiled (kernels.py)
            def zone_labels(part, check):
                for i, z in enumerate(part):
                    if check and progress is not None and i % 32 == 0:
                        progress.check()
                    rs, cs = boxes[z - 1]
                    src, vals = nb.zone_seeds(zn, sd, rs.start, rs.stop, cs.start, cs.stop, z)
                    _, nl = cv2.distanceTransformWithLabels(src, cv2.DIST_L2, 5, labelType=cv2.DIST_LABEL_PIXEL)
                    nb.zone_assign(lab, zn, nl, vals, rs.start, cs.start, z)

            if len(zs) >= ZONES_SPLIT:  # every zone writes its own pixels only: half of them on the second core
                from .segmentation import _Background

                other = _Background(lambda: zone_labels(zs[1::2], False))
                zone_labels(zs[0::2], True)
                other.result()
            else:
                zone_labels(zs, True)
            zs = []
        for i, z in enumerate(zs):
            if progress is not None and i % 32 == 0:
                progress.check()
            sl = boxes[z - 1]
            inside = zn[sl] == z
            sub_seeds = np.where(inside, sd[sl], 0)
            flat = np.flatnonzero(sub_seeds.ravel())
            _, nl = cv2.distanceTransformWithLabels((sub_seeds == 0).view(np.uint8), cv2.DIST_L2, 5,
                                                    labelType=cv2.DIST_LABEL_PIXEL)
            sub_lab = np.r_[0, sub_seeds.ravel()[flat]].astype(np.int32)[nl]
            lab[sl][inside] = sub_lab[inside]
        lab[~sp] = 0
    lab = _regrow_orphans(lab, sd, sp, zn, label_zone, progress=progress)
    if zn is not None and fill_zones and (sp & (lab == 0)).any():
        # the zones holding no seed: their pixels join the neighbouring labels
        lab = _regrow_orphans(lab, sd, sp, check_pieces=False, progress=progress)
    out[r0:r1, c0:c1] = lab
    return out


def _regrow_orphans(lab: np.ndarray, seeds: np.ndarray, space: np.ndarray, zones=None, label_zone=None,
                    check_pieces: bool = True, progress=None) -> np.ndarray:
    """Clear the pieces (4-connected) of every label that hold none of its seed pixels (with
    ``check_pieces``) and grow the labels into them and into the other unlabelled pixels of
    ``space``, one pixel ring per round, through ``space`` only (and inside the label's zone when
    ``zones`` is given)."""
    import cv2

    from . import kernels

    nb = kernels.get()
    if nb is not None and check_pieces:  # the same pieces from one compiled union-find pass
        if progress is not None:
            progress.check()
        orphan = nb.orphan_pieces(np.ascontiguousarray(lab), np.ascontiguousarray(seeds),
                                  np.ascontiguousarray(space))
        check_pieces = False
    else:
        orphan = space & (lab == 0)
    for lab_id, sl in enumerate(kernels.find_objects(lab) if check_pieces else [], start=1):
        if progress is not None and lab_id % 64 == 0:
            progress.check()
        if sl is None:
            continue
        sub = lab[sl] == lab_id
        n, cl = cv2.connectedComponents(sub.view(np.uint8), connectivity=4, ltype=cv2.CV_32S)
        if n <= 2:
            continue
        has = np.zeros(n, bool)
        has[cl[sub & (seeds[sl] == lab_id)]] = True
        bad = ~has
        bad[0] = False
        if bad.any():
            orphan[sl] |= bad[cl]
    if not orphan.any():
        return lab
    lab = lab.copy()
    lab[orphan] = 0
    rows, cols = lab.shape
    todo = np.flatnonzero(orphan.ravel())
    flat = lab.ravel()
    zflat = None if zones is None else zones.ravel()
    if nb is not None:  # the same synchronous rounds, compiled (kernels.py)
        if progress is not None:
            progress.check()
        use = zflat is not None
        nb.grow_rounds(flat, todo.astype(np.int64), rows, cols,
                       zflat if use else np.zeros(1, np.int32), label_zone if use else np.zeros(1, np.int64), use)
        return flat.reshape(rows, cols)
    while len(todo):
        if progress is not None:
            progress.check()
        r, c = todo // cols, todo % cols
        best = np.zeros(len(todo), np.int32)
        for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            rr, cc = r + dr, c + dc
            ok = (rr >= 0) & (rr < rows) & (cc >= 0) & (cc < cols)
            v = np.zeros(len(todo), np.int32)
            v[ok] = flat[rr[ok] * cols + cc[ok]]
            if zflat is not None:
                v[label_zone[v] != zflat[todo]] = 0
            best = np.where(best == 0, v, best)
        got = best > 0
        if not got.any():
            break  # pieces of space no seed reaches
        flat[todo[got]] = best[got]
        todo = todo[~got]
    return flat.reshape(rows, cols)
