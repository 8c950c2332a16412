"""Segmentation metrics against a ground-truth colour image."""
import math

import cv2
import numpy as np
import pytest

from algorithms.errors import InputError
from algorithms.evaluate import evaluate, evaluate_files, gt_rooms
from algorithms.raster_io import write_geotiff

COLOURS = [(240, 116, 248), (41, 230, 232), (251, 119, 13), (13, 251, 192)]


def _gt():
    """Four rooms in four colours, black walls, white outside and a grey border."""
    img = np.full((100, 120, 3), 255, np.uint8)
    img[:5] = (153, 153, 153)
    img[10:90, 10:110] = 0  # walls
    img[11:49, 11:59] = COLOURS[0]  # 38 x 48
    img[11:49, 61:109] = COLOURS[1]
    img[51:89, 11:59] = COLOURS[2]
    img[51:89, 61:109] = COLOURS[3]
    img[30, 30] = (200, 10, 10)  # a lone anti-aliased pixel: not a room
    return img


def _perfect_labels(img):
    lab = np.zeros(img.shape[:2], np.int32)
    for i, c in enumerate(COLOURS):
        lab[(img == c).all(-1)] = i + 1
    lab[30, 30] = 1
    return lab


def test_gt_rooms_parsing():
    rooms = gt_rooms(_gt(), min_room_px=50)
    assert rooms.max() == 4
    assert rooms[0, 0] == 0 and rooms[2, 2] == 0 and rooms[10, 10] == 0 and rooms[30, 30] == 0
    assert len(np.unique(rooms[11:49, 11:59])) == 2  # room 1 and the speck


def test_perfect_segmentation():
    img = _gt()
    ev = evaluate(_perfect_labels(img), img, min_room_px=50)
    assert ev["n_gt"] == 4 and ev["n_pred"] == 4
    assert ev["mcc"] == pytest.approx(1.0, abs=1e-3)
    assert ev["f1"] == 1.0
    assert ev["recall"] == pytest.approx(1.0, abs=1e-3)
    assert ev["precision"] == pytest.approx(1.0, abs=1e-3)  # the speck pixel is not annotated


def test_merged_rooms_figures():
    img = _gt()
    lab = _perfect_labels(img)
    lab[lab == 2] = 1  # two rooms predicted as one
    ev = evaluate(lab, img, min_room_px=50)
    n = 38 * 48
    # room 1 (minus the speck pixel) matches the merged segment (2n pixels)
    room1 = ev["rooms"][gt_rooms(img, 50)[20, 20] - 1]
    assert room1["pixels"] == n - 1
    assert room1["recall"] == pytest.approx(1.0)
    assert room1["precision"] == pytest.approx((n - 1) / (2 * n))
    # MCC by hand: evaluated pixels = the four rooms (4n)
    tp, fp, fn = n - 1, n + 1, 0
    tn = 4 * n - tp - fp - fn
    mcc = (tp * tn - fp * fn) / math.sqrt((tp + fp) * (tp + fn) * (tn + fp) * (tn + fn))
    assert room1["mcc"] == pytest.approx(mcc, rel=1e-6)
    # room 2 reaches IoU = n / 2n = 0.5 exactly (a match), room 1 (n-1)/2n does not: 3 of 4 matched
    assert ev["matched"] == 3
    p, r = 3 / 3, 3 / 4
    assert ev["f1"] == pytest.approx(2 * p * r / (p + r))
    assert 0 < ev["mcc"] < 1


def test_missing_room_and_unannotated_segments():
    img = _gt()
    lab = _perfect_labels(img)
    lab[lab == 4] = 0  # room 4 not segmented
    lab[95:100, 0:120] = 9  # a segment outside every annotated room is not judged
    ev = evaluate(lab, img, min_room_px=50)
    room4 = ev["rooms"][gt_rooms(img, 50)[60, 80] - 1]
    assert room4["recall"] == 0 and room4["mcc"] == 0
    assert ev["f1_recall"] == pytest.approx(3 / 4)
    assert ev["f1_precision"] == pytest.approx(1.0)


def test_size_mismatch_and_bad_gt():
    img = _gt()
    with pytest.raises(InputError, match="same grid"):
        evaluate(np.zeros((50, 50), np.int32), img)
    with pytest.raises(InputError, match="colour"):
        evaluate(np.zeros((100, 120), np.int32), img[:, :, 0])


def test_evaluate_files(tmp_path):
    img = _gt()
    gt_path = tmp_path / "gt.png"
    cv2.imwrite(str(gt_path), img[:, :, ::-1])
    lab_path = tmp_path / "labels.tif"
    write_geotiff(str(lab_path), _perfect_labels(img), 0.0, 5.0, 0.05)
    ev = evaluate_files(str(lab_path), str(gt_path), min_room_px=50)
    assert ev["mcc"] == pytest.approx(1.0, abs=1e-3) and ev["f1"] == 1.0
    with pytest.raises(InputError):
        evaluate_files(str(tmp_path / "missing.tif"), str(gt_path))


@pytest.mark.slow
def test_grid_gt_images_match_inputs(shared_data):
    """The ground-truth images are exactly the size of the input grids."""
    folder = shared_data / "grid_gt"
    for gt in sorted((folder / "gt").glob("*.png")):
        a = cv2.imread(str(folder / "input" / gt.name), cv2.IMREAD_UNCHANGED)
        b = cv2.imread(str(gt), cv2.IMREAD_UNCHANGED)
        assert a.shape[:2] == b.shape[:2], gt.name
        assert 10 <= gt_rooms(b[:, :, ::-1]).max() <= 60, gt.name
