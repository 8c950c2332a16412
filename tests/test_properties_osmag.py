"""Property tests of the osmAG writer and reader (algorithms/osmag.py) with hypothesis.

- Random valid area graphs (a random grid of rooms sharing walls, random names, types, extra tags with
  XML-special and non-ASCII characters, passages on shared walls, a random anchor and rotation, both
  variants) round-trip exactly: every area comes back with its name (the generated id when unnamed), type,
  tags, and its outline within 1 mm; every passage with its name, its two areas and its ends within 1 mm.
- Random invalid graphs are rejected by the writer naming the offending id (duplicate ids, passages to
  missing areas); files with unclosed ways, dangling passages, missing nodes or duplicate ids are read
  with exactly those ids reported.
- The osmAG files of other tools (../shared/data/osmag/) load with their defects reported.
"""
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Polygon, box

from algorithms.errors import InputError
from algorithms.georef import LocalFrame
from algorithms.model import Area, Passage
from algorithms.osmag import generated_name, read_osmag, to_frame, write_osmag

PROPS = dict(derandomize=True, deadline=None, database=None,
             suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
TAG_KEYS = st.text(alphabet="abcdefghijklmnopqrstuvwxyz:_", min_size=1, max_size=12).filter(
    lambda k: k.lower() not in {"osmag:type", "osmag:areatype", "indoor", "level", "height", "name",
                                "osmag:parent", "area", "osmag:from", "osmag:to"})
TAG_VALUES = st.text(alphabet=st.characters(blacklist_categories=("Cs", "Cc")), min_size=1, max_size=20).filter(
    lambda v: v.strip() == v and v != "")
NAMES = st.text(alphabet=st.characters(blacklist_categories=("Cs", "Cc", "Zs", "Zl", "Zp")), min_size=1, max_size=16)


@st.composite
def area_graphs(draw):
    """A rows x cols grid of rectangular rooms (random widths/heights in metres) sharing their walls."""
    nr, nc = draw(st.integers(1, 4)), draw(st.integers(1, 4))
    xs = np.concatenate([[0.0], np.cumsum(draw(st.lists(st.floats(2.0, 30.0), min_size=nc, max_size=nc)))])
    ys = np.concatenate([[0.0], np.cumsum(draw(st.lists(st.floats(2.0, 30.0), min_size=nr, max_size=nr)))])
    ox, oy = draw(st.floats(-500, 500)), draw(st.floats(-500, 500))
    xs, ys = np.round(xs + ox, 3), np.round(ys + oy, 3)
    names = draw(st.lists(st.one_of(st.just(""), NAMES), min_size=nr * nc, max_size=nr * nc))
    assume(len({n for n in names if n}) == len([n for n in names if n]))  # duplicate names are renamed
    ids = draw(st.lists(st.integers(1, 10 ** 6), min_size=nr * nc, max_size=nr * nc, unique=True))
    areas, cell = [], {}
    for r in range(nr):
        for c in range(nc):
            k = r * nc + c
            tags = draw(st.dictionaries(TAG_KEYS, TAG_VALUES, max_size=3))
            a = Area(id=ids[k], polygon=box(xs[c], ys[r], xs[c + 1], ys[r + 1]),
                     type=draw(st.sampled_from(["room", "corridor", "stairs", "elevator"])), name=names[k], tags=tags)
            areas.append(a)
            cell[(r, c)] = a
    assume(all(a.name != generated_name("1", "A", b.id) for a in areas for b in areas))
    passages, pid = [], 1
    for (r, c), a in cell.items():
        for dr, dc in ((0, 1), (1, 0)):
            b = cell.get((r + dr, c + dc))
            if b is None or not draw(st.booleans()):
                continue
            if dc:  # vertical shared wall at x = xs[c+1]
                x = xs[c + 1]
                y0 = ys[r] + draw(st.floats(0.1, 0.4)) * (ys[r + 1] - ys[r])
                line = LineString([(x, round(y0, 3)), (x, round(y0 + 0.9, 3))])
            else:
                y = ys[r + 1]
                x0 = xs[c] + draw(st.floats(0.1, 0.4)) * (xs[c + 1] - xs[c])
                line = LineString([(round(x0, 3), y), (round(x0 + 0.9, 3), y)])
            passages.append(Passage(id=pid, from_id=a.id, to_id=b.id, line=line,
                                    name=draw(st.one_of(st.just(""), NAMES.map(lambda s: "door " + s))),
                                    tags=draw(st.dictionaries(TAG_KEYS, TAG_VALUES, max_size=2))))
            pid += 1
    assume(len({p.name for p in passages if p.name}) == len([p for p in passages if p.name]))
    frame = LocalFrame(draw(st.floats(-179, 179)), draw(st.floats(-80, 80)), rotation_deg=draw(st.floats(-180, 180)))
    variant = draw(st.sampled_from(["semantic", "fix-id"]))
    return areas, passages, frame, variant


def _outline_close(p: Polygon, q: Polygon, tol=1e-3):
    return p.hausdorff_distance(q) <= tol and abs(p.area - q.area) <= tol * p.length


@settings(max_examples=35, **PROPS)
@given(graph=area_graphs())
def test_valid_area_graphs_round_trip_exactly(graph, tmp_path_factory):
    areas, passages, frame, variant = graph
    path = tmp_path_factory.mktemp("rt") / "g.osm"
    write_osmag(str(path), areas, passages, frame=frame, level="1", variant=variant)
    got_a, got_p, root, report = read_osmag(str(path))
    assert report["unclosed"] == [] and report["dangling_refs"] == [] and report["dangling_nodes"] == {}
    assert report["duplicate_ids"] == {"node": [], "way": []}
    assert root == pytest.approx((frame.anchor_lon, frame.anchor_lat), abs=1e-9)
    assert report["variant"] in ((variant if passages else "none"), "semantic" if variant == "semantic" else "fix-id")
    local_a, local_p = to_frame(got_a, got_p, frame)
    by_name = {a.name: a for a in local_a}
    assert len(by_name) == len(local_a) == len(areas)
    for a in areas:
        name = a.name or generated_name("1", "A", a.id)
        b = by_name[name]
        assert b.type == a.type
        for k, v in a.tags.items():
            assert b.tags.get(k) == v, (name, k)
        assert _outline_close(a.polygon, b.polygon), (name, a.polygon.wkt, b.polygon.wkt)
    id_to_name = {a.id: (a.name or generated_name("1", "A", a.id)) for a in areas}
    got_name = {a.id: a.name for a in local_a}
    pmap = {p.name: p for p in local_p}
    assert len(pmap) == len(passages)
    for p in passages:
        q = pmap[p.name or generated_name("1", "P", p.id)]
        assert {got_name[q.from_id], got_name[q.to_id]} == {id_to_name[p.from_id], id_to_name[p.to_id]}
        assert (got_name[q.from_id], got_name[q.to_id]) == (id_to_name[p.from_id], id_to_name[p.to_id])
        ends = np.array(q.line.coords)
        want = np.array(p.line.coords)
        assert np.abs(ends - want).max() <= 1e-3 or np.abs(ends[::-1] - want).max() <= 1e-3
        for k, v in p.tags.items():
            assert q.tags.get(k) == v


# ------------------------------------------------------------------------------------------ invalid graphs
@settings(max_examples=20, **PROPS)
@given(graph=area_graphs(), data=st.data())
def test_writer_rejects_duplicate_ids_naming_them(graph, data, tmp_path_factory):
    areas, passages, frame, _ = graph
    assume(len(areas) >= 2)
    i, j = data.draw(st.sampled_from([(i, j) for i in range(len(areas)) for j in range(len(areas)) if i < j]))
    areas[j].id = areas[i].id
    path = tmp_path_factory.mktemp("dup") / "g.osm"
    with pytest.raises(InputError, match=rf"duplicate area ids \[{areas[i].id}\]"):
        write_osmag(str(path), areas, [], frame=frame)
    assert not path.exists()


@settings(max_examples=20, **PROPS)
@given(graph=area_graphs(), missing=st.integers(-10 ** 6, 0), data=st.data())
def test_writer_rejects_dangling_passages_naming_them(graph, missing, data, tmp_path_factory):
    areas, passages, frame, _ = graph
    bad = Passage(id=data.draw(st.integers(500, 900)), from_id=areas[0].id, to_id=missing,
                  line=LineString([(0, 0), (1, 0)]))
    path = tmp_path_factory.mktemp("dang") / "g.osm"
    with pytest.raises(InputError, match=rf"passages reference missing areas: {bad.id} \({areas[0].id}->{missing}\)"):
        write_osmag(str(path), areas, passages + [bad], frame=frame)
    assert not path.exists()


@settings(max_examples=20, **PROPS)
@given(graph=area_graphs(), data=st.data())
def test_writer_rejects_duplicate_passage_ids_naming_them(graph, data, tmp_path_factory):
    areas, passages, frame, _ = graph
    assume(len(passages) >= 2)
    i, j = data.draw(st.sampled_from([(i, j) for i in range(len(passages)) for j in range(len(passages)) if i < j]))
    passages[j].id = passages[i].id  # a passage feature copied in QGIS keeps its id
    path = tmp_path_factory.mktemp("dupp") / "g.osm"
    with pytest.raises(InputError, match=rf"duplicate passage ids \[{passages[i].id}\] \(level 1\)"):
        write_osmag(str(path), areas, passages, frame=frame)
    assert not path.exists()


@st.composite
def broken_files(draw):
    areas, passages, frame, variant = draw(area_graphs())
    assume(passages)
    defect = draw(st.sampled_from(["unclosed", "dangling_passage", "missing_node", "duplicate_way",
                                   "duplicate_node", "nan_node"]))
    return areas, passages, frame, variant, defect, draw(st.randoms(use_true_random=False))


@settings(max_examples=35, **PROPS)
@given(case=broken_files())
def test_reader_reports_the_offending_id(case, tmp_path_factory):
    areas, passages, frame, variant, defect, rnd = case
    path = tmp_path_factory.mktemp("broken") / "g.osm"
    write_osmag(str(path), areas, passages, frame=frame, variant=variant)
    tree = ET.parse(path)
    osm = tree.getroot()
    area_ways = [w for w in osm.findall("way") if any(t.get("v") == "area" for t in w.findall("tag"))]
    passage_ways = [w for w in osm.findall("way") if any(t.get("v") == "passage" for t in w.findall("tag"))]
    nodes = [n for n in osm.findall("node") if not n.findall("tag")]
    if defect == "unclosed":
        w = rnd.choice(area_ways)
        w.remove(w.findall("nd")[-1])
    elif defect == "dangling_passage":
        w = rnd.choice(passage_ways)
        next(t for t in w.findall("tag") if t.get("k") == "osmAG:to").set("v", "no such area")
    elif defect == "missing_node":
        w = rnd.choice(area_ways)
        gone = w.findall("nd")[1].get("ref")
        for n in osm.findall("node"):  # tagged or not (a passage end carries door=yes)
            if n.get("id") == gone:
                osm.remove(n)
    elif defect == "duplicate_way":
        w = rnd.choice(area_ways)
        twin = ET.fromstring(ET.tostring(w))
        osm.append(twin)
    elif defect == "duplicate_node":
        n = rnd.choice(nodes)
        twin = ET.fromstring(ET.tostring(n))
        twin.set("lat", str(float(n.get("lat")) + 0.001))
        osm.insert(list(osm).index(n) + 1, twin)
    elif defect == "nan_node":
        n = rnd.choice(nodes)
        n.set("lat", "nan")
    tree.write(path, encoding="UTF-8", xml_declaration=True)
    got_a, got_p, _, report = read_osmag(str(path))
    text = "\n".join(report["warnings"])
    if defect == "unclosed":
        wid = int(w.get("id"))
        assert report["unclosed"] == [wid] and f"area way {wid} is not closed" in text
        assert wid not in {a.id for a in got_a}
    elif defect == "dangling_passage":
        wid = int(w.get("id"))
        assert (wid, "osmAG:to", "no such area") in report["dangling_refs"] and f"passage way {wid}" in text
        assert wid not in {p.id for p in got_p} and len(got_p) == len(passages) - 1
    elif defect == "missing_node":
        wid = int(w.get("id"))
        assert int(gone) in report["dangling_nodes"].get(wid, []) and f"{wid}" in text
    elif defect == "duplicate_way":
        assert report["duplicate_ids"]["way"] == [int(w.get("id"))] and f"way {w.get('id')} is defined twice" in text
        assert len(got_a) == len(areas)
    elif defect == "duplicate_node":
        assert report["duplicate_ids"]["node"] == [int(n.get("id"))] and f"node {n.get('id')} is defined twice" in text
    elif defect == "nan_node":
        assert f"node {n.get('id')} has an invalid position" in text
        assert all(np.isfinite(np.array(a.polygon.exterior.coords)).all() for a in got_a)


# ------------------------------------------------------------------------------------------ other tools' files
@pytest.mark.parametrize("fname,areas,passages,unclosed,dangling,root", [
    ("fix_id_ShanghaiTech_merge_2.osm", 270, 257, 0, 58, True),
    ("semantic_tags_SIST_1.osm", 179, 157, 3, 76, True),
    ("show_sist_f1_v5.osm", 28, 0, 5, 0, False),
    ("show_sist_merge_v1.osm", 56, 61, 4, 3, False),
])
def test_other_tools_files_load_with_their_defects_reported(shared_data, fname, areas, passages, unclosed, dangling,
                                                            root):
    got_a, got_p, got_root, report = read_osmag(str(shared_data / "osmag" / fname))
    assert (len(got_a), len(got_p)) == (areas, passages)
    assert len(report["unclosed"]) == unclosed and len(report["dangling_refs"]) == dangling
    assert (got_root is not None) == root
    if not root:
        assert "no root node (name=root)" in report["warnings"]
    for wid in report["unclosed"]:
        assert any(f"area way {wid} is not closed" in w for w in report["warnings"])
    for wid, key, value in report["dangling_refs"]:
        assert any(str(wid) in w and (value in w) for w in report["warnings"]), (wid, key, value)
    if fname.startswith("fix_id"):  # the README: 56 passages point at areas named out / out1
        outs = [r for r in report["dangling_refs"] if re.fullmatch(r"out1?", r[2])]
        assert len(outs) == 56


# ------------------------------------------------------------------------------------------ ids exactly
@settings(max_examples=25, **PROPS)
@given(graph=area_graphs())
def test_ids_come_back_and_a_read_file_rewrites_byte_for_byte(graph, tmp_path_factory):
    """Ids exactly (issue 13): every area way comes back under the way id the writer gave it, every passage
    between those ids; writing the file read (WGS84, same root) reproduces it byte for byte (node and way ids,
    node order, tags, coordinates at the written precision)."""
    areas, passages, frame, variant = graph
    folder = tmp_path_factory.mktemp("ids")
    first, second = folder / "a.osm", folder / "b.osm"
    stats = write_osmag(str(first), areas, passages, frame=frame, level="1", variant=variant)
    got_a, got_p, root, _ = read_osmag(str(first))
    assert {a.id for a in got_a} == set(stats["way_ids"].values())
    by_way = {stats["way_ids"][a.id]: a for a in areas}
    for b in got_a:
        assert b.name == stats["names"][by_way[b.id].id]
    want_ends = {(stats["way_ids"][p.from_id], stats["way_ids"][p.to_id]) for p in passages}
    assert {(p.from_id, p.to_id) for p in got_p} == want_ends
    write_osmag(str(second), got_a, got_p, crs="EPSG:4326", root=root, level="1", variant=variant)
    assert second.read_bytes() == first.read_bytes()
