"""Pixel-level evaluation of a room segmentation against a ground-truth colour image.

The ground truth paints every room in its own colour; pure greys (r = g = b: white / grey
outside, black walls), very dark colours (walls drawn with a slight tint) and colours covering
fewer than ``min_room_px`` pixels (anti-aliased edges) are not rooms.

For every ground-truth room G the *best* predicted segment S is the one with the largest overlap:

* recall = |G & S| / |G|, precision = |G & S| / |S|;
* MCC of the two binary masks over the evaluated pixels E = (all GT rooms) | (all predicted areas);
  the map's MCC is the mean over rooms weighted by room area;
* F1 of rooms matched one-to-one at IoU >= 0.5 (such a match is unique by construction). Predicted
  segments that lie mostly outside the annotated rooms are not judged (unannotated space such as
  a courtyard is neither right nor wrong).
"""
from __future__ import annotations

import math
from typing import Dict, List

import numpy as np

from .errors import InputError

MIN_ROOM_PX = 200
DARK = 50  # colours whose brightest channel is below this are wall ink, not rooms


def gt_rooms(gt_image: np.ndarray, min_room_px: int = MIN_ROOM_PX) -> np.ndarray:
    """int32 raster of ground-truth room ids (1..n, 0 = not a room) from a colour image."""
    img = np.asarray(gt_image)
    if img.ndim == 2:
        raise InputError("the ground truth must be a colour image (one colour per room); got a single band")
    if img.ndim != 3 or img.shape[2] < 3:
        raise InputError(f"unsupported ground-truth image shape {img.shape}")
    img = img[:, :, :3].astype(np.int64)
    code = (img[:, :, 0] << 16) | (img[:, :, 1] << 8) | img[:, :, 2]
    colours, inv, counts = np.unique(code.ravel(), return_inverse=True, return_counts=True)
    r, g, b = colours >> 16, (colours >> 8) & 255, colours & 255
    grey = (r == g) & (g == b)
    dark = np.maximum(np.maximum(r, g), b) < DARK
    is_room = ~grey & ~dark & (counts >= min_room_px)
    ids = np.zeros(len(colours), np.int32)
    ids[is_room] = np.arange(1, int(is_room.sum()) + 1, dtype=np.int32)
    return ids[inv].reshape(code.shape)


def _mcc(tp: float, fp: float, fn: float, tn: float) -> float:
    den = (tp + fp) * (tp + fn) * (tn + fp) * (tn + fn)
    if den <= 0:
        return 0.0
    return float((tp * tn - fp * fn) / math.sqrt(den))


def evaluate(labels: np.ndarray, gt_image: np.ndarray, min_room_px: int = MIN_ROOM_PX) -> Dict:
    """Compare a label raster (0 = no area) with a ground-truth colour image of the same size.

    Returns a dict: ``rooms`` (list of per-room dicts: gt id, pixels, best segment, recall,
    precision, iou, mcc), ``recall`` / ``precision`` (mean over rooms), ``mcc`` (area-weighted),
    ``f1`` / ``f1_precision`` / ``f1_recall`` (rooms matched at IoU >= 0.5), ``n_gt``, ``n_pred``.
    """
    labels = np.asarray(labels)
    if labels.ndim != 2:
        raise InputError(f"the label raster must be 2-D, got shape {labels.shape}")
    if tuple(np.asarray(gt_image).shape[:2]) != tuple(labels.shape):
        raise InputError(f"ground truth is {np.asarray(gt_image).shape[1]} x {np.asarray(gt_image).shape[0]} px but "
                         f"the labels are {labels.shape[1]} x {labels.shape[0]} px: they must be the same grid")
    gt = gt_rooms(gt_image, min_room_px)
    n_gt = int(gt.max())
    pred_ids, pred = np.unique(labels.astype(np.int64), return_inverse=True)
    pred = pred.reshape(labels.shape)
    # pred index 0 corresponds to label 0 only if 0 is present
    zero_present = pred_ids[0] == 0
    n_pred = len(pred_ids)
    cont = np.bincount(gt.ravel().astype(np.int64) * n_pred + pred.ravel(),
                       minlength=(n_gt + 1) * n_pred).reshape(n_gt + 1, n_pred)
    valid_pred = np.ones(n_pred, bool)
    if zero_present:
        valid_pred[0] = False
    gt_size = cont.sum(axis=1)
    pred_size = cont.sum(axis=0)
    evaluated = int(gt_size[1:].sum() + cont[0, valid_pred].sum())
    rooms: List[Dict] = []
    for g in range(1, n_gt + 1):
        row = np.where(valid_pred, cont[g], 0)
        size = int(gt_size[g])
        if row.max() <= 0:
            rooms.append(dict(gt=g, pixels=size, segment=0, recall=0.0, precision=0.0, iou=0.0, mcc=0.0))
            continue
        s = int(np.argmax(row))
        tp = float(row[s])
        fp = float(pred_size[s]) - tp
        fn = size - tp
        tn = evaluated - tp - fp - fn
        rooms.append(dict(gt=g, pixels=size, segment=int(pred_ids[s]), recall=tp / size,
                          precision=tp / float(pred_size[s]), iou=tp / (size + pred_size[s] - tp),
                          mcc=_mcc(tp, fp, fn, tn)))
    total = sum(r["pixels"] for r in rooms)
    mcc = sum(r["mcc"] * r["pixels"] for r in rooms) / total if total else 0.0
    # one-to-one matches at IoU >= 0.5
    inter = cont[1:, :].astype(np.float64)
    union = gt_size[1:, None] + pred_size[None, :] - inter
    iou = np.where(union > 0, inter / np.maximum(union, 1), 0.0)
    iou[:, ~valid_pred] = 0.0
    matched = int((iou >= 0.5).sum())
    on_rooms = cont[1:, :].sum(axis=0)
    judged = valid_pred & (on_rooms * 2 >= pred_size) & (pred_size > 0)
    n_judged = int(judged.sum())
    f1p = matched / n_judged if n_judged else 0.0
    f1r = matched / n_gt if n_gt else 0.0
    f1 = 2 * f1p * f1r / (f1p + f1r) if (f1p + f1r) > 0 else 0.0
    return dict(rooms=rooms, n_gt=n_gt, n_pred=int(valid_pred.sum()),
                recall=float(np.mean([r["recall"] for r in rooms])) if rooms else 0.0,
                precision=float(np.mean([r["precision"] for r in rooms])) if rooms else 0.0,
                mcc=float(mcc), f1=float(f1), f1_precision=float(f1p), f1_recall=float(f1r), matched=matched)


def read_gt_image(path: str) -> np.ndarray:
    import cv2

    img = cv2.imread(str(path), cv2.IMREAD_COLOR)
    if img is None:
        raise InputError(f"cannot read ground-truth image '{path}'")
    return img[:, :, ::-1].copy()  # RGB


def read_labels(path: str) -> np.ndarray:
    from osgeo import gdal

    gdal.UseExceptions()
    try:
        ds = gdal.Open(str(path))
    except RuntimeError as exc:
        raise InputError(f"cannot open label raster '{path}': {exc}") from exc
    if ds.RasterCount != 1:
        raise InputError(f"'{path}' has {ds.RasterCount} bands; a label raster has one")
    arr = ds.GetRasterBand(1).ReadAsArray()
    gt = ds.GetGeoTransform()
    if gt and gt[5] > 0:
        arr = arr[::-1]
    return arr.astype(np.int64)


def evaluate_files(labels_path: str, gt_path: str, min_room_px: int = MIN_ROOM_PX) -> Dict:
    """``evaluate`` on a label raster file (GeoTIFF/PNG) and a ground-truth colour image."""
    return evaluate(read_labels(labels_path), read_gt_image(gt_path), min_room_px)
