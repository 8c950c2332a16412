"""Room names headless (qgis_process): assignnames stage by stage, NAMES in dxftoosmag, user renames
surviving export with the passages following them."""
import pytest

from algorithms import osmag
from algorithms.sample_building import generate_building

from .qgis_process import run_alg

ANCHOR = "121.5906,31.1790 [EPSG:4326]"


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    return generate_building(str(tmp_path_factory.mktemp("names")), floors=1, seed=0)


def _features(path, layer=None):
    from osgeo import ogr

    ds = ogr.Open(str(path))
    lyr = ds.GetLayer(0) if layer is None else ds.GetLayerByName(layer)
    defn = lyr.GetLayerDefn()
    names = [defn.GetFieldDefn(i).GetName() for i in range(defn.GetFieldCount())]
    return names, [{n: f.GetField(n) for n in names} for f in lyr]


@pytest.mark.qgis_process
def test_assignnames_stage_by_stage(sample, tmp_path):
    d = tmp_path
    run_alg("extractstructure", {"INPUT": sample["dxf"][0], "WALLS": str(d / "walls.gpkg"), "TEXTS": str(d / "texts.gpkg")})
    tnames, texts = _features(d / "texts.gpkg")
    assert {"text", "layer", "entity", "block", "tag", "id"} <= set(tnames)
    assert sorted(t["id"] for t in texts) == list(range(len(texts)))
    run_alg("rasterize", {"WALLS": str(d / "walls.gpkg"), "OCCUPANCY": str(d / "occ.tif")})
    run_alg("segment", {"INPUT": str(d / "occ.tif"), "STRUCTURE": str(d / "walls.gpkg"), "AREAS": str(d / "areas.gpkg"),
                        "PASSAGES": str(d / "passages.gpkg"), "LABELS": str(d / "labels.tif")})
    run_alg("refine", {"AREAS": str(d / "areas.gpkg"), "PASSAGES": str(d / "passages.gpkg"),
                       "OUTPUT_AREAS": str(d / "rareas.gpkg"), "OUTPUT_PASSAGES": str(d / "rpass.gpkg")})
    _, res, log = run_alg("assignnames", {
        "AREAS": str(d / "rareas.gpkg"), "TEXTS": str(d / "texts.gpkg"), "PASSAGES": str(d / "rpass.gpkg"),
        "LEVEL": "2", "OUTPUT_AREAS": str(d / "named.gpkg"), "OUTPUT_PASSAGES": str(d / "npass.gpkg"),
        "TEXT_REPORT": str(d / "report.gpkg")})
    assert "room names" in log and res["CONFLICTS"] == 0 and res["OUTSIDE"] == 0
    fields, areas = _features(d / "named.gpkg")
    assert {"id", "type", "name", "ref", "indoor", "room", "label_score", "label_texts", "label_conflict"} <= set(fields)
    by_name = {a["name"]: a for a in areas}
    expected = set(sample["names"][0])
    assert expected <= set(by_name), expected - set(by_name)  # every named room of the sample gets its name
    assert by_name["Stair A"]["type"] == "stairs" and by_name["Lift 1"]["type"] == "elevator"
    assert by_name["WC"]["room"] == "toilets" and by_name["Office 101"]["room"] == "office"
    assert by_name["Corridor"]["type"] == "corridor" and by_name["Corridor"]["indoor"] == "corridor"
    assert all(a["label_score"] > 0 and a["label_texts"] for a in areas if a["name"] in expected)
    unnamed = [a["name"] for a in areas if a["name"] not in expected]
    assert all(n.startswith("2-") for n in unnamed)  # generated ids <level>-<id>
    assert res["NAMED"] == len(expected)
    _, report = _features(d / "report.gpkg")
    roles = {}
    for r in report:
        roles.setdefault(r["role"], []).append(r["reason"])
    assert len(roles["name"]) == len(expected) and "axis (layer)" in roles["ignored"]


@pytest.mark.qgis_process
def test_dxftoosmag_names_switch_and_renames_survive_export(sample, tmp_path):
    out = tmp_path / "named.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": sample["dxf"][0], "OUTPUT": str(out), "ANCHOR": ANCHOR,
                                         "OUTPUT_AREAS": str(tmp_path / "areas.gpkg"),
                                         "OUTPUT_PASSAGES": str(tmp_path / "passages.gpkg")})
    areas, passages, _, _ = osmag.read_osmag(str(out))
    names = {a.name: a for a in areas}
    assert set(sample["names"][0]) <= set(names)
    assert names["Office 101"].tags["room"] == "office" and names["Office 101"].tags["indoor"] == "room"
    assert names["Stair A"].type == "stairs" and names["Lift 1"].type == "elevator"
    assert not any(k.startswith("label_") for a in areas for k in a.tags)  # layer fields stay out of osmAG
    # NAMES off: generated names only
    off = tmp_path / "plain.osm"
    run_alg("dxftoosmag", {"INPUT": sample["dxf"][0], "OUTPUT": str(off), "ANCHOR": ANCHOR, "NAMES": "false"})
    plain, _, _, _ = osmag.read_osmag(str(off))
    assert "Office 101" not in {a.name for a in plain}
    # the user renames an area in the AREAS layer and exports again: passages follow the new name
    from osgeo import ogr

    ds = ogr.Open(str(tmp_path / "areas.gpkg"), 1)
    lyr = ds.GetLayer(0)
    old = "Office 101"
    lyr.CreateField(ogr.FieldDefn("ref", ogr.OFTString))  # the sample has no room numbers: the user adds them
    for f in lyr:
        if f.GetField("name") == old:
            f.SetField("name", "Director")
        elif f.GetField("name") == "Office 105":  # a stair the segmentation typed as a room, fixed by hand
            f.SetField("name", "Stair B")
            f.SetField("osmAG:areatype", "stairs")
            f.SetField("room", "stairs")
            f.SetField("ref", "S-2")
        elif f.GetField("name") == "Hall":
            f.SetField("indoor", "area")
            f.SetField("ref", "H0")
        lyr.SetFeature(f)
    ds = None
    again = tmp_path / "renamed.osm"
    run_alg("exportosmag", {"AREAS": str(tmp_path / "areas.gpkg"), "PASSAGES": str(tmp_path / "passages.gpkg"),
                            "OUTPUT": str(again)})
    areas2, passages2, _, report = osmag.read_osmag(str(again))
    names2 = {a.name for a in areas2}
    assert "Director" in names2 and old not in names2
    ends = [(p.tags["osmAG:from"], p.tags["osmAG:to"]) for p in passages2]
    assert any("Director" in e for e in ends) and not any(old in e for e in ends)
    assert len(passages2) == len(passages) and not report["dangling_refs"]
    # every edit is written as it is, in both variants; in fix-id the passages follow the edited areas by id
    fixid = tmp_path / "renamed-fixid.osm"
    run_alg("exportosmag", {"AREAS": str(tmp_path / "areas.gpkg"), "PASSAGES": str(tmp_path / "passages.gpkg"),
                            "VARIANT": 1, "OUTPUT": str(fixid)})
    for path, variant in ((again, "semantic"), (fixid, "fix-id")):
        got, gp, _, rep = osmag.read_osmag(str(path))
        assert rep["variant"] == variant and not rep["dangling_refs"] and len(gp) == len(passages)
        by = {a.name: a for a in got}
        stair, hall = by["Stair B"], by["Hall"]
        assert (stair.type, stair.tags["room"], stair.tags["ref"]) == ("stairs", "stairs", "S-2")
        assert (hall.tags["indoor"], hall.tags["ref"]) == ("area", "H0")
        name_of = {a.id: a.name for a in got}
        assert {name_of[q.from_id] for q in gp} | {name_of[q.to_id] for q in gp} >= {"Director", "Stair B"}


@pytest.mark.qgis_process
def test_texts_of_frozen_layers_name_rooms_headless(tmp_path):
    from .test_semantics_hidden import _plan_with_frozen_annotations

    d = tmp_path
    dxf = str(d / "frozen.dxf")
    _plan_with_frozen_annotations(dxf)
    _, res, _ = run_alg("extractstructure", {"INPUT": dxf, "WALLS": str(d / "walls.gpkg"), "TEXTS": str(d / "texts.gpkg")})
    assert res["TEXT_COUNT"] == 1  # the visible texts
    fields, texts = _features(d / "texts.gpkg")
    assert "hidden" in fields
    assert sorted(t["text"] for t in texts if t["hidden"]) == ["Archive", "Laboratory", "Store"]
    assert sorted(t["id"] for t in texts) == [0, 1, 2, 3]
    run_alg("rasterize", {"WALLS": str(d / "walls.gpkg"), "OCCUPANCY": str(d / "occ.tif")})
    run_alg("segment", {"INPUT": str(d / "occ.tif"), "STRUCTURE": str(d / "walls.gpkg"), "AREAS": str(d / "areas.gpkg"),
                        "PASSAGES": str(d / "passages.gpkg"), "LABELS": str(d / "labels.tif")})
    _, res, log = run_alg("assignnames", {"AREAS": str(d / "areas.gpkg"), "TEXTS": str(d / "texts.gpkg"),
                                          "OUTPUT_AREAS": str(d / "named.gpkg")})
    assert "frozen/off layers" in log
    _, areas = _features(d / "named.gpkg")
    assert sorted(a["name"] for a in areas) == ["Laboratory", "Office", "Store"]
