"""Issue 8 items 5 and 6: interior evidence where facades are open, door hints, connected floors.

Small synthetic plans only (quick); the real drawings are in test_real_plans.py.
"""
import numpy as np
import pytest
from shapely.geometry import LineString, box

from algorithms import rasterize as ras
from algorithms import segmentation as seg
from algorithms.model import FREE, OCCUPIED, Area, CadGeometry, CadText, DoorHint, OccupancyGrid, Passage
from algorithms.progress import RecordingProgress
from algorithms.sample_building import open_facade_plan

RES = 0.05


def _grid_of(walls, extent, res=RES):
    """Rasterize shapely wall polygons (metres) as filled geometry on ``extent``."""
    geoms = []
    for p in getattr(walls, "geoms", [walls]):
        rings = [np.asarray(r.coords) for r in [p.exterior] + list(p.interiors)]
        coords = np.concatenate([np.vstack([r, [[np.nan, np.nan]]]) for r in rings])[:-1]  # even-odd fill
        geoms.append(CadGeometry("A-WALL", "wall", coords, closed=True, filled=True))
    return ras.rasterize(geoms, resolution=res, extent=extent, kernel=3)


def _best(ag, poly):
    """(area, IoU) of the area overlapping ``poly`` most."""
    best, iou = None, 0.0
    for a in ag.areas:
        inter = a.polygon.intersection(poly).area
        if inter <= 0:
            continue
        v = inter / a.polygon.union(poly).area
        if v > iou:
            best, iou = a, v
    return best, iou


def _joined(ag, a, b):
    return any({p.from_id, p.to_id} == {a.id, b.id} for p in ag.passages)


@pytest.fixture(scope="module")
def open_facade():
    walls, rooms, doors, labels = open_facade_plan()
    grid = _grid_of(walls, (-6.0, -6.0, 40.0, 21.0))
    return grid, rooms, doors, labels


def test_robot_maps_use_no_footprint(open_facade):
    """Without footprint evidence (the default: robot maps, whose free space beside the rooms is
    where the scan ended) the open hall stays outside unless a name claims it."""
    grid, rooms, _, labels = open_facade
    ag = seg.segment(grid)
    assert _best(ag, rooms["HALL DISTRIBUZIONE"])[1] < 0.5
    named = seg.segment(grid, inside_points=np.array([labels["HALL DISTRIBUZIONE"]]))
    assert _best(named, rooms["HALL DISTRIBUZIONE"])[1] >= 0.8


def test_old_envelope_eats_the_open_hall_and_portico(open_facade):
    """The failure of issue 8: with the 4 m disk alone the hall open to the street and the portico
    closed only by pillars are outside, and the rooms fall apart into two components."""
    grid, rooms, _, _ = open_facade
    free = grid.data == FREE
    interior, _ = seg.building_interior(free, RES, footprint_gap=seg.DEFAULT_ENVELOPE_GAP)
    c, r = grid.world_to_pixel(17.0, 6.0)
    assert not interior[int(r), int(c)]  # the hall is "outside"
    c, r = grid.world_to_pixel(10.0, 13.5)
    assert not interior[int(r), int(c)]  # and so is the portico


@pytest.mark.parametrize("with_names", [False, True])
def test_open_hall_and_portico_become_areas_with_passages(open_facade, with_names):
    grid, rooms, doors, labels = open_facade
    pts = np.array(list(labels.values())) if with_names else None
    ag = seg.segment(grid, inside_points=pts, footprint=True)
    found = {}
    for name, poly in rooms.items():
        a, iou = _best(ag, poly)
        assert iou >= 0.8, (name, iou)
        found[name] = a
    assert len({a.id for a in found.values()}) == len(rooms)  # every space its own area
    for a_name, b_name, _ in doors:
        assert _joined(ag, found[a_name], found[b_name]), (a_name, b_name)
    assert ag.stats["components"] == 1 and ag.stats["largest_component_share"] == 1.0
    assert all(a.component == 0 for a in ag.areas)
    # closed at the chord between the wing corners, not eaten by a bite of the rolling disk
    hall = found["HALL DISTRIBUZIONE"]
    assert hall.polygon.area >= 0.95 * rooms["HALL DISTRIBUZIONE"].area
    assert hall.polygon.bounds[1] >= -0.3  # and no further out than the facade line
    portico = found["CORRIDOIO DI DISTRIBUZIONE"]
    assert portico.type == "corridor"
    assert portico.polygon.bounds[3] <= 15.3


def test_label_claims_a_hall_wider_than_the_footprint_scale():
    """A hall whose street side is wider than the footprint scale (3 x 4 m) is outside unless its
    name says otherwise; with the name it is an area, closed at the chord."""
    walls, rooms, doors, labels = open_facade_plan(hall_width=14.0)
    grid = _grid_of(walls, (-6.0, -6.0, 44.0, 21.0))
    hall = rooms["HALL DISTRIBUZIONE"]
    plain = seg.segment(grid, footprint=True)
    _, iou = _best(plain, hall)
    assert iou < 0.5
    rec = RecordingProgress()
    named = seg.segment(grid, inside_points=np.array(list(labels.values())), progress=rec, footprint=True)
    a, iou = _best(named, hall)
    assert iou >= 0.8
    assert named.stats["inside_points_outside"] == 0
    assert named.stats["components"] == 1


def test_names_far_outside_claim_nothing(open_facade):
    """A title or street name in open land is no evidence: it is reported, not turned into an area."""
    grid, rooms, _, labels = open_facade
    pts = np.array(list(labels.values()) + [(-4.0, -4.5)])
    rec = RecordingProgress()
    ag = seg.segment(grid, inside_points=pts, progress=rec, footprint=True)
    assert ag.stats["inside_points_outside"] == 1
    assert any(k == "warning" and "open to the outside" in m for k, m in rec.messages)
    total = sum(p.area for p in rooms.values())
    assert sum(a.area for a in ag.areas) <= 1.03 * total


def test_no_bites_where_windows_are_not_drawn():
    """A facade drawn as pillars with 3 m gaps (glazing not drawn): the 4 m disk bulges into every
    gap; the room is closed at the facade line instead."""
    t = 0.3
    segs = [(0, 0, 0, 8), (0, 8, 20, 8), (20, 8, 20, 0)]
    walls = [LineString([(a, b), (c, d)]).buffer(t / 2, cap_style=3) for a, b, c, d in segs]
    walls += [box(x - 0.2, -0.2, x + 0.2, 0.2) for x in (0.0, 3.4, 6.8, 10.2, 13.6, 17.0, 20.0)]
    from shapely.ops import unary_union

    grid = _grid_of(unary_union(walls), (-5.0, -5.0, 25.0, 13.0))
    ag = seg.segment(grid)
    room = box(t / 2, 0.0, 20 - t / 2, 8 - t / 2)
    a, iou = _best(ag, room)
    assert a.polygon.intersection(room).area >= 0.98 * room.area
    assert ag.stats["claimed_open_m2"] > 1.0


def test_footprint_pockets_without_doorway_stay_outside():
    """An exterior recess between two wings that opens onto no room (walls only) is landscape."""
    t = 0.3
    from shapely.ops import unary_union

    segs = [(0, 0, 8, 0), (0, 0, 0, 12), (0, 12, 26, 12), (26, 12, 26, 0), (18, 0, 26, 0),
            (8, 0, 8, 12), (18, 0, 18, 12)]  # two closed wings, a 10 m recess between them
    walls = unary_union([LineString([(a, b), (c, d)]).buffer(t / 2, cap_style=3) for a, b, c, d in segs])
    grid = _grid_of(walls, (-5.0, -5.0, 31.0, 17.0))
    ag = seg.segment(grid, footprint=True)
    recess = box(8.2, 0, 17.8, 11.8)
    assert all(a.polygon.intersection(recess).area < 1.0 for a in ag.areas)
    assert ag.stats["components"] == 2  # the two wings: nothing joins them, and the log says so


# ------------------------------------------------------------------------------------------ doors
def _two_rooms_with_leaf(res=RES):
    """Two 5 x 4 m rooms sharing a wall with a 1 m doorway at x = 5, y 1.5..2.5, closed by a door
    leaf drawn across the opening (a spaghetti drawing)."""
    lines = [[(0, 0), (10, 0)], [(10, 0), (10, 4)], [(10, 4), (0, 4)], [(0, 4), (0, 0)],
             [(5, 0), (5, 1.5)], [(5, 2.5), (5, 4)], [(5.05, 1.5), (5.05, 2.5)]]  # last: the leaf
    geoms = [CadGeometry("0", "wall", np.array(c, float)) for c in lines]
    return geoms, DoorHint(5.0, 1.5, 5.0, 2.5, "swing")


def test_door_hint_keeps_the_opening_free_in_the_raster():
    geoms, hint = _two_rooms_with_leaf()
    closed = ras.rasterize(geoms, resolution=RES, extent=(-1, -1, 11, 5))
    opened = ras.rasterize(geoms, resolution=RES, extent=(-1, -1, 11, 5), door_hints=[hint])
    c, r = closed.world_to_pixel(5.0, 2.0)
    assert closed.data[int(r), int(c)] == OCCUPIED
    assert opened.data[int(r), int(c)] == FREE
    c, r = opened.world_to_pixel(5.0, 1.3)  # the jambs stay walls
    assert opened.data[int(r), int(c)] == OCCUPIED
    seg_closed = seg.segment(closed, door_width=1.0, corridor_width=2.0)
    seg_open = seg.segment(opened, door_width=1.0, corridor_width=2.0)
    assert seg_closed.stats["components"] == 2 and len(seg_closed.passages) == 0
    assert seg_open.stats["components"] == 1 and len(seg_open.passages) == 1
    assert seg_open.passages[0].line.length == pytest.approx(1.0, abs=0.15)


def test_door_hint_given_to_segment_opens_a_foreign_raster():
    """A GeoTIFF from elsewhere with the door drawn shut: segment's door_hints open it too."""
    geoms, hint = _two_rooms_with_leaf()
    closed = ras.rasterize(geoms, resolution=RES, extent=(-1, -1, 11, 5))
    ag = seg.segment(closed, door_width=1.0, corridor_width=2.0, door_hints=[hint])
    assert ag.stats["components"] == 1 and len(ag.passages) == 1


def test_hint_passages_join_areas_the_segmentation_left_apart():
    grid = OccupancyGrid(np.zeros((40, 80), np.uint8), 0.0, 4.0, 0.1)
    labels = np.zeros((40, 80), np.int32)
    labels[:, :39] = 1
    labels[:, 41:] = 2  # a 2 px wall between them, no passage
    hint = DoorHint(4.0, 1.5, 4.0, 2.5)
    extra = seg.hint_passages(labels, grid, [hint], [])
    assert len(extra) == 1
    p = extra[0]
    assert (p.from_id, p.to_id) == (1, 2) and p.tags["cad2osmag:source"] == "door_hint"
    assert p.line.length == pytest.approx(1.0)
    # already joined: nothing added; a hint into no area: nothing added
    assert seg.hint_passages(labels, grid, [hint], [Passage(1, 2, 1, LineString([(4, 0), (4, 1)]))]) == []
    assert seg.hint_passages(labels, grid, [DoorHint(0.0, 5.0, 1.0, 5.0)], []) == []


# ------------------------------------------------------------------------------------------ components
def test_components_are_numbered_by_size_and_reported():
    areas = [Area(1, box(0, 0, 10, 10)), Area(2, box(10, 0, 20, 10)), Area(3, box(30, 0, 32, 2), name="Shaft"),
             Area(4, box(40, 0, 45, 5))]
    passages = [Passage(1, 1, 2, LineString([(10, 2), (10, 4)]))]
    comps = seg.assign_components(areas, passages)
    assert [c["ids"] for c in comps] == [[1, 2], [4], [3]]
    assert [a.component for a in areas] == [0, 0, 2, 1]
    assert comps[0]["share"] == pytest.approx(200 / 229)
    rec = RecordingProgress()
    seg.report_components(comps, rec, "test")
    text = "\n".join(m for _, m in rec.messages)
    assert "3 connected components" in text and "areas 3 (Shaft), 4.0 m2" in text


def test_room_name_points_rule():
    texts = [CadText(1, 1, "AULA 1", 0.3, 0, "t"), CadText(2, 2, "+0.30", 0.3, 0, "t"),
             CadText(3, 3, "A", 0.3, 0, "t"), CadText(4, 4, "Level -6.000", 0.3, 0, "t"),
             CadText(5, 5, "2.40x1.20", 0.3, 0, "t"), CadText(6, 6, "Hall distribuzione", 0.3, 0, "t"),
             CadText(7, 7, "h 2.70", 0.3, 0, "t"), CadText(8, 8, "办公室", 0.3, 0, "t"),
             CadText(9, 9, "PLAN", 0.3, 0, "t"), CadText(10, 10, "SECTION 1-1", 0.3, 0, "t"),
             CadText(11, 11, "Pianta piano terra scala 1:100", 0.3, 0, "t"),
             CadText(12, 12, "www.archweb.it", 0.3, 0, "t"), CadText(13, 13, "Planning office", 0.3, 0, "t")]
    pts = seg.room_name_points(texts)
    assert pts.tolist() == [[1, 1], [6, 6], [8, 8], [13, 13]]
