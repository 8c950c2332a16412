"""Connected floors (issue 8, item 6), kinds of drawing found on kindergarten-1.dxf, one rule each:

* a doorway in a two-line wall whose one face is drawn on across the opening (jambs capped on the other
  face only): ``cad_classify.lined_doorways`` gives it a hint, a niche down to a wall's middle line none;
* a door swing drawn without its leaf on a wall drawn straight through the doorway (a facade drawn as two
  long lines): ``cad_classify._swings_on_walls`` gives it a hint, an arc standing off the wall none;
* ground open to the outside along a stretch wider than any facade opening the envelope closes at its
  chord, reached from outside only (a porch between two walls under a roof edge):
  ``segmentation.open_ground_spaces`` counts it out of the connected share, on named drawings or not, never
  a named space, never a room whose missing door or window bay leaves a chord to the outside.
Each test builds the small drawing (or raster) the rule is about."""
import ezdxf
import numpy as np
import pytest

from algorithms import pipeline, segmentation
from algorithms.cad_classify import door_swings, lined_doorways
from algorithms.cad_import import import_dxf
from algorithms.model import OCCUPIED, Area, CadGeometry, DoorHint, OccupancyGrid


def _line(a, b, layer="0", kind="reference"):
    return CadGeometry(layer=layer, kind=kind, coords=np.array([a, b], dtype=float), entity="LINE")


def _arc(cx, cy, r, a0, a1, layer="4", kind="swing?", n=12):
    t = np.radians(np.linspace(a0, a1, n))
    return CadGeometry(layer=layer, kind=kind, coords=np.c_[cx + r * np.cos(t), cy + r * np.sin(t)], entity="ARC")


# ------------------------------------------------------------------ one face drawn on across the doorway
def _face_through_wall(niche=False):
    """A partition 0.1 m thick along y = 0..0.1 (layer "0"): the lower face y = 0 runs on across the opening
    x = 4.0-5.0; the upper face stops at the jamb caps. ``niche``: a third line y = -0.3 below (the caps end
    on the middle line of a 0.4 m wall: a niche, not a doorway)."""
    g = [_line((0, 0), (10, 0)),
         _line((0, 0.1), (4.0, 0.1)), _line((5.0, 0.1), (10, 0.1)),
         _line((4.0, 0.0), (4.0, 0.1)), _line((5.0, 0.0), (5.0, 0.1))]
    if niche:
        g.append(_line((0, -0.3), (10, -0.3)))
    return g


def test_a_doorway_whose_one_face_runs_on_gets_a_hint():
    g = _face_through_wall()
    hints = lined_doorways(g, [""] * len(g), {"0"})
    assert len(hints) == 1
    h = hints[0]
    assert sorted((round(h.x0, 3), round(h.x1, 3))) == [4.0, 5.0] and abs(h.y0 - 0.05) < 1e-6
    assert h.source == "lined"


def test_a_niche_down_to_a_middle_line_gets_none():
    g = _face_through_wall(niche=True)
    assert lined_doorways(g, [""] * len(g), {"0"}) == []


def test_a_wall_with_both_faces_through_and_no_caps_gets_none():
    g = [_line((0, 0), (10, 0)), _line((0, 0.1), (10, 0.1))]
    assert lined_doorways(g, [""] * len(g), {"0"}) == []


def _face_through_dxf(tmp_path):
    """Two rooms on layer "0" (8 x 5 m each) split by the partition above; no door is drawn."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    z = {"layer": "0"}
    for a, b in (((0, -5), (10, -5)), ((10, -5), (10, 5)), ((10, 5), (0, 5)), ((0, 5), (0, -5)),
                 ((0, 0), (10, 0)), ((0, 0.1), (4.0, 0.1)), ((5.0, 0.1), (10, 0.1)),
                 ((4.0, 0.0), (4.0, 0.1)), ((5.0, 0.0), (5.0, 0.1))):
        msp.add_line(a, b, dxfattribs=z)
    p = tmp_path / "face.dxf"
    doc.saveas(p)
    return str(p)


def test_face_through_doorway_joins_the_two_rooms(tmp_path):
    path = _face_through_dxf(tmp_path)
    assert [h.source for h in import_dxf(path).doors] == ["lined"]
    floor = pipeline.process_floor(path, names=False)
    big = [a for a in floor.refined.areas if a.polygon.area > 20]
    assert len(big) == 2, [round(a.polygon.area, 1) for a in floor.refined.areas]
    assert len({a.component for a in big}) == 1 and floor.stats["passages"] >= 1


# ------------------------------------------------------------------ a swing on a wall drawn through the doorway
def _facade(r=0.9, hinge_off=0.0, kind="swing?"):
    """A facade drawn as two long lines (x = 0 and x = 0.16, y = 0..10) with no opening; a quarter arc of
    radius ``r`` hinged at (hinge_off, 4) whose closed end lies on the wall at (0, 4 + r) and whose open end
    stands in the room west of it."""
    g = [_line((0, 0), (0, 10), "A-WALL", "wall"), _line((0.16, 0), (0.16, 10), "A-WALL", "wall")]
    g.append(_arc(hinge_off, 4.0, r, 90.0, 180.0, kind=kind))
    return g


def test_a_swing_on_a_wall_drawn_through_gets_a_hint():
    drop, hints = door_swings(_facade())
    assert drop == [2] and len(hints) == 1
    h = hints[0]
    assert np.allclose((h.x0, h.y0, h.x1, h.y1), (0.0, 4.0, 0.0, 4.9), atol=1e-6)


@pytest.mark.parametrize("off", [-0.5, 0.6])
def test_a_swing_standing_off_the_wall_gets_none(off):
    """The same arc with its centre in the room (0.5 m west) or beyond the wall: no hinge on the wall."""
    _, hints = door_swings(_facade(hinge_off=off))
    assert hints == []


def test_a_quarter_arc_on_a_wall_layer_stays_a_wall():
    drop, hints = door_swings(_facade(kind="wall"))
    assert hints == [] and drop == []


def test_an_arc_on_the_walls_own_layer_is_no_swing_on_a_wall():
    """Walls and arcs all on one layer (spaghetti on "0"): the arc may belong to the wall drawing."""
    g = _facade()
    g[2].layer = "A-WALL"
    assert door_swings(g)[1] == []


def _vestibule_dxf(tmp_path):
    """A room (6 x 5 m) west of a facade drawn as two long lines; outside it a vestibule (2 x 2 m, walls
    on its other three sides) reached through a door in the facade drawn only as a quarter arc on a layer
    no rule names (layer "4"), hinged on the facade's outer face, opening into the vestibule."""
    doc = ezdxf.new("R2010", setup=False)
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    w = {"layer": "A-WALL"}
    for a, b in (((-6, 0), (0, 0)), ((-6, 0), (-6, 5)), ((-6, 5), (0, 5)),
                 ((0, -1), (0, 6)), ((0.16, -1), (0.16, 6)),
                 ((0.16, 1.5), (2.2, 1.5)), ((2.2, 1.5), (2.2, 3.5)), ((2.2, 3.5), (0.16, 3.5))):
        msp.add_line(a, b, dxfattribs=w)
    msp.add_arc((0.16, 1.6), 0.9, 0, 90, dxfattribs={"layer": "4"})  # closed end (0.16, 2.5) on the wall
    p = tmp_path / "vestibule.dxf"
    doc.saveas(p)
    return str(p)


def test_swing_on_a_facade_drawn_through_joins_the_vestibule(tmp_path):
    path = _vestibule_dxf(tmp_path)
    d = import_dxf(path)
    assert len(d.doors) == 1 and d.doors[0].source == "swing"
    assert np.allclose(sorted((d.doors[0].y0, d.doors[0].y1)), (1.6, 2.5), atol=1e-3)
    floor = pipeline.process_floor(path, names=False)
    areas = [a for a in floor.refined.areas if a.polygon.area > 2]
    assert floor.stats["components"] == 1, [(round(a.polygon.area, 1), a.component) for a in areas]


# ------------------------------------------------------------------ ground open to the outside
def _grid(res=0.1, w=30.0, h=24.0):
    data = np.zeros((int(h / res), int(w / res)), np.uint8)
    return OccupancyGrid(data=data, origin_x=0.0, origin_y=h, resolution=res)


def _wall(grid, x0, y0, x1, y1):
    c0, r0 = grid.world_to_pixel(x0, y1)
    c1, r1 = grid.world_to_pixel(x1, y0)
    grid.data[int(round(r0)):int(round(r1)), int(round(c0)):int(round(c1))] = OCCUPIED


def _box(x0, y0, x1, y1):
    from shapely.geometry import box

    return box(x0, y0, x1, y1)


def _ground_plan():
    """A building (x 2-22, y 2-12, walls 0.2 m) of a hall (component 0) and a room east of it whose door the
    drawing forgot and whose facade misses a 3.5 m window bay (component 2); north of the hall a porch
    (x 2-14, y 12-18) between two walls, open to the north over 11.6 m (component 1)."""
    g = _grid()
    for x0, y0, x1, y1 in ((2, 2, 22, 2.2), (2, 11.8, 22, 12), (2, 2, 2.2, 12), (21.8, 2, 22, 12),
                           (14, 2, 14.2, 12),  # hall | room
                           (2, 12, 2.2, 18), (13.8, 12, 14, 18)):  # the porch's side walls
        _wall(g, x0, y0, x1, y1)
    g.data[int((24 - 2.2) / 0.1):int((24 - 2.0) / 0.1), int(16 / 0.1):int(19.5 / 0.1)] = 0  # the bay 16-19.5
    areas = [Area(1, _box(2.2, 2.2, 14, 11.8), component=0), Area(2, _box(2.2, 12, 13.8, 18), component=1),
             Area(3, _box(14.2, 2.2, 21.8, 11.8), component=2)]
    return g, areas


def test_a_porch_open_to_the_outside_counts_out_a_room_with_a_missing_window_does_not():
    g, areas = _ground_plan()
    info = {}
    assert segmentation.open_ground_spaces(areas, [], g, info=info) == [2]
    assert info["fronts"][1] > 8.5 and info["fronts"][2] < 4.0  # the porch's front; the room's 3.5 m bay
    # the bay is measured (it is no wall), only narrower than a front
    assert segmentation.open_ground_spaces(areas, [], g, min_front=1.0) == [2, 3]


def test_a_named_porch_or_one_a_door_reaches_stays():
    g, areas = _ground_plan()
    assert segmentation.open_ground_spaces(areas, [], g, name_points=[(6.0, 15.0, "Portico")]) == []
    door = DoorHint(5.0, 12.0, 6.0, 12.0, "swing")  # a doorway drawn from the porch into the hall
    assert segmentation.open_ground_spaces(areas, [], g, door_hints=[door]) == []


def test_the_main_component_and_counted_out_areas_are_never_listed():
    g, areas = _ground_plan()
    areas[1].component = 0
    assert segmentation.open_ground_spaces(areas, [], g) == []
    areas[1].component = 1
    assert segmentation.open_ground_spaces(areas, [], g, closed_ids=[2]) == []


def _porch_dxf(tmp_path, name=None):
    """Two classrooms (10 x 10 m) joined by a doorway; north of them a porch (12 x 6 m) between two walls,
    closed by a dash-dot roof edge (9 m), with a store in its corner that opens onto it; no door joins the porch
    to the classrooms (reached from outside only)."""
    doc = ezdxf.new("R2010", setup=["linetypes"])
    doc.header["$INSUNITS"] = 6
    doc.layers.add("misc")
    msp = doc.modelspace()
    w = {"layer": "MURI"}
    for a, b in (((0, 0), (20, 0)), ((0, 0), (0, 10)), ((20, 0), (20, 10)), ((0, 10), (20, 10)),
                 ((10, 0), (10, 4)), ((10, 5), (10, 10)), ((0, 10), (0, 16)), ((12, 10), (12, 16)),
                 ((0, 13), (3, 13)), ((3, 13), (3, 13.8)), ((3, 14.8), (3, 16)), ((0, 16), (3, 16))):
        msp.add_line(a, b, dxfattribs=w)
    msp.add_line((3, 16), (12, 16), dxfattribs={"layer": "misc", "linetype": "DASHDOT"})
    for k, x in enumerate((5, 15)):
        msp.add_text(f"Aula {k + 1}", dxfattribs={"layer": "SCRITTE", "height": 0.3, "insert": (x, 5)})
    if name:
        msp.add_text(name, dxfattribs={"layer": "SCRITTE", "height": 0.3, "insert": (5.5, 12)})
    p = tmp_path / f"porch{'_' + name if name else ''}.dxf"
    doc.saveas(p)
    return str(p)


def _porch(floor):
    from shapely.geometry import Point

    return [a for a in floor.refined.areas if a.polygon.contains(Point(5.5, 13.0))]


def test_a_porch_reached_from_outside_only_is_counted_out(tmp_path):
    floor = pipeline.process_floor(_porch_dxf(tmp_path))
    porch = _porch(floor)
    assert porch and porch[0].component != 0
    assert porch[0].id in floor.stats["outdoor_spaces"] and porch[0].tags.get("cad2osmag:outdoor") == "yes"
    assert floor.stats["largest_component_share"] == 1.0


def test_a_named_porch_is_never_counted_out(tmp_path):
    floor = pipeline.process_floor(_porch_dxf(tmp_path, name="Portico"))
    porch = _porch(floor)
    assert porch and porch[0].name == "Portico" and porch[0].id not in floor.stats["outdoor_spaces"]
    assert floor.stats["largest_component_share"] < 0.9


@pytest.mark.qgis_process
def test_dxftoosmag_headless_porch_and_face_through_doorway(tmp_path):
    """Headless: the porch is an area tagged outdoor in the osmAG file, the rooms split by the partition
    whose one face runs on across the doorway are joined by a passage."""
    from algorithms import osmag
    from tests.qgis_process import run_alg

    out = tmp_path / "porch.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": _porch_dxf(tmp_path), "OUTPUT": str(out)})
    assert "porches and yards open to the outside" in log
    areas, passages, _, _ = osmag.read_osmag(str(out))
    outdoor = [a for a in areas if (a.tags or {}).get("cad2osmag:outdoor") == "yes"]
    assert len(outdoor) == 1  # the porch (with its store); the classrooms are not
    out2 = tmp_path / "face.osm"
    run_alg("dxftoosmag", {"INPUT": _face_through_dxf(tmp_path), "OUTPUT": str(out2)})
    areas, passages, _, _ = osmag.read_osmag(str(out2))
    rooms = sorted((a for a in areas if a.type != "structure"), key=lambda a: a.polygon.area, reverse=True)[:2]
    assert len(rooms) == 2 and any({p.from_id, p.to_id} == {rooms[0].id, rooms[1].id} for p in passages)


@pytest.mark.slow
def test_kindergarten_door_kinds_and_open_ground(shared_data, floor_cache):
    """kindergarten-1.dxf (session-cached conversion): the 1 m door between the bedroom and the room south
    of it (the wall's lower face runs on across it) and the doors in the west facade drawn straight through
    (quarter arcs on layer '4' into the vestibules at the exterior steps) get hints; the bedroom, that room
    and the washroom are one component; the covered porch (pillars and a dash-dot roof edge, 121 m2) and the
    yard under the overhang south of the hall (110 m2), unnamed and reached from outside only, count out."""
    from shapely.geometry import Point

    kg = shared_data / "dxf" / "archweb" / "kindergarten-1.dxf"
    if not kg.exists():
        pytest.skip("shared ArchWeb plans missing")
    floor = floor_cache.process_floor(kg)

    def hint(src, *xy):
        return [h for h in floor.drawing.doors if h.source == src and (
            np.allclose((h.x0, h.y0, h.x1, h.y1), xy, atol=0.05)
            or np.allclose((h.x1, h.y1, h.x0, h.y0), xy, atol=0.05))]

    assert hint("lined", 97.62, 205.83, 98.49, 205.32)
    assert hint("swing", 99.10, 203.44, 99.67, 204.14) and hint("swing", 94.17, 195.02, 94.74, 195.72)

    def area_at(x, y):
        got = [a for a in floor.refined.areas if a.polygon.contains(Point(x, y))]
        assert got, (x, y)
        return got[0]

    bedroom, south, washroom = area_at(97.0, 208.5), area_at(96.0, 204.5), area_at(95.0, 202.0)
    assert len({bedroom.id, south.id, washroom.id}) == 3
    assert bedroom.component == south.component == washroom.component
    outdoor = set(floor.stats["outdoor_spaces"])
    assert area_at(140.0, 225.0).id in outdoor and area_at(170.0, 156.0).id in outdoor
    assert bedroom.id not in outdoor
    assert floor.stats["largest_component_share"] >= 0.95
