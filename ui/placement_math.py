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
