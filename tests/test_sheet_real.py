"""Whole sheets, spaghetti plans and bound-xref layers on the shared real drawings (slow).

The DWG sheets need the DWG reader (algorithms/cad_dwg.py); the tests skip with a reason without it.
Plan counts were counted by hand once on each sheet (pictures of the groups found) and are pinned here."""
import os

import numpy as np
import pytest

from algorithms.cad_import import import_dxf, list_layers

from .conftest import REPO

DATA = os.path.normpath(os.path.join(str(REPO), "..", "shared", "data"))
ARCHWEB = os.path.join(DATA, "dxf", "archweb")
DWG = os.path.join(DATA, "dwg")

pytestmark = pytest.mark.slow


def _need(path):
    if not os.path.exists(path):
        pytest.skip(f"shared data missing: {path}")
    return path


def _need_dwg(path):
    try:
        import algorithms.cad_dwg  # noqa: F401
    except ImportError:
        pytest.skip("the DWG reader (algorithms.cad_dwg, task A) is not merged yet")
    return _need(path)


def _plans(d, kind="plan"):
    return [p for p in d.plans if p.kind == kind]


# ------------------------------------------------------------------------------------------ ArchWeb
def test_office_plan_keeps_its_doorways_open_with_door_hints(floor_cache):
    d = floor_cache.import_dxf(_need(os.path.join(ARCHWEB, "office.dxf")))
    assert len(d.doors) >= 25  # 30 measured: the 'doors' layer's swings, jamb to jamb
    assert all(0.5 <= h.width <= 2.0 for h in d.doors)
    assert d.classes["door"] > 1000  # the door layer (leaves, swings, frames) is left out
    assert not any(g.kind == "door" for g in d.geometries)


def test_museum_sheet_takes_the_plan_not_the_section(floor_cache):
    """The section 1-1 above the plan has more wall mass than the plan: its title makes it a detail."""
    d = floor_cache.import_dxf(_need(os.path.join(ARCHWEB, "historical_museum.dxf")))
    assert [p.kind for p in d.plans] == ["plan", "detail"]
    assert "section" in d.plans[1].title.lower() and d.plans[1].wall_length > d.plans[0].wall_length
    x0, y0, x1, y1 = d.plans[0].extent
    assert 110 < x1 - x0 < 140 and 30 < y1 - y0 < 45
    assert len(d.doors) >= 30


def test_kindergarten_sheet_has_two_floor_plans_side_by_side_and_sections(floor_cache):
    d = floor_cache.import_dxf(_need(os.path.join(ARCHWEB, "kindergarten-1.dxf")))
    plans = _plans(d)
    assert len(plans) == 2  # levels 1 and 2 drawn side by side: two plans, never merged
    assert plans[0].extent[2] < plans[1].extent[0]
    assert all(140 < p.extent[2] - p.extent[0] < 150 for p in plans)
    assert sum("section" in p.title.lower() for p in _plans(d, "detail")) >= 2
    assert d.classes["furniture"] > 1000  # sinks (МОЙКА), desks... by block name, on layer 0
    d2 = import_dxf(os.path.join(ARCHWEB, "kindergarten-1.dxf"), plan=1)
    assert all(np.nanmin(g.coords[:, 0]) >= plans[1].extent[0] - 1 for g in d2.geometries)


@pytest.mark.parametrize("name", sorted(os.listdir(ARCHWEB)) if os.path.isdir(ARCHWEB) else [])
def test_every_archweb_plan_finds_one_main_plan(name, floor_cache):
    d = floor_cache.import_dxf(os.path.join(ARCHWEB, name))
    assert d.plans[0].selected and d.plans[0].kind == "plan"
    assert [t.id for t in d.texts] == list(range(len(d.texts)))


# ------------------------------------------------------------------------------------------ DWG sheets
# hand counts: plan-kind groups on each sheet, and the main plan's size (m)
SHEETS = {
    "sist-original/SIST-F1.dwg": (1, (170, 190), (140, 160)),  # measured 178 x 149 m
    "sist-original/SIST-F3.dwg": (1, (160, 185), (125, 145)),  # 171 x 136
    "sist-original/SIST-F4.dwg": (1, (160, 185), (125, 145)),  # 171 x 135
    "sist-original/SIST-F5.dwg": (1, (160, 185), (130, 150)),  # 171 x 142
    # 95 x 114: the clover-shaped pavilion just below the building (10 % of its walls) joins it as a wing
    "library/A-A3-10-04.dwg": (1, (85, 105), (105, 125)),
    "library/A-A3-10-05.dwg": (1, (85, 105), (105, 125)),
    "library/A-A3-10-06.dwg": (1, (85, 105), (85, 100)),  # 95 x 92
}


@pytest.mark.parametrize("sheet", sorted(SHEETS))
def test_dwg_sheet_plans(sheet, floor_cache):
    d = floor_cache.import_dxf(_need_dwg(os.path.join(DWG, sheet)))
    n, (wlo, whi), (hlo, hhi) = SHEETS[sheet]
    main = d.plans[0]
    assert main.selected and main.kind == "plan"
    x0, y0, x1, y1 = main.extent
    assert wlo <= x1 - x0 <= whi and hlo <= y1 - y0 <= hhi, main
    assert len(_plans(d)) == n, [(p.index, p.kind, p.title, p.wall_length) for p in d.plans[:8]]
    # the main plan holds by far the most wall: details are small
    assert all(p.wall_length < 0.2 * main.wall_length for p in d.plans[1:])
    assert len(d.doors) >= 40  # door blocks / swings found on every sheet (44-151 measured)


def test_library_roof_sheet_still_finds_a_plan(floor_cache):
    d = floor_cache.import_dxf(_need_dwg(os.path.join(DWG, "library", "A-A3-10-08.dwg")))
    assert d.plans[0].selected and d.plans[0].kind == "plan" and d.plans[0].wall_length > 100


def test_sist_f1_original_picks_the_main_plan_not_a_detail(floor_cache):
    d = floor_cache.import_dxf(_need_dwg(os.path.join(DWG, "sist-original", "SIST-F1.dwg")))
    main = d.plans[0]
    assert main.selected and main.kind == "plan" and main.wall_length > 3000
    assert all(np.nanmin(g.coords[:, 0]) >= main.extent[0] - 1 and np.nanmax(g.coords[:, 0]) <= main.extent[2] + 1
               for g in d.geometries)
    assert len(d.doors) >= 100  # 145 measured: door blocks and swings on the A—门窗 / A-DOOR layers


def test_dwg_bound_xref_layers_match_their_meaningful_part():
    infos = {i.name: i for i in list_layers(_need_dwg(os.path.join(DWG, "sist-original", "SIST-F1.dwg")))}
    xref_walls = [i for n, i in infos.items() if "$0$" in n and i.matched.upper() == "A-WALL"]
    assert xref_walls and all(i.kind == "wall" for i in xref_walls)
    assert all(i.matched == i.name.split("$")[-1] for n, i in infos.items() if "$0$" in n and not n.endswith("$"))
