"""cad2osmag:segment and cad2osmag:evaluatesegmentation headless through qgis_process."""
import cv2
import numpy as np
import pytest

from algorithms.model import FREE, OCCUPIED, UNKNOWN
from algorithms.raster_io import write_grid

from .qgis_process import layer_rows, run_alg
from .test_segmentation import Plan


@pytest.fixture(scope="module")
def plan_tif(tmp_path_factory):
    folder = tmp_path_factory.mktemp("seg")
    plan = Plan()
    path = folder / "plan.tif"
    write_grid(str(path), plan.grid)
    return plan, path


@pytest.mark.qgis_process
def test_segment_geotiff(plan_tif, tmp_path):
    plan, path = plan_tif
    out = {"AREAS": tmp_path / "areas.gpkg", "PASSAGES": tmp_path / "passages.gpkg", "LABELS": tmp_path / "labels.tif"}
    _, res, log = run_alg("segment", {"INPUT": path, "DOOR_WIDTH": 1.0, "CORRIDOR_WIDTH": 2.0,
                                      **{k: str(v) for k, v in out.items()}})
    n_rooms = len(plan.rooms)
    assert res["AREA_COUNT"] == n_rooms + 1
    assert res["CORRIDOR_COUNT"] == 1 and res["ROOM_COUNT"] == n_rooms
    assert res["PASSAGE_COUNT"] == len(plan.doors)
    assert res["ALPHA"] == 121  # ceil(1.1^2 / (4 * 0.05^2))
    assert 300 < res["INTERIOR_AREA_M2"] < 336  # 24 x 14 m minus walls
    assert "Interior free area" in log
    areas = layer_rows(out["AREAS"], ["id", "type", "area_m2", "perimeter_m", "max_clearance"], wkt=True)
    assert len(areas) == n_rooms + 1
    assert sum(a["area_m2"] for a in areas) == pytest.approx(res["INTERIOR_AREA_M2"], rel=0.02)
    room_a = [a for a in areas if a["area_m2"] > 30 and a["max_clearance"] > 2.7]
    assert room_a and all(a["perimeter_m"] > 20 for a in room_a)
    passages = layer_rows(out["PASSAGES"], ["id", "from_id", "to_id", "width_m"], wkt=True)
    ids = {a["id"] for a in areas}
    assert all(p["from_id"] in ids and p["to_id"] in ids for p in passages)
    assert all(0.6 <= p["width_m"] <= 1.2 for p in passages)
    from osgeo import gdal

    lab = gdal.Open(str(out["LABELS"])).ReadAsArray()
    assert lab.shape == plan.grid.data.shape
    assert set(np.unique(lab)) == {0} | ids


@pytest.mark.qgis_process
def test_segment_ros_yaml_with_unknown(tmp_path):
    plan = Plan(facade_gaps=False)
    data = plan.grid.data.copy()
    x0, y0, x1, y1 = [int(round(v / 0.05)) for v in plan.bx]
    outside = np.ones(data.shape, bool)
    outside[y0 - 2:y1 + 3, x0 - 2:x1 + 3] = False
    data[outside] = UNKNOWN  # a robot map: nothing known outside the walls
    img = np.where(data == FREE, 254, np.where(data == OCCUPIED, 0, 205)).astype(np.uint8)
    cv2.imwrite(str(tmp_path / "map.pgm"), img)
    (tmp_path / "map.yaml").write_text("image: map.pgm\nresolution: 0.05\norigin: [-3.0, -2.0, 0.0]\n"
                                       "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    out = {"AREAS": tmp_path / "a.gpkg", "PASSAGES": tmp_path / "p.gpkg", "LABELS": tmp_path / "l.tif"}
    _, res, _ = run_alg("segment", {"INPUT": tmp_path / "map.yaml", **{k: str(v) for k, v in out.items()}})
    assert res["AREA_COUNT"] == len(plan.rooms) + 1
    from osgeo import gdal

    ds = gdal.Open(str(out["LABELS"]))
    gt = ds.GetGeoTransform()
    assert gt[0] == pytest.approx(-3.0) and gt[1] == pytest.approx(0.05)
    assert gt[3] == pytest.approx(-2.0 + data.shape[0] * 0.05)


@pytest.mark.qgis_process
def test_segment_bad_input_writes_nothing(tmp_path):
    img = np.full((200, 300), 255, np.uint8)  # all free, but no resolution
    cv2.imwrite(str(tmp_path / "plain.png"), img)
    out = {"AREAS": tmp_path / "a.gpkg", "PASSAGES": tmp_path / "p.gpkg", "LABELS": tmp_path / "l.tif"}
    code, _, log = run_alg("segment", {"INPUT": tmp_path / "plain.png", **{k: str(v) for k, v in out.items()}},
                           check=False)
    assert code != 0 and "RESOLUTION" in log
    assert not any(p.exists() for p in out.values())
    # all occupied with a resolution
    cv2.imwrite(str(tmp_path / "black.png"), np.zeros((200, 300), np.uint8))
    code, _, log = run_alg("segment", {"INPUT": tmp_path / "black.png", "RESOLUTION": 0.05,
                                       **{k: str(v) for k, v in out.items()}}, check=False)
    assert code != 0 and "no free cell" in log
    assert not any(p.exists() for p in out.values())
    # a colour (multi-band) image
    colour = np.zeros((200, 300, 3), np.uint8)
    colour[..., 2] = 255
    cv2.imwrite(str(tmp_path / "colour.png"), colour)
    code, _, log = run_alg("segment", {"INPUT": tmp_path / "colour.png", "RESOLUTION": 0.05,
                                       **{k: str(v) for k, v in out.items()}}, check=False)
    assert code != 0 and "band" in log
    # a resolution so coarse that alpha < 2 px^2
    cv2.imwrite(str(tmp_path / "white.png"), np.full((200, 300), 255, np.uint8))
    code, _, log = run_alg("segment", {"INPUT": tmp_path / "white.png", "RESOLUTION": 3.0,
                                       **{k: str(v) for k, v in out.items()}}, check=False)
    assert code != 0 and "smaller than 2" in log
    assert not any(p.exists() for p in out.values())


@pytest.mark.qgis_process
def test_evaluatesegmentation(plan_tif, tmp_path):
    plan, path = plan_tif
    out = {"AREAS": tmp_path / "a.gpkg", "PASSAGES": tmp_path / "p.gpkg", "LABELS": tmp_path / "l.tif"}
    run_alg("segment", {"INPUT": path, "DOOR_WIDTH": 1.0, "CORRIDOR_WIDTH": 2.0, **{k: str(v) for k, v in out.items()}})
    # ground truth: every room box painted in its own colour, walls black, outside white
    gt = np.full(plan.grid.data.shape + (3,), 255, np.uint8)
    rng = np.random.default_rng(1)
    for x0, y0, x1, y1 in list(plan.rooms.values()) + [plan.corridor]:
        c = [int(v) for v in rng.integers(60, 230, 3)]
        gt[int(y0 / 0.05):int(y1 / 0.05), int(x0 / 0.05):int(x1 / 0.05)] = c
    gt[plan.grid.data == OCCUPIED] = 0
    cv2.imwrite(str(tmp_path / "gt.png"), gt)
    report = tmp_path / "report.csv"
    _, res, log = run_alg("evaluatesegmentation", {"LABELS": out["LABELS"], "GROUND_TRUTH": tmp_path / "gt.png",
                                                   "REPORT": report})
    assert res["GT_ROOMS"] == len(plan.rooms) + 1
    assert res["MCC"] > 0.95 and res["F1"] == 1.0
    assert len(report.read_text().strip().splitlines()) == len(plan.rooms) + 2
    # a ground truth of another size is refused
    cv2.imwrite(str(tmp_path / "small.png"), gt[:100, :100])
    code, _, log = run_alg("evaluatesegmentation", {"LABELS": out["LABELS"], "GROUND_TRUTH": tmp_path / "small.png"},
                           check=False)
    assert code != 0 and "same grid" in log
