"""Area Graph segmentation on small synthetic plans drawn with OpenCV (quick tests)."""
import math

import cv2
import numpy as np
import pytest
from shapely.geometry import Point, box
from shapely.ops import unary_union

from algorithms import segmentation as seg
from algorithms.errors import Canceled, InputError
from algorithms.model import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from algorithms.progress import RecordingProgress

RES = 0.05
WALL = 0.2  # m


def _px(v):
    return int(round(v / RES))


class Plan:
    """A 24 x 14 m office floor with a 2 m corridor, drawn on a 30 x 20 m free canvas (outside is
    free space too, like a rasterized CAD plan). Rooms in metres (x0, y0, x1, y1), y down."""

    def __init__(self, facade_gaps=True, pillar=True):
        self.w, self.h = 30.0, 20.0
        img = np.zeros((_px(self.h), _px(self.w)), np.uint8)
        self.img = img
        ox, oy = 3.0, 3.0
        self.bx = (ox, oy, ox + 24.0, oy + 14.0)
        self.rooms = {
            "A": (ox, oy, ox + 6, oy + 6), "B": (ox + 6, oy, ox + 12, oy + 6),
            "C": (ox + 12, oy, ox + 18, oy + 6), "D": (ox + 18, oy, ox + 24, oy + 6),
            "E": (ox, oy + 8, ox + 8, oy + 14), "F": (ox + 8, oy + 8, ox + 16, oy + 14),
            "G": (ox + 16, oy + 8, ox + 24, oy + 14),
            # a narrow store room (2.2 m), narrower than the default alpha disk
            "H": (ox + 16, oy + 8, ox + 18.2, oy + 14),
        }
        self.rooms["G"] = (ox + 18.2, oy + 8, ox + 24, oy + 14)
        self.corridor = (ox, oy + 6, ox + 24, oy + 8)
        for x0, y0, x1, y1 in list(self.rooms.values()) + [self.corridor]:
            self._rect(x0, y0, x1, y1)
        # doors (0.9 m) from every room into the corridor, plus A-B
        self.doors = []
        for name, (x0, y0, x1, y1) in self.rooms.items():
            cx = (x0 + x1) / 2
            y = y1 if y1 <= oy + 6 else y0
            self._gap_h(cx - 0.45, cx + 0.45, y)
            self.doors.append((name, "corridor", (cx, y)))
        self._gap_v(oy + 2.5, oy + 3.4, ox + 6)
        self.doors.append(("A", "B", (ox + 6, oy + 2.95)))
        if facade_gaps:
            # exterior door on the west end of the corridor, glazing gap (2 m) in room F's facade
            self._gap_v(oy + 6.4, oy + 7.6, ox)
            self._gap_h(ox + 10, ox + 12, oy + 14)
        if pillar:
            cx, cy = (ox + 8 + ox + 16) / 2, oy + 11
            cv2.rectangle(img, (_px(cx - 0.25), _px(cy - 0.25)), (_px(cx + 0.25), _px(cy + 0.25)), OCCUPIED, -1)
            self.pillar = (cx, cy)
        self.grid = OccupancyGrid(img.copy(), origin_x=100.0, origin_y=50.0 + self.h, resolution=RES)

    def _rect(self, x0, y0, x1, y1):
        cv2.rectangle(self.img, (_px(x0), _px(y0)), (_px(x1), _px(y1)), OCCUPIED, _px(WALL))

    def _gap_h(self, x0, x1, y):
        t = _px(WALL / 2) + 1
        self.img[_px(y) - t:_px(y) + t + 1, _px(x0):_px(x1)] = FREE

    def _gap_v(self, y0, y1, x):
        t = _px(WALL / 2) + 1
        self.img[_px(y0):_px(y1), _px(x) - t:_px(x) + t + 1] = FREE

    def world(self, x, y):
        """plan metres (y down from the canvas top) -> grid world coordinates"""
        return self.grid.origin_x + x, self.grid.origin_y - y

    def world_box(self, r):
        x0, y0 = self.world(r[0], r[3])
        x1, y1 = self.world(r[2], r[1])
        return box(x0, y0, x1, y1)


@pytest.fixture(scope="module")
def plan():
    return Plan()


@pytest.fixture(scope="module")
def result(plan):
    return seg.segment(plan.grid, door_width=1.0, corridor_width=2.0)


@pytest.fixture(scope="module")
def result_default(plan):
    return seg.segment(plan.grid)


def _best(ag, geom):
    best = max(ag.areas, key=lambda a: a.polygon.intersection(geom).area)
    inter = best.polygon.intersection(geom).area
    return best, inter / best.polygon.union(geom).area


def test_alpha_formula():
    assert seg.compute_alpha(2.8, 8.0, 0.1, 0.05) == 841  # (2.9 / 0.1)^2
    assert seg.compute_alpha(0.85, 1.65, 0.1, 0.05) == math.ceil(0.95 ** 2 / (4 * 0.05 ** 2))
    assert seg.compute_alpha(2.8, 1.4, 0.1, 0.044) == math.ceil(1.5 ** 2 / (4 * 0.044 ** 2))


@pytest.mark.parametrize("fixture", ["result", "result_default"])
def test_every_room_is_one_area(plan, fixture, request):
    ag = request.getfixturevalue(fixture)
    ids = set()
    for name, r in list(plan.rooms.items()) + [("corridor", plan.corridor)]:
        best, iou = _best(ag, plan.world_box(r))
        assert iou >= 0.8, (fixture, name, iou)
        ids.add(best.id)
    assert len(ids) == len(plan.rooms) + 1  # all different


@pytest.mark.parametrize("fixture", ["result", "result_default"])
def test_every_door_is_one_passage(plan, fixture, request):
    ag = request.getfixturevalue(fixture)
    area_of = {name: _best(ag, plan.world_box(r))[0].id for name, r in plan.rooms.items()}
    area_of["corridor"] = _best(ag, plan.world_box(plan.corridor))[0].id
    for a, b, (x, y) in plan.doors:
        p = Point(*plan.world(x, y))
        near = [q for q in ag.passages if q.line.distance(p) < 0.5]
        assert len(near) == 1, (a, b, [(q.from_id, q.to_id) for q in near])
        q = near[0]
        assert {q.from_id, q.to_id} == {area_of[a], area_of[b]}
        assert 0.6 <= q.width <= 1.2  # 0.9 m door
    # no passage anywhere but at the doors
    assert len(ag.passages) == len(plan.doors)


def test_outside_is_never_an_area(plan, result):
    building = plan.world_box(plan.bx).buffer(0.3)
    for a in result.areas:
        assert a.polygon.difference(building).area < 1.5, a.id  # at most the facade openings
    # a point well outside the facade gaps is not labelled
    col, row = plan.grid.world_to_pixel(*plan.world(plan.bx[0] - 1.5, plan.bx[1] + 7.0))
    assert result.labels[int(row), int(col)] == 0
    free_inside = plan.world_box(plan.bx).area - 1.0  # walls
    assert 0.85 * free_inside < result.stats["interior_area_m2"] < 1.05 * plan.world_box(plan.bx).area


def test_types_and_attributes(plan, result):
    corridor, _ = _best(result, plan.world_box(plan.corridor))
    assert corridor.type == "corridor"
    room_a, _ = _best(result, plan.world_box(plan.rooms["A"]))
    assert room_a.type == "room"
    assert room_a.max_clearance == pytest.approx(2.9, abs=0.15)  # 6 m room, 0.1 m wall half
    assert room_a.area == pytest.approx(room_a.polygon.area)
    for a in result.areas:
        assert a.polygon.geom_type == "Polygon" and a.polygon.is_valid
    # the pillar is a hole of room F
    room_f, _ = _best(result, plan.world_box(plan.rooms["F"]))
    assert len(room_f.polygon.interiors) == 1
    assert not room_f.polygon.contains(Point(*plan.world(*plan.pillar)))


def test_polygons_are_pixel_outlines_of_labels(plan, result):
    g = plan.grid
    for a in result.areas:
        n = int((result.labels == a.id).sum())
        assert a.polygon.area == pytest.approx(n * g.resolution ** 2, rel=1e-9)
        for x, y in list(a.polygon.exterior.coords):
            c, r = g.world_to_pixel(x, y)
            assert abs(c - round(c)) < 1e-6 and abs(r - round(r)) < 1e-6
    # areas never overlap
    union = unary_union([a.polygon for a in result.areas])
    assert union.area == pytest.approx(sum(a.polygon.area for a in result.areas), rel=1e-9)


def test_passage_endpoints_on_both_polygons(result):
    by_id = result.area_by_id()
    for p in result.passages:
        assert len(p.line.coords) == 2
        for pt in p.line.coords:
            for aid in (p.from_id, p.to_id):
                assert by_id[aid].polygon.exterior.distance(Point(pt)) < 1e-6 or \
                    any(r.distance(Point(pt)) < 1e-6 for r in by_id[aid].polygon.interiors)


def test_coverage_and_connectivity(plan, result):
    interior_free = result.stats["interior_area_m2"]
    covered = float((result.labels > 0).sum()) * plan.grid.resolution ** 2
    assert covered >= 0.97 * interior_free
    # all free pixels inside the facade are covered
    x0, y0, x1, y1 = [_px(v) for v in plan.bx]
    inside = plan.grid.data[y0 + 4:y1 - 4, x0 + 4:x1 - 4] == FREE
    lab = result.labels[y0 + 4:y1 - 4, x0 + 4:x1 - 4]
    assert (lab[inside] > 0).mean() >= 0.97
    # area graph connected
    ids = {a.id for a in result.areas}
    adj = {i: set() for i in ids}
    for p in result.passages:
        adj[p.from_id].add(p.to_id)
        adj[p.to_id].add(p.from_id)
    seen, todo = set(), [min(ids)]
    while todo:
        i = todo.pop()
        if i not in seen:
            seen.add(i)
            todo.extend(adj[i] - seen)
    assert seen == ids


def test_labels_raster(plan, result):
    assert result.labels.dtype == np.int32
    assert result.labels.shape == plan.grid.data.shape
    assert (result.labels[plan.grid.data != FREE] == 0).all()
    assert set(np.unique(result.labels)) == {0} | {a.id for a in result.areas}
    for key in ("skeleton_s", "graph_s", "merge_s", "passages_s", "polygons_s", "interior_area_m2", "alpha_px2"):
        assert key in result.stats


def test_deterministic(plan, result):
    again = seg.segment(plan.grid, door_width=1.0, corridor_width=2.0)
    assert np.array_equal(again.labels, result.labels)
    assert [(a.id, a.type, a.polygon.wkb) for a in again.areas] == [(a.id, a.type, a.polygon.wkb) for a in result.areas]
    assert [(p.from_id, p.to_id, p.line.wkb) for p in again.passages] == \
        [(p.from_id, p.to_id, p.line.wkb) for p in result.passages]


def test_closed_plan_without_outside_space():
    """A map that is all building (robot style, unknown outside): everything free is segmented."""
    plan = Plan(facade_gaps=False)
    data = plan.grid.data.copy()
    x0, y0, x1, y1 = [_px(v) for v in plan.bx]
    outside = np.ones(data.shape, bool)
    outside[y0 - 2:y1 + 3, x0 - 2:x1 + 3] = False
    data[outside] = UNKNOWN
    grid = OccupancyGrid(data, 0.0, data.shape[0] * RES, RES)
    ag = seg.segment(grid, door_width=1.0, corridor_width=2.0)
    free = data == FREE
    assert (ag.labels[free] > 0).mean() >= 0.97
    assert len(ag.areas) == len(plan.rooms) + 1


def test_progress_and_cancel(plan):
    rec = RecordingProgress()
    ag = seg.segment(plan.grid, progress=rec)
    assert rec.percents[-1] == 100
    assert "interior" in rec.text() and "m2" in rec.text()
    assert f"{ag.stats['interior_area_m2']:.1f}" in rec.text()
    with pytest.raises(Canceled):
        seg.segment(plan.grid, progress=RecordingProgress(cancel_after=2))


@pytest.mark.parametrize("data,res,msg", [
    (np.zeros((0, 0), np.uint8), 0.05, "empty"),
    (np.full((200, 200), OCCUPIED, np.uint8), 0.05, "no free"),
    (np.full((200, 200), UNKNOWN, np.uint8), 0.05, "no free"),
    (np.zeros((200, 200, 3), np.uint8), 0.05, "single-band"),
    (np.zeros((200, 200), np.uint8), 0.0, "resolution"),
    (np.zeros((200, 200), np.uint8), float("nan"), "resolution"),
    (np.zeros((200, 200), np.uint8), 2.5, "smaller than 2"),
    (np.zeros((40, 40), np.uint8), 0.01, "larger than the map"),
])
def test_bad_input(data, res, msg):
    with pytest.raises(InputError, match=msg):
        seg.segment(OccupancyGrid(data, 0.0, 0.0, res))


def test_bad_parameters(plan):
    with pytest.raises(InputError, match="DOOR_WIDTH"):
        seg.segment(plan.grid, door_width=0)
    with pytest.raises(InputError, match="PRUNE"):
        seg.segment(plan.grid, prune=-1)


def test_open_space_only_outside_raises():
    """Free space with no enclosure at all: nothing is inside a building."""
    data = np.zeros((300, 300), np.uint8)
    data[100:110, 100:200] = OCCUPIED  # a lone wall
    with pytest.raises(InputError, match="enclosed"):
        seg.segment(OccupancyGrid(data, 0.0, 15.0, 0.05))
