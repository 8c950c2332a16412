"""Two room names in one space split along a partition wall drawn on a layer no rule names (issue 9).

SIST-F3.dwg: the wall between 弱电间 and 强电间 (two closets, each with its own door GFM甲1022) is drawn as two
parallel faces 0.13 m apart on the CAD repair layer 'E1-RI-3F$0$AUDIT_D_131110141545-10'; no layer rule names
it, so the raster has no wall there and both names share one area. ``cad_classify.stray_wall_partitions``
finds such face pairs; ``semantics.assign_names`` splits the area along one only where room names lie on both
sides, with no passage across it when both rooms keep a door. Small drawings built with ezdxf."""
import ezdxf
import numpy as np

from algorithms import pipeline
from algorithms import semantics as S
from algorithms.cad_import import import_dxf


def _drawing(tmp_path, wall_layer="AUDIT_D_131110141545-10", names=("ufficio", "magazzino"), extra=None):
    """A 8 x 4 m space (walls on MURI) with a door on each half onto a corridor south of it; the partition at
    x 4 (faces x 3.94 / 4.06) on ``wall_layer`` (None: not drawn)."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    wall = {"layer": "MURI"}
    msp.add_lwpolyline([(-0.2, -2.7), (8.2, -2.7), (8.2, 4.2), (-0.2, 4.2)], close=True, dxfattribs=wall)
    msp.add_lwpolyline([(0, 0.1), (0, 4), (8, 4), (8, 0.1)], dxfattribs=wall)  # the space's inner faces
    msp.add_lwpolyline([(0, -0.1), (0, -2.5), (8, -2.5), (8, -0.1)], dxfattribs=wall)  # the corridor's
    for y in (0.1, -0.1):  # the wall between them, with a 0.9 m doorway into each half
        for a, b in ((0, 1.5), (2.4, 5.5), (6.4, 8)):
            msp.add_line((a, y), (b, y), dxfattribs=wall)
    for x in (1.5, 2.4, 5.5, 6.4):
        msp.add_line((x, -0.1), (x, 0.1), dxfattribs=wall)
    if wall_layer:
        msp.add_line((3.94, 0.1), (3.94, 4.0), dxfattribs={"layer": wall_layer})
        msp.add_line((4.06, 0.1), (4.06, 4.0), dxfattribs={"layer": wall_layer})
    if extra is not None:
        extra(msp)
    msp.add_text(names[0], dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (1.5, 2.0)})
    msp.add_text(names[1], dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (5.5, 2.0)})
    msp.add_text("corridoio", dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (3.5, -1.3)})
    p = tmp_path / "stray.dxf"
    doc.saveas(p)
    return str(p)


def test_face_pair_on_an_unnamed_layer_is_found_and_never_a_wall(tmp_path):
    d = import_dxf(_drawing(tmp_path))
    walls = [g for g in d.partitions if g.cls == "wall pair"]
    assert len(walls) == 1
    (x0, y0), (x1, y1) = walls[0].coords
    assert abs(x0 - 4.0) < 1e-6 and abs(x1 - 4.0) < 1e-6 and abs(abs(y1 - y0) - 3.9) < 1e-6
    assert not any(g.layer.startswith("AUDIT") for g in d.geometries)  # the raster still does not have it
    # on an excluded layer (furniture, text) or a wall layer (a real wall then) there is no stray wall
    assert not [g for g in import_dxf(_drawing(tmp_path, wall_layer="ARREDI")).partitions if g.cls == "wall pair"]
    assert not [g for g in import_dxf(_drawing(tmp_path, wall_layer=None)).partitions if g.cls == "wall pair"]


def test_stray_wall_splits_the_two_names_without_a_passage_across(tmp_path):
    floor = pipeline.process_floor(_drawing(tmp_path))
    areas = {a.name: a for a in floor.refined.areas}
    a, b = areas.get("ufficio"), areas.get("magazzino")
    assert a is not None and b is not None and a.id != b.id
    assert a.polygon.bounds[2] < 4.2 and b.polygon.bounds[0] > 3.8
    assert not any({p.from_id, p.to_id} == {a.id, b.id} for p in floor.refined.passages)  # a wall, no door
    corridor = areas["corridoio"]
    for room in (a, b):  # each keeps its own door
        assert any({p.from_id, p.to_id} == {room.id, corridor.id} for p in floor.refined.passages)
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    assert fig["conflicts"] == 0 and fig["own_area_pct"] == 100.0


def test_without_the_stray_wall_the_two_names_stay_a_conflict(tmp_path):
    floor = pipeline.process_floor(_drawing(tmp_path, wall_layer=None))
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    assert fig["conflicts"] == 1


def test_treads_and_racks_are_no_stray_walls(tmp_path):
    def treads(msp):  # a flight's treads from wall to wall, 0.28 m apart: a series, not the two faces of a wall
        for k in range(5):
            msp.add_line((6.0 + 0.28 * k, 0.1), (6.0 + 0.28 * k, 4.0), dxfattribs={"layer": "comunication"})

    def rack(msp):  # a free-standing rack drawn as two faces 0.1 m apart, touching no wall
        msp.add_line((5.0, 1.5), (7.0, 1.5), dxfattribs={"layer": "eq"})
        msp.add_line((5.0, 1.6), (7.0, 1.6), dxfattribs={"layer": "eq"})

    for extra in (treads, rack):
        d = import_dxf(_drawing(tmp_path, wall_layer=None, extra=extra))
        assert not [g for g in d.partitions if g.cls == "wall pair"], extra.__name__
