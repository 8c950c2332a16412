"""Georeferencing (stage 6): LocalFrame through pyproj, Helmert fit from GCPs, bad input."""
import os
import math

import numpy as np
import pyproj
import pytest
from shapely.geometry import LineString, Polygon

from algorithms.errors import InputError
from algorithms.georef import (LocalFrame, azimuth, fit_gcps, geodesic_distance, rotation_from_two_points,
                               transform_geometry)

# a synthetic 120 m x 80 m plan placed in Shanghai (UTM zone 51N), rotated 33.5 deg, CAD origin off-site
TRUTH = LocalFrame(121.5906, 31.1790, rotation_deg=33.5, scale=1.0, cad_anchor=(1000.0, 2000.0))
CAD_GCP = np.array([[1000.0, 2000.0], [1120.0, 2000.0], [1120.0, 2080.0], [1003.0, 2071.0]])
UTM = "EPSG:32651"


def _world(crs):
    lon, lat = TRUTH.to_wgs84(CAD_GCP[:, 0], CAD_GCP[:, 1])
    if crs == "EPSG:4326":
        return np.column_stack([lon, lat])
    tr = pyproj.Transformer.from_crs("EPSG:4326", crs, always_xy=True)
    return np.column_stack(tr.transform(lon, lat))


@pytest.mark.parametrize("crs", ["EPSG:4326", UTM])
def test_gcp_fit_places_plan(crs):
    frame, residuals, rms = fit_gcps(CAD_GCP, _world(crs), crs, ids=["a", "b", "c", "d"])
    assert rms <= 0.01 and residuals.max() <= 0.01
    assert frame.scale == pytest.approx(1.0, abs=1e-7)
    # any CAD point (not only the GCPs) lands where the truth puts it, within 1 mm
    pts = np.array([[1060.0, 2040.0], [1200.0, 1900.0], [990.0, 2100.0]])
    l1, b1 = frame.to_wgs84(pts[:, 0], pts[:, 1])
    l0, b0 = TRUTH.to_wgs84(pts[:, 0], pts[:, 1])
    assert np.max(geodesic_distance(l0, b0, l1, b1)) <= 1e-3


def test_gcp_fit_with_noise_reports_residuals():
    world = _world("EPSG:4326").copy()
    world[2, 0] += 0.5 / (111320 * math.cos(math.radians(31.18)))  # 0.5 m east error on GCP c
    frame, residuals, rms = fit_gcps(CAD_GCP, world, "EPSG:4326", ids=["a", "b", "c", "d"])
    assert residuals.argmax() == 2
    assert 0.1 < rms < 0.5
    assert residuals.shape == (4,)


def test_ellipsoidal_distance_equals_cad_distance():
    frame, _, _ = fit_gcps(CAD_GCP, _world(UTM), UTM)
    # a 100 m CAD segment and a long 144 m diagonal
    for p, q in [((1000.0, 2000.0), (1100.0, 2000.0)), ((1000.0, 2000.0), (1120.0, 2080.0))]:
        (lo1, lo2), (la1, la2) = frame.to_wgs84(np.array([p[0], q[0]]), np.array([p[1], q[1]]))
        d_cad = math.dist(p, q)
        d_ell = float(geodesic_distance(lo1, la1, lo2, la2))
        assert abs(d_ell - d_cad) <= 1e-3 * d_cad / 100.0


def test_anchor_mode_rotation_and_round_trip():
    f = LocalFrame(121.5906, 31.1790, rotation_deg=90.0)
    # with rotation 90 the CAD +y axis points east
    lon, lat = f.to_wgs84(np.array([0.0, 0.0]), np.array([0.0, 50.0]))
    assert azimuth(lon[0], lat[0], lon[1], lat[1]) == pytest.approx(90.0, abs=1e-6)
    assert float(geodesic_distance(lon[0], lat[0], lon[1], lat[1])) == pytest.approx(50.0, abs=1e-6)
    # the anchor is exactly the root
    l0, b0 = f.to_wgs84(0.0, 0.0)
    assert (float(l0), float(b0)) == pytest.approx((121.5906, 31.1790), abs=1e-12)
    x, y = f.from_wgs84(lon, lat)
    assert np.allclose(x, [0, 0], atol=1e-7) and np.allclose(y, [0, 50], atol=1e-7)
    # scale 2: CAD metres are 2 m on the ground
    f2 = LocalFrame(121.5906, 31.1790, scale=2.0)
    lon, lat = f2.to_wgs84(np.array([0.0, 10.0]), np.array([0.0, 0.0]))
    assert float(geodesic_distance(lon[0], lat[0], lon[1], lat[1])) == pytest.approx(20.0, abs=1e-6)


def test_rotation_from_two_points():
    lon, lat = TRUTH.to_wgs84(np.array([1000.0, 1003.0]), np.array([2000.0, 2071.0]))
    rot = rotation_from_two_points((lon[0], lat[0]), (lon[1], lat[1]), (1000.0, 2000.0), (1003.0, 2071.0))
    assert rot == pytest.approx(33.5, abs=1e-4)


def test_geometry_transforms():
    poly = Polygon([(1000, 2000), (1120, 2000), (1120, 2080), (1000, 2080)])
    g = TRUTH.geometry_to_crs(poly, "EPSG:4326")
    assert g.geom_type == "Polygon" and 121 < g.centroid.x < 122
    back = TRUTH.geometry_from_crs(g, "EPSG:4326")
    assert back.hausdorff_distance(poly) < 1e-6
    utm = TRUTH.geometry_to_crs(poly, UTM)
    # UTM is conformal with scale ~0.9996 near the zone edge: area within 0.2 %
    assert utm.area == pytest.approx(poly.area, rel=2e-3)
    line = transform_geometry(LineString([(121.59, 31.17), (121.6, 31.18)]), "EPSG:4326", UTM)
    assert 300000 < line.coords[0][0] < 500000


def test_bad_gcps_and_anchor():
    w = _world("EPSG:4326")
    with pytest.raises(InputError, match="at least 2 control points, got 1 .*ids: p1"):
        fit_gcps(CAD_GCP[:1], w[:1], ids=["p1"])
    with pytest.raises(InputError, match="at least 2 control points, got 0"):
        fit_gcps(np.zeros((0, 2)), np.zeros((0, 2)))
    col = np.array([[0.0, 0.0], [10.0, 10.0], [20.0, 20.0]])
    with pytest.raises(InputError, match="g1, g2, g3 are collinear"):
        fit_gcps(col, w[:3], ids=["g1", "g2", "g3"])
    with pytest.raises(InputError, match="control points a and b have the same CAD position"):
        fit_gcps(np.array([[0.0, 0.0], [0.0, 0.0], [5.0, 1.0]]), w[:3], ids=["a", "b", "c"])
    with pytest.raises(InputError, match="control point x .*latitude"):
        fit_gcps(CAD_GCP[:2], np.array([[121.0, 31.0], [121.0, 95.0]]), ids=["w", "x"])
    with pytest.raises(InputError, match="latitude 123.0"):
        LocalFrame(31.0, 123.0)
    with pytest.raises(InputError, match="longitude 200.0"):
        LocalFrame(200.0, 31.0)
    with pytest.raises(InputError, match="scale"):
        LocalFrame(121.0, 31.0, scale=0.0)
    # exactly two points are enough (no redundancy: residuals are ~0)
    frame, res, rms = fit_gcps(CAD_GCP[:2], w[:2])
    assert rms < 1e-6 and frame.rotation_deg == pytest.approx(33.5, abs=1e-3)


def test_osr_backend_matches_pyproj(monkeypatch):
    """Inside QGIS executables the transforms run through GDAL's osr (same PROJ as QGIS) and geodesics
    through Vincenty's formulae: both agree with pyproj to well below a millimetre."""
    import algorithms.georef as G

    pts = np.array([[0.0, 0.0], [120.0, 0.0], [37.5, -80.0], [1500.0, 900.0]])
    lon_p, lat_p = TRUTH.to_wgs84(pts[:, 0] + 1000, pts[:, 1] + 2000)
    g = pyproj.Geod(ellps="WGS84")
    _, _, d_p = g.inv(lon_p[:-1], lat_p[:-1], lon_p[1:], lat_p[1:])
    monkeypatch.setattr(G, "_BACKEND", "osr")
    frame = LocalFrame(121.5906, 31.1790, rotation_deg=33.5, cad_anchor=(1000.0, 2000.0))
    lon_o, lat_o = frame.to_wgs84(pts[:, 0] + 1000, pts[:, 1] + 2000)
    assert np.max(np.abs(lon_o - lon_p)) < 1e-11 and np.max(np.abs(lat_o - lat_p)) < 1e-11
    d_o = G.geodesic_distance(lon_p[:-1], lat_p[:-1], lon_p[1:], lat_p[1:])
    assert np.max(np.abs(d_o - d_p)) < 1e-4
    x, y = frame.from_crs(*frame.to_crs(pts[:, 0], pts[:, 1], UTM), UTM)
    assert np.allclose(x, pts[:, 0], atol=1e-6) and np.allclose(y, pts[:, 1], atol=1e-6)
    assert G.crs_is_geographic("EPSG:4326") and not G.crs_is_geographic(UTM)
    with pytest.raises(InputError, match="unknown coordinate reference system"):
        G.transform_geometry(LineString([(0, 0), (1, 1)]), "EPSG:999999", UTM)


def test_installed_pyproj_uses_the_system_proj_so_it_is_the_backend_inside_qgis_too():
    """make install builds pyproj against Debian's PROJ (the one QGIS links): no bundled copy, so the
    pyproj backend is safe inside qgis_process and is the one chosen."""
    import pyproj

    from algorithms import georef

    assert not georef._pyproj_bundles_proj()
    from osgeo import osr

    # the PROJ that GDAL/QGIS link: 9.1 on Debian 12 (QGIS 3.22), 9.6 on Debian 13 (QGIS 3.40)
    system_proj = f"{osr.GetPROJVersionMajor()}.{osr.GetPROJVersionMinor()}."
    assert pyproj.proj_version_str.startswith(system_proj)
    assert georef.backend() == "pyproj" or os.environ.get("CAD2OSMAG_PROJ_BACKEND") == "osr"
