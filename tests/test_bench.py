"""The benchmark harness (``make bench``): one run per process, figures, gallery pictures, failures as rows."""
import importlib.util
import math
import os
import struct
from pathlib import Path

import pytest

from algorithms.sample_building import generate_building
from benchmarks import plans

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data"


def _bench_module():
    spec = importlib.util.spec_from_file_location("bench_script", ROOT / "scripts" / "bench.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _png_size(path):
    with open(path, "rb") as fh:
        head = fh.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", head[16:24])


@pytest.fixture(scope="module")
def sample_floor(tmp_path_factory):
    out = tmp_path_factory.mktemp("sample")
    return generate_building(str(out), floors=1, seed=0)["dxf"][0]


def test_run_plan_figures_and_gallery(sample_floor, tmp_path):
    png = tmp_path / "gallery" / "sample.png"
    r = plans.run_plan(sample_floor, str(tmp_path / "sample.osm"), level="1", png=str(png))
    assert r["ok"], r
    # the sample floor: 13 offices/rooms + hall + corridor + stair + lift, every one named, one component
    assert 15 <= r["areas"] <= 22 and r["passages"] >= r["areas"] - 1
    assert r["named_areas"] >= 15 and r["components"] == 1 and r["largest_component_pct"] == pytest.approx(100.0)
    assert r["stairs"] >= 1 and r["elevators"] >= 1
    assert r["vertices"] >= 4 * r["areas"] and r["osm_nodes"] > 0
    cols, rows = r["raster"]
    assert cols > rows > 300 and r["resolution"] == pytest.approx(0.044)
    # wall and CPU seconds for every stage, and the stage sum is (nearly) the whole run
    for key in ("cad_import", "rasterize", "segment", "types", "refine", "names", "outline", "export"):
        assert r["stages_wall"][key] >= 0 and r["stages_cpu"][key] >= 0, key
    assert sum(r["stages_wall"].values()) <= r["wall_s"] + 1e-6
    assert sum(r["stages_wall"].values()) >= 0.9 * r["wall_s"]
    assert r["peak_mb"] >= r["baseline_mb"] > 0
    # a small palette picture, at most 1100 px wide
    w, h = _png_size(png)
    assert 600 <= w <= 1100 and h > 300 and png.stat().st_size < 300_000
    assert (tmp_path / "sample.osm").stat().st_size > 1000


def test_run_plan_bad_input_is_a_row(tmp_path):
    bad = tmp_path / "broken.dxf"
    bad.write_text("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nA-WALL\n10\n", encoding="ascii")  # truncated
    r = plans.run_plan(str(bad), str(tmp_path / "broken.osm"))
    assert r["ok"] is False and r["error"].startswith("InputError:") and "broken.dxf" in r["error"]
    assert not (tmp_path / "broken.osm").exists()


def test_spawned_child_failure_does_not_stop_the_bench(tmp_path):
    bench = _bench_module()
    missing = tmp_path / "nothing.dwg"
    r = bench.spawn("plan", {"path": str(missing), "out_osm": str(tmp_path / "x.osm")}, timeout=120)
    assert r["ok"] is False and "nothing.dwg" in r["error"]


def test_summary_medians_and_markdown(tmp_path):
    bench = _bench_module()
    stage = {k: 1.0 for k in bench.STAGES}
    base = {"ok": True, "cpu_s": 2.0, "peak_mb": 300.0, "baseline_mb": 100.0, "stages_wall": stage,
            "stages_cpu": stage, "raster": [1000, 800], "resolution": 0.044, "areas": 10, "passages": 9,
            "components": 1, "largest_component_pct": 100.0, "stairs": 1, "elevators": 0, "named_areas": 4,
            "vertices": 80, "segment_steps": {"skeleton": 0.5}}
    runs = [dict(base, wall_s=w, peak_mb=m) for w, m in ((3.0, 300.0), (1.0, 350.0), (2.0, 320.0))]
    s = bench.summarise(runs)
    assert s["runs"] == 3 and s["wall_s"] == 2.0 and s["peak_mb"] == 350.0
    s.update(label="SIST-F1", group="SIST filtered DXF", path="x")
    failed = {"ok": False, "error": "InputError: 'bad.dwg' | is damaged", "label": "bad.dwg",
              "group": "library DWG", "wall_s": 0.1, "peak_mb": 90.0}
    out = tmp_path / "docs" / "benchmarks.md"

    class A:
        runs, max_repeat_cpu, jobs = 3, 8.0, 3

    bench.write_markdown(out, [s, failed], {"resolution": [], "floors": [], "building": None}, 60.0, A)
    text = out.read_text(encoding="utf-8")
    assert "| SIST-F1 | SIST filtered DXF | 3 | 2.00 | 2.00 | 350 | 1000×800 | 10 | 9 | 4 | 1 (100 %)" in text
    assert "| bad.dwg | library DWG |" in text and "**failed**: InputError: 'bad.dwg' / is damaged" in text
    assert "| filtered SIST floor DXF -> osmAG (median) | ≤ 2.5 s, ≤ 1 GB | 2.00 s | 2.00 s | 350 MB | yes |" in text
    assert "[png](gallery/SIST-F1.png)" in text
    assert "Runs per plan: 3, once only when the first run took more than 8 CPU s" in text
    assert "speed targets' plans (filtered SIST floors, SIST-F5.dwg) one at a time" in text
    A.max_repeat_cpu = float("inf")  # the default: every plan runs --runs times
    bench.write_markdown(out, [s], {"resolution": [], "floors": [], "building": None}, 60.0, A)
    assert "Runs per plan: 3; the speed targets'" in out.read_text(encoding="utf-8")


def test_target_plans_are_timed_alone():
    """The plans whose wall seconds are a target's figure run one at a time (nothing else on the 2 cores)."""
    bench = _bench_module()
    assert bench._target_plan(("SIST-F3", "SIST filtered DXF", "x.dxf", "3"))
    assert bench._target_plan(("SIST-F5.dwg", "SIST original DWG", "x.dwg", "5"))
    assert not bench._target_plan(("SIST-F1.dwg", "SIST original DWG", "x.dwg", "1"))
    assert not bench._target_plan(("office", "ArchWeb DXF", "x.dxf", "1"))


def test_growth_exponent():
    bench = _bench_module()
    assert bench._growth([1, 2, 4], [3, 6, 12]) == pytest.approx(1.0)
    assert bench._growth([1, 2, 4], [1, 4, 16]) == pytest.approx(2.0)
    assert math.isnan(bench._growth([1], [1]))


@pytest.mark.slow
def test_sist_floor_run_on_real_data(tmp_path):
    dxf = SHARED / "dxf" / "sist" / "SIST-F5.dxf"
    if not dxf.exists():
        pytest.skip("../shared/data/dxf/sist is missing")
    # in a fresh interpreter, as the bench runs every plan: its peak RSS is the plan's own, not that of the
    # tests that ran before in this (possibly xdist worker) process or of what a spawned child re-imports
    import json
    import subprocess
    import sys

    code = ("import json, sys; from benchmarks import plans; "
            "print(json.dumps(plans.run_plan(sys.argv[1], sys.argv[2], level='5', png=sys.argv[3])))")
    proc = subprocess.run([sys.executable, "-c", code, str(dxf), str(tmp_path / "f5.osm"), str(tmp_path / "f5.png")],
                          cwd=str(Path(plans.__file__).resolve().parents[1]), capture_output=True, text=True,
                          timeout=1200)
    assert proc.returncode == 0, proc.stderr[-3000:]
    r = json.loads(proc.stdout.strip().splitlines()[-1])
    assert r["ok"], r
    assert r["areas"] >= 60 and r["passages"] >= 60 and r["components"] >= 1
    # measured 69.7 % at commit dfed94a (the filtered floor has unlinked wings: a segmentation finding
    # reported in docs/benchmarks.md); the bench must report it, not hide it
    assert 50 <= r["largest_component_pct"] <= 100 and r["components"] >= 2
    assert r["peak_mb"] < 1024  # the memory target for a filtered floor
    assert os.path.getsize(tmp_path / "f5.png") < 400_000
