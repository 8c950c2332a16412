"""Placement of a plan on the Earth by hand: the values and the geometry of the mouse gestures.

No Qt and no QGIS here (the map tool in ``ui/placement.py`` turns mouse positions into lon/lat and calls
these functions), so the gestures are tested without a canvas. Every conversion goes through
``algorithms.georef.LocalFrame`` (PROJ), never a flat-earth shortcut.

A :class:`Placement` is always expressed for the drawing origin (``cad_anchor = (0, 0)``): ``anchor_lon``
/ ``anchor_lat`` are where the CAD point (0, 0) lies, ``rotation_deg`` the azimuth of the drawing's +y axis
(clockwise from north) and ``scale`` ground metres per CAD metre; exactly the ANCHOR / ROTATION / SCALE
that ``cad2osmag:georeference`` and ``cad2osmag:dxftoosmag`` take. Control points (``gcps``) are kept
with it so that they can be edited later.
"""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field
from functools import lru_cache
from typing import List, Optional, Sequence, Tuple

from ..algorithms.georef import LocalFrame, azimuth, fit_gcps, geodesic_distance

LonLat = Tuple[float, float]


@lru_cache(maxsize=32)
def _frame(lon, lat, rot, scale) -> LocalFrame:
    return LocalFrame(lon, lat, rot, scale, (0.0, 0.0))


@dataclass
class Gcp:
    """One control point: a CAD point (metres, drawing frame) and where it lies on the Earth."""
    cad_x: float
    cad_y: float
    lon: float
    lat: float
    residual: Optional[float] = None  # metres, after a fit


@dataclass
class Placement:
    anchor_lon: float
    anchor_lat: float
    rotation_deg: float = 0.0
    scale: float = 1.0
    gcps: List[Gcp] = field(default_factory=list)
    rms: Optional[float] = None  # metres, when the placement was fitted to the control points

    # ------------------------------------------------------------------ conversions
    def frame(self) -> LocalFrame:
        # cached: creating a PROJ transformer takes ~0.1 s, too slow to repeat on every mouse move
        return _frame(float(self.anchor_lon), float(self.anchor_lat), float(self.rotation_deg), float(self.scale))

    @classmethod
    def from_frame(cls, frame: LocalFrame, gcps=None, rms=None) -> "Placement":
        """Any LocalFrame (e.g. one fitted to control points, whose projection is centred elsewhere)
        re-expressed for the drawing origin."""
        lon, lat = (float(v) for v in frame.to_wgs84(0.0, 0.0))
        # the azimuth of +y at the origin (at its own anchor a LocalFrame's grid north is true north), not
        # the frame's rotation, which is relative to north at the frame's own centre
        ylon, ylat = frame.to_wgs84(0.0, 10.0)
        rot = azimuth(lon, lat, float(ylon), float(ylat))
        return cls(lon, lat, float(rot) % 360.0, float(frame.scale), list(gcps or []), rms)

    def to_wgs84(self, x, y) -> LonLat:
        lon, lat = self.frame().to_wgs84(x, y)
        return float(lon), float(lat)

    def from_wgs84(self, lon, lat) -> Tuple[float, float]:
        x, y = self.frame().from_wgs84(lon, lat)
        return float(x), float(y)

    # ------------------------------------------------------------------ persistence
    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @classmethod
    def from_json(cls, text: str) -> "Placement":
        data = json.loads(text)
        gcps = [Gcp(**g) for g in data.pop("gcps", [])]
        return cls(gcps=gcps, **data)

    # ------------------------------------------------------------------ Processing parameters
    def anchor_parameter(self) -> str:
        """The ANCHOR point parameter value (a point with its CRS) for georeference / dxftoosmag."""
        return f"{self.anchor_lon:.10f},{self.anchor_lat:.10f} [EPSG:4326]"

    def georeference_parameters(self) -> dict:
        """Parameters of ``cad2osmag:georeference`` that reproduce this placement (mode 'Anchor')."""
        return {"MODE": 0, "ANCHOR": self.anchor_parameter(), "CAD_ANCHOR_X": 0.0, "CAD_ANCHOR_Y": 0.0,
                "ROTATION": self.rotation_deg, "SCALE": self.scale}

    def dxftoosmag_parameters(self) -> dict:
        """Parameters of ``cad2osmag:dxftoosmag`` (it places the drawing origin; its scale is 1)."""
        return {"ANCHOR": self.anchor_parameter(), "ROTATION": self.rotation_deg}

    def exportosmag_parameters(self) -> dict:
        return {"ANCHOR_LON": self.anchor_lon, "ANCHOR_LAT": self.anchor_lat, "ROTATION": self.rotation_deg,
                "SCALE": self.scale}


# ====================================================================== gestures
def place_cad_point(rotation_deg: float, scale: float, cad_point: Sequence[float], lonlat: LonLat,
                    reference: Placement, exact: bool = True) -> Tuple[float, float]:
    """Anchor (lon, lat) of the drawing origin such that, with ``rotation_deg`` and ``scale``, the CAD
    point ``cad_point`` lies at ``lonlat``. Solved in the local projection of ``reference`` and then
    once more in the projection of the result (meridian convergence between the two is far below a
    millimetre at building size). ``exact=False`` (while dragging) skips the second pass, which needs a
    new PROJ transformer."""
    ref = reference
    for _ in range(2 if exact else 1):
        frame = ref.frame()
        e, n = frame.cad_to_local(*frame.from_wgs84(*lonlat))
        th = math.radians(rotation_deg)
        c, s = math.cos(th), math.sin(th)
        x, y = float(cad_point[0]) * scale, float(cad_point[1]) * scale
        oe, on = float(e) - (x * c + y * s), float(n) - (-x * s + y * c)  # where the origin goes (local EN)
        lon, lat = (float(v) for v in frame.to_wgs84(*frame.local_to_cad(oe, on)))
        ref = Placement(lon, lat, rotation_deg, scale)
    return lon, lat


def moved(placement: Placement, start: LonLat, end: LonLat, exact: bool = True) -> Placement:
    """Drag to move: the drawing point under ``start`` follows the mouse to ``end``."""
    cad = placement.from_wgs84(*start)
    lon, lat = place_cad_point(placement.rotation_deg, placement.scale, cad, end, placement, exact)
    return Placement(lon, lat, placement.rotation_deg, placement.scale, list(placement.gcps), None)


def rotated(placement: Placement, pivot_cad: Sequence[float], start: LonLat, end: LonLat,
            snap_deg: Optional[float] = None, exact: bool = True) -> Placement:
    """Drag a handle around ``pivot_cad`` (CAD point that stays put) from ``start`` to ``end``: the plan
    turns by the change of azimuth of the handle seen from the pivot. ``snap_deg`` rounds the resulting
    rotation (e.g. 1 or 5 degrees)."""
    pivot = placement.to_wgs84(*pivot_cad)
    turn = azimuth(*pivot, *end) - azimuth(*pivot, *start)
    rot = (placement.rotation_deg + turn) % 360.0
    if snap_deg:
        rot = (round(rot / snap_deg) * snap_deg) % 360.0
    lon, lat = place_cad_point(rot, placement.scale, pivot_cad, pivot, placement, exact)
    return Placement(lon, lat, rot, placement.scale, list(placement.gcps), None)


def rotated_to(placement: Placement, pivot_cad: Sequence[float], rotation_deg: float,
               exact: bool = True) -> Placement:
    """``placement`` turned about the CAD point ``pivot_cad`` (which stays put) to ``rotation_deg``."""
    pivot = placement.to_wgs84(*pivot_cad)
    lon, lat = place_cad_point(rotation_deg, placement.scale, pivot_cad, pivot, placement, exact)
    return Placement(lon, lat, float(rotation_deg) % 360.0, placement.scale, list(placement.gcps), None)


def scaled(placement: Placement, pivot_cad: Sequence[float], start: LonLat, end: LonLat,
           exact: bool = True) -> Placement:
    """Drag the scale handle: the distance of the handle from the pivot sets the scale."""
    pivot = placement.to_wgs84(*pivot_cad)
    d0 = float(geodesic_distance(*pivot, *start))
    d1 = float(geodesic_distance(*pivot, *end))
    if d0 < 1e-6 or d1 < 1e-6:
        return placement
    scale = placement.scale * d1 / d0
    lon, lat = place_cad_point(placement.rotation_deg, scale, pivot_cad, pivot, placement, exact)
    return Placement(lon, lat, placement.rotation_deg, scale, list(placement.gcps), None)


def project_points(placement: Placement, xs, ys, reference: Placement):
    """(lon, lat) arrays of CAD points under ``placement``, computed in the projection of ``reference``
    (cached) instead of a new one: what the map tool draws while dragging. Differs from the exact
    placement by the meridian convergence between the two anchors (< 1 mm for a 100 m drag)."""
    import numpy as np

    rf = reference.frame()
    oe, on = rf.cad_to_local(*rf.from_wgs84(placement.anchor_lon, placement.anchor_lat))
    th = math.radians(placement.rotation_deg)
    c, s = math.cos(th), math.sin(th)
    x = np.asarray(xs, float) * placement.scale
    y = np.asarray(ys, float) * placement.scale
    e, n = float(oe) + x * c + y * s, float(on) - x * s + y * c
    return rf.to_wgs84(*rf.local_to_cad(e, n))


def fitted(gcps: Sequence[Gcp], fixed_scale: Optional[float] = None) -> Placement:
    """Helmert (similarity) fit of the control points (``algorithms.georef.fit_gcps``, at least 2)."""
    frame, residuals, rms = fit_gcps([(g.cad_x, g.cad_y) for g in gcps], [(g.lon, g.lat) for g in gcps],
                                     ids=[str(i + 1) for i in range(len(gcps))], fixed_scale=fixed_scale)
    out = [Gcp(g.cad_x, g.cad_y, g.lon, g.lat, float(r)) for g, r in zip(gcps, residuals)]
    return Placement.from_frame(frame, out, float(rms))


# ====================================================================== snapping to building edges
SNAP_PERIOD = 90.0  # buildings are drawn (mostly) at right angles: directions are compared modulo 90°
SNAP_TOLERANCE_DEG = 3.0  # the plan snaps when its walls are this close to the buildings' edges


def _circ_diff(a, b, period=SNAP_PERIOD):
    """Signed smallest difference a - b of two directions modulo ``period`` (in [-period/2, period/2))."""
    return (float(a) - float(b) + period / 2.0) % period - period / 2.0


def dominant_directions(angles_deg, lengths, period: float = SNAP_PERIOD, bin_deg: float = 0.5,
                        smooth_deg: float = 1.5, min_share: float = 0.3, max_peaks: int = 4) -> List[float]:
    """The directions (degrees in [0, period)) along which most of the length lies, strongest first.

    Angles are folded modulo ``period`` (90°: a wall and the walls at right angles to it count together),
    binned by length, smoothed circularly (``smooth_deg``, Gaussian) and every local maximum of at least
    ``min_share`` of the strongest is a direction (peaks closer than 5° are one). Each direction is refined
    by the length-weighted circular mean of the angles within 2 smoothing widths of its peak."""
    import numpy as np

    a = np.asarray(angles_deg, float).ravel() % period
    w = np.asarray(lengths, float).ravel()
    ok = np.isfinite(a) & np.isfinite(w) & (w > 0)
    a, w = a[ok], w[ok]
    if not len(a) or w.sum() <= 0:
        return []
    nb = max(int(round(period / bin_deg)), 8)
    hist = np.bincount((a / period * nb).astype(int) % nb, weights=w, minlength=nb)
    sigma = max(smooth_deg / (period / nb), 1e-6)
    reach = min(int(math.ceil(3 * sigma)), nb // 2)
    spec = sum(math.exp(-0.5 * (k / sigma) ** 2) * np.roll(hist, k) for k in range(-reach, reach + 1))
    peaks = [i for i in range(nb) if spec[i] >= spec[i - 1] and spec[i] > spec[(i + 1) % nb]]
    peaks.sort(key=lambda i: -spec[i])
    top = spec[peaks[0]] if peaks else 0.0
    out: List[float] = []
    for i in peaks:
        if spec[i] < min_share * top or len(out) >= max_peaks:
            break
        centre = (i + 0.5) * period / nb
        if any(abs(_circ_diff(centre, c, period)) < 5.0 for c in out):
            continue
        near = np.abs(((a - centre + period / 2) % period) - period / 2) <= 2 * smooth_deg
        if near.any():
            ph = np.exp(2j * np.pi * a[near] / period)
            centre = float(np.angle(np.sum(w[near] * ph)) / (2 * np.pi) * period) % period
        out.append(centre)
    return out


def cad_directions(segments) -> Tuple["object", "object"]:
    """Directions (degrees counter-clockwise from the drawing's +x axis) and lengths of CAD segments
    ``(x0, y0, x1, y1)`` rows."""
    import numpy as np

    s = np.asarray(segments, float).reshape(-1, 4)
    dx, dy = s[:, 2] - s[:, 0], s[:, 3] - s[:, 1]
    return np.degrees(np.arctan2(dy, dx)), np.hypot(dx, dy)


def ground_directions(segments_lonlat) -> Tuple["object", "object"]:
    """Azimuths (degrees clockwise from north, geodesic) and lengths (metres) of ``(lon0, lat0, lon1, lat1)``
    segments, e.g. the edges of building footprints."""
    import numpy as np

    from ..algorithms.georef import _geod_inv

    s = np.asarray(segments_lonlat, float).reshape(-1, 4)
    if not len(s):
        return np.zeros(0), np.zeros(0)
    az, d = _geod_inv(s[:, 0], s[:, 1], s[:, 2], s[:, 3])
    return np.asarray(az, float) % 360.0, np.asarray(d, float)


def plan_ground_direction(rotation_deg: float, cad_direction_deg: float, period: float = SNAP_PERIOD) -> float:
    """Azimuth (modulo ``period``) on the ground of the CAD direction ``cad_direction_deg`` (counter-clockwise
    from +x) under a placement rotated by ``rotation_deg`` (azimuth of +y): az = rotation + 90 - angle."""
    return (float(rotation_deg) + 90.0 - float(cad_direction_deg)) % period


def snap_rotation(rotation_deg: float, cad_direction_deg: Optional[float], targets: Sequence[float],
                  tolerance_deg: float = SNAP_TOLERANCE_DEG, period: float = SNAP_PERIOD
                  ) -> Tuple[float, Optional[float]]:
    """Turn ``rotation_deg`` so that the plan's dominant wall direction (``cad_direction_deg``, CAD frame)
    lies along the nearest of the buildings' edge directions ``targets`` (azimuths modulo ``period``) when
    it is within ``tolerance_deg`` of one. Returns (rotation, the target snapped to or None)."""
    if cad_direction_deg is None or not targets:
        return float(rotation_deg) % 360.0, None
    here = plan_ground_direction(rotation_deg, cad_direction_deg, period)
    best = min(targets, key=lambda t: abs(_circ_diff(t, here, period)))
    delta = _circ_diff(best, here, period)
    if abs(delta) > tolerance_deg:
        return float(rotation_deg) % 360.0, None
    return (float(rotation_deg) + delta) % 360.0, float(best) % period
