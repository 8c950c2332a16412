"""Multi-floor fusion (pipeline stage 8): osmAG floors -> one osmAG building with vertical passages.

1. **Floors and levels.** Each floor comes from an osmAG file (either variant) or from areas/passages
   already in memory (:class:`FloorData`). Its level is, in this order: the LEVELS given by the user,
   the ``level`` tags of its areas, the file name (``*-F3*``, ``*_L-1*``, ``*B1*``, ``*3F*``,
   ``*三层*``, ``*地下一层*``). A floor without a level, or two floors with one level, stop with an
   error that names the files.
2. **Vertical anchors** are the areas typed ``stairs``/``elevator`` (from symbols, layers, room names
   or manual tags), or named like one (``stair``, ``楼梯``, ``lift``, ``电梯``, ``E1-ST-03``...).
3. **Registration.** Floors of one building are often drawn in different frames (kilometres apart).
   Going out from the reference floor (the one with the most anchors), each floor is registered onto its
   nearest registered floor: anchors are matched by name first, else by type and shape, and a rigid
   transform is estimated by consensus (RANSAC over every pair of compatible matches, rotation from two
   anchors, translation from one): a wrong match never moves a floor, it is an outlier. The consensus
   is refined by least squares on the anchor centroids and polished on the shapes of the matched
   anchors, then refit ICP-like on where each shaft's outline lies best on its partner's; the residual
   per anchor (that local shift: a shaft only cut differently fits with ~0) and overall (RMS) is reported.
   Floors without a usable anchor match fall back to footprint registration (translation by
   cross-correlation of the area outlines, as ``rasterize.floor_offsets`` does for walls), with a
   warning.
3b. **Shafts of floors that show none** (:func:`propagate_shafts`). A floor with no anchor at all (a plan
   whose stair/lift symbols were filtered away) takes the shafts of the consecutive floors, once registered,
   where their walls stand on it: an untyped, unnamed area of the same outline is typed alike; a shaft the
   segmentation joined to a larger area, whose walls stand around it with one door-sized opening, is carved
   out of it with a passage through the door. Chained floor to floor; the floor is then registered again on
   the shafts it shares (:func:`_refine_on_propagated`).
4. **Stitching.** On consecutive converted levels, anchors of the same type that overlap (overlap ≥
   ``MIN_SHAFT_OVERLAP`` of the smaller) are joined by a vertical passage: a two-node way inside both
   shafts, with the upper floor's level and height (``../shared/docs/osmag-format.md``). Same shaft code
   first (overlap ≥ ``MIN_SAME_CODE_OVERLAP``); two codes that identify their areas and differ never link
   (:func:`shaft_link_candidates`).
5. **Hierarchy.** One building structure area (the union of the floor outlines) is the parent of one
   ``structure`` area per level (the floor's outline, computed when the floor has none), which is the
   parent of that floor's areas. Ids are renumbered across the building, names made unique
   (a repeated name gets `` (level N)``). Every area of every floor is written (areas in = areas out).
   Passages whose ``osmAG:from``/``to`` name no area are reported with their way ids and left out.
"""
from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .errors import InputError
from .model import Area, Passage, valid_polygon
from .progress import ensure

ANCHOR_TYPES = ("stairs", "elevator")
MATCH_TOLERANCE = 1.5  # metres: an anchor lands on its partner within this after the transform
MIN_SHAFT_OVERLAP = 0.3  # overlap / smaller shaft area for two anchors to be one shaft
SHAFT_MAX_AREA = 200.0  # m²: a stair/lift area larger than this is a hall holding stairs, not one shaft
MIN_SAME_CODE_OVERLAP = 0.1  # the same, for two anchors carrying the same shaft code (flight cut differently)
MIN_FLOOR_OVERLAP = 0.2  # overlap / smaller floor outline for two floors to belong to one building
DEFAULT_HEIGHT = 3.2

_STAIR_WORDS = re.compile(r"(stair|staircase|treppe|escal|scala|楼梯|樓梯|梯间|-ST-|^ST\d|\bST-?\d)", re.I)
_LIFT_WORDS = re.compile(r"(elevator|lift|aufzug|ascensor|ascensore|电梯|電梯|-EV\d|\bEV\d)", re.I)
_NOT_SHAFT = re.compile(r"(lobby|hall|foyer|landing|machine|motor|厅|前室|机房|候梯)", re.I)  # rooms beside shafts
_LIFT_CODE = re.compile(r"^[A-Z]{1,2}\d+[a-z]?-P\d{1,2}$")  # E1-P1, E2-P4: lift codes of Chinese drawings
# A shaft code of Chinese/office drawings: building part, kind, number ('E1-ST-03', 'E1 ST 03', 'E2-P1',
# 'A3-T2'). Drawn differently on different sheets ('E1-ST-03' / 'E1 ST-03' / 'e1_st_3'): compared by
# ``shaft_code``, which spells them one way.
_SHAFT_CODE = re.compile(r"(?<![A-Za-z0-9])([A-Z]{1,2}\d{0,2}[a-z]?)[-_ ]?(ST|LT|P|T|DT|KT|EV)[-_ ]?(\d{1,2}[a-z]?)(?![A-Za-z0-9])",
                         re.I)
_CN_DIGITS = {"零": 0, "一": 1, "二": 2, "两": 2, "三": 3, "四": 4, "五": 5, "六": 6, "七": 7, "八": 8, "九": 9,
              "十": 10}


# =========================================================================== levels
def _cn_number(s: str) -> Optional[int]:
    if s.isdigit():
        return int(s)
    if not s or any(ch not in _CN_DIGITS for ch in s):
        return None
    if s == "十":
        return 10
    if "十" in s:
        a, _, b = s.partition("十")
        return (_CN_DIGITS[a] if a else 1) * 10 + (_CN_DIGITS[b] if b else 0)
    return _CN_DIGITS[s] if len(s) == 1 else None


def level_from_name(name: str) -> Optional[str]:
    """The level a file name announces, or None: ``SIST-F3`` -> 3, ``plan_L-1`` -> -1, ``B2`` -> -2,
    ``3F`` -> 3, ``三层`` -> 3, ``地下一层`` -> -1, ``floor-2`` -> 2, ``level_0`` -> 0."""
    stem = os.path.splitext(os.path.basename(str(name)))[0]
    m = re.search(r"地下([零一二两三四五六七八九十\d]+)[层樓楼]", stem)
    if m and _cn_number(m.group(1)) is not None:
        return str(-_cn_number(m.group(1)))
    m = re.search(r"([零一二两三四五六七八九十\d]+)[层樓楼]", stem)
    if m and _cn_number(m.group(1)) is not None:
        return str(_cn_number(m.group(1)))
    sep = r"(?:^|[^A-Za-z0-9])"
    for pat, sign in ((sep + r"(?:level|floor|etage|piso|piano)[ _-]?(-?\d+)(?![0-9])", 1),
                      (sep + r"[LF][ _]?(-?\d+)(?![0-9])", 1),
                      (sep + r"B(\d+)(?![0-9])", -1),
                      (sep + r"(-?\d+)F(?![A-Za-z0-9])", 1)):
        m = re.search(pat, stem, re.I)
        if m:
            return str(sign * int(m.group(1)))
    return None


_XREF_LEVEL = re.compile(r"(?:^|[-_ ])(?:(B)(\d{1,2})F?|(\d{1,2})F|(RF|ROOF|WD))(?=$|[-_ (（])", re.I)


def level_from_layers(layer_names) -> Optional[str]:
    """The level a whole sheet announces in its bound external references, or None. Drawing offices bind
    one floor's xref per sheet, so its layers read ``E1-RI-1F$0$A-WALL``, ``A3-SYMB-3F-100$0$A-SYMB``:
    the majority level of the xref prefixes (the part before ``$0$``) wins; ``B1``/``B1F`` -> -1,
    ``RF``/roof -> ``'R'`` (the caller puts it above the highest floor). Only layers with a ``$`` count,
    so a sheet without bound xrefs says nothing."""
    import collections

    votes = collections.Counter()
    for name in layer_names:
        name = str(name)
        if "$" not in name:
            continue
        m = _XREF_LEVEL.search(name.split("$", 1)[0])
        if not m:
            continue
        if m.group(1):
            votes[str(-int(m.group(2)))] += 1
        elif m.group(3):
            votes[str(int(m.group(3)))] += 1
        else:
            votes["R"] += 1
    if not votes:
        return None
    (best, nb), *rest = votes.most_common(2) + [(None, 0)]
    return best if nb > rest[0][1] else None


def level_from_sheet(path: str) -> Optional[str]:
    """``level_from_layers`` of a DXF/DWG's layer table (read without filtering)."""
    from . import cad_import

    try:
        d = cad_import.inspect_dxf(path)
    except InputError:
        return None
    return level_from_layers([getattr(li, "name", li) for li in d.layers])


def _level_value(level: str) -> float:
    return float(level)


# =========================================================================== floors
@dataclass
class FloorData:
    """One floor to fuse. Geometries in ``frame``'s metres (x east, y north) once loaded."""

    source: str
    areas: List[Area]
    passages: List[Passage]
    outline: Optional[Area] = None  # the floor's structure area (parent of its areas)
    structures: List[Area] = field(default_factory=list)  # other structure areas of the floor
    parents: Dict[int, int] = field(default_factory=dict)  # area id -> parent area id, as read
    level: Optional[str] = None
    height: Optional[float] = None
    tag_level: Optional[str] = None
    dropped_passages: List[Tuple[int, str]] = field(default_factory=list)  # (way id, why)
    frame: object = None  # the LocalFrame the geometries are in

    @property
    def label(self) -> str:
        return os.path.basename(self.source) or self.source


def read_floor(path: str, frame, progress=None) -> FloorData:
    """An osmAG floor file -> :class:`FloorData` in ``frame`` (a LocalFrame; None = the file's root)."""
    from . import osmag

    areas, passages, root, report = osmag.read_osmag(path, progress=progress)
    if frame is None:
        frame = osmag.frame_from_root(root)
    areas, passages = osmag.to_frame(areas, passages, frame)
    for a in areas:
        a.polygon = valid_polygon(a.polygon)
    _attach_passage_ends(areas, passages)
    dropped = [(wid, f"{key}='{val}' names no area of the file") for wid, key, val in report["dangling_refs"]
               if key in ("osmAG:from", "osmAG:to")]
    dropped += [(wid, f"missing nodes {miss[:3]}") for wid, miss in report["dangling_nodes"].items()
                if wid not in {a.id for a in areas}]
    levels = [str(a.tags.get("level", "")).strip() for a in areas if a.type != "structure"]
    levels = [lv for lv in levels if lv]
    tag_level = None
    if levels:
        common = max(set(levels), key=levels.count)
        tag_level = common
    heights = []
    for a in areas:
        try:
            heights.append(float(a.tags.get("height")))
        except (TypeError, ValueError):
            pass
    fl = FloorData(source=path, areas=[], passages=list(passages), parents=dict(report["parents"]), frame=frame,
                   tag_level=tag_level, height=(max(set(heights), key=heights.count) if heights else None),
                   dropped_passages=sorted(set(dropped)))
    ids = {a.id for a in areas}
    _split_structures(fl, [a for a in areas if a.type == "structure"], ids)
    fl.areas = [a for a in areas if a.type != "structure"]
    return fl


#: a passage end this close to its area's ring but not on it (written by another tool at 7 decimals, ~1 cm,
#: or a ring opened at a pinch) becomes a vertex of that ring, so the fused file shares its node
PASSAGE_END_TOL = 0.01


def _passage_ends(areas: List[Area], passages: List[Passage]):
    """(area, end coordinate) for both ends of every passage line and each of its two areas that is a non-empty
    Polygon, in the order :func:`_attach_passage_ends` judges them."""
    by_id = {a.id: a for a in areas}
    for p in passages:
        if p.line is None or p.line.is_empty:
            continue
        for aid in (p.from_id, p.to_id):
            a = by_id.get(aid)
            if a is None or getattr(a.polygon, "geom_type", "") != "Polygon" or a.polygon.is_empty:
                continue
            yield a, p.line.coords[0]
            yield a, p.line.coords[-1]


def _attach_passage_ends(areas: List[Area], passages: List[Passage], tol: float = PASSAGE_END_TOL) -> int:
    """Insert every passage end lying within ``tol`` of one of its two areas' exterior ring, but not on it,
    into that ring as a vertex (on the nearest edge), when the ring stays valid. Returns the count."""
    import shapely
    from shapely.geometry import Point

    ends = list(_passage_ends(areas, passages))
    if not ends:
        return 0
    # every end's distance to its ring in one call; an area whose ring took a vertex meanwhile is measured again
    before = [a.polygon for a, _ in ends]
    first = shapely.distance(shapely.get_exterior_ring(np.array(before, dtype=object)),
                             shapely.points(np.array([c[:2] for _, c in ends], float)))
    n = 0
    for i, (a, c) in enumerate(ends):
        d = float(first[i]) if a.polygon is before[i] else a.polygon.exterior.distance(Point(c[:2]))
        if 1e-9 < d <= tol:
            n += _insert_end(a, c, tol)
    return n


def _insert_end(a: Area, c, tol: float) -> bool:
    """Insert the passage end ``c`` into ``a``'s exterior ring on the ring's nearest edge, when the ring stays
    valid and the area changes by at most max(tol², 1e-4 of it) (:func:`_attach_passage_ends`): True if done."""
    import shapely
    from shapely.geometry import Point, Polygon

    xy = np.asarray(a.polygon.exterior.coords, float)[:, :2]
    segs = shapely.linestrings(np.stack([xy[:-1], xy[1:]], axis=1))
    k = int(np.argmin(shapely.distance(segs, Point(c[:2]))))
    new = np.insert(xy, k + 1, np.asarray(c[:2], float), axis=0)
    cand = Polygon(new, [list(r.coords) for r in a.polygon.interiors])
    if cand.is_valid and abs(cand.area - a.polygon.area) <= max(tol * tol, 1e-4 * a.polygon.area):
        a.polygon = cand
        return True
    return False


def _split_structures(fl: FloorData, structures: List[Area], ids) -> None:
    """The floor's outline is its one structure area without a parent in the floor; with several (wings
    drawn as separate structures), a new outline is computed around them all and they become its
    children."""
    top = [a for a in structures if fl.parents.get(a.id) not in ids]
    if len(top) == 1:
        fl.outline = top[0]
        fl.structures = [a for a in structures if a is not top[0]]
    else:
        fl.outline = None
        fl.structures = list(structures)


def floors_from_layers(areas: Sequence[Area], passages: Sequence[Passage], frame, source: str = "layers",
                       level: Optional[str] = None) -> List[FloorData]:
    """Areas/passages in WGS84 lon/lat (e.g. QGIS layers made by loadosmag), split into one floor per
    ``level`` tag (or all on ``level``) and converted into ``frame``. ``osmAG:parent`` tags naming an
    area (by name or id) of the same floor become its parent."""
    from . import osmag

    areas, passages = osmag.to_frame(areas, passages, frame)
    groups: Dict[str, List[Area]] = {}
    for a in areas:
        lv = str(level or (a.tags or {}).get("level", "") or "").strip()
        if a.type == "structure" and (";" in lv or not lv):
            continue  # a building outline (several levels, or none): the fusion makes a new one
        groups.setdefault(lv, []).append(a)
    out = []
    for lv, group in groups.items():
        ids = {a.id for a in group}
        by_name = {a.name: a.id for a in group if a.name}
        fl = FloorData(source=f"{source} (level {lv or '?'})", areas=[], passages=[], tag_level=lv or None)
        for a in group:
            pv = str((a.tags or {}).get("osmAG:parent", "") or "").strip()
            pid = by_name.get(pv)
            if pid is None:
                try:
                    pid = int(float(pv)) if pv else None
                except ValueError:
                    pid = None
            if pid in ids:
                fl.parents[a.id] = pid
        _split_structures(fl, [a for a in group if a.type == "structure"], ids)
        fl.areas = [a for a in group if a.type != "structure"]
        for p in passages:
            if p.from_id in ids and p.to_id in ids:
                fl.passages.append(p)
            elif (p.from_id in ids) != (p.to_id in ids):
                continue  # a vertical passage of a merged file: the fusion links the shafts again
        heights = [float(a.tags["height"]) for a in group if _is_float((a.tags or {}).get("height"))]
        fl.height = max(set(heights), key=heights.count) if heights else None
        out.append(fl)
    known = {p.id for fl in out for p in fl.passages}
    for p in passages:
        if p.id not in known and not any(p.from_id in {a.id for a in fl.areas + fl.structures} for fl in out):
            out[0].dropped_passages.append((p.id, f"from {p.from_id} to {p.to_id}: no such area"))
    return out


def _is_float(v) -> bool:
    try:
        float(v)
        return True
    except (TypeError, ValueError):
        return False


def anchor_kind(a: Area) -> Optional[str]:
    """``stairs``/``elevator`` for a vertical anchor (type, else name/ref/tags), else None."""
    if a.type in ANCHOR_TYPES:
        return a.type
    tags = a.tags or {}
    if tags.get("stairs") == "yes" or tags.get("highway") in ("steps", "stairs") or tags.get("room") == "stairs":
        return "stairs"
    if tags.get("highway") == "elevator" or tags.get("elevator") == "yes" or tags.get("room") == "elevator":
        return "elevator"
    for text in (a.name, a.ref, tags.get("ref", "")):
        text = str(text or "")
        if not text or _NOT_SHAFT.search(text):
            continue
        if _STAIR_WORDS.search(text):
            return "stairs"
        if _LIFT_WORDS.search(text) or _LIFT_CODE.match(text.strip()):
            return "elevator"
    return None


def shaft_code(text) -> str:
    """The stair/lift code in ``text`` spelled one way ('E1 ST-3' -> 'E1-ST-03', 'e2_p1' -> 'E2-P1'), or ''."""
    m = _SHAFT_CODE.search(str(text or ""))
    if not m or not re.search(r"\d", m.group(1)) or not m.group(1)[:1].isalpha():
        return ""
    num = m.group(3)
    num = num.zfill(2 + (not num[-1].isdigit())) if m.group(2).upper() in ("ST", "LT") else num.lstrip("0") or "0"
    return f"{m.group(1).upper()}-{m.group(2).upper()}-{num.upper()}" if m.group(2).upper() in ("ST", "LT") \
        else f"{m.group(1).upper()}-{m.group(2).upper()}{num.upper()}"


def anchor_name(a: Area) -> str:
    """The name an anchor is matched by across floors: its shaft code (from ``ref``, then the name: a stair
    named '走道' with ref 'E1-ST-03', a lift lobby '电梯厅 E2-P1'), else its name ('' for generated names)."""
    for text in ((a.tags or {}).get("ref"), a.ref, a.name):
        code = shaft_code(text)
        if code:
            return code
    name = (a.name or "").strip()
    # generated names ('L3-A012' of the writer, '4-25' of stage 5) and bare numbers ('1536') differ from floor
    # to floor by construction: the anchor is anonymous and matched by position and shape
    if re.fullmatch(r"L-?[\d.]+-[ASP]\d+", name) or not re.search(r"[^\W\d_]", name):
        return ""
    return name


def _reconcile_shaft_kinds(floors, warn) -> Dict[str, str]:
    """One shaft code names one kind of shaft on every floor: when the floors disagree ('A3-T3' typed
    stairs on one sheet from a few treads drawn in it, a lift on the two others), the majority kind over
    the floors wins and the others are retyped, with a warning. Ties are left alone. Returns {code: kind}."""
    import collections

    seen: Dict[str, list] = collections.defaultdict(list)
    for fl in floors:
        for a in fl.areas:
            k = anchor_kind(a)
            code = anchor_name(a) if k else ""
            if k and code and shaft_code(code) == code:
                seen[code].append((fl, a, k))
    fixed = {}
    for code, items in seen.items():
        votes = collections.Counter(k for _, _, k in items)
        if len(votes) < 2:
            continue
        (best, nb), (_, second) = votes.most_common(2)
        if nb == second:
            continue
        for fl, a, k in items:
            if k != best:
                a.type = best
                warn(f"{code} is a {'lift' if best == 'elevator' else 'stair'} on {nb} floors but typed {k} on level "
                     f"{fl.level} ('{a.name}'): retyped {best}")
        fixed[code] = best
    return fixed


@dataclass
class Anchor:
    index: int  # index into FloorData.areas
    kind: str
    name: str
    xy: np.ndarray  # centroid
    size: float  # area in m²
    polygon: object
    openings: object = None  # the lines of the floor's horizontal passages of this area (None: none known)


def floor_anchors(fl: FloorData) -> List[Anchor]:
    out = []
    lines: Dict[int, list] = {}
    for p in fl.passages:  # a shaft's openings: where its outline is a cut, not a wall (core_shift)
        if p.line is not None and not p.line.is_empty:
            for end in {p.from_id, p.to_id}:
                lines.setdefault(end, []).append(p.line)
    for i, a in enumerate(fl.areas):
        k = anchor_kind(a)
        if k is None or a.polygon.is_empty:
            continue
        c = a.polygon.centroid
        op = None
        if lines.get(a.id):
            from shapely.geometry import MultiLineString

            op = MultiLineString([list(ln.coords) for ln in lines[a.id]])
        out.append(Anchor(i, k, anchor_name(a), np.array([c.x, c.y]), float(a.polygon.area), a.polygon, op))
    return out


# =========================================================================== registration
@dataclass
class Rigid:
    """x' = R(theta) x + t"""

    theta: float = 0.0
    tx: float = 0.0
    ty: float = 0.0

    def apply(self, xy: np.ndarray) -> np.ndarray:
        c, s = math.cos(self.theta), math.sin(self.theta)
        xy = np.asarray(xy, float)
        return np.stack([c * xy[..., 0] - s * xy[..., 1] + self.tx, s * xy[..., 0] + c * xy[..., 1] + self.ty], -1)

    def geometry(self, g):
        from shapely import affinity

        c, s = math.cos(self.theta), math.sin(self.theta)
        return affinity.affine_transform(g, [c, -s, s, c, self.tx, self.ty])

    def then(self, other: "Rigid") -> "Rigid":
        """self followed by other."""
        t = other.apply(np.array([self.tx, self.ty]))
        return Rigid(self.theta + other.theta, float(t[0]), float(t[1]))

    @property
    def degrees(self) -> float:
        return math.degrees(math.atan2(math.sin(self.theta), math.cos(self.theta)))


def _fit_rigid(src: np.ndarray, dst: np.ndarray, rotate: bool = True) -> Rigid:
    """Least-squares rigid transform src -> dst (Kabsch in 2D); translation only without rotate."""
    cs, cd = src.mean(0), dst.mean(0)
    if not rotate or len(src) < 2:
        d = cd - cs
        return Rigid(0.0, float(d[0]), float(d[1]))
    a, b = src - cs, dst - cd
    theta = math.atan2(float((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum()), float((a * b).sum()))
    c, s = math.cos(theta), math.sin(theta)
    t = cd - np.array([c * cs[0] - s * cs[1], s * cs[0] + c * cs[1]])
    return Rigid(theta, float(t[0]), float(t[1]))


def _compatible(a: Anchor, b: Anchor) -> bool:
    if a.kind != b.kind:
        return False
    if a.name and b.name and shaft_base_name(a.name) != shaft_base_name(b.name):
        return False
    r = a.size / max(b.size, 1e-9)
    return 0.4 <= r <= 2.5


def shaft_base_name(name: str) -> str:
    """A shaft's name without its level: 'Stair A (level 2)' -> 'stair a', 'E1-ST-03-3F' -> 'e1-st-03'."""
    code = shaft_code(name)
    if code:
        return code.lower()
    n = re.sub(r"\s*\((?:level|L)\s*-?[\d.]+\)\s*$", "", name.strip(), flags=re.I)
    n = re.sub(r"[-_ ]?(?:\d+F|F\d+|L-?\d+)$", "", n, flags=re.I)
    return n.lower()


def register_anchors(moving: Sequence[Anchor], fixed: Sequence[Anchor], tol: float = MATCH_TOLERANCE,
                     rotate: bool = True):
    """Robust rigid transform that brings ``moving`` anchors onto ``fixed`` ones.

    Hypotheses: every compatible pair (translation only; rotation from the floors' shared drawing
    orientation) and every two compatible pairs whose spacing agrees within ``tol`` (rotation and
    translation). Each is scored by its consensus (anchors landing within ``tol`` of a compatible
    partner, one-to-one); ties go to the smaller rotation, then the smaller residual. The winner is
    refit by least squares on its inliers, robustly, then on the shafts' outlines. Returns ``(Rigid, matches
    [(i_moving, i_fixed, residual)])``, the residual being :func:`shaft_residual` (judged on the walls
    both cuts share, the anchors' passages marking open ends) or ``(None, [])`` when no anchor pair is
    compatible.
    """
    from scipy.spatial import cKDTree

    if not moving or not fixed:
        return None, []
    M = np.array([a.xy for a in moving])
    F = np.array([b.xy for b in fixed])
    comp = [(i, j) for i, a in enumerate(moving) for j, b in enumerate(fixed) if _compatible(a, b)]
    if not comp:
        return None, []
    named = [(i, j) for i, j in comp if moving[i].name and fixed[j].name and
             shaft_base_name(moving[i].name) == shaft_base_name(fixed[j].name)]
    tree = cKDTree(F)

    compat = np.zeros((len(moving), len(fixed)), bool)
    for i, j in comp:
        compat[i, j] = True

    def consensus(T: Rigid):
        P = T.apply(M)
        pairs = []
        for i, js in enumerate(tree.query_ball_point(P, tol)):
            for j in js:
                if compat[i, j]:
                    pairs.append((float(np.hypot(*(P[i] - F[j]))), i, j))
        pairs.sort()
        used_i, used_j, out = set(), set(), []
        for d, i, j in pairs:
            if i not in used_i and j not in used_j:
                used_i.add(i)
                used_j.add(j)
                out.append((i, j, d))
        return out

    hyps: List[Rigid] = []
    for i, j in comp:
        d = F[j] - M[i]
        hyps.append(Rigid(0.0, float(d[0]), float(d[1])))
    if rotate and len(comp) <= 400:
        for x in range(len(comp)):
            i1, j1 = comp[x]
            for y in range(x + 1, len(comp)):
                i2, j2 = comp[y]
                if i1 == i2 or j1 == j2:
                    continue
                dm, df = np.hypot(*(M[i2] - M[i1])), np.hypot(*(F[j2] - F[j1]))
                if dm < 2 * tol or abs(dm - df) > tol:
                    continue
                hyps.append(_fit_rigid(M[[i1, i2]], F[[j1, j2]]))
    best, best_key = None, None
    named_set = set(named)
    for T in hyps:
        inl = consensus(T)
        res = math.sqrt(sum(d * d for _, _, d in inl) / len(inl)) if inl else math.inf
        n_named = sum((i, j) in named_set for i, j, _ in inl)
        key = (-n_named, -len(inl), round(res, 1), round(abs(T.degrees), 1), res)
        if best_key is None or key < best_key:
            best, best_key = T, key
    inl = consensus(best)
    if not inl:
        return None, []
    src = M[[i for i, _, _ in inl]]
    dst = F[[j for _, j, _ in inl]]
    # least squares on the consensus; the rotation is kept when the inliers spread enough to fix it and
    # it explains the data clearly better than a pure shift (floors are usually drawn the same way up)
    T = _fit_rigid(src, dst, rotate=False)
    spread = float(np.max(np.linalg.norm(src - src.mean(0), axis=1))) if len(src) >= 2 else 0.0
    if rotate and spread >= 1.0:
        TR = _fit_rigid(src, dst, rotate=True)

        def rms_of(X):
            return float(np.sqrt(np.mean(np.sum((X.apply(src) - dst) ** 2, axis=1))))

        if rms_of(T) - rms_of(TR) > 0.1:
            T = TR
    rot_ok = rotate and spread >= 1.0 and T.theta != 0.0
    T = _robust_refit(T, src, dst, rotate=rot_ok)
    pairs = [(moving[i].polygon, fixed[j].polygon) for i, j, _ in inl]
    T = _polish_on_shapes(T, pairs, rotate=rot_ok)
    T, shifts = _refit_on_local_fits(T, src, pairs, rotate=rot_ok)
    matches = []
    for i, j, _ in inl:
        om, of = moving[i].openings, fixed[j].openings
        matches.append((i, j, shaft_residual(T.geometry(moving[i].polygon), fixed[j].polygon,
                                             None if om is None else T.geometry(om), of)))
    return T, matches


def core_shift(moved, partner, moved_openings=None, partner_openings=None) -> np.ndarray:
    """The registration error at one shaft judged on what both cuts share: the walls of the core.

    Both outlines are measured in the frame of the partner's minimum rotated rectangle (u along its long
    axis, v across). Along each axis the two extents are two intervals; the error on that axis is the
    smallest shift that nests one interval in the other: 0 when one cut already spans the other (a core cut
    longer on one floor, a landing drawn on one floor only: one wall is common, the other is cut elsewhere),
    else the offset of the nearer pair of walls (two cores drawn alike 0.3 m apart: 0.3 m). It never exceeds
    the offset of the two rectangles' centres on that axis. Returns the shift (x, y, metres) of the moved
    outline.

    ``moved_openings`` / ``partner_openings``: the lines of each outline's passages. A side whose outermost
    edge runs along a passage is open, a cut (a flight carved out of a hall ends at its first and last
    tread, which each floor's plan cuts elsewhere), not a wall. An axis with an open side says nothing: the
    open end may lie anywhere, and a difference at the other end is a cut longer on one floor (as above);
    an offset is read only on an axis walled at both ends on both outlines (across a flight: its strings)."""
    rect = partner.minimum_rotated_rectangle
    xy = np.asarray(rect.exterior.coords, float)[:4] if rect.geom_type == "Polygon" else None
    if xy is None or len(xy) < 4:
        return np.zeros(2)
    e1, e2 = xy[1] - xy[0], xy[2] - xy[1]
    u = e1 if np.hypot(*e1) >= np.hypot(*e2) else e2
    nu = float(np.hypot(*u))
    if nu <= 1e-9:
        return np.zeros(2)
    u = u / nu
    v = np.array([-u[1], u[0]])

    try:
        m, p = _wall_extents(moved, u, v), _wall_extents(partner, u, v)
    except ValueError:  # no polygon part
        return np.zeros(2)
    m_open = _open_sides(moved, m, u, v, moved_openings)
    p_open = _open_sides(partner, p, u, v, partner_openings)
    out = np.zeros(2)
    for axis, (lo, hi) in zip((u, v), ((0, 1), (2, 3))):
        d_lo, d_hi = p[lo] - m[lo], p[hi] - m[hi]
        if m_open[lo] or p_open[lo] or m_open[hi] or p_open[hi]:
            continue  # an open end explains any difference there, and a cut longer the other: no error
        d = 0.0 if d_lo * d_hi <= 0 else (d_lo if abs(d_lo) <= abs(d_hi) else d_hi)
        out += d * axis
    return out


def _open_sides(g, ext, u: np.ndarray, v: np.ndarray, openings, band: float = 0.05, share: float = 0.5):
    """(lo_u, hi_u, lo_v, hi_v) booleans: is that side of outline ``g`` (at the positions ``ext`` of
    :func:`_wall_extents`) open, i.e. do its edges there (parallel to the side, within ``band`` of its
    position) run along the ``openings`` (passage lines) for at least ``share`` of their length?"""
    out = [False] * 4
    if openings is None or openings.is_empty:
        return out
    zone = openings.buffer(band, cap_style="flat")
    rings = [np.asarray(p.exterior.coords, float) for p in getattr(g, "geoms", [g]) if p.geom_type == "Polygon"]
    cos_tol = math.cos(math.radians(10.0))
    from shapely.geometry import LineString

    for k, (axis, along) in enumerate(((u, v), (u, v), (v, u), (v, u))):
        tot = inside = 0.0
        for r in rings:
            for a, b in zip(r[:-1], r[1:]):
                d = b - a
                L = float(np.hypot(*d))
                if L <= 1e-9 or abs(d @ along) / L < cos_tol or abs((a + b) / 2 @ axis - ext[k]) > band:
                    continue
                tot += L
                inside += LineString([a, b]).intersection(zone).length
        out[k] = tot > 0 and inside >= share * tot
    return out


def _wall_extents(g, u: np.ndarray, v: np.ndarray, share: float = 0.3, band: float = 0.05):
    """(u_lo, u_hi, v_lo, v_hi) of an outline: per side, the outermost *wall* of it, i.e. the outermost
    position where boundary edges parallel to that side (within 10°) carry ≥ ``share`` of the outline's
    extent along the side (within ``band`` m of each other); a notch or a door jamb sticking out of a core's
    wall by 0.3 m over 1 m does not move the wall. The raw extent where no wall qualifies (a curved side)."""
    rings = [np.asarray(p.exterior.coords, float) for p in getattr(g, "geoms", [g]) if p.geom_type == "Polygon"]
    pts = np.vstack(rings)
    out = []
    cos_tol = math.cos(math.radians(10.0))
    for axis, along in ((u, v), (v, u)):
        proj = pts @ axis
        raw_lo, raw_hi = float(proj.min()), float(proj.max())
        extent = float((pts @ along).max() - (pts @ along).min())
        pos, length = [], []
        for r in rings:
            d = np.diff(r, axis=0)
            L = np.hypot(d[:, 0], d[:, 1])
            ok = L > 1e-9
            par = np.zeros(len(d), bool)
            par[ok] = np.abs(d[ok] @ along) / L[ok] >= cos_tol
            mid = (r[:-1] + r[1:]) / 2 @ axis
            pos.extend(mid[par])
            length.extend(L[par])
        pos, length = np.asarray(pos, float), np.asarray(length, float)
        walls = [x for x in pos if length[np.abs(pos - x) <= band].sum() >= share * extent]
        lo = min(walls) if walls else raw_lo
        hi = max(walls) if walls else raw_hi
        out += [lo, hi] if lo < hi else [raw_lo, raw_hi]
    return tuple(out)


def shaft_residual(moved, partner, moved_openings=None, partner_openings=None) -> float:
    """The residual (metres) reported for one matched shaft: the wall-based :func:`core_shift`, capped by
    the distance of the two outlines' centroids (a residual is never larger than what the two centres of
    outlines that already overlap say). :func:`anchor_shift` (the outline fit) still drives the refit, but
    as a measure it slides a core cut longer on one floor along its long axis (SIST E2-ST-01: 1.15 m)."""
    r = float(np.hypot(*core_shift(moved, partner, moved_openings, partner_openings)))
    return min(r, float(moved.centroid.distance(partner.centroid)))


def _nelder_mead(fun, simplex, xatol: float, fatol: float, maxiter: int):
    """``scipy.optimize.minimize(fun, simplex[0], method="Nelder-Mead", options={"initial_simplex": simplex,
    "xatol": xatol, "fatol": fatol, "maxiter": maxiter})`` step for step (scipy 1.14's
    ``_minimize_neldermead`` without bounds, not adaptive: the same points in the same order, the same
    arithmetic on each coordinate, the same tie order of the sort, the same stop), on Python floats instead of
    2x3 numpy arrays and without ``minimize``'s set-up: the registration runs it ~270 times on cheap costs,
    where scipy's bookkeeping cost as much as the costs. ``fun`` gets a list of floats. Returns ``(x (numpy),
    fun, success)`` as scipy's result's ``x``, ``fun``, ``success``."""
    sim = [[float(c) for c in row] for row in np.asarray(simplex, float)]
    n = len(sim[0])
    if len(sim) != n + 1:
        raise ValueError("`initial_simplex` should be an array of shape (N+1,N)")

    def order(fs):  # numpy's argsort, as scipy sorts; a plain sort gives the same when no two values tie
        if len(set(fs)) == len(fs) and all(f == f for f in fs):
            return sorted(range(len(fs)), key=fs.__getitem__)
        return np.argsort(np.asarray(fs, float)).tolist()

    fsim = [float(fun(list(x))) for x in sim]
    for _ in range(2):  # scipy sorts twice here (and once more on a stop): ties may move under numpy's sort
        ind = order(fsim)
        sim, fsim = [sim[i] for i in ind], [fsim[i] for i in ind]
    iterations = 1
    while iterations < maxiter:
        s0 = sim[0]
        if (all(abs(x[i] - s0[i]) <= xatol for x in sim[1:] for i in range(n))
                and all(abs(fsim[0] - f) <= fatol for f in fsim[1:])):
            ind = order(fsim)
            sim, fsim = [sim[i] for i in ind], [fsim[i] for i in ind]
            break
        xbar = list(sim[0])
        for x in sim[1:-1]:
            xbar = [a + b for a, b in zip(xbar, x)]
        xbar = [a / n for a in xbar]
        last = sim[-1]
        xr = [2 * a - 1 * b for a, b in zip(xbar, last)]
        fxr = float(fun(list(xr)))
        if fxr < fsim[0]:
            xe = [3 * a - 2 * b for a, b in zip(xbar, last)]
            fxe = float(fun(list(xe)))
            sim[-1], fsim[-1] = (xe, fxe) if fxe < fxr else (xr, fxr)
        elif fxr < fsim[-2]:
            sim[-1], fsim[-1] = xr, fxr
        else:
            shrink = False
            if fxr < fsim[-1]:
                xc = [1.5 * a - 0.5 * b for a, b in zip(xbar, last)]
                fxc = float(fun(list(xc)))
                if fxc <= fxr:
                    sim[-1], fsim[-1] = xc, fxc
                else:
                    shrink = True
            else:
                xcc = [0.5 * a + 0.5 * b for a, b in zip(xbar, last)]
                fxcc = float(fun(list(xcc)))
                if fxcc < fsim[-1]:
                    sim[-1], fsim[-1] = xcc, fxcc
                else:
                    shrink = True
            if shrink:
                for j in range(1, n + 1):
                    sim[j] = [a + 0.5 * (b - a) for a, b in zip(sim[0], sim[j])]
                    fsim[j] = float(fun(list(sim[j])))
        iterations += 1
        ind = order(fsim)
        sim, fsim = [sim[i] for i in ind], [fsim[i] for i in ind]
    return np.array(sim[0], float), float(np.min(fsim)), iterations < maxiter


def anchor_shift(moved, partner, max_move: float = MATCH_TOLERANCE) -> np.ndarray:
    """The registration error at one shaft: the smallest shift (x, y, metres) that lays the moved shaft's
    outline on its partner's, i.e. minimises the part of the smaller of the two outside the other (plus
    1 cm per metre of shift, to pick the nearest of equally good shifts).

    Unlike the distance of the two centroids, it does not count a shaft cut differently on the two floors
    as an error: a stair drawn with its landing on one floor and without it on the next fits with no shift
    (the flight lies inside the larger outline), while two shafts drawn alike but offset by 0.3 m need
    exactly that shift. Nelder-Mead from no shift; (0, 0) when nothing better is found within ``max_move``."""
    import shapely

    small, big = (moved, partner) if moved.area <= partner.area else (partner, moved)
    sign = 1.0 if small is moved else -1.0
    a_small = max(float(small.area), 1e-9)
    shapely.prepare(big)
    # shapely.transform(small, lambda xy: xy + v) with its coordinates read once, and the intersection and
    # area ufuncs without shapely's argument wrappers: the same GEOS calls on the same coordinates
    xy = shapely.get_coordinates(small)

    def cost(v):
        g = shapely.lib.set_coordinates(np.array(small, dtype=np.object_), xy + (v[0], v[1])).item()
        return 1.0 - float(shapely.lib.area(shapely.lib.intersection(g, big))) / a_small + 0.01 * math.hypot(v[0], v[1])

    c0 = cost((0.0, 0.0))
    best = np.zeros(2)
    for step in (0.3, 0.05):
        x0 = best
        simplex = np.array([x0, x0 + [step, 0.0], x0 + [0.0, step]])
        try:
            x, fun, _ok = _nelder_mead(cost, simplex, xatol=1e-3, fatol=1e-6, maxiter=300)
        except Exception:  # noqa: BLE001 - a degenerate outline: no correction
            return np.zeros(2)
        if fun < c0 - 1e-9 and math.hypot(*x) <= max_move:
            best, c0 = x, fun
    return sign * best


def _refit_on_local_fits(T: Rigid, src: np.ndarray, pairs, rotate: bool, rounds: int = 3, c: float = 0.15):
    """ICP-like refinement on the shafts' outlines: each matched shaft proposes where its centroid should
    land (where its outline lies best on its partner's, :func:`anchor_shift`); the rigid transform is refit
    on those proposals with Cauchy weights (scale ``c`` m), a few rounds. A shaft cut differently on the
    two floors proposes no move and so cannot drag the floor. Returns (T, shifts (n, 2)), the shifts being
    the remaining error per shaft after the last fit."""
    if not pairs:
        return T, np.zeros((0, 2))

    def shifts_of(R):
        return np.array([anchor_shift(R.geometry(pm), pf) for pm, pf in pairs])

    sh = shifts_of(T)
    for _ in range(rounds if len(pairs) >= 1 else 0):
        target = T.apply(src) + sh
        r = np.linalg.norm(sh, axis=1)
        w = 1.0 / (1.0 + (r / c) ** 2)
        if len(src) >= 2 and rotate:
            cs = (src * w[:, None]).sum(0) / w.sum()
            cd = (target * w[:, None]).sum(0) / w.sum()
            a, b = (src - cs) * np.sqrt(w)[:, None], (target - cd) * np.sqrt(w)[:, None]
            theta = math.atan2(float((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum()), float((a * b).sum()))
        else:
            cs = (src * w[:, None]).sum(0) / w.sum()
            cd = (target * w[:, None]).sum(0) / w.sum()
            theta = T.theta
        co, si = math.cos(theta), math.sin(theta)
        t = cd - np.array([co * cs[0] - si * cs[1], si * cs[0] + co * cs[1]])
        R = Rigid(theta, float(t[0]), float(t[1]))
        sh_new = shifts_of(R)
        # keep the refit only if it lowers the (robust) error of the shafts
        def loss(x):
            return float(np.sum(np.log1p((np.linalg.norm(x, axis=1) / c) ** 2)))
        if loss(sh_new) >= loss(sh) - 1e-9:
            break
        T, sh = R, sh_new
    return T, sh


def _robust_refit(T: Rigid, src: np.ndarray, dst: np.ndarray, rotate: bool, c: float = 0.15,
                  iterations: int = 20) -> Rigid:
    """Iteratively reweighted least squares (Cauchy weights, scale ``c`` metres) from ``T``: a shaft
    drawn differently on two floors (a landing included on one of them) moves its centroid by a metre;
    it is kept as a match but no longer drags the floor, which follows the shafts that agree."""
    if len(src) < 2:
        return T
    for _ in range(iterations):
        r = np.linalg.norm(T.apply(src) - dst, axis=1)
        w = 1.0 / (1.0 + (r / c) ** 2)
        cs = (src * w[:, None]).sum(0) / w.sum()
        cd = (dst * w[:, None]).sum(0) / w.sum()
        theta = T.theta
        if rotate:
            a, b = (src - cs) * np.sqrt(w)[:, None], (dst - cd) * np.sqrt(w)[:, None]
            theta = math.atan2(float((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum()), float((a * b).sum()))
        co, si = math.cos(theta), math.sin(theta)
        t = cd - np.array([co * cs[0] - si * cs[1], si * cs[0] + co * cs[1]])
        new = Rigid(theta, float(t[0]), float(t[1]))
        if abs(new.tx - T.tx) < 1e-6 and abs(new.ty - T.ty) < 1e-6 and abs(new.theta - T.theta) < 1e-9:
            return new
        T = new
    return T


def _polish_on_shapes(T: Rigid, pairs, rotate: bool, max_move: float = MATCH_TOLERANCE) -> Rigid:
    """Refine ``T`` on the shapes of the matched shafts: minimise the mean non-overlap (1 - Dice) of each
    moved shaft with its partner (Nelder-Mead from ``T``). Shafts drawn alike on both floors then lie
    exactly on each other, and one drawn differently (a landing included on one floor) costs about the
    same wherever it is, so it cannot pull. Kept only when it lowers the cost and moves less than
    ``max_move``."""
    if not pairs:
        return T

    import shapely

    PM = np.empty(len(pairs), dtype=object)
    PM[:] = [pm for pm, _ in pairs]
    PF = np.empty(len(pairs), dtype=object)
    PF[:] = [pf for _, pf in pairs]
    denom = np.maximum(shapely.area(PM) + shapely.area(PF), 1e-9)  # a rigid move keeps the area

    def cost(v):
        th = v[2] if rotate else T.theta
        co, si = math.cos(th), math.sin(th)
        rot = np.array([[co, si], [-si, co]])
        G = shapely.transform(PM, lambda xy: xy @ rot + (v[0], v[1]))
        return float(np.mean(1.0 - 2.0 * shapely.area(shapely.intersection(G, PF)) / denom))

    x0 = np.array([T.tx, T.ty, T.theta])
    c0 = cost(x0)
    simplex = np.array([x0, x0 + [0.3, 0, 0], x0 + [0, 0.3, 0], x0 + [0, 0, math.radians(0.3)]])
    if not rotate:
        x0, simplex = x0[:2], simplex[:3, :2]
        simplex[1:] = x0 + np.array([[0.3, 0], [0, 0.3]])
    try:
        v, fun, ok = _nelder_mead(cost, simplex, xatol=1e-4, fatol=1e-7, maxiter=400)
    except Exception:  # noqa: BLE001 - a degenerate shape: keep the point fit
        return T
    if not ok and fun >= c0:
        return T
    R = Rigid(float(v[2]) if rotate else T.theta, float(v[0]), float(v[1]))
    moved = float(np.max(np.linalg.norm(R.apply(np.array([[0.0, 0.0]])) - T.apply(np.array([[0.0, 0.0]])), axis=1)))
    # judge the move where the shafts are, not at the frame origin kilometres away
    pts = np.array([[pm.centroid.x, pm.centroid.y] for pm, _ in pairs])
    moved = float(np.max(np.linalg.norm(R.apply(pts) - T.apply(pts), axis=1)))
    if fun < c0 - 1e-6 and moved <= max_move:
        return R
    return T


def _outline_geometries(fl: FloorData, T: Optional[Rigid] = None):
    from .model import CadGeometry

    out = []
    for a in fl.areas:
        g = T.geometry(a.polygon) if T is not None else a.polygon
        out.append(CadGeometry(layer="outline", kind="wall", coords=np.asarray(g.exterior.coords), closed=True))
    return out


def register_footprint(moving: FloorData, fixed: FloorData, T_fixed: Rigid, progress=None) -> Rigid:
    """Translation that lays ``moving``'s area outlines over ``fixed``'s (already moved by T_fixed):
    FFT cross-correlation of the outlines (rasterize.floor_offsets). Same orientation assumed."""
    from .rasterize import floor_offsets

    sets = [_outline_geometries(fixed, T_fixed), _outline_geometries(moving)]
    if not sets[0] or not sets[1]:
        raise InputError(f"floor '{moving.label}' or '{fixed.label}' has no areas to register by outline")
    offs = floor_offsets(sets, reference=0, resolution=0.25, progress=progress)
    dx, dy = offs[1]
    return Rigid(0.0, float(dx), float(dy))


# =========================================================================== fusion
def _outline_of(fl: FloorData):
    from shapely.ops import unary_union

    from .pipeline import floor_outline

    if fl.outline is not None:
        return fl.outline.polygon
    parts = fl.areas + fl.structures
    return floor_outline(parts) or unary_union([a.polygon for a in parts]).convex_hull


def _shaft_segment(poly):
    """A short segment (≤ 1 m) around the pole of inaccessibility of ``poly``: inside it."""
    from shapely.geometry import LineString

    from .model import polylabel

    try:
        c = polylabel(poly, tolerance=0.02)
    except Exception:  # noqa: BLE001 - degenerate polygon
        c = poly.representative_point()
    r = poly.exterior.distance(c)
    h = max(min(0.5, 0.8 * r), 0.01)
    seg = LineString([(c.x - h, c.y), (c.x + h, c.y)])
    if not poly.contains(seg):
        seg = LineString([(c.x, c.y - h), (c.x, c.y + h)])
    return seg


def reliable_codes(anchors: Sequence[Anchor]) -> Dict[int, str]:
    """{anchor index: shaft code} for the anchors of one floor whose code identifies them: the code is on
    that anchor only (a code written on two areas of one floor is right on one of them at most) and the
    anchor is shaft-sized (≤ SHAFT_MAX_AREA m²; a larger stair area is a hall the segmentation merged stairs
    into, holding several codes, of which it carries the first found)."""
    import collections

    codes = {a.index: shaft_code(a.name) for a in anchors}
    count = collections.Counter(c for c in codes.values() if c)
    return {a.index: codes[a.index] for a in anchors
            if codes[a.index] and count[codes[a.index]] == 1 and a.size <= SHAFT_MAX_AREA}


def shaft_link_candidates(lower: Sequence[Anchor], upper: Sequence[Anchor]):
    """Pairs of anchors on two consecutive levels (already registered) that may be one shaft, best first:
    [(overlap, lower anchor, upper anchor, intersection)]; the caller links them one to one in this order.

    A shaft code names one shaft on every floor: two anchors carrying the same code (``E1-ST-07`` on both
    levels) are linked first, when they overlap by MIN_SAME_CODE_OVERLAP of the smaller (the flights of one
    stair cut differently on two floors); merely touching is not enough (a lift lobby carrying the lift's code
    on one floor, next to the lift shaft on the next). Two anchors whose codes identify them
    (:func:`reliable_codes`) and differ are never linked, however much they overlap (one of the codes sits
    on the wrong stair, or two stairs share a stairwell outline). Other pairs are linked by overlap: same
    kind, the intersection covering at least MIN_SHAFT_OVERLAP of the smaller one."""
    rel_l, rel_h = reliable_codes(lower), reliable_codes(upper)
    out = []
    for x in lower:
        cx = shaft_code(x.name)
        for y in upper:
            if x.kind != y.kind:
                continue
            cy = shaft_code(y.name)
            if x.index in rel_l and y.index in rel_h and rel_l[x.index] != rel_h[y.index]:
                continue
            inter = x.polygon.intersection(y.polygon)
            if inter.is_empty:
                continue
            ov = inter.area / max(min(x.size, y.size), 1e-9)
            same = bool(cx) and cx == cy
            if ov >= MIN_SHAFT_OVERLAP or (same and ov >= MIN_SAME_CODE_OVERLAP):
                out.append((same, ov, x, y, inter))
    out.sort(key=lambda c: (not c[0], -c[1]))
    return [c[1:] for c in out]


def fuse_floors(floors: Sequence[FloorData], out_path: str, frame, building_name: str = "Building",
                levels: Optional[Sequence[str]] = None, heights: Optional[Sequence[float]] = None,
                variant: str = "semantic", register: bool = True, strict_passages: bool = False,
                progress=None) -> Dict[str, object]:
    """Fuse floors (already in ``frame``'s metres) into one osmAG building file at ``out_path``.

    ``levels``/``heights``: per floor (None entries: from tags / file name / default 3.2 m). Returns
    figures: ``levels``, ``transforms`` {level: (dx, dy, degrees, method)}, ``residuals`` {level:
    [(anchor, partner, metres)]} (after registration, the offset of the walls both cuts of each shaft share,
    :func:`shaft_residual`: a shaft only cut differently on the two floors reads ~0), ``centroid_residuals``
    (the same pairs, distance of the two centroids: cuts show here), ``rms`` and ``median_residual`` {level:
    metres}, ``overall_rms``, ``vertical`` [(lower area, upper area, kind)],
    ``areas_in``/``areas_out``, ``passages``, ``dropped_passages``, ``warnings``, plus the writer's stats.
    Raises InputError (nothing written) for unknown or repeated levels, floors that do not overlap,
    passages to missing areas with ``strict_passages``.
    """
    from shapely.ops import unary_union

    from . import osmag

    progress = ensure(progress)
    floors = list(floors)
    if not floors:
        raise InputError("no floors to merge: give at least one osmAG floor")
    warnings: List[str] = []

    def warn(msg):
        warnings.append(msg)
        progress.warning(msg)

    # ---- levels
    if levels is not None and len([lv for lv in levels if str(lv).strip()]) not in (0, len(floors)):
        raise InputError(f"LEVELS gives {len([lv for lv in levels if str(lv).strip()])} levels for "
                         f"{len(floors)} floors; give one level per floor, in the order of the floors")
    for k, fl in enumerate(floors):
        given = str(levels[k]).strip() if levels is not None and k < len(levels) and levels[k] is not None else ""
        lv = given or fl.level or fl.tag_level or level_from_name(fl.source)
        if not lv:
            raise InputError(f"the level of floor '{fl.label}' is unknown: its areas have no level tag and its "
                             "name does not say (like '*-F3*', '*_L-1*' or '*三层*'); give LEVELS")
        try:
            fl.level = osmag.check_level(lv)
        except InputError as exc:
            raise InputError(f"floor '{fl.label}': {exc}") from None
        if heights is not None and k < len(heights) and heights[k]:
            fl.height = float(heights[k])
        fl.height = float(fl.height or DEFAULT_HEIGHT)
        if fl.height <= 0:
            raise InputError(f"floor '{fl.label}': height must be positive, got {fl.height}")
    by_level: Dict[float, FloorData] = {}
    for fl in floors:
        v = _level_value(fl.level)
        if v in by_level:
            raise InputError(f"floors '{by_level[v].label}' and '{fl.label}' both claim level {fl.level}; give "
                             "LEVELS (one per floor) or fix the level tags / file names")
        by_level[v] = fl
    order = sorted(by_level)
    floors = [by_level[v] for v in order]
    n = len(floors)
    for fl in floors:
        if fl.dropped_passages:
            ids = ", ".join(str(w) for w, _ in fl.dropped_passages[:20])
            more = f" (+{len(fl.dropped_passages) - 20} more)" if len(fl.dropped_passages) > 20 else ""
            msg = (f"floor '{fl.label}' (level {fl.level}): {len(fl.dropped_passages)} passages reference areas "
                   f"that are not in the file and are left out: ways {ids}{more}; e.g. "
                   f"{fl.dropped_passages[0][1]}")
            if strict_passages:
                raise InputError(msg)
            warn(msg)
    progress.step(5, f"{n} floors: levels {', '.join(fl.level for fl in floors)}")
    _reconcile_shaft_kinds(floors, warn)
    # ---- registration, outward from the floor with most anchors
    anchors = [floor_anchors(fl) for fl in floors]
    ref = max(range(n), key=lambda k: (len(anchors[k]), -k))
    T: Dict[int, Rigid] = {ref: Rigid()}
    transforms: Dict[str, tuple] = {floors[ref].level: (0.0, 0.0, 0.0, "reference")}
    residuals: Dict[str, list] = {}
    centroid_res: Dict[str, list] = {}
    rms: Dict[str, float] = {}
    medians: Dict[str, float] = {}
    todo = sorted((k for k in range(n) if k != ref), key=lambda k: abs(k - ref))
    for step_i, k in enumerate(todo):
        progress.step(10 + 40.0 * step_i / max(len(todo), 1))
        done = sorted(T, key=lambda j: abs(j - k))
        fl = floors[k]
        got = None
        if register:
            for j in done:
                fixed = [Anchor(a.index, a.kind, a.name, T[j].apply(a.xy), a.size, T[j].geometry(a.polygon),
                                None if a.openings is None else T[j].geometry(a.openings)) for a in anchors[j]]
                R, matches = register_anchors(anchors[k], fixed)
                if R is None:
                    continue
                if len(matches) >= 2 or len(anchors[k]) == 1 or len(fixed) == 1:
                    got = (R, matches, j)
                    break
                if got is None:
                    got = (R, matches, j)  # one match only: keep looking for a better-supported partner
            if got is not None and len(got[1]) < FEW_ANCHORS:
                rejected = _few_anchor_fit_rejected(fl, floors[got[2]], T[got[2]], got[0], got[1], anchors[k],
                                                    anchors[got[2]], floors[got[2]].areas)
                if rejected is not None:
                    RF, msg = rejected
                    j = got[2]
                    T[k] = RF
                    transforms[fl.level] = (RF.tx, RF.ty, 0.0, "footprint")
                    warn(msg)
                    continue
            if got is not None:
                R, matches, j = got
                T[k] = R
                res = _record_residuals(fl, floors[j], anchors[k], anchors[j], matches, R, T[j], residuals,
                                        centroid_res, rms, medians)
                transforms[fl.level] = (R.tx, R.ty, R.degrees, f"anchors ({len(matches)} matched)")
                progress.info(f"level {fl.level}: registered on level {floors[j].level} by {len(matches)} anchors, "
                              f"shift ({R.tx:.2f}, {R.ty:.2f}) m, rotation {R.degrees:.2f}°, residual RMS "
                              f"{rms[fl.level]:.3f} m, median {medians[fl.level]:.3f} m (" + ", ".join(f"{a}: {d:.3f} m" for a, _, d in res) + ")")
                if len(matches) == 1:
                    warn(f"level {fl.level}: only one anchor matched ({res[0][0]}); translation only, no check "
                         "against a second anchor")
            else:
                j = done[0]
                R = register_footprint(fl, floors[j], T[j], progress=None)
                T[k] = R
                transforms[fl.level] = (R.tx, R.ty, 0.0, "footprint")
                warn(f"level {fl.level} ('{fl.label}'): no stair/lift anchor matches level {floors[j].level}; "
                     f"registered by its outline instead (shift {R.tx:.2f}, {R.ty:.2f} m, no rotation): check it, "
                     "or type the stairs and lifts (names, symbols or osmAG:areatype) and merge again")
        else:
            T[k] = Rigid()
            transforms[fl.level] = (0.0, 0.0, 0.0, "none")
    # ---- apply
    for k, fl in enumerate(floors):
        R = T[k]
        if R.theta == 0 and R.tx == 0 and R.ty == 0:
            continue
        _move_floor(fl, R)
    progress.step(55)
    propagated = propagate_shafts(floors, shaft_targets(floors), progress) if register else []
    if propagated:
        _refine_on_propagated(floors, T, ref, propagated, transforms, residuals, centroid_res, rms, medians, progress)
    # ---- floor outlines and overlap check
    outlines = []
    for fl in floors:
        poly = _outline_of(fl)
        if fl.outline is None:
            fl.outline = Area(id=0, polygon=poly, type="structure", name=f"Level {fl.level}")
        outlines.append(fl.outline.polygon)
    for k in range(n):
        if n == 1:
            break
        best = max((outlines[k].intersection(outlines[j]).area / max(min(outlines[k].area, outlines[j].area), 1e-9)
                    for j in range(n) if j != k), default=0.0)
        if best < MIN_FLOOR_OVERLAP:
            raise InputError(f"floor '{floors[k].label}' (level {floors[k].level}) does not overlap any other floor "
                             f"after registration (best overlap {best:.0%}); are they floors of one building? "
                             "Type the shared stairs/lifts or convert the floors with the same anchor")
    # ---- ids: renumber across the building
    new_id = 1
    id_map: List[Dict[int, int]] = []
    for fl in floors:
        m: Dict[int, int] = {}
        for a in [fl.outline] + fl.structures + fl.areas:
            m[a.id] = new_id
            new_id += 1
        id_map.append(m)
    parents: Dict[int, int] = {}
    names_seen: Dict[str, int] = {}
    for fl in floors:
        for a in [fl.outline] + fl.structures + fl.areas:
            if a.name:
                names_seen[a.name] = names_seen.get(a.name, 0) + 1
    layers: List[osmag.FloorLayer] = []
    copies: List[List[Area]] = []
    passages_out = 0
    for fl, m in zip(floors, id_map):
        def cp(a: Area, typ=None) -> Area:
            nm = a.name
            if nm and names_seen.get(nm, 0) > 1:
                nm = f"{nm} (level {fl.level})"
            tags = {kk: vv for kk, vv in (a.tags or {}).items() if kk != "osmAG:parent"}
            return Area(id=m[a.id], polygon=a.polygon, type=typ or a.type, name=nm, tags=tags, ref=a.ref,
                        max_clearance=a.max_clearance, component=a.component)

        outline = cp(fl.outline, "structure")
        structs = [cp(a, "structure") for a in fl.structures]
        areas = [cp(a) for a in fl.areas]
        copies.append(areas)
        for a in fl.structures + fl.areas:
            pid = fl.parents.get(a.id)
            parents[m[a.id]] = m[pid] if pid in m else outline.id
        passages = []
        for p in fl.passages:
            if p.from_id in m and p.to_id in m:
                passages.append(Passage(id=len(passages) + 1 + passages_out, from_id=m[p.from_id], to_id=m[p.to_id],
                                        line=p.line, name=p.name,
                                        tags={kk: vv for kk, vv in (p.tags or {}).items()
                                              if kk not in ("osmAG:from", "osmAG:to", "osmAG:type", "level", "name")}))
        passages_out += len(passages)
        layers.append(osmag.FloorLayer(fl.level, areas, passages, [outline] + structs, fl.height))
    # ---- vertical passages between consecutive converted levels
    vertical: List[Passage] = []
    links = []
    for k in range(n - 1):
        lo, hi = floors[k], floors[k + 1]
        if _level_value(hi.level) - _level_value(lo.level) > 1:
            warn(f"levels {lo.level} and {hi.level} are consecutive in this set but not adjacent: their shafts "
                 "are linked directly")
        al, ah = floor_anchors(lo), floor_anchors(hi)
        cands = shaft_link_candidates(al, ah)
        used_l, used_h = set(), set()
        for ov, x, y, inter in cands:
            if x.index in used_l or y.index in used_h:
                continue
            used_l.add(x.index)
            used_h.add(y.index)
            inter_poly = max(getattr(inter, "geoms", [inter]), key=lambda g: getattr(g, "area", 0))
            a_lo, a_hi = copies[k][x.index], copies[k + 1][y.index]
            n_kind = 1 + sum(1 for lk in links if lk[0] == lo.level and lk[1] == hi.level and lk[4] == x.kind)
            vertical.append(Passage(id=passages_out + len(vertical) + 1, from_id=a_lo.id, to_id=a_hi.id,
                                    line=_shaft_segment(inter_poly),
                                    name=f"{'Stairs' if x.kind == 'stairs' else 'Lift'} {n_kind} L{lo.level}-L{hi.level}",
                                    tags={"osmAG:vertical": "yes",
                                          ("stairs" if x.kind == "stairs" else "elevator"): "yes"}))
            links.append((lo.level, hi.level, a_lo.name or str(a_lo.id), a_hi.name or str(a_hi.id), x.kind,
                          round(ov, 3)))
        unlinked = [a for a in al if a.index not in used_l] + [a for a in ah if a.index not in used_h]
        progress.info(f"levels {lo.level}-{hi.level}: {len(used_l)} shafts linked "
                      f"({sum(1 for a in al if a.index in used_l and a.kind == 'stairs')} stairs, "
                      f"{sum(1 for a in al if a.index in used_l and a.kind == 'elevator')} lifts); "
                      f"{len(unlinked)} anchors without a partner")
    progress.step(65)
    # ---- building outline
    union = unary_union([o.buffer(0) for o in outlines])
    from shapely.geometry import Polygon

    if union.geom_type == "Polygon":
        shell = Polygon(union.exterior)
    else:
        shell = Polygon(union.convex_hull.exterior)
    bid = new_id
    top = Area(id=bid, polygon=shell, type="structure", name=building_name,
               tags={"building": "yes", "level": ";".join(fl.level for fl in floors),
                     "min_level": floors[0].level, "max_level": floors[-1].level,
                     "building:levels": str(n)})
    for lay in layers:
        parents[lay.structure_areas[0].id] = bid
    written = osmag.write_osmag_levels(out_path, layers, frame=frame, variant=variant, top_areas=[top],
                                       vertical_passages=vertical, parents=parents, progress=progress.sub(70, 100))
    areas_in = sum(len(fl.areas) + len(fl.structures) + (1 if fl.outline is not None else 0) for fl in floors)
    stats = {k: v for k, v in written.items() if k not in ("way_ids", "names")}
    stats.update({"floors": n, "levels": [fl.level for fl in floors], "transforms": transforms,
                  "residuals": residuals, "centroid_residuals": centroid_res, "rms": rms, "median_residual": medians, "vertical": links, "reference": floors[ref].level,
                  "propagated": propagated,
                  "areas_in": areas_in, "areas_out": written["areas"] + written["structure_areas"] - 1,
                  "dropped_passages": {fl.level: fl.dropped_passages for fl in floors if fl.dropped_passages},
                  "warnings": warnings + written["warnings"],
                  "overall_rms": (float(math.sqrt(np.mean([d * d for r in residuals.values() for _, _, d in r])))
                                  if any(residuals.values()) else None)})
    progress.info(f"building '{building_name}': {n} floors, {len(vertical)} vertical passages, "
                  f"{stats['areas_out']} areas (+1 building), {written['passages']} passages")
    return stats


FEW_ANCHORS = 3  # an anchor fit on fewer matches than this is cross-checked against the floor's outline
OUTLINE_AGREE = 3.0  # metres at the floor's centre: an anchor fit this close to the outline fit is not questioned
OUTLINE_WORSE = 0.1  # outline overlap (share of the smaller outline) the anchor fit may lose against the outline fit


def _outline_overlap(moving_outline, fixed_outline, T: Rigid) -> float:
    a = T.geometry(moving_outline)
    return float(a.intersection(fixed_outline).area / max(min(a.area, fixed_outline.area), 1e-9))


def _few_anchor_fit_rejected(fl: FloorData, other: FloorData, T_other: Rigid, R: Rigid, matches, mine, theirs,
                             their_areas):
    """One or two stair/lift matches prove little: a floor's only anchor may be a shaft its neighbour does not
    have (a courtyard glass lift on the ground floor), matched by type and size to another one far away, and
    a translation onto it moves the whole floor by tens of metres. Such a fit (fewer than ``FEW_ANCHORS``
    matches) is checked against the outline (footprint) registration: when the two put the floor's centre
    more than ``OUTLINE_AGREE`` m apart and the floor's outline overlaps its neighbour's clearly less under
    the anchor fit (by more than ``OUTLINE_WORSE`` of the smaller outline), the anchors matched different
    shafts and the outline fit is kept. Returns ``(outline fit, warning)`` then, else None (the anchor fit
    stands, e.g. a floor whose outline differs from its neighbour's but whose shared lift says where it is)."""
    try:
        RF = register_footprint(fl, other, T_other)
    except InputError:
        return None
    own = _outline_of(fl)
    c = np.array(own.centroid.coords[0])
    apart = float(np.hypot(*(R.apply(c) - RF.apply(c))))
    if apart <= OUTLINE_AGREE:
        return None
    fixed = T_other.geometry(_outline_of(other))
    ov_a, ov_f = _outline_overlap(own, fixed, R), _outline_overlap(own, fixed, RF)
    if ov_a >= ov_f - OUTLINE_WORSE:
        return None
    ids = ", ".join(f"{fl.areas[mine[i].index].name or fl.areas[mine[i].index].id} on "
                    f"{their_areas[theirs[jj].index].name or their_areas[theirs[jj].index].id}"
                    for i, jj, _d in matches)
    msg = (f"level {fl.level} ('{fl.label}'): its {len(matches)} matched stair/lift anchor(s) ({ids}) would put it "
           f"{apart:.1f} m from where its outline lies over level {other.level} (outline overlap {ov_a:.0%} against "
           f"{ov_f:.0%}): they are not the same shafts; registered by its outline instead (shift {RF.tx:.2f}, "
           f"{RF.ty:.2f} m, no rotation): check it, or name the shafts alike on both floors and merge again")
    return RF, msg


def _move_floor(fl: FloorData, R: Rigid) -> None:
    """Apply ``R`` to a floor in place: its areas, structures, outline and passages."""
    for a in fl.areas + fl.structures + ([fl.outline] if fl.outline is not None else []):
        a.polygon = R.geometry(a.polygon)
    for p in fl.passages:
        p.line = R.geometry(p.line)


def _record_residuals(fl: FloorData, other: FloorData, mine, theirs, matches, R: Rigid, T_other: Rigid, residuals,
                      centroid_res, rms, medians) -> list:
    """The per-anchor residuals of ``fl`` registered by ``R`` on ``other`` (placed by ``T_other``) through
    ``matches``, recorded under its level (names, residual, centroid distance; RMS and median): returns them."""
    res = [(fl.areas[mine[i].index].name or str(fl.areas[mine[i].index].id),
            other.areas[theirs[jj].index].name or str(other.areas[theirs[jj].index].id), round(d, 3))
           for i, jj, d in matches]
    cen = [R.apply(mine[i].xy) - T_other.apply(theirs[jj].xy) for i, jj, _ in matches]
    residuals[fl.level] = res
    centroid_res[fl.level] = [(r[0], r[1], round(float(np.hypot(*c)), 3)) for r, c in zip(res, cen)]
    rms[fl.level] = float(math.sqrt(np.mean([d * d for _, _, d in res]))) if res else 0.0
    medians[fl.level] = float(np.median([d for _, _, d in res])) if res else 0.0
    return res


def _refine_on_propagated(floors, T, ref, propagated, transforms, residuals, centroid_res, rms, medians,
                          progress) -> None:
    """A floor registered by its outline that took shafts from a consecutive floor (``propagate_shafts``) is
    registered again on those shared anchors (``register_anchors``), nearest the reference floor first, when
    at least two match and the correction is small (under ``MATCH_TOLERANCE`` at the floor's centre, under
    1°): moved in place, its transform and per-anchor residuals reported like an anchor registration."""
    n = len(floors)
    got = {t[1] for t in propagated}
    for k in sorted((k for k in range(n) if floors[k].level in got), key=lambda k: abs(k - ref)):
        fl = floors[k]
        src = {t[0] for t in propagated if t[1] == fl.level}
        js = [j for j in range(n) if floors[j].level in src and abs(j - k) == 1]
        if not js:
            continue
        j = min(js, key=lambda j: abs(j - ref))
        mine, theirs = floor_anchors(fl), floor_anchors(floors[j])
        R, matches = register_anchors(mine, theirs)
        if R is None or len(matches) < 2 or abs(R.degrees) > 1.0:
            continue
        c = np.array(_outline_of(fl).centroid.coords[0])
        if np.hypot(*(R.apply(c) - c)) > MATCH_TOLERANCE:
            continue
        _move_floor(fl, R)
        T[k] = T[k].then(R)
        _record_residuals(fl, floors[j], mine, theirs, matches, R, Rigid(), residuals, centroid_res, rms, medians)
        base = str(transforms.get(fl.level, (0, 0, 0, "footprint"))[3]).split(", refined")[0]
        transforms[fl.level] = (T[k].tx, T[k].ty, T[k].degrees, f"{base}, refined on {len(matches)} shared shafts")
        progress.info(f"level {fl.level}: registered again on level {floors[j].level} by the {len(matches)} shafts "
                      f"they share, moved {np.hypot(*(R.apply(c) - c)):.3f} m, rotation {R.degrees:.3f}°, residual "
                      f"RMS {rms[fl.level]:.3f} m, median {medians[fl.level]:.3f} m")


FEW_SHAFTS_COVERED = 0.5  # a floor whose anchors cover less than this share of a neighbour's shafts takes them


def shaft_targets(floors: Sequence[FloorData]) -> List[bool]:
    """Which floors (registered, in one frame) take their neighbours' shafts (:func:`propagate_shafts`): a
    floor with no stair or lift of its own, and a floor with fewer anchors than a consecutive floor has shafts
    (≤ SHAFT_MAX_AREA) that covers less than ``FEW_SHAFTS_COVERED`` of them (a plan filtered down to its walls
    that still shows one courtyard glass lift). A floor that shows most of its neighbours' shafts, or as many
    as they have, is left as drawn (a shaft missing there is the drawing's choice, not a filter's loss).
    Within a target floor, areas already typed or named are never retyped (:func:`propagate_shafts`)."""
    anchors = [floor_anchors(fl) for fl in floors]
    out = []
    for k in range(len(floors)):
        if not anchors[k]:
            out.append(True)
            continue
        few = False
        for j in (k - 1, k + 1):
            if not 0 <= j < len(floors):
                continue
            shafts = [b for b in anchors[j] if b.size <= SHAFT_MAX_AREA]
            if not shafts:
                continue
            covered = sum(1 for b in shafts if any(
                a.kind == b.kind and a.polygon.intersection(b.polygon).area >= MIN_SHAFT_OVERLAP * min(a.size, b.size)
                for a in anchors[k]))
            few = few or (covered < FEW_SHAFTS_COVERED * len(shafts) and len(anchors[k]) < len(shafts))
        out.append(few)
    return out


SHAFT_PRISM_OVERLAP = 0.6  # shared area / each of the two outlines for an area to be the same shaft a floor up or down


def propagate_shafts(floors: Sequence[FloorData], targets: Sequence[bool], progress=None) -> List[tuple]:
    """A stair core or lift shaft is a vertical prism: its walls stand at the same place on every floor it
    serves. A floor that shows no stair or lift at all (``targets``; its symbols were filtered away, as in
    plans reduced to walls, doors and glazing) takes its shafts from the consecutive floors, once registered:
    an area of it that is not typed, not named (a generated name or none) and shares at least
    ``SHAFT_PRISM_OVERLAP`` of its own outline and of a shaft's outline on the floor above or below (at most
    ``SHAFT_MAX_AREA``) is that shaft, typed alike with ``cad2osmag:shaft_from`` = the level it came from.
    Chains through consecutive such floors (F2's lifts type F3's shafts, those F4's). A target floor with a
    few anchors of its own (:func:`shaft_targets`) takes only the shafts its anchors do not cover; its typed
    and named areas are never retyped. A shaft the segmentation joined to a larger area is carved out of it
    (:func:`_carve_shaft`). Returns [(from level, to level, area id, kind, carved)]."""
    from shapely.strtree import STRtree

    progress = ensure(progress)
    n = len(floors)
    out: List[tuple] = []
    trees = {}
    for k in range(n):
        if targets[k]:
            cand = [a for a in floors[k].areas if a.type != "structure" and not a.polygon.is_empty]
            trees[k] = (cand, STRtree([a.polygon for a in cand]) if cand else None)
    changed = True
    while changed:
        changed = False
        for k in range(n):
            shafts = [a for a in floors[k].areas if anchor_kind(a) and 0 < a.polygon.area <= SHAFT_MAX_AREA]
            for j in (k - 1, k + 1):
                if not (0 <= j < n and j in trees and trees[j][1] is not None):
                    continue
                cand, tree = trees[j]
                for s in shafts:
                    kind = anchor_kind(s)
                    best, best_iou = None, 0.0
                    partnered = False
                    for i in tree.query(s.polygon, predicate="intersects"):
                        b = cand[i]
                        inter = s.polygon.intersection(b.polygon).area
                        if anchor_kind(b):
                            partnered = partnered or (anchor_kind(b) == kind and inter >= MIN_SHAFT_OVERLAP
                                                      * min(s.polygon.area, b.polygon.area))
                            continue
                        if anchor_name(b) or inter < SHAFT_PRISM_OVERLAP * max(s.polygon.area, b.polygon.area):
                            continue
                        iou = inter / (s.polygon.area + b.polygon.area - inter)
                        if iou > best_iou:
                            best, best_iou = b, iou
                    if partnered:
                        continue
                    if best is None:
                        best = _carve_shaft(floors[j], s, cand, tree)
                        if best is None:
                            continue
                        cand.append(best)
                        trees[j] = (cand, STRtree([a.polygon for a in cand]))
                        cand, tree = trees[j]
                    best.type = kind
                    best.tags = dict(best.tags or {}, **{"cad2osmag:shaft_from": f"level {floors[k].level}"})
                    out.append((floors[k].level, floors[j].level, best.id, kind,
                                best.tags.get("cad2osmag:carved") == "yes"))
                    changed = True
    if out:
        for lv in sorted({t[1] for t in out}, key=_level_value):
            got = [t for t in out if t[1] == lv]
            progress.info(f"level {lv} shows no stair or lift: {sum(t[3] == 'stairs' for t in got)} stair(s) and "
                          f"{sum(t[3] == 'elevator' for t in got)} lift(s) typed where the walls of a shaft of the "
                          f"floor above or below stand, {sum(t[4] for t in got)} of them carved out of the area that "
                          "swallowed them (" + ", ".join(f"area {t[2]} from level {t[0]}" for t in got) + ")")
    return out


SHAFT_WALL_REACH = 0.3  # metres: a shaft's outline within this of its host's boundary has its wall on this floor
SHAFT_WALLED = 0.6  # share of a shaft's outline that must run along walls of the host for the shaft to be carved
SHAFT_MOUTH = (0.6, 3.0)  # metres: the opening of a carved shaft onto its host (a lift door, a stair's mouth)
SHAFT_HELD = 0.8  # share of the shaft's outline inside the one area that swallowed it (the rest: its walls)
SHAFT_MOUTH_SIDE = 0.75  # the opening at most this share of the shaft's short side: a door with wall beside it


def _short_side(poly) -> float:
    r = np.asarray(poly.minimum_rotated_rectangle.exterior.coords)
    return float(min(np.hypot(*(r[1] - r[0])), np.hypot(*(r[2] - r[1]))))


def _open_samples(host, pts: np.ndarray, normal: np.ndarray, step: float, probe: float) -> np.ndarray:
    """Which samples ``pts`` of a shaft's outline are open onto ``host``: the host holds every probe point
    ``pts + r * normal``, r = step, 2 step, ... up to ``probe`` (a wall anywhere on the probe: walled). All
    probe points in one ``contains_xy`` call on the prepared host (GEOS's indexed point-in-area test, the same
    answers as the unprepared one; 6000 points in a 2000-vertex polygon: 0.8 ms instead of 190); a host the caller
    had not prepared is left unprepared."""
    import shapely

    r = np.arange(step, probe + 1e-9, step)[:, None, None]
    out = pts[None] + r * normal[None]
    was = bool(shapely.is_prepared(host))
    shapely.prepare(host)
    try:
        return shapely.contains_xy(host, out[..., 0], out[..., 1]).all(axis=0)
    finally:
        if not was:
            shapely.destroy_prepared(host)


def _shaft_mouth(shaft, host, step: float = 0.05, probe: float = 0.3):
    """The opening of ``shaft`` onto ``host`` (a LineString across it), when the shaft's walls stand on the
    host's floor: walking its outline every ``step`` m, a point is open when the host holds the whole probe
    from it ``probe`` m outwards (the host goes on there), walled when a wall cuts the probe (so a wall face
    drawn up to ``probe`` m apart on the two floors still reads as a wall). None unless ≥ ``SHAFT_WALLED`` of
    the outline is walled and the open part is one run (shorter runs at corners ignored) of ``SHAFT_MOUTH``
    metres, at most ``SHAFT_MOUTH_SIDE`` of the shaft's short side: a door with wall beside it; a whole side
    open is a room that goes on where the shaft ends."""
    import shapely
    from shapely.geometry import LineString
    from shapely.geometry.polygon import orient

    ring = orient(shaft, 1.0).exterior  # counter-clockwise: the outside is on the right
    n = max(int(ring.length / step), 8)
    d = np.linspace(0.0, ring.length, n, endpoint=False)
    pts = shapely.get_coordinates(shapely.line_interpolate_point(ring, d))
    nxt = shapely.get_coordinates(shapely.line_interpolate_point(ring, (d + step / 2) % ring.length))
    t = nxt - pts
    t /= np.maximum(np.hypot(t[:, 0], t[:, 1]), 1e-12)[:, None]
    normal = np.column_stack([t[:, 1], -t[:, 0]])
    open_ = _open_samples(host, pts, normal, step, probe)
    if open_.mean() > 1.0 - SHAFT_WALLED or not open_.any() or open_.all():
        return None
    k = int(np.argmin(open_))  # start the walk on a wall: every open run is then whole
    o = np.roll(open_, -k)
    starts = np.flatnonzero(o & ~np.roll(o, 1))
    ends = np.flatnonzero(~o[1:] & o[:-1]) + 1  # first walled sample after each run (o[0] is walled)
    ends = np.append(ends, n) if o[-1] else ends
    runs = [(i0, i1) for i0, i1 in zip(starts, ends) if (i1 - i0) * step >= SHAFT_MOUTH[0] / 3]  # corner noise out
    if len(runs) != 1:
        return None
    idx = (np.arange(*runs[0]) + k) % n
    run = pts[idx]
    mouth = LineString([run[0], run[-1]])
    if not SHAFT_MOUTH[0] <= mouth.length <= min(SHAFT_MOUTH[1], SHAFT_MOUTH_SIDE * _short_side(shaft)):
        return None
    return mouth


def _carve_shaft(fl: FloorData, shaft: Area, cand: List[Area], tree) -> Optional[Area]:
    """The shaft ``shaft`` (of a consecutive floor, registered) swallowed by an untyped area of ``fl`` (a lift
    car the segmentation joined to its lobby through the door gap): when one area holds ``SHAFT_HELD`` of it, is at
    least twice its size, and its boundary runs along ≥ ``SHAFT_WALLED`` of the shaft's outline (the shaft's
    walls stand on this floor too) leaving one opening of ``SHAFT_MOUTH`` (its door), the shaft is cut out of
    that area as an area of its own (returned, appended to ``fl.areas``, with a passage through the opening);
    else None. The host keeps its id, name and passages (it must stay one piece)."""
    sp = shaft.polygon
    hosts = [cand[i] for i in tree.query(sp, predicate="intersects")]
    hosts = [h for h in hosts if not anchor_kind(h) and h.polygon.area >= 2 * sp.area
             and h.polygon.intersection(sp).area >= SHAFT_HELD * sp.area]
    if len(hosts) != 1:
        return None
    host = hosts[0]
    mouth = _shaft_mouth(sp, host.polygon)
    if mouth is None:
        return None
    inside = valid_polygon(host.polygon.intersection(sp))
    rest = valid_polygon(host.polygon.difference(sp))
    parts = sorted(getattr(rest, "geoms", [rest]), key=lambda g: -g.area)
    if not parts or parts[0].is_empty or sum(g.area for g in parts[1:]) > 0.5 or inside.is_empty:
        return None
    inside = max(getattr(inside, "geoms", [inside]), key=lambda g: g.area)
    host.polygon = parts[0]
    ids = [a.id for a in fl.areas + fl.structures] + ([fl.outline.id] if fl.outline is not None else [])
    new = Area(id=max(abs(i) for i in ids) + 1, polygon=inside, type=shaft.type,
               tags={"cad2osmag:carved": "yes"})
    fl.areas.append(new)
    if host.id in fl.parents:
        fl.parents[new.id] = fl.parents[host.id]
    pid = max([abs(p.id) for p in fl.passages] + [0]) + 1
    fl.passages.append(Passage(id=pid, from_id=host.id, to_id=new.id, line=mouth))
    return new


def is_fix_id(path: str) -> bool:
    """True when the file references areas by way id (fix-id variant)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            head = fh.read(1_000_000)
    except OSError:
        return False
    return bool(re.search(r'k=["\']osmAG:(?:from|to|parent)["\'] v=["\']-?\d+["\']', head))


def merge_floor_files(paths: Sequence[str], out_path: str, building_name: str = "Building",
                      levels: Optional[Sequence[str]] = None, heights: Optional[Sequence[float]] = None,
                      variant: Optional[str] = None, register: bool = True, strict_passages: bool = False,
                      progress=None) -> Dict[str, object]:
    """osmAG floor files -> one building file (see the module docstring). ``variant`` None: fix-id if
    any input is fix-id, else semantic. The output frame is the first file's root node."""
    from . import osmag

    progress = ensure(progress)
    paths = [str(p) for p in paths if str(p).strip()]
    if not paths:
        raise InputError("no floor files to merge: give at least one osmAG floor file")
    frame = None
    floors = []
    fixid = False
    for i, path in enumerate(paths):
        progress.step(5.0 * i / len(paths), f"reading {os.path.basename(path)}")
        if not os.path.isfile(path):
            raise InputError(f"floor file '{path}' does not exist")
        fl = read_floor(path, frame)
        frame = frame or fl.frame
        floors.append(fl)
        fixid = fixid or is_fix_id(path)
    variant = variant or ("fix-id" if fixid else "semantic")
    return fuse_floors(floors, out_path, frame, building_name=building_name, levels=levels, heights=heights,
                       variant=variant, register=register, strict_passages=strict_passages,
                       progress=progress.sub(5, 100))


def _convert_one(args):
    from . import pipeline, segmentation

    dxf, out, level, kwargs = args
    import time as _t

    t0 = _t.perf_counter()
    with segmentation.busy_cpu():  # in a pool: one of the CPUs its workers keep busy
        stats = pipeline.convert_dxf(dxf, out, level=level, **kwargs)
    return out, _t.perf_counter() - t0, stats.get("areas"), stats.get("passages")


def _pool_worker(running) -> None:
    """Pool initializer: the workers count their running conversions in ``running`` (shared); a worker's
    segmentation takes a second thread only while a CPU is left (``segmentation.share_cpus``): with as many
    workers as CPUs, once the other worker has no floor left."""
    from . import segmentation

    segmentation.share_cpus(running)


def convert_floors(dxf_paths: Sequence[str], out_dir: str, levels: Optional[Sequence[str]] = None,
                   workers: int = 2, progress=None, **convert_kwargs) -> List[Tuple[str, float, int, int]]:
    """Convert DXF floors to osmAG files in ``out_dir`` (``<stem>.osm``), ``workers`` at a time in a
    process pool (each floor is independent). Levels: ``levels``, else from the file names. Returns
    [(osm path, seconds, areas, passages)] in input order. Every floor gets the same anchor (the
    ``anchor_lon``/``anchor_lat`` keyword, default 0/0), so the fusion only has to register them."""
    import concurrent.futures as cf

    progress = ensure(progress)
    jobs = []
    lvs = []
    for k, dxf in enumerate(dxf_paths):
        lv = (levels[k] if levels is not None and k < len(levels) else None) or level_from_name(dxf)
        if lv is None:
            lv = level_from_sheet(dxf)
            if lv is not None:
                progress.info(f"{os.path.basename(dxf)}: level {'roof' if lv == 'R' else lv} from the sheet's "
                              "bound external references")
        if lv is None:
            raise InputError(f"the level of '{os.path.basename(dxf)}' is unknown: neither its name ('*-F3*') nor "
                             "its layers ('E1-RI-3F$0$...') say; give levels")
        lvs.append(str(lv))
    numeric = [float(v) for v in lvs if v != "R"]
    for k, dxf in enumerate(dxf_paths):
        lv = lvs[k]
        if lv == "R":  # a roof plan: the level above the highest floor given
            lv = str(int(max(numeric)) + 1 if numeric else 1)
        out = os.path.join(out_dir, os.path.splitext(os.path.basename(dxf))[0] + ".osm")
        jobs.append((dxf, out, lv, dict(convert_kwargs)))
    os.makedirs(out_dir, exist_ok=True)
    results: Dict[int, tuple] = {}
    if workers <= 1 or len(jobs) == 1:
        for k, job in enumerate(jobs):
            progress.check()
            results[k] = _convert_one(job)
            progress.step(100.0 * (k + 1) / len(jobs), f"{os.path.basename(job[0])}: {results[k][1]:.1f} s")
    else:
        import multiprocessing as mp

        ctx = mp.get_context("spawn")  # no fork of a process that may hold QGIS/Qt state
        # workers busy on every core: a worker's own second thread (segmentation) would only compete with the
        # other workers for the cores; it runs once a core is left (the last floors: _pool_worker)
        with cf.ProcessPoolExecutor(max_workers=workers, mp_context=ctx, initializer=_pool_worker,
                                    initargs=(ctx.Value("i", 0),)) as ex:
            futs = {ex.submit(_convert_one, job): k for k, job in enumerate(jobs)}
            for f in cf.as_completed(futs):
                k = futs[f]
                results[k] = f.result()
                progress.step(100.0 * len(results) / len(jobs),
                              f"{os.path.basename(jobs[k][0])}: {results[k][1]:.1f} s")
                if progress.is_canceled():
                    for other in futs:
                        other.cancel()
                    progress.check()
    return [results[k] for k in range(len(jobs))]


__all__ = ["level_from_layers", "level_from_sheet", "shaft_code", "anchor_name", "convert_floors", "floors_from_layers", "FloorData", "read_floor", "fuse_floors", "merge_floor_files", "level_from_name", "anchor_kind",
           "register_anchors", "Rigid", "floor_anchors"]
