"""Drawing units: what $INSUNITS says, and the plausibility rule that decides the unit actually used."""
from __future__ import annotations

import math
from typing import Optional, Sequence, Tuple

import numpy as np

from .errors import InputError

UNIT_SCALES = {"mm": 0.001, "cm": 0.01, "dm": 0.1, "m": 1.0, "km": 1000.0, "inch": 0.0254, "feet": 0.3048}
_INSUNITS = {0: "unitless", 1: "inch", 2: "feet", 4: "mm", 5: "cm", 6: "m", 7: "km", 14: "dm"}
_UNIT_ALIASES = {"millimetre": "mm", "millimeter": "mm", "millimetres": "mm", "millimeters": "mm",
                 "centimetre": "cm", "centimeter": "cm", "centimetres": "cm", "centimeters": "cm",
                 "metre": "m", "meter": "m", "metres": "m", "meters": "m", "in": "inch", "inches": "inch",
                 "ft": "feet", "foot": "feet", "auto": "", "": ""}
PLAUSIBLE_SIZE = (5.0, 500.0)  # metres across a floor
TYPICAL_SIZE = 40.0  # metres; ties between plausible units go to the one closest (log scale) to this
CHORD_TOL = 0.01  # metres


def normalize_unit(units: Optional[str]) -> str:
    if units is None:
        return ""
    u = str(units).strip().lower()
    u = _UNIT_ALIASES.get(u, u)
    if u and u not in UNIT_SCALES:
        raise InputError(f"unknown unit '{units}'; use one of {', '.join(UNIT_SCALES)} (or leave empty for automatic)")
    return u



def _header_unit(doc) -> str:
    try:
        code = int(doc.header.get("$INSUNITS", 0) or 0)
    except (TypeError, ValueError):
        code = 0
    return _INSUNITS.get(code, "unitless")



UNIT_SIZE_PERCENTILES = (2.0, 98.0)  # a few stray entities far away must not change the unit


def _percentile_size(coords: Sequence[np.ndarray], pct=(0.5, 99.5)) -> float:
    if not coords:
        return 0.0
    allc = np.concatenate(coords, axis=0)
    allc = allc[np.isfinite(allc).all(axis=1)]
    if len(allc) == 0:
        return 0.0
    lo = np.percentile(allc, pct[0], axis=0)
    hi = np.percentile(allc, pct[1], axis=0)
    return float(np.max(hi - lo))


def choose_unit(size_du: float, header_unit: str) -> Tuple[str, Optional[str]]:
    """Pick the unit that makes a floor ``size_du`` drawing units across plausible (5-500 m).

    Returns ``(unit, warning or None)``.
    """
    lo, hi = PLAUSIBLE_SIZE
    cands = ["mm", "cm", "m"]
    if header_unit in UNIT_SCALES and header_unit not in cands:
        cands.append(header_unit)
    if size_du <= 0:
        unit = header_unit if header_unit in UNIT_SCALES else "m"
        return unit, None
    if header_unit in UNIT_SCALES:
        s = size_du * UNIT_SCALES[header_unit]
        if lo <= s <= hi:
            return header_unit, None
    plaus = [u for u in cands if lo <= size_du * UNIT_SCALES[u] <= hi]
    pool = plaus or cands
    best = min(pool, key=lambda u: abs(math.log(size_du * UNIT_SCALES[u] / TYPICAL_SIZE)))
    size_best = size_du * UNIT_SCALES[best]
    if header_unit in UNIT_SCALES:
        s = size_du * UNIT_SCALES[header_unit]
        msg = (f"the header says the drawing is in {header_unit} ($INSUNITS), but that makes the building "
               f"{s:.3g} m across, which is implausible for a floor (expected {lo:g}-{hi:g} m); using {best} "
               f"instead ({size_best:.3g} m across). Set UNITS to override")
    else:
        msg = (f"the drawing has no unit ($INSUNITS unitless); using {best}, which makes the building "
               f"{size_best:.3g} m across. Set UNITS to override")
    if not plaus:
        msg += f" (no unit gives a plausible size: the extent is {size_du:.6g} drawing units)"
    return best, msg

