"""Fuzzing the DWG reader (ezdwg's Rust decoders behind algorithms/cad_dwg.py) with hypothesis.

Two bases: the smallest shared sheet, A-A3-10-08.dwg (R2004: compressed sections, GBK texts, 10 061
entities), and the sample building's floor 1 written as an R2000 DWG with ezdwg (uncompressed object
stream: byte flips reach the object decoders directly). Mutations: truncation, byte flips (anywhere, or
in the first 0x100 header bytes), zeroed or deleted byte ranges, a patched version string, duplicated
ranges. Every case runs in a separate worker process (tests/fuzz_support.py): a Rust panic that aborts
or a segfault is reported as a crash, not as a dead pytest. Each case must import or fail with an
``InputError`` naming the file, within the time limit. Derandomized: every run tests the same cases.

Fast subset: 12 cases. Full run (slow): 560 cases (A-A3-10-08: 500, the issue's count for one shared DWG; sample
R2000: 60; a sheet case costs ~0.3 s, a sample case ~0.2 s at load ~1).
"""
import os
import tempfile
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import REPO, SHARED_DATA
from .fuzz_support import Isolated
from .test_fuzz_dxf import base_dxf, check_outcome

ezdwg = pytest.importorskip("ezdwg")

LIMIT = 60.0  # s per case on the loaded machine (a clean read of A-A3-10-08: 0.9 s of CPU)
# cases in the full run: the 500 of the shared sheet (157 s wall for the 500 at load ~1, 2026-12-02: the
# run that found the spline hang below) and 60 of the sample floor as R2000 DWG (uncompressed: flips reach the
# object decoders directly; ~0.2 s each). Fewer for a quick look: CAD2OSMAG_FUZZ_SHEET / CAD2OSMAG_FUZZ_SAMPLE
SHEET_EXAMPLES = int(os.environ.get("CAD2OSMAG_FUZZ_SHEET", "500"))
SAMPLE_EXAMPLES = int(os.environ.get("CAD2OSMAG_FUZZ_SAMPLE", "60"))
SHEET = SHARED_DATA / "dwg" / "library" / "A-A3-10-08.dwg"
_BASES = {}


def base(name: str) -> bytes:
    if name not in _BASES:
        if name == "sheet":
            if not SHEET.is_file():
                pytest.skip(f"{SHEET} is missing")
            _BASES[name] = SHEET.read_bytes()
        else:
            from .test_dwg import dwg_copy_of

            folder = tempfile.mkdtemp(prefix="cad2osmag-fuzz-dwg-")
            path = os.path.join(folder, "sample-F1.dwg")
            dwg_copy_of(str(base_dxf()), path)
            with open(path, "rb") as fh:
                _BASES[name] = fh.read()
    return _BASES[name]


@st.composite
def mutated_dwg(draw, which=("sheet", "sample")):
    name = draw(st.sampled_from(which))
    data = bytearray(base(name))
    kind = draw(st.sampled_from(["truncate", "flip", "flip_header", "zero", "delete", "version", "duplicate"]))
    n = len(data)
    if kind == "truncate":
        data = data[:draw(st.integers(0, n - 1))]
    elif kind in ("flip", "flip_header"):
        hi = min(n, 0x100) if kind == "flip_header" else n
        for _ in range(draw(st.integers(1, 16))):
            i = draw(st.integers(0, hi - 1))
            data[i] ^= draw(st.integers(1, 255))
    elif kind == "zero":
        i = draw(st.integers(0, n - 1))
        k = draw(st.integers(1, 8192))
        data[i:i + k] = bytes(len(data[i:i + k]))
    elif kind == "delete":
        i = draw(st.integers(0, n - 1))
        del data[i:i + draw(st.integers(1, 8192))]
    elif kind == "version":
        data[:6] = draw(st.sampled_from([b"AC1009", b"AC1033", b"AC9999", b"AC1015", b"AC1018", b"AC1032",
                                         b"\x00\x00\x00\x00\x00\x00", b"AC10\xff\xfe"]))
    elif kind == "duplicate":
        i = draw(st.integers(0, n - 1))
        data[i:i] = data[i:i + draw(st.integers(1, 4096))]
    return name, kind, bytes(data)


@pytest.fixture(scope="module")
def worker():
    w = Isolated(REPO)
    yield w
    w.close()


def _fuzz(worker, case):
    name, kind, data = case
    folder = tempfile.mkdtemp(prefix="fuzz-dwg-")
    path = os.path.join(folder, "mutant.dwg")
    with open(path, "wb") as fh:
        fh.write(data)
    t0 = time.monotonic()
    status, payload = worker.run("import", path, timeout=LIMIT)
    check_outcome(status, payload, "mutant.dwg")
    assert time.monotonic() - t0 < LIMIT
    if status == "input":
        assert "mutant.dwg" in payload, payload
    os.remove(path)
    os.rmdir(folder)


FUZZ = dict(derandomize=True, deadline=None, database=None, print_blob=True,
            suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.large_base_example])


@settings(max_examples=12, **FUZZ)
@given(case=mutated_dwg())
def test_fuzz_dwg_import_quick(worker, case):
    _fuzz(worker, case)


@pytest.mark.slow
@settings(max_examples=SHEET_EXAMPLES, **FUZZ)
@given(case=mutated_dwg(("sheet",)))
def test_fuzz_dwg_shared_sheet_full(worker, case):
    _fuzz(worker, case)


@pytest.mark.slow
@settings(max_examples=SAMPLE_EXAMPLES, **FUZZ)
@given(case=mutated_dwg(("sample",)))
def test_fuzz_dwg_sample_r2000_full(worker, case):
    _fuzz(worker, case)


# seven bytes of A-A3-10-08.dwg flipped (hypothesis, CAD2OSMAG_FUZZ_SHEET=500 run of 2026-12-02): one turns a
# SPLINE control point into -2e266 and the import hung in the spline's adaptive flattening (cad_explode)
HANG_FLIPS = [(58, 1), (765, 77), (935, 1), (1803, 227), (3407, 167), (13048, 47), (510510, 107)]


@pytest.mark.slow
def test_the_flipped_sheet_that_hung_the_import_reads(worker):
    data = bytearray(base("sheet"))
    for i, v in HANG_FLIPS:
        data[i] = v
    folder = tempfile.mkdtemp(prefix="fuzz-dwg-hang-")
    path = os.path.join(folder, "mutant.dwg")
    with open(path, "wb") as fh:
        fh.write(bytes(data))
    status, payload = worker.run("import", path, timeout=LIMIT)
    os.remove(path)
    os.rmdir(folder)
    assert status == "ok", (status, str(payload)[:500])
    assert any("not finite" in w for w in payload["warnings"]) and payload["geometries"] > 200
