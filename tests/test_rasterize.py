"""Rasterization of synthetic geometry: geotransform, repair, bounds, budget, common grid."""
import numpy as np
import pytest

from algorithms.errors import InputError
from algorithms.model import FREE, OCCUPIED, CadGeometry
from algorithms.rasterize import (common_extent, geometry_bounds, grid_for_extent, rasterize, repair,
                                  suggest_resolution)


def line(*pts, **kw):
    return CadGeometry(layer=kw.pop("layer", "A-WALL"), kind=kw.pop("kind", "wall"),
                       coords=np.array(pts, dtype=np.float64), **kw)


def box(x0, y0, x1, y1, **kw):
    return line((x0, y0), (x1, y0), (x1, y1), (x0, y1), closed=True, **kw)


def occupied_at(grid, x, y):
    c, r = grid.world_to_pixel(x, y)
    return grid.data[int(np.floor(r)), int(np.floor(c))] == OCCUPIED


def free_components(grid):
    import cv2

    n, lab, st, _ = cv2.connectedComponentsWithStats((grid.data == FREE).astype(np.uint8), connectivity=4)
    return n - 1, st[1:, cv2.CC_STAT_AREA]


def test_geotransform_maps_pixels_back_to_cad_frame():
    geoms = [box(10.0, 20.0, 30.0, 32.0)]
    g = rasterize(geoms, resolution=0.05, kernel=0)
    assert g.data.dtype == np.uint8 and set(np.unique(g.data)) <= {FREE, OCCUPIED}
    # origin snapped to the resolution grid
    assert g.origin_x / 0.05 == pytest.approx(round(g.origin_x / 0.05))
    assert g.origin_y / 0.05 == pytest.approx(round(g.origin_y / 0.05))
    assert g.geotransform == (g.origin_x, 0.05, 0.0, g.origin_y, 0.0, -0.05)
    # the wall line x=10 is occupied exactly in the pixel column that contains x=10
    col, row = g.world_to_pixel(10.0, 26.0)
    assert g.data[int(row), int(col)] == OCCUPIED
    assert occupied_at(g, 30.0, 26.0) and occupied_at(g, 20.0, 20.0) and occupied_at(g, 20.0, 32.0)
    assert not occupied_at(g, 20.0, 26.0)  # inside the room
    assert not occupied_at(g, 10.0 - 0.3, 26.0)  # outside, beyond the stroke
    # stroke width ~0.15 m -> 3 px
    r = int(g.world_to_pixel(20, 26)[1])
    assert 2 <= int((g.data[r] > 0).sum()) // 2 <= 4
    xmin, ymin, xmax, ymax = g.extent
    assert xmin < 10 and ymin < 20 and xmax > 30 and ymax > 32
    assert xmin > 10 - 0.03 * 20 - 1 and xmax < 30 + 0.03 * 20 + 1  # 3 % padding plus a stroke margin


def test_gap_of_20cm_bridged_and_specks_removed():
    # a room whose right wall has a 0.2 m gap (drawing error) and a 5 cm speck inside
    walls = [line((0, 0), (10, 0)), line((10, 0), (10, 4.9)), line((10, 5.1), (10, 10)),
             line((10, 10), (0, 10)), line((0, 10), (0, 0)),
             box(5.0, 5.0, 5.01, 5.01)]
    g = rasterize(walls)
    assert occupied_at(g, 10.0, 5.0)  # gap closed
    assert not occupied_at(g, 5.0, 5.0)  # speck removed
    n, areas = free_components(g)
    assert n == 2  # inside and outside are separated
    # a doorway-sized gap (0.6 m) is not bridged
    walls[1:3] = [line((10, 0), (10, 4.7)), line((10, 5.3), (10, 10))]
    assert free_components(rasterize(walls))[0] == 1


def test_door_opening_of_80cm_stays_open():
    walls = [line((0, 0), (10, 0)), line((10, 0), (10, 4.6)), line((10, 5.4), (10, 10)),
             line((10, 10), (0, 10)), line((0, 10), (0, 0))]
    g = rasterize(walls)
    assert not occupied_at(g, 10.0, 5.0)
    assert free_components(g)[0] == 1


def test_thin_diagonal_wall_survives_opening():
    walls = [box(0, 0, 20, 20), line((0, 0), (20, 20))]
    g = rasterize(walls)
    assert occupied_at(g, 10.0, 10.0) and occupied_at(g, 5.0, 5.0)
    assert free_components(g)[0] == 3  # two triangles and the outside


def test_filled_polygon_with_hole_and_wide_polyline():
    ring = np.array([(0, 0), (4, 0), (4, 4), (0, 4), (np.nan, np.nan), (1, 1), (3, 1), (3, 3), (1, 3)], float)
    geoms = [CadGeometry("A-WALL", "wall", ring, closed=True, filled=True, entity="HATCH"),
             line((6, 0), (6, 8), width=0.6), box(-1, -1, 10, 10)]
    g = rasterize(geoms, resolution=0.02)
    assert occupied_at(g, 0.5, 0.5) and occupied_at(g, 3.5, 2.0)
    assert not occupied_at(g, 2.0, 2.0)  # the island stays free (even-odd)
    assert occupied_at(g, 6.25, 4.0) and not occupied_at(g, 6.4, 4.0)


def test_stray_entity_far_away_does_not_blow_up_the_raster():
    geoms = [box(0, 0, 40, 20)] + [line((x, 0), (x, 20)) for x in np.arange(1, 40, 0.1)]
    geoms.append(line((5000.0, 8000.0), (5001.0, 8000.0)))  # 9 km away
    g = rasterize(geoms)
    xmin, ymin, xmax, ymax = g.extent
    assert xmax < 45 and ymax < 25 and g.data.size < 2e6


def test_pixel_budget_error_names_extent_and_resolution():
    geoms = [box(0, 0, 2000, 1000)]
    with pytest.raises(InputError) as exc:
        rasterize(geoms, resolution=0.044, max_pixels=60e6, padding=0)
    msg = str(exc.value)
    assert "Mpx" in msg and "2000" in msg and "m/px" in msg
    r = suggest_resolution(2000, 1000, 60e6)
    assert r > 0.044
    g = rasterize(geoms, resolution=r * 1.1, max_pixels=60e6, padding=0, kernel=0)
    assert g.data.size <= 60e6


def test_common_extent_aligns_floors_pixel_for_pixel():
    f1 = [box(0, 0, 30, 20), line((10, 0), (10, 20))]
    f2 = [box(5, -3, 42, 18), line((10, -3), (10, 18))]
    ext = common_extent([f1, f2])
    g1 = rasterize(f1, extent=ext)
    g2 = rasterize(f2, extent=ext)
    assert g1.shape == g2.shape and g1.geotransform == g2.geotransform
    # the shared wall x=10 occupies the same pixel columns in both floors
    r1 = int(g1.world_to_pixel(10, 10)[1])
    c = int(g1.world_to_pixel(10.0, 0)[0])
    near = slice(c - 10, c + 11)
    assert np.array_equal(np.flatnonzero(g1.data[r1, near] > 0), np.flatnonzero(g2.data[r1, near] > 0))
    assert len(np.flatnonzero(g1.data[r1, near] > 0)) >= 3
    rows = slice(int(g1.world_to_pixel(0, 15)[1]), int(g1.world_to_pixel(0, 5)[1]))
    assert np.array_equal(g1.data[rows, c - 3:c + 4], g2.data[rows, c - 3:c + 4])
    assert (g1.data[rows, c] == OCCUPIED).all()
    # an explicit extent is snapped outward to multiples of the resolution
    ox, oy, rows_, cols = grid_for_extent((0.01, 0.01, 1.0, 1.0), 0.044)
    assert ox == pytest.approx(0.0) and oy == pytest.approx(1.012) and cols == 23 and rows_ == 23


def test_bad_parameters():
    with pytest.raises(InputError, match="no geometry"):
        rasterize([])
    with pytest.raises(InputError, match="resolution"):
        rasterize([box(0, 0, 1, 1)], resolution=0)
    with pytest.raises(InputError, match="percentiles"):
        geometry_bounds([box(0, 0, 1, 1)], (99, 1))


def test_repair_keeps_long_thin_lines():
    img = np.zeros((100, 100), np.uint8)
    img[50, 10:90] = OCCUPIED  # 1 px line, 80 px long: not a speck
    img[10:12, 10:12] = OCCUPIED  # 2x2 speck
    out = repair(img, 5)
    assert out[50, 50] == OCCUPIED and out[10, 10] == FREE


def _irregular_floor(seed=1):
    rng = np.random.default_rng(seed)
    geoms = [box(0, 0, 60, 30)]
    for x in rng.uniform(3, 57, 12):
        geoms.append(line((x, 0), (x, rng.uniform(8, 14))))
    for y in rng.uniform(3, 27, 6):
        x0 = rng.uniform(0, 30)
        geoms.append(line((x0, y), (x0 + rng.uniform(5, 25), y)))
    geoms.append(box(20, 12, 24.5, 18.3))  # a stair core
    return geoms


def test_floor_offsets_recover_a_translation():
    from algorithms.rasterize import floor_offsets, floors_share_frame, shift_geometries

    f1 = _irregular_floor()
    f2 = shift_geometries(f1[:-3], 1234.567, -345.678) + [line((1300, -340), (1310, -330))]
    assert not floors_share_frame([f1, f2])
    (d0, d1) = floor_offsets([f1, f2])
    assert d0 == (0.0, 0.0)
    assert d1 == pytest.approx((-1234.567, 345.678), abs=0.03)


def test_floor_grids_line_up_floors_drawn_with_different_origins():
    from algorithms.rasterize import floor_grids, shift_geometries

    f1 = _irregular_floor()
    f2 = shift_geometries(f1, 500.0, 200.0)
    f3 = f1[:-1]  # same frame, no stair core
    grids, offs = floor_grids([f1, f2, f3], resolution=0.05)
    assert {g.shape for g in grids} == {grids[0].shape}
    assert offs[1] == pytest.approx((-500.0, -200.0), abs=1e-9) and offs[2] == (0.0, 0.0)
    assert np.array_equal(grids[0].data, grids[1].data)  # pixel for pixel
    assert grids[1].origin_x == pytest.approx(grids[0].origin_x + 500.0)
    # the stair core is at the same pixels on floors 1 and 3, and only there
    c, r = grids[0].world_to_pixel(20.0, 15.0)
    assert grids[0].data[int(r), int(c)] == OCCUPIED and grids[2].data[int(r), int(c)] == FREE
    assert np.array_equal(grids[0].data[:, :int(c) - 10], grids[2].data[:, :int(c) - 10])
