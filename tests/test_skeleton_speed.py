"""Issue 13: skeleton_graph measures its chains from the skeleton pixels, not by whole-raster comparisons
of the label box; the lengths must be the same, bit for bit (random 8-connected label sets, labels
touching each other, at the raster border)."""
import numpy as np
import pytest

from algorithms.skeleton import _chain_lengths, _chain_lengths_raster


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
