"""scripts/evaluate_grids.py --data: score any folder laid out like grid_gt, with pictures of the worst maps."""
import csv
import io
import sys
from pathlib import Path

import cv2
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
import evaluate_grids  # noqa: E402


def _two_rooms(tmp: Path, name: str, door_px: int) -> None:
    """Two 4 x 4 m rooms (0.05 m/px) joined by a doorway ``door_px`` wide; gt paints each room."""
    occ = np.zeros((100, 180), np.uint8)
    occ[10:90, 10:88] = 255
    occ[10:90, 92:170] = 255
    occ[50 - door_px // 2:50 + door_px - door_px // 2, 88:92] = 255
    gt = np.full((100, 180, 3), 255, np.uint8)
    gt[5:95, 5:175] = 0
    gt[10:90, 10:90] = (240, 116, 248)
    gt[10:90, 90:170] = (41, 230, 232)
    for sub, img in (("input", occ), ("gt", gt[:, :, ::-1])):
        (tmp / sub).mkdir(exist_ok=True)
        cv2.imwrite(str(tmp / sub / f"{name}.png"), img)


def test_data_folder_without_maps_csv(tmp_path):
    _two_rooms(tmp_path, "a", 18)
    _two_rooms(tmp_path, "b", 20)
    out = tmp_path / "out"
    buf = io.StringIO()
    res = evaluate_grids.run(tmp_path, str(out), worst=1, out=buf)
    assert {r["map"] for r in res} == {"a", "b"}
    assert all(r["setting"] == "default" for r in res)  # no maps.csv: default widths only
    for r in res:  # a 0.9 m door between two 4 m rooms: two areas, each room found
        assert r["areas"] == 2 and r["mcc"] > 0.95 and r["f1"] == 1.0
    rows = list(csv.DictReader(open(out / "scores.csv")))
    assert len(rows) == 2
    pics = sorted(p.name for p in out.glob("worst_*.png"))
    assert len(pics) == 1
    img = cv2.imread(str(out / pics[0]))
    assert img.shape[1] > 4 * 180  # four panels side by side
    assert "mean" in buf.getvalue()


def test_main_exit_codes(tmp_path):
    assert evaluate_grids.main(["--data", str(tmp_path / "missing")]) == 2
    _two_rooms(tmp_path, "a", 18)
    (tmp_path / "maps.csv").write_text("map,resolution_m_per_px,widest_door_m,narrowest_corridor_m\na,0.05,1.0,\n")
    assert evaluate_grids.main(["--data", str(tmp_path), "--out", str(tmp_path / "o")]) == 0
    rows = list(csv.DictReader(open(tmp_path / "o" / "scores.csv")))
    assert [r["setting"] for r in rows] == ["maps.csv", "default"]


def test_rotate_raster_keeps_values_and_cuts_nothing():
    from algorithms.raster_io import rotate_raster

    a = np.full((40, 60), 128, np.uint8)  # unknown outside
    a[10:30, 10:50] = 0
    a[10, 10:50] = 255
    out, m = rotate_raster(a, 30.0)
    assert set(np.unique(out)) == {0, 128, 255}  # nearest neighbour: no blended values
    assert out.shape[0] >= 40 * np.cos(np.radians(30)) + 60 * np.sin(np.radians(30))
    assert abs(int((out == 0).sum()) - int((a == 0).sum())) < 0.05 * (a == 0).sum()  # the free space is all there
    c, r = m @ (30.0, 20.0, 1.0)  # the centre of a free pixel lands on a free pixel
    assert out[int(round(r)), int(round(c))] == 0
    same, _ = rotate_raster(a, 90.0)
    assert np.array_equal(same[1:-1, 1:-1], np.rot90(a))  # a quarter turn is exact
    rgb = np.zeros((40, 60, 3), np.uint8) + 255
    rgb[15:25, 20:40] = (240, 116, 248)
    col, _ = rotate_raster(rgb, 45.0, fill=(255, 255, 255))
    assert {tuple(v) for v in col.reshape(-1, 3)} == {(255, 255, 255), (240, 116, 248)}


def test_rotated_maps_are_scored_at_every_angle(tmp_path):
    """--rotate: the map and its ground truth turned together; two rooms joined by a 0.9 m door stay two
    areas, each its room, at 0, 15, 30 and 45 degrees."""
    _two_rooms(tmp_path, "a", 18)
    buf = io.StringIO()
    res = evaluate_grids.run(tmp_path, angles=(0.0, 15.0, 30.0, 45.0), out=buf)
    assert [r["angle"] for r in res] == [0.0, 15.0, 30.0, 45.0]
    for r in res:
        assert r["areas"] == 2 and r["mcc"] > 0.95 and r["f1"] == 1.0, r
    assert " deg " in buf.getvalue()
    assert evaluate_grids.main(["--data", str(tmp_path), "--rotate", "30"]) == 0  # judged on the unturned maps


def test_shifted_maps_are_scored_at_every_shift(tmp_path):
    """--shift: the map and its ground truth moved together by whole pixels (padded with what lies outside each);
    two rooms joined by a 0.9 m door: the same figures at every shift, the spread printed per map; a bad shift
    is a clear error."""
    _two_rooms(tmp_path, "a", 18)
    grid = evaluate_grids._read_map(tmp_path / "input" / "a.png", 0.05)
    gt = evaluate_grids.read_gt_image(str(tmp_path / "gt" / "a.png"))
    g2, gt2 = evaluate_grids.shift_map(grid, gt, 3, 1)
    assert g2.data.shape == (101, 183) and (g2.data[1:, 3:] == grid.data).all()
    assert (g2.data[0] == grid.data[0, 0]).all() and (gt2[:, :3] == gt[0, 0]).all()
    buf = io.StringIO()
    res = evaluate_grids.run(tmp_path, out=buf, shifts=((0, 0), (1, 0), (2, 3)))
    assert [r["shift"] for r in res] == ["0,0", "1,0", "2,3"]
    assert len({(r["areas"], round(r["mcc"], 6)) for r in res}) == 1 and res[0]["mcc"] > 0.95
    assert "spread   a" in buf.getvalue() and "(0.000," in buf.getvalue()
    assert evaluate_grids.main(["--data", str(tmp_path), "--shift", "1", "0,2"]) == 0
    assert evaluate_grids.main(["--data", str(tmp_path), "--shift", "x"]) == 2
    assert evaluate_grids.main(["--data", str(tmp_path), "--shift=-1,0"]) == 2
