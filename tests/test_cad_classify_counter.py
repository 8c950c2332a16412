"""Two room names in one space split along a counter that closes it (issue 9, 'what the paper leaves open').

A bar or reception counter standing wall to wall (schema-ufficio-1: the 'wine & water bar' behind the
'bancone refrigerato per esposizione vini', which runs from the bar's north wall to the jamb of its service
door) closes the service space behind it from the room in front; furniture is never a wall in the raster, so
segmentation joins both sides. Where two room names share that space it is split along the counter
(``cad_classify.counter_partitions`` -> ``CadDrawing.partitions`` -> ``semantics.assign_names``), the pieces
joined by a passage along it, as a folding partition. Small drawings built with ezdxf."""
import ezdxf
import numpy as np
import pytest

from algorithms import pipeline
from algorithms import semantics as S
from algorithms.cad_classify import counter_partitions
from algorithms.cad_import import import_dxf
from algorithms.model import CadGeometry


def _doc():
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6  # metres
    return doc


def _room(msp):
    """An 8 x 4 m room (walls 0.2 m, two faces each) with a 0.9 m door in its south wall on each side of x 2.8;
    a corridor south of it (y -2.5..0) closed at both ends, so the floor is connected through the doors."""
    for pts in ([(-0.2, -2.7), (8.2, -2.7), (8.2, 4.2), (-0.2, 4.2)], [(0, 0.1), (8, 0.1), (8, 4), (0, 4)],
                [(0, -2.5), (8, -2.5), (8, -0.1), (0, -0.1)]):
        msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "MURI"})
    for x in (1.0, 5.5):  # door openings: break the corridor wall's two faces
        msp.add_line((x, -0.1), (x, 0.1), dxfattribs={"layer": "MURI"})
        msp.add_line((x + 0.9, -0.1), (x + 0.9, 0.1), dxfattribs={"layer": "MURI"})


def _counter(msp, layer="ARREDI attrezzature"):
    """A 0.6 m deep counter from the north wall face to the south one at x 2.5..3.1, with a stool row in front."""
    msp.add_lwpolyline([(2.5, 4.0), (3.1, 4.0), (3.1, 0.1), (2.5, 0.1)], close=True, dxfattribs={"layer": layer})
    for y in (1.0, 2.0, 3.0):
        msp.add_circle((3.5, y), 0.18, dxfattribs={"layer": layer})


def _drawing(tmp_path, counter=True, **kw):
    doc = _doc()
    msp = doc.modelspace()
    _room(msp)
    if counter:
        _counter(msp, **kw)
    msp.add_text("wine bar", dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (0.6, 2.0)})
    msp.add_text("sala clienti", dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (5.5, 2.0)})
    msp.add_text("corridoio", dxfattribs={"layer": "SCRITTE", "height": 0.2, "insert": (3.5, -1.3)})
    p = tmp_path / "bar.dxf"
    doc.saveas(p)
    return str(p)


def _walls():
    """The wall faces of a 6 x 4 m room as geometry (metres)."""
    return [CadGeometry(layer="W", kind="wall", coords=np.array([(0, 0), (6, 0), (6, 4), (0, 4)], float), closed=True)]


def test_counter_from_wall_to_wall_is_found():
    rect = np.array([(2.0, 4.0), (2.6, 4.0), (2.6, 0.0), (2.0, 0.0), (2.0, 4.0)])
    (g,) = counter_partitions([rect], _walls())
    (x0, y0), (x1, y1) = g.coords
    assert g.cls == "counter" and g.kind == "partition"
    assert abs(x0 - 2.3) < 1e-6 and abs(x1 - 2.3) < 1e-6 and {round(y0, 6), round(y1, 6)} == {0.0, 4.0}
    # drawn as loose lines touching end to end (a chamfered bar counter), 5 cm short of the south wall
    lines = [np.array(s) for s in ([(2.0, 4.0), (2.0, 0.05)], [(2.0, 0.05), (2.5, 0.4)], [(2.5, 0.4), (2.5, 3.6)],
                                   [(2.5, 3.6), (2.0, 4.0)])]
    (g,) = counter_partitions(lines, _walls())
    assert abs(np.hypot(*(g.coords[1] - g.coords[0])) - 3.95) < 0.05


def test_furniture_that_closes_nothing_is_no_counter():
    table = np.array([(2.0, 1.0), (3.5, 1.0), (3.5, 2.0), (2.0, 2.0), (2.0, 1.0)])  # free-standing
    desk = np.array([(0.0, 1.0), (1.6, 1.0), (1.6, 1.8), (0.0, 1.8), (0.0, 1.0)])  # against one wall
    # a kitchen run along two walls in a corner: its ends are on the walls, but it does not run between them
    worktop_l = np.array([(0.0, 1.0), (0.6, 1.0), (0.6, 3.4), (3.0, 3.4), (3.0, 4.0), (0.0, 4.0), (0.0, 1.0)])
    short = np.array([(2.0, 4.0), (2.6, 4.0), (2.6, 3.3), (2.0, 3.3), (2.0, 4.0)])  # a cabinet against the wall
    assert counter_partitions([table, desk, worktop_l, short], _walls()) == []
    # a counter line through a wall (two rooms) is none either
    walls = _walls() + [CadGeometry(layer="W", kind="wall", coords=np.array([(0, 2.0), (6, 2.0)], float))]
    rect = np.array([(2.0, 4.0), (2.6, 4.0), (2.6, 0.0), (2.0, 0.0), (2.0, 4.0)])
    assert counter_partitions([rect], walls) == []  # its ends are on the outer walls, its middle crosses a wall


def test_counter_found_on_the_furniture_layer_only(tmp_path):
    d = import_dxf(_drawing(tmp_path))
    assert [g.cls for g in d.partitions] == ["counter"]
    (x0, y0), (x1, y1) = d.partitions[0].coords
    assert abs(x0 - 2.8) < 0.05 and abs(x1 - 2.8) < 0.05 and abs(y0 - y1) > 3.5
    assert not any(g.layer.startswith("ARREDI") for g in d.geometries)  # still never a wall
    # the same outline on a layer no rule calls furniture says nothing
    assert import_dxf(_drawing(tmp_path, layer="BANCONE")).partitions == []


def test_counter_splits_the_two_names_with_a_passage(tmp_path):
    floor = pipeline.process_floor(_drawing(tmp_path))
    areas = {a.name: a for a in floor.refined.areas}
    bar, lounge = areas.get("wine bar"), areas.get("sala clienti")
    assert bar is not None and lounge is not None and bar.id != lounge.id
    assert bar.polygon.bounds[2] < 3.2 and lounge.polygon.bounds[0] > 2.4  # cut along the counter
    assert 8.0 < bar.polygon.area < 13.0 and 18.0 < lounge.polygon.area < 24.0
    assert any({p.from_id, p.to_id} == {bar.id, lounge.id} for p in floor.refined.passages)
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    assert fig["conflicts"] == 0 and fig["own_area_pct"] == 100.0


def test_without_the_counter_the_two_names_stay_a_conflict(tmp_path):
    floor = pipeline.process_floor(_drawing(tmp_path, counter=False))
    fig = S.floor_figures(floor.refined.areas, floor.refined.passages, floor.names)
    assert fig["conflicts"] == 1


@pytest.mark.slow
@pytest.mark.qgis_process
def test_dxftoosmag_headless_splits_at_the_counter(tmp_path):
    """dxftoosmag headless on the drawing: the bar and the lounge are two areas joined by a passage."""
    from algorithms import osmag

    from .qgis_process import run_alg

    out = tmp_path / "bar.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": _drawing(tmp_path), "OUTPUT": str(out),
                                         "ANCHOR": "121.59,31.179 [EPSG:4326]"})
    areas, passages, _, _ = osmag.read_osmag(str(out))
    by_name = {a.name: a for a in areas}
    assert {"wine bar", "sala clienti", "corridoio"} <= set(by_name), sorted(by_name)
    a, b = by_name["wine bar"], by_name["sala clienti"]
    assert any({p.from_id, p.to_id} == {a.id, b.id} for p in passages)
