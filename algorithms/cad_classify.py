"""Classifying drawing entities by what the drawing says: door swings (arc + leaf), door and furniture
blocks, pattern hatches."""
from __future__ import annotations

import math
from typing import List, Sequence

import numpy as np

from .model import CadGeometry


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

