"""Connected floors: doorways drawn in ways that closed them (issue 8, item 6), one rule per kind of drawing.

Each test builds the small drawing the rule is about with ezdxf and checks the door hint and, through the
whole floor pipeline, that the floor's area graph is one connected component."""
import math

import ezdxf
import numpy as np
import pytest

from algorithms import pipeline
from algorithms.cad_classify import _circle_from_3, _leaf_and_arc
from algorithms.cad_import import import_dxf
from algorithms.errors import InputError


def _doc():
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6  # metres
    return doc


def _two_rooms(msp, layer="A-WALL"):
    """Two 6 x 6 m rooms; the partition between them (x = 6) is drawn straight through the doorway."""
    msp.add_lwpolyline([(0, 0), (12, 0), (12, 6), (0, 6)], close=True, dxfattribs={"layer": layer})
    msp.add_line((6, 0), (6, 6), dxfattribs={"layer": layer})


def _pline_door(msp, layer="A-DOOR", hinge=(6.0, 2.0), r=0.9, reverse=False):
    """A door swing drawn as ONE open polyline: hinge -> open leaf's end -> quarter arc (bulge) -> closed end."""
    hx, hy = hinge
    pts = [(hx, hy, 0.0), (hx - r, hy, -math.tan(math.radians(90) / 4)), (hx, hy + r, 0.0)]
    if reverse:  # the same door drawn from the closed end back to the hinge
        pts = [(hx, hy + r, math.tan(math.radians(90) / 4)), (hx - r, hy, 0.0), (hx, hy, 0.0)]
    msp.add_lwpolyline(pts, format="xyb", dxfattribs={"layer": layer})


def _save(doc, tmp_path, name="t.dxf"):
    p = tmp_path / name
    doc.saveas(p)
    return str(p)


@pytest.mark.parametrize("ox, oy", [(0.0, 0.0), (1.2e4, -6.4e3), (5e5, 3.5e6), (5e5, 9.5e6)])
def test_swing_circle_in_georeferenced_coordinates(ox, oy):
    """The three-point circle of a door swing (a 0.9 m leaf) in site or UTM coordinates (southern northings
    near 10^7 m): the squares of the coordinates cancel in float64 (r came out 0.98 m at 10^7, beyond the
    swing test's 2 cm), so the circle is computed again relative to the first point where it is off."""
    pts = [(ox + 0.9 * math.cos(t), oy + 0.9 * math.sin(t)) for t in np.radians([0.0, 45.0, 90.0])]
    cx, cy, r = _circle_from_3(*pts)
    assert abs(r - 0.9) < 1e-6 and abs(cx - ox) < 1e-6 and abs(cy - oy) < 1e-6
    assert _circle_from_3((ox, oy), (ox + 1.0, oy), (ox + 2.0, oy)) is None  # on a line


def test_leaf_and_arc_polyline_shape():
    hinge = np.array([6.0, 2.0])
    ang = np.radians(np.linspace(180, 90, 12))
    arc = np.c_[6.0 + 0.9 * np.cos(ang), 2.0 + 0.9 * np.sin(ang)]
    c = np.vstack([hinge, arc])
    cx, cy, end = _leaf_and_arc(c)
    assert (cx, cy) == (6.0, 2.0) and np.allclose(end, (6.0, 2.9), atol=1e-6)
    back = _leaf_and_arc(c[::-1])
    assert back is not None and np.allclose(back[2], (6.0, 2.9), atol=1e-6)
    # a wall polyline with a rounded corner: its first vertex is not the arc's centre
    corner = np.vstack([[0.0, 0.0], [5.1, 2.0] + 0 * arc[0], arc])
    assert _leaf_and_arc(corner) is None
    # a half circle is no door swing (sweep 180 degrees), nor is a leaf longer than the radius
    half = np.vstack([hinge, np.c_[6.0 + 0.9 * np.cos(np.radians(np.linspace(180, 0, 20))),
                                   2.0 + 0.9 * np.sin(np.radians(np.linspace(180, 0, 20)))]])
    assert _leaf_and_arc(half) is None
    assert _leaf_and_arc(np.vstack([[6.0, 0.5], arc])) is None


def test_pline_door_swing_becomes_a_hint_and_keeps_the_floor_connected(tmp_path):
    doc = _doc()
    msp = doc.modelspace()
    _two_rooms(msp)
    _pline_door(msp)
    _pline_door(msp, hinge=(6.0, 4.0), reverse=True)  # a second door, drawn backwards
    path = _save(doc, tmp_path)
    d = import_dxf(path)
    assert len(d.doors) == 2
    ends = sorted(tuple(np.round(p, 2)) for h in d.doors for p in ((h.x0, h.y0), (h.x1, h.y1)))
    assert ends == [(6.0, 2.0), (6.0, 2.9), (6.0, 4.0), (6.0, 4.9)]
    assert not any(g.layer == "A-DOOR" for g in d.geometries)  # the swings are left out
    floor = pipeline.process_floor(path, names=False)
    rooms = [a for a in floor.refined.areas if a.polygon.area > 20]
    assert len(rooms) == 2, [round(a.polygon.area, 1) for a in floor.refined.areas]
    assert floor.stats["components"] == 1
    assert floor.stats["largest_component_share"] == 1.0


def test_without_the_door_the_partition_closes_the_rooms(tmp_path):
    """The control: the same partition with no door keeps two components (the rule adds nothing else)."""
    doc = _doc()
    _two_rooms(doc.modelspace())
    floor = pipeline.process_floor(_save(doc, tmp_path), names=False)
    assert floor.stats["components"] == 2


def _rect(msp, x0, y0, x1, y1, layer="A-WALL"):
    """Four lines (a closed rectangle standing free around everything would be taken for a sheet frame)."""
    for a, b in (((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))):
        msp.add_line(a, b, dxfattribs={"layer": layer})


def _closed_spaces_plan(tmp_path):
    """A thick outer wall drawn as two lines (its inside is a closed 0.9 m cavity), a hall and a room joined
    by a doorway, a shaft labelled 管井 and an office whose door the drawing forgot."""
    doc = _doc()
    msp = doc.modelspace()
    _rect(msp, 0, 0, 24, 12)
    _rect(msp, 0.9, 0.9, 23.1, 11.1)  # the wall's inner face: the cavity between is 0.9 m wide
    msp.add_line((12, 0.9), (12, 5.0), dxfattribs={"layer": "A-WALL"})  # partition, doorway 5.0-6.0
    msp.add_line((12, 6.0), (12, 11.1), dxfattribs={"layer": "A-WALL"})
    _rect(msp, 2, 8, 4.5, 10.5)  # the shaft, 2.5 x 2.5 m
    msp.add_text("管井", dxfattribs={"layer": "A-TEXT", "height": 0.3, "insert": (2.8, 9.2)})
    _rect(msp, 18, 7, 22, 10.5)  # the office with no door, 4 x 3.5 m
    msp.add_text("Office", dxfattribs={"layer": "A-TEXT", "height": 0.3, "insert": (19.0, 8.5)})
    msp.add_text("Hall", dxfattribs={"layer": "A-TEXT", "height": 0.3, "insert": (6.0, 4.0)})
    return _save(doc, tmp_path)


def test_closed_cavities_and_named_shafts_count_out_but_orphaned_rooms_do_not(tmp_path):
    """A thick outer wall drawn as two lines (its inside is a closed 0.9 m cavity), a shaft labelled 管井 and
    an office whose door the drawing forgot: the cavity and the shaft are spaces the drawing really closes
    (counted out of the connectivity figure, tagged), the office is an orphaned room (it counts)."""
    floor = pipeline.process_floor(_closed_spaces_plan(tmp_path))
    areas = {a.id: a for a in floor.refined.areas}
    closed = floor.stats["closed_spaces"]
    kinds = sorted(("shaft" if a.polygon.area < 8 else "cavity") for i, a in areas.items() if i in closed)
    assert kinds == ["cavity", "shaft"], [(i, round(a.polygon.area, 1)) for i, a in areas.items()]
    assert all(areas[i].tags.get("cad2osmag:closed") == "yes" for i in closed)
    office = [a for a in areas.values() if a.polygon.contains(__import__("shapely").Point(19.0, 8.5))]
    assert office and office[0].id not in closed and office[0].component != 0
    main = sum(a.polygon.area for a in areas.values() if a.component == 0)
    counted = sum(a.polygon.area for a in areas.values() if a.id not in closed)
    assert abs(floor.stats["largest_component_share"] - main / counted) < 1e-6
    assert floor.stats["largest_component_share"] < 1.0  # the office still counts against the figure


@pytest.mark.qgis_process
def test_dxftoosmag_headless_tags_closed_spaces_and_reports_components(tmp_path):
    from algorithms import osmag
    from tests.qgis_process import run_alg

    out = tmp_path / "closed.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": _closed_spaces_plan(tmp_path), "OUTPUT": str(out)})
    assert "closed space(s)" in log and "component" in log
    areas, passages, _, _ = osmag.read_osmag(str(out))
    closed = [a for a in areas if (a.tags or {}).get("cad2osmag:closed") == "yes"]
    assert len(closed) == 2
    assert any(a.name == "Office" for a in areas) and not any(a.name == "Office" for a in closed)


def test_half_circle_swing_on_an_unnamed_layer_with_its_leaf_on_a_window_layer(tmp_path):
    """Doors drawn opening flat against the wall (a 180 degree arc) whose arc lies on a layer no rule names
    ('fine projection lines') and whose leaf lies on a layer of doors *and* windows (kept as windows): the
    swing is found across layers, the leaf is left out and the doorway joins the two rooms."""
    doc = _doc()
    msp = doc.modelspace()
    _two_rooms(msp, layer="MURATURA sezioni - section wall")
    win = {"layer": "PORTE finestre - doors windows"}
    aux = {"layer": "PROIEZIONI finissime - fine lines"}
    # the doorway 2.0-3.0 in the partition x = 6; the wall is drawn through it, the door closes it
    msp.add_line((6.0, 3.0), (6.0, 4.0), dxfattribs=win)  # the open leaf, flat against the wall, hinge (6, 3)
    msp.add_arc((6.0, 3.0), 1.0, 90, 270, dxfattribs=aux)  # 180 degrees: from the open leaf to the closed end
    msp.add_arc((3.0, 5.0), 0.9, 0, 180, dxfattribs=aux)  # a half circle with no leaf: never a door
    path = _save(doc, tmp_path)
    d = import_dxf(path)
    assert len(d.doors) == 1
    h = d.doors[0]
    ends = sorted([(round(h.x0, 2), round(h.y0, 2)), (round(h.x1, 2), round(h.y1, 2))])
    assert ends == [(6.0, 2.0), (6.0, 3.0)]
    assert not any(g.layer == aux["layer"] for g in d.geometries)  # the unnamed layer stays out
    assert d.classes.get("door") == 2  # the arc and its open leaf
    floor = pipeline.process_floor(path, names=False)
    assert floor.stats["components"] == 1


def _double_wall_rooms(cavity=0.2, wall=0.25, door=True):
    """Two 5 x 4 m rooms separated by two walls side by side (a joint: ``wall`` thick each, ``cavity``
    between), each drawn as a closed outline with a doorway gap at y 1.5-2.5 in the west wall only; the
    door block's hint lies at the west wall's west face, as door blocks are inserted."""
    from algorithms.model import CadGeometry, DoorHint

    x0 = 5.0
    x1 = x0 + wall + cavity + wall
    outlines = [[(0, 0), (10.7, 0), (10.7, 4), (0, 4), (0, 0)],
                [(x0, 0), (x0 + wall, 0), (x0 + wall, 1.5), (x0, 1.5), (x0, 0)],
                [(x0, 2.5), (x0 + wall, 2.5), (x0 + wall, 4), (x0, 4), (x0, 2.5)],
                [(x1 - wall, 0), (x1, 0), (x1, 4), (x1 - wall, 4), (x1 - wall, 0)]]  # no gap drawn in the east wall
    geoms = [CadGeometry("A-WALL", "wall", np.array(c, float), closed=True) for c in outlines]
    return geoms, ([DoorHint(x0, 1.5, x0, 2.5, "block")] if door else [])


def test_door_hint_opens_a_double_wall_joint_through_to_the_room_beyond():
    from algorithms import rasterize as ras
    from algorithms import segmentation as seg

    geoms, hints = _double_wall_rooms()
    grid = ras.rasterize(geoms, resolution=0.05, extent=(-1, -1, 12, 5), door_hints=hints)
    for x in (5.0, 5.2, 5.35, 5.55, 5.65):  # the whole joint is open across the doorway
        c, r = grid.world_to_pixel(x, 2.0)
        assert grid.data[int(r), int(c)] == 0, x
    c, r = grid.world_to_pixel(5.5, 1.2)  # beside the doorway the walls stay
    assert grid.data[int(r), int(c)] != 0
    ag = seg.segment(grid, door_width=1.0, corridor_width=2.0, door_hints=hints)
    big = [a for a in ag.areas if a.polygon.area > 10]
    assert len(big) == 2 and ag.stats["components"] == 1


def test_door_hint_never_opens_more_than_a_wall_thickness():
    """A hint with no room within DOOR_MAX_WALL behind the wall (a solid 2 m block) clears no more than the
    default opening depth."""
    from algorithms import rasterize as ras
    from algorithms.model import CadGeometry, DoorHint

    block = CadGeometry("A-WALL", "wall", np.array([(5, 0), (7, 0), (7, 4), (5, 4), (5, 0)], float), closed=True,
                        filled=True)
    grid = ras.rasterize([block], resolution=0.05, extent=(-1, -1, 12, 5),
                         door_hints=[DoorHint(5.0, 1.5, 5.0, 2.5, "block")])
    c, r = grid.world_to_pixel(5.5, 2.0)
    assert grid.data[int(r), int(c)] != 0


def _flight_plan(tmp_path, treads=True):
    """Two rooms (10 x 3 m) joined only by a 2 m wide flight of seven treads drawn on the wall layer (a stair
    half a level between two parts of a floor)."""
    doc = _doc()
    msp = doc.modelspace()
    w = {"layer": "A-WALL"}
    msp.add_lwpolyline([(0, 0), (10, 0), (10, 8), (0, 8)], close=True, dxfattribs=w)
    for y in (3.0, 5.0):
        msp.add_line((0, y), (4, y), dxfattribs=w)
        msp.add_line((6, y), (10, y), dxfattribs=w)
    msp.add_line((4, 3), (4, 5), dxfattribs=w)  # the flight's sides
    msp.add_line((6, 3), (6, 5), dxfattribs=w)
    if treads:
        for k in range(7):
            msp.add_line((4, 3.1 + 0.3 * k), (6, 3.1 + 0.3 * k), dxfattribs=w)
    return _save(doc, tmp_path)


def test_stair_treads_on_a_wall_layer_are_a_way_through(tmp_path):
    path = _flight_plan(tmp_path)
    d = import_dxf(path)
    assert sum(g.kind == "stair" for g in d.geometries) == 7
    floor = pipeline.process_floor(path, names=False)
    assert floor.stats["components"] == 1
    rooms = [a for a in floor.refined.areas if a.polygon.area > 20]
    assert len(rooms) == 2


def test_curved_treads_are_stairs_and_lone_arcs_stay():
    from algorithms.cad_classify import free_stair_treads
    from algorithms.model import CadGeometry

    def arc(cx, cy, r, a0=200, a1=250):
        t = np.radians(np.linspace(a0, a1, 9))
        return CadGeometry("0", "reference", np.c_[cx + r * np.cos(t), cy + r * np.sin(t)], entity="ARC")

    geoms = [arc(0, 0, 1.0 + 0.3 * k) for k in range(5)] + [arc(20, 0, 1.0), arc(20, 0, 3.0), arc(40, 0, 2.0)]
    assert free_stair_treads(geoms) == 5
    assert [g.kind for g in geoms] == ["stair"] * 5 + ["reference"] * 3


# ------------------------------------------------------------------ corridors closed only by projection lines
def _corridor_plan(tmp_path, line="layer", depth=2.5, name="Corridoio distribuzione", name_file="c.dxf"):
    """Three 8 x 7 m classrooms in a row, each with a 1 m doorway in its north wall; north of them a corridor
    bounded by no wall: only a line ``depth`` m beyond the facade, drawn as ``line``: "layer" (a layer named
    for projections, continuous linetype), "entity" (dash-dot linetype on an unnamed layer), "continuous"
    (a plain line on an unnamed layer: no evidence), "axis" (a dash-dot line on a grid-axis layer) or None."""
    doc = ezdxf.new("R2010", setup=["linetypes"])
    doc.header["$INSUNITS"] = 6
    doc.layers.add("PROIEZIONI - projections")
    doc.layers.add("misc")
    doc.layers.add("S-GRID", linetype="CENTER")
    msp = doc.modelspace()
    wall = {"layer": "MURATURA"}
    msp.add_line((0, 0), (24, 0), dxfattribs=wall)
    msp.add_line((0, 0), (0, 7), dxfattribs=wall)
    msp.add_line((24, 0), (24, 7), dxfattribs=wall)
    for x in (8, 16):
        msp.add_line((x, 0), (x, 7), dxfattribs=wall)
    xs = [0, 3, 4, 11, 12, 19, 20, 24]  # north wall with doorways 3-4, 11-12, 19-20
    for a, b in zip(xs[0::2], xs[1::2]):
        msp.add_line((a, 7), (b, 7), dxfattribs=wall)
    for k, x in enumerate((4, 12, 20)):
        msp.add_text(f"Aula {k + 1}", dxfattribs={"layer": "SCRITTE", "height": 0.3, "insert": (x, 3.5)})
    if name:
        msp.add_text(name, dxfattribs={"layer": "SCRITTE", "height": 0.3, "insert": (10.0, 7 + depth / 2)})
    y = 7 + depth
    if line == "layer":
        msp.add_line((0, y), (24, y), dxfattribs={"layer": "PROIEZIONI - projections"})
    elif line == "entity":
        msp.add_line((0, y), (24, y), dxfattribs={"layer": "misc", "linetype": "DASHDOT"})
    elif line == "continuous":
        msp.add_line((0, y), (24, y), dxfattribs={"layer": "misc"})
    elif line == "axis":
        msp.add_line((0, y), (24, y), dxfattribs={"layer": "S-GRID"})
    return _save(doc, tmp_path, name_file)


def _corridor_area(floor, y):
    from shapely.geometry import Point

    return [a for a in floor.refined.areas if a.polygon.buffer(0.05).contains(Point(10.0, y))]


@pytest.mark.parametrize("line", ["layer", "entity"])
def test_corridor_closed_only_by_a_projection_line_is_inside(tmp_path, line):
    """A corridor bounded by walls on one side and by a projection line (a layer named for projections, or a
    dash-dot linetype) on the other is an area, and the classrooms open onto it: one component."""
    path = _corridor_plan(tmp_path, line)
    drawing = import_dxf(path)
    assert len(drawing.boundary) == 1 and drawing.boundary[0].kind == "boundary"
    assert not any(abs(g.coords[:, 1] - 9.5).max() < 1e-6 for g in drawing.geometries)  # never a wall
    floor = pipeline.process_floor(path)
    corridor = _corridor_area(floor, 8.25)
    assert corridor, [a.polygon.bounds for a in floor.refined.areas]
    minx, miny, maxx, maxy = corridor[0].polygon.bounds
    assert maxy <= 9.6 and maxx - minx > 20 and corridor[0].polygon.area > 0.8 * 24 * 2.5
    assert floor.stats["components"] == 1 and floor.stats["largest_component_share"] == 1.0
    assert floor.stats["passages"] >= 3
    # the line is not drawn into the raster: the row of the line is free between the rooms' ends
    from algorithms.segmentation import FREE

    c, r = floor.grid.world_to_pixel(np.array([6.0, 14.0]), np.array([9.5, 9.5]))
    assert (floor.grid.data[np.floor(r).astype(int), np.floor(c).astype(int)] == FREE).all()


def test_corridor_without_a_name_is_inside_through_its_doorways(tmp_path):
    floor = pipeline.process_floor(_corridor_plan(tmp_path, "entity", name=None))
    assert _corridor_area(floor, 8.25)
    assert floor.stats["components"] == 1


@pytest.mark.parametrize("line", [None, "continuous", "axis"])
def test_without_projection_evidence_the_corridor_stays_outside(tmp_path, line):
    """No line, a plain line on an unnamed layer, or a dash-dot grid axis: no boundary evidence, the strip
    is open to the outside and the three classrooms stay apart (the rule is what connects them)."""
    path = _corridor_plan(tmp_path, line)
    assert import_dxf(path).boundary == []
    floor = pipeline.process_floor(path)
    assert not _corridor_area(floor, 8.25)
    assert floor.stats["components"] == 3


def test_an_eave_line_close_to_the_facade_closes_nothing(tmp_path):
    """A dash-dot eave line 0.4 m beyond the facade, no name in the strip: too narrow to be a space, so it is
    no boundary (no strip area, the rooms stay as without it)."""
    floor = pipeline.process_floor(_corridor_plan(tmp_path, "entity", depth=0.4, name=None))
    assert floor.stats["segment"].get("boundary_px", 0) == 0
    assert not _corridor_area(floor, 7.2)
    assert floor.stats["components"] == 3


# ------------------------------------------------------------------ an elevation drawn close to the plan
def _plan_with_elevation(tmp_path, title="ELEVACION PRINCIPAL", gap=2.0, angle=0.0):
    """A 30 x 16 m plan of six rooms (titled 'PLANTA DE DISTRIBUCION') and, ``gap`` m below it (closer than
    the sheet gap), its main elevation: a facade outline with doors and windows, titled ``title`` under it;
    the whole sheet turned by ``angle`` degrees about the origin."""
    doc = _doc()
    msp = doc.modelspace()
    for i in range(3):
        for j in range(2):
            x0, y0 = 10.0 * i, 8.0 * j
            msp.add_line((x0, y0), (x0 + 4, y0), dxfattribs={"layer": "A-WALL"})
            msp.add_line((x0 + 5, y0), (x0 + 10, y0), dxfattribs={"layer": "A-WALL"})
            msp.add_line((x0 + 10, y0), (x0 + 10, y0 + 8), dxfattribs={"layer": "A-WALL"})
            msp.add_line((x0 + 10, y0 + 8), (x0, y0 + 8), dxfattribs={"layer": "A-WALL"})
            msp.add_line((x0, y0 + 8), (x0, y0), dxfattribs={"layer": "A-WALL"})
    msp.add_text("PLANTA DE DISTRIBUCION", dxfattribs={"layer": "TXT", "height": 0.5, "insert": (32.0, 0.5)})
    top = -gap
    base = top - 6.0
    _rect(msp, 4, base, 26, top)  # the facade
    for x in (6, 12, 18, 22):
        _rect(msp, x, base, x + 1.2, base + 2.4)  # doors
        _rect(msp, x, base + 3.5, x + 1.2, base + 5.0)  # windows
    msp.add_line((3, base), (27, base), dxfattribs={"layer": "A-WALL"})  # ground line
    if title:
        msp.add_text(title, dxfattribs={"layer": "TXT", "height": 0.6, "insert": (10.0, base - 1.2)})
    if angle:
        from ezdxf.math import Matrix44

        for e in msp:
            e.transform(Matrix44.z_rotate(math.radians(angle)))
    return _save(doc, tmp_path, "elev.dxf")


@pytest.mark.parametrize("title", ["ELEVACION PRINCIPAL", "SECTION A-A", "PROSPETTO SUD", "南立面图"])
def test_an_elevation_drawn_close_below_the_plan_is_a_group_of_its_own(tmp_path, title):
    drawing = import_dxf(_plan_with_elevation(tmp_path, title))
    sel = [p for p in drawing.plans if p.selected]
    assert len(sel) == 1 and sel[0].kind == "plan" and sel[0].title == "PLANTA DE DISTRIBUCION"
    assert sel[0].extent[1] >= -0.5  # the plan alone, not the elevation below it
    other = [p for p in drawing.plans if not p.selected]
    assert len(other) == 1 and other[0].kind == "detail" and other[0].title == title
    assert all(g.coords[:, 1].min() >= -0.5 for g in drawing.geometries)


@pytest.mark.parametrize("angle", [12.0, 30.0, -20.0, 45.0])
def test_an_elevation_beside_a_turned_plan_is_a_group_of_its_own(tmp_path, angle, monkeypatch):
    """A sheet drawn turned (a building in site or survey coordinates): the empty band between the plan and
    its elevation runs along the walls, not along the axes, and the boxes that decide which title is the
    plan's are the walls' boxes (cad_sheet.ALIGN_SHEET). Without the rule the elevation stays with the plan
    or takes its title (the sheet is then refused as 'only detail views')."""
    from algorithms import cad_sheet

    path = _plan_with_elevation(tmp_path, angle=angle)
    drawing = import_dxf(path)
    sel = [p for p in drawing.plans if p.selected]
    assert len(sel) == 1 and sel[0].kind == "plan" and sel[0].title == "PLANTA DE DISTRIBUCION"
    other = [p for p in drawing.plans if not p.selected]
    assert len(other) == 1 and other[0].kind == "detail" and other[0].title == "ELEVACION PRINCIPAL"
    turn, coherence = cad_sheet.wall_direction(drawing.geometries)
    assert abs(turn - (angle if angle < 45 else 45.0)) < 0.5 and coherence > 0.9
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    back = np.concatenate([g.coords for g in drawing.geometries]) @ np.array(((c, -s), (s, c)))
    assert back[:, 1].min() >= -0.5 and back[:, 0].min() >= -0.5  # the plan alone, turned back
    x0, y0, x1, y1 = sel[0].extent  # in the CAD frame: the box of the turned plan
    corners = np.array(((0.0, 0.0), (30.0, 0.0), (30.0, 16.0), (0.0, 16.0))) @ np.array(((c, s), (-s, c)))
    assert np.allclose((x0, y0, x1, y1), (*corners.min(axis=0), *corners.max(axis=0)), atol=0.3)
    monkeypatch.setattr(cad_sheet, "ALIGN_SHEET", False)
    try:
        plans = import_dxf(path).plans
    except InputError as exc:
        assert "only plan-like groups are detail views" in str(exc)
    else:
        assert not any(p.kind == "detail" for p in plans)


def test_an_untitled_view_close_to_the_plan_stays_with_it(tmp_path):
    """Without a title saying elevation/section, a drawing 2 m off the plan stays with it (a wing, a porch):
    the band alone proves nothing."""
    drawing = import_dxf(_plan_with_elevation(tmp_path, None))
    assert len([p for p in drawing.plans if p.kind != "other"]) == 1
    assert any(g.coords[:, 1].min() < -2.5 for g in drawing.geometries)


@pytest.mark.qgis_process
def test_dxftoosmag_headless_corridor_closed_by_a_projection_line(tmp_path):
    """Headless: the corridor closed only by a projection line is an area of the osmAG file, named by its
    text, and each classroom has a passage to it."""
    from algorithms import osmag
    from tests.qgis_process import run_alg

    out = tmp_path / "corridor.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": _corridor_plan(tmp_path, "layer"), "OUTPUT": str(out)})
    areas, passages, _, _ = osmag.read_osmag(str(out))
    corridor = [a for a in areas if a.name == "Corridoio distribuzione"]
    assert len(corridor) == 1
    assert len([p for p in passages if corridor[0].id in (p.from_id, p.to_id)]) >= 3


# ------------------------------------------------------------------ dashed projections on wall layers
def _vaulted_rooms(tmp_path, how="entity", name="v.dxf"):
    """Two 6 x 6 m rooms joined by a 1 m doorway (partition at x = 6, opening 2.5-3.5); the left room is
    crossed by a line at x = 4 on the WALL layer (a vault's springing line, a beam overhead), drawn as
    ``how``: "entity" (a linetype whose name says nothing, 'RAYITAS', but whose pattern has gaps), "layer"
    (the wall layer's own linetype is such a pattern: an arc of the vault drawn BYLAYER on a layer of
    projections that a rule maps to walls), or "continuous" (a real wall: the control)."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    doc.linetypes.add("RAYITAS", pattern=[0.375, 0.25, -0.125], description="_ _ _ _ _")
    doc.layers.add("MUROS")
    doc.layers.add("MUROS-BOVEDA", linetype="RAYITAS")
    msp = doc.modelspace()
    wall = {"layer": "MUROS"}
    msp.add_lwpolyline([(0, 0), (12, 0), (12, 6), (0, 6)], close=True, dxfattribs=wall)
    msp.add_line((6, 0), (6, 2.5), dxfattribs=wall)
    msp.add_line((6, 3.5), (6, 6), dxfattribs=wall)
    if how == "entity":
        msp.add_line((4, 0), (4, 6), dxfattribs={"layer": "MUROS", "linetype": "RAYITAS"})
    elif how == "layer":
        msp.add_arc((4, 3), 3.0, -90, 90, dxfattribs={"layer": "MUROS-BOVEDA"})  # a half vault, ends on the walls
    else:
        msp.add_line((4, 0), (4, 6), dxfattribs=wall)
    for x, t in ((2.0, "AMBIENTE 1"), (9.0, "AMBIENTE 2")):
        msp.add_text(t, dxfattribs={"layer": "TEXTOS", "height": 0.25, "insert": (x, 1.0)})
    return _save(doc, tmp_path, name)


def test_linetype_pattern_with_gaps_is_dashed_whatever_its_name():
    from algorithms.cad_explode import linetype_has_gaps

    doc = ezdxf.new("R2010", setup=False)
    doc.linetypes.add("RAYITAS", pattern=[0.375, 0.25, -0.125])
    doc.linetypes.add("LINEA_SOLIDA", pattern=[0.0])
    assert linetype_has_gaps(doc, "RAYITAS")
    assert not linetype_has_gaps(doc, "LINEA_SOLIDA")
    assert not linetype_has_gaps(doc, "Continuous")
    assert not linetype_has_gaps(doc, "NO_SUCH_LINETYPE")


@pytest.mark.parametrize("how", ["entity", "layer"])
def test_a_dashed_line_on_a_wall_layer_is_a_projection_not_a_wall(tmp_path, how):
    """CASONA_DE_YANAHUARA.dxf: vaults drawn as dashed arcs on a kept layer cut every room in two and left
    its doorway opening into the sliver beyond the arc (46 % of the floor connected). A line drawn broken
    (dashed linetype by entity or by layer, by name or by pattern) on a wall layer is boundary evidence."""
    path = _vaulted_rooms(tmp_path, how)
    d = import_dxf(path)
    assert d.classes.get("projection") == 1, d.classes
    assert [g.kind for g in d.boundary] == ["boundary"]
    assert all(g.kind != "boundary" for g in d.geometries)
    floor = pipeline.process_floor(path)
    rooms = [a for a in floor.refined.areas if a.polygon.area > 10]
    assert len(rooms) == 2, [round(a.polygon.area, 1) for a in floor.refined.areas]
    assert all(a.polygon.area > 30 for a in rooms)  # each room whole (6 x 6 m less the walls)
    assert floor.stats["components"] == 1 and floor.stats["largest_component_share"] == 1.0


def test_a_continuous_line_on_a_wall_layer_still_divides(tmp_path):
    """The control: the same line drawn continuous is a wall; the left room's west part is closed."""
    path = _vaulted_rooms(tmp_path, "continuous")
    d = import_dxf(path)
    assert "projection" not in d.classes and not d.boundary
    floor = pipeline.process_floor(path)
    assert floor.stats["components"] == 2


# ------------------------------------------------------------------ floor markings and linings on layer "0"
def _layer0_hall(tmp_path, court=True, tied=False, core=True, name="h.dxf"):
    """Everything on layer "0": a 30 x 12 m hall whose outer wall is two outlines 0.2 m apart that never
    touch; in it a sports court drawn in single lines (a 14 x 8 m rectangle, its centre line and centre
    circle) and a free-standing 6 x 6 m core of two-line walls. ``tied``: one court line runs on to the wall."""
    doc = _doc()
    msp = doc.modelspace()
    z = "0"
    _rect(msp, 0, 0, 30, 12, z)
    _rect(msp, 0.2, 0.2, 29.8, 11.8, z)
    for a, b in (((30, 4), (34, 4)), ((34, 4), (34, 8)), ((34, 8), (30, 8))):  # an annex: no sheet frame
        msp.add_line(a, b, dxfattribs={"layer": z})
    if court:
        _rect(msp, 2, 2, 16, 10, z)
        msp.add_line((9, 2), (9, 10), dxfattribs={"layer": z})
        msp.add_circle((9, 6), 1.8, dxfattribs={"layer": z})
        if tied:
            msp.add_line((2, 6), (0.2, 6), dxfattribs={"layer": z})
    if core:
        _rect(msp, 20, 3, 26, 9, z)
        _rect(msp, 20.2, 3.2, 25.8, 8.8, z)
    return _save(doc, tmp_path, name)


def test_court_markings_inside_a_hall_are_left_out(tmp_path):
    """kindergarten-1.dxf: a sports hall cut into pieces by its court markings drawn on the wall layer. Single
    lines standing free inside the walls, larger than furniture, with no second line at a wall's thickness are
    markings; the free-standing core (two-line walls) and the hall's inner wall face stay walls."""
    path = _layer0_hall(tmp_path)
    d = import_dxf(path)
    assert d.classes.get("marking") == 6, d.classes  # 4 court sides, the centre line, the circle
    floor = pipeline.process_floor(path, names=False)
    from shapely.geometry import Point

    court = [a for a in floor.refined.areas if a.polygon.contains(Point(9, 6))]
    assert len(court) == 1, [round(a.polygon.area, 1) for a in floor.refined.areas]
    # inside the court, its centre circle and the strip between court and walls are one space
    assert all(court[0].polygon.contains(Point(*p)) for p in ((3, 3), (15, 9), (1, 1), (9, 7.5), (17, 11)))
    # the core's inside (5.6 x 5.6 m) is still a space of its own: its walls were kept
    core = [a for a in floor.refined.areas if a.polygon.contains(Point(23, 6))]
    assert core and core[0].id != court[0].id and 25 < core[0].polygon.area < 35


def test_court_markings_tied_to_a_wall_are_walls(tmp_path):
    """The control: the same court with one line running on to the wall is part of the walls (closes spaces)."""
    d = import_dxf(_layer0_hall(tmp_path, tied=True))
    assert "marking" not in d.classes


def _lined_hall(tmp_path, lining=True, name="l.dxf"):
    """Everything on layer "0": a hall (10 x 8 m) north of a 3 m corridor; the wall between them is two lines
    0.2 m apart with a 1.2 m doorway, both jambs capped; ``lining``: a closed outline 0.3 m inside the hall's
    walls (a sports hall's wall lining) runs across the doorway."""
    doc = _doc()
    msp = doc.modelspace()
    z = {"layer": "0"}
    _rect(msp, 0, -3, 10, 8, "0")
    for y in (0.0, 0.2):
        msp.add_line((0, y), (4.0, y), dxfattribs=z)
        msp.add_line((5.2, y), (10, y), dxfattribs=z)
    msp.add_line((4.0, 0.0), (4.0, 0.2), dxfattribs=z)  # jamb caps
    msp.add_line((5.2, 0.0), (5.2, 0.2), dxfattribs=z)
    if lining:
        msp.add_lwpolyline([(0.3, 0.5), (9.7, 0.5), (9.7, 7.7), (0.3, 7.7)], close=True, dxfattribs=z)
    return _save(doc, tmp_path, name)


def test_a_lining_across_a_doorway_does_not_close_it(tmp_path):
    path = _lined_hall(tmp_path)
    d = import_dxf(path)
    lined = [h for h in d.doors if h.source == "lined"]
    assert len(lined) == 1
    h = lined[0]
    assert sorted((round(h.x0, 2), round(h.x1, 2))) == [4.0, 5.2] and abs(h.y0 - 0.1) < 1e-6
    floor = pipeline.process_floor(path, names=False)
    big = [a for a in floor.refined.areas if a.polygon.area > 20]
    assert len(big) == 2, [round(a.polygon.area, 1) for a in floor.refined.areas]
    assert len({a.component for a in big}) == 1


def test_an_open_doorway_without_a_lining_needs_no_hint(tmp_path):
    """The control: the doorway alone is open anyway; no hint is added for it."""
    d = import_dxf(_lined_hall(tmp_path, lining=False))
    assert not [h for h in d.doors if h.source == "lined"]


@pytest.mark.parametrize("label,kept", [("VOID", True), ("Luftraum", True), ("挑空", True), ("Sala", False)])
def test_a_dashed_outline_around_a_void_stays_a_wall(tmp_path, label, kept):
    """A floor opening (void, atrium, double height) is outlined dashed too, and its edge is a drop for a
    robot: dashed lines whose group holds a text naming a void stay walls; around any other text they are
    projections."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    doc.linetypes.add("RAYITAS", pattern=[0.375, 0.25, -0.125])
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (20, 0), (20, 10), (0, 10)], close=True, dxfattribs={"layer": "MUROS"})
    msp.add_line((0, 5), (20, 5), dxfattribs={"layer": "MUROS"})
    for a, b in (((6, 6), (14, 6)), ((14, 6), (14, 9)), ((14, 9), (6, 9)), ((6, 9), (6, 6))):
        msp.add_line(a, b, dxfattribs={"layer": "MUROS", "linetype": "RAYITAS"})
    # a void names the opening inside its outline; any other text lies outside the outline here (a named
    # zone inside its own outline stays too: see the next test)
    msp.add_text(label, dxfattribs={"layer": "TEXTOS", "height": 0.3, "insert": (9, 7.5) if kept else (2, 2)})
    d = import_dxf(_save(doc, tmp_path))
    dashed = [g for g in d.geometries if g.coords[:, 1].min() >= 5.9 and g.coords[:, 1].max() <= 9.1]
    assert len(dashed) == (4 if kept else 0)
    assert d.classes.get("projection", 0) == (0 if kept else 4)


@pytest.mark.qgis_process
def test_dxftoosmag_headless_vaulted_rooms_and_lined_hall(tmp_path):
    """Headless: the two vaulted rooms (dashed springing line on the wall layer) are two named areas joined
    by a passage; the lined hall opens onto its corridor through its doorway."""
    from algorithms import osmag
    from tests.qgis_process import run_alg

    out = tmp_path / "vaults.osm"
    run_alg("dxftoosmag", {"INPUT": _vaulted_rooms(tmp_path, "entity"), "OUTPUT": str(out)})
    areas, passages, _, _ = osmag.read_osmag(str(out))
    named = {a.name: a for a in areas if a.name.startswith("AMBIENTE")}
    assert set(named) == {"AMBIENTE 1", "AMBIENTE 2"}
    ids = {named["AMBIENTE 1"].id, named["AMBIENTE 2"].id}
    assert any({p.from_id, p.to_id} == ids for p in passages)
    out2 = tmp_path / "hall.osm"
    run_alg("dxftoosmag", {"INPUT": _lined_hall(tmp_path), "OUTPUT": str(out2)})
    areas, passages, _, _ = osmag.read_osmag(str(out2))
    rooms = [a for a in areas if a.type != "structure"]
    big = sorted(rooms, key=lambda a: a.polygon.area, reverse=True)[:2]  # hall and corridor (any unit)
    assert len(big) == 2 and any({p.from_id, p.to_id} == {big[0].id, big[1].id} for p in passages)


@pytest.mark.slow
def test_real_plans_projections_and_lined_doorways(shared_data):
    """CASONA_DE_YANAHUARA.dxf: its vault lines (linetype 'RAYITAS', a pattern with gaps, on kept layers) are
    projections; kindergarten-1.dxf: the sports hall's lining runs across jamb-capped doorways that get
    'lined' door hints (its court markings are dashed: projections too)."""
    casona = shared_data / "dxf" / "archweb" / "CASONA_DE_YANAHUARA.dxf"
    kg = shared_data / "dxf" / "archweb" / "kindergarten-1.dxf"
    if not casona.exists() or not kg.exists():
        pytest.skip("shared ArchWeb plans missing")
    d = import_dxf(str(casona))
    assert d.classes.get("projection", 0) >= 15
    assert not any(g.layer == "Rotulos" for g in d.geometries)  # every line of that layer is dashed
    d = import_dxf(str(kg))
    lined = [h for h in d.doors if h.source == "lined"]
    assert len(lined) >= 4
    # two of them are the hall's doorways in its west wall (x = 156.7, 1 m wide)
    west = [h for h in lined if abs(h.x0 - 156.725) < 0.05 and abs(abs(h.y1 - h.y0) - 1.01) < 0.05]
    assert len(west) == 2


@pytest.mark.parametrize("shape,label,kept", [
    ("cone", "cinema", True),     # a zone marked by its own dashed outline, free in the hall, holding a name
    ("cone", None, False),        # the same outline with no name in it: a projection
    ("vault", "AMBIENTE 1", False),  # an outline that follows the room's walls (a vault, a roof): a projection
])
def test_a_named_dashed_zone_free_in_a_hall_stays_but_a_vault_outline_goes(tmp_path, shape, label, kept):
    """historical_museum.dxf: a dashed triangle (a projector's cone) around 'cinema' in the exposition hall
    is the zone the name belongs to; CASONA's dashed outline of a collapsed vault 0.3 m inside the walls of
    AMBIENTE 1 is a projection (the room's door opens between it and the walls)."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    doc.linetypes.add("RAYITAS", pattern=[0.375, 0.25, -0.125])
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (30, 0), (30, 16), (0, 16)], close=True, dxfattribs={"layer": "MUROS"})
    msp.add_line((20, 0), (20, 7), dxfattribs={"layer": "MUROS"})
    msp.add_line((20, 8.5), (20, 16), dxfattribs={"layer": "MUROS"})
    dash = {"layer": "MUROS", "linetype": "RAYITAS"}
    if shape == "cone":
        pts = [(4, 8), (14, 10), (14, 6)]
        at = (11, 8)
    else:
        pts = [(20.3, 0.3), (29.7, 0.3), (29.7, 15.7), (20.3, 15.7)]
        at = (24, 8)
    for a, b in zip(pts, pts[1:] + pts[:1]):
        msp.add_line(a, b, dxfattribs=dash)
    if label:
        msp.add_text(label, dxfattribs={"layer": "TEXTOS", "height": 0.3, "insert": at})
    d = import_dxf(_save(doc, tmp_path))
    assert d.classes.get("projection", 0) == (0 if kept else len(pts))


def test_a_level_mark_block_is_annotation_not_a_wall(tmp_path):
    """CASONA_DE_YANAHUARA.dxf: every room holds a spot-level symbol (block 'NPT': a circle, a hatched
    quadrant, a cross and a 2 m leader line under 'NPT + 0.20') on a wall layer; in a 2 m wide room the
    leader cut the room in two. Level-mark blocks (NPT, FFL, OKFF, quota, 标高) are left out after the
    plans are found; a block of another name with the same lines stays."""
    def plan(block_name):
        doc = _doc()
        blk = doc.blocks.new(block_name)
        blk.add_circle((0, 0), 0.08)
        blk.add_line((-0.15, 0), (1.9, 0))
        blk.add_line((0, -0.15), (0, 0.3))
        msp = doc.modelspace()
        msp.add_lwpolyline([(0, 0), (8, 0), (8, 3), (0, 3)], close=True, dxfattribs={"layer": "MUROS"})
        msp.add_line((2, 0), (2, 1.2), dxfattribs={"layer": "MUROS"})  # a 2 m room, doorway 1.2-2.2
        msp.add_line((2, 2.2), (2, 3), dxfattribs={"layer": "MUROS"})
        msp.add_blockref(block_name, (0.1, 1.5), dxfattribs={"layer": "MUROS"})
        return import_dxf(_save(doc, tmp_path, f"{block_name}.dxf"))

    d = plan("NPT")
    assert d.classes.get("level mark") == 3
    assert not any(g.block == "NPT" for g in d.geometries)
    d = plan("PILAR")
    assert "level mark" not in d.classes and sum(g.block == "PILAR" for g in d.geometries) == 3
