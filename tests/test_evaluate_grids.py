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
