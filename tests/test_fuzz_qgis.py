"""Hostile input headless (qgis_process): the algorithm fails with a QgsProcessingException whose message
names the problem, QGIS itself does not crash (no signal, no Python traceback), nothing is written."""
import pytest

from .fuzz_support import add_block_bomb
from .qgis_process import run_alg
from .test_fuzz_dxf import base_bytes, base_dxf


def _check_failed_cleanly(code, text, outputs, *expect):
    assert code > 0, f"qgis_process ended with {code} (a negative code is a signal: QGIS crashed)\n{text[-2000:]}"
    assert "Traceback" not in text, text[-3000:]
    for e in expect:
        assert e in text, (e, text[-2000:])
    for p in outputs:
        assert not p.exists(), f"{p} was written by a failed run"


@pytest.mark.qgis_process
def test_damaged_dwg_headless(tmp_path):
    from .test_fuzz_dwg import base

    data = base("sample")
    src = tmp_path / "halved.dwg"
    src.write_bytes(data[:len(data) // 2])  # a download cut in the middle
    out, png = tmp_path / "f.osm", tmp_path / "f.png"
    code, _, text = run_alg("dxftoosmag", {"INPUT": str(src), "OUTPUT": str(out), "PREVIEW": str(png)}, check=False)
    _check_failed_cleanly(code, text, [out, png], "halved.dwg", "truncated")


@pytest.mark.slow
@pytest.mark.qgis_process
@pytest.mark.parametrize("case", ["truncated", "bomb"])
def test_hostile_dxf_headless(tmp_path, case):
    import ezdxf

    src = tmp_path / f"{case}.dxf"
    if case == "truncated":
        src.write_bytes(base_bytes()[:9000])
        expect = ["truncated.dxf"]
    else:
        doc = ezdxf.readfile(str(base_dxf()))
        add_block_bomb(doc, 8)
        doc.saveas(str(src))
        expect = ["nests blocks too deeply"]
    out, png = tmp_path / "f.osm", tmp_path / "f.png"
    code, _, text = run_alg("dxftoosmag", {"INPUT": str(src), "OUTPUT": str(out), "PREVIEW": str(png)}, check=False)
    if case == "truncated" and code == 0:  # salvaged: then the output must be a complete osmAG file
        from algorithms.osmag import read_osmag

        read_osmag(str(out))
        return
    _check_failed_cleanly(code, text, [out, png], *expect)
