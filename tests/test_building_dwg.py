"""Stage 8 on the real deliverables: the original SIST sheets (F1, F3, F4, F5) and the library sheets
(A-A3-10-04..06), straight from DWG through `pipeline` (default settings: main plan, names on), fused into
one building each. `building.convert_floors` runs on the session's conversions (tests/conftest.py
`floor_cache`, which test_real_plans, test_semantics and test_sist_connect share: each sheet is converted once
per session, whatever level each caller gives); the tests then read the floors and merged buildings. Slow: the
first user of a sheet pays its conversion (~15-30 CPU s each). The process pool of `convert_floors` is tested
on small synthetic floors (test_convert_floors_pool_gives_what_one_process_gives)."""
from __future__ import annotations

import os
import time

import numpy as np
import pytest

from algorithms import building, osmag
from algorithms.progress import RecordingProgress

pytestmark = pytest.mark.slow

SIST = [f"SIST-F{k}.dwg" for k in (1, 3, 4, 5)]
LIBRARY = [f"A-A3-10-0{k}.dwg" for k in (4, 5, 6)]  # 08 is the roof plan (see test_roof_sheet_...)

# Shafts named on both sheets of a pair of consecutive converted SIST levels, counted once by hand from the
# DWG originals' TEXT/MTEXT (E1-ST-xx stairs, E1-Px/E2-Px lifts; block attributes not included). F2's
# original is missing: F1 and F3 are consecutive in this set.
SIST_NAMED_ON_BOTH = {
    ("1", "3"): ["E1-P1", "E1-P2", "E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06",
                 "E1-ST-08", "E1-ST-09", "E2-P1", "E2-P2", "E2-P3", "E2-P4", "E2-ST-01", "E2-ST-02"],
    ("3", "4"): ["E1-P2", "E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06", "E1-ST-07",
                 "E1-ST-08", "E1-ST-09", "E1-ST-15", "E2-P1", "E2-ST-01", "E2-ST-02", "E2-ST-05"],
    ("4", "5"): ["E1-P2", "E1-P3", "E1-ST-01", "E1-ST-02", "E1-ST-03", "E1-ST-04", "E1-ST-05", "E1-ST-06",
                 "E1-ST-07", "E1-ST-08", "E1-ST-09", "E2-P1", "E2-ST-01", "E2-ST-02"],
}
# Named on both sheets but drawn on one of the two plans only, with the evidence: no shaft spans the two
# converted levels, so there is nothing to link (re-checked 2026-12-02 on pictures of the plans registered by the
# fusion, and on entity counts; README "Fusion of the DWG sheets"). Every other hand-counted code is linked
# (asserted in _check_building: every shaft that spans two converted levels is linked).
_F4_NO_E2_ST_02 = ("SIST-F4 names it only in the callout 'E2-ST-02详见建施(A-E-40-16)' of the bound 4F xref's frozen "
                   "text layer (E2-RI-4F$0$A-TEXT), 6.7 m north of the plan; where F3's and F5's E2-ST-02 (a dog-leg "
                   "stair at the end of the link bridge 连廊) register on F4 there is no area and no stair entity (F5's "
                   "outline: 0 entities; F3's: 1 window line; within 3 m only walls, windows, columns): F4 draws no bridge there")
_F5_ONLY_IN_2F_XREF = ("SIST-F5 names it only in a bound 2F xref's frozen layers (E1-RI-2F$0$A-TEXT, ...$A-DIMS-100), whose "
                       "callouts sit where F4's do, 11.7 km from F5's plan (plan at -28..143 x -11..131 m); ")
SIST_NOT_ON_BOTH_PLANS = {
    ("3", "4"): {"E2-ST-02": _F4_NO_E2_ST_02},
    ("4", "5"): {"E2-ST-02": _F4_NO_E2_ST_02,
                 "E1-P2": _F5_ONLY_IN_2F_XREF + "F4's shaft (7.3 m²) registers under F5's room '电梯机房' (lift machine room, "
                          "18.6 m², 95 % of the shaft; one wall line crosses it): the lift ends at F4, its machine room above",
                 "E1-P3": _F5_ONLY_IN_2F_XREF + "F4's lifts E1-P3/P4 (6.1 and 7.5 m²) register under F5's room '电梯机房' "
                          "(15.7 m², 100 % / 99 % of them, no entity inside): the lifts end at F4, their machine room above",
                 "E1-ST-04": _F5_ONLY_IN_2F_XREF + "F4's open atrium stair E1-ST-04 (16.3 m²) registers on F5 inside a "
                             "796 m² roof (drainage slopes '1%' / '2%' x 9, roof projection line '屋面投影线'), no entity "
                             "within its outline: the stair ends at F4 under the roof"},
}
# Library, counted by hand from the sheets' texts: stair codes A3-ST-xx on 3F (sheet 04): 01-04, 06-10;
# 4F (05): 01-04, 06, 09-12; 5F (06): 01-04, 06, 11, 12. Lifts A3-T1..T3 are named only in the enlarged
# details, so they come from the lift symbols (crosses on the stair/lift layers) on every level.
LIBRARY_NAMED_ON_BOTH = {
    ("3", "4"): ["A3-ST-01", "A3-ST-02", "A3-ST-03", "A3-ST-04", "A3-ST-06", "A3-ST-09", "A3-ST-10"],
    ("4", "5"): ["A3-ST-01", "A3-ST-02", "A3-ST-03", "A3-ST-04", "A3-ST-06", "A3-ST-11", "A3-ST-12"],
}
# What the fusion links today, pinned (lower bounds). The shafts named on both sheets that are not linked
# are not converted as areas of their own on one of the two levels (a stair drawn only in a detail view, an
# outdoor stair outside the plan); see README "Fusion of the DWG sheets".
# (vertical links, of which hand-counted codes linked), per pair of consecutive levels.
# Since stairs and lifts swallowed by a hall or corridor are carved out as areas of their own
# (algorithms/anchors.py): 1-3 links 16 (was pinned 18 before the stair-code rule: two of those 18 were not
# shafts, F1's 1 791 m² hall 大厅 carrying E1-ST-04 linked over F3's atrium, and a duplicated F1 code
# E1-ST-10; E1-ST-04 is now a stair of its own on both levels and linked by its code), 3-4 14 (was 13),
# 4-5 11 (was 10); hand-counted codes linked 15 / 10 / 7 (were 15 / 8 / 7).
# After the merges of session 4 (curtain-wall doors, roofs and exterior ground counted out, cluttered borders,
# named passages): 4-5 has 10 links (hand-counted codes still 7), one unnamed pair fewer.
# Session 5 (named outdoor stairs, break-line stair cores, callouts beside the plan, anchors.py): 17 / 17 / 13
# links, hand-counted codes linked 15 / 13 / 10.
# F4's E1-P2, an empty lift box merged into its corridor, carved by its code (anchors.coded_lift_recesses): 3-4 18 / 14
# F3's E2-ST-02, a stair the link bridge's outline cuts through, carved whole (anchors._beyond_the_plan): 1-3 18 / 16,
# i.e. every hand-counted code of every pair that spans both plans (SIST_NOT_ON_BOTH_PLANS) is linked
SIST_LINKED = {("1", "3"): (18, 16), ("3", "4"): (18, 14), ("4", "5"): (13, 10)}
# library 3-4: 11 links since the carve (A3-ST-09 and -10, open stairs of the 3F atrium, are stairs of their own);
# 4-5: 11 links, the 7 hand-counted codes all linked since the merges of session 4 (A3-ST-11 and -12, flights
# of the 4F/5F atrium gallery, are stairs of their own on both levels; re-measured 2026-12-02 on branch route)
LIBRARY_LINKED = {("3", "4"): (11, 7), ("4", "5"): (11, 7)}
# (first level of the building, level) whose shaft residual RMS is >= 0.2 m, with why (known, not yet fixed).
# Library 5F (A3-ST-11 0.9 m, RMS 0.30 m, overall 0.21 m after session 4's merges) is fixed: A3-ST-11 is a
# free-standing flight of the atrium gallery whose both ends are passages (first and last tread) and which 4F
# and 5F cut at different treads (0.9 m apart along the run); the residual now reads an axis only where both
# outlines are walled at both ends (building.core_shift, openings from the floor's passages): 0.000 m, level 5
# RMS 0.002 m, overall 0.002 m (transforms unchanged).
KNOWN_RESIDUAL: dict = {}


@pytest.fixture(scope="session")
def dwg_buildings(shared_data, tmp_path_factory, floor_cache):
    sist_dir, lib_dir = shared_data / "dwg" / "sist-original", shared_data / "dwg" / "library"
    paths = [sist_dir / n for n in SIST] + [lib_dir / n for n in LIBRARY]
    missing = [str(p) for p in paths if not p.exists()]
    if missing:
        pytest.skip(f"shared DWG sheets missing: {missing}")
    out = tmp_path_factory.mktemp("dwg-floors")
    rec = RecordingProgress()
    t0 = time.perf_counter()
    pool = 1  # in this process, on the session's conversions (the pool: test_convert_floors_pool_...)
    with floor_cache.patched():
        conv = building.convert_floors([str(p) for p in paths], str(out), workers=pool, variant="fix-id",
                                       progress=rec)
    t_conv = time.perf_counter() - t0
    result = {"convert_seconds": t_conv, "infos": [m for k, m in rec.messages if k == "info"]}
    for key, k0, k1 in (("sist", 0, len(SIST)), ("library", len(SIST), len(paths))):
        c = conv[k0:k1]
        t1 = time.perf_counter()
        st = building.merge_floor_files([x[0] for x in c], str(out / f"{key}.osm"), building_name=key,
                                        variant="fix-id")
        areas, passages, root, rep = osmag.read_osmag(str(out / f"{key}.osm"))
        by_name = {a.name: a for a in areas}
        links = {}
        for lo, hi, a_lo, a_hi, kind, _ov in st["vertical"]:
            n_lo, n_hi = building.anchor_name(by_name[a_lo]), building.anchor_name(by_name[a_hi])
            code = building.shaft_code(n_lo) or building.shaft_code(n_hi) or n_lo or n_hi
            links.setdefault((lo, hi), []).append((code, kind))
        result[key] = dict(conv=c, st=st, areas=areas, passages=passages, report=rep, links=links, by_name=by_name,
                           merge_seconds=time.perf_counter() - t1, path=out / f"{key}.osm")
    print(f"DWG sheets: convert {t_conv:.0f} s (pool of {pool}), merge SIST {result['sist']['merge_seconds']:.1f} s, "
          f"library {result['library']['merge_seconds']:.1f} s")
    for key in ("sist", "library"):
        print(_figures(key, result[key]))
    return result


def _figures(key, b) -> str:
    """The README table: per level areas, passages, named, stairs, lifts; links per pair; residuals."""
    import re

    st, lines = b["st"], [f"{key}:"]
    ids = {a.id: a for a in b["areas"]}
    for lv in st["levels"]:
        ar = [a for a in b["areas"] if a.tags.get("level") == lv and a.type != "structure"]
        npass = sum(1 for p in b["passages"] if p.tags.get("osmAG:vertical") != "yes"
                    and ids.get(p.from_id) is not None and ids[p.from_id].tags.get("level") == lv)
        named = sum(1 for a in ar if a.name and not re.fullmatch(r"(L-?[\d.]+-[ASP]\d+|[\d\-]+( \(level .*\))?)", a.name))
        lines.append(f"  level {lv}: areas {len(ar)}, passages {npass}, named {named}, "
                     f"stairs {sum(a.type == 'stairs' for a in ar)}, lifts {sum(a.type == 'elevator' for a in ar)}, "
                     f"transform {st['transforms'][lv]}, median {st['median_residual'].get(lv)}, "
                     f"rms {st['rms'].get(lv)}")
        if lv in st["residuals"]:
            lines.append(f"    residuals {st['residuals'][lv]}")
    hand = SIST_NAMED_ON_BOTH if key == "sist" else LIBRARY_NAMED_ON_BOTH
    for pair, got in sorted(b["links"].items()):
        codes = {c for c, _ in got if c}
        lines.append(f"  links {pair}: {len(got)} ({sum(k == 'stairs' for _, k in got)} stairs, "
                     f"{sum(k == 'elevator' for _, k in got)} lifts) codes {sorted(codes)}; hand-counted "
                     f"{len(hand[pair])}, linked {len(codes & set(hand[pair]))}, not linked "
                     f"{sorted(set(hand[pair]) - codes)} (drawn on one plan only: "
                     f"{sorted((SIST_NOT_ON_BOTH_PLANS if key == 'sist' else {}).get(pair, {}))})")
    lines.append(f"  areas in {st['areas_in']} out {st['areas_out']}, passages {st['passages']}, "
                 f"vertical {len(st['vertical'])}, overall rms {st['overall_rms']}, warnings {st['warnings']}")
    return "\n".join(lines)


def _reliable_code(b, area):
    """The area's shaft code when it identifies the area (building.reliable_codes: the code is on this
    area only on its level and the area is shaft-sized), else ''."""
    lv = area.tags.get("level")
    code = building.shaft_code(building.anchor_name(area))
    if not code:
        return ""
    same = [a for a in b["areas"] if a.tags.get("level") == lv and building.anchor_kind(a)
            and building.shaft_code(building.anchor_name(a)) == code]
    g = area.polygon  # lon/lat degrees: to m²
    m2 = g.area * 111320.0 ** 2 * np.cos(np.radians(g.centroid.y))
    return code if len(same) == 1 and m2 <= building.SHAFT_MAX_AREA else ""


def _off_border_ends(paths) -> int:
    """Passage ends that a floor file itself places off their area's ring (farther than
    building.PASSAGE_END_TOL): the passage stage put them there, the fusion cannot share their node."""
    from shapely.geometry import Point

    n = 0
    for path in paths:
        areas, passages, root, _ = osmag.read_osmag(str(path))
        areas, passages = osmag.to_frame(areas, passages, osmag.frame_from_root(root))
        by_id = {a.id: a for a in areas}
        for p in passages:
            for aid in (p.from_id, p.to_id):
                if aid in by_id:
                    ext = by_id[aid].polygon.exterior
                    n += sum(ext.distance(Point(c)) > building.PASSAGE_END_TOL
                             for c in (p.line.coords[0], p.line.coords[-1]))
    return n


def _check_building(b, levels, pinned_links, named_on_both, not_on_both_plans=None):
    """Every check of a fused building. ``not_on_both_plans``: {pair: {code: evidence}}, the codes named on both
    sheets of a pair that one of the two plans does not draw."""
    st = b["st"]
    assert st["levels"] == levels
    # the fusion never moves a passage end off its area: a ring that touches itself (the 4F atrium gallery
    # 中庭回廊 (2), SIST-F1's hall 大厅) stays one ring (model.open_ring_pinches), so its passages keep their
    # nodes. Measured on the session-5 floor files: library 22 -> 1, SIST 14 -> 4 such warnings; the ones
    # left were doors that a carve or a name split cut and that followed one piece, 0.06-1.3 m off it
    # (library L3-P025, SIST L1-P036, L1-P077, L1-P174, L4-P052): laid on the borders they lie on since
    # (anchors.refit_passage_ends): 0 and 0, and the floor files put no passage end off its area
    off = [w for w in st["warnings"] if "is not on the border of area" in w]
    assert not off, off
    assert _off_border_ends([c[0] for c in b["conv"]]) == 0
    # nothing lost: every area and passage of every floor is in the building
    n_floor_areas = sum(c[2] for c in b["conv"])
    assert st["areas_in"] == st["areas_out"] >= n_floor_areas
    assert st["passages"] == sum(c[3] for c in b["conv"]) + len(st["vertical"])
    assert b["report"]["dangling_refs"] == [] and b["report"]["variant"] == "fix-id"
    names = [a.name for a in b["areas"]]
    assert len(names) == len(set(names))
    # registered by shafts, never by the outline fallback; the shafts land on each other: the residual per
    # shaft (the shift that lays its outline on its partner's) is below 0.2 m overall (RMS) and per level
    for lv, (dx, dy, deg, how) in st["transforms"].items():
        assert how == "reference" or how.startswith("anchors"), (lv, how)
        assert abs(deg) < 0.05, (lv, deg)
    over = {}
    for lv, med in st["median_residual"].items():
        assert med < 0.2, (lv, med, st["residuals"][lv])  # the registration itself
        if st["rms"][lv] >= 0.2:
            over[lv] = (round(st["rms"][lv], 3), sorted(st["residuals"][lv], key=lambda r: -r[-1])[:2])
    # measured on the walls both cuts of a core share (building.shaft_residual): SIST level 3 RMS 0.022 m,
    # E1-ST-01 (segmented differently on F3: deepened door openings), E2-ST-01 (cut 1.5 m longer on F3) and
    # E1-ST-03 (F3 0.6 m deeper, F1's top wall notched) all <= 0.01 m: their shared walls coincide
    over = {lv: v for lv, v in over.items() if (levels[0], lv) not in KNOWN_RESIDUAL}
    assert not over, over
    if not any(k[0] == levels[0] for k in KNOWN_RESIDUAL):
        assert st["overall_rms"] < 0.2, st["overall_rms"]
    for lv, res in st["residuals"].items():  # never larger than the centroid distance
        for (a, _, d), (_, _, c) in zip(res, st["centroid_residuals"][lv]):
            assert d <= c + 1e-3, (lv, a, d, c)
    short = {}
    # every pair of same-kind shafts that overlap on consecutive levels is linked (one to one: a shaft split in
    # two areas on one floor, flight and landing, links once), unless their codes identify them and differ
    for lo, hi in zip(levels, levels[1:]):
        a_lo = [a for a in b["areas"] if a.tags.get("level") == lo and a.type in ("stairs", "elevator")]
        a_hi = [a for a in b["areas"] if a.tags.get("level") == hi and a.type in ("stairs", "elevator")]
        code = {a.name: _reliable_code(b, a) for a in a_lo + a_hi}
        overlapping = {(a.name, x.name) for a in a_lo for x in a_hi if a.type == x.type and
                       a.polygon.intersection(x.polygon).area >= 0.3 * min(a.polygon.area, x.polygon.area)
                       and not (code[a.name] and code[x.name] and code[a.name] != code[x.name])}
        pairs = [(v[2], v[3]) for v in st["vertical"] if (v[0], v[1]) == (lo, hi)]
        lows, highs = {p[0] for p in pairs}, {p[1] for p in pairs}
        unlinked = {(x, y) for x, y in overlapping if x not in lows and y not in highs}
        assert overlapping and not unlinked, (lo, hi, unlinked)
        got = b["links"].get((lo, hi), [])
        n_links, n_hand = pinned_links[(lo, hi)]
        codes = {c for c, _ in got if c}
        n_codes = len(codes & set(named_on_both[(lo, hi)]))
        if len(got) < n_links or n_codes < n_hand:
            short[(lo, hi)] = f"{len(got)} links (pinned {n_links}), {n_codes} hand-counted codes (pinned {n_hand})"
        # every shaft that spans two converted levels is linked: the hand-counted codes but those one plan lacks
        spanning = set(named_on_both[(lo, hi)]) - set((not_on_both_plans or {}).get((lo, hi), {}))
        if spanning - codes:
            short[(lo, hi, "not linked")] = sorted(spanning - codes)
        # a link joins one shaft: never two areas whose codes identify them and differ
        mismatched = [(x, y, code[x], code[y]) for x, y in pairs if code[x] and code[y] and code[x] != code[y]]
        assert not mismatched, (lo, hi, mismatched)
    assert not short, short


def test_sist_dwg_sheets_fuse_into_one_building(dwg_buildings):
    b = dwg_buildings["sist"]
    _check_building(b, ["1", "3", "4", "5"], SIST_LINKED, SIST_NAMED_ON_BOTH, SIST_NOT_ON_BOTH_PLANS)
    assert all(code in SIST_NAMED_ON_BOTH[pair] for pair, codes in SIST_NOT_ON_BOTH_PLANS.items() for code in codes)
    # F1, F3 and F4/F5 sit kilometres apart in the originals too
    assert max(np.hypot(v[0], v[1]) for v in b["st"]["transforms"].values()) > 1000


def test_library_dwg_sheets_fuse_into_one_building_with_levels_from_the_sheets(dwg_buildings):
    b = dwg_buildings["library"]
    # the library file names carry no level: 3F, 4F, 5F come from the bound xrefs ('A3-SYMB-3F-100$0$...')
    assert sum("from the sheet's bound external references" in m for m in dwg_buildings["infos"]) == 3
    assert any("from the sheet's bound external references" in m for m in dwg_buildings["infos"])
    _check_building(b, ["3", "4", "5"], LIBRARY_LINKED, LIBRARY_NAMED_ON_BOTH)
    # the library's sheets share one frame: registration must not move them
    for lv, (dx, dy, deg, how) in b["st"]["transforms"].items():
        assert np.hypot(dx, dy) < 0.05, (lv, dx, dy)
    # the three lifts run through every level
    for pair in (("3", "4"), ("4", "5")):
        assert sorted(c for c, k in b["links"][pair] if k == "elevator") == ["A3-T1", "A3-T2", "A3-T3"]


def test_roof_sheet_is_recognised_from_its_xref(shared_data):
    """A-A3-10-08 is the roof plan (its only xref is 'A3-RI-RF(顶视)', a top view): level 'R', i.e. above
    the highest floor given. It holds no room, stair or lift, so the fusion leaves it out of the building."""
    p = shared_data / "dwg" / "library" / "A-A3-10-08.dwg"
    if not p.exists():
        pytest.skip(f"{p} is missing")
    assert building.level_from_sheet(str(p)) == "R"


def test_convert_floors_pool_gives_what_one_process_gives(tmp_path):
    """``building.convert_floors`` in a spawn pool of 2 (the benchmark's and users' path; the real sheets above
    run in one process on the session's conversions): the same files, byte for byte, and the same figures as
    one floor after the other, on two small synthetic floors."""
    from algorithms.sample_building import generate_building

    dxfs = generate_building(str(tmp_path / "src"), floors=2, seed=5)["dxf"]
    one = building.convert_floors(dxfs, str(tmp_path / "one"), workers=1, variant="fix-id")
    two = building.convert_floors(dxfs, str(tmp_path / "two"), workers=2, variant="fix-id")
    assert [os.path.basename(c[0]) for c in two] == ["sample-F1.osm", "sample-F2.osm"]
    assert [c[2:] for c in two] == [c[2:] for c in one] and all(c[2] > 5 for c in one)
    for a, b in zip(one, two):
        assert open(a[0], "rb").read() == open(b[0], "rb").read()
