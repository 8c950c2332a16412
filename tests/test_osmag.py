"""osmAG export/import (stage 7): format rules, real clients (osmium, GDAL), round trip, bad input."""
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon

from algorithms.errors import InputError
from algorithms.georef import LocalFrame, geodesic_distance
from algorithms.model import Area, Passage
from algorithms.osmag import read_osmag, to_frame, write_osmag
from algorithms.refine import graph_from_labels, refine
from tests.test_refine import RES, synthetic_labels

DATA = Path(__file__).parent / "data"
FRAME = LocalFrame(121.5906, 31.1790, rotation_deg=20.0)


@pytest.fixture(scope="module")
def refined():
    g = graph_from_labels(synthetic_labels(), 0.0, 20.0, RES, types={3: "corridor"})
    out, _ = refine(g, RES)
    out.area_by_id()[1].name = "Lab 101"
    return out


@pytest.fixture(scope="module")
def written(refined, tmp_path_factory):
    path = tmp_path_factory.mktemp("osmag") / "floor1.osm"
    floor = Area(900, Polygon([(-1, -1), (31, -1), (31, 21), (-1, 21)]), type="structure", name="Floor 1")
    stats = write_osmag(str(path), refined.areas, refined.passages, frame=FRAME, level="1", height=3.2,
                        structure_areas=[floor])
    return path, stats


def _parse(path):
    root = ET.parse(path).getroot()
    nodes = {int(n.get("id")): n for n in root.iter("node")}
    ways = {int(w.get("id")): ([int(nd.get("ref")) for nd in w.iter("nd")],
                               {t.get("k"): t.get("v") for t in w.iter("tag")}) for w in root.iter("way")}
    return root, nodes, ways


def test_format_rules(written, refined):
    path, stats = written
    root, nodes, ways = _parse(path)
    assert root.tag == "osm" and root.get("version") == "0.6" and root.get("generator") == "cad2osmag"
    roots = [n for n in nodes.values() if any(t.get("k") == "name" and t.get("v") == "root" for t in n)]
    assert len(roots) == 1
    assert float(roots[0].get("lat")) == pytest.approx(31.179) and float(roots[0].get("lon")) == pytest.approx(121.5906)
    assert all(i < 0 for i in nodes) and all(i < 0 for i in ways)
    for n in nodes.values():
        assert len(n.get("lat").split(".")[1]) >= 9 and len(n.get("lon").split(".")[1]) >= 9
    areas = {i: w for i, w in ways.items() if w[1]["osmAG:type"] == "area"}
    passages = {i: w for i, w in ways.items() if w[1]["osmAG:type"] == "passage"}
    assert len(areas) == len(refined.areas) + 1 and len(passages) == len(refined.passages)
    names = {w[1]["name"]: i for i, w in areas.items()}
    assert "Lab 101" in names and "L1-A002" in names and "L1-A003" in names and "Floor 1" in names
    for i, (refs, tags) in areas.items():
        assert refs[0] == refs[-1] and len(refs) >= 4
        assert tags["level"] == "1" and tags["height"] == "3.2"
        assert tags["osmAG:areatype"] in ("room", "corridor", "structure")
        assert tags["indoor"] == {"corridor": "corridor", "structure": "area"}.get(tags["osmAG:areatype"], "room")
        assert tags["osmAG:areaType"] == tags["osmAG:areatype"]
        if tags["name"] != "Floor 1":
            assert tags["osmAG:parent"] == "Floor 1"
    assert areas[names["L1-A003"]][1]["osmAG:areatype"] == "corridor"
    # shared nodes between adjacent areas; passage nodes belong to both areas
    assert stats["shared_nodes"] >= 6
    for refs, tags in passages.values():
        assert len(refs) == 2 and tags["level"] == "1" and tags["name"].startswith("L1-P")
        for key in ("osmAG:from", "osmAG:to"):
            arefs = areas[names[tags[key]]][0]
            assert refs[0] in arefs and refs[1] in arefs
    assert stats["holes_dropped"] >= 1  # the pillars
    # what the osmAG authors' C++ parser demands of the root node, and JOSM's attributes everywhere
    r = roots[0]
    assert r.get("root") == "true" and all(r.get(k) is not None for k in ("alt", "qx", "qy", "qz"))
    assert list(root).index(r) == 0  # the root node comes first (nodes before it would abort that parser)
    for el in list(nodes.values()) + list(root.iter("way")):
        assert el.get("action") == "modify" and el.get("visible") == "true"
    # renderer-friendly tags: door=yes on every passage end node, and only there
    door_nodes = {i for i, n in nodes.items() if any(t.get("k") == "door" and t.get("v") == "yes" for t in n)}
    ends = {r for refs, _ in passages.values() for r in refs}
    assert door_nodes == ends and len(ends) >= 2 * len(passages) - 2
    # areas are written before the passages that reference them
    kinds = [w[1]["osmAG:type"] for w in ways.values()]
    order = [dict((t.get("k"), t.get("v")) for t in w.iter("tag"))["osmAG:type"] for w in root.iter("way")]
    assert order == sorted(order)  # "area" < "passage"


def test_level_must_be_numeric_and_ref_and_indoor_are_written(tmp_path):
    from shapely.geometry import box

    path = tmp_path / "r.osm"
    with pytest.raises(InputError, match="level 'F3' is not a number"):
        write_osmag(str(path), [Area(1, box(0, 0, 4, 4))], frame=FRAME, level="F3")
    assert not path.exists()
    areas = [Area(1, box(0, 0, 4, 4), type="stairs", ref="E1-ST-03"),
             Area(2, box(4, 0, 8, 4), type="room", tags={"indoor": "area"}),
             Area(3, box(0, 4, 8, 6), type="corridor")]
    write_osmag(str(path), areas, [Passage(1, 1, 3, LineString([(1, 4), (2, 4)]))], frame=FRAME, level="-1")
    _, _, ways = _parse(path)
    tags = {w[1].get("name"): w[1] for w in ways.values()}
    assert tags["L-1-A001"]["ref"] == "E1-ST-03" and tags["L-1-A001"]["indoor"] == "room"
    assert tags["L-1-A001"]["osmAG:areatype"] == "stairs"
    assert tags["L-1-A002"]["indoor"] == "area" and "ref" not in tags["L-1-A002"]
    assert tags["L-1-A003"]["indoor"] == "corridor"
    assert tags["L-1-P001"]["level"] == "-1"


def test_osmium_accepts(written):
    if not shutil.which("osmium"):
        pytest.skip("osmium-tool is not installed (make install provides it)")
    path, stats = written
    r = subprocess.run(["osmium", "fileinfo", "-e", str(path)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert f"Number of ways: {stats['areas'] + stats['structure_areas'] + stats['passages']}" in r.stdout
    assert f"Number of nodes: {stats['nodes']}" in r.stdout


def test_gdal_osm_driver_sees_polygons_with_tags(written, refined):
    from osgeo import gdal, ogr

    path, stats = written
    gdal.UseExceptions()
    # GDAL's default node index rejects negative (new-object) ids; this documented option lifts that
    gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", "NO")
    try:
        ds = ogr.Open(str(path))
        lyr = ds.GetLayerByName("multipolygons")
        feats = [(f.GetField("name"), f.GetField("other_tags"), f.GetGeometryRef().Area()) for f in lyr]
        assert len(feats) == len(refined.areas) + 1
        for name, other, area in feats:
            assert name and area > 0
            assert '"osmAG:type"=>"area"' in other and '"osmAG:areatype"=>' in other and '"level"=>"1"' in other
        lines = [(f.GetField("name"), f.GetField("other_tags")) for f in ds.GetLayerByName("lines")]
        assert len(lines) == len(refined.passages)
        assert all('"osmAG:type"=>"passage"' in o for _, o in lines)
        ds = None
    finally:
        gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", None)


def _ring_xy(poly):
    return np.asarray(poly.exterior.coords)


def test_round_trip(written, refined, tmp_path):
    path, _ = written
    a1, p1, root1, rep1 = read_osmag(str(path))
    assert rep1["variant"] == "semantic" and not rep1["unclosed"] and not rep1["dangling_refs"]
    assert root1 == pytest.approx((121.5906, 31.179))
    # geometry back in the CAD frame equals the refined polygons within 1 mm
    cad_a, cad_p = to_frame(a1, p1, FRAME)
    byname = {a.name: a for a in cad_a}
    src = {a.id: a for a in refined.areas}
    for aid, nm in [(1, "Lab 101"), (2, "L1-A002"), (3, "L1-A003"), (4, "L1-A004")]:
        d = byname[nm].polygon.exterior.hausdorff_distance(src[aid].polygon.exterior)
        assert d <= 1e-3, (nm, d)
    # export again from the loaded layers (in EPSG:4326) and load: same everything
    structure = [a for a in a1 if a.type == "structure"]
    rooms = [a for a in a1 if a.type != "structure"]
    out2 = tmp_path / "again.osm"
    write_osmag(str(out2), rooms, p1, crs="EPSG:4326", root=root1, level="1", height=3.2, structure_areas=structure)
    a2, p2, root2, rep2 = read_osmag(str(out2))
    assert root2 == pytest.approx(root1, abs=1e-10)
    m1 = {a.name: a for a in a1}
    m2 = {a.name: a for a in a2}
    assert set(m1) == set(m2)
    for nm, a in m1.items():
        b = m2[nm]
        assert a.tags == b.tags
        ca, cb = _ring_xy(a.polygon), _ring_xy(b.polygon)
        assert len(ca) == len(cb)
        d = geodesic_distance(ca[:, 0], ca[:, 1], cb[:, 0], cb[:, 1])
        assert np.max(d) <= 1e-3
    n1 = {p.name: (p.tags, np.asarray(p.line.coords)) for p in p1}
    n2 = {p.name: (p.tags, np.asarray(p.line.coords)) for p in p2}
    assert set(n1) == set(n2)
    for k in n1:
        assert n1[k][0] == n2[k][0]
        assert np.abs(n1[k][1] - n2[k][1]).max() < 1e-9
    # the file itself is reproduced byte for byte
    assert Path(path).read_text() == out2.read_text()


def test_fix_id_variant(refined, tmp_path):
    path = tmp_path / "fixid.osm"
    write_osmag(str(path), refined.areas, refined.passages, frame=FRAME, level="-1", variant="fix-id")
    _, _, ways = _parse(path)
    area_ids = {i for i, w in ways.items() if w[1]["osmAG:type"] == "area"}
    for refs, tags in ways.values():
        if tags["osmAG:type"] == "passage":
            assert int(tags["osmAG:from"]) in area_ids and int(tags["osmAG:to"]) in area_ids
            assert tags["level"] == "-1"
    a, p, _, rep = read_osmag(str(path))
    assert rep["variant"] == "fix-id" and len(p) == len(refined.passages)
    assert {x.name for x in a} >= {"L-1-A002", "Lab 101"}


def test_unrefined_graph_nodes_are_shared(tmp_path):
    # straight from polygonize: collinear vertices are missing on one side of shared borders
    g = graph_from_labels(synthetic_labels(), 0.0, 20.0, RES)
    path = tmp_path / "raw.osm"
    stats = write_osmag(str(path), g.areas, g.passages, frame=FRAME)
    assert stats["vertices_inserted"] > 0
    assert not [w for w in stats["warnings"] if "passage" in w]
    _, _, ways = _parse(path)
    names = {w[1]["name"]: w[0] for w in ways.values() if w[1]["osmAG:type"] == "area"}
    for refs, tags in ways.values():
        if tags["osmAG:type"] == "passage":
            assert set(refs) <= set(names[tags["osmAG:from"]]) and set(refs) <= set(names[tags["osmAG:to"]])


@pytest.mark.parametrize("fname,variant", [("osmag_semantic.osm", "semantic"), ("osmag_fixid.osm", "fix-id")])
def test_hand_written_examples_load(fname, variant):
    areas, passages, root, rep = read_osmag(str(DATA / fname))
    assert rep["variant"] == variant
    assert root == pytest.approx((121.59, 31.18))
    assert sorted(a.name for a in areas) == ["Corridor 1", "Floor 1", "Room 101", "Room 102"]
    by_id = {a.id: a for a in areas}
    types = {a.name: a.type for a in areas}
    assert types == {"Floor 1": "structure", "Room 101": "room", "Room 102": "room", "Corridor 1": "corridor"}
    conn = sorted((p.name, by_id[p.from_id].name, by_id[p.to_id].name) for p in passages)
    assert conn == [("D1", "Room 101", "Room 102"), ("D2", "Room 102", "Corridor 1")]
    parents = {by_id[c].name: by_id[p].name for c, p in rep["parents"].items()}
    assert parents == {"Room 101": "Floor 1", "Room 102": "Floor 1", "Corridor 1": "Floor 1"}
    # the door D1 is ~2.2 m wide (2e-5 degrees of latitude)
    d1 = [p for p in passages if p.name == "D1"][0]
    c = np.asarray(d1.line.coords)
    assert geodesic_distance(c[0, 0], c[0, 1], c[1, 0], c[1, 1]) == pytest.approx(2.218, abs=0.01)
    assert not rep["unclosed"] and not rep["dangling_nodes"] and not rep["dangling_refs"]


def test_hand_written_example_reexports(tmp_path):
    areas, passages, root, _ = read_osmag(str(DATA / "osmag_fixid.osm"))
    st = [a for a in areas if a.type == "structure"]
    rooms = [a for a in areas if a.type != "structure"]
    out = tmp_path / "x.osm"
    stats = write_osmag(str(out), rooms, passages, crs="EPSG:4326", root=root, structure_areas=st)
    assert stats["shared_nodes"] >= 6 and not stats["warnings"]
    a2, p2, _, rep = read_osmag(str(out))
    by_id = {a.id: a for a in a2}
    assert {by_id[c].name: by_id[p].name for c, p in rep["parents"].items()}["Room 101"] == "Floor 1"
    assert sorted(p.name for p in p2) == ["D1", "D2"]


def test_bad_files_on_load(tmp_path):
    with pytest.raises(InputError, match="not an osmAG file"):
        read_osmag(str(DATA / "not_osmag.osm"))
    bad = tmp_path / "x.osm"
    bad.write_text("this is not xml")
    with pytest.raises(InputError, match="not an OSM XML file"):
        read_osmag(str(bad))
    with pytest.raises(InputError, match="does not exist"):
        read_osmag(str(tmp_path / "missing.osm"))
    areas, passages, root, rep = read_osmag(str(DATA / "broken_osmag.osm"))
    assert [a.name for a in areas] == ["A"]
    assert rep["dangling_nodes"] == {-3: [-99]}
    assert rep["unclosed"] == [-4]
    assert (-5, "osmAG:to", "Nowhere") in rep["dangling_refs"]
    assert passages == []
    assert any("-99" in w for w in rep["warnings"])


def test_bad_input_on_write_leaves_nothing(refined, tmp_path):
    path = tmp_path / "out.osm"
    bad_p = list(refined.passages) + [Passage(77, 1, 555, LineString([(0, 0), (1, 0)]))]
    with pytest.raises(InputError, match=r"passages reference missing areas: 77 \(1->555\)"):
        write_osmag(str(path), refined.areas, bad_p, frame=FRAME)
    assert not path.exists() and not list(tmp_path.iterdir())
    with pytest.raises(InputError, match=r"areas \[42\] have empty geometries"):
        write_osmag(str(path), list(refined.areas) + [Area(42, Polygon())], [], frame=FRAME)
    bow = Polygon([(40, 0), (45, 5), (45, 0), (40, 5)])
    with pytest.raises(InputError, match="area 43 has an invalid polygon"):
        write_osmag(str(path), list(refined.areas) + [Area(43, bow)], [], frame=FRAME)
    with pytest.raises(InputError, match="georeference"):
        write_osmag(str(path), refined.areas, refined.passages)
    with pytest.raises(InputError, match="variant"):
        write_osmag(str(path), refined.areas, refined.passages, frame=FRAME, variant="other")
    # an existing file is left untouched by a failing export
    path.write_text("previous")
    with pytest.raises(InputError):
        write_osmag(str(path), refined.areas, bad_p, frame=FRAME)
    assert path.read_text() == "previous"
    assert sorted(os.listdir(tmp_path)) == ["out.osm"]


def test_conflicting_areatype_spellings_are_reported(tmp_path):
    """Both spellings are written; if an editor changes only one, the reader says so instead of guessing."""
    from shapely.geometry import box

    from algorithms.georef import LocalFrame
    from algorithms.model import Area
    from algorithms.osmag import read_osmag, write_osmag

    path = tmp_path / "a.osm"
    write_osmag(str(path), [Area(1, box(0, 0, 4, 4), type="room", name="R1")], frame=LocalFrame(10.0, 50.0))
    text = path.read_text().replace('k="osmAG:areaType" v="room"', 'k="osmAG:areaType" v="stairs"')
    path.write_text(text)
    areas, _, _, report = read_osmag(str(path))
    assert areas[0].type == "room"
    assert any("osmAG:areaType=stairs" in w and "edited" in w for w in report["warnings"])


# --------------------------------------------------------------------------- rings that touch themselves
@pytest.mark.parametrize("ring, kind", [
    # a gallery round a void: the ring goes round the outside, in along a zero-width cut, round the void
    # (clockwise) and back out the same cut: the cut's two nodes are visited twice
    ([(0, 0), (10, 0), (10, 6), (6, 6), (6, 14), (14, 14), (14, 6), (10, 6), (10, 0), (20, 0), (20, 20), (0, 20)],
     "slit"),
    # a zero-width finger out of a room (out and back along the same nodes)
    ([(0, 0), (10, 0), (10, 10), (5, 10), (5, 13), (5, 15), (5, 13), (5, 10), (0, 10)], "spike"),
    # two lobes touching at one node
    ([(0, 0), (4, 0), (4, 4), (8, 4), (8, 8), (4, 8), (4, 4), (0, 4)], "touch"),
])
def test_a_ring_visiting_a_vertex_twice_is_opened_and_stays_one_ring(ring, kind):
    from algorithms.model import PINCH_OPEN, open_ring_pinches, valid_polygon

    poly = Polygon(ring)
    assert not poly.is_valid
    for p in (poly, Polygon(ring[::-1])):  # either orientation
        fixed = valid_polygon(p)
        assert fixed.is_valid and fixed.geom_type == "Polygon" and len(fixed.interiors) == 0, kind
        assert fixed.area == pytest.approx(abs(poly.area), abs=20 * PINCH_OPEN)
        # every vertex of the ring is still on it (within the opening), the first visits exactly
        for xy in ring:
            assert fixed.exterior.distance(Point(xy)) <= 1e-9
        assert open_ring_pinches(fixed) is None  # nothing left to open
    # a valid polygon is returned as given
    ok = Polygon([(0, 0), (1, 0), (1, 1)])
    assert valid_polygon(ok) is ok


def test_writer_opens_a_ring_that_would_visit_a_node_twice(tmp_path):
    """A C-shaped area whose ends are 0.4 um apart (below the 1e-6 m shared-node precision) is written as a
    simple way: no node twice, and it reads back valid, as one ring of the same area."""
    frame = LocalFrame(121.5906, 31.1790)
    w = 4e-7
    g = Polygon([(0, 0), (10, 0), (10, 6), (6, 6), (6, 14), (14, 14), (14, 6), (10 + w, 6), (10 + w, 0),
                 (20, 0), (20, 20), (0, 20)])
    assert g.is_valid
    out = tmp_path / "f.osm"
    write_osmag(str(out), [Area(1, g, type="corridor"), Area(2, Polygon([(6, 6), (14, 6), (14, 14), (6, 14)]),
                                                             type="stairs")],
                [Passage(1, 1, 2, LineString([(6, 9), (6, 10)]))], frame=frame)
    root = ET.parse(out).getroot()
    for way in root.iter("way"):
        refs = [nd.get("ref") for nd in way.iter("nd")]
        assert len(set(refs[:-1])) == len(refs) - 1
    areas, passages, _, _ = read_osmag(str(out))
    areas, passages = to_frame(areas, passages, frame)
    a = [x for x in areas if x.type == "corridor"][0]
    assert a.polygon.is_valid and a.polygon.area == pytest.approx(g.area, rel=1e-3)
