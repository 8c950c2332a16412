"""Typing areas as stairs or elevators from the stair and lift symbols of the drawing.

Stair runs (treads, handrails, arrows) and lift symbols (car outline and its cross) are drawn on their
own layers, which the layer rules classify as ``stair`` and ``elevator``. The rasterizer leaves them out
of the obstacles, so each stair core and lift shaft becomes an area; this module recognises those areas
by the density of symbol lines inside them (metres of line per square metre of floor). A stair run has
treads every ~0.3 m (about 3 m/m² over the run), a lift car its outline and two diagonals (about 1.5 m/m²
in a 2 x 2 m shaft), whereas a hall that merely contains a stair keeps a low density and stays a room.
Text labels refine this later (semantics stage).
"""
from __future__ import annotations

from typing import Dict, Sequence

from shapely.geometry import LineString, MultiLineString
from shapely.strtree import STRtree

from .model import Area, CadGeometry

DENSITY = {"stairs": 0.6, "elevator": 0.5}  # metres of symbol line per m² of area, at least
KIND_TO_TYPE = {"stair": "stairs", "elevator": "elevator"}


def _lines(geometries: Sequence[CadGeometry], kind: str):
    out = []
    for g in geometries:
        if g.kind != kind or len(g.coords) < 2:
            continue
        c = g.coords[~(g.coords != g.coords).any(axis=1)]  # drop NaN ring separators
        if len(c) >= 2:
            pts = list(map(tuple, c)) + ([tuple(c[0])] if g.closed else [])
            out.append(LineString(pts))
    return out


def classify_vertical_areas(areas: Sequence[Area], geometries: Sequence[CadGeometry],
                            density: Dict[str, float] = None) -> Dict[int, str]:
    """Set ``type`` to "stairs"/"elevator" on areas dense in stair/lift symbols. Returns {id: type}."""
    density = dict(DENSITY, **(density or {}))
    changed: Dict[int, str] = {}
    for kind, area_type in KIND_TO_TYPE.items():
        lines = _lines(geometries, kind)
        if not lines:
            continue
        tree = STRtree(lines)
        for a in areas:
            if a.type in ("stairs", "elevator") or a.polygon.area <= 0:
                continue
            hits = tree.query(a.polygon, predicate="intersects")
            if len(hits) == 0:
                continue
            inside = MultiLineString([lines[i] for i in hits]).intersection(a.polygon).length
            if inside / a.polygon.area >= density[area_type]:
                a.type = area_type
                changed[a.id] = area_type
    return changed
