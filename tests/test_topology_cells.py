"""The segmentation's topology on coarser cells (session 10, issue 13): the skeleton, regions and merges work on
cells of about ``segmentation.TOPOLOGY_RESOLUTION`` (2 x 2 pixels of a 0.044 m CAD raster), the outlines and
passages are traced on the raster's own pixels. And the identical-output speed-ups that came with it (rasterize
repair by boxes, open-ground painting, polygons without copies)."""
import numpy as np
import pytest
from shapely.geometry import box

from algorithms import pipeline, rasterize, refine, segmentation
from algorithms.model import FREE, OCCUPIED, UNKNOWN, Area, AreaGraph, OccupancyGrid, Passage
from algorithms.sample_building import generate_building, ground_truth_doors, ground_truth_rooms

RES = 0.044


def _grid(img, res=RES):
    return OccupancyGrid(img, 0.0, img.shape[0] * res, res)


# --------------------------------------------------------------------------- the cells
@pytest.mark.parametrize("res,k", [(0.044, 2), (0.05, 1), (0.022, 4), (0.03, 2), (0.088, 1), (0.1, 1)])
def test_topology_scale_is_the_whole_multiple_of_the_raster_cell_up_to_the_topology_cell(res, k):
    assert segmentation.topology_scale(res) == k


def test_topology_scale_off_and_too_coarse_for_the_openings():
    assert segmentation.topology_scale(0.044, cell=0) == 1
    assert segmentation.topology_scale(0.044, cell=0.2) == 4
    # narrow doors and corridors: cells so coarse that alpha < 2 px^2 are refused, the scale steps down
    k = segmentation.topology_scale(0.01, door_width=0.1, corridor_width=0.1, delta=0.0, cell=1.0)
    assert k >= 1 and segmentation.compute_alpha(0.1, 0.1, 0.0, 0.01 * k) >= 2
    assert segmentation.compute_alpha(0.1, 0.1, 0.0, 0.01 * (k + 1)) < 2


def test_topology_cell_from_the_environment(monkeypatch):
    monkeypatch.setenv("CAD2OSMAG_TOPOLOGY_CELL", "0")
    assert segmentation._topology_default() == 0.0
    for bad in ("x", "-1", "nan"):
        monkeypatch.setenv("CAD2OSMAG_TOPOLOGY_CELL", bad)
        assert segmentation._topology_default() == 0.088


def test_coarse_cells_keep_every_wall_and_let_doors_and_unknown_through():
    img = np.zeros((9, 11), np.uint8)
    img[:, 5] = OCCUPIED  # a wall one pixel thick on an odd column: it falls inside one cell column
    img[0, 0] = UNKNOWN
    img[8, 10] = 100  # any value but free and unknown is occupied
    opened = np.zeros_like(img, bool)
    opened[4:6, 5] = True  # a door hint opens the wall (both pixel rows of one cell row)
    c = segmentation.coarsen_grid(_grid(img), 2)
    assert c.data.shape == (5, 6) and c.resolution == pytest.approx(2 * RES)
    assert (c.origin_x, c.origin_y) == (0.0, img.shape[0] * RES)
    assert (c.data[:, 2] == OCCUPIED).all()  # the wall is closed on the coarse cells
    assert c.data[0, 0] == UNKNOWN and c.data[4, 5] == OCCUPIED and c.data[2, 0] == FREE
    o = segmentation.coarsen_grid(_grid(img), 2, opened)
    assert o.data[2, 2] == FREE and (o.data[[0, 1, 3, 4], 2] == OCCUPIED).all()


def test_fine_labels_fill_the_free_pixels_of_each_room_and_never_cross_a_wall():
    img = np.zeros((40, 61), np.uint8)
    img[0, :] = img[-1, :] = img[:, 0] = img[:, -1] = OCCUPIED
    img[:, 31] = OCCUPIED  # one-pixel wall at an odd column: its cells hold free pixels of both rooms
    grid = _grid(img)
    k = 2
    coarse = segmentation.coarsen_grid(grid, k)
    cl = np.zeros(coarse.data.shape, np.int32)
    free_c = coarse.data == FREE
    cl[:, :16][free_c[:, :16]] = 1
    cl[:, 16:][free_c[:, 16:]] = 2
    fine = segmentation.refine_labels(cl, coarse, grid, k)
    assert fine.shape == img.shape
    assert (fine[img != FREE] == 0).all()
    assert (fine[1:-1, 1:31] == 1).all() and (fine[1:-1, 32:-1] == 2).all()  # every free pixel, wall to wall
    # a free cell the segmentation left outside every area stays outside at full resolution
    cl2 = cl.copy()
    cl2[5:8, 5:8] = 0
    fine2 = segmentation.refine_labels(cl2, coarse, grid, k)
    assert (fine2[10:16, 10:16] == 0).all()


def _two_rooms(door_m, wall_px=1, odd=True):
    """Two 6 x 5 m rooms side by side, a wall ``wall_px`` thick between them with a door ``door_m`` wide,
    closed by thick outer walls (a CAD raster at 0.044 m/px)."""
    h, w = int(5.0 / RES) + 20, int(12.0 / RES) + 20
    img = np.full((h, w), OCCUPIED, np.uint8)
    img[10:-10, 10:-10] = FREE
    x = w // 2 + (1 if odd and (w // 2) % 2 == 0 else 0)
    img[10:-10, x:x + wall_px] = OCCUPIED
    d0 = h // 2 - int(door_m / RES / 2)
    img[d0:d0 + int(door_m / RES), x:x + wall_px] = FREE
    return _grid(img)


@pytest.mark.parametrize("door", [0.7, 0.9])
@pytest.mark.parametrize("wall_px", [1, 2, 3])
def test_rooms_behind_a_thin_wall_stay_two_areas_joined_by_their_door(door, wall_px):
    grid = _two_rooms(door, wall_px)
    ag = segmentation.segment(grid)
    ref = segmentation.segment(grid, topology_resolution=0)
    assert ag.stats["topology_scale"] == 2 and ref.stats["topology_scale"] == 1
    assert len(ag.areas) == len(ref.areas) == 2
    assert len(ag.passages) == len(ref.passages) == 1
    p = ag.passages[0]
    assert abs(p.line.length - door) < 3 * RES  # across the door, on the raster's pixels
    for a in ag.areas:  # the same rooms, outlines on the raster's pixels: each pixel of the room
        b = max(ref.areas, key=lambda r: r.polygon.intersection(a.polygon).area)
        assert a.polygon.intersection(b.polygon).area / a.polygon.union(b.polygon).area > 0.97
    free = grid.data == FREE
    assert np.count_nonzero((ag.labels > 0) & free) >= 0.995 * np.count_nonzero((ref.labels > 0) & free)
    assert not (ag.labels[~free] > 0).any()
    assert ag.skeleton_grid is not None and ag.skeleton_grid.resolution == pytest.approx(2 * RES)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_every_ground_truth_room_and_door_of_other_sample_buildings(tmp_path, seed):
    """The kind: office floors of rooms on a corridor (other seeds than the pinned one), on the coarse cells."""
    gen = generate_building(str(tmp_path), floors=1, seed=seed)
    fl = pipeline.process_floor(gen["dxf"][0])
    assert fl.segmented.stats["topology_scale"] == 2
    spaces = fl.refined.areas
    rooms = ground_truth_rooms(gen["ground_truth"][0])
    matched = {}
    for room in rooms:
        best = max(spaces, key=lambda a: a.polygon.intersection(room["polygon"]).area)
        iou = best.polygon.intersection(room["polygon"]).area / best.polygon.union(room["polygon"]).area
        assert iou >= 0.8, (seed, room["name"], iou)
        matched[room["name"]] = best.id
    assert len(set(matched.values())) == len(matched) == len(spaces)
    pairs = {frozenset((p.from_id, p.to_id)) for p in fl.refined.passages}
    for door in ground_truth_doors(gen["ground_truth"][0]):
        if door["from"] in matched and door["to"] in matched:
            assert frozenset((matched[door["from"]], matched[door["to"]])) in pairs, (seed, door)


# --------------------------------------------------------------------------- refine: borders on coarse cells
def _staircase_pair(step):
    """Two areas whose shared border is a staircase of ``step`` m steps (a diagonal decided on cells that
    coarse), walls straight."""
    import shapely
    from shapely.geometry import Polygon

    pts = [(0.0, 0.0)]
    x = y = 0.0
    while x < 3.0 - 1e-9:
        y += step
        pts.append((x, y))
        x += step
        pts.append((x, y))
    y += step
    pts.append((x, y))
    left = Polygon([(-2.0, 0.0)] + pts + [(-2.0, y)])
    right = Polygon([(5.0, 0.0), (5.0, y)] + pts[::-1])
    i = len(pts) // 2
    return AreaGraph([Area(1, left), Area(2, right)], [Passage(1, 1, 2, line=shapely.LineString([pts[i - 4], pts[i]]))])


def test_a_border_between_two_areas_is_simplified_with_the_tolerance_of_its_cells():
    g = _staircase_pair(2 * RES)
    assert g.areas[0].polygon.is_valid and g.areas[1].polygon.is_valid
    fine, st1 = refine.refine(g, RES, min_area=0.0)
    g.stats["topology_scale"] = 2
    coarse, st2 = refine.refine(g, RES, min_area=0.0)
    assert st1["border_epsilon_m"] == pytest.approx(st1["epsilon_m"])
    assert st2["border_epsilon_m"] == pytest.approx(2 * st2["epsilon_m"])
    assert st2["vertices_after"] < st1["vertices_after"]  # the cells' steps are gone
    assert st2["max_deviation_dp_m"] <= st2["border_epsilon_m"] + 1e-9
    a2 = {a.id: a.polygon for a in coarse.areas}
    assert a2[1].intersection(a2[2]).area < 1e-9  # still one shared border, no overlap
    # a wall face keeps the raster's tolerance: the outer corners are where they were
    for a in coarse.areas:
        assert a.polygon.bounds == pytest.approx(next(x.polygon.bounds for x in g.areas if x.id == a.id), abs=1e-9)


# --------------------------------------------------------------------------- identical-output speed-ups
def _repair_reference(img, k):
    import cv2

    se = cv2.getStructuringElement(cv2.MORPH_RECT, (k, k))
    closed = cv2.morphologyEx(img, cv2.MORPH_CLOSE, se, borderType=cv2.BORDER_CONSTANT, borderValue=0)
    opened = cv2.morphologyEx(closed, cv2.MORPH_OPEN, se, borderType=cv2.BORDER_CONSTANT, borderValue=0)
    n, labels, stats, _ = cv2.connectedComponentsWithStats((closed > 0).astype(np.uint8), connectivity=8)
    if n <= 1:
        return closed
    keep = np.zeros(n, dtype=bool)
    keep[labels[opened > 0]] = True
    span = np.maximum(stats[:, cv2.CC_STAT_WIDTH], stats[:, cv2.CC_STAT_HEIGHT])
    keep |= span > 2 * k
    keep[0] = False
    return np.where(keep, OCCUPIED, FREE).astype(np.uint8)[labels]


@pytest.mark.parametrize("share", [0.002, 0.05])  # few specks (boxes), many (one whole-raster pass)
@pytest.mark.parametrize("k", [3, 5])
def test_repair_by_boxes_equals_the_whole_raster_pass(share, k):
    rng = np.random.default_rng(7)
    img = np.where(rng.random((400, 600)) < share, OCCUPIED, FREE).astype(np.uint8)
    img[100:300, 200:204] = OCCUPIED
    img[50:52, 10:500] = 200  # any occupied value comes out OCCUPIED
    got = rasterize.repair(img.copy(), k)
    assert got.dtype == np.uint8 and np.array_equal(got, _repair_reference(img, k))


def test_open_ground_painting_first_area_wins_like_repainting_each():
    import cv2

    grid = _grid(np.zeros((120, 160), np.uint8))
    polys = [box(0.5, 0.5, 3.0, 3.0), box(2.9, 0.6, 5.0, 2.5).union(box(1.0, 1.0, 1.5, 1.5)),
             box(1.0, 1.0, 2.0, 2.0), box(4.0, 0.2, 6.5, 4.9)]
    ref = np.zeros(grid.shape, np.int32)
    for i, p in enumerate(polys, 1):
        for part in getattr(p, "geoms", [p]):
            rasterize.repaint_polygon(ref, grid, part, i, old_id=0)
    got = np.zeros(grid.shape, np.int32)
    for i, p in reversed(list(enumerate(polys, 1))):
        for part in reversed(list(getattr(p, "geoms", [p]))):
            cv2.fillPoly(got, [rasterize.ring_px(part.exterior, grid)], i, shift=3)
    assert np.array_equal(got, ref)


def test_label_polygons_are_the_exact_pixel_outlines():
    lab = np.zeros((30, 40), np.int32)
    lab[2:10, 3:20] = 1
    lab[12:25, 5:9] = 2
    lab[12:25, 9:30] = 3
    lab[15:18, 15:18] = 0  # a hole
    polys = segmentation.label_polygons(lab, _grid(np.zeros((30, 40), np.uint8), res=1.0))
    assert sorted(polys) == [1, 2, 3]
    for i, p in polys.items():
        assert p.area == pytest.approx(np.count_nonzero(lab == i))
    assert len(polys[3].interiors) == 1


# --------------------------------------------------------------------------- robot maps at a finer resolution
@pytest.mark.slow
@pytest.mark.parametrize("name", ["intel_map", "lab_d"])
def test_a_robot_map_at_half_the_cell_size_segments_as_well_as_at_its_own(shared_data, name):
    """The kind: a robot map recorded at 0.025 m/px (SLAM packages save either). The topology cells (3 x 3 pixels
    there, 0.075 m) keep its figures near those at 0.05 m/px; on the raster's own cells intel_map falls from
    MCC 0.82 to 0.60 (measured in session 10: mean over the five maps 0.913 with cells, 0.867 without)."""
    import sys

    from algorithms.evaluate import evaluate, read_gt_image

    from .conftest import REPO

    folder = shared_data / "grid_gt"
    if not (folder / "gt" / f"{name}.png").is_file():
        pytest.skip("the robot maps with ground truth are not in the shared data")
    sys.path.insert(0, str(REPO / "scripts"))
    try:
        from evaluate_grids import _read_map
    finally:
        sys.path.remove(str(REPO / "scripts"))
    g0 = _read_map(folder / "input" / f"{name}.png", 0.05)
    gt0 = read_gt_image(str(folder / "gt" / f"{name}.png"))
    native = evaluate(segmentation.segment(g0).labels, gt0)["mcc"]
    up = OccupancyGrid(np.repeat(np.repeat(g0.data, 2, 0), 2, 1), g0.origin_x, g0.origin_y, 0.025)
    ag = segmentation.segment(up)
    assert ag.stats["topology_scale"] == 3
    fine = evaluate(ag.labels, np.repeat(np.repeat(gt0, 2, 0), 2, 1))["mcc"]
    assert fine >= native - 0.03, (name, native, fine)


@pytest.mark.parametrize("rows,cols,k", [(7, 9, 2), (8, 9, 2), (7, 8, 2), (8, 8, 2), (10, 11, 3), (9, 9, 3), (5, 5, 1)])
def test_upsampled_labels_are_the_cells_on_their_pixels_cut_at_the_edge(rows, cols, k):
    """``_upsample`` writes every cell's label on its k x k pixels straight into the raster's shape (the last
    row and column of cells cut by the edge): the same as repeating and cropping, without the cropped copy."""
    rng = np.random.default_rng(rows * 100 + cols * 10 + k)
    cells = rng.integers(0, 50, (-(-rows // k), -(-cols // k))).astype(np.int32)
    want = np.repeat(np.repeat(cells, k, axis=0), k, axis=1)[:rows, :cols]
    got = segmentation._upsample(cells, k, rows, cols)
    assert got.shape == (rows, cols) and got.flags.c_contiguous and np.array_equal(got, want)
