"""cad2osmag:samplebuilding headless through qgis_process."""
import hashlib

import pytest

from .qgis_process import run_alg


def _digest(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


@pytest.mark.qgis_process
def test_samplebuilding_headless_writes_floors_and_ground_truth(tmp_path):
    _, res, _ = run_alg("samplebuilding", {"FLOORS": 2, "SEED": 3, "OUTPUT_FOLDER": str(tmp_path / "a")})
    dxfs = res["DXF_FILES"].split(";")
    gts = res["GROUND_TRUTH_FILES"].split(";")
    assert res["FLOOR_COUNT"] == 2 and len(dxfs) == 2 and len(gts) == 2
    assert res["FIRST_FLOOR_DXF"] == dxfs[0]
    for path in dxfs + gts:
        assert (tmp_path / "a").joinpath(path.split("/")[-1]).stat().st_size > 1000
    # the same seed through the GUI path gives byte-identical drawings
    _, res2, _ = run_alg("samplebuilding", {"FLOORS": 2, "SEED": 3, "OUTPUT_FOLDER": str(tmp_path / "b")})
    assert [_digest(p) for p in res2["DXF_FILES"].split(";")] == [_digest(p) for p in dxfs]


@pytest.mark.qgis_process
def test_samplebuilding_rejects_bad_floor_count(tmp_path):
    code, _, out = run_alg("samplebuilding", {"FLOORS": 0, "OUTPUT_FOLDER": str(tmp_path / "c")}, check=False)
    assert code != 0
    assert "FLOORS" in out or "Number of floors" in out
    assert not (tmp_path / "c").exists() or not any((tmp_path / "c").iterdir())
