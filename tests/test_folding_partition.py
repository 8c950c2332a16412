"""Two room names in one room split along a folding partition (issue 9, 'what the paper leaves open').

A folding (accordion) partition drawn folded at both ends of its track (schema-ufficio-1: the two general
secretaries' 25.6 m2 room, zig-zags at x 325 on the furniture layer) is a wall that opens: the room is split
along its track and the two rooms get a passage along it. Small drawings built with ezdxf."""
import math

import ezdxf
import pytest
import numpy as np

from algorithms import pipeline
from algorithms import semantics as S
from algorithms.cad_import import import_dxf


def _doc():
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6  # metres
    return doc


def _room(msp):
    """An 8 x 4 m room (walls 0.2 m, two faces each) with a 0.9 m door in its south wall on each half; a
    corridor south of it (y -2.5..0) closed at both ends, so the floor is connected through the doors."""
    for pts in ([(-0.2, -2.7), (8.2, -2.7), (8.2, 4.2), (-0.2, 4.2)], [(0, 0.1), (8, 0.1), (8, 4), (0, 4)],
                [(0, -2.5), (8, -2.5), (8, -0.1), (0, -0.1)]):
        msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "MURI"})
    for x in (1.5, 5.5):  # door openings: break the corridor wall's two faces
        msp.add_line((x, -0.1), (x, 0.1), dxfattribs={"layer": "MURI"})
        msp.add_line((x + 0.9, -0.1), (x + 0.9, 0.1), dxfattribs={"layer": "MURI"})


def _stack(msp, x, y, down, layer="ARREDI"):
    """A folded stack of two 0.6 m leaves hinged at the track end (x, y): a V opening away from the wall."""
    s = -1.0 if down else 1.0
    a = math.radians(20.0)
    apex = (x - 0.6 * math.cos(a), y + s * 0.6 * math.sin(a))
    end = (apex[0] + 0.6 * math.cos(math.radians(45.0)), apex[1] - s * 0.6 * math.sin(math.radians(45.0)))
    msp.add_lwpolyline([(x, y), apex], dxfattribs={"layer": layer})
    msp.add_lwpolyline([apex, end], dxfattribs={"layer": layer})
    # the track's stub from the wall to the stack (thin, two faces)
    wy = 4.0 if not down else 0.1
    msp.add_lwpolyline([(x, wy), (x, y), (x + 0.04, y), (x + 0.04, wy)], dxfattribs={"layer": layer})


def _names(msp, left="segreteria A", right="segreteria B"):
    msp.add_text(left, dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (1.5, 2.0)})
    msp.add_text(right, dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (5.5, 2.0)})
    msp.add_text("corridoio", dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (3.5, -1.3)})


def _drawing(tmp_path, partition=True, across=False):
    doc = _doc()
    msp = doc.modelspace()
    _room(msp)
    if partition:
        _stack(msp, 4.0, 3.4, down=False)  # stacked at the north wall
        _stack(msp, 4.0, 0.7, down=True)  # and at the south wall: the track x = 4 between them is open
    if across:  # a shelf drawn across the track: no open track, no partition
        msp.add_line((3.0, 2.2), (5.0, 2.2), dxfattribs={"layer": "ARREDI"})
    _names(msp)
    p = tmp_path / "fold.dxf"
    doc.saveas(p)
    return str(p)


def test_folding_partition_found_on_any_layer(tmp_path):
    d = import_dxf(_drawing(tmp_path))
    assert len(d.partitions) == 1 and d.classes.get("folding partition") == 1
    (x0, y0), (x1, y1) = d.partitions[0].coords
    assert abs(x0 - x1) < 0.1 and 3.3 < (x0 + x1) / 2 < 4.1 and abs(y0 - y1) > 2.0  # the track at x 4, N-S
    # the furniture layer is still left out of the walls
    assert not any(g.layer == "ARREDI" for g in d.geometries)


def test_no_partition_without_both_stacks_or_across_a_shelf(tmp_path):
    assert import_dxf(_drawing(tmp_path, partition=False)).partitions == []
    assert import_dxf(_drawing(tmp_path, across=True)).partitions == []


def test_folding_partition_splits_the_two_names_with_a_passage(tmp_path):
    floor = pipeline.process_floor(_drawing(tmp_path))
    areas = {a.name: a for a in floor.refined.areas}
    a, b = areas.get("segreteria A"), areas.get("segreteria B")
    assert a is not None and b is not None and a.id != b.id
    assert a.polygon.centroid.x < 4.1 < b.polygon.centroid.x
    assert 12.0 < a.polygon.area < 20.0 and 12.0 < b.polygon.area < 20.0
    assert any({p.from_id, p.to_id} == {a.id, b.id} for p in floor.refined.passages)
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    assert fig["conflicts"] == 0 and fig["own_area_pct"] == 100.0


def test_without_the_partition_the_two_names_stay_a_conflict(tmp_path):
    floor = pipeline.process_floor(_drawing(tmp_path, partition=False))
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    assert fig["conflicts"] == 1


@pytest.mark.slow
@pytest.mark.qgis_process
def test_dxftoosmag_headless_splits_at_the_partition(tmp_path):
    """dxftoosmag headless on the drawing: the two secretaries are two areas joined by a passage in the osmAG."""
    from algorithms import osmag

    from .qgis_process import run_alg

    out = tmp_path / "fold.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": _drawing(tmp_path), "OUTPUT": str(out),
                                         "ANCHOR": "121.59,31.179 [EPSG:4326]"})
    areas, passages, _, _ = osmag.read_osmag(str(out))
    by_name = {a.name: a for a in areas}
    assert {"segreteria A", "segreteria B", "corridoio"} <= set(by_name), sorted(by_name)
    a, b = by_name["segreteria A"], by_name["segreteria B"]
    assert any({p.from_id, p.to_id} == {a.id, b.id} for p in passages)
