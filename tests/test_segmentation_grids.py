"""Issue 14: rooms open to a corridor through an opening wider than a door but in a wall line
(``segmentation._split_at_wall_openings``) are areas of their own; corridors are not cut at their
junctions by the same rule.

Small synthetic robot-map-like grids (0.05 m/px, walls 0.15 m, y down, metres)."""
import math

import numpy as np
import pytest

from algorithms import segmentation as seg
from algorithms.model import FREE, OCCUPIED, OccupancyGrid

RES = 0.05


def _px(v):
    return int(round(v / RES))


def _free(img, x0, y0, x1, y1):
    img[_px(y0):_px(y1), _px(x0):_px(x1)] = FREE


def _labels_in(ag, x0, y0, x1, y1):
    sub = ag.labels[_px(y0):_px(y1), _px(x0):_px(x1)]
    vals, counts = np.unique(sub[sub > 0], return_counts=True)
    return dict(zip(vals.tolist(), counts.tolist()))


def _main(ag, *box):
    d = _labels_in(ag, *box)
    return max(d, key=d.get)


def _offices_on_corridor(opening=2.2, office_w=3.5, scale=1.0):
    """A corridor 2.4 m wide (y 5.15..7.55) with four offices 4 m deep on its north side (x from
    1, ``office_w`` wide, walls 0.15 m): offices 1 and 3 open onto it through ``opening`` m (wider than
    a door, narrower than the office), office 2 through a 0.9 m door, office 4 through ``opening``
    too. A side corridor 2.4 m wide leaves it southwards (a T junction). ``scale`` scales every length."""
    s = scale
    n = 4
    width = 1 + n * (office_w + 0.15) + 1.5
    img = np.full((_px((7.55 + 6.5) * s), _px(width * s)), OCCUPIED, np.uint8)
    _free(img, 1 * s, 5.15 * s, (width - 1) * s, 7.55 * s)  # corridor
    _free(img, 6.0 * s, 7.55 * s, 8.4 * s, 13.5 * s)  # side corridor (T junction)
    rooms = []
    for i in range(n):
        x0 = 1 + i * (office_w + 0.15)
        _free(img, x0 * s, 1 * s, (x0 + office_w) * s, 5 * s)
        w = 0.9 if i == 1 else opening
        xm = x0 + office_w / 2
        _free(img, (xm - w / 2) * s, 5 * s, (xm + w / 2) * s, 5.15 * s)
        rooms.append(tuple(v * s for v in (x0 + 0.2, 1.2, x0 + office_w - 0.2, 4.8)))
    corridor = tuple(v * s for v in (1.2, 5.5, width - 1.2, 7.2))
    side = tuple(v * s for v in (6.2, 9.0, 8.2, 13.3))
    return OccupancyGrid(img, 0.0, img.shape[0] * RES, RES), rooms, corridor, side


@pytest.mark.parametrize("scale", [1.0, 1.5])
def test_offices_behind_wide_openings_are_rooms(scale):
    grid, rooms, corridor, side = _offices_on_corridor(scale=scale)
    ag = seg.segment(grid)
    c = _main(ag, *corridor)
    ids = [_main(ag, *r) for r in rooms]
    assert c not in ids, (c, ids)
    assert len(set(ids)) == len(ids)  # every office its own area
    for r, i in zip(rooms, ids):
        d = _labels_in(ag, *r)
        assert d[i] >= 0.97 * sum(d.values())  # ... and whole
    assert _main(ag, *side) == c  # the side corridor is not cut off at the junction
    assert ag.stats["wall_line_doors"] >= 3


def test_rule_off_offices_are_swallowed(monkeypatch):
    """The failure the rule fixes, so the test above cannot pass by accident."""
    monkeypatch.setattr(seg, "WALL_CUTS", False)
    grid, rooms, corridor, _ = _offices_on_corridor()
    ag = seg.segment(grid)
    c = _main(ag, *corridor)
    assert sum(_main(ag, *r) == c for r in rooms) >= 2


def test_opening_as_wide_as_the_office_is_no_door():
    """An office open over (almost) its whole width onto the corridor is a bay of the corridor:
    the opening is not clearly narrower than the space behind it."""
    grid, rooms, corridor, _ = _offices_on_corridor(opening=3.3)
    ag = seg.segment(grid)
    c = _main(ag, *corridor)
    assert _main(ag, *rooms[0]) == c


def test_corridor_leaving_a_hall_is_not_cut_off():
    """A 1.6 m corridor leaves an 8 x 6 m hall through the hall's wall line; beside its mouth a 0.6 m
    door recess makes the corridor wider than the mouth on one side. The corridor runs along no
    wall at its mouth (space beyond one end only) and is corridor-shaped: no door, one area."""
    img = np.full((_px(16), _px(11)), OCCUPIED, np.uint8)
    _free(img, 1, 1, 9, 7)  # hall
    _free(img, 4, 7.15, 5.6, 15)  # corridor south, through the hall's south wall (y 7 .. 7.15)
    _free(img, 4, 7, 5.6, 7.15)
    _free(img, 3.4, 7.15, 4, 8.2)  # door recess beside the mouth
    ag = seg.segment(OccupancyGrid(img, 0.0, img.shape[0] * RES, RES))
    assert _main(ag, 2, 2, 8, 6) == _main(ag, 4.2, 9, 5.4, 14.8)


@pytest.mark.slow
def test_wall_line_rule_on_the_shared_robot_maps(shared_data):
    """The five grid_gt maps with the default widths: rule off, the session-4 rule (no jogs, lines
    from corners too) and the rule now (measured 2026-12-02, off -> session 4 -> now: Freiburg101 0.906
    -> 0.906 -> 0.906, freiburg_building52 0.970 (all three), intel_map 0.621 -> 0.687 -> 0.741, lab_a
    0.918 -> 0.928 -> 0.931, lab_d 0.955 (all three); mean 0.874 -> 0.889 -> 0.901). No map gets
    worse, the mean rises; on intel_map offices open to the corridor through 1.8-3.9 m openings become
    areas, and the bay east of the arc (its wall's face steps sideways before its end).
    Re-measured in session 9 with the wall faces found wherever the map lies (``FACE_FRAME``, ``FACE_PHASES``;
    the figures above were the image origin's phase): off -> session 4 -> now intel_map 0.637 -> 0.734 -> 0.730,
    lab_a 0.918 -> 0.915 -> 0.918, lab_d 0.955 -> 0.952 -> 0.952, the others unchanged; mean 0.877 -> 0.895 ->
    0.895. The wall-line rule still lifts the mean and intel_map; the jog and wall-end rules' own gain on
    intel_map (+0.054 at that phase) is not there at every position (their synthetic tests show what they do)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
    from evaluate_grids import _read_map, load_maps

    from algorithms.evaluate import evaluate, read_gt_image

    folder = shared_data / "grid_gt"
    scores = {}
    # the wall-line rule alone: the corridor loops and partition lines that run after it are off in all three
    later = dict(CORRIDOR_LOOPS=False, PARTITION_LINES=False)
    settings = {"off": dict(WALL_CUTS=False, **later), "s4": dict(FACE_JOG_PX=0, WALL_ENDS=False, **later),
                "on": later}
    for m in load_maps(folder):
        grid = _read_map(folder / "input" / f"{m['name']}.png", m["resolution"])
        gt = read_gt_image(str(folder / "gt" / f"{m['name']}.png"))
        for key, flags in settings.items():
            saved = {k: getattr(seg, k) for k in flags}
            for k, v in flags.items():
                setattr(seg, k, v)
            try:
                ag = seg.segment(grid)
            finally:
                for k, v in saved.items():
                    setattr(seg, k, v)
            scores[(m["name"], key)] = evaluate(ag.labels, gt)["mcc"]
    names = sorted({n for n, _ in scores})
    for n in names:  # no map clearly worse than without the wall-line rule (lab_d -0.003, lab_a -0.004 in session 4)
        assert scores[(n, "on")] >= scores[(n, "off")] - 0.005, (n, scores)
        assert scores[(n, "s4")] >= scores[(n, "off")] - 0.005, (n, scores)
    mean = {k: np.mean([scores[(n, k)] for n in names]) for k in settings}
    assert mean["s4"] >= mean["off"] + 0.01 and mean["on"] >= mean["off"] + 0.01, mean
    assert mean["on"] >= 0.89, (mean, scores)
    assert scores[("intel_map", "on")] >= scores[("intel_map", "off")] + 0.07, scores


# ----------------------------------------------------------------- recorded maps: unknown is no wall
def _office_with_leaf_shadow():
    """A recorded 5 x 4 m office (walls 0.15 m occupied, unknown beyond them) with the unknown wedge
    an open door leaf casts: 1.5 m long, 0.3 m thick, from the west wall at mid height (y 2.85-3.15)."""
    from algorithms.model import UNKNOWN

    img = np.full((_px(6), _px(7)), UNKNOWN, np.uint8)
    img[_px(0.85):_px(5.15), _px(0.85):_px(6.15)] = OCCUPIED
    _free(img, 1, 1, 6, 5)
    img[_px(2.85):_px(3.15), _px(1):_px(2.5)] = UNKNOWN
    return img


def test_unknown_wedge_edges_are_no_wall_lines():
    """The straight edge of an unknown wedge (where the laser did not see, behind a door leaf or a
    desk) continued across the room would be a 3.5 m 'opening': only observed obstacles are walls."""
    img = _office_with_leaf_shadow()
    space = img == FREE
    labels = space.astype(np.int32)

    def from_wedge(openings):
        # openings starting at the wedge's free end (x = 2.5 m), along its edges
        return [o for o in openings if abs(o[0][0] - _px(2.5)) <= 3 and _px(2.6) <= o[0][1] <= _px(3.4)]

    assert from_wedge(seg._wall_line_openings(space, labels, RES, 4.0))  # the failure: unknown taken for wall
    occupied = seg._observed_walls(img, space)
    assert occupied is not None and not occupied[_px(3.0), _px(2.0)] and occupied[_px(0.9), _px(3.0)]
    assert not from_wedge(seg._wall_line_openings(space, labels, RES, 4.0, occupied))


def test_observed_walls_only_on_recorded_maps():
    """Binary grids (every CAD floor, cleaned maps) and maps that draw their walls in grey (no
    occupied cell on the space's border) keep every non-space cell as a wall: the rule is off."""
    from algorithms.model import UNKNOWN

    grid, _, _, _ = _offices_on_corridor()
    space = grid.data == FREE
    assert seg._observed_walls(grid.data, space) is None
    grey = np.where(grid.data == OCCUPIED, UNKNOWN, grid.data).astype(np.uint8)
    assert seg._observed_walls(grey, space) is None
    assert seg._observed_walls(_office_with_leaf_shadow(), _office_with_leaf_shadow() == FREE) is not None


def test_recorded_map_offices_still_rooms():
    """The offices-on-a-corridor plan recorded (unknown beyond 0.15 m of wall): the walls seen are
    occupied, so the wall-line openings still make the offices rooms."""
    from scipy import ndimage as ndi

    from algorithms.model import UNKNOWN

    grid, rooms, corridor, side = _offices_on_corridor()
    data = grid.data.copy()
    far = ndi.distance_transform_edt(data != FREE) > 3
    data[far] = UNKNOWN
    ag = seg.segment(OccupancyGrid(data, grid.origin_x, grid.origin_y, RES))
    c = _main(ag, *corridor)
    ids = [_main(ag, *r) for r in rooms]
    assert c not in ids and len(set(ids)) == len(ids), (c, ids)
    assert _main(ag, *side) == c


@pytest.mark.slow
def test_observed_walls_on_the_recorded_maps(shared_data):
    """``input_raw`` of the five grid_gt maps, default widths, unknown-edge faces on / off (measured
    2026-12-01: lab_a 0.844 -> 0.867, the others unchanged: Freiburg101 0.915, freiburg_building52
    0.949, intel_map 0.671 (walls drawn grey: rule off), lab_d 0.959; mean 0.867 -> 0.872)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
    from evaluate_grids import _read_map, load_maps

    from algorithms.evaluate import evaluate, read_gt_image

    folder = shared_data / "grid_gt"
    scores = {}
    for m in load_maps(folder):
        path = folder / "input_raw" / f"{m['name']}.png"
        if not path.is_file():
            continue
        grid = _read_map(path, m["resolution"])
        gt = read_gt_image(str(folder / "gt" / f"{m['name']}.png"))
        for on in (False, True):
            seg.WALLS_OBSERVED = on
            try:
                ag = seg.segment(grid)
            finally:
                seg.WALLS_OBSERVED = True
            scores[(m["name"], on)] = evaluate(ag.labels, gt)["mcc"]
    names = sorted({n for n, _ in scores})
    for n in names:
        assert scores[(n, True)] >= scores[(n, False)] - 0.002, (n, scores)
    assert scores[("lab_a", True)] >= scores[("lab_a", False)] + 0.015, scores
    assert np.mean([scores[(n, True)] for n in names]) >= 0.87, scores


# ------------------------------------------------- wall faces: scanned jogs, corners are no wall ends
def _bay_beside_jogged_wall(jog_px=1):
    """A recorded map (unknown beyond 0.15 m of wall): a corridor 2.4 m wide (x 1..3.4, y 1..15) whose east wall (a 0.25 m partition, x 3.4..3.65,
    y 7..15, an office behind it) ends 3 m short of a wall stub (y 1..4): behind the 3 m opening a
    4.35 x 5 m bay (x 3.65..8, y 2..7). The wall's corridor face steps ``jog_px`` into the corridor
    (both faces) for its last 0.9 m, as a scanned wall does (intel_map's east-room wall), so its Hough segment
    stops 0.9 m short of the wall's end."""
    img = np.full((_px(16), _px(9)), OCCUPIED, np.uint8)
    _free(img, 1, 1, 3.4, 15)  # corridor
    _free(img, 3.4, 4, 3.65, 7)  # the opening in the wall line
    _free(img, 3.65, 2, 8, 7)  # bay
    _free(img, 3.65, 7.15, 8, 15)  # office behind the partition ...
    _free(img, 3.4, 11, 3.65, 11.9)  # ... through a 0.9 m door
    if jog_px:  # the wall's last 0.9 m, both faces, shifted into the corridor
        img[_px(7):_px(7.9), _px(3.4) - jog_px:_px(3.4)] = OCCUPIED
        img[_px(7):_px(7.9), _px(3.65) - jog_px:_px(3.65)] = FREE
    from scipy import ndimage as ndi

    from algorithms.model import UNKNOWN

    img[ndi.distance_transform_edt(img != FREE) > 3] = UNKNOWN  # recorded: unknown beyond the walls seen
    grid = OccupancyGrid(img, 0.0, img.shape[0] * RES, RES)
    return grid, (3.8, 2.2, 7.8, 6.8), (1.2, 8, 3.2, 14.8)


@pytest.mark.parametrize("jog", [0, 1])
def test_jogged_wall_face_still_makes_an_opening(jog, monkeypatch):
    """A face that steps 1 px sideways before its end is followed through the step
    (``_face_jog``, on scanned maps: grids with unknown cells): the bay behind the 3 m opening is a
    room, not part of the corridor."""
    monkeypatch.setattr(seg, "FACE_JOG_PX", jog)
    grid, bay, corridor = _bay_beside_jogged_wall()
    ag = seg.segment(grid)
    if jog:
        assert _main(ag, *bay) != _main(ag, *corridor)
        d = _labels_in(ag, *bay)
        assert max(d.values()) >= 0.97 * sum(d.values()), d
    else:  # the failure the rule fixes: the face is lost at its step, the bay joins the corridor ...
        assert _main(ag, *bay) != _main(ag, *corridor)  # (... now the partition's bay face makes the opening:
        monkeypatch.setattr(seg, "SLIVERS_APART", False)  # it touches a sliver, and was rejected unjudged)
        assert _main(seg.segment(grid), *bay) == _main(ag, *corridor)


def _hall_with_pier():
    """An 8.3 x 8 m hall (x 1..9.3, y 1..9) with a 1.6 m thick pier standing out 3.5 m from its
    north wall (x 6..7.6, y 1..4.5; 1.7 m from the east wall) and a 1.6 x 0.7 m cabinet against its
    south wall (x 5.2..6.8, y 8.3..9), as in lab_d: the pier's west face, continued south, meets the
    cabinet 3.8 m further, with the hall running on beyond both ends: a wall line, but from a corner
    (the pier's outline turns), not from a wall's end."""
    img = np.full((_px(10), _px(10.3)), OCCUPIED, np.uint8)
    _free(img, 1, 1, 9.3, 9)
    img[_px(1):_px(4.5), _px(6):_px(7.6)] = OCCUPIED
    img[_px(8.3):_px(9), _px(5.2):_px(6.8)] = OCCUPIED
    return OccupancyGrid(img, 0.0, img.shape[0] * RES, RES)


def _from_pier(ops):
    """Openings continuing the pier's west or east face (x 6 or 7.6 m) south of it."""
    return [o for o in ops if min(abs(o[0][0] - _px(6)), abs(o[0][0] - _px(7.6))) <= 2 and o[0][1] >= _px(4.4)]


def test_pier_face_continued_is_no_opening(monkeypatch):
    """The line of a thick pier's face continued across the hall is no wall-line opening
    (``_wall_ends``: across the line the pier is 1.6 m thick at the face's end, a corner); with the
    rule off it is a 3.8 m candidate. The hall is one area."""
    grid = _hall_with_pier()
    space = grid.data == FREE
    assert not _from_pier(seg._wall_line_openings(space, space.astype(np.int32), RES, 4.0))
    ag = seg.segment(grid)
    hall = _labels_in(ag, 1.2, 1.2, 9.1, 8.1)
    assert max(hall.values()) >= 0.97 * sum(hall.values()), hall
    monkeypatch.setattr(seg, "WALL_ENDS", False)
    ops = _from_pier(seg._wall_line_openings(space, space.astype(np.int32), RES, 4.0))
    assert ops and max(o[1] for o in ops) * RES >= 3.5, ops


def test_wall_ends_keep_thin_partitions():
    """The ends of 0.15 m partitions (office fronts, door jambs) are wall ends: every opening in the
    offices' fronts is still a candidate."""
    grid, _, _, _ = _offices_on_corridor()
    space = grid.data == FREE
    on = seg._wall_line_openings(space, space.astype(np.int32), RES, 4.0)
    seg.WALL_ENDS = False
    try:
        off = seg._wall_line_openings(space, space.astype(np.int32), RES, 4.0)
    finally:
        seg.WALL_ENDS = True
    front = {o[0] for o in off if max(o[0][1], o[0][3]) <= _px(5.15)}  # the office fronts' openings
    assert len(front) >= 4 and front <= {o[0] for o in on}
    # the corridor's walls turning into the side corridor's at the T junction are corners: dropped
    assert len(on) < len(off)


def test_cad_rasters_do_not_jog(monkeypatch):
    """A binary grid (every CAD raster) draws exact lines: the face is not followed through steps
    (the same plan without unknown cells keeps the bay in the corridor, as before the rule; with
    ``SLIVERS_APART`` the partition's bay face makes the opening, see the jogged-face test)."""
    monkeypatch.setattr(seg, "SLIVERS_APART", False)
    grid, bay, corridor = _bay_beside_jogged_wall()
    from algorithms.model import UNKNOWN

    data = np.where(grid.data == UNKNOWN, OCCUPIED, grid.data).astype(np.uint8)
    ag = seg.segment(OccupancyGrid(data, grid.origin_x, grid.origin_y, RES))
    assert _main(ag, *bay) == _main(ag, *corridor)


# ------------------------------------------------- wall lines that end on a free-standing block
def _bay_behind_block():
    """The recorded corridor and bay of ``_bay_beside_jogged_wall`` (no jog), its wall stub 1 m
    shorter (y 1..3: a 4 m opening) and a 0.45 x 0.5 m block (a cabinet, x 3.3..3.75, y 3.5..4)
    standing free in the opening: the stub's line meets the block after 0.5 m, and beyond the block
    3 m of free space lead to the partition's end (y 7). The partition ends at a corner (the bay's
    south wall runs on from it), so only the stub's line is a candidate, and the bay meets the
    corridor round the block."""
    grid, bay, corridor = _bay_beside_jogged_wall(jog_px=0)
    img = grid.data.copy()
    img[_px(3):_px(4), _px(3.4):_px(3.65)] = FREE
    img[_px(3.5):_px(4), _px(3.3):_px(3.75)] = OCCUPIED
    return OccupancyGrid(img, grid.origin_x, grid.origin_y, RES), bay, corridor


@pytest.mark.parametrize("on", [False, True])
def test_wall_line_continues_beyond_a_free_standing_block(on, monkeypatch):
    """``_block_extensions``: the opening ends on a block, so the cut alone does not close the bay
    (it meets the corridor again round the block); continued through the block to the stub beyond,
    cut + block + cut span wall to wall and the bay is a room. With the rule off the bay stays part
    of the corridor."""
    monkeypatch.setattr(seg, "BLOCK_CUTS", on)
    grid, bay, corridor = _bay_behind_block()
    ag = seg.segment(grid)
    if on:
        assert ag.stats["block_cuts"] >= 1
        assert _main(ag, *bay) != _main(ag, *corridor)
        d = _labels_in(ag, *bay)
        assert max(d.values()) >= 0.97 * sum(d.values()), d
    else:
        assert _main(ag, *bay) == _main(ag, *corridor)


def test_block_extension_only_for_free_standing_blocks(monkeypatch):
    """An opening that ends on wall mass (the stub of the plan without the block) gets no
    continuation; one that ends on the block gets one, from the block's far side to the partition."""
    monkeypatch.setattr(seg, "BLOCK_CUTS", True)
    grid, _, _ = _bay_behind_block()
    space = grid.data == FREE
    wall = ~space
    ops = [((_px(3.5), _px(3), _px(3.5), _px(3.5) - 1), 10.0, (1.0, 0.0))]
    ext = seg._block_extensions(space, wall, ops, RES, 4.0)
    assert 0 in ext
    x0, y0, x1, y1 = ext[0]
    assert x0 == x1 == _px(3.5) and y0 == _px(4) and y1 == _px(7) - 1  # the 3 m beyond the block
    plain, _, _ = _bay_beside_jogged_wall(jog_px=0)
    space = plain.data == FREE
    assert seg._block_extensions(space, ~space, [((_px(3.5), _px(7) - 1, _px(3.5), _px(4)), 60.0, (-1.0, 0.0))],
                                 RES, 4.0) == {}


@pytest.mark.slow
@pytest.mark.parametrize("folder_name", ["input", "input_raw"])
def test_corridor_loops_on_the_shared_robot_maps(shared_data, folder_name):
    """Issue 14's target on the five grid_gt maps, default widths, ``CORRIDOR_LOOPS`` and
    ``PARTITION_LINES`` off / on (measured 2026-12-02): intel_map 0.741 -> 0.781 (loops: its corridor
    ring's west arm, three pieces between the north arm and the south-west corner, joins the ring; the
    ring's recall 0.71 -> 0.93) -> 0.831 (partition lines: the two rooms west of the south-west corridor,
    open over their whole side, are cut off along the corridor's west wall continued across their
    partitions' ends) in both folders; the other maps unchanged (input/: binary, the steps do not run;
    input_raw/: nothing passes). Every map >= 0.75 and the mean >= 0.90 with the rules. Re-measured in session 9
    with the wall faces found wherever the map lies (``FACE_FRAME``): intel_map 0.730 -> 0.821 in both folders;
    means 0.913 (input/), 0.911 (input_raw/)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
    from evaluate_grids import _read_map, load_maps

    from algorithms.evaluate import evaluate, read_gt_image
    from algorithms.model import UNKNOWN

    folder = shared_data / "grid_gt"
    on, off = {}, {}
    for m in load_maps(folder):
        path = folder / folder_name / f"{m['name']}.png"
        if not path.is_file():
            path = folder / "input" / f"{m['name']}.png"
        grid = _read_map(path, m["resolution"])
        gt = read_gt_image(str(folder / "gt" / f"{m['name']}.png"))
        ag = seg.segment(grid)
        on[m["name"]] = evaluate(ag.labels, gt)["mcc"]
        if not (grid.data == UNKNOWN).any():
            assert "corridor_loops_joined" not in ag.stats and "partition_line_rooms" not in ag.stats
            off[m["name"]] = on[m["name"]]
            continue
        seg.CORRIDOR_LOOPS = seg.PARTITION_LINES = False
        try:
            off[m["name"]] = evaluate(seg.segment(grid).labels, gt)["mcc"]
        finally:
            seg.CORRIDOR_LOOPS = seg.PARTITION_LINES = True
    assert len(on) == 5
    for n in on:
        assert on[n] >= off[n] - 0.002, (n, on, off)
    assert on["intel_map"] >= off["intel_map"] + 0.07, (on, off)
    assert min(on.values()) >= 0.75 and np.mean(list(on.values())) >= 0.90, on


def _turned_offices_areas(angle, scale=1.0):
    """The area of ``_offices_on_corridor`` turned by ``angle`` (raster and truth turned alike) that holds most of
    each office and of the corridor: five different areas when every office is its own."""
    from algorithms.raster_io import rotate_raster

    grid, rooms, corridor, side = _offices_on_corridor(scale=scale)
    ids = np.zeros(grid.data.shape, np.uint8)
    for k, (x0, y0, x1, y1) in enumerate(rooms + [corridor], start=1):
        ids[_px(y0):_px(y1), _px(x0):_px(x1)] = k
    data, _ = rotate_raster(grid.data, angle, fill=OCCUPIED)
    turned, _ = rotate_raster(ids, angle, fill=0)
    ag = seg.segment(OccupancyGrid(data, 0.0, data.shape[0] * RES, RES))
    best = []
    for k in range(1, len(rooms) + 2):
        vals, counts = np.unique(ag.labels[turned == k], return_counts=True)
        best.append(int(vals[vals > 0][np.argmax(counts[vals > 0])]))
    return best


TURNED_OFFICES_MERGE = {(1.0, 15.0), (1.0, 20.0)}  # (scale, angle) where an office still joins the corridor


@pytest.mark.parametrize("scale,angle", [(s, float(a)) for s in (1.0, 1.5) for a in range(0, 50, 5)])
def test_offices_behind_wide_openings_on_a_turned_plan(scale, angle):
    """The offices of ``test_offices_behind_wide_openings_are_rooms``, the raster turned by ``angle``: every
    office stays its own area. Session 8: the Hough lines of a face at an angle (1 deg apart) crossed in the
    opening and cut slivers (``SAME_OPENING_PX``), and the line continued from one jamb passed the wall beyond
    by a pixel (``GAP_SIDE_PX``): 14/20 angles. Session 9: the faces found in a 2 x 2 block of frames
    (``FACE_PHASES``) and an opening beside slivers judged between the two spaces (``SLIVERS_APART``): 18/20
    (15 and 20 deg at 1x still merge; 20 deg passed before at the image origin's phase, 40 and 45 now pass)."""
    if (scale, angle) in TURNED_OFFICES_MERGE:
        pytest.xfail("an office still joins the corridor at this angle")
    best = _turned_offices_areas(angle, scale)
    assert len(set(best)) == len(best), best  # four offices and the corridor: five areas


def test_rules_off_turned_offices_merge(monkeypatch):
    """The failures the rules fix, so the turned-plan test cannot pass by accident: without ``SAME_OPENING_PX`` and
    ``GAP_SIDE_PX`` an office joins the corridor at 10 deg; without ``SLIVERS_APART`` at 40 deg and at 30 deg (1.5 x:
    lines of one opening a pixel apart, each touching more than two pieces, were rejected unjudged), with one Hough
    frame (``FACE_PHASES`` = 1) at 30 deg and at 5 deg (1.5 x)."""
    cases = [(dict(SAME_OPENING_PX=0.0, GAP_SIDE_PX=0), 1.0, 10.0), (dict(SLIVERS_APART=False), 1.0, 40.0),
             (dict(SLIVERS_APART=False), 1.5, 30.0), (dict(FACE_PHASES=1), 1.0, 30.0), (dict(FACE_PHASES=1), 1.5, 5.0)]
    for flags, scale, angle in cases:
        with monkeypatch.context() as m:
            for k, v in flags.items():
                m.setattr(seg, k, v)
            best = _turned_offices_areas(angle, scale)
        assert len(set(best)) < len(best), (flags, scale, angle, best)


def test_same_opening_from_both_jambs():
    """Two candidate openings that cross in the gap (the lines of one face at an angle, from its two jambs) are
    one; the openings along a wall's two faces (parallel, 2 px apart) stay two; the longer run is kept."""
    out, seen = [], set()
    xs = np.array([[0, 10, 20, 30, 40], [40, 30, 20, 10, 0], [0, 10, 20, 30, 40]])
    ys = np.array([[0, 0, 1, 1, 2], [3, 2, 2, 1, 0], [4, 4, 5, 5, 6]])
    seg._add_runs(out, seen, xs, ys, np.arange(3), np.zeros(3, np.int64), np.array([5, 5, 5]),
                  np.zeros(3), np.ones(3), 1.0, 100.0)
    # crossing: one, the longer run (41.1 px from (40, 3), not 41.05 from (0, 0)) kept; 4 px apart: two
    assert [o[0] for o in out] == [(40, 3, 0, 0), (0, 4, 40, 6)]
    assert seg._same_opening((0, 0, 40, 0), [((0, 2, 40, 2), 41.0, (0.0, 1.0))]) == -1  # parallel faces


def test_gap_ends_at_the_wall_a_pixel_beside_the_line():
    """A wall line continued across an opening ends at the wall beyond it when that wall lies a pixel beside the
    line (a face at an angle steps by a pixel): the run is the opening, not the way to the next wall."""
    space = np.ones((40, 120), bool)
    space[10:13, :30] = False  # the wall up to the opening (face on row 12, the space below it)
    space[13:16, 74:] = False  # the wall beyond the 2.2 m opening, its face one pixel lower
    space[:, 118:] = False
    ops = seg._wall_line_openings(space, None, RES, 2.5)
    def across(o):
        return o[0][1] in (12, 13) and sorted((o[0][0], o[0][2])) == [30, 73]

    # 30..73 (seen from either wall: one opening), not on to the map's edge (88 px: longer than a cut)
    assert [round(o[1]) for o in ops if across(o)] == [44], ops
    ops_off = []
    try:
        seg.GAP_SIDE_PX = 0
        ops_off = seg._wall_line_openings(space, None, RES, 2.5)
    finally:
        seg.GAP_SIDE_PX = 1
    assert not [o for o in ops_off if across(o)], ops_off


# ------------------------------------------------- openings wherever the map lies (session 9)
def _same_partition(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two label rasters cut the free space into the same areas (ids may differ)."""
    m = (a > 0) | (b > 0)
    pairs = np.unique(np.stack([a[m], b[m]]), axis=1)
    return len(np.unique(pairs[0])) == pairs.shape[1] == len(np.unique(pairs[1]))


def _moved(data: np.ndarray, dx: int, dy: int, fill=OCCUPIED) -> np.ndarray:
    """``data`` moved ``dx`` px right and ``dy`` px down, padded with ``fill``."""
    out = np.full((data.shape[0] + dy, data.shape[1] + dx), fill, data.dtype)
    out[dy:, dx:] = data
    return out


def _turned_offices_grid(angle, scale=1.0):
    from algorithms.raster_io import rotate_raster

    return rotate_raster(_offices_on_corridor(scale=scale)[0].data, angle, fill=OCCUPIED)[0]


SHIFTS = ((1, 0), (0, 1), (2, 2), (3, 1))


@pytest.mark.parametrize("scale,angle", [(1.0, 10.0), (1.0, 20.0), (1.5, 30.0)])
def test_turned_offices_segment_alike_wherever_the_map_lies(scale, angle):
    """The turned office row moved by 1-3 px in x and y (padded): the same areas, cut along the same lines
    (``FACE_FRAME``: the wall faces' Hough runs in the face pixels' box, not from the image's origin)."""
    data = _turned_offices_grid(angle, scale)
    ref = seg.segment(OccupancyGrid(data, 0.0, data.shape[0] * RES, RES)).labels
    for dx, dy in SHIFTS:
        d2 = _moved(data, dx, dy)
        got = seg.segment(OccupancyGrid(d2, 0.0, d2.shape[0] * RES, RES)).labels[dy:, dx:]
        assert _same_partition(ref, got), (scale, angle, dx, dy)


def test_wall_faces_move_with_the_map(monkeypatch):
    """The faces of the space moved by (dx, dy) are its faces moved by (dx, dy), exactly; with ``FACE_FRAME`` off
    (the Hough from the image's origin) they are not: the failure the rule fixes."""
    space = _turned_offices_grid(20.0) == FREE
    ref = seg._wall_faces(space, RES)
    assert len(ref) > 10
    for dx, dy in SHIFTS:
        got = seg._wall_faces(_moved(space, dx, dy, False), RES)
        assert got.shape == ref.shape and np.allclose(got - np.array([dx, dy, dx, dy]), ref, atol=1e-9), (dx, dy)
    monkeypatch.setattr(seg, "FACE_FRAME", False)
    ref = seg._wall_faces(space, RES)
    moved = [seg._wall_faces(_moved(space, dx, dy, False), RES) for dx, dy in SHIFTS]
    assert any(len(g) != len(ref) or not np.allclose(g - np.array([dx, dy, dx, dy]), ref)
               for g, (dx, dy) in zip(moved, SHIFTS))


@pytest.mark.parametrize("deg", [7.3, 17.5, 33.0])
def test_wall_face_at_an_angle_is_fitted_to_its_pixels(deg, monkeypatch):
    """A straight face at ``deg`` (its pixels a staircase): with ``FACE_FIT`` (off by default: on recorded maps it
    follows the scan's ragged pixels) the face's line runs at ``deg`` within 0.15 deg; the Hough's own segments
    are 0.3-0.9 deg off at 17.5 deg (1-deg bins, rounded ends)."""
    monkeypatch.setattr(seg, "FACE_FIT", True)
    rows, cols = 200, 300
    yy, xx = np.mgrid[0:rows, 0:cols]
    t = math.tan(math.radians(deg))
    space = (yy > 40 + t * xx) & (yy < 190) & (xx > 5) & (xx < cols - 5)

    def angles():
        f = seg._wall_faces(space, RES)
        d = f[:, 2:] - f[:, :2]
        long = np.hypot(d[:, 0], d[:, 1]) > 100
        a = np.degrees(np.arctan2(d[long, 1], d[long, 0])) % 180
        return a[np.abs(a - deg) < 5]

    fitted = angles()
    assert len(fitted) and np.abs(fitted - deg).max() <= 0.15, fitted
    monkeypatch.setattr(seg, "FACE_FIT", False)
    if deg == 17.5:
        assert np.abs(angles() - deg).min() >= 0.3


def _room_behind_opening(strip_m=0.75):
    """Labels as the merge leaves them when a room's front has no space of its own: a corridor (y 0..2 m,
    x 0..6 m), a wall (0.15 m) with a 1.2 m opening, a room 3 x 2.5 m behind it; the corridor's label 1
    reaches through the opening over the room's first ``strip_m``, the rest of the room is label 2."""
    space = np.zeros((_px(5.0), _px(6.0)), bool)
    space[_px(0.2):_px(2.0), _px(0.2):_px(5.8)] = True  # corridor
    space[_px(2.0):_px(2.15), _px(2.0):_px(3.2)] = True  # the opening in its wall line
    space[_px(2.15):_px(4.65), _px(1.5):_px(4.5)] = True  # the room
    labels = np.where(space, 1, 0).astype(np.int32)
    labels[_px(2.15 + strip_m):_px(4.65), _px(1.5):_px(4.5)] = 2
    import cv2

    dist = cv2.distanceTransform(space.view(np.uint8), cv2.DIST_L2, 5).astype(np.float32)
    return space, labels, dist


@pytest.mark.parametrize("rejoin", [True, False])
def test_a_piece_a_wall_line_door_cuts_off_joins_the_room_it_opens_onto(monkeypatch, rejoin):
    """The merge gave a room's front strip (no clearance peak of its own: it rises less than MIN_RISE_M
    above its border with the room) to the corridor, through the opening. The wall line's cut takes it off
    the corridor; it is the room's (its door is the room's door), not an area of its own. SIST-F4.dwg: the
    strip between a lift's door and the car symbol standing in the shaft, on 2 x 2 cells, was an area that
    took the lift's name and left the lift reachable over 0.26 m only."""
    monkeypatch.setattr(seg, "PIECES_REJOIN", rejoin)
    space, labels, dist = _room_behind_opening()
    peaks, grown = {}, {}
    out, cuts = seg._split_at_wall_openings(labels.copy(), space, RES, 2.0, dist, peaks, grown)
    corridor = out[_px(0.5):_px(1.8), _px(0.5):_px(5.5)]
    strip = out[_px(2.3):_px(2.8), _px(1.7):_px(4.3)]
    back = out[_px(3.2):_px(4.5), _px(1.7):_px(4.3)]
    assert set(np.unique(corridor).tolist()) == {1} and set(np.unique(back).tolist()) == {2}
    if rejoin:
        assert set(np.unique(strip).tolist()) == {2} and cuts == 0  # the room is whole, through its door
        assert set(np.unique(out).tolist()) == {0, 1, 2}
        assert grown.get(2, 0.0) > 0 and not any(k > 2 for k in peaks)
    else:
        assert len(np.unique(strip)) == 1 and int(strip[0, 0]) not in (1, 2) and cuts == 1  # the defect


def test_a_piece_with_space_of_its_own_stays_an_area():
    """A vestibule deeper than its border with the room behind is wide (its clearance peak rises
    MIN_RISE_M above that border): the cut keeps it an area, as the merge keeps such splits."""
    space, labels, dist = _room_behind_opening(strip_m=1.5)
    # a wall with a 0.5 m gap between the vestibule and the room: the vestibule's peak rises above it
    wall = np.zeros_like(space)
    wall[_px(3.65):_px(3.8), _px(1.5):_px(4.5)] = True
    wall[_px(3.65):_px(3.8), _px(2.75):_px(3.25)] = False
    space &= ~wall
    labels[wall] = 0
    import cv2

    dist = cv2.distanceTransform(space.view(np.uint8), cv2.DIST_L2, 5).astype(np.float32)
    out, cuts = seg._split_at_wall_openings(labels.copy(), space, RES, 2.0, dist, {}, {})
    vest = out[_px(2.4):_px(3.4), _px(1.7):_px(4.3)]
    assert cuts == 1 and len(np.unique(vest)) == 1 and int(vest[0, 0]) not in (1, 2)
