"""The whole pipeline (algorithms.pipeline), stair/lift typing and the building merge, on the sample building."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from shapely.geometry import box

from algorithms import building, osmag, pipeline
from algorithms.area_types import classify_vertical_areas
from algorithms.errors import InputError
from algorithms.georef import LocalFrame
from algorithms.model import Area, CadGeometry
from algorithms.progress import RecordingProgress
from algorithms.sample_building import generate_building, ground_truth_doors, ground_truth_rooms

ANCHOR = (121.5906, 31.1790)


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sample")
    return generate_building(str(folder), floors=2, seed=0)


@pytest.fixture(scope="module")
def converted(sample, tmp_path_factory):
    out = tmp_path_factory.mktemp("osm")
    files, stats = [], []
    for k, dxf in enumerate(sample["dxf"], 1):
        path = str(out / f"floor-{k}.osm")
        rec = RecordingProgress()
        stats.append((pipeline.convert_dxf(dxf, path, preview_png=str(out / f"floor-{k}.png"),
                                           anchor_lon=ANCHOR[0], anchor_lat=ANCHOR[1], level=str(k),
                                           progress=rec), rec))
        files.append(path)
    return files, stats, out


def _iou(a, b):
    return a.intersection(b).area / a.union(b).area


def test_every_ground_truth_space_is_one_typed_area_in_the_osmag_file(sample, converted):
    files, stats, _ = converted
    for k, (path, gt_path) in enumerate(zip(files, sample["ground_truth"]), 1):
        areas, passages, root, report = osmag.read_osmag(path)
        assert root == pytest.approx(ANCHOR, abs=1e-9)
        assert report["unclosed"] == [] and report["dangling_refs"] == [] and report["dangling_nodes"] == {}
        frame = LocalFrame(*ANCHOR)
        areas, passages = osmag.to_frame(areas, passages, frame)
        spaces = [a for a in areas if a.type != "structure"]
        matched = {}
        for room in ground_truth_rooms(gt_path):
            best = max(spaces, key=lambda a: a.polygon.intersection(room["polygon"]).area)
            assert _iou(best.polygon, room["polygon"]) >= 0.8, (k, room["name"])
            assert best.type == room["areatype"], (room["name"], best.type)
            matched[room["name"]] = best.id
        assert len(set(matched.values())) == len(matched) == len(spaces)
        # each door between two spaces is one passage between the right two areas
        pairs = {frozenset((p.from_id, p.to_id)) for p in passages}
        for door in ground_truth_doors(gt_path):
            if door["from"] in matched and door["to"] in matched:
                assert frozenset((matched[door["from"]], matched[door["to"]])) in pairs, door
        # the floor outline is the parent of every area
        floor = [a for a in areas if a.type == "structure"]
        assert len(floor) == 1 and floor[0].name == f"Level {k}"
        assert all(a.tags.get("osmAG:parent") == f"Level {k}" for a in spaces)
        assert all(a.tags.get("level") == str(k) for a in areas)


def test_pipeline_reports_stage_times_and_figures(converted):
    _, stats, out = converted
    s, rec = stats[0]
    assert set(s["timings"]) == {"cad_import", "rasterize", "segment", "types", "refine", "names", "outline", "export"}
    assert set(s["cpu"]) == set(s["timings"])  # CPU seconds per stage beside the wall seconds
    assert s["unit"] == "mm" and s["areas"] >= 15 and s["passages"] >= 15
    assert s["osm"]["shared_nodes"] >= 2 * s["passages"]  # both ends of every passage are shared
    assert "stair/lift areas recognised" in rec.text()
    assert rec.percents[-1] == 100.0 and rec.percents == sorted(rec.percents)
    import cv2

    img = cv2.imread(str(out / "floor-1.png"))
    assert img is not None and min(img.shape[:2]) > 300


def test_no_anchor_warns_and_places_the_map_at_null_island(sample, tmp_path):
    rec = RecordingProgress()
    pipeline.convert_dxf(sample["dxf"][0], str(tmp_path / "f.osm"), progress=rec)
    assert any(kind == "warning" and "no anchor" in msg for kind, msg in rec.messages)
    _, _, root, _ = osmag.read_osmag(str(tmp_path / "f.osm"))
    assert root == pytest.approx((0.0, 0.0))


def test_bad_dxf_fails_clearly_and_writes_nothing(tmp_path):
    bad = tmp_path / "plan.dxf"
    bad.write_text("this is not a drawing")
    out = tmp_path / "out.osm"
    with pytest.raises(InputError, match="plan.dxf"):
        pipeline.convert_dxf(str(bad), str(out), anchor_lon=0.0, anchor_lat=0.0)
    assert not out.exists()
    with pytest.raises(InputError):
        pipeline.convert_dxf(str(bad), str(out), anchor_lon=0.0, anchor_lat=95.0)
    assert not out.exists()


def test_floor_outline_contains_all_areas_even_for_detached_parts():
    areas = [Area(1, box(0, 0, 4, 4)), Area(2, box(4.2, 0, 8, 4)), Area(3, box(30, 0, 34, 4))]
    outline = pipeline.floor_outline(areas)
    assert outline.geom_type == "Polygon" and not outline.interiors
    assert all(outline.contains(a.polygon) for a in areas)
    assert pipeline.floor_outline([]) is None


# --------------------------------------------------------------------------- stair / lift typing
def _geom(kind, pts, closed=False):
    return CadGeometry(layer=kind, kind=kind, coords=np.array(pts, float), closed=closed)


def test_stair_and_lift_symbols_type_their_areas_only():
    stair = Area(1, box(0, 0, 3, 5))
    lift = Area(2, box(3.2, 0, 5.2, 2))
    hall = Area(3, box(6, 0, 26, 20))  # contains one short stair stroke: stays a room
    geoms = [_geom("stair", [(0.2, y), (2.8, y)]) for y in np.arange(0.3, 4.8, 0.28)]
    geoms += [_geom("elevator", [(3.3, 0.1), (5.1, 0.1), (5.1, 1.9), (3.3, 1.9)], closed=True),
              _geom("elevator", [(3.3, 0.1), (5.1, 1.9)]), _geom("elevator", [(3.3, 1.9), (5.1, 0.1)]),
              _geom("stair", [(10, 10), (12, 10)])]
    changed = classify_vertical_areas([stair, lift, hall], geoms)
    assert changed == {1: "stairs", 2: "elevator"}
    assert (stair.type, lift.type, hall.type) == ("stairs", "elevator", "room")


# --------------------------------------------------------------------------- building merge
def test_merge_floors_into_one_building(converted, tmp_path):
    files, _, _ = converted
    out = tmp_path / "building.osm"
    stats = building.merge_floor_files(files, str(out), building_name="Sample")
    assert stats["levels"] == ["1", "2"] and stats["floors"] == 2
    areas, passages, root, report = osmag.read_osmag(str(out))
    assert root == pytest.approx(ANCHOR, abs=1e-9)
    assert report["dangling_refs"] == [] and report["unclosed"] == []
    per_file = [osmag.read_osmag(f) for f in files]
    assert len(areas) == sum(len(r[0]) for r in per_file) + 1
    # the floors' passages, plus one vertical passage per shaft (stair, lift) between levels 1 and 2
    assert stats["vertical_passages"] == 2
    assert len(passages) == sum(len(r[1]) for r in per_file) + 2
    names = {a.name: a for a in areas}
    assert names["Sample"].tags["level"] == "1;2"
    assert names["Level 1"].tags["osmAG:parent"] == "Sample" and names["Level 2"].tags["osmAG:parent"] == "Sample"
    assert names["Sample"].polygon.buffer(1e-9).contains(names["Level 1"].polygon)
    ids = [e.get("id") for e in ET.parse(out).getroot() if e.tag in ("node", "way")]
    assert all(int(i) < 0 for i in ids)
    roots = [n for n in ET.parse(out).getroot().findall("node") if any(t.get("v") == "root" for t in n)]
    assert len(roots) == 1


def test_merge_registers_floors_with_different_anchors(sample, converted, tmp_path):
    files, _, _ = converted
    other = tmp_path / "moved.osm"
    pipeline.convert_dxf(sample["dxf"][1], str(other), anchor_lon=ANCHOR[0] + 0.01, anchor_lat=ANCHOR[1], level="2")
    out = tmp_path / "building.osm"
    # ~950 m apart: the stair and the lift bring floor 2 back onto floor 1 (tests/test_building.py)
    stats = building.merge_floor_files([files[0], str(other)], str(out))
    assert stats["vertical_passages"] == 2 and stats["overall_rms"] < 0.2
    with pytest.raises(InputError):
        building.merge_floor_files([], str(out))


def test_merge_renumbers_fix_id_references(sample, tmp_path):
    files = []
    for k, dxf in enumerate(sample["dxf"], 1):
        files.append(str(tmp_path / f"f{k}.osm"))
        pipeline.convert_dxf(dxf, files[-1], anchor_lon=ANCHOR[0], anchor_lat=ANCHOR[1], level=str(k),
                             variant="fix-id")
    out = tmp_path / "b.osm"
    assert building.merge_floor_files(files, str(out))["variant"] == "fix-id"
    areas, passages, _, report = osmag.read_osmag(str(out))
    assert report["variant"] == "fix-id" and report["dangling_refs"] == []
    by_id = {a.id: a for a in areas}
    for p in passages:  # every passage joins two areas of its own level, except the vertical ones
        if p.tags.get("osmAG:vertical") != "yes":
            assert by_id[p.from_id].tags["level"] == by_id[p.to_id].tags["level"] == p.tags["level"]


@pytest.mark.parametrize("cancel_after", [1, 5, 12])
def test_cancel_at_any_stage_stops_and_writes_nothing(sample, tmp_path, cancel_after):
    from algorithms.errors import Canceled

    out, png = tmp_path / "f.osm", tmp_path / "f.png"
    with pytest.raises(Canceled):
        pipeline.convert_dxf(sample["dxf"][0], str(out), preview_png=str(png), anchor_lon=ANCHOR[0],
                             anchor_lat=ANCHOR[1], progress=RecordingProgress(cancel_after=cancel_after))
    assert not out.exists() and not png.exists()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_real_sist_floor_to_osmag_opens_in_real_clients(shared_data, tmp_path):
    """SIST-F3 (real, millimetres) through the whole pipeline, rotated 30° onto the Earth: osmium and GDAL
    open the file, every area is a polygon with its tags, and lengths survive georeferencing."""
    import subprocess

    from osgeo import gdal, ogr

    from algorithms.georef import geodesic_distance

    out = tmp_path / "sist3.osm"
    stats = pipeline.convert_dxf(str(shared_data / "dxf" / "sist" / "SIST-F3.dxf"), str(out),
                                 anchor_lon=ANCHOR[0], anchor_lat=ANCHOR[1], rotation_deg=30.0, level="3")
    assert stats["unit"] == "mm" and stats["areas"] >= 80 and stats["passages"] >= 60
    assert stats["refine"]["vertex_reduction"] >= 0.85
    assert subprocess.run(["osmium", "fileinfo", "-e", str(out)], capture_output=True).returncode == 0
    areas, passages, root, report = osmag.read_osmag(str(out))
    assert root == pytest.approx(ANCHOR, abs=1e-9) and report["dangling_refs"] == []
    assert len([a for a in areas if a.type != "structure"]) == stats["areas"]
    gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", "NO")
    try:
        ds = ogr.Open(str(out))
        polys = ds.GetLayerByName("multipolygons")
        names = {f.GetField("name") for f in polys}
    finally:
        gdal.SetConfigOption("OSM_USE_CUSTOM_INDEXING", None)
    assert names >= {a.name for a in areas}
    # a passage's width measured on the ellipsoid equals its width in the drawing (1 mm per 100 m)
    frame = LocalFrame(*ANCHOR, rotation_deg=30.0)
    cad_areas, cad_passages = osmag.to_frame(areas, passages, frame)
    for p, q in zip(passages[:20], cad_passages[:20]):
        (lon0, lat0), (lon1, lat1) = list(p.line.coords)
        assert geodesic_distance(lon0, lat0, lon1, lat1) == pytest.approx(q.line.length, abs=1e-5 * max(q.line.length, 1))
