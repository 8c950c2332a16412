"""Issue 13: skeleton_graph measures its chains from the skeleton pixels, not by whole-raster comparisons
of the label box; the lengths must be the same, bit for bit (random 8-connected label sets, labels
touching each other, at the raster border)."""
import numpy as np
import pytest

from algorithms.skeleton import SQRT2, _chain_lengths


def _chain_lengths_raster(labels: np.ndarray, n: int) -> np.ndarray:
    """``_chain_lengths`` by whole-raster comparisons (the code it replaced: the reference it is compared with)."""
    length = np.zeros(n + 1)
    a = labels
    for dr, dc, w in ((0, 1, 1.0), (1, 0, 1.0)):
        x, y = a[:a.shape[0] - dr, :a.shape[1] - dc], a[dr:, dc:]
        same = (x == y) & (x > 0)
        length += w * np.bincount(x[same], minlength=n + 1)
    for dc in (1, -1):
        if dc == 1:
            x, y = a[:-1, :-1], a[1:, 1:]
            p, q = a[:-1, 1:], a[1:, :-1]  # the two 4-neighbours shared by the diagonal pair
        else:
            x, y = a[:-1, 1:], a[1:, :-1]
            p, q = a[:-1, :-1], a[1:, 1:]
        same = (x == y) & (x > 0) & (p != x) & (q != x)
        length += SQRT2 * np.bincount(x[same], minlength=n + 1)
    return length


@pytest.mark.parametrize("seed", range(6))
def test_chain_lengths_from_the_pixels_equal_the_whole_raster_comparison(seed):
    import cv2

    rng = np.random.default_rng(seed)
    shape = (int(rng.integers(20, 90)), int(rng.integers(20, 90)))
    lines = np.zeros(shape, np.uint8)
    for _ in range(25):  # random thin polylines, diagonal and straight, some over the border
        pts = rng.integers(-5, max(shape) + 5, size=(3, 2)).astype(np.int32)
        cv2.polylines(lines, [pts], False, 1, thickness=1, lineType=cv2.LINE_8)
    n, lab = cv2.connectedComponents(lines, connectivity=8, ltype=cv2.CV_32S)
    lab = np.where(rng.random(shape) < 0.05, (lab * 7) % max(n, 2), lab).astype(np.int32)  # mixed labels
    m = int(lab.max())
    ref = _chain_lengths_raster(lab, m)
    assert np.array_equal(_chain_lengths(lab, m), ref)
    assert np.array_equal(_chain_lengths(lab, m, np.flatnonzero(lab)), ref)
    assert ref[1:].sum() > 0


def test_chain_lengths_of_single_pixels_and_an_empty_raster():
    lab = np.zeros((5, 6), np.int32)
    assert np.array_equal(_chain_lengths(lab, 0), np.zeros(1))
    lab[0, 0] = 1
    lab[4, 5] = 2
    lab[2, 2:5] = 3  # 2 steps
    lab[1, 1] = 3  # a diagonal step onto the row: sqrt(2)
    got = _chain_lengths(lab, 3)
    assert np.array_equal(got, _chain_lengths_raster(lab, 3))
    assert got[1] == got[2] == 0 and got[3] == pytest.approx(2 + np.sqrt(2))


def _zoned_seeds(seed):
    """A 240 x 300 space with walls and holes, 120 zones (blocks of 20 x 30 px, some cut in two by a wall),
    2-4 labels seeded in most zones (each label's seeds inside its zone)."""
    rng = np.random.default_rng(seed)
    space = rng.random((240, 300)) > 0.08
    space[::37, :] = False
    zones = (np.arange(240)[:, None] // 20) * 10 + np.arange(300)[None, :] // 30 + 1
    zones = np.where(space, zones, 0).astype(np.int32)
    seeds = np.zeros(space.shape, np.int32)
    lid = 0
    for z in range(1, 121):
        rr, cc = np.nonzero(zones == z)
        if len(rr) == 0 or rng.random() < 0.1:
            continue
        for _ in range(int(rng.integers(2, 5))):
            lid += 1
            k = rng.integers(0, len(rr), size=int(rng.integers(1, 6)))
            seeds[rr[k], cc[k]] = lid
    return seeds, space, zones


@pytest.mark.parametrize("seed", range(2))
def test_nearest_seed_regions_shared_by_two_threads_equal_one_thread_and_numpy(seed, monkeypatch):
    """From ZONES_SPLIT zones on, two threads share the zones' transforms (each writes its own zone's
    pixels): the same regions as one thread and as the numpy path."""
    from algorithms import kernels, segmentation
    from algorithms.skeleton import ZONES_SPLIT, nearest_seed_regions

    seeds, space, zones = _zoned_seeds(seed)
    assert len(np.unique(zones)) - 1 >= ZONES_SPLIT
    monkeypatch.setattr(segmentation, "_cpus", lambda: 2)
    got = {}
    try:
        for name, env, compiled in (("two", "2", True), ("one", "1", True), ("numpy", "2", False)):
            monkeypatch.setenv("CAD2OSMAG_THREADS", env)
            kernels.set_enabled(compiled)
            if compiled and kernels.get() is None:
                pytest.skip("numba not available")
            got[name] = nearest_seed_regions(seeds, space, zones=zones)
    finally:
        kernels.set_enabled(None)
    assert np.array_equal(got["two"], got["one"]) and np.array_equal(got["two"], got["numpy"])
    assert (got["two"][space] > 0).mean() > 0.9
