"""Open facades, room-name evidence, door hints and components through qgis_process (headless)."""
import numpy as np
import pytest

from algorithms.raster_io import write_grid
from algorithms.sample_building import generate_open_facade

from .qgis_process import run_alg
from .test_segmentation_evidence import _grid_of, _two_rooms_with_leaf


def _rows(path, fields):
    from osgeo import ogr

    ds = ogr.Open(str(path))
    return [{k: f.GetField(k) for k in fields} for f in ds.GetLayer(0)]


def _write_points(path, pts):
    from osgeo import ogr

    ds = ogr.GetDriverByName("GPKG").CreateDataSource(str(path))
    layer = ds.CreateLayer("texts", geom_type=ogr.wkbPoint)
    layer.CreateField(ogr.FieldDefn("text", ogr.OFTString))
    for text, (x, y) in pts.items():
        f = ogr.Feature(layer.GetLayerDefn())
        f.SetField("text", text)
        f.SetGeometry(ogr.CreateGeometryFromWkt(f"POINT ({x} {y})"))
        layer.CreateFeature(f)
    ds = None


def _write_lines(path, lines):
    from osgeo import ogr

    ds = ogr.GetDriverByName("GPKG").CreateDataSource(str(path))
    layer = ds.CreateLayer("doors", geom_type=ogr.wkbLineString)
    for (x0, y0), (x1, y1) in lines:
        f = ogr.Feature(layer.GetLayerDefn())
        f.SetGeometry(ogr.CreateGeometryFromWkt(f"LINESTRING ({x0} {y0}, {x1} {y1})"))
        layer.CreateFeature(f)
    ds = None


@pytest.mark.qgis_process
def test_segment_open_facade_with_texts_gives_one_component(tmp_path):
    from algorithms.sample_building import open_facade_plan

    walls, rooms, doors, labels = open_facade_plan(hall_width=14.0)  # hall wider than the footprint scale
    grid = _grid_of(walls, (-6.0, -6.0, 44.0, 21.0))
    write_grid(str(tmp_path / "plan.tif"), grid)
    _write_points(tmp_path / "texts.gpkg", labels)
    out = {"AREAS": tmp_path / "areas.gpkg", "PASSAGES": tmp_path / "passages.gpkg", "LABELS": tmp_path / "labels.tif"}
    _, res, log = run_alg("segment", {"INPUT": tmp_path / "plan.tif", "TEXTS": tmp_path / "texts.gpkg",
                                      **{k: str(v) for k, v in out.items()}})
    assert res["COMPONENTS"] == 1 and res["LARGEST_COMPONENT_SHARE"] == pytest.approx(1.0)
    assert res["AREA_COUNT"] == len(rooms)
    assert "6 room-name points" in log and "kept inside on evidence" in log
    areas = _rows(out["AREAS"], ["id", "component", "area_m2"])
    assert {a["component"] for a in areas} == {0}
    assert sum(a["area_m2"] for a in areas) == pytest.approx(sum(p.area for p in rooms.values()), rel=0.05)


@pytest.mark.qgis_process
def test_rasterize_and_segment_keep_door_hints_open(tmp_path):
    geoms, hint = _two_rooms_with_leaf()
    from osgeo import ogr

    ds = ogr.GetDriverByName("GPKG").CreateDataSource(str(tmp_path / "walls.gpkg"))
    layer = ds.CreateLayer("walls", geom_type=ogr.wkbLineString)
    for g in geoms:
        f = ogr.Feature(layer.GetLayerDefn())
        f.SetGeometry(ogr.CreateGeometryFromWkt("LINESTRING (" + ", ".join(f"{x} {y}" for x, y in g.coords) + ")"))
        layer.CreateFeature(f)
    ds = None
    _write_lines(tmp_path / "doors.gpkg", [((hint.x0, hint.y0), (hint.x1, hint.y1))])
    for with_doors in (False, True):
        extra = {"DOORS": tmp_path / "doors.gpkg"} if with_doors else {}
        tif = tmp_path / f"occ{int(with_doors)}.tif"
        run_alg("rasterize", {"WALLS": tmp_path / "walls.gpkg", "RESOLUTION": 0.05, "OCCUPANCY": tif, **extra})
        out = {"AREAS": tmp_path / f"a{int(with_doors)}.gpkg", "PASSAGES": tmp_path / f"p{int(with_doors)}.gpkg",
               "LABELS": tmp_path / f"l{int(with_doors)}.tif"}
        _, res, log = run_alg("segment", {"INPUT": tif, "DOOR_WIDTH": 1.0, "CORRIDOR_WIDTH": 2.0,
                                          **{k: str(v) for k, v in out.items()}})
        if with_doors:
            assert res["COMPONENTS"] == 1 and res["PASSAGE_COUNT"] == 1
        else:
            assert res["COMPONENTS"] == 2 and res["PASSAGE_COUNT"] == 0
            assert "2 connected components" in log
            comps = sorted(a["component"] for a in _rows(out["AREAS"], ["component"]))
            assert comps == [0, 1]


@pytest.mark.qgis_process
def test_dxftoosmag_open_facade_sample(tmp_path):
    sample = generate_open_facade(str(tmp_path))
    _, res, log = run_alg("dxftoosmag", {"INPUT": sample["dxf"], "OUTPUT": str(tmp_path / "f.osm")})
    assert res["AREA_COUNT"] == len(sample["rooms"])
    assert res["PASSAGE_COUNT"] >= len(sample["doors"])
    assert "connected components" not in log  # one component: nothing to report


@pytest.mark.slow
@pytest.mark.qgis_process
def test_dxftoosmag_casona_no_raw_exception(shared_data, tmp_path):
    """The plan that crashed with a raw GEOS TopologyException in refine."""
    path = shared_data / "dxf" / "archweb" / "CASONA_DE_YANAHUARA.dxf"
    code, res, log = run_alg("dxftoosmag", {"INPUT": path, "OUTPUT": str(tmp_path / "c.osm")})
    assert "Traceback" not in log and "GEOSException" not in log
    assert res["AREA_COUNT"] > 10
    assert (tmp_path / "c.osm").is_file()
