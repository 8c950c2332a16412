"""Georeferencing: placing the CAD frame on the Earth (pipeline stage 6).

The CAD frame is metric (x right, y up). A :class:`LocalFrame` places it with a similarity transform
(rotation, uniform scale, translation) into a *local transverse Mercator* projection centred on the
anchor (``+proj=tmerc +lat_0=<anchor lat> +lon_0=<anchor lon> +k=1``, WGS84 ellipsoid). Every
conversion to WGS84 or any other CRS goes through PROJ (pyproj; GDAL's osr only where an incompatible
pyproj wheel cannot load, see ``backend``) from that projection, never through a flat-earth (degrees-per-metre) shortcut. At the anchor the projection's
scale is exactly 1 and grid north is true north; at 1 km from the anchor the scale error is ~1e-8, far below a millimetre per
100 m.

Conventions
- ``rotation_deg``: the azimuth of the CAD +y axis, in degrees clockwise from true north
  (0 = the plan is drawn north-up).
- ``scale``: metres on the ground per CAD metre (1.0 for a correct drawing).
- ``cad_anchor``: the CAD point that sits exactly at ``(anchor_lon, anchor_lat)`` (default the drawing
  origin). The osmAG root node is written at the anchor.

:func:`fit_gcps` solves the frame from >= 2 ground control points by least squares (2-D Helmert /
similarity) in a local projection centred on the control points and reports per-point residuals in
metres measured on the ellipsoid.
"""
from __future__ import annotations

import math
import os
from typing import Iterable, List, Optional, Sequence, Tuple

import numpy as np

from .errors import InputError

WGS84 = "EPSG:4326"


# =========================================================================== PROJ backends
# pyproj is the backend. `make install` builds it against the system PROJ that QGIS links (as Debian's
# python3-pyproj is). A pyproj *wheel*, however, bundles its own PROJ, and inside the QGIS executables
# (qgis, qgis_process) the system PROJ is loaded into the global symbol namespace and shadows the bundled
# copy, which then aborts (bad_alloc / TypeError). Only in that case is the same system PROJ reached
# through GDAL's osr bindings instead. Both do real projections (a test checks they agree); set
# CAD2OSMAG_PROJ_BACKEND=pyproj|osr to force one.
_BACKEND = None


def _proj_loaded_globally() -> bool:
    import ctypes

    try:
        return hasattr(ctypes.CDLL(None), "proj_context_create")
    except OSError:  # pragma: no cover
        return False


def _pyproj_bundles_proj() -> bool:
    """True when the importable pyproj is a wheel with its own PROJ (``pyproj.libs/libproj*``)."""
    import glob
    import importlib.util

    spec = importlib.util.find_spec("pyproj")
    if spec is None or not spec.origin:
        return False
    site = os.path.dirname(os.path.dirname(spec.origin))
    return bool(glob.glob(os.path.join(site, "pyproj.libs", "libproj*")))


def backend() -> str:
    """'pyproj' or 'osr' (see above)."""
    global _BACKEND
    if _BACKEND is None:
        forced = os.environ.get("CAD2OSMAG_PROJ_BACKEND", "").strip().lower()
        if forced in ("pyproj", "osr"):
            _BACKEND = forced
        else:
            _BACKEND = "osr" if _proj_loaded_globally() and _pyproj_bundles_proj() else "pyproj"
    return _BACKEND


def _crs_text(crs) -> str:
    """Any CRS description (EPSG code, 'EPSG:xxxx', WKT, PROJ string, pyproj CRS) -> text."""
    if isinstance(crs, int):
        return f"EPSG:{crs}"
    if hasattr(crs, "to_wkt"):
        return crs.to_wkt()
    return str(crs)


def _osr_srs(crs):
    from osgeo import osr

    osr.UseExceptions()
    srs = osr.SpatialReference()
    try:
        srs.SetFromUserInput(_crs_text(crs))
    except RuntimeError as exc:
        raise InputError(f"unknown coordinate reference system {crs!r}: {exc}") from exc
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    return srs


def _crs(crs):
    """Validated CRS object of the active backend."""
    if backend() == "osr":
        return _osr_srs(crs)
    import pyproj

    if isinstance(crs, pyproj.CRS):
        return crs
    try:
        return pyproj.CRS.from_user_input(_crs_text(crs))
    except Exception as exc:  # pyproj.exceptions.CRSError and friends
        raise InputError(f"unknown coordinate reference system {crs!r}: {exc}") from exc


def crs_is_geographic(crs) -> bool:
    c = _crs(crs)
    return bool(c.IsGeographic()) if backend() == "osr" else bool(c.is_geographic)


class _Transformer:
    """x/lon-first transformer between two CRSs, vectorised over numpy arrays."""

    def __init__(self, src, dst):
        if backend() == "osr":
            from osgeo import osr

            self._ct = osr.CoordinateTransformation(_osr_srs(src), _osr_srs(dst))
            self._tr = None
        else:
            import pyproj

            self._tr = pyproj.Transformer.from_crs(_crs(src), _crs(dst), always_xy=True)

    def transform(self, x, y):
        if self._tr is not None:
            X, Y = self._tr.transform(x, y)
            return X, Y
        xa = np.asarray(x, dtype=float)
        ya = np.asarray(y, dtype=float)
        flat = np.column_stack([xa.reshape(-1), ya.reshape(-1)])
        if len(flat) == 0:
            return xa.copy(), ya.copy()
        ok = np.all(np.isfinite(flat), axis=1)
        out = np.full((len(flat), 2), np.inf)
        if ok.any():
            try:
                res = np.asarray(self._ct.TransformPoints(flat[ok].tolist()), dtype=float)[:, :2]
            except RuntimeError:
                res = np.array([self._one(p) for p in flat[ok]])
            out[ok] = res
        X, Y = out[:, 0].reshape(xa.shape), out[:, 1].reshape(ya.shape)
        if xa.ndim == 0:
            return float(X), float(Y)
        return X, Y

    def _one(self, p):
        try:
            return self._ct.TransformPoint(float(p[0]), float(p[1]))[:2]
        except RuntimeError:
            return (np.inf, np.inf)


def _vincenty_inverse(lon1, lat1, lon2, lat2):
    """Geodesic inverse on WGS84 (Vincenty 1975; ~0.1 mm for non-antipodal points): (az12, dist)."""
    a, f = 6378137.0, 1 / 298.257223563
    b = a * (1 - f)
    L = np.radians(np.asarray(lon2, float) - np.asarray(lon1, float))
    U1 = np.arctan((1 - f) * np.tan(np.radians(np.asarray(lat1, float))))
    U2 = np.arctan((1 - f) * np.tan(np.radians(np.asarray(lat2, float))))
    sU1, cU1, sU2, cU2 = np.sin(U1), np.cos(U1), np.sin(U2), np.cos(U2)
    lam = L
    for _ in range(200):
        sl, cl = np.sin(lam), np.cos(lam)
        ss = np.sqrt((cU2 * sl) ** 2 + (cU1 * sU2 - sU1 * cU2 * cl) ** 2)
        cs = sU1 * sU2 + cU1 * cU2 * cl
        sig = np.arctan2(ss, cs)
        with np.errstate(invalid="ignore", divide="ignore"):
            sa = np.where(ss > 0, cU1 * cU2 * sl / np.where(ss > 0, ss, 1), 0.0)
            c2a = 1 - sa ** 2
            c2sm = np.where(c2a > 0, cs - 2 * sU1 * sU2 / np.where(c2a > 0, c2a, 1), 0.0)
        C = f / 16 * c2a * (4 + f * (4 - 3 * c2a))
        prev = lam
        lam = L + (1 - C) * f * sa * (sig + C * ss * (c2sm + C * cs * (-1 + 2 * c2sm ** 2)))
        if np.all(np.abs(lam - prev) < 1e-13):
            break
    u2 = c2a * (a * a - b * b) / (b * b)
    A = 1 + u2 / 16384 * (4096 + u2 * (-768 + u2 * (320 - 175 * u2)))
    B = u2 / 1024 * (256 + u2 * (-128 + u2 * (74 - 47 * u2)))
    ds = B * ss * (c2sm + B / 4 * (cs * (-1 + 2 * c2sm ** 2)
                                   - B / 6 * c2sm * (-3 + 4 * ss ** 2) * (-3 + 4 * c2sm ** 2)))
    dist = b * A * (sig - ds)
    az = np.degrees(np.arctan2(cU2 * np.sin(lam), cU1 * sU2 - sU1 * cU2 * np.cos(lam)))
    return az, dist


def _geod_inv(lon1, lat1, lon2, lat2):
    if backend() == "osr":
        return _vincenty_inverse(lon1, lat1, lon2, lat2)
    import pyproj

    az, _, d = pyproj.Geod(ellps="WGS84").inv(lon1, lat1, lon2, lat2)
    return az, d


def check_lonlat(lon: float, lat: float, what: str = "anchor") -> None:
    """Raise InputError if (lon, lat) is not a valid WGS84 position."""
    if not (np.isfinite(lon) and np.isfinite(lat)):
        raise InputError(f"{what} ({lon}, {lat}) is not a number")
    if not -90.0 < lat < 90.0:
        raise InputError(f"{what} latitude {lat} is outside -90..90 degrees (or at a pole); "
                         "pick the anchor on a map in a valid CRS, or check that lon/lat are not swapped")
    if not -180.0 <= lon <= 180.0:
        raise InputError(f"{what} longitude {lon} is outside -180..180 degrees; "
                         "check that the anchor point's CRS is the one it was picked in")


class LocalFrame:
    """A CAD frame placed on the Earth. See the module docstring for the conventions."""

    def __init__(self, anchor_lon: float, anchor_lat: float, rotation_deg: float = 0.0, scale: float = 1.0,
                 cad_anchor: Tuple[float, float] = (0.0, 0.0)):
        anchor_lon, anchor_lat = float(anchor_lon), float(anchor_lat)
        check_lonlat(anchor_lon, anchor_lat)
        if not (np.isfinite(scale) and scale > 0):
            raise InputError(f"scale must be a positive number, got {scale}")
        if not np.isfinite(rotation_deg):
            raise InputError(f"rotation must be a number of degrees, got {rotation_deg}")
        self.anchor_lon = anchor_lon
        self.anchor_lat = anchor_lat
        self.rotation_deg = float(rotation_deg) % 360.0
        self.scale = float(scale)
        self.cad_anchor = (float(cad_anchor[0]), float(cad_anchor[1]))
        # the local projection as a PROJ string (accepted by pyproj, osr and QGIS)
        self.crs = (f"+proj=tmerc +lat_0={anchor_lat:.12f} +lon_0={anchor_lon:.12f} +k=1 +x_0=0 +y_0=0 "
                    "+ellps=WGS84 +units=m +no_defs +type=crs")
        self._transformers = {}
        th = math.radians(self.rotation_deg)
        self._c, self._s = math.cos(th), math.sin(th)

    # -------------------------------------------------------------------- description
    def __repr__(self) -> str:
        return (f"LocalFrame(anchor_lon={self.anchor_lon:.9f}, anchor_lat={self.anchor_lat:.9f}, "
                f"rotation_deg={self.rotation_deg:.6f}, scale={self.scale:.9f}, cad_anchor={self.cad_anchor})")

    def as_dict(self) -> dict:
        return {"anchor_lon": self.anchor_lon, "anchor_lat": self.anchor_lat, "rotation_deg": self.rotation_deg,
                "scale": self.scale, "cad_anchor": list(self.cad_anchor)}

    # -------------------------------------------------------------------- CAD <-> local EN (metres)
    def cad_to_local(self, x, y):
        """CAD metres -> local east/north metres of ``self.crs`` (the tmerc frame)."""
        dx = (np.asarray(x, dtype=float) - self.cad_anchor[0]) * self.scale
        dy = (np.asarray(y, dtype=float) - self.cad_anchor[1]) * self.scale
        return dx * self._c + dy * self._s, -dx * self._s + dy * self._c

    def local_to_cad(self, e, n):
        e = np.asarray(e, dtype=float)
        n = np.asarray(n, dtype=float)
        dx = (e * self._c - n * self._s) / self.scale
        dy = (e * self._s + n * self._c) / self.scale
        return dx + self.cad_anchor[0], dy + self.cad_anchor[1]

    # -------------------------------------------------------------------- CRS transforms
    def _transformer(self, crs, inverse=False):
        key = (_crs_text(crs), inverse)
        tr = self._transformers.get(key)
        if tr is None:
            tr = _Transformer(crs, self.crs) if inverse else _Transformer(self.crs, crs)
            self._transformers[key] = tr
        return tr

    def to_crs(self, x, y, crs=WGS84):
        """CAD (x, y) -> coordinates in ``crs`` (x/lon first, always)."""
        e, n = self.cad_to_local(x, y)
        return self._transformer(crs).transform(e, n)

    def from_crs(self, X, Y, crs=WGS84):
        """Coordinates in ``crs`` (x/lon first) -> CAD (x, y)."""
        e, n = self._transformer(crs, inverse=True).transform(np.asarray(X, float), np.asarray(Y, float))
        return self.local_to_cad(e, n)

    def to_wgs84(self, x, y):
        """CAD (x, y) -> (lon, lat) in degrees."""
        return self.to_crs(x, y, WGS84)

    def from_wgs84(self, lon, lat):
        """(lon, lat) in degrees -> CAD (x, y)."""
        return self.from_crs(lon, lat, WGS84)

    # -------------------------------------------------------------------- shapely geometries
    def geometry_to_crs(self, geom, crs=WGS84):
        """Transform a shapely geometry from the CAD frame into ``crs``."""
        import shapely

        def f(xy):
            X, Y = self.to_crs(xy[:, 0], xy[:, 1], crs)
            return np.column_stack([X, Y])

        return shapely.transform(geom, f)

    def geometry_from_crs(self, geom, crs=WGS84):
        """Transform a shapely geometry from ``crs`` into the CAD frame."""
        import shapely

        def f(xy):
            x, y = self.from_crs(xy[:, 0], xy[:, 1], crs)
            return np.column_stack([x, y])

        return shapely.transform(geom, f)


def transform_geometry(geom, src_crs, dst_crs):
    """Transform a shapely geometry (or an array of them) between two pyproj CRSs."""
    import shapely

    tr = _Transformer(src_crs, dst_crs)

    def f(xy):
        X, Y = tr.transform(xy[:, 0], xy[:, 1])
        return np.column_stack([X, Y])

    return shapely.transform(geom, f)


def to_wgs84_points(X, Y, crs) -> Tuple[np.ndarray, np.ndarray]:
    """Points in any CRS -> (lon, lat)."""
    tr = _Transformer(crs, WGS84)
    lon, lat = tr.transform(np.asarray(X, float), np.asarray(Y, float))
    return np.asarray(lon, float), np.asarray(lat, float)


def geodesic_distance(lon1, lat1, lon2, lat2):
    """Ellipsoidal (WGS84) distance in metres."""
    _, d = _geod_inv(lon1, lat1, lon2, lat2)
    return d


def azimuth(lon1, lat1, lon2, lat2) -> float:
    """Forward azimuth (degrees clockwise from north) from point 1 to point 2 on the ellipsoid."""
    az, _ = _geod_inv(lon1, lat1, lon2, lat2)
    return float(az) % 360.0


def rotation_from_two_points(anchor_lonlat: Tuple[float, float], target_lonlat: Tuple[float, float],
                             cad_anchor: Tuple[float, float], cad_target: Tuple[float, float]) -> float:
    """Rotation (deg clockwise from north of the CAD +y axis) that makes the CAD direction
    cad_anchor -> cad_target point from anchor_lonlat towards target_lonlat."""
    dx, dy = cad_target[0] - cad_anchor[0], cad_target[1] - cad_anchor[1]
    if math.hypot(dx, dy) < 1e-9:
        raise InputError("the two CAD points that define the rotation coincide; pick two distinct points")
    check_lonlat(*anchor_lonlat, what="anchor")
    check_lonlat(*target_lonlat, what="rotation point")
    if geodesic_distance(*anchor_lonlat, *target_lonlat) < 1e-6:
        raise InputError("the two map points that define the rotation coincide; pick two distinct points")
    cad_bearing = math.degrees(math.atan2(dx, dy))  # clockwise from CAD +y
    return (azimuth(*anchor_lonlat, *target_lonlat) - cad_bearing) % 360.0


def _solve_similarity(src: np.ndarray, dst: np.ndarray):
    """Least-squares 2-D similarity dst ~ [[a, -b], [b, a]] @ src + t. Returns (a, b, tx, ty)."""
    n = len(src)
    A = np.zeros((2 * n, 4))
    A[0::2, 0] = src[:, 0]
    A[0::2, 1] = -src[:, 1]
    A[0::2, 2] = 1.0
    A[1::2, 0] = src[:, 1]
    A[1::2, 1] = src[:, 0]
    A[1::2, 3] = 1.0
    rhs = dst.reshape(-1)
    sol, *_ = np.linalg.lstsq(A, rhs, rcond=None)
    return sol


def fit_gcps(cad_xy: Sequence[Sequence[float]], world_xy: Sequence[Sequence[float]], world_crs=WGS84,
             ids: Optional[Sequence] = None, fixed_scale: Optional[float] = None):
    """Solve a :class:`LocalFrame` from ground control points (least-squares similarity / Helmert).

    ``cad_xy``: (N, 2) CAD metres; ``world_xy``: (N, 2) in ``world_crs`` (x/lon first); ``ids``: names
    of the points for messages. ``fixed_scale``: keep the scale at this value (e.g. 1.0) and solve
    rotation and translation only.

    Returns ``(frame, residuals, rms)``: residuals are the ellipsoidal distances in metres between
    each point's world position and where the frame puts its CAD position; ``rms`` their root mean
    square. The frame's anchor is the world position of the control points' CAD centroid (the
    projection is centred there). Errors (InputError): fewer than 2 points, coincident points, 3 or
    more points on one line, points outside valid lat/lon.
    """
    cad = np.asarray(cad_xy, dtype=float).reshape(-1, 2)
    world = np.asarray(world_xy, dtype=float).reshape(-1, 2)
    n = len(cad)
    ids = [str(i) for i in (ids if ids is not None else range(1, n + 1))]
    if len(world) != n:
        raise InputError(f"{n} CAD points but {len(world)} map points: every control point needs both")
    if n < 2:
        raise InputError(f"georeferencing needs at least 2 control points, got {n} (ids: {', '.join(ids) or 'none'})")
    bad = [ids[i] for i in range(n) if not (np.all(np.isfinite(cad[i])) and np.all(np.isfinite(world[i])))]
    if bad:
        raise InputError(f"control points {', '.join(bad)} have missing or non-numeric coordinates")
    # coincident CAD points
    for i in range(n):
        for j in range(i + 1, n):
            if np.hypot(*(cad[i] - cad[j])) < 1e-6:
                raise InputError(f"control points {ids[i]} and {ids[j]} have the same CAD position; "
                                 "each control point must be a distinct CAD point")
    c0 = cad.mean(axis=0)
    sv = np.linalg.svd(cad - c0, compute_uv=False)
    if n >= 3 and sv[1] < 1e-3 * sv[0]:
        raise InputError(f"control points {', '.join(ids)} are collinear in the CAD drawing; add a control "
                         "point away from that line (or use exactly 2 points)")
    lon, lat = to_wgs84_points(world[:, 0], world[:, 1], world_crs)
    for i in range(n):
        check_lonlat(lon[i], lat[i], what=f"control point {ids[i]}")
    # iterate: provisional frame centred on the world centroid, then on the solved anchor
    clon, clat = float(np.mean(lon)), float(np.mean(lat))
    frame = None
    for _ in range(3):
        probe = LocalFrame(clon, clat)
        tr = probe._transformer(WGS84, inverse=True)
        e, nn = tr.transform(lon, lat)
        dst = np.column_stack([e, nn])
        src = cad - c0
        if fixed_scale is not None:
            # rotation-only Procrustes, then translation
            dc = dst - dst.mean(axis=0)
            h = (src * dc).sum()  # sum x*e + y*n
            k = (src[:, 0] * dc[:, 1] - src[:, 1] * dc[:, 0]).sum()
            phi = math.atan2(k, h)
            a, b = fixed_scale * math.cos(phi), fixed_scale * math.sin(phi)
            tx, ty = dst.mean(axis=0)  # src is centred, so the translation is the centroid
        else:
            a, b, tx, ty = _solve_similarity(src, dst)
        s = math.hypot(a, b)
        if not s > 0:
            raise InputError("control points do not define a transform (degenerate configuration)")
        # CAD point that maps exactly onto the projection centre (E, N) = (0, 0)
        M = np.array([[a, -b], [b, a]])
        cad_anchor = np.linalg.solve(M, -np.array([tx, ty])) + c0
        rot = (-math.degrees(math.atan2(b, a))) % 360.0
        frame = LocalFrame(clon, clat, rot, s, (float(cad_anchor[0]), float(cad_anchor[1])))
        # move the centre to the world position of the CAD centroid and solve again
        nlon, nlat = frame.to_wgs84(c0[0], c0[1])
        if abs(nlon - clon) < 1e-10 and abs(nlat - clat) < 1e-10:
            break
        clon, clat = float(nlon), float(nlat)
    plon, plat = frame.to_wgs84(cad[:, 0], cad[:, 1])
    residuals = np.asarray(geodesic_distance(plon, plat, lon, lat), dtype=float)
    rms = float(np.sqrt(np.mean(residuals ** 2)))
    return frame, residuals, rms


def frame_from_params(anchor_lon: float, anchor_lat: float, rotation_deg: float = 0.0, scale: float = 1.0,
                      cad_anchor=(0.0, 0.0)) -> LocalFrame:
    """Same as ``LocalFrame(...)``; kept for symmetry with ``fit_gcps``."""
    return LocalFrame(anchor_lon, anchor_lat, rotation_deg, scale, cad_anchor)


def ellipsoidal_length_of_line(coords_lonlat: Iterable[Tuple[float, float]]) -> float:
    pts = np.asarray(list(coords_lonlat), float)
    if len(pts) < 2:
        return 0.0
    d = geodesic_distance(pts[:-1, 0], pts[:-1, 1], pts[1:, 0], pts[1:, 1])
    return float(np.sum(d))


__all__: List[str] = ["LocalFrame", "backend", "crs_is_geographic", "fit_gcps", "transform_geometry",
                      "to_wgs84_points", "geodesic_distance",
                      "azimuth", "rotation_from_two_points", "check_lonlat", "frame_from_params", "WGS84"]
