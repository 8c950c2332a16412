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
    cache.process_floor(sample_dxf, level="2")  # other arguments: another conversion
    assert cache.misses == 2


def test_cached_convert_writes_the_same_osmag(sample_dxf, tmp_path):
    cache = FloorCache(tmp_path / "cache")
    out = cache.convert_dxf(sample_dxf, tmp_path / "a.osm")
    cache.convert_dxf(sample_dxf, tmp_path / "b.osm")
    ref = pipeline.convert_dxf(sample_dxf, str(tmp_path / "ref.osm"))
    assert (cache.misses, cache.hits) == (1, 1)
    assert (tmp_path / "a.osm").read_bytes() == (tmp_path / "b.osm").read_bytes() == (tmp_path / "ref.osm").read_bytes()
    assert {k: out[k] for k in ("areas", "passages", "components")} == {k: ref[k] for k in ("areas", "passages", "components")}
    assert {k: v for k, v in out["osm"].items() if k != "path"} == {k: v for k, v in ref["osm"].items() if k != "path"}
    areas = osmag.read_osmag(str(tmp_path / "a.osm"))[0]
    assert len([a for a in areas if a.type != "structure"]) == ref["areas"]


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
