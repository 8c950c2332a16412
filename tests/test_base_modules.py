"""Shared plumbing: atomic writes, progress/cancel, occupancy raster I/O."""
import os

import cv2
import numpy as np
import pytest

from algorithms import raster_io
from algorithms.errors import Canceled, InputError
from algorithms.io_utils import atomic_path, atomic_write
from algorithms.model import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from algorithms.progress import RecordingProgress, ensure


# --------------------------------------------------------------------------- atomic output
def test_atomic_write_leaves_nothing_on_failure(tmp_path):
    target = tmp_path / "out.osm"
    with pytest.raises(RuntimeError):
        with atomic_write(str(target)) as fh:
            fh.write("<osm>half")
            raise RuntimeError("boom")
    assert not target.exists()
    assert os.listdir(tmp_path) == []


def test_atomic_output_has_ordinary_permissions(tmp_path):
    with atomic_write(str(tmp_path / "f.txt")) as fh:
        fh.write("x")
    umask = os.umask(0)
    os.umask(umask)
    assert (tmp_path / "f.txt").stat().st_mode & 0o777 == 0o666 & ~umask


def test_atomic_write_keeps_previous_file_until_success(tmp_path):
    target = tmp_path / "out.txt"
    target.write_text("old")
    with pytest.raises(ValueError):
        with atomic_path(str(target)) as tmp:
            open(tmp, "w").write("new but broken")
            raise ValueError
    assert target.read_text() == "old"
    with atomic_write(str(target)) as fh:
        fh.write("new")
    assert target.read_text() == "new"
    assert sorted(os.listdir(tmp_path)) == ["out.txt"]


# --------------------------------------------------------------------------- progress
def test_sub_progress_maps_range_and_cancel_propagates():
    rec = RecordingProgress(cancel_after=2)
    sub = rec.sub(50, 100)
    sub.step(0, "start")
    sub.step(50)
    assert rec.percents == [50.0, 75.0]
    assert ("info", "start") in rec.messages
    with pytest.raises(Canceled):
        sub.step(100)


def test_ensure_gives_a_null_progress():
    p = ensure(None)
    p.step(10, "x")  # never raises, never records
    assert not p.is_canceled()


# --------------------------------------------------------------------------- raster I/O
def _grid():
    data = np.zeros((40, 60), np.uint8)
    data[0, :] = OCCUPIED
    data[10:20, 30:35] = UNKNOWN
    return OccupancyGrid(data, origin_x=12.5, origin_y=-3.25, resolution=0.05)


def test_geotiff_roundtrip_keeps_values_and_geotransform(tmp_path):
    g = _grid()
    path = str(tmp_path / "grid.tif")
    raster_io.write_grid(path, g)
    back = raster_io.read_grid(path)
    assert np.array_equal(back.data, g.data)
    assert back.geotransform == pytest.approx(g.geotransform)
    # pixel centre -> world -> pixel is exact
    x, y = back.pixel_to_world(30.5, 10.5)
    assert (x, y) == pytest.approx((12.5 + 30.5 * 0.05, -3.25 - 10.5 * 0.05))
    c, r = back.world_to_pixel(x, y)
    assert (c, r) == pytest.approx((30.5, 10.5))
    assert back.extent == pytest.approx((12.5, -3.25 - 2.0, 12.5 + 3.0, -3.25))


def test_png_needs_a_resolution_and_is_classified_like_ros(tmp_path):
    img = np.full((20, 30), 254, np.uint8)  # free
    img[0, :] = 0  # occupied
    img[5:8, 5:8] = 205  # unknown grey of ROS maps
    path = str(tmp_path / "map.png")
    cv2.imwrite(path, img)
    with pytest.raises(InputError, match="RESOLUTION"):
        raster_io.read_grid(path)
    g = raster_io.read_grid(path, resolution=0.05)
    assert g.data[0, 0] == OCCUPIED and g.data[10, 10] == FREE and g.data[6, 6] == UNKNOWN
    assert g.resolution == 0.05


def test_ros_yaml_honours_origin_negate_and_thresholds(tmp_path):
    img = np.full((10, 20), 0, np.uint8)  # with negate=1, black is free
    img[:, 0] = 255
    cv2.imwrite(str(tmp_path / "m.pgm"), img)
    (tmp_path / "m.yaml").write_text("image: m.pgm\nresolution: 0.1\norigin: [-1.0, -2.0, 0.0]\n"
                                     "negate: 1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    g = raster_io.read_grid(str(tmp_path / "m.yaml"))
    assert g.data[5, 0] == OCCUPIED and g.data[5, 5] == FREE
    # ROS origin is the lower-left corner: top-left y = -2 + 10 * 0.1
    assert (g.origin_x, g.origin_y, g.resolution) == pytest.approx((-1.0, -1.0, 0.1))


def test_unreadable_and_multiband_rasters_are_rejected(tmp_path):
    bad = tmp_path / "bad.png"
    bad.write_bytes(b"not a png")
    with pytest.raises(InputError, match="cannot read"):
        raster_io.read_grid(str(bad), resolution=0.05)
    colour = np.zeros((10, 10, 3), np.uint8)
    colour[..., 2] = 200
    cv2.imwrite(str(tmp_path / "c.png"), colour)
    with pytest.raises(InputError, match="single grey band"):
        raster_io.read_grid(str(tmp_path / "c.png"), resolution=0.05)
    with pytest.raises(InputError, match="does not exist"):
        raster_io.read_grid(str(tmp_path / "missing.tif"))
    (tmp_path / "r.yaml").write_text("image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0.5]\n")
    cv2.imwrite(str(tmp_path / "m.pgm"), np.zeros((4, 4), np.uint8))
    with pytest.raises(InputError, match="rotated"):
        raster_io.read_grid(str(tmp_path / "r.yaml"))


def test_failed_geotiff_write_leaves_no_file(tmp_path):
    path = tmp_path / "x.tif"
    with pytest.raises(InputError):
        raster_io.write_geotiff(str(path), np.zeros((2, 2, 2), np.uint8), 0, 0, 1)
    assert not path.exists()


def test_only_our_tagged_geotiffs_use_0_free_other_geotiffs_follow_the_image_convention(tmp_path):
    from osgeo import gdal

    data = np.zeros((20, 20), np.uint8)
    data[:2, :] = OCCUPIED  # a wall along the top, free below (our convention)
    ours = str(tmp_path / "ours.tif")
    raster_io.write_grid(ours, OccupancyGrid(data, 0.0, 1.0, 0.05))
    assert raster_io.OCCUPANCY_TAG in gdal.Open(ours).GetMetadata()
    g = raster_io.read_grid(ours)
    assert g.data[0, 0] == OCCUPIED and g.data[10, 10] == FREE
    # the same picture from another tool, ROS style: 0 = occupied (black), 255 = free (white)
    foreign = str(tmp_path / "foreign.tif")
    raster_io.write_geotiff(foreign, np.where(data == OCCUPIED, 0, 255).astype(np.uint8), 0.0, 1.0, 0.05)
    f = raster_io.read_grid(foreign)
    assert f.data[0, 0] == OCCUPIED and f.data[10, 10] == FREE
    assert np.array_equal(f.data, g.data)


def test_ros_raw_mode_reads_occupancy_percentages(tmp_path):
    img = np.zeros((6, 8), np.uint8)  # raw: 0 = free
    img[0, :] = 100  # occupied
    img[5, :] = 255  # unknown (-1 stored as 255)
    img[3, 3] = 50  # between the thresholds: unknown
    cv2.imwrite(str(tmp_path / "raw.pgm"), img)
    (tmp_path / "raw.yaml").write_text("image: raw.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nmode: raw\n"
                                       "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    g = raster_io.read_grid(str(tmp_path / "raw.yaml"))
    assert g.data[0, 0] == OCCUPIED and g.data[2, 2] == FREE and g.data[5, 0] == UNKNOWN and g.data[3, 3] == UNKNOWN
    (tmp_path / "bad.yaml").write_text("image: raw.pgm\nresolution: 0.05\nmode: fancy\n")
    with pytest.raises(InputError, match="mode"):
        raster_io.read_grid(str(tmp_path / "bad.yaml"))


def test_geometry_library_measures_hausdorff_distance_correctly():
    """Refinement reports its deviation with Hausdorff distances; Debian's GEOS 3.11.1 returns ~15 m for
    two identical rings like this one, so the install keeps shapely's own GEOS (>= 3.11.2)."""
    import shapely
    from shapely.geometry import LinearRing

    ring = LinearRing([(3, 9.9), (4, 9.9), (4, 10), (14.5, 10), (14.5, 19.5), (0.5, 19.5), (0.5, 10), (3, 10)])
    moved = LinearRing([(x + 1e-6, y) for x, y in ring.coords])
    assert shapely.geos_version >= (3, 11, 2)
    assert ring.hausdorff_distance(moved) == pytest.approx(1e-6, abs=1e-9)
