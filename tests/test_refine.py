"""Refinement (stage 4) on synthetic AreaGraphs built like segmentation builds them."""
import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Polygon

from algorithms.errors import Canceled, InputError
from algorithms.model import Area, AreaGraph, Passage
from algorithms.progress import RecordingProgress
from algorithms.refine import graph_from_labels, refine

RES = 0.05


def synthetic_labels():
    """A small floor at 0.05 m/px (30 m x 20 m):
    1 room (top left) with a 0.3 m pillar, 2 room (top right), 3 corridor (bottom), 4 room (bottom right)
    separated from the corridor by a staircase (diagonal) border, 5 tiny niche (1 m²) open to room 1,
    6 isolated tiny closet (walled), doors 1-3 and 2-3 through the wall."""
    L = np.zeros((400, 600), np.int32)
    L[10:200, 10:290] = 1
    L[10:200, 292:590] = 2
    L[202:390, 10:590] = 3
    L[200:202, 60:80] = 1  # door 1->3 (gap in the wall, belongs to room 1)
    L[200:202, 300:320] = 2  # door 2->3
    for r in range(202, 390):  # diagonal border 3|4 (slope 1:2)
        L[r, 350 + (r - 202) // 2:590] = 4
    L[100:106, 100:106] = 0  # pillar inside room 1
    L[60:80, 270:290] = 5  # a 1 m² niche 5 at the wall of room 1
    L[20:26, 320:326] = 0  # pillar in room 2
    L[380:388, 20:28] = 0  # pillar in the corridor
    L[150:160, 150:160] = 0  # walled closet inside room 1 ...
    L[152:158, 152:158] = 6  # ... with a tiny isolated area 6
    return L


@pytest.fixture(scope="module")
def graph():
    g = graph_from_labels(synthetic_labels(), 0.0, 20.0, RES, types={3: "corridor"})
    return g


@pytest.fixture(scope="module")
def refined(graph):
    prog = RecordingProgress()
    out, stats = refine(graph, RES, progress=prog)
    return out, stats, prog


def test_synthetic_graph_is_what_segmentation_gives(graph):
    ids = sorted(a.id for a in graph.areas)
    assert ids == [1, 2, 3, 4, 5, 6]
    pairs = sorted(tuple(sorted((p.from_id, p.to_id))) for p in graph.passages)
    assert (1, 3) in pairs and (2, 3) in pairs and (3, 4) in pairs and (1, 5) in pairs


def test_small_areas_merged_or_dropped(graph, refined):
    out, stats, prog = refined
    ids = sorted(a.id for a in out.areas)
    assert ids == [1, 2, 3, 4]
    assert stats["merged_into"] == {5: 1}
    assert stats["dropped"] == 1 and stats["dropped_ids"] == [6]
    assert "dropped" in prog.text()
    # the 1-5 passage became internal; none refers to a removed area
    assert all(p.from_id in ids and p.to_id in ids for p in out.passages)
    assert not any({p.from_id, p.to_id} == {1} for p in out.passages)
    a1 = out.area_by_id()[1]
    assert a1.polygon.area == pytest.approx(graph.area_by_id()[1].polygon.area + graph.area_by_id()[5].polygon.area,
                                            abs=0.05)


def test_vertex_reduction_and_deviation(graph, refined):
    out, stats, _ = refined
    assert stats["vertices_after"] < stats["vertices_before"]
    assert stats["vertex_reduction"] >= 0.85
    assert stats["epsilon_m"] == pytest.approx(1.2 * RES)
    assert stats["max_deviation_dp_m"] <= 1.2 * RES + 1e-9
    # independent measurement against the unsimplified polygons (areas not merged)
    src = graph.area_by_id()
    for a in out.areas:
        if a.id in (2, 3, 4):
            d = shapely.hausdorff_distance(src[a.id].polygon.boundary, a.polygon.boundary, densify=0.1)
            assert d <= 1.2 * RES + 1e-9, (a.id, d)
    # the staircase border really was simplified: area 4 went from ~190 vertices to a handful
    assert len(src[4].polygon.exterior.coords) > 150
    assert len(out.area_by_id()[4].polygon.exterior.coords) <= 8


def test_shared_borders_stay_shared(refined):
    out, _, _ = refined
    polys = [a.polygon for a in out.areas]
    assert all(p.is_valid for p in polys)
    # no overlaps: the union area equals the sum of areas
    u = shapely.union_all(polys)
    assert u.area == pytest.approx(sum(p.area for p in polys), abs=1e-6)
    # no gaps (slivers) between neighbours: every hole of the union is a real wall/pillar (>= 0.05 m²)
    holes = [Polygon(r) for g in getattr(u, "geoms", [u]) for r in g.interiors]
    assert all(h.area > 0.05 for h in holes)
    # identical vertices along common borders: every vertex of A lying on B's boundary is a vertex of B
    for i, a in enumerate(out.areas):
        va = np.asarray(a.polygon.exterior.coords)[:-1]
        for b in out.areas[i + 1:]:
            if not a.polygon.touches(b.polygon):
                continue
            common = a.polygon.boundary.intersection(b.polygon.boundary)
            vb = {tuple(c) for r in [b.polygon.exterior] + list(b.polygon.interiors) for c in r.coords}
            on_b = [tuple(c) for c in va if b.polygon.boundary.distance(shapely.points(c)) < 1e-9]
            assert on_b, (a.id, b.id)
            assert all(c in vb for c in on_b), (a.id, b.id)
            assert common.length > 0.5


def test_passage_endpoints_are_vertices_of_both_areas(refined):
    out, stats, _ = refined
    amap = out.area_by_id()
    assert len(out.passages) == stats["passages_out"] >= 3
    for p in out.passages:
        assert len(p.line.coords) == 2
        for aid in (p.from_id, p.to_id):
            verts = {tuple(c) for c in amap[aid].polygon.exterior.coords}
            for c in p.line.coords:
                assert tuple(c) in verts, (p.id, aid, c)
    # the door 1->3 keeps its width (2 px wall, 20 px door = 1.0 m)
    widths = sorted(round(p.width, 3) for p in out.passages if {p.from_id, p.to_id} == {1, 3})
    assert widths == [1.0]


def test_pillar_hole_kept(refined):
    out, _, _ = refined
    a1 = out.area_by_id()[1]
    holes = [Polygon(r).area for r in a1.polygon.interiors]
    assert any(abs(h - 0.09) < 1e-6 for h in holes)  # 6 x 6 px pillar


def test_spike_removed_with_passage_endpoint_locked():
    # room with a narrow spike (11 deg, 0.2 m) on its free border, and a second room sharing a border
    a = Polygon([(0, 0), (4, 0), (4, 4), (2.0, 4.0), (1.98, 4.2), (1.96, 4.0), (0, 4)])
    b = Polygon([(4, 0), (8, 0), (8, 4), (4, 4)])
    g = AreaGraph([Area(1, a), Area(2, b)], [Passage(1, 1, 2, LineString([(4, 1), (4, 2)]))])
    out, stats = refine(g, RES, min_area=1.0)
    verts = {tuple(np.round(c, 6)) for c in out.area_by_id()[1].polygon.exterior.coords}
    assert (1.98, 4.2) not in verts
    assert stats["spikes_removed"] >= 1
    # the passage endpoints were inserted into both rings and kept
    for aid in (1, 2):
        v = {tuple(c) for c in out.area_by_id()[aid].polygon.exterior.coords}
        assert (4.0, 1.0) in v and (4.0, 2.0) in v
    # a long protrusion (0.5 m) is a real feature and stays
    a2 = Polygon([(0, 0), (4, 0), (4, 4), (2.0, 4.0), (1.95, 4.5), (1.9, 4.0), (0, 4)])
    out2, _ = refine(AreaGraph([Area(1, a2)], []), RES, min_area=1.0)
    assert any(abs(c[1] - 4.5) < 1e-9 for c in out2.areas[0].polygon.exterior.coords)


def test_input_not_modified(graph):
    before = [a.polygon.wkb for a in graph.areas]
    refine(graph, RES)
    assert [a.polygon.wkb for a in graph.areas] == before


def test_bad_input_names_features():
    ok = Polygon([(0, 0), (5, 0), (5, 5), (0, 5)])
    bow = Polygon([(10, 0), (15, 5), (15, 0), (10, 5)])
    with pytest.raises(InputError, match=r"area 7 .*Self-intersection"):
        refine(AreaGraph([Area(1, ok), Area(7, bow)], []), RES)
    with pytest.raises(InputError, match=r"area 3 has an empty polygon"):
        refine(AreaGraph([Area(1, ok), Area(3, Polygon())], []), RES)
    with pytest.raises(InputError, match=r"passages reference missing areas: 12 \(1->99\)"):
        refine(AreaGraph([Area(1, ok)], [Passage(12, 1, 99, LineString([(0, 0), (0, 1)]))]), RES)
    with pytest.raises(InputError, match="resolution"):
        refine(AreaGraph([Area(1, ok)], []), 0.0)
    with pytest.raises(InputError, match="areas overlap: 1 and 2"):
        refine(AreaGraph([Area(1, ok), Area(2, Polygon([(0, 0), (5, 0), (5, 5), (0, 5)]))], []), RES)
    with pytest.raises(InputError, match="areas overlap: 1 and 3"):
        refine(AreaGraph([Area(1, ok), Area(3, Polygon([(1, 1), (2, 1), (2, 2), (1, 2)]))], []), RES, min_area=0.5)
    over = Polygon([(4, 0), (9, 0), (9, 5), (4, 5)])
    with pytest.raises(InputError, match=r"areas overlap: 1 and 8"):
        refine(AreaGraph([Area(1, ok), Area(8, over)], []), RES)


def test_cancel(graph):
    with pytest.raises(Canceled):
        refine(graph, RES, progress=RecordingProgress(cancel_after=2))


def test_thin_wall_fallback_keeps_polygons_valid():
    # two rooms separated by a 1-pixel wall with staircase borders: simplification of both sides
    # could cross; the result must stay valid and non-overlapping
    L = np.zeros((120, 120), np.int32)
    for r in range(5, 115):
        c = 5 + (r * 3) // 7
        L[r, 5:c] = 1
        L[r, c + 1:115] = 2
    g = graph_from_labels(L, 0.0, 6.0, RES)
    out, stats = refine(g, RES, min_area=1.0)
    p1, p2 = (a.polygon for a in sorted(out.areas, key=lambda a: a.id))
    assert p1.is_valid and p2.is_valid
    assert p1.intersection(p2).area < 1e-9
    assert stats["max_deviation_m"] <= 1.2 * RES + 1e-9


# ----------------------------------------------------------------------------- real data
@pytest.fixture(scope="module")
def sist_graph(shared_data):
    from algorithms.cad_import import import_dxf
    from algorithms.rasterize import rasterize
    from algorithms.segmentation import segment

    drawing = import_dxf(str(shared_data / "dxf" / "sist" / "SIST-F5.dxf"))
    return segment(rasterize(drawing.geometries))


@pytest.mark.slow
def test_sist_floor_refine_and_export(sist_graph, tmp_path):
    import subprocess
    import time

    from osgeo import gdal, ogr

    from algorithms.georef import LocalFrame
    from algorithms.osmag import read_osmag, write_osmag

    g = sist_graph
    res = g.grid.resolution
    t0 = time.perf_counter()
    out, st = refine(g, res)
    path = tmp_path / "sist5.osm"
    written = write_osmag(str(path), out.areas, out.passages, frame=LocalFrame(121.5906, 31.179), level="5")
    wall = time.perf_counter() - t0
    assert wall < 3.0  # target 1 s on an idle machine (the benchmark reports it); shared CPUs here
    assert st["vertex_reduction"] >= 0.85
    # strictly within ε·r on walls, within ε·r times the segmentation's topology scale on borders between two areas
    assert st["max_deviation_m"] <= st["border_epsilon_m"]
    assert st["border_epsilon_m"] == pytest.approx(st["epsilon_m"] * g.stats.get("topology_scale", 1))
    # measured independently on the areas that were not merged
    src = g.area_by_id()
    merged_targets = set(st["merged_into"].values())
    devs = [shapely.hausdorff_distance(src[a.id].polygon.boundary, a.polygon.boundary, densify=0.25)
            for a in out.areas if a.id not in merged_targets]
    assert max(devs) <= st["max_deviation_m"] + 1e-9
    polys = [a.polygon for a in out.areas]
    assert all(p.is_valid for p in polys)
    assert shapely.union_all(polys).area == pytest.approx(sum(p.area for p in polys), abs=1e-6)
    amap = out.area_by_id()
    for p in out.passages:
        for aid in (p.from_id, p.to_id):
            verts = {tuple(c) for c in amap[aid].polygon.exterior.coords}
            assert all(tuple(c) in verts for c in p.line.coords), (p.id, aid)
    # real clients
    r = subprocess.run(["osmium", "fileinfo", "-e", str(path)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and f"Number of ways: {len(out.areas) + len(out.passages)}" in r.stdout
    gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", "NO")
    try:
        ds = ogr.Open(str(path))
        polys_gdal = [f for f in ds.GetLayerByName("multipolygons")]
        assert len(polys_gdal) == len(out.areas)
        assert all('"osmAG:type"=>"area"' in f.GetField("other_tags") for f in polys_gdal)
        ds = None
    finally:
        gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", None)
    areas, passages, root, rep = read_osmag(str(path))
    assert len(areas) == len(out.areas) and len(passages) == len(out.passages) == written["passages"]
    assert not rep["unclosed"] and not rep["dangling_refs"] and not rep["dangling_nodes"]


def test_self_touching_ring_is_repaired_not_passed_on():
    """A ring touching itself (invalid for OGC/GEOS) comes out of refine valid, with a warning."""
    from shapely.geometry import LineString, Polygon, box

    from algorithms.model import Area, AreaGraph, Passage
    from algorithms.progress import RecordingProgress
    from algorithms.refine import refine

    pinched = Polygon([(20, 0), (30, 0), (30, 10), (25, 0), (20, 10)])
    assert not pinched.is_valid
    areas = [Area(1, box(0, 0, 20, 10)), Area(2, pinched)]
    graph = AreaGraph(areas, [Passage(1, 1, 2, LineString([(20, 2), (20, 8)]))])
    rec = RecordingProgress()
    out, _ = refine(graph, 0.05, min_area=0, progress=rec)
    assert all(a.polygon.is_valid for a in out.areas)
    assert any(kind == "warning" and "area 2 touches itself" in msg for kind, msg in rec.messages)


def test_overlap_check_skips_invalid_polygons_instead_of_raising():
    """CASONA_DE_YANAHUARA: a polygon made invalid by simplification made the GEOS 'overlaps'
    query raise a raw TopologyException; invalid polygons are offenders of their own, never queried."""
    from algorithms.refine import _overlapping_pairs

    bowtie = Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])  # self-intersecting
    a = Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    b = Polygon([(0.5, 0), (1.5, 0), (1.5, 1), (0.5, 1)])  # overlaps a
    arr = np.array([a, bowtie, b], dtype=object)
    valid = shapely.is_valid(arr)
    assert not valid[1]
    pairs = _overlapping_pairs(arr, valid, 0.05)
    assert [(x, y) for x, y, _ in pairs] == [(0, 2)]
    assert pairs[0][2] == pytest.approx(0.5)


def _stretch_between_stair_and_corridor():
    """A 4 x 2 m stretch (5) under a stair (1, their border 4 m long), a corridor (2) east of it (2 m border),
    a room (3) west of it whose 1 m door opens onto the stretch only, and a 0.16 m2 niche (4) in the stair's
    corner (it touches the stair alone). 0.05 m/px, y down."""
    L = np.zeros((200, 300), np.int32)
    L[10:90, 10:290] = 1  # the stair, north
    L[90:130, 120:200] = 5  # the stretch
    L[90:170, 200:290] = 2  # the corridor, east
    L[90:170, 10:118] = 3  # the room, west (a wall between it and the stretch) ...
    L[100:120, 118:120] = 3  # ... and its door
    L[12:20, 12:20] = 4  # the niche
    return L


@pytest.mark.parametrize("shafts_last", [True, False])
def test_a_small_stretch_joins_a_stair_only_when_it_touches_nothing_else(monkeypatch, shafts_last):
    """SIST-F4.dwg (level 4): a corridor's 10 m2 stretch between a lobby and the E2 wing's corridor shared its
    longest border with a stair and was merged into it: the stair became the wing's only way through, and a robot
    avoiding stairs could not reach the lifts. A small area joins a stair or a lift only when nothing else
    touches it (here the corridor); the niche touching the stair alone still joins it."""
    from algorithms import refine as R

    monkeypatch.setattr(R, "SHAFTS_LAST", shafts_last)
    L = _stretch_between_stair_and_corridor()
    g = graph_from_labels(L, 0.0, 10.0, RES, types={1: "stairs", 2: "corridor"})
    areas, passages, info = R.merge_small_areas(g.areas, g.passages, 10.0, keep_types=())
    into = info["merged_into"]
    assert into[4] == 1  # the niche: the stair is its only neighbour
    assert into[5] == (2 if shafts_last else 1)
    if shafts_last:  # the room's door now opens onto the corridor, not the stair
        assert any({p.from_id, p.to_id} == {2, 3} for p in passages)
