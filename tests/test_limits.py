"""Resource limits: an input that needs more pixels or memory than the budget stops before allocating,
with advice (resolution, plan selection, units); block explosion has its own entity budget
(tests/test_fuzz_dxf.py). Headless: the same message through qgis_process, nothing written."""
import time
import tracemalloc

import numpy as np
import pytest

from algorithms import pipeline, rasterize
from algorithms.errors import InputError
from algorithms.model import CadGeometry

from .test_fuzz_dxf import base_dxf


def _walls(size_m, n=40):
    """n x n rooms of a square floor ``size_m`` across (hairline walls)."""
    out = []
    for v in np.linspace(0, size_m, n + 1):
        out.append(CadGeometry("A-WALL", "wall", np.array([(v, 0.0), (v, size_m)])))
        out.append(CadGeometry("A-WALL", "wall", np.array([(0.0, v), (size_m, v)])))
    return out


def _peak_bytes(func, *args, **kwargs):
    tracemalloc.start()
    t0 = time.process_time()
    try:
        func(*args, **kwargs)
    finally:
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
    return peak, time.process_time() - t0


def test_pixel_budget_stops_before_allocating_with_advice():
    geoms = _walls(3000.0)  # 3 km across: 4.6 Gpx at 0.044 m/px
    with pytest.raises(InputError) as err:
        _peak_bytes(rasterize.rasterize, geoms)
    msg = str(err.value)
    for advice in ("Mpx", "budget of 60 Mpx", "resolution of at least 0.4", "one plan of the sheet", "units"):
        assert advice in msg, (advice, msg)
    tracemalloc.start()
    try:
        with pytest.raises(InputError):
            rasterize.rasterize(geoms)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 20e6  # nothing of the 4.6 GB raster was allocated


def test_the_suggested_resolution_fits_the_budget():
    geoms = _walls(3000.0, n=10)
    with pytest.raises(InputError, match=r"at least ([0-9.]+) m/px") as err:
        rasterize.rasterize(geoms, max_pixels=2e6)
    import re

    res = float(re.search(r"at least ([0-9.]+) m/px", str(err.value)).group(1))
    grid = rasterize.rasterize(geoms, resolution=res, max_pixels=2e6, kernel=1)
    assert grid.data.size <= 2e6


def test_memory_budget_stops_before_allocating(monkeypatch):
    geoms = _walls(300.0)  # 46 Mpx at 0.044: within the pixel budget, 2.3 GB of memory to segment
    monkeypatch.setattr(rasterize, "available_memory", lambda: 1 * 2 ** 30)
    tracemalloc.start()
    t0 = time.process_time()
    try:
        with pytest.raises(InputError) as err:
            rasterize.rasterize(geoms)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    msg = str(err.value)
    assert "GB of memory" in msg and "1.0 GB available" in msg and "coarser resolution (at least 0.0" in msg
    assert "one plan of the sheet" in msg and "units" in msg
    assert peak < 20e6 and time.process_time() - t0 < 5
    # the advice works: at the suggested resolution the raster fits
    res = float(msg.split("at least ")[1].split(" m/px")[0])
    rows = cols = int(300.0 * 1.1 / res) + 20
    assert rows * cols * rasterize.BYTES_PER_PIXEL <= 1 * 2 ** 30 * 1.05


def test_memory_check_is_skipped_when_unknown(monkeypatch):
    monkeypatch.setattr(rasterize, "available_memory", lambda: None)
    rasterize.check_memory(10 ** 5, 10 ** 5, 0.01)  # no error: nothing to compare with


def test_wrong_units_stop_the_pipeline_before_allocating(tmp_path):
    """The sample floor (mm) read as metres is 60 km across: the pipeline stops at the budget, fast, with
    the units named, and writes nothing."""
    out = tmp_path / "f.osm"
    t0 = time.process_time()
    with pytest.raises(InputError, match=r"(?s)Mpx.*budget.*units"):
        pipeline.convert_dxf(str(base_dxf()), str(out), units="m")
    assert time.process_time() - t0 < 10 and not out.exists() and list(tmp_path.iterdir()) == []


@pytest.mark.qgis_process
def test_budget_error_headless(tmp_path):
    from .qgis_process import run_alg

    out = tmp_path / "f.osm"
    code, _, text = run_alg("dxftoosmag", {"INPUT": str(base_dxf()), "UNITS": 3, "OUTPUT": str(out)},
                            check=False)
    assert code != 0 and "Mpx" in text and "resolution of at least" in text and "Traceback" not in text
    assert not out.exists()


# ------------------------------------------------------------------------------------------ grids from other tools
def _robot_map(tmp_path, rows=300, cols=400):
    """A small grey robot map as PNG, as ROS map.yaml + PNG and as a plain GeoTIFF from another tool."""
    import cv2

    from algorithms.raster_io import write_geotiff

    img = np.full((rows, cols), 254, np.uint8)
    img[::50, :] = 0
    png = tmp_path / "map.png"
    cv2.imwrite(str(png), img)
    yaml_path = tmp_path / "map.yaml"
    yaml_path.write_text("image: map.png\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                         "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    tif = tmp_path / "map.tif"
    write_geotiff(str(tif), img, 0.0, rows * 0.05, 0.05)
    return png, yaml_path, tif


def test_a_robot_map_too_big_to_segment_stops_before_it_is_read(tmp_path, monkeypatch):
    """Occupancy rasters from other tools (PNG, ROS map.yaml, GeoTIFF) are read whole: one that needs more
    memory to segment than the machine has stops from its header, before the pixels are decoded, with the
    cure (resample to a resolution that fits, or crop)."""
    import cv2

    from algorithms import raster_io

    png, yaml_path, tif = _robot_map(tmp_path)
    ok = raster_io.read_grid(str(png), resolution=0.05)  # fits: read as before
    assert ok.shape == (300, 400)
    monkeypatch.setattr(rasterize, "available_memory", lambda: 2 ** 20)  # 1 MB: 400 x 300 px needs ~6 MB

    def no_decoding(*a, **k):
        raise AssertionError("the image was decoded before the budget check")

    monkeypatch.setattr(cv2, "imread", no_decoding)
    for path, kwargs in ((png, {"resolution": 0.05}), (yaml_path, {}), (tif, {})):
        with pytest.raises(InputError) as err:
            raster_io.read_grid(str(path), **kwargs)
        msg = str(err.value)
        assert "400 x 300 px" in msg and "GB of memory" in msg and "crop it to the building" in msg, msg
        res = float(msg.split("at least ")[1].split(" m/px")[0])
        assert 400 * 300 * (0.05 / res) ** 2 * rasterize.BYTES_PER_PIXEL <= 2 ** 20  # the advice fits


def test_a_ros_map_with_a_bad_resolution_is_named(tmp_path):
    _, yaml_path, _ = _robot_map(tmp_path)
    yaml_path.write_text(yaml_path.read_text().replace("resolution: 0.05", "resolution: fine"))
    from algorithms import raster_io

    with pytest.raises(InputError, match="resolution must be a number of metres per pixel, got 'fine'"):
        raster_io.read_grid(str(yaml_path))


def test_segment_algorithm_on_a_too_big_map_fails_with_the_advice_and_writes_nothing(qgis_app, tmp_path,
                                                                                     monkeypatch):
    from qgis.core import QgsProcessingContext, QgsProcessingFeedback

    from .conftest import plugin_package

    png, _, _ = _robot_map(tmp_path)
    plugin_package()
    from cad2osmag.algorithms import rasterize as plugin_rasterize
    from cad2osmag.processing_provider.alg_segment import SegmentAlgorithm

    monkeypatch.setattr(plugin_rasterize, "available_memory", lambda: 2 ** 20)
    alg = SegmentAlgorithm().create()
    alg.initAlgorithm()
    out = tmp_path / "out"
    out.mkdir()

    class Log(QgsProcessingFeedback):
        text = []

        def reportError(self, error, fatalError=False):  # noqa: N802, N803
            Log.text.append(error)

    params = {"INPUT": str(png), "RESOLUTION": 0.05, "AREAS": str(out / "a.gpkg"), "PASSAGES": str(out / "p.gpkg"),
              "LABELS": str(out / "l.tif")}
    try:
        _, ok = alg.run(params, QgsProcessingContext(), Log())
    except Exception as exc:  # QgsProcessingException on QGIS versions that raise it
        ok = False
        Log.text.append(str(exc))
    assert not ok and any("GB of memory" in t and "resample it" in t for t in Log.text), Log.text
    assert list(out.iterdir()) == []
