"""Issue 13: the segmentation runs independent raster passes of one floor on two threads
(``segmentation._Background``: the footprint disk's reach beside the envelope's, the clearance basins
beside the skeleton, the clearance transform and the envelope transform in two row strips). The results
must be those of the serial code bit for bit, on any number of threads; ``CAD2OSMAG_THREADS=1`` runs
everything in line.

Small synthetic rasters (1-1.2 Mpx: the strips need >= 6 x SPLIT_MARGIN rows and OpenCV's large-image
path), each transform a few ms."""
import numpy as np
import pytest

from algorithms import segmentation as seg


def _rooms(seed, shape=(1200, 900), hall=False):
    """Free space of random rectangles with pillars and specks; ``hall``: a free hall 600 px across over
    the middle rows (the strips' check fails there: its clearance exceeds the margin)."""
    rng = np.random.default_rng(seed)
    img = np.zeros(shape, bool)
    for _ in range(60):
        r0, c0 = rng.integers(2, shape[0] - 40), rng.integers(2, shape[1] - 40)
        img[r0:r0 + rng.integers(10, 260), c0:c0 + rng.integers(10, 300)] = True
    for _ in range(200):
        r, c = rng.integers(0, shape[0]), rng.integers(0, shape[1])
        img[r:r + rng.integers(1, 5), c:c + rng.integers(1, 5)] = False
    if hall:
        img[shape[0] // 2 - 300:shape[0] // 2 + 300, 100:shape[1] - 100] = True
    img[:2] = img[-2:] = False
    return img


@pytest.fixture
def threads_on(monkeypatch):
    monkeypatch.setenv("CAD2OSMAG_THREADS", "2")
    monkeypatch.setattr(seg, "_cpus", lambda: 2)


def test_background_returns_the_value_and_raises_the_error_in_the_caller(monkeypatch):
    for env in ("2", "1"):
        monkeypatch.setenv("CAD2OSMAG_THREADS", env)
        assert seg._Background(lambda: 6 * 7).result() == 42

        def boom():
            raise ValueError("in the helper")

        job = seg._Background(boom)
        with pytest.raises(ValueError, match="in the helper"):
            job.result()


def test_threads_are_off_on_one_cpu_or_when_asked(monkeypatch):
    monkeypatch.setattr(seg, "_cpus", lambda: 1)
    monkeypatch.delenv("CAD2OSMAG_THREADS", raising=False)
    assert not seg._threads_on()
    monkeypatch.setattr(seg, "_cpus", lambda: 2)
    assert seg._threads_on()
    monkeypatch.setenv("CAD2OSMAG_THREADS", "1")
    assert not seg._threads_on()


@pytest.mark.parametrize("seed,hall", [(0, False), (1, False), (2, True)])
def test_clearance_in_two_strips_equals_the_whole_transform_bit_for_bit(seed, hall, threads_on, monkeypatch):
    mask = _rooms(seed, hall=hall)
    whole = seg._edt(mask)
    calls = []
    edt = seg._edt
    monkeypatch.setattr(seg, "_edt", lambda m: calls.append(m.shape) or edt(m))
    got = seg._edt_split(mask)
    assert got.dtype == np.float32 and np.array_equal(got, whole)
    m = seg.SPLIT_MARGIN
    strips = [(mask.shape[0] // 2 + m, mask.shape[1]), (mask.shape[0] - mask.shape[0] // 2 + m, mask.shape[1])]
    # the strips ran; with the hall over the split rows their check failed and the whole was computed
    assert calls == strips + ([mask.shape] if hall else [])
    if hall:
        assert whole[mask.shape[0] // 2].max() > m


def test_clearance_strips_are_not_used_on_a_short_raster_or_without_threads(monkeypatch):
    mask = _rooms(3, shape=(600, 1800))
    calls = []
    edt = seg._edt
    monkeypatch.setattr(seg, "_edt", lambda m: calls.append(m.shape) or edt(m))
    monkeypatch.setenv("CAD2OSMAG_THREADS", "2")
    seg._edt_split(mask)
    assert calls == [mask.shape]
    calls.clear()
    monkeypatch.setenv("CAD2OSMAG_THREADS", "1")
    seg._edt_split(_rooms(0))
    assert calls == [(1200, 900)]


@pytest.mark.parametrize("seed", range(3))
def test_envelope_transform_in_strips_gives_the_same_disk_centres(seed, threads_on):
    """``_edt_upto``: the padded transform is only compared with the envelope and footprint radii, which
    it gets right in strips grown by the largest radius (distances beyond it may differ)."""
    mask = np.pad(_rooms(seed), 40, constant_values=True)
    radii = [45.45454545454546, 136.36363636363637]  # 2 m and 6 m at 0.044 m/px: no pixel distance within 1e-4
    assert all(seg._tie_free(r) for r in radii)
    whole = seg._edt(mask)
    got = seg._edt_upto(mask, radii)
    for r in radii:
        assert np.array_equal(got > r, whole > r)
    # on a pixel distance (40 px = 2 m at 0.05 m/px) the whole transform runs
    assert np.array_equal(seg._edt_upto(mask, [40.0, 120.0]), whole)


def test_building_interior_is_the_same_with_threads_on_and_off(monkeypatch):
    """The footprint reach on the helper thread, the envelope transform in strips: the same interior,
    envelope and claimed space as in line (1.2 Mpx of random rooms, a 0.75 m envelope gap at 0.044 m/px:
    disks of 8.5 and 25.6 px, tie-free)."""
    free = _rooms(4)
    out = {}
    for env in ("1", "2"):
        monkeypatch.setenv("CAD2OSMAG_THREADS", env)
        info = {}
        interior, envelope = seg.building_interior(free, 0.044, 0.75, footprint=True, info=info,
                                                   inside_points=np.array([[450.0, 600.0], [100.0, 100.0]]))
        out[env] = (interior, envelope, info["claimed"])
    for a, b in zip(out["1"], out["2"]):
        assert np.array_equal(a, b)
    assert out["1"][0].sum() > 0.2 * free.sum()


def test_sample_building_output_is_pinned_with_threads_off(tmp_path, monkeypatch):
    """One thread (CAD2OSMAG_THREADS=1, a one-CPU machine) writes the pinned file, as two do
    (test_speed_equivalence.test_sample_building_output_is_pinned)."""
    from .test_speed_equivalence import _check, _sample_f1

    monkeypatch.setenv("CAD2OSMAG_THREADS", "1")
    _check("sample-F1", _sample_f1(tmp_path), tmp_path)


def test_memory_of_a_finished_helper_thread_is_released_where_the_c_library_can():
    """glibc keeps what a helper thread freed in the thread's arena (SIST-F5.dwg peaked ~150 MB higher):
    ``_release_thread_memory`` trims it after every join; elsewhere it does nothing, never raises."""
    seg._release_thread_memory()
    seg._release_thread_memory()
    assert "fn" in seg._TRIM
