"""Issue 14: furniture-cluttered rooms are one area; free-standing wall pieces still make doors;
enclosed pockets nobody can enter (inside furniture outlines, wall cavities) are no areas.

Small synthetic robot-map-like grids (0.05 m/px, walls 0.15 m, y down, metres)."""
import cv2
import numpy as np
import pytest

from algorithms import segmentation as seg
from algorithms.model import FREE, OCCUPIED, OccupancyGrid

RES = 0.05


def _px(v):
    return int(round(v / RES))


def _grid(w, h):
    return np.full((_px(h), _px(w)), OCCUPIED, np.uint8)


def _free(img, x0, y0, x1, y1):
    img[_px(y0):_px(y1), _px(x0):_px(x1)] = FREE


def _block(img, x0, y0, x1, y1, outline=False):
    if outline:
        cv2.rectangle(img, (_px(x0), _px(y0)), (_px(x1) - 1, _px(y1) - 1), OCCUPIED, 1)
    else:
        img[_px(y0):_px(y1), _px(x0):_px(x1)] = OCCUPIED


def _rotated_block(img, cx, cy, length, width, angle):
    pts = cv2.boxPoints(((_px(cx), _px(cy)), (_px(length), _px(width)), angle)).astype(np.int32)
    cv2.fillPoly(img, [pts], OCCUPIED)


def _segment(img, **kw):
    return seg.segment(OccupancyGrid(img, 0.0, img.shape[0] * RES, RES), **kw)


def _labels_in(ag, x0, y0, x1, y1):
    sub = ag.labels[_px(y0):_px(y1), _px(x0):_px(x1)]
    vals, counts = np.unique(sub[sub > 0], return_counts=True)
    return dict(zip(vals.tolist(), counts.tolist()))


def _office_with_tables(outline_table=False):
    """A 5 x 5 m office (x 1..6, y 1..6) behind a 0.9 m door on a 2 m corridor (y 6.15..8.15).
    A 3 m x 1 m table across the middle leaves 1 m gaps at both ends; a second, rotated desk in the
    lower half. Without the furniture rule the gaps look like doors (1 m openings into 2 m spaces)."""
    img = _grid(14, 9.2)
    _free(img, 1, 1, 6, 6)
    _free(img, 1, 6.15, 13, 8.15)
    _free(img, 3, 6, 3.9, 6.15)  # door
    _free(img, 6.15, 1, 13, 6)  # a second room east
    _free(img, 9, 6, 9.9, 6.15)
    _block(img, 2.0, 3.0, 5.0, 4.0, outline=outline_table)
    _rotated_block(img, 3.5, 5.0, 1.6, 0.8, 30)
    return img


@pytest.mark.parametrize("outline", [False, True])
def test_furnished_room_is_one_area(outline):
    img = _office_with_tables(outline)
    ag = _segment(img)
    office = _labels_in(ag, 1.1, 1.1, 5.9, 5.9)
    total = sum(office.values())
    main = max(office.values())
    assert main >= 0.97 * total, office  # one area, not one per side of the table
    corridor = _labels_in(ag, 1.5, 6.5, 12.5, 7.8)
    assert max(corridor, key=corridor.get) not in office  # still behind its door
    assert ag.stats["areas"] == 3  # office, east room, corridor: nothing inside the table outline
    if outline:
        # the inside of the outlined table is no area of its own
        inside = _labels_in(ag, 2.1, 3.1, 4.9, 3.9)
        assert set(inside) <= set(office)


def test_furniture_rule_off_splits_the_room(monkeypatch):
    """The failure the rule fixes, so the test above cannot pass by accident."""
    monkeypatch.setattr(seg, "FREE_STANDING", False)
    ag = _segment(_office_with_tables())
    office = _labels_in(ag, 1.1, 1.1, 5.9, 5.9)
    assert len([v for v in office.values() if v > 0.1 * sum(office.values())]) >= 2


def _two_rooms_with_stub(shape):
    """Two 5 x 4 m rooms side by side (x 1..6 and 6.15..11.15, y 1..5); the wall between them
    has a 1 m doorway at both ends, so its middle is a free-standing piece of wall."""
    img = _grid(12.2, 6)
    _free(img, 1, 1, 11.15, 5)
    if shape == "stub":  # a straight wall piece 0.15 m thick
        _block(img, 6.0, 2.0, 6.15, 4.0)
    else:  # an L of wall pieces (a corner of the wall between the rooms)
        _block(img, 6.0, 2.0, 6.15, 4.0)
        _block(img, 6.0, 3.85, 7.5, 4.0)
    return img


@pytest.mark.parametrize("shape", ["stub", "corner"])
def test_wall_pieces_still_make_doors(shape):
    ag = _segment(_two_rooms_with_stub(shape))
    west = _labels_in(ag, 1.2, 1.2, 5.5, 4.8)
    east = _labels_in(ag, 8.0, 1.2, 11.0, 3.5)
    assert max(west, key=west.get) != max(east, key=east.get)


def test_furniture_classification_figures():
    """Which blobs count as free-standing furniture (``_furniture``)."""
    img = np.full((400, 400), FREE, np.uint8)
    img[0, :] = img[-1, :] = img[:, 0] = img[:, -1] = OCCUPIED  # border: walls
    blobs = {
        "desk": (20, 20, 52, 36),  # 1.6 x 0.8 m solid
        "table": (100, 20, 170, 40),  # 3.5 x 1.0 m
        "column": (20, 100, 32, 112),  # 0.6 x 0.6 m: structure, frames openings
        "long": (100, 100, 190, 120),  # 4.5 m: a wall, not furniture
        "thin": (20, 200, 80, 203),  # 3 m x 0.15 m wall stub
        "shelf_room": (200, 200, 260, 260),  # 3 x 3 m = 9 m2: too big
    }
    for x0, y0, x1, y1 in blobs.values():
        img[y0:y1, x0:x1] = OCCUPIED
    cv2.rectangle(img, (300, 20), (340, 50), int(OCCUPIED), 1)  # 2 x 1.5 m outline (a table drawn as contour)
    cv2.line(img, (300, 300), (340, 300), int(OCCUPIED), 3)  # L of thin wall pieces
    cv2.line(img, (300, 300), (300, 340), int(OCCUPIED), 3)
    space = img == FREE
    n, lab, st, _ = cv2.connectedComponentsWithStats((~space).view(np.uint8), connectivity=8, ltype=cv2.CV_32S)
    furn = seg._furniture(lab, st, RES, np.ones(n, bool))
    got = {name: bool(furn[lab[(y0 + y1) // 2, (x0 + x1) // 2]]) for name, (x0, y0, x1, y1) in blobs.items()}
    assert got == {"desk": True, "table": True, "column": False, "long": False, "thin": False, "shelf_room": False}
    assert furn[lab[20, 320]]  # the outlined table
    assert not furn[lab[300, 320]]  # the L
    assert not furn[lab[0, 0]]  # the walls


def test_narrow_pocket_is_no_area():
    """A closed 0.5 m wide cavity between two walls is no room; a 1.2 m wide closet is one."""
    img = _grid(10, 6)
    _free(img, 1, 1, 9, 5)
    _block(img, 1, 2.5, 9, 3.5)  # thick wall band between two rooms ...
    _free(img, 2, 2.8, 7, 3.3)  # ... with a 0.5 m cavity inside it
    _free(img, 4, 2.5, 4.9, 2.8)  # (no door into the cavity)
    img[_px(2.5):_px(2.8), _px(4):_px(4.9)] = OCCUPIED
    ag = _segment(img)
    assert ag.stats.get("narrow_pockets_m2", 0) == pytest.approx(5 * 0.5, rel=0.05)
    assert not _labels_in(ag, 2.1, 2.85, 6.9, 3.25)
    img2 = img.copy()
    _free(img2, 2, 2.6, 7, 3.4)  # widen the cavity to 0.8 m: a closet, kept
    ag2 = _segment(img2)
    assert _labels_in(ag2, 2.1, 2.7, 6.9, 3.3)


def _conference_room(ends=True):
    """A 10 x 3.4 m conference room (x 1..11, y 1..4.4) behind a 0.9 m door on a 2 m corridor, with a
    5 x 1.2 m oval table scanned as a dotted outline (specks of 0.35 m, larger than SPECK_M2) and a
    0.5 m chair or table leg at each end -- so at both table ends the room narrows to two 1.2 m gaps
    beside it (intel_map's conference room)."""
    img = _grid(12, 8.7)
    _free(img, 1, 1, 11, 4.4)
    _free(img, 1, 4.55, 11, 6.55)
    _free(img, 2, 4.4, 2.9, 4.55)  # door
    cx, cy = 6.0, 2.7
    for t in np.linspace(0, 2 * np.pi, 40, endpoint=False):
        cv2.circle(img, (_px(cx + 2.5 * np.cos(t)), _px(cy + 0.6 * np.sin(t))), 3, OCCUPIED, -1)
    if ends:
        for ex in (cx - 2.5, cx + 2.5):
            cv2.ellipse(img, (_px(ex), _px(cy)), (_px(0.25), _px(0.25)), 0, 0, 360, OCCUPIED, -1)
    return img


def _room_pieces(ag):
    """Areas in the conference room outside the table (share of its pixels, largest first)."""
    sub = ag.labels[_px(1):_px(4.4), _px(1):_px(11)].copy()
    table = np.zeros(sub.shape, np.uint8)
    cv2.ellipse(table, (_px(5.0), _px(1.7)), (_px(2.8), _px(0.9)), 0, 0, 360, 1, -1)
    got = sub[(sub > 0) & (table == 0)]
    vals, counts = np.unique(got, return_counts=True)
    return sorted((c / len(got) for c in counts), reverse=True), set(vals.tolist())


def test_table_across_the_room_makes_no_door():
    """Furniture standing in an opening makes no door: the border the merge draws from wall to wall
    through the table ends is as long as the room is wide, so the pieces are one room; the room
    keeps its door onto the corridor."""
    ag = _segment(_conference_room())
    shares, ids = _room_pieces(ag)
    assert shares[0] >= 0.97, shares
    assert ag.stats["clutter_borders_joined"] >= 1
    corridor = _labels_in(ag, 1.5, 4.8, 10.5, 6.3)
    assert max(corridor, key=corridor.get) not in ids  # the door still separates room and corridor


def test_table_splits_the_room_without_the_rule(monkeypatch):
    monkeypatch.setattr(seg, "CLUTTER_BORDERS", False)
    shares, _ = _room_pieces(_segment(_conference_room()))
    assert shares[0] < 0.7 and shares[1] > 0.25, shares


def test_doors_are_no_clutter_borders():
    """Offices behind 0.9 m doors on a corridor, and two offices joined by a 1.2 m opening in the
    wall between them, keep their splits: their borders are much shorter than the rooms are wide."""
    img = _grid(13, 8.4)
    _free(img, 1, 1, 6, 5)
    _free(img, 6.15, 1, 12, 5)
    _free(img, 6, 2.5, 6.15, 3.7)  # 1.2 m opening between the offices
    _free(img, 1, 5.15, 12, 7.15)
    _free(img, 2, 5, 2.9, 5.15)
    _free(img, 9, 5, 9.9, 5.15)
    ag = _segment(img)
    west, east = _labels_in(ag, 1.5, 1.5, 5.5, 4.5), _labels_in(ag, 6.5, 1.5, 11.5, 4.5)
    corridor = _labels_in(ag, 1.5, 5.5, 11.5, 6.8)
    ids = [max(d, key=d.get) for d in (west, east, corridor)]
    assert len(set(ids)) == 3, ids
    assert ag.stats["clutter_borders_joined"] == 0


@pytest.mark.slow
@pytest.mark.parametrize("folder_name", ["input", "input_raw"])
def test_cluttered_borders_on_the_shared_robot_maps(shared_data, folder_name):
    """The five grid_gt maps, default widths, ``CLUTTER_BORDERS`` off / on (measured 2026-12-01):
    input/ intel_map 0.671 -> 0.687 (the conference room split in three around its dotted table is one
    area), the other four unchanged, mean 0.886 -> 0.889; input_raw/ freiburg_building52 0.949 ->
    0.974, intel_map 0.671 -> 0.687, lab_a 0.867 -> 0.887, the others unchanged, mean 0.872 -> 0.884.
    No map gets worse."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
    from evaluate_grids import _read_map, load_maps

    from algorithms.evaluate import evaluate, read_gt_image

    folder = shared_data / "grid_gt"
    scores = {}
    for m in load_maps(folder):
        path = folder / folder_name / f"{m['name']}.png"
        if not path.is_file():
            continue
        grid = _read_map(path, m["resolution"])
        gt = read_gt_image(str(folder / "gt" / f"{m['name']}.png"))
        for on in (False, True):
            seg.CLUTTER_BORDERS = on
            try:
                ag = seg.segment(grid)
            finally:
                seg.CLUTTER_BORDERS = True
            scores[(m["name"], on)] = evaluate(ag.labels, gt)["mcc"]
    names = sorted({n for n, _ in scores})
    assert len(names) == 5
    for n in names:
        assert scores[(n, True)] >= scores[(n, False)] - 0.002, (n, scores)
    assert scores[("intel_map", True)] >= scores[("intel_map", False)] + 0.01, scores
    mean_on = np.mean([scores[(n, True)] for n in names])
    assert mean_on >= np.mean([scores[(n, False)] for n in names]) + 0.002, scores
    assert mean_on >= (0.888 if folder_name == "input" else 0.88), scores


def _corridor_ring(cabinets):
    """Twelve 4 x 3.85 m offices (0.9 m doors) on both sides of a 24 x 10 m ring of 2 m corridors round a
    solid core; ``cabinets``: 0.6 x 0.5 m boxes (a printer, a bin) standing in the corridor in three places."""
    img = _grid(26, 20)
    _free(img, 1, 5, 25, 7)
    _free(img, 1, 13, 25, 15)
    _free(img, 1, 5, 3, 15)
    _free(img, 23, 5, 25, 15)
    for i in range(6):
        ox = 1 + i * 4
        _free(img, ox + 0.075, 1, ox + 3.925, 4.85)
        _free(img, ox + 1, 4.85, ox + 1.9, 5)
        _free(img, ox + 0.075, 15.15, ox + 3.925, 19)
        _free(img, ox + 1, 15, ox + 1.9, 15.15)
    if cabinets:
        for cx, cy in ((8, 6), (18, 14), (2, 10)):
            _block(img, cx - 0.3, cy - 0.25, cx + 0.3, cy + 0.25)
    return img


def test_corridor_ring_is_one_area():
    ag = _segment(_corridor_ring(False))
    ring = _labels_in(ag, 1, 5, 25, 15)
    assert len(ring) == 1 and len(ag.areas) == 13, ring


@pytest.mark.xfail(strict=False, reason="known defect on binary grids (issue 14, corridors cut into pieces): a "
                   "0.6 x 0.5 m box standing in a 2 m corridor leaves two 0.75 m gaps, door-like narrowings, so "
                   "the ring comes out in two. On recorded maps the corridor-loop rule joins it "
                   "(test_recorded_corridor_ring_with_cabinets_is_one_area); binary grids are left alone because "
                   "every CAD raster is one, and a door drawn across a CAD corridor is a door")
def test_corridor_ring_with_cabinets_is_one_area():
    ag = _segment(_corridor_ring(True))
    ring = _labels_in(ag, 1, 5, 25, 15)
    main = max(ring.values()) / sum(ring.values())
    assert main >= 0.97, ring


# ----------------------------------------------------------------- corridor loops (scanned maps)
def _recorded(img):
    """The plan as a robot records it: unknown beyond 0.15 m of the walls it saw."""
    from scipy import ndimage as ndi

    from algorithms.model import UNKNOWN

    img = img.copy()
    img[ndi.distance_transform_edt(img != FREE) > 3] = UNKNOWN
    return img


def _ring_share(ag):
    ring = _labels_in(ag, 1, 5, 25, 15)
    return max(ring.values()) / sum(ring.values()), ring


def test_recorded_corridor_ring_with_cabinets_is_one_area(monkeypatch):
    """The ring with three boxes standing in it, recorded: the piece between two boxes leaves the ring
    and comes back to it 7 m further on, while the way round the ring between those two places is
    40 m: the rest of the ring's loop, joined. The offices stay rooms (13 areas). With the rule off
    the ring is in two (8300 + 39340 px)."""
    img = _recorded(_corridor_ring(True))
    ag = _segment(img)
    share, ring = _ring_share(ag)
    assert share >= 0.97 and len(ag.areas) == 13, ring
    assert ag.stats["corridor_loops_joined"] == 1
    monkeypatch.setattr(seg, "CORRIDOR_LOOPS", False)
    ag = _segment(img)
    share, ring = _ring_share(ag)
    assert share < 0.9 and len(ag.areas) == 14, ring


def test_recorded_ring_in_even_pieces_is_one_area(monkeypatch):
    """Seven boxes cut the recorded ring into five pieces of similar size: no piece holds most of the
    ring, so no chain is a shortcut of a piece's own way round, but the cycle of pieces goes round the
    ring's 6 m core (thicker than a wall, ``LOOP_CORE_M``): one area. Without that test (a chain must
    be a shortcut) it stays in five pieces."""
    img = _corridor_ring(False)
    for cx, cy in ((6, 6), (12, 6), (18, 6), (18, 14), (10, 14)):
        _block(img, cx - 0.3, cy - 0.25, cx + 0.3, cy + 0.25)
    for cx, cy in ((24, 10), (2, 10)):
        _block(img, cx - 0.25, cy - 0.3, cx + 0.25, cy + 0.3)
    img = _recorded(img)
    ag = _segment(img)
    share, ring = _ring_share(ag)
    assert share >= 0.97 and len(ag.areas) == 13, ring
    monkeypatch.setattr(seg, "LOOP_CORE_M", 1e9)
    ag = _segment(img)
    share, ring = _ring_share(ag)
    assert len(ring) == 5 and share < 0.3, ring


def test_offices_opening_into_each_other_are_no_corridor_loop():
    """The six north offices of the ring opening into each other (0.9 m doors in their partitions) lead
    from the ring back to it, but the way along the ring between their doors is as short as the way
    through them, and each office is visited, not passed along (doors 1-4 m apart in a 3.85 m room):
    they stay six rooms. Also with the boxes in the ring (the ring is joined, the offices not)."""
    for cabinets in (False, True):
        img = _corridor_ring(cabinets)
        for i in range(1, 6):
            _free(img, 1 + i * 4 - 0.075, 2.5, 1 + i * 4 + 0.075, 3.4)
        ag = _segment(_recorded(img))
        share, ring = _ring_share(ag)
        assert share >= 0.97, (cabinets, ring)
        offices = [_labels_in(ag, 1.2 + i * 4, 1.2, 4.8 + i * 4, 4.6) for i in range(6)]
        assert all(len(o) == 1 for o in offices), offices
        assert len({next(iter(o)) for o in offices}) == 6 and next(iter(offices[0])) not in ring, offices


def _ring_with_core_rooms():
    """The clean ring (no boxes) with two 4 x 2.75 m rooms in its core, one above the other (x 5..9, y
    7.15..9.9 and 10.1..12.85), a 0.9 m door between them and one door from each onto the arm beside
    it: a way from the north arm to the south arm through the core, 3 x shorter than round the ring."""
    img = _corridor_ring(False)
    _free(img, 5, 7.15, 9, 9.9)
    _free(img, 5, 10.1, 9, 12.85)
    _free(img, 6.5, 9.9, 7.4, 10.1)
    _free(img, 6.5, 7, 7.4, 7.15)
    _free(img, 6.5, 12.85, 7.4, 13)
    return _recorded(img)


def test_rooms_across_the_core_are_no_corridor(monkeypatch):
    """Rooms visited on a way across the ring's core (lab_a's cubicle block) are no stretch of corridor:
    each room's doors are 2.75 m apart in a room 2.75 m wide (less than 1.5 x its width). Without that
    test (``LOOP_TRAVERSE`` = 0) the shortcut alone would join them to the ring."""
    ag = _segment(_ring_with_core_rooms())
    a = _labels_in(ag, 5.2, 7.3, 8.8, 9.7)
    b = _labels_in(ag, 5.2, 10.3, 8.8, 12.7)
    _, ring = _ring_share(ag)
    assert len(a) == 1 and len(b) == 1 and set(a) != set(b), (a, b)
    assert not (set(a) | set(b)) & set(k for k, v in ring.items() if v > 10000), (a, b, ring)
    monkeypatch.setattr(seg, "LOOP_TRAVERSE", 0.0)
    ag = _segment(_ring_with_core_rooms())
    assert ag.stats["corridor_loops_joined"] == 2


def test_corridor_loops_leave_binary_grids_alone():
    """Binary grids (every CAD raster) are not touched: the step does not even run."""
    ag = _segment(_corridor_ring(True))
    assert "corridor_loops_joined" not in ag.stats


def test_way_round_is_geodesic():
    """The way round inside a U (two 10 px arms 100 px long, 20 px apart, joined at the bottom) from one
    tip to the other is about 2 x 100 + 30 px, not the 30 px straight across; on a 4 px grid."""
    mask = np.zeros((120, 60), bool)
    mask[0:110, 0:10] = True
    mask[0:110, 30:40] = True
    mask[100:110, 0:40] = True
    around = seg._geodesic_from(mask, (2, 5), 4)(2, 35)
    assert 200 <= around <= 250, around
    pieces = seg._border_pieces(np.array([5, 5, 5, 5, 40, 40, 40]), np.array([1, 2, 3, 4, 7, 8, 9]), 2)
    assert len(pieces) == 2 and pieces[0] == pytest.approx((5.0, 2.5)), pieces


@pytest.mark.qgis_process
def test_recorded_corridor_ring_through_qgis_process(tmp_path):
    """cad2osmag:segment on the recorded ring with three boxes as a ROS map (unknown = 205): the ring is
    one corridor area, the twelve offices rooms, twelve door passages."""
    from .qgis_process import run_alg

    from algorithms.model import UNKNOWN

    data = _recorded(_corridor_ring(True))
    img = np.where(data == FREE, 254, np.where(data == OCCUPIED, 0, 205)).astype(np.uint8)
    assert (data == UNKNOWN).any()
    cv2.imwrite(str(tmp_path / "map.pgm"), img)
    (tmp_path / "map.yaml").write_text("image: map.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n"
                                       "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    out = {"AREAS": tmp_path / "a.gpkg", "PASSAGES": tmp_path / "p.gpkg", "LABELS": tmp_path / "l.tif"}
    _, res, _ = run_alg("segment", {"INPUT": tmp_path / "map.yaml", **{k: str(v) for k, v in out.items()}})
    assert res["AREA_COUNT"] == 13 and res["CORRIDOR_COUNT"] == 1 and res["ROOM_COUNT"] == 12, res
    assert res["PASSAGE_COUNT"] == 12, res


def test_recorded_straight_corridor_with_boxes_is_one_area():
    """A recorded 24 m straight corridor (2 m) with twelve offices and three boxes standing in it is one
    area before the loop step (its boxes leave no piece of its own there): no chain to judge, nothing joined."""
    img = _grid(26, 11)
    _free(img, 1, 5, 25, 7)
    for i in range(6):
        ox = 1 + i * 4
        _free(img, ox + 0.075, 1, ox + 3.925, 4.85)
        _free(img, ox + 1, 4.85, ox + 1.9, 5)
        _free(img, ox + 0.075, 7.15, ox + 3.925, 10)
        _free(img, ox + 1, 7, ox + 1.9, 7.15)
    for cx in (7, 13, 19):
        _block(img, cx - 0.3, 5.75, cx + 0.3, 6.25)
    ag = _segment(_recorded(img))
    corridor = _labels_in(ag, 1, 5, 25, 7)
    assert len(ag.areas) == 13 and max(corridor.values()) / sum(corridor.values()) >= 0.97, corridor
    assert ag.stats["corridor_loops_joined"] == 0


# ----------------------------------------------------------------- partition lines (scanned maps)
def _rooms_open_over_their_side(n):
    """Recorded: a 2 m corridor (y 6..8) whose north wall ends at a 0.9 m door into a room (x 1..5.9);
    east of it ``n`` rooms 3.5 x 3 m open onto the corridor over their whole side, their 0.15 m
    partitions stopping on the corridor's wall line (intel_map's rooms west of its south-west corridor)."""
    img = _grid(24, 12)
    _free(img, 1, 6, 23, 8)
    _free(img, 1, 1, 5.9, 5.85)
    _free(img, 5, 5.85, 5.9, 6)
    for i in range(n):
        _free(img, 6.05 + i * 3.65, 3, 9.55 + i * 3.65, 6)
    return _recorded(img)


@pytest.mark.parametrize("n", [2, 3])
def test_rooms_open_over_their_side_behind_partition_ends(n, monkeypatch):
    """The corridor's wall line continued from its door across the ends of the partitions that stop on
    it (two or more: the missing wall is proven) cuts each room off; with the rule off each room is
    part of the corridor (a bay: its opening is as wide as the room)."""
    ag = _segment(_rooms_open_over_their_side(n))
    corridor = set(_labels_in(ag, 1, 6.2, 23, 7.8))
    rooms = [_labels_in(ag, 6.2 + i * 3.65, 3.2, 9.4 + i * 3.65, 5.8) for i in range(n)]
    assert all(len(r) == 1 for r in rooms), rooms
    assert len({next(iter(r)) for r in rooms}) == n and not corridor & {next(iter(r)) for r in rooms}, (rooms, corridor)
    assert ag.stats["partition_line_rooms"] == n
    monkeypatch.setattr(seg, "PARTITION_LINES", False)
    ag = _segment(_rooms_open_over_their_side(n))
    corridor = set(_labels_in(ag, 1, 6.2, 23, 7.8))
    assert all(set(_labels_in(ag, 6.2 + i * 3.65, 3.2, 9.4 + i * 3.65, 5.8)) <= corridor for i in range(n))


def test_one_room_open_over_its_side_stays_a_bay():
    """One partition end proves nothing: a single room open over its side stays with the corridor."""
    ag = _segment(_rooms_open_over_their_side(1))
    assert ag.stats["partition_line_rooms"] == 0
    assert set(_labels_in(ag, 6.2, 3.2, 9.4, 5.8)) <= set(_labels_in(ag, 1, 6.2, 23, 7.8))
