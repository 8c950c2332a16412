"""Fuzzing the DXF reader and the pipeline with hypothesis (issue 13, robustness).

Mutated versions of the sample building's first floor (truncation, byte flips, deleted sections, deleted
or swapped lines, NaN / inf / huge / garbage coordinates, duplicated entity runs) must each import or fail
with an ``InputError`` that says what is wrong, within a time limit, without a hard crash (every case runs
in a separate worker process, see tests/fuzz_support.py) and, for whole conversions, without leaving any
file behind. Hostile drawings built on purpose (blocks that insert themselves, block bombs, 10^6 copies of
one line, a stray entity 100 km away, zero-length and self-overlapping entities, NaN coordinates and block
scales) are regular tests. The examples are derandomized: every run tests the same cases.

Fast subset: ``test_fuzz_dxf_import_quick`` (40 cases). Full run (slow): 460 import cases + 40 whole
conversions.
"""
import os
import re
import tempfile
import time
from pathlib import Path

import ezdxf
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from algorithms import cad_explode, cad_import, osmag, pipeline
from algorithms.errors import InputError

from .conftest import REPO
from .fuzz_support import Isolated, add_block_bomb, leftovers

IMPORT_LIMIT = 60.0  # s per import on the loaded 2-core machine (a clean import takes 0.1-0.5 s of CPU)
CONVERT_LIMIT = 120.0

_BASE = {}


def base_dxf() -> Path:
    """The sample building's floor 1 (116 kB, mm, blocks, hatches, texts), generated once per process."""
    if "path" not in _BASE:
        from algorithms.sample_building import generate_building

        folder = tempfile.mkdtemp(prefix="cad2osmag-fuzz-")
        _BASE["path"] = Path(generate_building(folder, floors=1, seed=0)["dxf"][0])
        _BASE["bytes"] = _BASE["path"].read_bytes()
    return _BASE["path"]


def base_bytes() -> bytes:
    base_dxf()
    return _BASE["bytes"]


# ------------------------------------------------------------------------------------------ mutations
BAD_NUMBERS = ["nan", "NaN", "inf", "-inf", "1e300", "-1e308", "1e20", "1.7976931348623157e308", "", "abc",
               "0x1F", "1,5", "--3", "1e-320"]
COORD_CODES = {"10", "20", "11", "21", "12", "22", "13", "23", "40", "41", "42", "43", "50", "51", "70", "71"}


def _lines(data: bytes):
    return data.split(b"\n")


@st.composite
def mutated_dxf(draw):
    data = base_bytes()
    kind = draw(st.sampled_from(["truncate", "flip", "delete_section", "delete_lines", "coords", "swap",
                                 "duplicate", "mixed"]))
    kinds = [kind] if kind != "mixed" else draw(st.lists(st.sampled_from(
        ["truncate", "flip", "delete_lines", "coords", "swap"]), min_size=2, max_size=3))
    for k in kinds:
        data = _mutate(draw, k, data)
    return kind, data


def _mutate(draw, kind, data: bytes) -> bytes:
    if len(data) < 2:  # a "mixed" chain may have truncated everything already
        return data
    if kind == "truncate":
        return data[:draw(st.integers(0, len(data)))]
    if kind == "flip":
        b = bytearray(data)
        for _ in range(draw(st.integers(1, 24))):
            i = draw(st.integers(0, len(b) - 1))
            b[i] ^= draw(st.integers(1, 255))
        return bytes(b)
    lines = _lines(data)
    if kind == "delete_section":
        starts = [i for i in range(1, len(lines) - 3) if lines[i].strip() == b"SECTION" and lines[i + 1].strip() == b"2"]
        if not starts:
            return data
        i = draw(st.sampled_from(starts))
        j = next((k for k in range(i, len(lines)) if lines[k].strip() == b"ENDSEC"), len(lines) - 1)
        return b"\n".join(lines[:i - 1] + lines[j + 1:])
    if kind == "delete_lines":
        i = draw(st.integers(0, len(lines) - 1))
        n = draw(st.integers(1, 400))
        return b"\n".join(lines[:i] + lines[i + n:])
    if kind == "coords":
        values = [i + 1 for i in range(0, len(lines) - 1) if lines[i].strip().decode("latin-1") in COORD_CODES]
        if not values:
            return data
        for _ in range(draw(st.integers(1, 12))):
            i = draw(st.sampled_from(values))
            lines[i] = draw(st.sampled_from(BAD_NUMBERS)).encode()
        return b"\n".join(lines)
    if kind == "swap":
        for _ in range(draw(st.integers(1, 6))):
            i, j = draw(st.integers(0, len(lines) - 1)), draw(st.integers(0, len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        return b"\n".join(lines)
    if kind == "duplicate":  # a run of entities pasted many times (copy-paste in place)
        ent = [i for i in range(len(lines)) if lines[i].strip() == b"ENTITIES"]
        if not ent:
            return data
        if ent[0] + 1 > len(lines) - 2:
            return data
        i = draw(st.integers(ent[0] + 1, len(lines) - 2))
        i -= (i - ent[0] - 1) % 2  # keep code/value pairs aligned
        n = 2 * draw(st.integers(1, 100))
        return b"\n".join(lines[:i] + lines[i:i + n] * draw(st.integers(2, 300)) + lines[i:])
    raise AssertionError(kind)


# ------------------------------------------------------------------------------------------ checks
@pytest.fixture(scope="module")
def worker():
    w = Isolated(REPO)
    yield w
    w.close()


def check_outcome(status, payload, name: str):
    """ok, or an InputError that names the file or the problem; never a crash, a hang or a raw error."""
    assert status in ("ok", "input"), f"{status}: {payload}"
    if status == "input":
        msg = payload
        assert len(msg) >= 25 and "Traceback" not in msg, msg
        assert name in msg or re.search(r"layer|geometr|entit|drawing|raster|area|block|unit|extent|model space",
                                        msg, re.I), msg


def _fuzz_import(worker, case):
    kind, data = case
    folder = tempfile.mkdtemp(prefix="fuzz-dxf-")
    path = os.path.join(folder, "mutant.dxf")
    with open(path, "wb") as fh:
        fh.write(data)
    t0 = time.monotonic()
    status, payload = worker.run("import", path, timeout=IMPORT_LIMIT)
    check_outcome(status, payload, "mutant.dxf")
    assert time.monotonic() - t0 < IMPORT_LIMIT
    os.remove(path)
    os.rmdir(folder)


FUZZ = dict(derandomize=True, deadline=None, database=None, print_blob=True,
            suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.large_base_example])


@settings(max_examples=40, **FUZZ)
@given(case=mutated_dxf())
def test_fuzz_dxf_import_quick(worker, case):
    _fuzz_import(worker, case)


@pytest.mark.slow
@settings(max_examples=460, **FUZZ)
@given(case=mutated_dxf())
def test_fuzz_dxf_import_full(worker, case):
    _fuzz_import(worker, case)


@pytest.mark.slow
@settings(max_examples=40, **FUZZ)
@given(case=mutated_dxf().filter(lambda c: c[0] in ("coords", "flip", "delete_lines", "duplicate", "swap")))
def test_fuzz_dxf_whole_conversion_writes_all_or_nothing(worker, case):
    kind, data = case
    folder = tempfile.mkdtemp(prefix="fuzz-conv-")
    path, out, png = (os.path.join(folder, n) for n in ("mutant.dxf", "mutant.osm", "mutant.png"))
    with open(path, "wb") as fh:
        fh.write(data)
    status, payload = worker.run("convert", path, out, preview_png=png, anchor_lon=121.59, anchor_lat=31.18,
                                 timeout=CONVERT_LIMIT)
    check_outcome(status, payload, "mutant.dxf")
    if status == "ok":
        assert leftovers(folder) == ["mutant.dxf", "mutant.osm", "mutant.png"]
        areas, passages, root, report = osmag.read_osmag(out)  # a complete, valid osmAG file
        assert len([a for a in areas if a.type != "structure"]) == payload["areas"]
        assert report["unclosed"] == [] and report["dangling_nodes"] == {}
    else:
        assert leftovers(folder) == ["mutant.dxf"], "a failed conversion left files behind"
    for f in leftovers(folder):
        os.remove(os.path.join(folder, f))
    os.rmdir(folder)


# ------------------------------------------------------------------------------------------ built on purpose
def _doc():
    return ezdxf.readfile(str(base_dxf()))


def _save(doc, tmp_path, name="hostile.dxf"):
    p = str(tmp_path / name)
    doc.saveas(p)
    return p


@pytest.fixture(scope="module")
def reference():
    """The unmodified floor's conversion: hostile additions that are not walls must not change it."""
    with tempfile.TemporaryDirectory() as d:
        r = pipeline.convert_dxf(str(base_dxf()), os.path.join(d, "ref.osm"))
    return r


def _convert(path, tmp_path):
    out = tmp_path / "out.osm"
    t0 = time.process_time()
    try:
        r = pipeline.convert_dxf(path, str(out))
    except InputError as exc:
        assert not out.exists()
        return None, str(exc), time.process_time() - t0
    assert out.exists()
    return r, "", time.process_time() - t0


def _add_self_inserting(doc, msp):
    b = doc.blocks.new("SELF")
    b.add_line((0, 0), (1000, 0), dxfattribs={"layer": "0"})
    b.add_blockref("SELF", (10, 10))
    msp.add_blockref("SELF", (5000, 5000), dxfattribs={"layer": "A-FURN"})
    a, c = doc.blocks.new("PING"), doc.blocks.new("PONG")
    a.add_blockref("PONG", (0, 0))
    c.add_blockref("PING", (0, 0))
    c.add_line((0, 0), (100, 0))
    msp.add_blockref("PING", (0, 0), dxfattribs={"layer": "A-FURN"})


def _add_stray_100km(doc, msp):
    msp.add_line((1e8, 1e8), (1e8 + 3000, 1e8), dxfattribs={"layer": "A-WALL"})  # mm: 141 km away


def _add_stray_line_1e9m(doc, msp):
    msp.add_line((0, 0), (1e12, 0), dxfattribs={"layer": "A-WALL"})  # mm: one line 10^9 m long
    msp.add_line((-1e12, 5e11), (-1e12 + 3000, 5e11), dxfattribs={"layer": "A-WALL"})  # a short one 10^9 m away


def _add_nan_and_huge(doc, msp):
    nan, inf = float("nan"), float("inf")
    msp.add_line((nan, 0), (inf, 5), dxfattribs={"layer": "A-WALL"})
    msp.add_line((1e300, 0), (-1e300, 0), dxfattribs={"layer": "A-WALL"})
    msp.add_lwpolyline([(0, 0), (nan, 1), (2, -inf)], dxfattribs={"layer": "A-WALL"})
    msp.add_circle((nan, 0), 5, dxfattribs={"layer": "A-WALL"})
    msp.add_arc((0, 0), inf, 0, 90, dxfattribs={"layer": "A-WALL"})
    msp.add_text("NaN room", dxfattribs={"insert": (nan, nan), "layer": "A-ANNO"})
    b = doc.blocks.new("SCALED")
    b.add_line((0, 0), (100, 0))
    msp.add_blockref("SCALED", (0, 0), dxfattribs={"layer": "A-WALL", "xscale": 1e300, "yscale": 0})
    msp.add_blockref("SCALED", (0, 0), dxfattribs={"layer": "A-WALL", "xscale": nan})


def _add_degenerate(doc, msp):
    for i in range(200):
        msp.add_line((i * 100, 0), (i * 100, 0), dxfattribs={"layer": "A-WALL"})
    msp.add_circle((0, 0), 0, dxfattribs={"layer": "A-WALL"})
    msp.add_lwpolyline([(5, 5)], dxfattribs={"layer": "A-WALL"})
    msp.add_lwpolyline([(0, 0), (10000, 0), (0, 0), (10000, 0), (0, 0)], close=True, dxfattribs={"layer": "A-WALL"})
    h = msp.add_hatch(dxfattribs={"layer": "A-WALL"})
    h.paths.add_polyline_path([(0, 0), (1000, 1000), (1000, 0), (0, 1000)])  # a bow tie
    h2 = msp.add_hatch(dxfattribs={"layer": "A-WALL"})
    h2.paths.add_polyline_path([(0, 0), (0, 0), (0, 0)])


@pytest.mark.parametrize("mutate", [_add_self_inserting, _add_stray_100km, _add_stray_line_1e9m, _add_nan_and_huge,
                                    _add_degenerate],
                         ids=["self-inserting blocks", "100 km stray", "1e9 m stray line", "NaN-inf-huge",
                              "zero-length, self-overlapping"])
def test_hostile_additions_leave_the_floor_unchanged(mutate, reference, tmp_path):
    doc = _doc()
    mutate(doc, doc.modelspace())
    r, err, cpu = _convert(_save(doc, tmp_path), tmp_path)
    assert r is not None, err
    assert (r["areas"], r["passages"], r["raster_shape"]) == (reference["areas"], reference["passages"],
                                                               reference["raster_shape"])
    assert cpu < 20


def test_an_entity_longer_than_any_building_is_left_out_and_reported(tmp_path):
    doc = _doc()
    _add_stray_line_1e9m(doc, doc.modelspace())
    d = cad_import.import_dxf(_save(doc, tmp_path))
    assert any("left out 1 entities longer than 20 km" in w for w in d.warnings), d.warnings
    assert max(float(abs(g.coords).max()) for g in d.geometries) < 1e8


def test_self_inserting_blocks_are_reported(tmp_path):
    doc = _doc()
    _add_self_inserting(doc, doc.modelspace())
    d = cad_import.import_dxf(_save(doc, tmp_path))
    assert any("contains itself" in w for w in d.warnings)


def test_non_finite_coordinates_are_left_out_and_reported(tmp_path):
    doc = _doc()
    _add_nan_and_huge(doc, doc.modelspace())
    d = cad_import.import_dxf(_save(doc, tmp_path))
    assert all(np.isfinite(g.coords[~np.isnan(g.coords).all(axis=1)]).all() for g in d.geometries)
    assert all(np.abs(g.coords[np.isfinite(g.coords).all(axis=1)]).max() < 1e6 for g in d.geometries)
    assert all(np.isfinite([t.x, t.y]).all() for t in d.texts)
    assert any("not finite" in w for w in d.warnings)


def test_a_million_copies_of_one_line_stop_fast_with_advice(tmp_path):
    doc = _doc()
    b = doc.blocks.new("ONE")
    b.add_line((0, 0), (100, 0))
    doc.modelspace().add_blockref("ONE", (0, 0), dxfattribs={"layer": "A-WALL"}).grid(size=(1000, 1000),
                                                                                      spacing=(10, 10))
    t0 = time.process_time()
    with pytest.raises(InputError, match=r"(?s)more than 1,000,000 entities.*'ONE'.*1,000,000 copies.*OVERKILL"):
        cad_import.import_dxf(_save(doc, tmp_path))
    assert time.process_time() - t0 < 10


def test_block_bomb_stops_before_filling_the_memory(tmp_path):
    doc = _doc()
    add_block_bomb(doc, 9)  # 10^8 lines once exploded
    out = tmp_path / "bomb.osm"
    t0 = time.process_time()
    with pytest.raises(InputError, match="nests blocks too deeply"):
        pipeline.convert_dxf(_save(doc, tmp_path), str(out))
    assert time.process_time() - t0 < 20 and not out.exists()


def test_minsert_with_zero_spacing_is_one_copy_and_huge_counts_are_refused(tmp_path):
    doc = _doc()
    b = doc.blocks.new("ONE")
    b.add_line((0, 0), (100, 0))
    doc.modelspace().add_blockref("ONE", (0, 0), dxfattribs={"layer": "A-WALL"}).grid(size=(30000, 30000),
                                                                                      spacing=(0, 0))
    base = cad_import.import_dxf(str(base_dxf()))
    d = cad_import.import_dxf(_save(doc, tmp_path))  # coinciding copies are one copy, as in ezdxf
    assert len(d.geometries) == len(base.geometries) + 1
    doc.modelspace().add_blockref("ONE", (0, 0), dxfattribs={"layer": "A-WALL"}).grid(size=(30000, 30000),
                                                                                      spacing=(5, 5))
    with pytest.raises(InputError, match="900,000,000 copies"):
        cad_import.import_dxf(_save(doc, tmp_path, "huge.dxf"))


@pytest.mark.parametrize("rotation,extrusion", [(0.0, (0, 0, 1)), (30.0, (0, 0, 1)), (-75.0, (0, 0, -1))])
def test_minsert_grid_equals_ezdxf_multi_insert(tmp_path, rotation, extrusion):
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 6
    blk = doc.blocks.new("CELL", base_point=(1, 2))
    blk.add_lwpolyline([(0, 0), (3, 0), (3, 2)], dxfattribs={"layer": "0"})
    msp = doc.modelspace()
    for x in (0, 40):
        msp.add_line((x, 0), (x, 30), dxfattribs={"layer": "A-WALL"})
    ins = msp.add_blockref("CELL", (10, 5), dxfattribs={"layer": "A-WALL", "rotation": rotation,
                                                        "xscale": 1.5, "yscale": 0.5, "extrusion": extrusion})
    ins.grid(size=(3, 4), spacing=(4, 6))
    path = _save(doc, tmp_path)
    got = sorted(tuple(np.round(g.coords, 9).ravel()) for g in cad_import.import_dxf(path).geometries
                 if g.entity == "LWPOLYLINE")
    want = []
    cell = np.array([(0, 0), (3, 0), (3, 2)], float)
    for one in ins.multi_insert():
        m = one.matrix44()
        pts = [m.transform((x, y, 0)) for x, y in cell]
        want.append(tuple(np.round(np.array([(p.x, p.y) for p in pts]), 9).ravel()))
    assert len(got) == 12 and got == sorted(want)


def test_model_space_with_too_many_entities_is_refused(tmp_path, monkeypatch):
    monkeypatch.setattr(cad_explode, "MAX_EXPLODED", 100)  # the same rule as 10^6 LINEs, on a small file
    with pytest.raises(InputError, match=r"holds \d[\d,]* entities in model space.*OVERKILL"):
        cad_import.import_dxf(str(base_dxf()))


def test_a_spline_with_a_damaged_control_point_is_left_out_not_subdivided_forever(worker, tmp_path):
    """A byte flip turned a SPLINE control point into -2e266 (A-A3-10-08.dwg, test_fuzz_dwg.py): the adaptive
    flattening halves the chord until it is within the tolerance of the curve and never ended. Such a spline is
    not subdivided; its far point is left out with the other non-finite coordinates."""
    doc = _doc()
    msp = doc.modelspace()
    msp.add_open_spline([(0, 0), (1000, 500), (-2.02e266, -650), (3000, 0)], degree=3,
                        dxfattribs={"layer": "A-WALL"})
    path = _save(doc, tmp_path)
    t0 = time.monotonic()
    status, payload = worker.run("import", path, timeout=IMPORT_LIMIT)
    assert status == "ok", (status, str(payload)[:500])
    assert any("not finite" in w for w in payload["warnings"]), payload["warnings"]
    assert time.monotonic() - t0 < IMPORT_LIMIT
