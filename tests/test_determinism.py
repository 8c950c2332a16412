"""Determinism: the same input gives a byte-identical osmAG file, run after run, in one process and
across processes with different PYTHONHASHSEED values (set iteration order, dict order of str keys
and hash-based containers must not leak into ids, names or node order)."""
import hashlib
import os
import subprocess
import sys

import pytest

from algorithms import pipeline

from .conftest import REPO
from .test_fuzz_dxf import base_dxf

ANCHOR = dict(anchor_lon=121.5906, anchor_lat=31.1790, rotation_deg=12.5)

_SCRIPT = """
import sys
sys.path.insert(0, {repo!r})
from algorithms import pipeline
pipeline.convert_dxf({src!r}, {out!r}, anchor_lon=121.5906, anchor_lat=31.1790, rotation_deg=12.5, level="2",
                     variant={variant!r})
"""


def _digest(path):
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def _run_in_process(src, out, seed, variant="semantic"):
    env = dict(os.environ, PYTHONHASHSEED=str(seed))
    code = _SCRIPT.format(repo=str(REPO), src=str(src), out=str(out), variant=variant)
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=900,
                          stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return _digest(out)


def test_two_runs_in_one_process_are_byte_identical(tmp_path):
    a, b = tmp_path / "a.osm", tmp_path / "b.osm"
    pipeline.convert_dxf(str(base_dxf()), str(a), level="2", **ANCHOR)
    pipeline.convert_dxf(str(base_dxf()), str(b), level="2", **ANCHOR)
    assert a.read_bytes() == b.read_bytes()
    assert a.stat().st_size > 10000


@pytest.mark.parametrize("variant", ["semantic", "fix-id"])
def test_runs_across_processes_and_hash_seeds_are_byte_identical(tmp_path, variant):
    here = tmp_path / "here.osm"
    pipeline.convert_dxf(str(base_dxf()), str(here), level="2", variant=variant, **ANCHOR)
    digests = {_run_in_process(base_dxf(), tmp_path / f"seed{seed}.osm", seed, variant) for seed in (0, 4242)}
    assert digests == {_digest(here)}


def test_sample_building_dxf_is_byte_identical_across_hash_seeds(tmp_path):
    """The input itself: the sample building generator writes the same bytes under any hash seed."""
    code = ("import sys; sys.path.insert(0, {repo!r}); from algorithms.sample_building import generate_building; "
            "generate_building({out!r}, floors=2, seed=5)")
    digests = []
    for seed in (1, 977):
        out = tmp_path / f"s{seed}"
        env = dict(os.environ, PYTHONHASHSEED=str(seed))
        proc = subprocess.run([sys.executable, "-c", code.format(repo=str(REPO), out=str(out))], env=env,
                              capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
        assert proc.returncode == 0, proc.stderr[-3000:]
        digests.append(sorted((p.name, _digest(p)) for p in out.iterdir()))
    assert digests[0] == digests[1] and len(digests[0]) >= 4


@pytest.mark.slow
def test_real_dxf_is_byte_identical_across_processes_and_hash_seeds(shared_data, tmp_path):
    src = shared_data / "dxf" / "sist" / "SIST-F3.dxf"
    digests = {_run_in_process(src, tmp_path / f"seed{seed}.osm", seed) for seed in (0, 31337)}
    assert len(digests) == 1


@pytest.mark.slow
def test_real_dwg_is_byte_identical_across_processes_and_hash_seeds(shared_data, tmp_path):
    src = shared_data / "dwg" / "sist-original" / "SIST-F4.dwg"
    if not src.is_file():
        pytest.skip(f"{src} is missing")
    digests = {_run_in_process(src, tmp_path / f"seed{seed}.osm", seed) for seed in (3, 2024)}
    assert len(digests) == 1


_MERGE = """
import sys
sys.path.insert(0, {repo!r})
from algorithms import building
building.merge_floor_files({paths!r}, {out!r}, building_name="B")
"""


def _floor_files(folder):
    """Three small floors (rooms round a corridor, a stair core and a lift, drawn 0.3 m and 2 degrees apart
    from floor to floor so that the registration has work to do), written as osmAG floor files."""
    from shapely import affinity
    from shapely.geometry import LineString, box

    from algorithms.georef import LocalFrame
    from algorithms.model import Area, Passage
    from algorithms.osmag import write_osmag

    paths = []
    for k in (1, 2, 3):
        cells = [(box(0, 0, 6, 5), "room", f"Room {k}01"), (box(6, 0, 12, 5), "room", f"Room {k}02"),
                 (box(0, 5, 12, 8), "corridor", "Corridor"), (box(12, 0, 16, 5), "stairs", "Stair A"),
                 (box(12, 5, 14.5, 8), "elevator", "Lift 1"), (box(14.5, 5, 16, 8), "room", "")]
        areas = [Area(id=10 * k + i, polygon=affinity.rotate(affinity.translate(p, 0.3 * k, 0), 2 * k, origin=(0, 0)),
                      type=t, name=n) for i, (p, t, n) in enumerate(cells)]
        doors = [(0, 2, [(2, 5), (3, 5)]), (1, 2, [(8, 5), (9, 5)]), (3, 2, [(12.5, 5), (13.5, 5)]),
                 (4, 2, [(12, 6), (12, 7)]), (5, 2, [(14.6, 5), (15.4, 5)])]
        passages = [Passage(id=100 * k + j, from_id=areas[a].id, to_id=areas[b].id,
                            line=affinity.rotate(affinity.translate(LineString(c), 0.3 * k, 0), 2 * k, origin=(0, 0)))
                    for j, (a, b, c) in enumerate(doors)]
        path = folder / f"F{k}.osm"
        write_osmag(str(path), areas, passages, frame=LocalFrame(121.5906, 31.1790), level=str(k))
        paths.append(str(path))
    return paths


def test_merged_building_is_byte_identical_across_processes_and_hash_seeds(tmp_path):
    """The fused building (registration, vertical passages, building outline) is deterministic too."""
    from algorithms import building

    paths = _floor_files(tmp_path)
    here = tmp_path / "here.osm"
    st = building.merge_floor_files(paths, str(here), building_name="B")
    assert len(st["vertical"]) == 4  # the stair and the lift link 1-2 and 2-3: the merge did its work
    digests = set()
    for seed in (0, 777):
        out = tmp_path / f"seed{seed}.osm"
        env = dict(os.environ, PYTHONHASHSEED=str(seed))
        proc = subprocess.run([sys.executable, "-c", _MERGE.format(repo=str(REPO), paths=paths, out=str(out))],
                              env=env, capture_output=True, text=True, timeout=600, stdin=subprocess.DEVNULL)
        assert proc.returncode == 0, proc.stderr[-3000:]
        digests.add(_digest(out))
    assert digests == {_digest(here)}
