"""Free-standing furniture drawn in pieces on the wall layer (``cad_classify.furniture_groups``).

Spaghetti drawings put chairs and tables on layer "0" with the walls, each chair drawn as dozens of arcs
(kindergarten-1's round dining hall: 130 chairs of ~53 elliptic arcs and polylines each). No piece is a
closed outline, so ``_free_furniture`` does not see them, and the hall split into a dozen areas along the rows
of chairs. A group of touching pieces that touches nothing else, is furniture-sized, holds a curve or many
strokes and no wall-thick pair is furniture; columns (a square with its diagonals, a hatched square), a chair
against a wall and a wall stub stay. Small drawings built with ezdxf."""
import math

import ezdxf
import numpy as np
import pytest

from algorithms import cad_classify, pipeline
from algorithms.cad_import import import_dxf

HALL = (0.0, 0.0, 16.0, 10.0)  # inner faces of the hall (metres)


def _chair(msp, x, y, layer="0", pieces=12):
    """A 0.5 m chair drawn as ``pieces`` short arcs around its seat and a back rest (touching each other)."""
    for k in range(pieces):
        a0, a1 = 360.0 * k / pieces, 360.0 * (k + 1) / pieces
        msp.add_arc((x, y), 0.22, a0, a1, dxfattribs={"layer": layer})
    msp.add_line((x - 0.25, y + 0.22), (x + 0.25, y + 0.22), dxfattribs={"layer": layer})


def _table_set(msp, x, y, layer="0"):
    """A 1.2 x 0.7 m table drawn in straight strokes (outline and a border inset) with two chairs touching it."""
    w, h = 0.6, 0.35
    for (a, b) in (((-w, -h), (w, -h)), ((w, -h), (w, h)), ((w, h), (-w, h)), ((-w, h), (-w, -h))):
        msp.add_line((x + a[0], y + a[1]), (x + b[0], y + b[1]), dxfattribs={"layer": layer})
    for dx in (-0.3, 0.3):  # the chairs' seats touch the table's long sides
        msp.add_circle((x + dx, y + h + 0.2), 0.2, dxfattribs={"layer": layer})
        msp.add_circle((x + dx, y - h - 0.2), 0.2, dxfattribs={"layer": layer})


def _hall(tmp_path, furnish=True, extra=None, name="hall.dxf"):
    """A 16 x 10 m hall with a 1 m door into a 5 x 10 m side room, walls as two faces 0.2 m apart, everything on
    layer "0" (a spaghetti drawing); ``furnish``: five rows of eleven chairs and a band of five table sets."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    L = {"layer": "0"}
    x0, y0, x1, y1 = HALL
    t = 0.2
    # the door: both faces of the dividing wall open between y 4.5 and 5.5 (jamb caps across the wall)
    msp.add_lwpolyline([(x0 - t, y0 - t), (x1 + 5 + 2 * t, y0 - t), (x1 + 5 + 2 * t, y1 + t), (x0 - t, y1 + t)],
                       close=True, dxfattribs=L)
    msp.add_lwpolyline([(x1, 4.5), (x1, y0), (x0, y0), (x0, y1), (x1, y1), (x1, 5.5)], dxfattribs=L)
    msp.add_lwpolyline([(x1 + t, 4.5), (x1 + t, y0), (x1 + 5 + t, y0), (x1 + 5 + t, y1), (x1 + t, y1),
                        (x1 + t, 5.5)], dxfattribs=L)
    msp.add_line((x1, 4.5), (x1 + t, 4.5), dxfattribs=L)
    msp.add_line((x1, 5.5), (x1 + t, 5.5), dxfattribs=L)
    if furnish:
        for row in range(5):
            yy = 1.2 + 1.5 * row
            for col in range(11):
                _chair(msp, 1.3 + 1.2 * col, yy)
        for col in range(5):  # a band of table sets along the north wall
            _table_set(msp, 2.5 + 2.6 * col, 8.9)
    if extra is not None:
        extra(msp)
    p = tmp_path / name
    doc.saveas(p)
    return str(p)


def _classes_near(d, x, y, r=0.6):
    return {g.cls for g in d.geometries if np.hypot(*(g.coords.mean(axis=0) - (x, y))) < r}


def test_chairs_drawn_as_arcs_and_tables_in_strokes_are_furniture(tmp_path):
    d = import_dxf(_hall(tmp_path))
    assert d.classes.get("furniture", 0) == 55 * 13 + 5 * 8
    kept = [g for g in d.geometries if HALL[0] + 0.3 < g.coords[:, 0].min() and g.coords[:, 0].max() < HALL[2] - 0.3
            and HALL[1] + 0.3 < g.coords[:, 1].min() and g.coords[:, 1].max() < HALL[3] - 0.3]
    assert not kept  # nothing of the furniture reaches the raster
    cad_classify.FURNITURE_GROUPS = False
    try:
        d_off = import_dxf(_hall(tmp_path, name="off.dxf"))
    finally:
        cad_classify.FURNITURE_GROUPS = True
    assert d_off.classes.get("furniture", 0) < 100  # the switch: the old behaviour


def test_columns_a_chair_against_the_wall_and_a_wall_stub_stay(tmp_path):
    def extra(msp):
        L = {"layer": "0"}
        # a 0.6 m column: square with its diagonals (six straight strokes, no curve)
        sq = [(3, 8), (3.6, 8), (3.6, 8.6), (3, 8.6)]
        for a, b in zip(sq, sq[1:] + sq[:1]):
            msp.add_line(a, b, dxfattribs=L)
        msp.add_line(sq[0], sq[2], dxfattribs=L)
        msp.add_line(sq[1], sq[3], dxfattribs=L)
        # a round column hatched solid
        msp.add_circle((7, 8.3), 0.3, dxfattribs=L)
        h = msp.add_hatch(dxfattribs=L)
        h.set_solid_fill()
        h.paths.add_edge_path().add_arc((7, 8.3), 0.3, 0, 360)
        # a chair whose back touches the north wall's inner face
        _chair(msp, 11.0, 10.0 - 0.22)
        # a free wall stub: two faces 0.15 m apart, 2 m long, in eight strokes (no curve)
        for yy in (7.0, 7.15):
            for k in range(4):
                msp.add_line((12 + 0.5 * k, yy), (12 + 0.5 * (k + 1), yy), dxfattribs=L)

    d = import_dxf(_hall(tmp_path, furnish=False, extra=extra))
    assert "furniture" not in _classes_near(d, 3.3, 8.3)
    assert _classes_near(d, 3.3, 8.3)  # the column square is kept
    assert any(g.filled for g in d.geometries if np.hypot(*(g.coords.mean(axis=0) - (7, 8.3))) < 0.4)
    assert _classes_near(d, 11.0, 9.8) and "furniture" not in _classes_near(d, 11.0, 9.8)
    assert _classes_near(d, 13.0, 7.07) and "furniture" not in _classes_near(d, 13.0, 7.07)


def test_a_furnished_hall_is_one_area(tmp_path):
    """The end-to-end effect: the furnished hall converts to the same areas as the empty one."""
    def hall_areas(path):
        floor = pipeline.process_floor(path, names=False)
        inside = [a for a in floor.refined.areas
                  if a.polygon.intersection(_box(HALL)).area > 0.05 * a.polygon.area]
        return sorted(inside, key=lambda a: -a.polygon.area)

    furnished = hall_areas(_hall(tmp_path))
    empty = hall_areas(_hall(tmp_path, furnish=False, name="empty.dxf"))
    assert len(furnished) == len(empty) == 1
    assert furnished[0].polygon.area == pytest.approx(empty[0].polygon.area, rel=0.02)
    cad_classify.FURNITURE_GROUPS = False
    try:
        off = hall_areas(_hall(tmp_path, name="off.dxf"))
    finally:
        cad_classify.FURNITURE_GROUPS = True
    assert len(off) >= 2 or off[0].polygon.area < 0.9 * empty[0].polygon.area  # what the rule mends


def _box(b):
    from shapely.geometry import box

    return box(*b)


def test_turned_table_set_is_judged_by_its_oriented_box(tmp_path):
    """Orientation-free: a 2 m square table set turned 45 degrees has an axis-aligned box of 2.8 m (larger than
    any furniture) but is 2 x 2 m: furniture."""
    c, s = math.cos(math.radians(45)), math.sin(math.radians(45))

    def rot(px, py):
        return (8 + c * px - s * py, 5 + s * px + c * py)

    def extra(msp):
        corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
        for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1]):
            for k in range(2):  # each side in two strokes
                p0 = (ax + (bx - ax) * k / 2, ay + (by - ay) * k / 2)
                p1 = (ax + (bx - ax) * (k + 1) / 2, ay + (by - ay) * (k + 1) / 2)
                msp.add_line(rot(*p0), rot(*p1), dxfattribs={"layer": "0"})
        msp.add_circle(rot(0, 0), 1.0, dxfattribs={"layer": "0"})  # the round top touches the sides' middles

    d = import_dxf(_hall(tmp_path, furnish=False, extra=extra))
    assert d.classes.get("furniture", 0) >= 9
    assert not [g for g in d.geometries if np.hypot(*(g.coords.mean(axis=0) - (8, 5))) < 1.6]
