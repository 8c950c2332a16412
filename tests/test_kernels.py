"""The compiled kernels (algorithms/kernels.py, numba) give exactly what the numpy code gives.

Every helper that has a compiled path runs twice on the same random input, once with the kernels
forced off and once on; the outputs must be equal array for array. Without numba the comparison
is skipped (the numpy path is what runs, and the rest of the suite tests it)."""
import numpy as np
import pytest

from algorithms import kernels

from .test_speed_equivalence import _random_rooms


@pytest.fixture(params=["build", "numba"])
def both_paths(request, monkeypatch):
    """Run a callable with the numpy path and with a compiled one (the ahead-of-time build, or numba's
    kernels); restores the default after."""
    if request.param == "numba":
        monkeypatch.setattr(kernels, "AOT", False)
    kernels.set_enabled(True)
    mod = kernels.get()
    if mod is None:
        kernels.set_enabled(None)
        pytest.skip("numba is not installed: only the numpy path exists")
    if request.param == "build" and not isinstance(mod, kernels._AotKernels):
        kernels.set_enabled(None)
        pytest.skip("no ahead-of-time build here (scripts/build_kernels.py)")

    def run(fn):
        kernels.set_enabled(False)
        try:
            plain = fn()
        finally:
            kernels.set_enabled(True)
        return plain, fn()

    yield run
    kernels.set_enabled(None)


def _same(a, b):
    if isinstance(a, tuple):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            _same(x, y)
    else:
        assert a.dtype == b.dtype and a.shape == b.shape
        assert np.array_equal(a, b)


def _blobs(seed, shape=(97, 131), keep=0.72):
    """Random free space: noise opened into rooms, passages and pillars (thinning's hard cases:
    one-pixel bridges, loops, diagonal steps)."""
    import cv2

    rng = np.random.default_rng(seed)
    img = (rng.random(shape) < keep).astype(np.uint8)
    img = cv2.morphologyEx(img, cv2.MORPH_OPEN, np.ones((2, 2), np.uint8))
    img[rng.integers(0, shape[0], 6), :] = 1  # long one-pixel corridors
    img[:, rng.integers(0, shape[1], 4)] = 1
    return img.astype(bool)


@pytest.mark.parametrize("seed", range(10))
def test_thinning_equals_numpy(both_paths, seed):
    from algorithms.skeleton import thin

    mask = _blobs(seed) if seed % 2 else _random_rooms(seed)[0]
    plain, fast = both_paths(lambda: thin(mask))
    _same(plain, fast)
    assert fast.sum() > 0


def test_thinning_with_float64_clearance_and_a_border_touching_mask(both_paths):
    from algorithms.segmentation import _edt
    from algorithms.skeleton import thin

    mask = np.ones((40, 60), bool)  # touches every border: the padded image takes care of it
    mask[10:14, 20:45] = False
    dist = _edt(mask).astype(np.float64) + 1e-9
    plain, fast = both_paths(lambda: thin(mask, dist))
    _same(plain, fast)


@pytest.mark.parametrize("seed", range(10))
def test_basins_equal_numpy(both_paths, seed):
    from algorithms.segmentation import _cells

    free, dist = _random_rooms(seed) if seed % 2 else (_blobs(seed), None)
    plain, fast = both_paths(lambda: _cells(free, dist)[1:])
    _same(plain, fast)


def test_basins_of_plateaus_and_ties(both_paths):
    """Equal clearance everywhere on a ridge: the first direction wins a tie, on both paths."""
    from algorithms.segmentation import _cells

    free = np.zeros((30, 50), bool)
    free[5:25, 3:47] = True
    dist = np.where(free, 2.0, 0.0).astype(np.float32)
    dist[10:20, 10:40] = 3.0
    plain, fast = both_paths(lambda: _cells(free, dist)[1:])
    _same(plain, fast)


def _seeds_and_zones(seed, shape=(120, 160)):
    """Free space, scattered seed pixels with labels 1..n, and zones (the clearance basins) in
    which every label lies whole, some zones holding several labels and some none."""
    from algorithms.segmentation import _cells

    rng = np.random.default_rng(seed)
    free, dist = _random_rooms(seed, shape)
    _, basins, _ = _cells(free, dist)
    seeds = np.zeros(shape, np.int32)
    rr, cc = np.nonzero(free)
    pick = rng.choice(len(rr), size=min(len(rr), 60), replace=False)
    seeds[rr[pick], cc[pick]] = np.arange(1, len(pick) + 1, dtype=np.int32)
    # short seed runs (several pixels of one label), one label per run
    for k in range(1, len(pick) + 1, 7):
        r, c = rr[pick[k - 1]], cc[pick[k - 1]]
        run = free[r, c:c + 5] & (basins[r, c:c + 5] == basins[r, c])
        seeds[r, c:c + 5][run] = k
    # drop the seeds of a few zones: they are filled from their neighbours (fill_zones)
    for z in rng.choice(int(basins.max()) + 1, size=3):
        seeds[basins == z] = 0
    return seeds, free, basins


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("zoned", [False, True])
def test_nearest_seed_regions_equal_numpy(both_paths, seed, zoned):
    from algorithms.skeleton import nearest_seed_regions

    seeds, space, zones = _seeds_and_zones(seed)
    plain, fast = both_paths(lambda: nearest_seed_regions(seeds, space, zones if zoned else None))
    _same(plain, fast)
    assert (fast[space] > 0).mean() > 0.9


@pytest.mark.parametrize("seed", range(6))
def test_orphan_regrowth_equals_numpy(both_paths, seed):
    """Labels split into pieces by walls: the pieces without a seed of their label are cleared and
    grown into from their neighbours, the same on both paths (zoned and not)."""
    from algorithms.skeleton import _regrow_orphans

    rng = np.random.default_rng(seed)
    seeds, space, zones = _seeds_and_zones(seed)
    lab = np.where(space, rng.integers(1, 9, space.shape), 0).astype(np.int32)
    lab = np.repeat(np.repeat(lab[::8, ::8], 8, 0), 8, 1)[:space.shape[0], :space.shape[1]] * space
    lab = lab.astype(np.int32)
    sd = np.where(space & (rng.random(space.shape) < 0.01), lab, 0).astype(np.int32)
    label_zone = rng.integers(0, int(zones.max()) + 1, 10)
    label_zone[0] = 0
    plain, fast = both_paths(lambda: _regrow_orphans(lab.copy(), sd, space))
    _same(plain, fast)
    plain, fast = both_paths(lambda: _regrow_orphans(lab.copy(), sd, space, zones, label_zone))
    _same(plain, fast)


def test_the_path_that_runs_is_logged():
    from algorithms.progress import RecordingProgress
    from algorithms.sample_building import generate_building  # noqa: F401  (import check only)

    kernels.set_enabled(False)
    try:
        assert "numpy" in kernels.describe()
    finally:
        kernels.set_enabled(None)
    if kernels.get() is not None:
        assert "compiled kernels" in kernels.describe()
    p = RecordingProgress()
    from algorithms import segmentation
    from algorithms.model import OccupancyGrid

    data = np.full((60, 80), 255, np.uint8)
    data[5:55, 5:75] = 0
    segmentation.segment(OccupancyGrid(data=data, resolution=0.05, origin_x=0.0, origin_y=0.0), progress=p)
    assert "pixel loops:" in p.text()


def test_environment_switch_forces_numpy(monkeypatch):
    monkeypatch.setenv("CAD2OSMAG_NUMBA", "0")
    kernels.set_enabled(None)
    try:
        assert kernels.get() is None
        assert "CAD2OSMAG_NUMBA=0" in kernels.describe()
    finally:
        monkeypatch.delenv("CAD2OSMAG_NUMBA")
        kernels.set_enabled(None)


@pytest.mark.parametrize("seed", range(5))
def test_neighbour_pairs_equal_numpy(both_paths, seed):
    from algorithms.segmentation import _cell_graph, _cells, _neighbour_pairs

    free, dist = _random_rooms(seed)
    _, cells, _ = _cells(free, dist)
    plain, fast = both_paths(lambda: _neighbour_pairs(cells, dist))
    _same(plain, fast)
    assert len(fast[0]) > 0
    plain, fast = both_paths(lambda: _neighbour_pairs(cells))
    _same(plain, fast)
    plain, fast = both_paths(lambda: _cell_graph(cells, dist))
    _same(plain, fast)


@pytest.mark.qgis_process
def test_qgis_process_segment_runs_the_kernels_and_gives_the_numpy_result(tmp_path):
    """Inside QGIS the package is ``cad2osmag.algorithms``, in the tests ``algorithms``: the kernels'
    cache, written by either, must load in both (it failed with ModuleNotFoundError before the
    kernels got one fixed module name). The labels equal the numpy path's."""
    from osgeo import gdal

    from algorithms import segmentation
    from algorithms.raster_io import write_grid

    from .qgis_process import run_alg
    from .test_segmentation import Plan

    plan = Plan()
    path = tmp_path / "plan.tif"
    write_grid(str(path), plan.grid)
    kernels.get()  # writes / loads the cache under this process's package name first
    out = tmp_path / "labels.tif"
    _, res, log = run_alg("segment", {"INPUT": path, "DOOR_WIDTH": 1.0, "CORRIDOR_WIDTH": 2.0,
                                      "AREAS": tmp_path / "a.gpkg", "PASSAGES": tmp_path / "p.gpkg", "LABELS": out})
    assert "pixel loops:" in log
    if kernels.get() is not None:
        assert "compiled kernels (" in log, log[-2000:]
    kernels.set_enabled(False)
    try:
        ref = segmentation.segment(plan.grid, door_width=1.0, corridor_width=2.0)
    finally:
        kernels.set_enabled(None)
    assert res["AREA_COUNT"] == len(ref.areas)
    lab = gdal.Open(str(out)).ReadAsArray()
    assert np.array_equal(lab, ref.labels)


def test_preload_loads_in_a_thread_and_get_waits_for_it(monkeypatch):
    """``preload`` starts the load beside the caller; ``get`` returns the same choice as a load in the caller's
    thread (it waits for the load, never answers "numpy" because the load is still running); ``describe``
    does not wait, and says the kernels are still loading."""
    import threading

    expected = kernels.get() is not None  # this environment's choice, loaded in the caller's thread
    kernels.set_enabled(None)
    gate = threading.Event()
    real, real_aot = kernels._load, kernels._load_aot

    def slow(load):  # both load paths wait: the ahead-of-time one loads in a millisecond, before describe asks
        def wait_then_load():
            gate.wait(10)
            return load()
        return wait_then_load

    monkeypatch.setattr(kernels, "_load", slow(real))
    monkeypatch.setattr(kernels, "_load_aot", slow(real_aot))
    try:
        kernels.preload()
        kernels.preload()  # a second call starts no second load
        th = kernels._STATE["thread"]
        assert th is not None and th.name == "cad2osmag-kernels"
        if expected:
            assert "loading" in kernels.describe() and not kernels._STATE["loaded"]
        gate.set()
        assert (kernels.get() is not None) == expected
        assert kernels._STATE["loaded"] and not th.is_alive()
        assert ("compiled kernels" in kernels.describe()) == expected and "loading" not in kernels.describe()
    finally:
        gate.set()
        monkeypatch.setattr(kernels, "_load", real)
        monkeypatch.setattr(kernels, "_load_aot", real_aot)
        kernels.set_enabled(None)


def test_preload_respects_the_environment_switch(monkeypatch):
    monkeypatch.setenv("CAD2OSMAG_NUMBA", "0")
    kernels.set_enabled(None)
    try:
        kernels.preload()
        assert kernels.get() is None and "CAD2OSMAG_NUMBA=0" in kernels.describe()
    finally:
        monkeypatch.delenv("CAD2OSMAG_NUMBA")
        kernels.set_enabled(None)


@pytest.mark.slow
@pytest.mark.qgis_process
def test_qgis_process_conversion_preloads_the_kernels_and_writes_the_same_map(tmp_path):
    """``cad2osmag:dxftoosmag`` headless: the kernels load in their thread beside the conversion
    (``kernels.preload``), the log names the path, and the map is the one this process writes with the
    kernels loaded before the conversion started (the areas and passages of both files are equal)."""
    from algorithms import osmag, pipeline, sample_building

    from .qgis_process import run_alg

    info = sample_building.generate_open_anchors(str(tmp_path))
    out = tmp_path / "qgis.osm"
    _, res, log = run_alg("dxftoosmag", {"INPUT": info["dxf"], "OUTPUT": str(out), "LEVEL": 1}, headless=True)
    assert "pixel loops:" in log
    if kernels.get() is not None:  # loaded here first: this process's conversion does not preload
        assert "pixel loops: compiled kernels (" in log, log[-2000:]
    ref = tmp_path / "here.osm"
    pipeline.convert_dxf(info["dxf"], str(ref), level="1")
    a1, p1, _r1, _ = osmag.read_osmag(str(out))
    a2, p2, _r2, _ = osmag.read_osmag(str(ref))
    key = lambda a: (a.type, round(a.polygon.area, 3), round(a.polygon.centroid.x, 3), round(a.polygon.centroid.y, 3))
    assert sorted(map(key, a1)) == sorted(map(key, a2)) and len(a1) > 3
    assert len(p1) == len(p2) > 2


def test_a_compiling_load_is_noted_once():
    """A load that compiled (> 3 CPU s: the first use on a machine) is reported once by ``compile_note``,
    which a preloaded conversion logs after the segmentation; a cached load is not."""
    kernels.set_enabled(None)
    try:
        if kernels.get() is None:
            assert kernels.compile_note() == ""
            return
        assert kernels.compile_note() == ""  # loaded from the cache in well under 3 s
        kernels._STATE["load_s"] = 14.2
        note = kernels.compile_note()
        assert "compiled on this first use in 14 s" in note and kernels.compile_note() == ""
    finally:
        kernels.set_enabled(None)


# ------------------------------------------------------------------ the ahead-of-time build
def _aot_or_skip():
    kernels.set_enabled(None)
    mod = kernels.get()
    if not isinstance(mod, kernels._AotKernels):
        pytest.skip("no ahead-of-time build here (scripts/build_kernels.py)")
    return mod


def test_the_build_loads_without_numba_and_says_so():
    """A fresh process with the build imports no numba: the fixed cost of every conversion process."""
    import subprocess
    import sys

    _aot_or_skip()
    code = ("import sys; sys.path.insert(0, '.'); from algorithms import kernels; m = kernels.get(); "
            "print(type(m).__name__, 'numba' in sys.modules, kernels.describe())")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         cwd=str(__import__("pathlib").Path(__file__).resolve().parents[1])).stdout
    assert out.startswith("_AotKernels False pixel loops: compiled kernels (ahead-of-time build")


def test_arguments_outside_the_built_signatures_run_numba_with_the_same_result():
    """The build's wrappers do not check types (a float64 clearance would be read as float32): every call is
    checked, and another dtype, a strided array where a contiguous one is built or a read-only one goes to
    numba's kernel."""
    mod = _aot_or_skip()
    mask = _blobs(3)
    dist = (mask * 2.0).astype(np.float32)
    specs = mod._by_base["thin_setup"][0][1]
    assert kernels._fits(specs, (mask, dist))
    assert not kernels._fits(specs, (mask, dist.astype(np.float64)))
    assert not kernels._fits(specs, (mask[:, ::2], dist[:, ::2]))
    ro = dist.copy()
    ro.flags.writeable = False
    assert not kernels._fits(specs, (mask, ro))
    assert not kernels._fits(mod._by_base["grow_rounds"][0][1],
                             (np.zeros(3, np.int32), np.zeros(1, np.int64), 1, 3, np.zeros(3, np.int32),
                              np.zeros(1, np.int64), 1))  # an int where a bool is built
    a = mod.thin_setup(mask, dist.astype(np.float64))  # numba's float64 kernel
    b = mod.thin_setup(mask, dist)
    _same(a, b)  # the clearance's values are the same in both dtypes here


def test_a_stale_build_is_not_loaded(monkeypatch):
    """Built from another ``_kernels_nb.py`` (its stamp differs): numba's kernels run instead."""
    _aot_or_skip()
    monkeypatch.setattr(kernels, "source_digest", lambda: "0" * 64)
    kernels.set_enabled(None)
    try:
        mod = kernels.get()
        assert mod is not None and not isinstance(mod, kernels._AotKernels)
    finally:
        monkeypatch.undo()
        kernels.set_enabled(None)


def test_signature_table_parses():
    specs = kernels._arg_specs("Tuple((u1[:, ::1], i4[::1]))(i4[:, :], i4[:, ::1], i8, b1)")
    assert specs == ((np.dtype(np.int32), 2, False), (np.dtype(np.int32), 2, True), ("i8", None, None),
                     ("b1", None, None))
    assert {base for _n, base, _s in kernels.AOT_EXPORTS} == {
        "thin_setup", "thin_layers", "thin_rest", "ascent_basins", "grow_rounds", "orphan_pieces", "zone_seeds",
        "zone_assign", "neighbour_pairs", "label_boxes"}


def test_the_build_releases_the_gil():
    """The segmentation runs kernels on its second thread beside the first (``segmentation._Background``): the
    build's wrappers must release the GIL as numba's ``nogil`` kernels do (``scripts/build_kernels.py`` sets
    numba's ``release_gil`` flag for them). Such wrappers call ``PyEval_SaveThread``; a build without the flag
    does not reference it (checked on a build made without it)."""
    _aot_or_skip()
    path, _stamp = kernels.aot_paths()
    with open(path, "rb") as fh:
        assert b"PyEval_SaveThread" in fh.read()
