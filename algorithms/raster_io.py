"""Reading and writing occupancy rasters.

Formats: GeoTIFF (our own output, any single-band GDAL raster), PNG/PGM images with an explicit
resolution, and ROS ``map_server`` maps (``map.yaml`` + image, honouring resolution, origin,
negate, occupied_thresh, free_thresh and mode). Everything comes back as an ``OccupancyGrid`` with
the 0 free / 255 occupied / 128 unknown convention.

Our occupancy GeoTIFFs carry the metadata item ``CAD2OSMAG_OCCUPANCY`` and are read as they are.
Any other raster (a GeoTIFF from another tool, a PNG, a ROS image) follows the image convention of
robot maps: dark = occupied, light = free, mid grey = unknown; there the same 0/255 values mean the
opposite, so the tag, not the values, decides.
"""
from __future__ import annotations

import math
import os
from typing import Optional

import numpy as np

from .errors import InputError
from .io_utils import atomic_path
from .model import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

OCCUPANCY_TAG = "CAD2OSMAG_OCCUPANCY"
OCCUPANCY_METADATA = {OCCUPANCY_TAG: f"{FREE}=free {OCCUPIED}=occupied {UNKNOWN}=unknown"}


def _gdal():
    from osgeo import gdal  # Debian's python3-gdal (a dependency of QGIS)

    gdal.UseExceptions()
    return gdal


def write_geotiff(path: str, data: np.ndarray, origin_x: float, origin_y: float, resolution: float,
                  crs_wkt: str = "", nodata: Optional[float] = None, metadata: Optional[dict] = None) -> str:
    """Write a single-band north-up GeoTIFF atomically (temp file + rename). Returns ``path``.
    ``metadata``: GDAL metadata items (``OCCUPANCY_METADATA`` marks an occupancy grid)."""
    gdal = _gdal()
    if data.ndim != 2:
        raise InputError(f"expected a single-band 2-D array, got shape {data.shape}")
    dtype_map = {np.dtype(np.uint8): gdal.GDT_Byte, np.dtype(np.int32): gdal.GDT_Int32,
                 np.dtype(np.uint16): gdal.GDT_UInt16, np.dtype(np.float32): gdal.GDT_Float32}
    if data.dtype not in dtype_map:
        raise InputError(f"unsupported raster dtype {data.dtype}")
    with atomic_path(path, suffix=".tif") as tmp:
        drv = gdal.GetDriverByName("GTiff")
        ds = drv.Create(tmp, int(data.shape[1]), int(data.shape[0]), 1, dtype_map[data.dtype],
                        options=["COMPRESS=DEFLATE", "TILED=YES"])
        ds.SetGeoTransform((float(origin_x), float(resolution), 0.0, float(origin_y), 0.0, -float(resolution)))
        if metadata:
            ds.SetMetadata({str(k): str(v) for k, v in metadata.items()})
        if crs_wkt:
            ds.SetProjection(crs_wkt)
        band = ds.GetRasterBand(1)
        if nodata is not None:
            band.SetNoDataValue(nodata)
        band.WriteArray(data)
        band.FlushCache()
        ds = None  # close before rename
    return path


def write_grid(path: str, grid: OccupancyGrid) -> str:
    return write_geotiff(path, grid.data, grid.origin_x, grid.origin_y, grid.resolution, grid.crs_wkt,
                         metadata=OCCUPANCY_METADATA)


def _classify(img: np.ndarray, negate: bool = False, occupied_thresh: float = 0.65,
              free_thresh: float = 0.196) -> np.ndarray:
    """ROS map_server 'trinary' interpretation of a grey image -> FREE/OCCUPIED/UNKNOWN."""
    img = img.astype(np.float64)
    maxv = 255.0 if img.max(initial=0) <= 255 else float(img.max())
    p = img / maxv if negate else (maxv - img) / maxv  # occupancy probability
    out = np.full(img.shape, UNKNOWN, np.uint8)
    out[p > occupied_thresh] = OCCUPIED
    out[p < free_thresh] = FREE
    return out


def check_grid_size(path: str, rows: int, cols: int, resolution: Optional[float] = None) -> None:
    """Raise InputError before an occupancy raster is read when segmenting it would need more memory than
    the machine has available (the same budget as ``rasterize.check_memory``), with the cure: resample or
    crop the map. A robot map or GeoTIFF from another tool is read whole; a 40 000 px square image needs
    ~80 GB to segment and used to end in MemoryError or the OOM killer."""
    from .rasterize import BYTES_PER_PIXEL, available_memory

    avail = available_memory()
    need = int(rows) * int(cols) * BYTES_PER_PIXEL
    if avail is None or need <= avail:
        return
    factor = math.sqrt(need / avail) * 1.05
    coarser = (f"at least {resolution * factor:.3g} m/px instead of {resolution:g}" if resolution and resolution > 0
               else f"{factor:.1f} times coarser")
    raise InputError(
        f"'{os.path.basename(path)}' is {cols} x {rows} px ({rows * cols / 1e6:.1f} Mpx): segmenting it needs about "
        f"{need / 2 ** 30:.1f} GB of memory, more than the {avail / 2 ** 30:.1f} GB available; resample it to a "
        f"coarser resolution ({coarser}; QGIS 'Warp (reproject)' or gdalwarp -tr) or crop it to the building")


def _image_shape(path: str):
    """(rows, cols) from the image header (GDAL reads PNG, PGM, JPEG, BMP headers without decoding), or None."""
    try:
        ds = _gdal().Open(path)
        return (ds.RasterYSize, ds.RasterXSize) if ds is not None else None
    except Exception:  # noqa: BLE001 - no GDAL or an unreadable header: cv2 reports the file below
        return None


def _read_image(path: str, resolution: Optional[float] = None) -> np.ndarray:
    import cv2

    shape = _image_shape(path) if os.path.isfile(path) else None
    if shape is not None:
        check_grid_size(path, shape[0], shape[1], resolution)
    img = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    if img is None:
        raise InputError(f"cannot read '{path}' as an image (not an image file, or corrupt)")
    if img.ndim == 3:
        if img.shape[2] == 4:
            img = img[:, :, :3]
        if not (np.array_equal(img[:, :, 0], img[:, :, 1]) and np.array_equal(img[:, :, 1], img[:, :, 2])):
            raise InputError(f"'{os.path.basename(path)}' is a colour image with {img.shape[2]} bands; "
                             "an occupancy grid must be a single grey band")
        img = img[:, :, 0]
    return img


def read_ros_yaml(path: str) -> OccupancyGrid:
    """Read a ROS map_server ``map.yaml`` and its image."""
    import yaml  # python3-yaml ships with Debian's QGIS

    try:
        with open(path, encoding="utf-8") as fh:
            meta = yaml.safe_load(fh)
    except (OSError, yaml.YAMLError) as exc:
        raise InputError(f"cannot read ROS map description '{path}': {exc}") from exc
    if not isinstance(meta, dict) or "image" not in meta or "resolution" not in meta:
        raise InputError(f"'{path}' is not a ROS map yaml (needs 'image' and 'resolution')")
    img_path = meta["image"]
    if not os.path.isabs(img_path):
        img_path = os.path.join(os.path.dirname(os.path.abspath(path)), img_path)
    try:
        res = float(meta["resolution"])
    except (TypeError, ValueError):
        raise InputError(f"'{path}': resolution must be a number of metres per pixel, got {meta['resolution']!r}")
    img = _read_image(img_path, res)
    if not res > 0:
        raise InputError(f"'{path}': resolution must be positive, got {meta['resolution']}")
    origin = meta.get("origin", [0.0, 0.0, 0.0]) or [0.0, 0.0, 0.0]
    mode = str(meta.get("mode", "trinary")).strip().lower()
    occ_t, free_t = float(meta.get("occupied_thresh", 0.65)), float(meta.get("free_thresh", 0.196))
    if mode == "raw":
        # pixel values are occupancy percentages (0 free .. 100 occupied); anything above 100 is unknown
        v = img.astype(np.float64)
        data = np.full(img.shape, UNKNOWN, np.uint8)
        data[(v <= 100) & (v >= occ_t * 100)] = OCCUPIED
        data[v <= free_t * 100] = FREE
    elif mode in ("trinary", "scale"):
        # scale keeps intermediate probabilities, which segmentation treats as unknown like trinary
        data = _classify(img, bool(int(meta.get("negate", 0))), occ_t, free_t)
    else:
        raise InputError(f"'{path}': unknown map mode '{mode}' (ROS map_server knows trinary, scale and raw)")
    # ROS origin is the bottom-left pixel corner; image row 0 is the top.
    ox, oy = float(origin[0]), float(origin[1])
    if len(origin) > 2 and abs(float(origin[2])) > 1e-9:
        raise InputError(f"'{path}': rotated map origins (yaw={origin[2]}) are not supported")
    return OccupancyGrid(data, ox, oy + img.shape[0] * res, res)


def read_grid(path: str, resolution: Optional[float] = None, origin=(0.0, 0.0)) -> OccupancyGrid:
    """Read any supported occupancy raster.

    ``resolution`` is required for plain images (PNG/PGM/JPG without georeferencing) and overrides
    nothing for GeoTIFFs, which carry their own geotransform. Grey images are classified like ROS
    maps (dark = occupied, light = free, mid grey = unknown).
    """
    if not os.path.exists(path):
        raise InputError(f"raster '{path}' does not exist")
    ext = os.path.splitext(path)[1].lower()
    if ext in (".yaml", ".yml"):
        return read_ros_yaml(path)
    if ext in (".png", ".pgm", ".jpg", ".jpeg", ".bmp"):
        img = _read_image(path, resolution)
        if resolution is None or not resolution > 0:
            raise InputError(f"'{os.path.basename(path)}' carries no resolution: give RESOLUTION in metres per pixel")
        data = _classify(img)
        return OccupancyGrid(data, float(origin[0]), float(origin[1]) + img.shape[0] * resolution, float(resolution))
    gdal = _gdal()
    try:
        ds = gdal.Open(path)
    except RuntimeError as exc:
        raise InputError(f"cannot open raster '{path}': {exc}") from exc
    if ds.RasterCount != 1:
        raise InputError(f"'{os.path.basename(path)}' has {ds.RasterCount} bands; an occupancy grid must have one")
    gt = ds.GetGeoTransform(can_return_null=True)
    check_grid_size(path, ds.RasterYSize, ds.RasterXSize, abs(gt[1]) if gt is not None and gt[1] != 1.0 else resolution)
    arr = ds.GetRasterBand(1).ReadAsArray()
    if gt is None or (gt[1] == 1.0 and gt[5] == 1.0 and gt[0] == 0 and gt[3] == 0):
        if resolution is None:
            raise InputError(f"'{os.path.basename(path)}' has no geotransform: give RESOLUTION in metres per pixel")
        gt = (float(origin[0]), resolution, 0.0, float(origin[1]) + arr.shape[0] * resolution, 0.0, -resolution)
    if abs(gt[2]) > 1e-12 or abs(gt[4]) > 1e-12 or not math.isclose(abs(gt[1]), abs(gt[5]), rel_tol=1e-6):
        raise InputError(f"'{os.path.basename(path)}' is rotated or has non-square pixels; resample it first")
    if gt[5] > 0:
        arr = arr[::-1]
        gt = (gt[0], gt[1], 0.0, gt[3] + arr.shape[0] * gt[5], 0.0, -gt[5])
    ours = OCCUPANCY_TAG in (ds.GetMetadata() or {})
    if ours:
        data = arr.astype(np.uint8)
    else:  # a raster from another tool: image convention (dark = occupied), like PNG and ROS maps
        data = _classify(arr)
    return OccupancyGrid(data, float(gt[0]), float(gt[3]), float(gt[1]), ds.GetProjection() or "")


def border_value(img: np.ndarray):
    """The value (a pixel: scalar or channel vector) most common on ``img``'s border: what lies outside the map."""
    border = np.concatenate([img[0], img[-1], img[:, 0], img[:, -1]]).reshape(-1, *img.shape[2:])
    vals, counts = np.unique(border, axis=0, return_counts=True)
    return vals[int(np.argmax(counts))]


def rotate_raster(img: np.ndarray, degrees: float, fill=None):
    """``img`` (2-D, or 3-D with channels) turned counter-clockwise (as shown, rows down) by ``degrees`` about
    its centre, nearest neighbour (occupancy values, labels and ground-truth colours stay exact), on a canvas
    large enough that nothing is cut. The new corners take ``fill``, by default the value most common on the
    image's border (what lies outside the map). Returns ``(turned, m)``: ``m`` the 2x3 affine matrix that
    takes (col, row) pixel indices of ``img`` to those of ``turned``."""
    import cv2

    img = np.ascontiguousarray(img)
    h, w = img.shape[:2]
    if fill is None:
        fill = border_value(img)
    m = cv2.getRotationMatrix2D(((w - 1) / 2.0, (h - 1) / 2.0), float(degrees), 1.0)
    c, s = abs(m[0, 0]), abs(m[0, 1])
    nw, nh = int(math.ceil(w * c + h * s - 1e-9)) + 2, int(math.ceil(w * s + h * c - 1e-9)) + 2
    m[0, 2] += (nw - w) / 2.0
    m[1, 2] += (nh - h) / 2.0
    fill = np.atleast_1d(fill)
    outside = tuple(float(v) for v in fill) + (0.0,) * (4 - fill.size)
    dtype = img.dtype
    src = img.view(np.uint8) if dtype == bool else img
    out = cv2.warpAffine(src, m, (nw, nh), flags=cv2.INTER_NEAREST, borderMode=cv2.BORDER_CONSTANT,
                         borderValue=outside)
    return (out.view(bool) if dtype == bool else out), m
