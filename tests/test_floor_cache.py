"""The session cache of conversions (tests/conftest.py FloorCache) gives what the pipeline gives, once."""
import os

import numpy as np
import pytest

from algorithms import osmag, pipeline
from algorithms.errors import InputError
from algorithms.sample_building import generate_building

from .conftest import FloorCache


@pytest.fixture(scope="module")
def sample_dxf(tmp_path_factory):
    return generate_building(str(tmp_path_factory.mktemp("cache-sample")), floors=1, seed=2)["dxf"][0]


def test_cached_floor_equals_the_pipeline_and_is_computed_once(sample_dxf, tmp_path):
    cache = FloorCache(tmp_path / "cache")
    first = cache.process_floor(sample_dxf)
    again = cache.process_floor(sample_dxf, level="1")  # the default given explicitly: the same key
    assert (cache.misses, cache.hits) == (1, 1)
    direct = pipeline.process_floor(sample_dxf)
    for got in (first, again):
        assert np.array_equal(got.segmented.labels, direct.segmented.labels)
        assert [a.polygon.wkt for a in got.refined.areas] == [a.polygon.wkt for a in direct.refined.areas]
        assert [a.name for a in got.refined.areas] == [a.name for a in direct.refined.areas]
    assert first is not again and first.refined.areas[0] is not again.refined.areas[0]  # own copies
    cache.process_floor(sample_dxf, min_area=2.5)  # other arguments: another conversion
    assert cache.misses == 2


@pytest.fixture(scope="module")
def half_named_dxf(sample_dxf, tmp_path_factory):
    """The sample floor with every other text removed: some areas get generated ids (they carry the level)."""
    import ezdxf

    doc = ezdxf.readfile(sample_dxf)
    msp = doc.modelspace()
    for e in list(msp.query("TEXT MTEXT"))[::2]:
        msp.delete_entity(e)
    out = tmp_path_factory.mktemp("cache-half") / "half-named.dxf"
    doc.saveas(out)
    return str(out)


def _named(floor):
    return [(a.id, a.name, a.type, sorted(a.tags.items())) for a in floor.refined.areas]


def test_another_level_is_the_same_conversion_relevelled(half_named_dxf, tmp_path):
    """The level only names things: one conversion serves every level (test_real_plans converts the DWG sheets
    at level 1, test_building_dwg at their real levels), and gives what a conversion at that level gives."""
    cache = FloorCache(tmp_path / "cache")
    one = cache.process_floor(half_named_dxf)
    three = cache.process_floor(half_named_dxf, level="3")
    assert (cache.misses, cache.hits, cache.relevelled) == (1, 1, 1)
    direct = pipeline.process_floor(half_named_dxf, level="3")
    assert _named(three) == _named(direct) != _named(one)
    assert three.floor_area.name == direct.floor_area.name == "Level 3"
    auto = [a.name for a in three.refined.areas if a.name.startswith("3-")]
    assert len(auto) == three.names.auto > 0  # the generated ids are what changed
    assert np.array_equal(three.segmented.labels, direct.segmented.labels)


def test_relevel_refuses_when_a_name_could_differ(half_named_dxf, tmp_path, monkeypatch):
    """A drawing's name that a generated id of the new level would take (the real conversion suffixes the id):
    not re-levelled, and the cache converts at that level instead."""
    from . import conftest

    cache = FloorCache(tmp_path / "cache")
    floor = cache.process_floor(half_named_dxf)
    auto = [a for a in floor.refined.areas if a.name == f"1-{a.id}"]
    named = [a for a in floor.refined.areas if a.type != "structure" and a.name and a not in auto]
    assert auto and named
    named[0].name = f"3-{auto[0].id}"
    before = _named(floor)
    assert conftest.relevel(floor, "1", "3") is False and _named(floor) == before  # untouched
    auto[0].name = f"1-{auto[0].id}-2"  # a suffixed id: the same
    assert conftest.relevel(floor, "1", "3") is False
    monkeypatch.setattr(conftest, "relevel", lambda *a: False)
    got = cache.process_floor(half_named_dxf, level="3")
    assert (cache.misses, cache.relevelled) == (2, 0)
    assert _named(got) == _named(pipeline.process_floor(half_named_dxf, level="3"))


def test_cached_convert_writes_the_same_osmag(half_named_dxf, tmp_path):
    cache = FloorCache(tmp_path / "cache")
    out = cache.convert_dxf(half_named_dxf, tmp_path / "a.osm")
    cache.convert_dxf(half_named_dxf, tmp_path / "b.osm")
    ref = pipeline.convert_dxf(half_named_dxf, str(tmp_path / "ref.osm"))
    assert (cache.misses, cache.hits) == (1, 1)
    assert (tmp_path / "a.osm").read_bytes() == (tmp_path / "b.osm").read_bytes() == (tmp_path / "ref.osm").read_bytes()
    assert {k: out[k] for k in ("areas", "passages", "components")} == {k: ref[k] for k in ("areas", "passages", "components")}
    assert {k: v for k, v in out["osm"].items() if k != "path"} == {k: v for k, v in ref["osm"].items() if k != "path"}
    areas = osmag.read_osmag(str(tmp_path / "a.osm"))[0]
    assert len([a for a in areas if a.type != "structure"]) == ref["areas"]


def test_a_conversion_stores_its_import_and_a_read_is_what_import_dxf_gives(sample_dxf, tmp_path):
    from algorithms.cad_import import import_dxf

    cache = FloorCache(tmp_path / "cache")
    cache.process_floor(sample_dxf)
    assert (cache.import_misses, cache.import_hits) == (1, 0)
    got = cache.import_dxf(sample_dxf)  # what the conversion read, before the pipeline used it
    assert (cache.import_misses, cache.import_hits, cache.misses) == (1, 1, 1)
    ref = import_dxf(sample_dxf)
    assert [(g.layer, g.kind, g.coords.tolist()) for g in got.geometries] == \
        [(g.layer, g.kind, g.coords.tolist()) for g in ref.geometries]
    assert [(t.text, t.x, t.y, t.layer) for t in got.texts] == [(t.text, t.x, t.y, t.layer) for t in ref.texts]
    assert (got.unit_name, got.warnings, len(got.doors)) == (ref.unit_name, ref.warnings, len(ref.doors))
    cache.import_dxf(sample_dxf, include_doors=True)  # other arguments: another read
    assert cache.import_misses == 2


def test_input_errors_are_cached_and_raised_again(tmp_path):
    bad = tmp_path / "broken.dxf"
    bad.write_text("this is not a drawing\n")
    cache = FloorCache(tmp_path / "cache")
    for _ in range(2):
        with pytest.raises(InputError, match="broken.dxf"):
            cache.process_floor(str(bad))
    assert (cache.misses, cache.hits) == (1, 1)
    bad.write_text("still not a drawing, but changed\n")  # a changed file is a new key
    os.utime(bad, ns=(1, 1))
    with pytest.raises(InputError):
        cache.process_floor(str(bad))
    assert cache.misses == 2
