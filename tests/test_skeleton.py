"""Skeleton graph of the free space (algorithms/skeleton.py) on small synthetic shapes (quick tests)."""
import numpy as np
import pytest

from algorithms import segmentation as seg
from algorithms.model import FREE, OCCUPIED, OccupancyGrid
from algorithms.skeleton import nearest_seed_regions, skeleton_graph, thin


def plus(res, width=2.0, span=10.0):
    """A plus-shaped corridor: two corridors ``width`` m wide and ``span`` m long crossing."""
    n, w = int(round(span / res)), int(round(width / res))
    m = np.zeros((n + 2, n + 2), bool)
    c = (n + 2) // 2 - w // 2
    m[1:-1, c:c + w] = True
    m[c:c + w, 1:-1] = True
    return m


def notched(res, width, notch_w, notch_d, length=6.0):
    """A straight corridor with a recess of ``notch_w`` x ``notch_d`` m in one wall, mid-length."""
    w, n = int(round(width / res)), int(round(length / res))
    a, d = int(round(notch_w / res)), int(round(notch_d / res))
    m = np.zeros((w + d + 4, n + 4), bool)
    m[2 + d:2 + d + w, 2:2 + n] = True
    c = 2 + n // 2
    m[2:2 + d, c - a // 2:c - a // 2 + a] = True
    return m


def test_plus_is_four_dead_ends_one_junction_four_edges():
    res = 0.05
    g = skeleton_graph(plus(res), res)
    assert g.n_nodes == 5 and g.n_edges == 4
    assert g.dead_ends == 4 and g.junctions == 1
    assert sorted(g.node_degree.tolist()) == [1, 1, 1, 1, 4]
    centre = int(np.argmax(g.node_degree))
    assert all(centre in uv for uv in g.edge_nodes.tolist())
    # dead ends lie on the corridor axis, half the width from the walls (within a pixel)
    ends = g.node_degree == 1
    assert np.allclose(g.node_clearance_m[ends], 1.0, atol=res)
    assert g.node_clearance_m[centre] >= 1.0  # the crossing is wider than the corridors
    # each arm: from 1 m before its end (the dead end) to the centre
    assert np.allclose(g.edge_length_m, 4.0, atol=2 * res)
    assert (g.edge_min_clearance_m >= 1.0 - res).all()
    assert (g.edge_max_clearance_m <= g.node_clearance_m[centre] + 1e-9).all()
    # the skeleton is one pixel thick and lies in the free space
    sk = thin(plus(res))
    assert sk.sum() == sum(len(p) for p in g.edge_pixels) + sum(len(p) for p in g.node_pixels)
    assert not (sk & ~plus(res)).any()


def test_short_spur_pruned_long_spur_kept():
    res = 0.05
    short = notched(res, 0.4, 0.4, 0.25)  # a recess makes a ~0.15 m branch
    g0 = skeleton_graph(short, res, prune=0.0)
    assert (g0.n_edges, g0.dead_ends, g0.junctions, g0.pruned) == (3, 3, 1, 0)
    assert min(g0.edge_length_m) < 0.25
    g = skeleton_graph(short, res)  # PRUNE = 0.25 m
    assert (g.n_edges, g.n_nodes, g.dead_ends, g.junctions, g.pruned) == (1, 2, 2, 0, 1)
    assert g.edge_length_m[0] == pytest.approx(sum(g0.edge_length_m) - min(g0.edge_length_m), abs=3 * res)
    long_ = notched(res, 1.0, 0.4, 0.25)  # the same recess in a wider corridor: a ~0.5 m branch
    g = skeleton_graph(long_, res)
    assert (g.n_edges, g.pruned) == (3, 0)
    g = skeleton_graph(long_, res, prune=1.0)
    assert (g.n_edges, g.pruned) == (1, 1)


@pytest.mark.parametrize("shape", ["plus", "short", "long"])
def test_pruning_in_metres_same_graph_at_two_resolutions(shape):
    make = {"plus": lambda r: plus(r), "short": lambda r: notched(r, 0.4, 0.4, 0.25),
            "long": lambda r: notched(r, 1.0, 0.4, 0.25)}[shape]
    graphs = [skeleton_graph(make(r), r, prune=0.25) for r in (0.05, 0.025)]
    a, b = graphs
    assert (a.n_nodes, a.n_edges, a.pruned) == (b.n_nodes, b.n_edges, b.pruned)
    assert sorted(a.node_degree.tolist()) == sorted(b.node_degree.tolist())
    assert np.allclose(np.sort(a.edge_length_m), np.sort(b.edge_length_m), atol=0.1)
    assert np.allclose(np.sort(a.node_clearance_m), np.sort(b.node_clearance_m), atol=0.05)


def test_edge_regions_cover_the_space_once_and_are_closest():
    res = 0.05
    m = plus(res)
    g = skeleton_graph(m, res)
    regions = nearest_seed_regions(g.edge_raster(lone_nodes=True), m)
    assert (regions[m] > 0).all() and (regions[~m] == 0).all()  # every free pixel in exactly one region
    assert set(np.unique(regions[m]).tolist()) == set(range(1, g.n_edges + 1))
    # a pixel of an arm belongs to that arm's edge
    rows, cols = m.shape
    for j, px in enumerate(g.edge_pixels):
        r, c = np.mean(px // cols), np.mean(px % cols)
        assert regions[int(round(r)), int(round(c))] == j + 1
    # the closest edge pixel, checked on a sample of pixels
    er = g.edge_raster()
    er_r, er_c = np.nonzero(er)
    fr, fc = np.nonzero(m)
    for k in range(0, len(fr), 997):
        d2 = (er_r - fr[k]) ** 2 + (er_c - fc[k]) ** 2
        best = er[er_r, er_c][d2 <= d2.min() + 2 * np.sqrt(d2.min()) + 2]  # ties within the 5x5 metric error
        assert regions[fr[k], fc[k]] in set(best.tolist())


def test_regions_do_not_cross_walls():
    """A wide room beside a narrow corridor: the room pixels along the wall are closer to the corridor's
    skeleton as the crow flies, but they are reached through the room."""
    res = 0.05
    m = np.zeros((140, 200), bool)
    m[2:102, 2:198] = True  # room 5 m deep
    m[106:126, 2:198] = True  # corridor 1 m wide behind a 0.2 m wall
    m[102:106, 90:110] = True  # a door
    g = skeleton_graph(m, res)
    regions = nearest_seed_regions(g.edge_raster(lone_nodes=True), m)
    assert (regions[m] > 0).all()
    room_ids = set(np.unique(regions[2:102, 2:198]).tolist())
    corridor_ids = set(np.unique(regions[110:126, 2:80]).tolist())
    assert not room_ids & corridor_ids
    # each region is one 4-connected piece
    import cv2
    for lab in np.unique(regions[m]):
        n, _ = cv2.connectedComponents((regions == lab).view(np.uint8), connectivity=4)
        assert n == 2, lab


def test_loop_around_a_pillar_and_lone_blob():
    res = 0.05
    m = np.zeros((100, 100), bool)
    m[10:90, 10:90] = True
    m[40:60, 40:60] = False  # pillar
    m[95:98, 95:98] = True  # a 3x3 px pocket: its skeleton is one node without edges
    g = skeleton_graph(m, res)
    sk = thin(m)
    import cv2
    n, _ = cv2.connectedComponents((~sk[5:93, 5:93]).view(np.uint8), connectivity=4)
    assert n - 1 == 2  # the skeleton still surrounds the pillar
    assert (g.node_degree == 0).sum() == 1
    regions = nearest_seed_regions(g.edge_raster(lone_nodes=True), m)
    assert (regions[m] > 0).all()
    ring = [j for j, (u, v) in enumerate(g.edge_nodes.tolist()) if u == v]
    assert ring
    path = g.edge_path(ring[0])
    assert (np.abs(np.diff(path, axis=0)).max(axis=1) == 1).all() and (path[0] == path[-1]).all()


def test_deterministic():
    res = 0.05
    m = notched(res, 1.0, 0.4, 0.25)
    a = skeleton_graph(m, res, prune=0.0)
    b = skeleton_graph(m.copy(), res, prune=0.0)
    assert [p.tolist() for p in a.edge_pixels] == [p.tolist() for p in b.edge_pixels]
    assert a.edge_nodes.tolist() == b.edge_nodes.tolist()
    assert np.array_equal(a.edge_length_m, b.edge_length_m)
    path = a.edge_path(0)
    assert len(path) >= len(a.edge_pixels[0])
    steps = np.abs(np.diff(path, axis=0)).max(axis=1)
    assert (steps == 1).all()  # a connected pixel chain


def test_segment_reports_the_skeleton():
    res = 0.05
    data = np.full((160, 160), OCCUPIED, np.uint8)
    data[4:156, 4:156][plus(res, width=2.0, span=7.5)] = FREE
    ag = seg.segment(OccupancyGrid(data, 0.0, 8.0, res), door_width=1.0, corridor_width=2.0)
    st = ag.stats
    assert (st["skeleton_nodes"], st["skeleton_edges"], st["skeleton_junctions"], st["skeleton_dead_ends"]) == \
        (5, 4, 1, 4)
    assert st["skeleton_pruned"] == 0
    assert st["regions"] >= 4  # at least one region per skeleton edge
    assert seg.skeleton_graph is skeleton_graph


def test_edge_lines_follow_the_edges():
    res = 0.05
    g = skeleton_graph(plus(res), res)
    gt = (100.0, res, 0.0, 50.0, 0.0, -res)
    lines = g.edge_lines(gt)
    assert len(lines) == g.n_edges
    for line, length in zip(lines, g.edge_length_m):
        assert line.is_simple
        assert line.length == pytest.approx(length, abs=3 * res)


def test_segmentation_regions_are_skeleton_edge_pieces():
    """segment's initial partition: one region per skeleton edge piece (edges split at the clearance
    valleys), every free pixel in exactly one; a branch PRUNE removes takes its region with it."""
    res = 0.05
    m = notched(res, 0.4, 0.4, 0.25)
    dist = seg._edt(m)
    counts = {}
    for prune in (0.0, 0.25):
        g = skeleton_graph(m, res, prune=prune, dist=dist)
        regions, peak, _ = seg._edge_regions(g, m, dist)
        assert (regions[m] > 0).all() and (regions[~m] == 0).all()
        assert len(peak) == regions.max() + 1
        er = g.edge_raster()
        for lab in range(1, regions.max() + 1):
            edges = set(np.unique(er[(regions == lab) & (er > 0)]).tolist())
            assert len(edges) == 1, (prune, lab, edges)  # a region holds a piece of one edge
        counts[prune] = (g.n_edges, int(regions.max()))
    assert counts[0.0][0] == 3 and counts[0.25][0] == 1
    assert counts[0.0][1] > counts[0.25][1]
