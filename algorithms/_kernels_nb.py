"""Compiled (numba) versions of the segmentation's pixel loops. Imported only through
``kernels.py``, which falls back to the numpy code when numba is missing or disabled.

Every kernel is a line-by-line transcription of the numpy code it replaces (same visiting order,
same ties, same synchronous rounds), so its output is identical: tests/test_kernels.py compares
them on random inputs. ``cache=True``: compiled once per machine (into ``__pycache__`` beside this
file, or numba's user cache when that is read-only), not once per process.
"""
import numpy as np
from numba import njit


# --------------------------------------------------------------------------- thinning (skeleton._thin_box)
@njit(cache=True, nogil=True)
def _sweep(img, cand, n, luts, width, flags):
    """Guo-Hall sub-iterations 0, 1, 0, 1, ... on the first ``n`` candidates of ``cand`` until a
    pair removes nothing; the candidates still set are compacted to the front of ``cand`` (order
    kept) and their count returned. Parallel semantics: every sub-iteration judges all candidates
    on the image as it was before it removes any."""
    o0, o1, o2, o3 = 1, 1 - width, -width, -width - 1
    o4, o5, o6, o7 = -1, width - 1, width, width + 1
    while True:
        removed = 0
        for sub in range(2):
            m = 0
            for i in range(n):
                p = cand[i]
                if img[p] == 1:
                    cand[m] = p
                    m += 1
            n = m
            if n == 0:
                return 0
            for i in range(n):
                p = cand[i]
                code = (img[p + o0] | (img[p + o1] << 1) | (img[p + o2] << 2) | (img[p + o3] << 3)
                        | (img[p + o4] << 4) | (img[p + o5] << 5) | (img[p + o6] << 6) | (img[p + o7] << 7))
                flags[i] = luts[sub, code]
            for i in range(n):
                if flags[i]:
                    img[cand[i]] = 0
                    removed += 1
        if removed == 0:
            m = 0
            for i in range(n):
                p = cand[i]
                if img[p] == 1:
                    cand[m] = p
                    m += 1
            return m


@njit(cache=True, nogil=True)
def thin_setup(mask, dist):
    """The padded uint8 image (flat, row width cols + 2) of ``mask``, its pixels' padded positions
    ordered by clearance layer floor(dist) (capped at 65535; raster order inside a layer, as numpy's
    stable argsort) and the layer bounds (``bounds[k]`` = number of pixels of layers below k)."""
    rows, cols = mask.shape
    width = cols + 2
    img = np.zeros((rows + 2) * width, np.uint8)
    n = 0
    top = 0
    for r in range(rows):
        for c in range(cols):
            if mask[r, c]:
                img[(r + 1) * width + c + 1] = 1
                n += 1
                lay = min(int(np.floor(dist[r, c])), 65535)
                if lay > top:
                    top = lay
    count = np.zeros(top + 2, np.int64)
    for r in range(rows):
        for c in range(cols):
            if mask[r, c]:
                count[min(int(np.floor(dist[r, c])), 65535) + 1] += 1
    bounds = np.cumsum(count)
    fill = bounds[:-1].copy()
    pos = np.empty(n, np.int64)
    for r in range(rows):
        for c in range(cols):
            if mask[r, c]:
                lay = min(int(np.floor(dist[r, c])), 65535)
                pos[fill[lay]] = (r + 1) * width + c + 1
                fill[lay] += 1
    return img, pos, bounds


@njit(cache=True, nogil=True)
def thin_layers(img, pos, bounds, k0, k1, luts, width, cand, ncarry, flags):
    """Layers ``k0``..``k1 - 1`` of the layered thinning. ``cand[:ncarry]`` holds the pixels carried
    over from the previous layer (on entry and on return); returns the new carry count."""
    for k in range(k0, k1):
        a, b = bounds[k], bounds[k + 1]
        n = ncarry
        for j in range(a, b):
            cand[n] = pos[j]
            n += 1
        if n == 0:
            continue
        n = _sweep(img, cand, n, luts, width, flags)
        m = 0
        for i in range(n):
            p = cand[i]
            if img[p + 1] != 0 and img[p - 1] != 0 and img[p + width] != 0 and img[p - width] != 0:
                cand[m] = p
                m += 1
        ncarry = m
    return ncarry


@njit(cache=True, nogil=True)
def thin_rest(img, luts, width, flags):
    """The last round of the thinning over every pixel still set."""
    n = 0
    for p in range(img.shape[0]):
        if img[p]:
            n += 1
    cand = np.empty(n, np.int64)
    n = 0
    for p in range(img.shape[0]):
        if img[p]:
            cand[n] = p
            n += 1
    _sweep(img, cand, n, luts, width, flags)


# --------------------------------------------------------------------------- clearance basins (segmentation._cells)
@njit(cache=True, nogil=True)
def ascent_basins(dbox, free_box, markers):
    """Label of the local maximum every free pixel reaches by steepest ascent (8 neighbours, the
    first of the directions (-1,-1), (-1,0), ... (1,1) wins a tie, strictly higher only; outside the
    box counts as -1). A pointer to a pixel that is not free resolves, as numpy's index -1 did, to
    the last free pixel in raster order."""
    R, C = dbox.shape
    N = R * C
    d = dbox.ravel()
    fr = free_box.ravel()
    mk = markers.ravel()
    parent = np.zeros(N, np.int32)
    last_free = -1
    for p in range(N):
        if fr[p]:
            last_free = p
    for r in range(R):
        for c in range(C):
            p = r * C + c
            if not fr[p]:
                continue
            best = d[p]
            step = 0
            for dr in range(-1, 2):
                rr = r + dr
                for dc in range(-1, 2):
                    if dr == 0 and dc == 0:
                        continue
                    cc = c + dc
                    if rr < 0 or rr >= R or cc < 0 or cc >= C:
                        nb = -1.0
                    else:
                        nb = d[rr * C + cc]
                    if nb > best:
                        best = nb
                        step = dr * C + dc
            t = p + step
            parent[p] = t if fr[t] else last_free
    # roots by path halving (the pointers only climb, so every chain ends at a pixel pointing at
    # itself; a cycle, impossible for a clearance, is cut after N steps)
    out = np.zeros(N, np.int32)
    for p in range(N):
        if not fr[p]:
            continue
        q = p
        k = 0
        while parent[q] != q and k < N:
            g = parent[parent[q]]
            parent[q] = g
            q = g
            k += 1
        out[p] = mk[q]
    return out.reshape(R, C)


# --------------------------------------------------------------------------- region growth (skeleton._regrow_orphans)
@njit(cache=True, nogil=True)
def grow_rounds(flat, todo, rows, cols, zflat, label_zone, use_zones):
    """Grow the labels of ``flat`` into the pixels ``todo``, one synchronous 4-neighbour ring per
    round (the first of up, down, left, right that holds a label, of the label's own zone when
    ``use_zones``), until a round labels nothing. ``flat`` is changed in place."""
    n = todo.shape[0]
    cur = todo.copy()
    best = np.zeros(n, np.int32)
    while n > 0:
        got = 0
        for i in range(n):
            p = cur[i]
            r = p // cols
            c = p - r * cols
            b = 0
            for k in range(4):
                if k == 0:
                    rr, cc = r - 1, c
                elif k == 1:
                    rr, cc = r + 1, c
                elif k == 2:
                    rr, cc = r, c - 1
                else:
                    rr, cc = r, c + 1
                if rr < 0 or rr >= rows or cc < 0 or cc >= cols:
                    v = 0
                else:
                    v = flat[rr * cols + cc]
                if use_zones and label_zone[v] != zflat[p]:
                    v = 0
                if v != 0:
                    b = v
                    break
            best[i] = b
            if b > 0:
                got += 1
        if got == 0:
            break
        m = 0
        for i in range(n):
            if best[i] > 0:
                flat[cur[i]] = best[i]
            else:
                cur[m] = cur[i]
                m += 1
        n = m


@njit(cache=True, nogil=True)
def _find(parent, p):
    while parent[p] != p:
        g = parent[parent[p]]
        parent[p] = g
        p = g
    return p


@njit(cache=True, nogil=True)
def orphan_pieces(lab, seeds, space):
    """``space & (lab == 0)``, plus the pieces (4-connected) of every label that has two or more
    pieces and that hold none of that label's own seed pixels (``seeds == label``): what
    ``skeleton._regrow_orphans`` clears, from one union-find pass instead of a labelling per label."""
    R, C = lab.shape
    N = R * C
    parent = np.arange(N).astype(np.int32)
    for r in range(R):
        for c in range(C):
            l = lab[r, c]
            if l <= 0:
                continue
            p = r * C + c
            if c > 0 and lab[r, c - 1] == l:
                a, b = _find(parent, p), _find(parent, p - 1)
                if a != b:
                    if a < b:
                        parent[b] = a
                    else:
                        parent[a] = b
            if r > 0 and lab[r - 1, c] == l:
                a, b = _find(parent, p), _find(parent, p - C)
                if a != b:
                    if a < b:
                        parent[b] = a
                    else:
                        parent[a] = b
    top = 0
    for r in range(R):
        for c in range(C):
            if lab[r, c] > top:
                top = lab[r, c]
    pieces = np.zeros(top + 1, np.int64)
    has = np.zeros(N, np.bool_)
    for r in range(R):
        for c in range(C):
            l = lab[r, c]
            if l <= 0:
                continue
            p = r * C + c
            q = _find(parent, p)
            if q == p:
                pieces[l] += 1
            if seeds[r, c] == l:
                has[q] = True
    out = np.zeros((R, C), np.bool_)
    for r in range(R):
        for c in range(C):
            l = lab[r, c]
            if l == 0:
                out[r, c] = space[r, c]
            elif l > 0 and pieces[l] >= 2 and not has[_find(parent, r * C + c)]:
                out[r, c] = True
    return out


# --------------------------------------------------------------------------- zones (skeleton.nearest_seed_regions)
@njit(cache=True, nogil=True)
def zone_seeds(zn, sd, r0, r1, c0, c1, z):
    """The seed image of zone ``z`` in the box rows r0:r1, cols c0:c1 (uint8: 0 on the zone's seed
    pixels, 1 elsewhere, as ``distanceTransformWithLabels`` takes it) and the seed values in raster
    order after a leading 0 (the labels it gives count the seed pixels in raster order)."""
    R, C = r1 - r0, c1 - c0
    src = np.ones((R, C), np.uint8)
    n = 0
    for r in range(R):
        for c in range(C):
            if zn[r0 + r, c0 + c] == z and sd[r0 + r, c0 + c] != 0:
                n += 1
    vals = np.zeros(n + 1, np.int32)
    n = 0
    for r in range(R):
        for c in range(C):
            if zn[r0 + r, c0 + c] == z:
                v = sd[r0 + r, c0 + c]
                if v != 0:
                    src[r, c] = 0
                    n += 1
                    vals[n] = v
    return src, vals


@njit(cache=True, nogil=True)
def zone_assign(lab, zn, nl, vals, r0, c0, z):
    """``lab`` = the value of the nearest seed (``vals[nl]``) on the pixels of zone ``z``."""
    R, C = nl.shape
    for r in range(R):
        for c in range(C):
            if zn[r0 + r, c0 + c] == z:
                lab[r0 + r, c0 + c] = vals[nl[r, c]]


# --------------------------------------------------------------------------- label borders (segmentation._neighbour_pairs)
@njit(cache=True, nogil=True)
def neighbour_pairs(labels, dist, use_dist):
    """4-neighbour pixel pairs with two different non-zero labels, vertical pairs first, each kind
    in raster order (as ``np.nonzero`` lists them): (lo, hi, min clearance, axis, row, col)."""
    R, C = labels.shape
    n0 = 0
    for r in range(R - 1):
        for c in range(C):
            a, b = labels[r, c], labels[r + 1, c]
            if a != b and a > 0 and b > 0:
                n0 += 1
    n1 = 0
    for r in range(R):
        for c in range(C - 1):
            a, b = labels[r, c], labels[r, c + 1]
            if a != b and a > 0 and b > 0:
                n1 += 1
    n = n0 + n1
    lo = np.empty(n, labels.dtype)
    hi = np.empty(n, labels.dtype)
    v = np.zeros(n, dist.dtype)
    axis = np.empty(n, np.int8)
    rows = np.empty(n, np.int64)
    cols = np.empty(n, np.int64)
    k = 0
    for r in range(R - 1):
        for c in range(C):
            a, b = labels[r, c], labels[r + 1, c]
            if a != b and a > 0 and b > 0:
                lo[k] = min(a, b)
                hi[k] = max(a, b)
                if use_dist:
                    v[k] = min(dist[r, c], dist[r + 1, c])
                axis[k] = 0
                rows[k] = r
                cols[k] = c
                k += 1
    for r in range(R):
        for c in range(C - 1):
            a, b = labels[r, c], labels[r, c + 1]
            if a != b and a > 0 and b > 0:
                lo[k] = min(a, b)
                hi[k] = max(a, b)
                if use_dist:
                    v[k] = min(dist[r, c], dist[r, c + 1])
                axis[k] = 1
                rows[k] = r
                cols[k] = c
                k += 1
    return lo, hi, v, axis, rows, cols


@njit(cache=True, nogil=True)
def label_boxes(labels, n):
    """Bounding boxes of the labels 1..``n`` of ``labels`` (2-D int), one raster pass: row k holds
    (first row, last row + 1, first column, last column + 1) of label k, (0, 0, 0, 0) for a label
    that is absent; labels <= 0 or > n are ignored (``scipy.ndimage.find_objects``)."""
    rows, cols = labels.shape
    box = np.zeros((n + 1, 4), np.int64)
    seen = np.zeros(n + 1, np.bool_)
    for r in range(rows):
        c = 0
        while c < cols:  # run by run: a label's box changes only at its runs' ends
            v = labels[r, c]
            start = c
            c += 1
            while c < cols and labels[r, c] == v:
                c += 1
            if v <= 0 or v > n:
                continue
            if not seen[v]:
                seen[v] = True
                box[v, 0] = r
                box[v, 2] = start
                box[v, 3] = c
            else:
                if start < box[v, 2]:
                    box[v, 2] = start
                if c > box[v, 3]:
                    box[v, 3] = c
            box[v, 1] = r + 1
    return box, seen
