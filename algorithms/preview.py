"""Overlay picture of an Area Graph: areas in colours, walls black, passages red, ids at centroids."""
from __future__ import annotations

import os

import numpy as np

from .io_utils import atomic_path
from .model import OCCUPIED, UNKNOWN, AreaGraph, OccupancyGrid


def _palette(n: int) -> np.ndarray:
    """Deterministic distinct pastel colours (BGR) for ids 0..n."""
    rng = np.random.default_rng(12345)
    cols = rng.integers(70, 240, size=(n + 1, 3)).astype(np.uint8)
    cols[0] = (255, 255, 255)
    return cols


TYPE_SUFFIX = {"corridor": "c", "stairs": " stairs", "elevator": " lift"}  # appended to the area id label


def render_image(grid: OccupancyGrid, area_graph: AreaGraph, max_size: int = 2000) -> np.ndarray:
    """The overlay as a BGR uint8 image, scaled so its longer side is at most ``max_size``."""
    import cv2

    data = grid.data
    labels = area_graph.labels if area_graph.labels is not None else np.zeros(data.shape, np.int32)
    scale = min(1.0, float(max_size) / max(data.shape))
    if scale < 1.0:
        size = (max(1, int(round(data.shape[1] * scale))), max(1, int(round(data.shape[0] * scale))))
        labels_s = cv2.resize(labels.astype(np.int32), size, interpolation=cv2.INTER_NEAREST)
        occ = cv2.resize((data == OCCUPIED).astype(np.uint8) * 255, size, interpolation=cv2.INTER_AREA) > 40
        unk = cv2.resize((data == UNKNOWN).astype(np.uint8), size, interpolation=cv2.INTER_NEAREST) > 0
    else:
        labels_s, occ, unk = labels, data == OCCUPIED, data == UNKNOWN
    pal = _palette(int(labels.max()) if labels.size else 0)
    img = pal[np.clip(labels_s, 0, len(pal) - 1)]
    img[(labels_s == 0) & unk] = (200, 200, 200)
    img[occ] = (0, 0, 0)

    def to_px(x, y):
        col, row = grid.world_to_pixel(x, y)
        return int(round(float(col) * scale)), int(round(float(row) * scale))

    thick = max(1, int(round(2 * max(1.0, scale * 2))))
    for p in area_graph.passages:
        (x0, y0), (x1, y1) = list(p.line.coords)[:2]
        cv2.line(img, to_px(x0, y0), to_px(x1, y1), (0, 0, 230), thick, cv2.LINE_AA)
        for x, y in ((x0, y0), (x1, y1)):
            cv2.circle(img, to_px(x, y), thick + 1, (0, 0, 160), -1, cv2.LINE_AA)
    font_scale = max(0.3, min(1.0, max(img.shape) / 2500.0))
    for a in area_graph.areas:
        pt = a.polygon.representative_point()
        c, r = to_px(pt.x, pt.y)
        txt = f"{a.id}{TYPE_SUFFIX.get(a.type, '')}"
        cv2.putText(img, txt, (c - 6, r + 4), cv2.FONT_HERSHEY_SIMPLEX, font_scale, (40, 40, 40), 1, cv2.LINE_AA)
    return img


def render_preview(grid: OccupancyGrid, area_graph: AreaGraph, path: str, max_size: int = 2000) -> str:
    """Write the overlay picture to ``path`` (PNG, atomically). Returns ``path``."""
    import cv2

    img = render_image(grid, area_graph, max_size)
    with atomic_path(str(path), suffix=os.path.splitext(str(path))[1] or ".png") as tmp:
        if not cv2.imwrite(tmp, img):
            raise OSError(f"cannot write preview '{path}'")
    return str(path)
