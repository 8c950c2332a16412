"""Every shared plan through the whole pipeline (issue 8, item 7): no raw exception, and the
floor's area graph in one piece (item 6: the largest component holds >= 95 % of the area).

Prints one line of figures per plan (areas, passages, components, largest share, seconds) so the
run documents where each drawing stands. DWG sheets join when the DWG reader is merged
(``algorithms.cad_dwg``); until then that test is skipped with the reason.
"""
import time

import pytest

from algorithms.errors import InputError

pytestmark = pytest.mark.slow

TARGET = 0.95  # the quality target for the largest component

# Plans below the target today, with why; the connectivity test is an expected failure for them
# (not strict: when another part lands and they pass, the lead deletes the entry). Never a threshold.
KNOWN_BELOW = {
    # kindergarten-1 left this list at 96.8 % (K3, 2026-12-02): its last orphans are the bedroom group of the west
    # wing (bedroom, room, washroom: 75 m2, joined now) whose only way out is a door in the facade to a landing
    # with exterior steps (a group room entered from the garden), a 27 m2 box standing in the porch, and a 16 m2
    # strip of ground outside the west facade between two exterior steps (open to the outside only in stretches
    # between pillars, each under OPEN_FRONT)
    # cleaned SIST floors: doors were removed by hand and no room names survive (see shared data README);
    # diagnosed by picture against the DWG originals, which share their frame (tests/test_sist_connect.py, README
    # "Connected SIST floors"): what stays apart is not connected in these files
    "SIST-F1": "3 components (84 %): the north wing E2 (16 %) is a separate building at ground level, met outdoors "
               "(the DWG's passage 通道 between the wings); this file holds nothing between them (1 wall line, "
               "0 texts), and a 22 m2 detached room",
    "SIST-F4": "81.6 % (a 50 m2 outdoor notch between the wings counted out since session 6): the north wing (18 %) meets the main wing over the bridge 室外连廊, which is not "
               "in this cleaned file (0 entities between the wings; the DWG draws its railings and label); the "
               "curtain-wall door at its end is found but opens onto the outside",
    "SIST-F5": "the north wing (16 %; its bridge 连廊 is not in this cleaned file) and the roofs of the lecture block "
               "and the atrium (about 23 %; 5 texts in the file, no roof label: the DWG labels them 屋面, with drainage "
               "falls, and counts them out) meet the main wing through no opening (0 doorways); 57.3 % (a 121 m2 ground strip south of the curtain wall counted out since session 6, as on the DWG)",
}

# DWG sheets below the connectivity target with the current segmentation (measured 2026-12-01: A-A3-10-04
# 0.93, -05 0.90, -06 0.58, SIST-F1 0.80, F4 0.62, F5 0.70; with closed shafts and wall cavities counted out:
# A-A3-10-04 0.9498, -05 0.916, -06 0.585); each floor's other components are listed in the
# log and the 'component' field. Remove an entry when its sheet reaches the target.
KNOWN_BELOW_DWG = {
    "A-A3-10-08": "a roof plan (top view): one roof area, nothing to connect",
    # A-A3-10-04 (94.98 -> 100 %) and -05 (91.6 -> 99.4 %) reach it since exterior ground outside the facade counts
    # out (segmentation.outdoor_spaces): the terrace pieces between the planters south of the curtain wall (one
    # labelled 不上人平屋面, a flat roof no one walks on) hold only window codes, falls and a fire-window note, and
    # five of the six bays outside -05's west facade hold only level texts; the sixth (22 m2) stays an orphan.
    # SIST-F4 (98.1 % since curtain-wall doors), SIST-F5 (95.0 % since roofs below the floor count out, 97.8 % since the 129 m2 strip outside
    # its south curtain wall, holding only window codes, and a louvre screen 金属百叶 among the roofs count out as exterior) and SIST-F1
    # (99.7 % since the named passage 通道 between the two buildings closes at its two mouths) reach it, and so does
    # A-A3-10-06 (58.5 -> 100 %: the atrium gallery 中庭回廊 between its two wings, around the voids 下空, is named, and
    # each of its six tags carries the level +18.950 of this floor's wings: a walkway on this floor, not below it)
}


def _plans(shared, sub, pattern):
    folder = shared / sub
    return sorted(folder.rglob(pattern)) if folder.is_dir() else []


def _convert(path, tmp, floor_cache):
    t = time.perf_counter()
    out = floor_cache.convert_dxf(path, tmp / f"{path.stem}.osm")  # pipeline.convert_dxf, stages 1-5 shared
    return out, time.perf_counter() - t


@pytest.fixture(scope="module")
def dxf_results(shared_data, tmp_path_factory, floor_cache):
    tmp = tmp_path_factory.mktemp("plans")
    files = _plans(shared_data, "dxf", "*.dxf")
    assert len(files) >= 13
    results = {}
    for f in files:
        try:
            results[f.stem] = _convert(f, tmp, floor_cache)
        except InputError as exc:  # a clear message is acceptable input handling, but reported
            results[f.stem] = (exc, 0.0)
    print("\nplan                          areas passages comps largest    s")
    for name, (out, sec) in results.items():
        if isinstance(out, Exception):
            print(f"{name:28s} InputError: {out}")
            continue
        print(f"{name:28s} {out['areas']:6d} {out['passages']:8d} {out['components']:5d} "
              f"{out['largest_component_share']:7.1%} {sec:5.1f}")
    return results


def test_every_dxf_plan_converts_with_defaults(dxf_results):
    failed = {k: str(v) for k, (v, _) in dxf_results.items() if isinstance(v, Exception)}
    assert not failed, failed
    for name, (out, _) in dxf_results.items():
        assert out["areas"] > 0 and out["osm"]["areas"] > 0, name


def test_largest_component_holds_95_percent(dxf_results, request):
    below = {}
    for name, (out, _) in dxf_results.items():
        if isinstance(out, Exception):
            continue
        share = out["largest_component_share"]
        if share < TARGET and name not in KNOWN_BELOW:
            below[name] = round(share, 3)
    assert not below, f"largest component below {TARGET:.0%}: {below}"
    unexpected_ok = [n for n in KNOWN_BELOW if n in dxf_results
                     and not isinstance(dxf_results[n][0], Exception)
                     and dxf_results[n][0]["largest_component_share"] >= TARGET]
    if unexpected_ok:
        print(f"now at target, remove from KNOWN_BELOW: {unexpected_ok}")


def test_known_below_target_are_still_reported(dxf_results):
    """The plans under the target report their components in figures (nothing is silently orphaned)."""
    for name in KNOWN_BELOW:
        if name not in dxf_results or isinstance(dxf_results[name][0], Exception):
            continue
        out = dxf_results[name][0]
        assert out["components"] >= 1
        if out["largest_component_share"] < TARGET:
            assert out["components"] > 1


def test_every_dwg_sheet_converts(shared_data, tmp_path, floor_cache):
    try:
        import algorithms.cad_dwg  # noqa: F401
    except ImportError:
        pytest.skip("the DWG reader (algorithms.cad_dwg) is not merged yet")
    files = _plans(shared_data, "dwg", "*.dwg")
    if not files:
        pytest.skip("no DWG sheets in the shared data")
    below = {}
    for f in files:
        out, sec = _convert(f, tmp_path, floor_cache)
        print(f"{f.stem:28s} {out['areas']:6d} {out['passages']:8d} {out['components']:5d} "
              f"{out['largest_component_share']:7.1%} {sec:5.1f}")
        assert out["areas"] > 0, f.stem
        if out["largest_component_share"] < TARGET:
            assert out["components"] > 1, f.stem  # below target means orphans, and they are reported
            if f.stem not in KNOWN_BELOW_DWG:
                below[f.stem] = round(out["largest_component_share"], 3)
    assert not below, f"largest component below {TARGET:.0%}: {below}"
