"""Stages 1-2 on every real plan in ../shared/data/dxf (ArchWeb plans and the SIST floor set)."""
import re

import numpy as np
import pytest

from algorithms.cad_import import list_layers
from algorithms.model import FREE, OCCUPIED
from algorithms.rasterize import floor_grids, floor_offsets, rasterize

pytestmark = pytest.mark.slow

# unit each ArchWeb plan is really drawn in (every header says mm)
ARCHWEB_UNITS = {
    "Aule-scolastiche-pianta-1": "m", "CASONA_DE_YANAHUARA": "m", "Universita-pianta-02": "m",
    "historical_museum": "mm", "kindergarten-1": "mm", "modular_housing": "mm", "office": "mm",
    "schema-ufficio-1": "m",
}
NOT_STRUCTURE = re.compile(r"arred|furn|quot|dim|txt|text|cota|movil|mebel|мебел|hatch pattern|www\.", re.I)


def _free_stats(grid):
    import cv2

    free = (grid.data == FREE).astype(np.uint8)
    n, _, st, _ = cv2.connectedComponentsWithStats(free, connectivity=4)
    areas = np.sort(st[1:, cv2.CC_STAT_AREA])[::-1]
    return float(areas[0]) / float(free.sum()), n - 1


@pytest.fixture(scope="module")
def archweb(shared_data, floor_cache):
    files = sorted((shared_data / "dxf" / "archweb").glob("*.dxf"))
    assert len(files) >= 8
    out = {}
    for f in files:
        d = floor_cache.import_dxf(f)  # what the session's conversions read (tests/conftest.py)
        out[f.stem] = (d, rasterize(d.geometries))
    return out


@pytest.fixture(scope="module")
def sist(shared_data, floor_cache):
    files = sorted((shared_data / "dxf" / "sist").glob("SIST-F*.dxf"))
    assert len(files) == 5
    return [floor_cache.import_dxf(f) for f in files]


def test_archweb_units_are_chosen_by_plausibility(archweb):
    for name, (d, _) in archweb.items():
        assert d.header_unit == "mm"
        assert d.unit_name == ARCHWEB_UNITS[name], name
        if d.unit_name != "mm":
            assert any("using m" in w and "mm" in w for w in d.warnings), name


def test_archweb_rasters_show_the_building(archweb):
    for name, (d, g) in archweb.items():
        occ = float((g.data == OCCUPIED).mean())
        share, _ = _free_stats(g)
        xmin, ymin, xmax, ymax = g.extent
        size = max(xmax - xmin, ymax - ymin)
        assert 0.02 <= occ <= 0.40, (name, occ)
        # free space is one large connected component. (Since whole sheets keep only their main plan, the
        # kindergarten's raster no longer holds the second level and the sections, whose surroundings added
        # outside space to that component: 0.65 there.)
        assert share >= 0.60, (name, share)
        assert 5.0 <= size <= 500.0, (name, size)
        assert g.data.size <= 60e6


def test_archweb_walls_exclude_text_furniture_and_dimensions(archweb):
    for name, (d, _) in archweb.items():
        kept = {g.layer for g in d.geometries}
        assert kept, name
        bad = [lay for lay in kept if NOT_STRUCTURE.search(lay)]
        assert not bad, (name, bad)
    # the free-form wall layers are recognised
    assert "MURATURA sezioni - section wall" in {g.layer for g in archweb["Aule-scolastiche-pianta-1"][0].geometries}
    assert "стены" in {g.layer for g in archweb["modular_housing"][0].geometries}
    assert "wall" in {g.layer for g in archweb["historical_museum"][0].geometries}
    # texts are kept for later, with their source layer
    texts = archweb["schema-ufficio-1"][0].texts
    assert len(texts) >= 30 and any(t.layer == "SCRITTE - txt" for t in texts)


def test_archweb_layer_report_counts_after_explosion(shared_data):
    infos = {i.name: i for i in list_layers(str(shared_data / "dxf" / "archweb" / "kindergarten-1.dxf"))}
    # every model-space entity sits on layer 0 and inside blocks; explosion moves counts to real layers
    assert infos["EXTERIOR_WALLS"].counts and infos["columns"].counts
    assert infos["FURNITURE_&_EQUIPMENT"].kind is None
    assert sum(sum(i.counts.values()) for i in infos.values()) > 11236


def test_sist_floors_import_in_millimetres(sist):
    for d in sist:
        assert d.unit_name == "mm" and not any("implausible" in w for w in d.warnings)
        assert len(d.geometries) > 3000
    assert 13000 <= len(sist[4].geometries) <= 17000  # SIST-F5: ~15 k entities after explosion


def test_sist_floors_align_on_a_common_grid(sist):
    import cv2

    sets = [d.geometries for d in sist]
    raw = floor_offsets(sets)
    # F2 and F4 are drawn in the same frame: their offsets to F1 agree within 5 cm
    assert np.hypot(raw[1][0] - raw[3][0], raw[1][1] - raw[3][1]) < 0.05
    grids, offs = floor_grids(sets)
    shapes = {g.shape for g in grids}
    assert len(shapes) == 1 and grids[0].data.size <= 60e6
    for g, (dx, dy) in zip(grids, offs):
        # each geotransform maps onto the floor's own frame: origin = common origin - offset
        assert g.origin_x == pytest.approx(grids[0].origin_x - dx, abs=1e-6)
        assert g.origin_y == pytest.approx(grids[0].origin_y - dy, abs=1e-6)
        occ = float((g.data == OCCUPIED).mean())
        assert 0.02 <= occ <= 0.40
    k = cv2.getStructuringElement(cv2.MORPH_RECT, (5, 5))
    a = grids[1].data > 0
    for j in (0, 3, 4):  # walls of F2 lie on walls of other floors, and a 1 m shift breaks it
        b = cv2.dilate(grids[j].data, k) > 0
        aligned = (a & b).sum() / a.sum()
        shifted = (np.roll(a, (23, 23), axis=(0, 1)) & b).sum() / a.sum()
        assert aligned > 0.4 and aligned > 3 * shifted, (j, aligned, shifted)
