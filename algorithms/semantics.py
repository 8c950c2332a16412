"""Stage 5: room names, numbers and types from the drawing's texts.

Public API
----------
``load_name_rules(path=None) -> NameRules``
    The configurable rules (``default_name_rules.json`` beside this module, or a copy of it).
``normalize_text(text) -> str``
    NFKC, control / bidi / formatting codes removed, whitespace collapsed.
``classify_text(text, rules=None, layer="", block="", tag="") -> (role, reason)``
    role ``name`` | ``number`` | ``ignored``; reason says why (``dimension``, ``area``, ``elevation``,
    ``door/window code``, ``axis``, ``stair arrow``, ``note``, ``title``, ``title block``, ``empty``...).
    ``text`` may be a ``CadText`` (its layer, block and ATTRIB tag are then used).
``room_name_points(texts, rules=None, classified=None) -> [(x, y, text)]``
    Where the room names (and numbers) of a drawing are: evidence that a space is inside the building.
``assign_names(areas, texts, level, rules=None, progress=None, grid=None, labels=None, passages=None,
split=True, classified=None) -> NamesReport``
    Scores every room text against every area exactly as the paper (below), gives each text to its
    best-scoring area, joins name + number, splits areas holding two different room names when a
    narrowing separates them (else ``label_conflict``), suffixes duplicate names, gives unnamed areas
    a stable id ``<level>-<id>`` and types areas from keywords, codes and geometry. Areas are changed in
    place (``name``, ``ref``, ``type``, ``tags``); split pieces and their passages are appended to
    ``areas`` / ``passages``.
``classified``: ``classify_labels(texts, rules)`` computed once by the caller (``pipeline.process_floor``
classifies a drawing's texts once and passes it to every function that needs it).

Score (Zhang et al., "CAD to osmAG", text-to-room association): with the text point p, the area's
centroid c and area A (m²), S = sqrt(A / pi), rho = |p - c| / S, d_b = distance from p to the boundary:
* p inside:  100 - 50 rho for rho <= rho_max (0.7), else 50 - 25 (rho - rho_max);
* p outside, d_b < D_max (2.2 m): 40 + 30 f_size + 20 f_dist, f_size = 1 / (1 + log10(1 + A / 10000)),
  f_dist = 1 - d_b / D_max;
* otherwise 0 (not a candidate). Each text goes to the area with the highest positive score, except that
a text inside an area belongs to it (``inside_first``; the paper would let a room 2 m away, >= 40, beat
a text inside a long corridor far from its centroid, < 40) and that an inside score at or below 0 counts
as 1. Stair/lift detail callouts ("E1-ST-01详见建施(...)", drawn beside the stair on a leader) name the
nearest stair or lift area within ``CALLOUT_REACH`` and are never given to the corridor they lie in.

Layer fields written on the areas (``Area.tags``, so they reach the AREAS layer): ``label_score`` (best
score of the texts used), ``label_texts`` (ids of the CadTexts used, ';'-separated), ``label_conflict``
(the other room names when an area holds several and could not be split). ``osm_tags(area)`` gives the
tags meant for the osmAG file (these three replaced by a ``fixme`` on conflicts).
"""
from __future__ import annotations

import json
import math
import os
import re
import unicodedata
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
from shapely.geometry import LineString, Point
from shapely.ops import split as shp_split
from shapely.strtree import STRtree

from .errors import InputError
from .model import Area, CadText, Passage
from .progress import ensure

DEFAULT_NAME_RULES_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "default_name_rules.json")
RHO_MAX = 0.7
D_MAX = 2.2  # metres
CALLOUT_REACH = 8.0  # metres from a stair/lift detail callout to the stair or lift it names
NARROWING_RATIO = 0.6  # a split cut must be at most this share of the narrower piece's width
MAX_SPLIT_ROUNDS = 4  # an area and its pieces are split at most this many times
DOOR_HALF_WIDTH = 1.4  # metres: clearance thresholds up to half the widest door seed every core
WIDE_OPENING_HALF_WIDTH = 3.0  # beyond, up to this half-width (6 m openings), only the named cores seed
SPLIT_THRESHOLDS = tuple(np.round(np.concatenate([np.arange(0.2, DOOR_HALF_WIDTH + 0.01, 0.1),
                                                  np.arange(DOOR_HALF_WIDTH + 0.2, WIDE_OPENING_HALF_WIDTH + 0.01, 0.2)]), 2))
LABEL_FIELDS = ("label_score", "label_texts", "label_conflict")
ROLES = ("name", "number", "ignored")


# ------------------------------------------------------------------------------------------ rules
@dataclass
class NameRules:
    name_layers: List[str]
    name_blocks: List[str]
    name_tags: List[str]
    number_tags: List[str]
    ignore_layers: List[Tuple[str, List[str]]]
    ignore_patterns: List[Tuple[str, "re.Pattern"]]
    number_patterns: List["re.Pattern"]
    types: List[dict]
    code_types: List[dict]
    max_name_words: int = 7
    max_name_chars: int = 48
    corridor_geometry: Dict[str, float] = field(default_factory=dict)
    source: str = ""
    callout: Optional["re.Pattern"] = None  # "E1-ST-01详见建施(...)": the code a detail reference names
    callout_tail: Optional["re.Pattern"] = None  # "卫生间详见建施(...)": the reference after a name
    weak_name_layers: List[str] = field(default_factory=list)  # generic text layers: names likely, not sure
    # the largest area (m²) a stair / lift code or keyword may type as stairs / elevator (a stair core, a
    # lift shaft or group; an atrium holding an open stair stays what it is)
    vertical_max_area: Dict[str, float] = field(default_factory=lambda: {"stairs": 80.0, "elevator": 40.0})
    # MEP shafts (水井, 加压, shaft, cavedio): closed cavities of the walls, labelled in or beside the cavity
    shaft_keywords: List[str] = field(default_factory=list)
    # outdoor labels (室外…, 排水暗沟, lawn): name no indoor space when they lie outside every area
    outdoor_keywords: List[str] = field(default_factory=list)
    # zones of an open space (阅览区, 开放性坐区, open space, zona): no room where another name labels the space
    zone_keywords: List[str] = field(default_factory=list)
    # small service rooms (开水间 water points, 清洁间 cleaners' closets, 弱电/强电 electrical closets): their
    # label off the centre of a long, busy corridor-shaped area larger than ``point_max_area`` (m²) marks a
    # point along the corridor, not its name (``_demote_service_points``)
    point_keywords: List[str] = field(default_factory=list)
    point_max_area: float = 20.0

    def __post_init__(self):
        # keyword -> (type entry) sorted longest first: the longest keyword found in a name wins
        kws = []
        for entry in self.types:
            for kw in entry.get("keywords", []):
                kws.append((normalize_text(kw).casefold(), entry))
        kws.sort(key=lambda t: -len(t[0]))
        self._type_keywords = [(kw, _keyword_regex(kw), e) for kw, e in kws if kw]


def _keyword_regex(kw: str) -> "re.Pattern":
    """Latin/Cyrillic keywords match at the start of a word (stems: 'riunion' matches 'riunioni');
    CJK keywords match anywhere."""
    if re.match(r"^[\w .'&/-]+$", kw) and not re.search(r"[\u3000-\u9fff]", kw):
        return re.compile(r"(?<![^\W\d_])" + re.escape(kw))
    return re.compile(re.escape(kw))


def _layer_match(words: Sequence[str], name: str) -> Optional[str]:
    """The first keyword occurring in ``name`` (casefolded). ASCII keywords of <= 3 characters must be
    a whole token of the name (``tk`` matches 'TK' or 'A-TK', not 'ATKINS')."""
    if not name:
        return None
    tokens = None
    for w in words:
        if len(w) <= 3 and w.isascii() and w.isalnum():
            if tokens is None:
                tokens = set(re.split(r"[^0-9a-z\u0080-\uffff]+", name))
            if any(tok.startswith(w) for tok in tokens):
                return w
        elif w in name:
            return w
    return None


def load_name_rules(path: Optional[str] = None) -> NameRules:
    """Rules from a JSON file (None: the built-in defaults). Raises InputError on a bad file."""
    src = path or DEFAULT_NAME_RULES_PATH
    try:
        with open(src, encoding="utf-8") as fh:
            data = json.load(fh)
    except FileNotFoundError:
        raise InputError(f"name rules file '{src}' does not exist; give an existing JSON file or leave it empty")
    except (OSError, ValueError) as exc:
        raise InputError(f"name rules file '{os.path.basename(src)}' is not valid JSON ({exc}); "
                         "start from a copy of algorithms/default_name_rules.json")
    if not isinstance(data, dict):
        raise InputError(f"name rules file '{os.path.basename(src)}' must hold a JSON object")

    def words(key):
        return [normalize_text(w).casefold() for w in data.get(key, []) if str(w).strip()]

    try:
        if data.get("callout"):
            re.compile(data["callout"])
        ignore_layers = [(reason, [normalize_text(w).casefold() for w in ws])
                         for reason, ws in (data.get("ignore_layers") or {}).items()]
        pats = [(reason, re.compile(p, re.IGNORECASE)) for reason, p in data.get("ignore_patterns", [])]
        nums = [re.compile(p, re.IGNORECASE) for p in data.get("number_patterns", [])]
        codes = [dict(e, _re=re.compile(e["pattern"], re.IGNORECASE)) for e in data.get("code_types", [])]
        types = [dict(e) for e in data.get("types", [])]
        vmax = {str(k): float(v) for k, v in (data.get("vertical_max_area") or {"stairs": 80.0, "elevator": 40.0}).items()}
        for e in types + codes:
            if e.get("type") not in ("room", "corridor", "stairs", "elevator"):
                raise ValueError(f"unknown area type {e.get('type')!r} (room, corridor, stairs, elevator)")
    except (re.error, ValueError, TypeError, KeyError) as exc:
        raise InputError(f"name rules file '{os.path.basename(src)}': {exc}")
    return NameRules(name_layers=words("name_layers"), name_blocks=words("name_blocks"),
                     name_tags=words("name_tags"), number_tags=words("number_tags"),
                     ignore_layers=ignore_layers, ignore_patterns=pats, number_patterns=nums, types=types,
                     code_types=codes, max_name_words=int(data.get("max_name_words", 7)),
                     max_name_chars=int(data.get("max_name_chars", 48)),
                     corridor_geometry=dict(data.get("corridor_geometry") or {}), source=src,
                     callout=re.compile(data["callout"], re.IGNORECASE) if data.get("callout") else None,
                     callout_tail=re.compile(data["callout_tail"], re.IGNORECASE) if data.get("callout_tail") else None,
                     weak_name_layers=words("weak_name_layers"),
                     vertical_max_area=vmax, shaft_keywords=words("shaft_keywords"),
                     outdoor_keywords=words("outdoor_keywords"), zone_keywords=words("zone_keywords"),
                     point_keywords=words("point_keywords"), point_max_area=float(data.get("point_max_area", 20.0)))


_DEFAULT: Optional[NameRules] = None


def default_name_rules() -> NameRules:
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = load_name_rules(None)
    return _DEFAULT


def _resolve(rules) -> NameRules:
    if rules is None:
        return default_name_rules()
    if isinstance(rules, NameRules):
        return rules
    return load_name_rules(str(rules))


# ------------------------------------------------------------------------------------------ text
_MTEXT_CODES = re.compile(r"\\[ACFHQTWfhqtwacLlOoKkXx][^;\\{}]*;?|\\[PpNn~]|[{}]")
_PERCENT_CODES = {"%%c": "⌀", "%%d": "°", "%%p": "±", "%%u": "", "%%o": "", "%%k": "", "%%%": "%"}
_XREF_PREFIX = re.compile(r"^.*\$\d+\$")


def strip_xref(layer: str) -> str:
    """'E1-RI-1F$0$A-ANNO-ROOM' -> 'A-ANNO-ROOM' (bound external reference prefixes, any depth)."""
    return _XREF_PREFIX.sub("", layer or "")


def normalize_text(text) -> str:
    """Plain, comparable text: MTEXT/percent formatting codes, control and bidi/format characters
    removed, NFKC (full-width forms to ASCII, '㎡' to 'm2'), whitespace collapsed."""
    if text is None:
        return ""
    s = str(text)
    if "\\" in s or "{" in s:
        s = _MTEXT_CODES.sub(" ", s)
    if "%%" in s:
        for k, v in _PERCENT_CODES.items():
            s = re.sub(re.escape(k), v, s, flags=re.IGNORECASE)
    if "\x1b" in s:
        s = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]|\x1b[@-_]", " ", s)  # terminal escape sequences
    s = unicodedata.normalize("NFKC", s)
    s = "".join(ch if unicodedata.category(ch)[0] != "C" else " " for ch in s)
    s = " ".join(s.split())
    # letter-spaced CJK names ("走 道", "通 廊") are one word
    return re.sub(r"(?<=[\u3400-\u9fff])\s+(?=[\u3400-\u9fff])", "", s)


def _has_letter(s: str) -> bool:
    return any(unicodedata.category(ch).startswith("L") for ch in s)


def _text_fields(text, layer, block, tag):
    if isinstance(text, CadText):
        return text.text, text.layer, text.block, text.tag
    return text, layer, block, tag


def classify_text(text, rules=None, layer: str = "", block: str = "", tag: str = "",
                  _plain_block: bool = False) -> Tuple[str, str]:
    """``(role, reason)`` of one text. role: ``name`` (a room name), ``number`` (a room number, kept
    as ref), ``ignored``. The reason names the rule: 'name layer', 'keyword', 'room tag' ... for names
    and numbers; 'dimension', 'area', 'elevation', 'door/window code', 'axis', 'stair arrow', 'note',
    'title', 'title block', 'furniture', 'long text', 'empty', 'digits only' ... for ignored texts."""
    rules = _resolve(rules)
    raw, layer, block, tag = _text_fields(text, layer, block, tag)
    s = normalize_text(raw)
    if not s or not re.search(r"\w", s):
        return "ignored", "empty"
    low = s.casefold()
    lay = strip_xref(layer).casefold()
    blk = strip_xref(block).casefold()
    tg = normalize_text(tag).casefold()
    # ---- ATTRIB tags and room-name layers / blocks: what the drawing says the text is
    tag_tokens = set(re.split(r"[^0-9a-z\u0080-\uffff]+", tg)) if tg else set()
    number_tag = bool(tg) and any((w in tag_tokens) if len(w) <= 3 else (w in tg) for w in rules.number_tags)
    name_tag = bool(tg) and not number_tag and any(
        (w in tag_tokens) if len(w) <= 3 else (w in tg) for w in rules.name_tags)
    name_layer = _layer_match(rules.name_layers, lay)
    name_block = _layer_match(rules.name_blocks, blk)
    if name_block and not _plain_block:
        # a generic tag block ('ECADI-TAG-DOOR', 'TAG-GRID') says what it tags: a door, an axis... the
        # word 'tag' alone is no room evidence then; nor is it when the ATTRIB tag names doors ('门窗主编号').
        # What the text would be as a room tag decides: a would-be name or number is that block's thing
        # ('door/window code (block)'); a text ignored anyway keeps its own reason ('FM乙1522').
        for reason, words in rules.ignore_layers:
            if _layer_match(words, blk) or (tg and _layer_match(words, tg)):
                if name_tag or number_tag:
                    name_block = None
                    break
                role, why = classify_text(raw, rules, layer=layer, block=block, tag=tag, _plain_block=True)
                return ("ignored", f"{reason} (block)") if role != "ignored" else (role, why)
    evidence = "room tag" if (name_tag or number_tag) else ("name layer" if name_layer else
                                                            ("room block" if name_block else ""))
    weak = not evidence and bool(_layer_match(rules.weak_name_layers, lay))
    type_hit = _type_entry(low, rules)
    # ---- layers that hold other things
    if not evidence:
        for reason, words in rules.ignore_layers:
            if _layer_match(words, lay):
                if reason in ("stair arrow", "door/window code", "note") and type_hit is not None and \
                        _is_name_like(low, rules):
                    break  # "Stair A" on the stair layer is a name
                return "ignored", f"{reason} (layer)"
    # ---- numbers
    if number_tag:
        return ("number", "room tag") if _has_alnum(low) else ("ignored", "empty")
    if _is_door_code(low, rules):
        return "ignored", "door/window code"
    if any(p.search(low) for p in rules.number_patterns) and not _is_elevation(low, rules):
        digits = low.isdigit()
        if digits and not evidence and int(low) % 50 == 0:
            return "ignored", "dimension"
        return "number", evidence or "number pattern"
    if low.isdigit() or re.fullmatch(r"[\d\s.,]+", low):
        if evidence and low.isdigit():
            return "number", evidence
        # single digits: axis bubbles, section marks; more: dimensions
        return "ignored", "axis" if len(low) <= 2 else "dimension"
    # ---- everything else that is not a name
    for reason, pat in rules.ignore_patterns:
        if evidence and reason in ("furniture", "long text", "spaced title"):
            continue
        if pat.search(low):
            if reason in ("furniture",) and type_hit is not None and type_hit[1].get("type") != "room":
                continue
            return "ignored", reason
    if not _has_letter(low):
        return "ignored", "digits only" if re.search(r"\d", low) else "symbols only"
    if not evidence and (len(low) > rules.max_name_chars or len(low.split()) > rules.max_name_words):
        return "ignored", "long text"
    if name_tag:
        return "name", "room tag"
    if evidence:
        return "name", evidence
    if weak and type_hit is None:
        return "name", "text layer"
    if type_hit is not None:
        return "name", "keyword"
    return "name", "short text"


def _has_alnum(s: str) -> bool:
    return any(ch.isalnum() for ch in s)


def _is_name_like(low: str, rules: NameRules) -> bool:
    return len(low) <= rules.max_name_chars and not _is_arrow(low, rules)


def _is_arrow(low: str, rules: NameRules) -> bool:
    return any(r == "stair arrow" and p.search(low) for r, p in rules.ignore_patterns)


def _is_door_code(low: str, rules: NameRules) -> bool:
    return any(r == "door/window code" and p.search(low) for r, p in rules.ignore_patterns)


def _is_elevation(low: str, rules: NameRules) -> bool:
    return any(r in ("elevation", "area") and p.search(low) for r, p in rules.ignore_patterns)


def _type_entry(low: str, rules: NameRules):
    """(keyword, entry) of the longest type keyword in the text, or None."""
    for kw, rx, entry in rules._type_keywords:
        if kw in low and rx.search(low):  # every keyword regex matches the keyword itself: test that first
            return kw, entry
    return None


def type_of_name(name: str, ref: str = "", rules=None) -> Optional[dict]:
    """The type entry (type, indoor, room) a name or number implies: code patterns first
    (E1-ST-03 stairs, E2-P1 lift), then the longest keyword. None when nothing matches."""
    rules = _resolve(rules)
    for s in (ref, name):
        low = normalize_text(s).casefold()
        if not low:
            continue
        for e in rules.code_types:
            if e["_re"].search(low):
                return e
    hit = _type_entry(normalize_text(name).casefold(), rules)
    return hit[1] if hit else None


# ------------------------------------------------------------------------------------------ lines
@dataclass
class Label:
    """One label: a text, or several lines of one multi-line TEXT label joined."""

    ids: List[int]
    text: str
    x: float
    y: float
    height: float
    layer: str
    block: str
    tag: str
    role: str = ""
    reason: str = ""
    alts: List[Tuple[float, float]] = field(default_factory=list)  # where copies of it are drawn


def _text_id(t: CadText, k: int) -> int:
    return int(t.id) if getattr(t, "id", -1) is not None and int(getattr(t, "id", -1)) >= 0 else k


def _est_width(s: str, h: float) -> float:
    wide = sum(1 for ch in s if unicodedata.east_asian_width(ch) in ("W", "F"))
    return h * (0.65 * (len(s) - wide) + 1.0 * wide)


_NO_JOIN = ("elevation", "area", "dimension", "axis", "door/window code", "scale", "stair arrow", "empty")

# switches of the two rules below (tests turn them off to show what they do)
TEXT_FRAME_JOIN = True  # lines of a label are stacked in the texts' own frame, not only when upright
STACKED_NAMES_GUARD = True  # two stacked lines that are each a complete name of a different kind stay two


def _room_word(low: str, rules: NameRules):
    """(keyword, kind) of the longest room word in ``low`` (casefolded): a type keyword (kind: its type
    entry), a shaft keyword (kind 'shaft') or a service-point keyword (kind 'point'); None when none."""
    hit = _type_entry(low, rules)
    best = None if hit is None else (hit[0], (hit[1].get("type"), hit[1].get("indoor"), hit[1].get("room")))
    for kind, words in (("shaft", rules.shaft_keywords), ("point", rules.point_keywords)):
        for w in words:
            w = normalize_text(w).casefold()
            if best is not None and len(w.lstrip("=")) <= len(best[0]):
                continue
            if _matches([w], low):
                best = (w.lstrip("="), (kind,))
    return best


_GENERIC_ROOM = ("room", "room", "")  # the kind of 'room', 'sala', 'Raum': a word of a name, not a name


def _two_names(upper: str, lower: str, rules: NameRules, roles_differ: bool = False) -> bool:
    """Two stacked lines that are each a complete name by themselves are two names, not one label: each
    holds a room word (a type, shaft or service-point keyword) and they name different kinds of space
    ('排风井' over '清洁间': a shaft and a cleaners' closet of two neighbouring shafts), or they are the
    same name twice. A keyword running across the two lines keeps them one name ('Vano' over 'scala':
    'vano scala'); so do lines of one kind ('WC' over 'uomini'), a line without a room word ('Ufficio' over
    'direttore') and a line that is only a generic room word ('Sala' over 'riunioni', 'Technical' over
    'room'; a name ending in one, '理论与计算研究室', is complete). ``roles_differ``: one line is a room name, the other one the rules ignore (a note): they are two
    labels when either holds a room word ('送风' supply air over '女卫生间', a shaft's '水井' over a room's
    name): a note's second line without one ('PISO DE LADRILLO' over 'ESPINA DE PEZ') stays in the note."""
    a, b = normalize_text(upper).casefold(), normalize_text(lower).casefold()
    ka, kb = _room_word(a, rules), _room_word(b, rules)
    # a line that is only a generic word ('Sala', 'room') is part of a name; '理论与计算研究室' (…室) is a name
    whole = [k is not None and not (k[1] == _GENERIC_ROOM and low == k[0]) for k, low in ((ka, a), (kb, b))]
    if roles_differ:
        return any(whole)
    if not all(whole):
        return False
    kj = _room_word(a + " " + b, rules)
    if kj is not None and kj[0] not in a and kj[0] not in b:
        return False  # one keyword over both lines
    return ka[1] != kb[1] or _key(upper) == _key(lower)


def _frame_angle(rotation: float) -> Optional[float]:
    """The angle (deg, (-90, 90]) of the frame a text's lines stack in, None when it cannot be a line of a
    label. The rotation alone does not tell a mirrored text from an upside-down one (a mirrored INSERT gives
    180 - r): a text turned more than 90 deg is read as mirrored, its lines stacked as if it were turned back
    by 180 deg (an upright label mirrored reads top to bottom; a plan turned upside down, not mirrored, joins
    its lines in reverse order). Texts within 1 deg of upright use the page axes; with ``TEXT_FRAME_JOIN``
    off only they are lines (the old behaviour)."""
    r = float(rotation or 0.0)
    if not math.isfinite(r):
        return None
    a = r % 180.0
    if a < 1.0 or a > 179.0:
        return 0.0
    if not TEXT_FRAME_JOIN:
        return None
    return a - 180.0 if a > 90.0 else a


def group_lines(texts: Sequence[CadText], rules=None, _memo=None) -> List[Label]:
    """Join the lines of multi-line labels drawn as separate TEXTs: same layer, height (+-15 %) and
    rotation (+-1 deg), the next line 0.5-2.7 heights below the previous one and overlapping it along the
    line, both measured in the texts' own frame (a label on a turned or mirrored drawing reads as
    delivered). Two lines that are each a complete name of another kind stay two (``_two_names``).
    Each text belongs to at most one label; ATTRIBs and MTEXTs stay alone (they carry their own lines)."""
    labels: List[Label] = []
    cand = []
    ang: Dict[int, float] = {}
    roles: Dict[int, str] = {}
    memo = {} if _memo is None else _memo
    rules_ = _resolve(rules)
    for k, t in enumerate(texts):
        s = normalize_text(t.text)
        lab = Label([_text_id(t, k)], s, float(t.x), float(t.y), float(t.height or 0.0), t.layer or "",
                    getattr(t, "block", "") or "", getattr(t, "tag", "") or "")
        labels.append(lab)
        a = _frame_angle(t.rotation) if t.entity == "TEXT" and s and t.height and t.height > 0 else None
        if a is not None and math.isfinite(lab.x) and math.isfinite(lab.y):
            role, reason = _classify_memo(memo, s, rules_, lab.layer, lab.block, lab.tag)
            callout = rules_.callout is not None and rules_.callout.match(s.casefold()) is not None
            # numbers, elevations, areas... are lines of their own: "Office" over "101" is name + number;
            # so is a detail callout ("E1-ST-01详见…" stacked over "E1-ST-02详见…" are two callouts)
            if role != "number" and not callout and reason.split(" (")[0] not in _NO_JOIN:
                cand.append(len(labels) - 1)
                ang[len(labels) - 1], roles[len(labels) - 1] = a, role
    if len(cand) < 2:
        return labels
    above: Dict[int, int] = {}
    # texts of one rotation (+-1 deg, modulo 180) stack in their own frame: u along the line, v up
    cand.sort(key=lambda i: ang[i])
    groups: List[List[int]] = [[cand[0]]]
    for i in cand[1:]:
        if ang[i] - ang[groups[-1][-1]] <= 1.0:
            groups[-1].append(i)
        else:
            groups.append([i])
    if len(groups) > 1 and ang[groups[0][0]] + 180.0 - ang[groups[-1][-1]] <= 1.0:
        groups[0] = groups.pop() + groups[0]  # 179.5 and 0.3 deg are one rotation
    for grp in groups:
        if len(grp) > 1:
            _link_lines(labels, grp, float(np.median([ang[i] for i in grp])), above, rules_, roles)
    if not above:
        return labels
    below = {j: i for i, j in above.items()}
    out: List[Label] = []
    used = set()
    for k, lab in enumerate(labels):
        if k in used:
            continue
        if k in above:  # not the first line: emitted with its first line
            continue
        chain = [k]
        while chain[-1] in below:
            chain.append(below[chain[-1]])
        used.update(chain)
        if len(chain) == 1:
            out.append(lab)
            continue
        parts = [labels[c] for c in chain]
        out.append(Label(ids=[i for p in parts for i in p.ids], text=" ".join(p.text for p in parts),
                         x=float(np.mean([p.x for p in parts])), y=float(np.mean([p.y for p in parts])),
                         height=lab.height, layer=lab.layer, block=lab.block, tag=lab.tag))
    return out


def _link_lines(labels: List[Label], cand: List[int], deg: float, above: Dict[int, int], rules: NameRules,
                roles: Dict[int, str]) -> None:
    """Link each candidate line to the nearest line right above it in the frame turned by ``deg``
    (``above[line] = the line above``). With ``STACKED_NAMES_GUARD`` a room name and a line the rules ignore
    ('送风' supply air over '女卫生间', a shaft's '水井' beside a room name) are not one label either: the
    lines of one label are of one role (the old join made the name a note and lost it)."""
    c, s_ = (1.0, 0.0) if deg == 0.0 else (math.cos(math.radians(deg)), math.sin(math.radians(deg)))
    uv = {i: (labels[i].x * c + labels[i].y * s_, -labels[i].x * s_ + labels[i].y * c) for i in cand}
    # sort candidates top to bottom
    cand = sorted(cand, key=lambda i: (-uv[i][1], uv[i][0]))
    xs = np.array([uv[i][0] for i in cand])
    ys = np.array([uv[i][1] for i in cand])
    taken = set(above.values())
    for a_pos, i in enumerate(cand):
        li = labels[i]
        h = li.height
        dy = ys - ys[a_pos]  # positive: the other line is above
        ok = (dy >= 0.5 * h) & (dy <= 2.7 * h)
        if not ok.any():
            continue
        best = None
        for b_pos in np.flatnonzero(ok):
            j = cand[b_pos]
            lj = labels[j]
            if j in taken or lj.layer != li.layer or abs(lj.height - h) > 0.15 * max(h, lj.height):
                continue
            wi, wj = _est_width(li.text, h), _est_width(lj.text, h)
            # overlap of [u, u + w] extents, tolerant to centred/right alignment
            if min(xs[a_pos] + wi, xs[b_pos] + wj) - max(xs[a_pos] - 0.5 * wi, xs[b_pos] - 0.5 * wj) <= 0:
                continue
            d = dy[b_pos] + abs(xs[b_pos] - xs[a_pos]) / max(wi, wj, 1e-9)
            if best is None or d < best[0]:
                best = (d, j)
        if best is not None:
            if STACKED_NAMES_GUARD and _two_names(labels[best[1]].text, li.text, rules, roles[best[1]] != roles[i]):
                continue
            above[i] = best[1]
            taken.add(best[1])


def classify_labels(texts: Sequence[CadText], rules=None) -> List[Label]:
    """Labels (multi-line TEXTs joined) with role and reason. Two refinements on top of
    ``classify_text``: a detail callout ('E1-ST-01详见建施(A-E-40-01)', 'P2 see 5/A-501') is the room
    number it names; a name ending in a room code ('研究室 E1a-F4-06') is split into name + number."""
    rules = _resolve(rules)
    memo: Dict[tuple, Tuple[str, str]] = {}  # one drawing repeats its texts (door codes, tags): classify each once
    labels = group_lines(texts, rules, _memo=memo)
    out: List[Label] = []
    for lab in labels:
        m = rules.callout.match(lab.text.casefold()) if rules.callout is not None and lab.text else None
        if m and m.group("code"):
            lab.text = lab.text[m.start("code"):m.end("code")]
            lab.role, lab.reason = "number", "callout"
            out.append(lab)
            continue
        if rules.callout_tail is not None and lab.text:
            m = rules.callout_tail.search(lab.text)
            if m and m.start() > 0 and _has_letter(lab.text[:m.start()]):
                lab.text = lab.text[:m.start()].strip()
        lab.role, lab.reason = _classify_memo(memo, lab.text, rules, lab.layer, lab.block, lab.tag)
        parts = lab.text.rsplit(" ", 1)
        if lab.role == "name" and len(parts) == 2 and "-" in parts[1] and _has_letter(parts[0]) and \
                any(p.search(parts[1].casefold()) for p in rules.number_patterns):
            from dataclasses import replace

            out.append(replace(lab, text=parts[0]))
            out.append(replace(lab, text=parts[1], role="number", reason="code after the name"))
            continue
        out.append(lab)
    return _merge_copies(out)


def _classify_memo(memo: Dict[tuple, Tuple[str, str]], text: str, rules: NameRules, layer: str, block: str,
                   tag: str) -> Tuple[str, str]:
    """``classify_text`` remembered in ``memo`` (one call of ``classify_labels``: the rules do not change)."""
    key = (text, layer, block, tag)
    hit = memo.get(key)
    if hit is None:
        hit = memo[key] = classify_text(text, rules, layer=layer, block=block, tag=tag)
    return hit


def _merge_copies(labels: List[Label]) -> List[Label]:
    """One label drawn twice is one label: a room tag block inserted twice (an xref bound twice, a copy
    pasted in place: every tag of library sheet A-A3-10-04 is there twice) or the same name copied to a
    layer for another print scale ('大厅' on 'I—平面—文字' and, shifted by a line and at half the height,
    on 'I—平面—文字（放大1：100）' on SIST-F1). Names and numbers with the same text count once when
    their insertion points are within a quarter of the text height, or, on different layers, within twice
    the larger height; the copy's ids join the first label and its position is kept as an alternative
    (``Label.alts``: the label is where its best-placed copy is)."""
    keep: List[Label] = []
    seen: Dict[Tuple[str, str], List[Label]] = {}
    for lab in labels:
        if lab.role not in ("name", "number") or not (math.isfinite(lab.x) and math.isfinite(lab.y)):
            keep.append(lab)
            continue
        key = (lab.role, _key(lab.text))
        twin = None
        for o in seen.get(key, []):
            d = math.hypot(lab.x - o.x, lab.y - o.y)
            h = max(lab.height, o.height, 0.0)
            if d <= max(0.25 * h, 1e-3) or (lab.layer != o.layer and d <= 2.0 * h):
                twin = o
                break
        if twin is not None:
            twin.ids = list(dict.fromkeys(twin.ids + lab.ids))
            twin.alts.append((lab.x, lab.y))
            if PLAIN_SPELLING and _floor_prefix(twin.text) and not _floor_prefix(lab.text):
                twin.text = lab.text  # one label: its plain spelling ('中庭回廊' over '2F中庭回廊', see _spelling)
            continue
        seen.setdefault(key, []).append(lab)
        keep.append(lab)
    return keep


def room_name_points(texts: Sequence[CadText], rules=None, classified: Optional[List[Label]] = None
                     ) -> List[Tuple[float, float, str]]:
    """(x, y, text) of every room name and room number of a drawing (CAD frame, metres). Segmentation
    uses them as evidence that the space around them is inside the building. Door and window tags of
    tag blocks ('1522' in ECADI-TAG-DOOR) are no names but mark the building's doorways: they count as
    evidence too (without them SIST-F3's largest component fell from 98 % to 80 % of the floor).
    ``classified``: ``classify_labels(texts, rules)`` when the caller has it (classify a drawing once)."""
    out = []
    for lab in (classify_labels(texts, rules) if classified is None else classified):
        if lab.role in ("name", "number") or lab.reason == "door/window code (block)":
            out.append((lab.x, lab.y, lab.text))
            out.extend((x, y, lab.text) for x, y in lab.alts)  # every copy of a label drawn twice
    return out


PROTECTED_TYPE = "room:labelled"  # temporary type that keeps refinement from merging a labelled small room


def protect_labelled_areas(areas: Sequence[Area], texts: Sequence[CadText], min_area: float, rules=None,
                           smallest: float = 1.0, classified: Optional[List[Label]] = None) -> Dict[int, str]:
    """Before refinement: areas smaller than ``min_area`` (but at least ``smallest`` m²) that hold a room
    name or number get the temporary type ``PROTECTED_TYPE`` so that the small-area merge keeps them (a
    labelled WC or store room is a room, however small); so do those a room name lies beside, in the
    wall, outside every area (within ``PROTECT_REACH``). Returns {area id: original type} for
    ``restore_types``. ``classified``: ``classify_labels(texts, rules)`` when the caller has it."""
    if classified is None:
        classified = classify_labels(texts, rules)
    pts = room_name_points(texts, rules, classified=classified)
    if not pts:
        return {}
    small = [a for a in areas if smallest <= a.polygon.area < min_area and a.type in ("room", "corridor")]
    if not small:
        return {}
    tree = STRtree([a.polygon for a in small])
    saved: Dict[int, str] = {}
    for x, y, _ in pts:
        for i in tree.query(Point(x, y), predicate="intersects").tolist():
            a = small[i]
            if a.id not in saved:
                saved[a.id] = a.type
                a.type = PROTECTED_TYPE
    # a room name whose insertion point falls in the wall (outside every area) within PROTECT_REACH of a
    # small area labels that area: SIST-F3's 4 m² '储藏室' starts 9 cm inside the wall of its store room,
    # which the merge then gave to the boiled-water room next door
    all_polys = [a.polygon for a in areas if a.polygon is not None and not a.polygon.is_empty]
    any_tree = STRtree(all_polys)
    for lab in classified:
        if lab.role != "name":
            continue
        for x, y in [(lab.x, lab.y)] + list(lab.alts):
            if not (math.isfinite(x) and math.isfinite(y)):
                continue
            p = Point(x, y)
            if len(any_tree.query(p, predicate="intersects")):
                continue
            near = tree.query(p, predicate="dwithin", distance=PROTECT_REACH).tolist()
            if not near:
                continue
            a = small[min(near, key=lambda i: (small[i].polygon.distance(p), small[i].id))]
            if a.id not in saved:
                saved[a.id] = a.type
                a.type = PROTECTED_TYPE
    return saved


PROTECT_REACH = 0.3  # metres: a name this close to a small area, outside every area, labels it (in the wall)


def restore_types(saved: Dict[int, str], *area_lists: Sequence[Area]) -> None:
    for areas in area_lists:
        for a in areas:
            if a.type == PROTECTED_TYPE:
                a.type = saved.get(a.id, "room")


# ------------------------------------------------------------------------------------------ score
def score(px: float, py: float, polygon, centroid=None, area: Optional[float] = None,
          rho_max: float = RHO_MAX, d_max: float = D_MAX) -> Tuple[float, str]:
    """The paper's score of text point (px, py) for a polygon and how it matched: 'inside', 'nearby'
    or '' (score 0, not a candidate). Inside scores at or below 0 are raised to 1 (see module doc)."""
    A = float(polygon.area) if area is None else float(area)
    if A <= 0:
        return 0.0, ""
    p = Point(px, py)
    if polygon.covers(p):
        c = centroid if centroid is not None else polygon.centroid
        S = math.sqrt(A / math.pi)
        rho = math.hypot(px - c.x, py - c.y) / S
        s = 100.0 - 50.0 * rho if rho <= rho_max else 50.0 - 25.0 * (rho - rho_max)
        return max(s, 1.0), "inside"
    d_b = float(polygon.exterior.distance(p)) if polygon.geom_type == "Polygon" else float(polygon.distance(p))
    if d_b < d_max:
        f_size = 1.0 / (1.0 + math.log10(1.0 + A / 10000.0))
        f_dist = 1.0 - d_b / d_max
        return 40.0 + 30.0 * f_size + 20.0 * f_dist, "nearby"
    return 0.0, ""


# ------------------------------------------------------------------------------------------ report
@dataclass
class TextRecord:
    ids: List[int]
    text: str
    x: float
    y: float
    layer: str
    role: str
    reason: str
    area_id: Optional[int] = None
    score: float = 0.0
    match: str = ""  # inside | nearby | "" (outside every area)
    hidden: bool = False  # on a frozen / off layer (CadDrawing.hidden_texts)
    alts: List[Tuple[float, float]] = field(default_factory=list)  # copies of the label drawn elsewhere


@dataclass
class NamesReport:
    texts: List[TextRecord] = field(default_factory=list)
    named: int = 0  # areas with a name from the drawing
    numbered: int = 0  # areas with a ref
    auto: int = 0  # areas with a generated id
    conflicts: List[int] = field(default_factory=list)  # area ids holding several names
    splits: List[Tuple[int, List[int]]] = field(default_factory=list)  # (original id, piece ids)
    duplicates: Dict[str, List[int]] = field(default_factory=dict)  # name -> area ids suffixed
    typed: Dict[str, int] = field(default_factory=dict)  # type -> count set from names / geometry
    new_passages: List[int] = field(default_factory=list)
    base_names: Dict[int, str] = field(default_factory=dict)  # area id -> name from the drawing, before suffixes
    name_record: Dict[int, "TextRecord"] = field(default_factory=dict)  # area id -> the text it is named after
    hidden: List[TextRecord] = field(default_factory=list)  # room texts of frozen / off layers (fallback names)

    def counts(self) -> Dict[str, object]:
        ignored: Dict[str, int] = {}
        for r in self.texts:
            if r.role == "ignored":
                ignored[r.reason] = ignored.get(r.reason, 0) + 1
        room = [r for r in self.texts if r.role in ("name", "number")]
        return {"labels": len(self.texts), "names": sum(r.role == "name" for r in self.texts),
                "numbers": sum(r.role == "number" for r in self.texts),
                "ignored": sum(r.role == "ignored" for r in self.texts), "ignored_by_reason": ignored,
                "assigned": sum(r.area_id is not None for r in room),
                "inside": sum(r.match == "inside" for r in room), "nearby": sum(r.match == "nearby" for r in room),
                "outside": sum(r.area_id is None for r in room), "named_areas": self.named,
                "numbered_areas": self.numbered, "auto_ids": self.auto, "conflicts": len(self.conflicts),
                "splits": len(self.splits), "duplicate_names": len(self.duplicates), "typed": dict(self.typed),
                "hidden": len(self.hidden), "hidden_used": sum(r.area_id is not None for r in self.hidden)}

    def summary(self) -> str:
        c = self.counts()
        ign = ", ".join(f"{k} {v}" for k, v in sorted(c["ignored_by_reason"].items(), key=lambda kv: -kv[1]))
        return (f"{c['labels']} labels: {c['names']} room names, {c['numbers']} room numbers, {c['ignored']} "
                f"ignored ({ign or 'none'}); {c['assigned']} assigned ({c['inside']} inside, {c['nearby']} "
                f"nearby), {c['outside']} outside every area; {c['named_areas']} areas named, "
                f"{c['numbered_areas']} numbered, {c['auto_ids']} with a generated id, {c['splits']} split, "
                f"{c['conflicts']} with conflicting names, {c['duplicate_names']} duplicate names suffixed"
                + (f"; {c['hidden_used']} of {c['hidden']} room texts on frozen/off layers name an area no "
                   "visible text names" if c["hidden"] else ""))


def floor_figures(areas: Sequence[Area], passages: Sequence[Passage], report: Optional[NamesReport]) -> Dict[str, object]:
    """Quality figures of one converted floor (``make evaluate-cad``): room-name texts inside an area and
    naming an area of their own (%), the largest component's share of the floor area (%), semantic
    accuracy (named areas whose name text lies inside them, %), counts."""
    rooms = [a for a in areas if a.type != "structure"]
    parent = {a.id: a.id for a in rooms}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for p in passages:
        if p.from_id in parent and p.to_id in parent:
            parent[find(p.from_id)] = find(p.to_id)
    comp: Dict[int, float] = {}
    for a in rooms:
        comp[find(a.id)] = comp.get(find(a.id), 0.0) + a.area
    total = sum(comp.values())
    out: Dict[str, object] = {"areas": len(rooms), "passages": len(passages), "components": len(comp),
                              "largest_component_pct": 100.0 * max(comp.values()) / total if total else 0.0,
                              "stairs": sum(a.type == "stairs" for a in rooms),
                              "elevators": sum(a.type == "elevator" for a in rooms),
                              "corridors": sum(a.type == "corridor" for a in rooms)}
    if report is None:
        return out
    names = [r for r in report.texts if r.role == "name"]
    conflict = {a.id for a in rooms if (a.tags or {}).get("label_conflict")}
    own = 0
    for r in names:
        if r.area_id is None or r.area_id in conflict:
            continue
        if _key(report.base_names.get(r.area_id, "")) == _key(r.text):
            own += 1
    named = [aid for aid, rec in report.name_record.items() if rec.role == "name"]
    correct = sum(report.name_record[aid].match == "inside" for aid in named)
    c = report.counts()
    out.update({"room_texts": len(names), "numbers": c["numbers"], "ignored": c["ignored"],
                "ignored_by_reason": c["ignored_by_reason"],
                "inside_pct": 100.0 * sum(r.match == "inside" for r in names) / len(names) if names else None,
                "own_area_pct": 100.0 * own / len(names) if names else None,
                "named_areas": len(named), "conflicts": len(conflict & set(named)),
                "conflict_pct": 100.0 * len(conflict & set(named)) / len(named) if named else None,
                "semantic_accuracy_pct": 100.0 * correct / len(named) if named else None,
                "splits": len(report.splits), "outside": c["outside"], "own_texts": own,
                "hidden_texts": c["hidden"], "hidden_used": c["hidden_used"]})
    return out


def missed_texts(areas: Sequence[Area], report: Optional[NamesReport]) -> List[Dict[str, object]]:
    """The room-name texts that miss the quality figures, with why: ``outside`` (no area), ``nearby``
    (beside an area, not in one), ``conflict`` (in an area holding another name), ``not own`` (the area
    is named after another text). For ``make evaluate-cad --misses``: the list to look at on a new drawing."""
    if report is None:
        return []
    by_id = {a.id: a for a in areas}
    conflict = {a.id for a in areas if (a.tags or {}).get("label_conflict")}
    out = []
    for r in report.texts:
        if r.role != "name":
            continue
        why = []
        if r.area_id is None:
            why.append("outside")
        elif r.match != "inside":
            why.append("nearby")
        if r.area_id in conflict:
            why.append("conflict")
        elif r.area_id is not None and _key(report.base_names.get(r.area_id, "")) != _key(r.text):
            why.append("not own")
        if why:
            a = by_id.get(r.area_id)
            out.append({"text": r.text, "x": round(r.x, 2), "y": round(r.y, 2), "layer": r.layer, "why": "+".join(why),
                        "area": r.area_id, "area_name": a.name if a is not None else "",
                        "area_m2": round(float(a.polygon.area), 1) if a is not None else None,
                        "conflict": (a.tags or {}).get("label_conflict", "") if a is not None else ""})
    return out


# ------------------------------------------------------------------------------------------ assign
_LEVEL_PREFIX = re.compile(r"^(\d{1,2}f|b\d)\s*(?=[\u3400-\u9fff])")


def _key(name: str) -> str:
    """Comparable name: normalised, casefolded; a floor prefix before a CJK name is dropped ('2F中庭回廊'
    and '中庭回廊' are one name)."""
    return _LEVEL_PREFIX.sub("", " ".join(normalize_text(name).casefold().split()))


def _floor_prefix(name: str) -> str:
    """The floor prefix of a CJK name ('2f' for '2F中庭回廊'), '' when it has none."""
    m = _LEVEL_PREFIX.match(" ".join(normalize_text(name).casefold().split()))
    return m.group(1) if m else ""


def _level_prefixes(level) -> set:
    """The floor prefixes that mean this plan's ``level`` ('3', 'L3', '3F' -> {'3f'}; '-1', 'B1' -> {'b1'})."""
    low = str(level or "").strip().casefold()
    m = re.fullmatch(r"(?:l|level\s*)?(-?\d{1,2})f?|b(\d)", low)
    if not m:
        return set()
    if m.group(2):
        return {f"b{m.group(2)}"}
    n = int(m.group(1))
    return {f"{n}f"} if n > 0 else {f"b{-n}"} if n < 0 else set()


PLAIN_SPELLING = True  # switch of the rule below (tests turn it off to show what it does)


def _spelling(rec: TextRecord, recs: Sequence[TextRecord], level) -> str:
    """The spelling an area is named by, among the copies of its name (one ``_key``): a copy written with a
    floor prefix ('2F中庭回廊' on the 3F plan: an atrium gallery labelled for every floor it spans, the labels
    copied from another floor's sheet) never wins over the plain spelling ('中庭回廊') of the same name in
    the area; when every copy carries a prefix, the one naming this plan's ``level`` wins. Otherwise (one
    spelling, or no copy matching the level) the best-placed copy ``rec`` names it, as before."""
    if not PLAIN_SPELLING or not _floor_prefix(rec.text):
        return rec.text
    key = _key(rec.text)
    copies = sorted([r for r in recs if r.role == "name" and _key(r.text) == key],
                    key=lambda r: (r.match == "nearby", r.hidden, not _strong(r), -r.score, r.ids[0]))
    plain = [r for r in copies if not _floor_prefix(r.text)]
    if plain:
        return plain[0].text
    own = _level_prefixes(level)
    mine = [r for r in copies if _floor_prefix(r.text) in own]
    return mine[0].text if mine else rec.text


def auto_id(level: str, area_id: int) -> str:
    """The stable generated id of an unnamed area: ``<level>-<area id>``."""
    return f"{str(level).strip() or '1'}-{int(area_id)}"


def assign_names(areas: List[Area], texts: Sequence[CadText], level="1", rules=None, progress=None,
                 grid=None, labels=None, passages: Optional[List[Passage]] = None, split: bool = True,
                 rho_max: float = RHO_MAX, d_max: float = D_MAX, inside_first: bool = True,
                 hidden_texts: Optional[Sequence[CadText]] = None,
                 classified: Optional[List[Label]] = None, partitions=None, door_hints=None) -> NamesReport:
    """Name, number and type ``areas`` (in place) from ``texts``; see the module doc. ``grid`` gives
    the resolution of the split raster, ``labels`` (the label raster on ``grid``) is updated for split
    areas, ``passages`` get the split cuts and follow the pieces. ``hidden_texts``: texts on frozen / off
    layers (``CadDrawing.hidden_texts``): their room names and codes name only areas that no visible text
    names (a sheet often freezes one wing's annotation layer; the names are still the building's), they
    never split an area nor compete with a visible name. ``classified``: ``classify_labels(texts, rules)``
    when the caller has it (a drawing's texts are classified once). ``partitions``: folding partitions,
    counters standing wall to wall and partition walls on layers no rule names (``CadDrawing.partitions``:
    lines, metres; ``cad_classify`` ``folding_partitions`` / ``counter_partitions`` /
    ``stray_wall_partitions``): an area whose names lie on both sides of one is split along it first
    (``_split_at_partition``; no passage across a wall when both rooms keep a door). ``door_hints``: the import's doorways (``CadDrawing.doors``): a named
    part of an area behind a door as wide as itself is split off at the door (``_split_at_doors``). Never
    raises on odd texts."""
    progress = ensure(progress)
    rules = _resolve(rules)
    report = NamesReport()
    level = str(level).strip() or "1"
    progress.step(0, "classifying texts")
    labs = classify_labels(list(texts or []), rules) if classified is None else classified
    records = [TextRecord(list(l.ids), l.text, l.x, l.y, l.layer, l.role, l.reason, alts=list(l.alts)) for l in labs]
    report.texts = records
    areas_ok = [a for a in areas if a.polygon is not None and not a.polygon.is_empty and a.polygon.area > 0
                and a.type != "structure"]
    progress.step(15, "scoring texts against areas")
    best_by_area: Dict[int, List[TextRecord]] = {}
    if areas_ok:
        index = (areas_ok, [a.polygon for a in areas_ok])
        index = index + (STRtree(index[1]), [p.centroid for p in index[1]])
        room = [r for r in records if r.role in ("name", "number")]
        _place_records(room, index, best_by_area, rules, rho_max, d_max, inside_first, progress)
    progress.step(50, "naming areas")
    _demote_shafts_and_outdoor(best_by_area, records, rules)
    by_id = {a.id: a for a in areas}
    _demote_shafts_in_anchors(best_by_area, by_id, rules)
    if split and door_hints:  # a named closet as wide as its door: split off at the door first
        _split_at_doors(areas, by_id, best_by_area, door_hints, passages, labels, grid, report, progress, rules)
    # ---- split areas holding several different names
    if split:
        # a piece still holding two names is split again (a hall with a lift lobby at one end and a round
        # room opening onto it: the corridor comes off at a doorway, the round room at its wide opening)
        queue = sorted(best_by_area)
        rounds: Dict[int, int] = {}
        while queue:
            aid = queue.pop(0)
            recs = best_by_area.get(aid, [])
            names = {_key(r.text): r for r in reversed(_competing(recs))}
            if len(names) < 2 or rounds.get(aid, 0) >= MAX_SPLIT_ROUNDS:
                continue
            rounds[aid] = rounds.get(aid, 0) + 1
            a = by_id[aid]
            if a.type in ("stairs", "elevator"):
                continue
            try:
                pieces = _split_at_partition(a, recs, names, partitions, areas, passages, labels, grid)
                pieces = pieces or _split_area(a, recs, names, grid, areas, passages, labels)
            except Exception as exc:  # an invalid polygon must not stop the naming: keep it whole
                progress.warning(f"area {aid}: could not be split between its room names "
                                 f"({type(exc).__name__}: {exc}); kept whole")
                pieces = None
            if pieces:
                report.splits.append((aid, [p.id for p in pieces]))
                for p in pieces:
                    by_id[p.id] = p
                best_by_area.pop(aid)
                for p in pieces:
                    best_by_area[p.id] = [r for r in recs if r.area_id == p.id]
                _corridor_points_in_pieces(pieces, best_by_area, passages, rules, progress)
                report.new_passages.extend(pieces[0].tags.pop("_new_passages", []))
                progress.info(f"area {aid} held {len(names)} room names ({', '.join(r.text for r in names.values())}); "
                              f"split along the narrowing between them into areas {[p.id for p in pieces]}")
                for p in pieces:
                    rounds.setdefault(p.id, rounds[aid])
                    if len({_key(r.text) for r in _competing(best_by_area[p.id])}) >= 2:
                        queue.append(p.id)
    _demote_zones(best_by_area, rules, progress)
    _demote_service_points(best_by_area, by_id, passages, rules, progress)
    # ---- texts of frozen / off layers: names for areas that no visible text names
    if hidden_texts:
        hl = [l for l in classify_labels(list(hidden_texts), rules) if l.role in ("name", "number")]
        report.hidden = [TextRecord(l.ids, l.text, l.x, l.y, l.layer, l.role, l.reason, hidden=True, alts=list(l.alts))
                       for l in hl]
        # scored against every area (a hidden text inside a named room must not drift to its neighbour),
        # kept only where the best area has no visible name or number
        cand = [a for a in areas if a.polygon is not None and not a.polygon.is_empty and a.polygon.area > 0
                and a.type != "structure"]
        taken_before = {aid for aid, recs in best_by_area.items() if recs}
        if report.hidden:
            polys = [a.polygon for a in cand]
            no_code = {aid for aid, recs in best_by_area.items() if not any(_vertical_code(r, rules) for r in recs)}
            _place_records(report.hidden, (cand, polys, STRtree(polys), [p.centroid for p in polys]), best_by_area,
                           rules, rho_max, d_max, inside_first, None, only=lambda aid: aid not in taken_before,
                           only_vertical=lambda aid: aid not in taken_before or aid in no_code)
    _demote_thing_labels(best_by_area)
    # ---- names, refs, label fields
    for a in areas:
        if a.type == "structure":
            continue
        recs = best_by_area.get(a.id, [])
        for k in LABEL_FIELDS:
            a.tags.pop(k, None)
        names = sorted([r for r in recs if r.role == "name"], key=lambda r: (not _strong(r), -r.score, r.ids[0]))
        vertical = a.type in ("stairs", "elevator")
        nums = sorted([r for r in recs if r.role == "number"],
                      key=lambda r: (not (vertical and _vertical_code(r, rules)), r.hidden, -r.score, r.ids[0]))
        distinct = _competing(recs)
        a.name = a.name if (a.name and not recs and not _looks_auto(a.name)) else ""
        a.ref = ""
        if distinct:
            a.name = _spelling(distinct[0], recs, level)
        if nums:
            a.ref = nums[0].text
            if not a.name:
                a.name = nums[0].text
        if recs:
            a.tags["label_score"] = f"{max(r.score for r in recs):.1f}"
            a.tags["label_texts"] = ";".join(dict.fromkeys(str(i) for r in names + nums for i in r.ids))
        if len(distinct) > 1:
            a.tags["label_conflict"] = " | ".join(d.text for d in distinct[1:])
            report.conflicts.append(a.id)
            progress.warning(f"area {a.id} holds {len(distinct)} room names ({', '.join(d.text for d in distinct)}) "
                             "and no narrowing separates them: named after the best-placed one, the others kept in "
                             "label_conflict (split the area by hand, or check the walls around it)")
        if distinct:
            report.base_names[a.id] = a.name
            report.name_record[a.id] = distinct[0]
        elif nums:
            report.base_names[a.id] = a.name
            report.name_record[a.id] = nums[0]
        if a.name:
            report.named += bool(distinct)
            report.numbered += bool(a.ref)
    # ---- duplicate names on the floor: suffix, never merge
    groups: Dict[str, List[Area]] = {}
    for a in areas:
        if a.type != "structure" and a.name:
            groups.setdefault(_key(a.name), []).append(a)
    taken = {_key(a.name) for a in areas if a.name}
    for key, grp in sorted(groups.items()):
        if len(grp) < 2:
            continue
        grp.sort(key=lambda a: a.id)
        report.duplicates[grp[0].name] = [a.id for a in grp]
        base = grp[0].name
        n = 0
        for a in grp:
            if a.ref and _key(a.ref) not in _key(a.name) and _key(f"{a.name} {a.ref}") not in taken:
                a.name = f"{a.name} {a.ref}"
            else:
                while True:
                    n += 1
                    cand = f"{base} ({n})"
                    if _key(cand) not in taken:
                        break
                a.name = cand
            taken.add(_key(a.name))
    # ---- generated ids for the rest
    for a in areas:
        if a.type == "structure" or a.name:
            continue
        cand = auto_id(level, a.id)
        k = 1
        while _key(cand) in taken:
            k += 1
            cand = f"{auto_id(level, a.id)}-{k}"
        a.name = cand
        taken.add(_key(cand))
        report.auto += 1
    progress.step(85, "typing areas")
    _type_areas(areas, best_by_area, passages, rules, report)
    progress.step(100, report.summary())
    return report


def _vertical_code(r: "TextRecord", rules) -> Optional[str]:
    """'stairs' / 'elevator' when the text is a stair or lift code (E1-ST-03, E2-P1/P2, a detail callout
    naming one), else None. Keyword names ('Stair A', '楼梯间') are not codes: they label the space they
    are written in."""
    if r.role != "number":
        return None
    t = (type_of_name("", r.text, rules) or {}).get("type")
    return t if t in ("stairs", "elevator") else None


def _max_area(rules, vtype: str) -> float:
    return float((rules.vertical_max_area or {}).get(vtype, 80.0))


def _place_records(room: Sequence["TextRecord"], index, best_by_area: Dict[int, List["TextRecord"]], rules,
                   rho_max: float, d_max: float, inside_first: bool, progress=None, only=None,
                   only_vertical=None) -> None:
    """Give each room text to its best-scoring area (paper score; inside first). ``only``: a predicate on
    area ids an area must pass to take a text. Stair and lift codes (``_vertical_code``) that are detail
    callouts, or whose best area is larger than a stair core / lift shaft can be (an atrium with an open
    stair), go to ``_place_vertical`` instead (``only_vertical``: its extra eligibility predicate)."""
    areas_ok, polys, tree, cents = index
    deferred = []
    placed_copies = []
    for n, r in enumerate(room):
        if progress is not None and n % 200 == 0:
            progress.step(15 + 35 * n / max(1, len(room)))
        if not (math.isfinite(r.x) and math.isfinite(r.y)):
            continue
        vtype = _vertical_code(r, rules)
        if vtype and r.reason == "callout":
            deferred.append((r, vtype))
            continue
        # a label drawn twice (``_merge_copies``) is where its best-placed copy is
        best, best_xy = (0.0, None, ""), (r.x, r.y)
        copies = []
        for xy in [(r.x, r.y)] + [q for q in r.alts if math.isfinite(q[0]) and math.isfinite(q[1])]:
            cand = _best_area(xy[0], xy[1], polys, tree, cents, rho_max, d_max, inside_first)
            copies.append((cand, xy))
            if cand[0] > best[0]:
                best, best_xy = cand, xy
        if len(copies) > 1:
            placed_copies.append((r, copies))
        r.x, r.y = best_xy
        if best[0] > 1000.0:
            best = (best[0] - 1000.0, best[1], best[2])
        elif best[0] > 500.0 and inside_first:
            best = (best[0] - 500.0, best[1], best[2])
        if vtype and (best[1] is None or polys[best[1]].area > _max_area(rules, vtype)
                      or areas_ok[best[1]].type == "corridor"
                      or (only is not None and not only(areas_ok[best[1]].id))):
            deferred.append((r, vtype))
            continue
        if best[1] is not None and (only is None or only(areas_ok[best[1]].id)):
            a = areas_ok[best[1]]
            r.area_id, r.score, r.match = a.id, round(best[0], 2), best[2]
            best_by_area.setdefault(a.id, []).append(r)
    _settle_copies(placed_copies, areas_ok, best_by_area, inside_first, only)
    if deferred:
        _place_vertical(deferred, index, best_by_area, rules, rho_max, d_max, only_vertical or only)


def _settle_copies(placed_copies, areas_ok, best_by_area, inside_first: bool, only=None) -> None:
    """A name drawn twice whose best-placed copy landed in an area another name labels, while another
    copy lies in (or beside) an area no name labels, names that area: the copies of SIST-F4's '女卫生间'
    are 1 m apart, one in the corridor-side area of the next room, one in the WC itself."""
    for r, copies in placed_copies:
        if r.role != "name" or r.area_id is None:
            continue
        cur = r.area_id
        if not any(o is not r and o.role == "name" and _key(o.text) != _key(r.text) for o in best_by_area.get(cur, [])):
            continue
        for (sc, i, how), xy in sorted(copies, key=lambda c: -c[0][0]):
            if i is None or areas_ok[i].id == cur or (only is not None and not only(areas_ok[i].id)):
                continue
            if any(o.role == "name" for o in best_by_area.get(areas_ok[i].id, [])):
                continue
            best_by_area[cur].remove(r)
            if sc > 1000.0:
                sc -= 1000.0
            elif sc > 500.0 and inside_first:
                sc -= 500.0
            r.area_id, r.score, r.match = areas_ok[i].id, round(sc, 2), how
            r.x, r.y = xy
            best_by_area.setdefault(r.area_id, []).append(r)
            break


def _best_area(x, y, polys, tree, cents, rho_max, d_max, inside_first):
    """(score with the inside bonus, index, how) of the best area for the point (x, y)."""
    p = Point(x, y)
    best = (0.0, None, "")
    for i in sorted(tree.query(p, predicate="dwithin", distance=d_max).tolist()):
        try:
            s, how = score(x, y, polys[i], cents[i], rho_max=rho_max, d_max=d_max)
        except Exception:  # GEOS on an invalid polygon: this area is no candidate
            continue
        if how != "inside" and _on_island(polys[i], p):
            # written on a pillar or a piece of furniture standing free in the room (a small hole of
            # the area): inside the room, ranked after an area that holds the point itself
            s, how = _island_score(x, y, polys[i], cents[i], rho_max), "inside"
            if inside_first:
                s += 500.0
        elif inside_first and how == "inside":
            s += 1000.0  # a text inside an area is that area's (nearby scores only for texts outside)
        if s > best[0]:
            best = (s, i, how)
    return best


ISLAND_MAX_M2 = 4.0  # the largest hole of an area a label may sit on and still be in the area (a pillar, a desk)


def _on_island(poly, p: Point) -> bool:
    """p lies in a small hole of ``poly`` (at most ISLAND_MAX_M2): on an obstacle standing free inside it."""
    if poly.geom_type != "Polygon" or not poly.interiors:
        return False
    from shapely.geometry import Polygon

    for ring in poly.interiors:
        h = Polygon(ring)
        if h.area <= ISLAND_MAX_M2 and h.covers(p):
            return True
    return False


def _island_score(px, py, poly, cent, rho_max) -> float:
    S = math.sqrt(float(poly.area) / math.pi)
    rho = math.hypot(px - cent.x, py - cent.y) / max(S, 1e-9)
    s = 100.0 - 50.0 * rho if rho <= rho_max else 50.0 - 25.0 * (rho - rho_max)
    return max(s, 1.0)


def _matches(words: Sequence[str], text: str) -> bool:
    """A keyword occurs in ``text``; a keyword written '=水' must be the whole text (a one-character shaft
    label '水' beside the shaft, while '水泵房' is a pump room)."""
    low = normalize_text(text).casefold()
    return any((low == w[1:].strip()) if w.startswith("=") else bool(_keyword_regex(w).search(low)) for w in words)


def _demote_shafts_and_outdoor(best_by_area: Dict[int, List[TextRecord]], records: Sequence[TextRecord],
                               rules: NameRules) -> None:
    """Two kinds of name that name no space of the indoor map where they are written:

    * an MEP shaft label (水井, 风井, 加压, shaft, cavedio) written outside every area, or in (beside) an
      area that another, non-shaft name labels from inside: the shaft is a closed cavity of the wall,
      too small to hold its label (library sheets write '加压' in the hall beside the pressurisation
      shafts, SIST-F1 '水井' in the laboratory beside its shaft) -> ignored, 'shaft label';
    * an outdoor label (室外庭院, 排水暗沟, lawn) outside every area -> ignored, 'outdoor'.

    A shaft segmentation made an area of, holding its own label, keeps it as its name."""
    shaft = rules.shaft_keywords
    outdoor = rules.outdoor_keywords
    if not shaft and not outdoor:
        return
    for r in records:
        if r.role != "name" or r.hidden:
            continue
        if shaft and _matches(shaft, r.text):
            if r.area_id is None:
                r.role, r.reason = "ignored", "shaft label"
                continue
            others = [o for o in best_by_area.get(r.area_id, []) if o is not r and o.role == "name"
                      and o.match == "inside" and not _matches(shaft, o.text)]
            if others:
                r.role, r.reason = "ignored", "shaft label"
        elif outdoor and r.match != "inside" and _matches(outdoor, r.text):
            r.role, r.reason = "ignored", "outdoor"


def _demote_shafts_in_anchors(best_by_area: Dict[int, List[TextRecord]], by_id: Dict[int, Area],
                              rules: NameRules) -> None:
    """An MEP shaft label (暖, 水井, duct) inside an area typed stairs / elevator from its symbols labels the
    duct in the core's wall, not the stair or lift: ignored ('shaft label'), so the stair or lift keeps the
    name its code gives (SIST-F4: the E1-ST-01 core was named '暖')."""
    if not rules.shaft_keywords:
        return
    for aid, recs in best_by_area.items():
        a = by_id.get(aid)
        if a is None or a.type not in ("stairs", "elevator"):
            continue
        for r in recs:
            if r.role == "name" and _matches(rules.shaft_keywords, r.text):
                r.role, r.reason = "ignored", "shaft label"


def _demote_zones(best_by_area: Dict[int, List[TextRecord]], rules: NameRules, progress) -> None:
    """A zone of an open space ('阅览区(随意开放性坐区)', a reading zone with free seating in the atrium
    gallery of library sheet A-A3-10-04; 'open space', 'zona relax') that shares its area with another
    room name, and that no narrowing split off, is a part of that space, not a second room: it is
    reported as ignored ('zone in a named space'), and the space keeps its name without a conflict."""
    if not rules.zone_keywords:
        return
    for aid, recs in best_by_area.items():
        comp = _competing(recs)
        if len(comp) < 2:
            continue
        zones = [r for r in comp if _matches(rules.zone_keywords, r.text)]
        if not zones or len(zones) == len(comp):
            continue
        keys = {_key(r.text) for r in zones}
        for r in recs:
            if r.role == "name" and _key(r.text) in keys:
                r.role, r.reason = "ignored", "zone in a named space"
        progress.info(f"area {aid}: {', '.join(sorted(keys))} is a zone of the space, not a room of its own")


SERVICE_POINTS = True  # switch of _demote_service_points (tests turn it off to show what it does)
POINT_SCORE = 50.0  # an inside score below this: the label lies beyond rho_max, off the area's centre


def _demote_service_points(best_by_area: Dict[int, List[TextRecord]], by_id: Dict[int, Area], passages,
                           rules: NameRules, progress) -> None:
    """A small service room's label (``point_keywords``: 开水间 water point, 清洁间, 弱电 / 强电 closets)
    written off the centre (inside score < POINT_SCORE: beyond rho_max, at an end or a side niche) of an area
    that is corridor-shaped (``_corridor_shaped``: long, narrow, at least ``min_degree`` passages) and larger
    than ``point_max_area`` marks a point along a corridor (a water boiler, a cleaners' sink, a closet drawn
    open onto it), not the corridor's name: SIST-F1's 60 m corridor with 24 doors was '开水间 (2)' after a
    label at its far end. Such labels are ignored ('point in a corridor'); the corridor keeps an auto id and
    is typed corridor by its shape. A label near the centre of such an area still names it (a long 开水间
    room), as does any other name (a fire lobby 前室 is long, narrow and busy too, and it is a room)."""
    if not SERVICE_POINTS or not rules.point_keywords:
        return
    geo = _corridor_geometry(rules)
    degree = _passage_degrees(passages)
    for aid, recs in best_by_area.items():
        a = by_id.get(aid)
        if a is None or a.polygon is None or a.type in ("stairs", "elevator", "structure"):
            continue
        pts = [r for r in recs if r.role == "name" and r.match == "inside" and r.score < POINT_SCORE
               and _matches(rules.point_keywords, r.text)]
        if not pts or a.polygon.area <= rules.point_max_area:
            continue
        if not _corridor_shaped(a, degree.get(aid, 0), geo):
            continue
        for r in pts:
            r.role, r.reason = "ignored", "point in a corridor"
        progress.info(f"area {aid} ({a.polygon.area:.0f} m², corridor-shaped, {degree.get(aid, 0)} passages): "
                      f"{', '.join(sorted({r.text for r in pts}))} marks a point along it, not its name")


def _place_vertical(deferred, index, best_by_area, rules, rho_max, d_max, allow=None) -> None:
    """Stair and lift codes written beside their stair or lift (a callout on a leader, a code next to an
    open stair): each names the nearest small closed area within CALLOUT_REACH that is a stair (lift)
    area (typed from its symbols, or named so by a visible keyword), else an unnamed room of at most half
    that size within D_MAX; never a corridor nor an area of the other kind, never an area larger than
    ``vertical_max_area``. Greedy by distance, one code per area (the same code twice is one).
    The corridor or atrium the code lies in is never typed by it."""
    areas_ok, polys, tree, cents = index
    eff: Dict[int, str] = {}

    def effective_type(a: Area) -> str:
        """The area's type as its visible name says it ('客梯' is a lift even before typing; '中庭' is
        no lift, whatever lift lines cross it), else its type from symbols."""
        if a.id not in eff:
            names = [r for r in best_by_area.get(a.id, []) if r.role == "name"]
            t = a.type
            if names:
                e = type_of_name(max(names, key=lambda r: r.score).text, "", rules)
                if e is not None:
                    t = e["type"] if e["type"] in ("stairs", "elevator") else "room:named"
            eff[a.id] = t
        return eff[a.id]

    pairs = []
    for k, (r, vtype) in enumerate(deferred):
        p = Point(r.x, r.y)
        for i in tree.query(p, predicate="dwithin", distance=CALLOUT_REACH).tolist():
            a = areas_ok[i]
            if polys[i].area > _max_area(rules, vtype):
                continue
            d = float(polys[i].distance(p))
            if effective_type(a) == vtype:
                rank = 0
            elif a.type == "room" and not best_by_area.get(a.id) and d <= d_max and \
                    polys[i].area <= 0.5 * _max_area(rules, vtype):
                rank = 1  # an unnamed small room right beside the code (nearby, as the paper's D_max)
            else:
                continue
            if allow is not None and not allow(a.id):
                continue
            pairs.append((rank, d, k, i))
    pairs.sort()
    done = set()
    code_of: Dict[int, str] = {}
    for aid, recs in best_by_area.items():
        for r in recs:
            if _vertical_code(r, rules):
                code_of.setdefault(aid, _key(r.text))
    for rank, dist, k, i in pairs:
        r, vtype = deferred[k]
        a = areas_ok[i]
        if k in done or code_of.get(a.id, _key(r.text)) != _key(r.text):
            continue
        done.add(k)
        code_of[a.id] = _key(r.text)
        r.area_id, r.match = a.id, "callout"
        r.score = round(score(r.x, r.y, polys[i], cents[i], rho_max=rho_max, d_max=d_max)[0], 2)
        best_by_area.setdefault(a.id, []).append(r)


def _demote_thing_labels(best_by_area: Dict[int, List[TextRecord]]) -> None:
    """A short keyword-less text ('copy', 'coffee', 'cassa') in an area named by a real room name (a
    keyword, a room-name layer or tag) labels a thing in that room, unless the same text is the name of an
    area of its own somewhere on the floor ('exposition' naming three halls is a room name, and one
    inside the hall means hall and exposition space were not separated). Things are reported as ignored
    ('label in a named room'), not as room names that lost their area."""
    top: Dict[int, TextRecord] = {}
    for aid, recs in best_by_area.items():
        comp = _competing(recs)
        if comp:
            top[aid] = comp[0]
    naming = {_key(r.text) for r in top.values()}
    for aid, recs in best_by_area.items():
        t = top.get(aid)
        if t is None or not _strong(t):
            continue
        for r in recs:
            if r.role == "name" and not r.hidden and not _strong(r) and _key(r.text) not in naming:
                r.role, r.reason = "ignored", "label in a named room"


def _strong(r: TextRecord) -> bool:
    """A name backed by more than its shortness: a room-name layer, block or tag, or a room keyword."""
    return r.reason not in ("short text", "text layer")


def _competing(recs: Sequence[TextRecord]) -> List[TextRecord]:
    """The distinct room names of an area that compete for it, best first: the strong names when there
    is one (a keyword-less short text beside 'Office' labels a thing in it, e.g. 'copy', 'coffee'),
    else the short texts. A name written inside the area beats every name written outside it (nearby):
    a label just outside a room belongs to a space segmentation did not make (a corridor eaten by the
    envelope), it neither renames the room nor conflicts with the room's own label."""
    names = [r for r in recs if r.role == "name"]
    names = [r for r in names if r.match != "nearby"] or names
    names.sort(key=lambda r: (not _strong(r), -r.score, r.ids[0]))
    strong = [r for r in names if _strong(r)]
    pool = strong or names
    out: List[TextRecord] = []
    for r in pool:
        if all(_key(r.text) != _key(d.text) for d in out):
            out.append(r)
    return out


def _looks_auto(name: str) -> bool:
    return bool(re.fullmatch(r"-?\w{1,6}-\d+(-\d+)?|L-?\w+-[ASP]\d+", name or ""))


def _corridor_geometry(rules: NameRules) -> dict:
    """The corridor shape test's parameters: the rules' ``corridor_geometry`` over the defaults."""
    return dict({"min_elongation": 3.0, "max_width": 4.0, "min_degree": 3}, **rules.corridor_geometry)


def _passage_degrees(passages) -> Dict[int, int]:
    """{area id: the number of passage ends on it}."""
    degree: Dict[int, int] = {}
    for ps in passages or ():
        degree[ps.from_id] = degree.get(ps.from_id, 0) + 1
        degree[ps.to_id] = degree.get(ps.to_id, 0) + 1
    return degree


def _type_areas(areas, best_by_area, passages, rules: NameRules, report: NamesReport) -> None:
    degree = _passage_degrees(passages)
    geo = _corridor_geometry(rules)
    for a in areas:
        if a.type == "structure":
            continue
        for k in ("indoor", "room", "ref", "name"):
            a.tags.pop(k, None)
        named = any(r.role in ("name", "number") for r in best_by_area.get(a.id, ()))  # not only ignored labels
        entry = type_of_name(a.name, a.ref, rules) if named else None
        if entry is not None and entry["type"] in ("stairs", "elevator") and \
                a.polygon.area > _max_area(rules, entry["type"]) and a.type not in ("stairs", "elevator"):
            # far larger than a stair core or lift shaft (an atrium with an open stair, a hall with lifts):
            # the name does not make it a stair or a lift
            entry = _type_entry(normalize_text(a.name).casefold(), rules)
            entry = entry[1] if entry and entry[1]["type"] not in ("stairs", "elevator") else None
        rec = report.name_record.get(a.id)
        # the text beats the symbol density of area_types when it says stairs/lift, or when it is the
        # area's own label (inside, near the centre): a lobby is not a lift because lift lines cross it
        own_label = rec is not None and rec.match == "inside" and rec.score >= 65.0
        if entry is not None and (a.type not in ("stairs", "elevator") or entry["type"] in ("stairs", "elevator")
                                  or own_label):
            if entry["type"] != a.type:
                report.typed[entry["type"]] = report.typed.get(entry["type"], 0) + 1
            a.type = entry["type"]
        elif entry is None and not named and a.type == "room" and _corridor_shaped(a, degree.get(a.id, 0), geo):
            a.type = "corridor"
            report.typed["corridor (geometry)"] = report.typed.get("corridor (geometry)", 0) + 1
        # Simple Indoor Tagging
        if a.type == "corridor":
            indoor, room = "corridor", ""
        elif a.type == "stairs":
            indoor, room = "room", "stairs"
        elif a.type == "elevator":
            indoor, room = "room", "elevator"
        else:
            indoor = (entry or {}).get("indoor") or "room"
            room = (entry or {}).get("room") or ""
            if indoor == "corridor":
                indoor = "area"
        a.tags["indoor"] = indoor
        if room:
            a.tags["room"] = room
        if a.ref:
            a.tags["ref"] = a.ref


def _corridor_shaped(a: Area, degree: int, geo: Dict[str, float]) -> bool:
    if degree < geo["min_degree"]:
        return False
    rect = a.polygon.minimum_rotated_rectangle
    xy = np.asarray(rect.exterior.coords)
    if len(xy) < 4:
        return False
    e = np.hypot(*np.diff(xy[:3], axis=0).T)
    length, width = max(e), min(e)
    # the width that matters is the free width: area / length is robust to side niches
    free_w = a.polygon.area / max(length, 1e-9)
    return width > 0 and length / max(free_w, 1e-9) >= geo["min_elongation"] and free_w <= geo["max_width"]


def osm_tags(area: Area) -> Dict[str, str]:
    """The area's tags for the osmAG file: the label fields left out, a conflict as ``fixme``."""
    tags = {k: v for k, v in (area.tags or {}).items() if k not in LABEL_FIELDS and not k.startswith("_")}
    conflict = (area.tags or {}).get("label_conflict")
    if conflict:
        tags["fixme"] = f"several room names in one area: {area.name} | {conflict}"
    return tags


def for_osm(areas: Sequence[Area]) -> List[Area]:
    """Copies of the areas with ``osm_tags`` (for writing osmAG without the layer-only fields)."""
    from dataclasses import replace

    return [replace(a, tags=osm_tags(a)) for a in areas]


# ------------------------------------------------------------------------------------------ split
def _split_area(a: Area, recs: List[TextRecord], names: Dict[str, TextRecord], grid, areas: List[Area],
                passages: Optional[List[Passage]], labels) -> Optional[List[Area]]:
    """Split area ``a`` between its different room names at the narrowings of its clearance map.

    The clearance (distance to the area's border) is thresholded at growing half-widths t (0.2 m up to
    half the widest door, 1.4 m): the first t at which two names fall into different cores is where
    the narrowings are. Every core bigger than 2 m² (named or not: a corridor joining the rooms becomes
    its own area) seeds a watershed of the clearance inside the area; a split is kept only when the
    opening (2 t, or twice the clearance on the cut) is at most NARROWING_RATIO of the width of every piece
    (NARROWING_RATIO_DOOR for a door-wide opening: ``_narrow_enough``). Returns the pieces (``a``
    first, changed in place, the others appended to ``areas``) or None (no narrowing: a conflict)."""
    from scipy import ndimage
    import cv2

    from .model import OccupancyGrid
    from .segmentation import label_polygons

    poly = a.polygon
    if poly.geom_type != "Polygon":
        return None
    res = float(grid.resolution) if grid is not None else 0.05
    x0, y0, x1, y1 = poly.bounds
    while (x1 - x0) * (y1 - y0) / (res * res) > 6e6:
        res *= 1.5
    pad = 3
    cols = int(math.ceil((x1 - x0) / res)) + 2 * pad
    rows = int(math.ceil((y1 - y0) / res)) + 2 * pad
    ox, oy = x0 - pad * res, y1 + pad * res

    def to_px(xy):
        xy = np.asarray(xy, float)
        return np.column_stack(((xy[:, 0] - ox) / res, (oy - xy[:, 1]) / res))

    mask = np.zeros((rows, cols), np.uint8)
    cv2.fillPoly(mask, [np.round(to_px(poly.exterior.coords) * 8).astype(np.int32)], 1, shift=3)
    for hole in poly.interiors:
        cv2.fillPoly(mask, [np.round(to_px(hole.coords) * 8).astype(np.int32)], 0, shift=3)
    inside = mask.astype(bool)
    if inside.sum() < 20:
        return None
    clearance = ndimage.distance_transform_edt(inside) * res
    keys = list(names)
    seeds: Dict[str, List[Tuple[int, int]]] = {k: [] for k in keys}
    rr, cc = np.nonzero(inside)
    for r in recs:
        k = _key(r.text)
        if r.role != "name" or k not in seeds:
            continue
        c, rw = to_px([(r.x, r.y)])[0]
        ci, ri = int(c), int(rw)
        if not (0 <= ri < rows and 0 <= ci < cols and inside[ri, ci]):
            j = int(np.argmin((rr - rw) ** 2 + (cc - c) ** 2))
            ri, ci = int(rr[j]), int(cc[j])
        seeds[k].append((ri, ci))
    min_core_px = 2.0 / (res * res)
    found = None
    for t in SPLIT_THRESHOLDS:
        core = clearance > t
        comp, n = ndimage.label(core)
        if n < 2:
            continue
        # a seed outside the core belongs to the core nearest to it
        cr = cc_ = None
        owner = {}
        for k in keys:
            cs = set()
            for (pr, pc) in seeds[k]:
                if core[pr, pc]:
                    cs.add(int(comp[pr, pc]))
                    continue
                if cr is None:
                    cr, cc_ = np.nonzero(core)
                if not len(cr):
                    break
                j = int(np.argmin((cr - pr) ** 2 + (cc_ - pc) ** 2))
                cs.add(int(comp[cr[j], cc_[j]]))
            if cs:
                owner[k] = min(cs)
        if len(set(owner.values())) < 2:
            continue
        if t <= DOOR_HALF_WIDTH:
            # doorway-wide narrowings: every core is a space (a corridor joining two rooms is its own area)
            sizes = ndimage.sum(np.ones_like(comp), comp, index=np.arange(1, n + 1))
            keep = {i + 1 for i, sz in enumerate(sizes) if sz >= min_core_px} | set(owner.values())
        else:
            # wider openings (an arch, the open front of a round room onto a hall): only the named cores
            # seed, so that the hall is not cut into the pieces its columns and bays make at this scale
            keep = set(owner.values())
        markers = np.where(np.isin(comp, list(keep)), comp, 0).astype(np.int32)
        # every pixel goes to the core nearest along the floor (a watershed of the clearance leaked: its
        # ties let a corridor's flood run through the door along every wall of the hall behind it)
        reg = _geodesic_regions(markers, inside)
        reg[~inside] = 0
        present = [k for k in sorted(keep) if (reg == k).any()]
        if len(present) < 2:
            continue
        # the opening must be clearly narrower than every piece; if not, a wider threshold may still
        # find the narrowing between the names (the first separation can be a bay of one room)
        if not _narrow_enough(t, reg, present, clearance, inside):
            continue
        found = (t, reg, present, owner)
        break
    if found is None:
        return None
    t, reg, present, owner = found
    # cells tiling the window: every pixel takes the region of the nearest area pixel
    ir, ic = ndimage.distance_transform_edt(reg == 0, return_distances=False, return_indices=True)
    cells = reg[ir, ic].astype(np.int32)
    cell_polys = label_polygons(cells, OccupancyGrid(cells, ox, oy, res))
    pieces = []
    for k in present:
        cp = cell_polys.get(k)
        if cp is None:
            return None
        g = poly.intersection(cp)
        if g.is_empty:
            continue
        if g.geom_type != "Polygon":
            parts = [p for p in getattr(g, "geoms", []) if p.geom_type == "Polygon" and p.area > 0]
            if not parts:
                continue
            g = max(parts, key=lambda p: p.area)
        pieces.append((g, {kk for kk, o in owner.items() if o == k}))
    if len(pieces) < 2 or sum(1 for _, ks in pieces if ks) < 2:
        return None
    # what the intersections left over (slivers) joins the piece it touches most
    from shapely.ops import unary_union

    rest = poly.difference(unary_union([g for g, _ in pieces]))
    for frag in getattr(rest, "geoms", [rest]):
        if frag.is_empty or frag.area <= 0:
            continue
        j = max(range(len(pieces)), key=lambda i: pieces[i][0].buffer(1e-6).intersection(frag).area)
        merged = unary_union([pieces[j][0], frag])
        if merged.geom_type == "Polygon":
            pieces[j] = (merged, pieces[j][1])
    pieces = _straighten(pieces, res)
    return _finish(a, pieces, areas, passages, labels, grid, recs, t)


def _split_at_partition(a: Area, recs: List[TextRecord], names: Dict[str, TextRecord], partitions, areas: List[Area],
                        passages: Optional[List[Passage]], labels, grid) -> Optional[List[Area]]:
    """Split area ``a`` along a folding partition (``cad_classify.folding_partitions``: a wall that opens,
    drawn folded at both ends of its track) or a counter standing wall to wall (``counter_partitions``: the
    service space behind a bar or reception counter) that has its room names on both sides: the track, extended to
    the area's outline, cuts the area in two, each piece holding names; the pieces get a passage along it
    (``_finish``). Returns the pieces or None (no partition crosses the area between its names)."""
    poly = a.polygon
    if not partitions or poly is None or poly.geom_type != "Polygon":
        return None
    named = [r for r in recs if r.role == "name" and _key(r.text) in names]
    x0, y0, x1, y1 = poly.bounds
    reach = math.hypot(x1 - x0, y1 - y0)
    for g in partitions:
        c = np.asarray(getattr(g, "coords", g), dtype=float)
        if len(c) < 2:
            continue
        p, q = c[0], c[-1]
        u = q - p
        ln = float(np.hypot(*u))
        if ln <= 0:
            continue
        u = u / ln
        mid = Point(*((p + q) / 2.0))
        if not poly.contains(mid):
            continue
        # the track, extended both ways to the outline: the piece of it through the span's middle
        try:
            halves = _chord_halves(poly, p, q, u, mid, reach)
        except Exception:
            continue
        if halves is None or len(halves) != 2:
            continue
        keys = [{_key(r.text) for r in named if h.buffer(1e-6).contains(Point(r.x, r.y))} for h in halves]
        if not keys[0] or not keys[1] or keys[0] & keys[1]:
            continue
        pieces = _finish(a, list(zip(halves, keys)), areas, passages, labels, grid, recs, 0.0)
        if getattr(g, "cls", "") == "wall pair":
            _no_passage_across(pieces, passages)
        return pieces
    return None


def _no_passage_across(pieces: List[Area], passages: Optional[List[Passage]]) -> None:
    """A split along a wall (``cad_classify.stray_wall_partitions``): the passages ``_finish`` made between the
    pieces along it are dropped when every piece keeps a passage of its own (its door); else kept, so that
    no room is orphaned by a wall the raster never had."""
    if passages is None or len(pieces) != 2:
        return
    ids = {b.id for b in pieces}
    new = set(pieces[0].tags.get("_new_passages", []))
    across = [p for p in passages if p.id in new and {p.from_id, p.to_id} == ids]
    if not across:
        return
    for b in pieces:
        if not any(b.id in (p.from_id, p.to_id) for p in passages if p not in across):
            return
    drop = {p.id for p in across}
    passages[:] = [p for p in passages if p.id not in drop]
    pieces[0].tags["_new_passages"] = [i for i in pieces[0].tags.get("_new_passages", []) if i not in drop]


DOOR_SPLIT_WIDTHS = (0.6, 2.4)  # m: door hints of this width (one leaf to a double door) may split an area
DOOR_SPLIT_REACH = 0.3  # m: a hint's jambs lie at most this far from the area's outline (the mouth's sides)
DOOR_SPLIT_MIN_PIECE = 0.8  # m²: each piece of a door split is at least this large


def _split_at_doors(areas: List[Area], by_id: Dict[int, Area], best_by_area: Dict[int, List[TextRecord]],
                    door_hints, passages: Optional[List[Passage]], labels, grid, report: "NamesReport",
                    progress, rules=None) -> None:
    """Split off, along its door line, a named dead-end part of an area that opens through a door as wide as
    itself (a duct, shaft or storage closet 强电间 / 弱电间 / 管井: no narrowing at its mouth, so segmentation
    kept it in the space outside). A door hint (the import's doorways: door blocks, swings, door codes) cuts
    an area in two when its jambs lie on the area's outline (``DOOR_SPLIT_REACH``) and the hint's line, up to
    the outline, splits it into exactly two pieces of at least ``DOOR_SPLIT_MIN_PIECE``; the split is kept
    when one piece holds a room name written inside it and the other holds none of that name (none, or
    another name) and, when the other holds no name, the named piece is the smaller one and no other passage
    of the area ends on it (a dead end). The pieces get a passage at the door (``_finish``); in place."""
    hints = []
    for h in door_hints or ():
        try:
            p, q = np.array((h.x0, h.y0), float), np.array((h.x1, h.y1), float)
        except (TypeError, ValueError, AttributeError):
            continue
        w = float(np.hypot(*(q - p)))
        if np.isfinite(w) and DOOR_SPLIT_WIDTHS[0] <= w <= DOOR_SPLIT_WIDTHS[1]:
            hints.append((p, q, (q - p) / w))
    if not hints:
        return
    mids = [Point(*((p + q) / 2.0)) for p, q, _ in hints]
    tree = STRtree(mids)
    queue = sorted(aid for aid, recs in best_by_area.items() if any(r.role == "name" for r in recs))
    tried = set()
    while queue:
        aid = queue.pop(0)
        a = by_id.get(aid)
        recs = best_by_area.get(aid, [])
        if a is None or a.type in ("stairs", "elevator", "structure") or a.polygon is None \
                or a.polygon.geom_type != "Polygon":
            continue
        for j in sorted(int(k) for k in tree.query(a.polygon)):
            if (aid, j) in tried:
                continue
            tried.add((aid, j))
            try:
                halves = _door_halves(a.polygon, *hints[j], mids[j])
            except Exception:  # an invalid outline must not stop the naming
                halves = None
            if halves is None:
                continue
            keys, moves = _door_keys(recs, halves, hints[j])
            if not (keys[0] or keys[1]) or keys[0] & keys[1]:
                continue
            if not (keys[0] and keys[1]):
                k = 0 if keys[0] else 1
                part, rest = halves[k], halves[1 - k]
                if part.area >= rest.area or _other_passage_on(part, rest, aid, passages, mids[j]):
                    continue
            else:
                k = _corridor_point_side(recs, keys, halves, aid, passages, mids[j], rules)
                if k is not None:  # the corridor's branch behind the door: its label marks a point along it
                    for r in recs:
                        if r.role == "name" and _key(r.text) in keys[k]:
                            r.role, r.reason = "ignored", "point in a corridor"
                    progress.info(f"area {aid}: {', '.join(sorted(keys[k]))} labels a point in the corridor "
                                  "behind a door, not the corridor")
                    keys[k] = set()
            for r, xy in moves:  # a label drawn twice is where its copy inside a piece is (_merge_copies)
                r.alts = [q for q in r.alts if q != xy] + [(r.x, r.y)]
                r.x, r.y = xy
            pieces = _finish(a, list(zip(halves, keys)), areas, passages, labels, grid, recs, 0.0)
            report.splits.append((aid, [b.id for b in pieces]))
            report.new_passages.extend(pieces[0].tags.pop("_new_passages", []))
            best_by_area.pop(aid, None)
            for b in pieces:
                by_id[b.id] = b
                best_by_area[b.id] = [r for r in recs if r.area_id == b.id]
                queue.append(b.id)
            progress.info(f"area {aid}: split at a door drawn across it between its named part and the rest "
                          f"({' | '.join(', '.join(sorted(k)) or '-' for k in keys)}) into areas "
                          f"{[b.id for b in pieces]}")
            break


def _corridor_point_side(recs: Sequence[TextRecord], keys, halves, aid: int, passages, door_mid, rules):
    """Which of the two door-split ``halves`` is a corridor's branch named only by a room label standing in
    it (a water point 开水间, a vending corner or a niche drawn along the corridor), or None. The other half
    holds a corridor name (``type_of_name``), this half no corridor or hall name, and it is corridor-shaped
    (``_corridor_shaped``: long, narrow) with at least the corridor geometry's ``min_degree`` passages of
    the area ending on it besides the door (the doors of the rooms along it): a space people walk through
    to other rooms is the corridor, whatever label a fixture in it carries. Its labels are then ignored
    ('point in a corridor'): the branch is split off at its door unnamed (an auto id, typed corridor by
    its shape), the label no longer renames it."""
    rules = _resolve(rules)
    by_key = {_key(r.text): r for r in recs if r.role == "name"}

    def kind(key):
        e = type_of_name(by_key[key].text, "", rules) if key in by_key else None
        return e["type"] if e else None, (e or {}).get("indoor")

    geo = _corridor_geometry(rules)
    for k in (0, 1):
        mine, other = keys[k], keys[1 - k]
        if not mine or not other or not any(kind(x)[0] == "corridor" for x in other):
            continue
        if any(kind(x)[0] == "corridor" or kind(x)[1] == "area" for x in mine):
            continue
        part, rest = halves[k], halves[1 - k]
        on = 0
        for ps in passages or ():
            if aid not in (ps.from_id, ps.to_id) or ps.line is None:
                continue
            m = ps.line.interpolate(0.5, normalized=True)
            if m.distance(door_mid) >= 0.5 and part.distance(m) < rest.distance(m):
                on += 1
        if on >= geo["min_degree"] and _corridor_shaped(Area(id=-1, polygon=part), on + 1, geo):
            return k
    return None


def _corridor_points_in_pieces(pieces: Sequence[Area], best_by_area: Dict[int, List[TextRecord]], passages,
                               rules, progress) -> None:
    """After a split between room names: a piece named only by room labels (no corridor or hall name) that
    is a corridor's branch -- another piece holds a corridor name and this one is corridor-shaped with at
    least ``min_degree`` passages (``_corridor_point_side``'s rule, on the pieces as split) -- keeps no name
    from them: its labels are ignored ('point in a corridor')."""
    rules = _resolve(rules)
    geo = _corridor_geometry(rules)

    def types(recs):
        out = set()
        for r in _competing(recs):
            e = type_of_name(r.text, "", rules)
            out.add("corridor" if e and e["type"] == "corridor" else "area" if e and e.get("indoor") == "area"
                    else "room")
        return out

    kinds = {b.id: types(best_by_area.get(b.id, [])) for b in pieces}
    if not any("corridor" in k for k in kinds.values()):
        return
    degree = _passage_degrees(passages)
    for b in pieces:
        if kinds[b.id] != {"room"} or degree.get(b.id, 0) < geo["min_degree"] + 1:
            continue
        if not _corridor_shaped(b, degree.get(b.id, 0), geo):
            continue
        names = sorted({r.text for r in _competing(best_by_area[b.id])})
        for r in best_by_area[b.id]:
            if r.role == "name":
                r.role, r.reason = "ignored", "point in a corridor"
        progress.info(f"area {b.id}: {', '.join(names)} labels a point in a corridor's branch, not the corridor")


def _door_keys(recs: Sequence[TextRecord], halves, hint):
    """The room names (keys) written inside each of the two ``halves``, and the labels to move to a copy.
    A label is where any of its copies is (``TextRecord.alts``); a copy written across the door line (within
    DOOR_SPLIT_REACH of it) counts for no side when another copy lies clear of it: the closet's label is
    often written twice, once straddling its door. Returns ([keys0, keys1], [(record, (x, y)) to move])."""
    p, q, _u = hint
    door = LineString([tuple(p), tuple(q)])
    keys: List[set] = [set(), set()]
    moves = []
    by_key: Dict[str, List[TextRecord]] = {}
    for r in recs:  # every label of a name (copies merged or not) counts for the name
        if r.role == "name" and r.match != "nearby":
            by_key.setdefault(_key(r.text), []).append(r)
    competing = {_key(r.text) for r in _competing(recs)}
    for key, group in by_key.items():
        if key not in competing:
            continue
        pts = [(r.x, r.y) for r in group] + [tuple(c) for r in group for c in r.alts
                                              if math.isfinite(c[0]) and math.isfinite(c[1])]
        clear = [c for c in pts if door.distance(Point(*c)) > DOOR_SPLIT_REACH] or pts
        where = {}
        for c in clear:
            for k, h in enumerate(halves):
                if h.buffer(1e-6).contains(Point(*c)):
                    where.setdefault(k, c)
                    break
        for k in where:
            keys[k].add(key)
        if len(where) == 1:
            c = next(iter(where.values()))
            moves += [(r, c) for r in group if (r.x, r.y) not in clear]
    return keys, moves


def _door_halves(poly, p, q, u, mid):
    """The two pieces of ``poly`` cut along the door hint p-q (unit direction u), or None: the hint's middle
    lies inside, the line through it meets the outline within DOOR_SPLIT_REACH of both jambs, and the cut
    leaves exactly two pieces of at least DOOR_SPLIT_MIN_PIECE."""
    if not poly.contains(mid):
        return None

    def at_jambs(c0, c1):
        return np.hypot(*(c0 - p)) <= DOOR_SPLIT_REACH and np.hypot(*(c1 - q)) <= DOOR_SPLIT_REACH

    halves = _chord_halves(poly, p, q, u, mid, DOOR_SPLIT_REACH + 0.05, at_jambs)
    if halves is None or len(halves) != 2 or min(g.area for g in halves) < DOOR_SPLIT_MIN_PIECE:
        return None
    return halves


def _chord_halves(poly, p, q, u, mid, reach: float, accept=None):
    """The pieces of ``poly`` cut along the line p-q (unit direction u), or None. The line, extended ``reach``
    beyond p and q, meets ``poly`` in chords: the one nearest ``mid``, oriented along u (``accept(c0, c1)``,
    when given, may still refuse its ends), extended 1 cm across the outline (not onto it), splits ``poly``.
    Returns the pieces of positive area (any number: the caller wants two). Shared by the folding-partition
    split and the door split."""
    long = LineString([tuple(p - u * reach), tuple(q + u * reach)]).intersection(poly)
    parts = [g for g in getattr(long, "geoms", [long]) if g.geom_type == "LineString" and g.length > 0]
    if not parts:
        return None
    chord = min(parts, key=lambda g: g.distance(mid))
    c0, c1 = np.asarray(chord.coords[0]), np.asarray(chord.coords[-1])
    if float(np.dot(c1 - c0, u)) < 0:
        c0, c1 = c1, c0
    if accept is not None and not accept(c0, c1):
        return None
    cut = LineString([tuple(c0 - u * 0.01), tuple(c1 + u * 0.01)])
    return [g for g in shp_split(poly, cut).geoms if g.area > 0]


def _other_passage_on(part, rest, aid: int, passages, door_mid) -> bool:
    """A passage of area ``aid`` other than the door at ``door_mid`` ends on ``part`` (not on ``rest``)."""
    for ps in passages or ():
        if aid not in (ps.from_id, ps.to_id) or ps.line is None:
            continue
        m = ps.line.interpolate(0.5, normalized=True)
        if m.distance(door_mid) < 0.5:
            continue
        if part.distance(m) < rest.distance(m):
            return True
    return False


DOOR_OPENING = 1.0  # m: an opening no wider than one door leaf is a doorway (NARROWING_RATIO_DOOR)
NARROWING_RATIO_DOOR = 0.8  # a doorway must be at most this share of the width of the pieces it joins


def _narrow_enough(t: float, reg: np.ndarray, present, clearance: np.ndarray, inside: np.ndarray) -> bool:
    """The opening between the pieces ``present`` of ``reg`` is clearly narrower than every piece: its width
    (twice the highest clearance on the pieces' common border, at most 2 t) is at most NARROWING_RATIO of
    the piece's width (twice its largest clearance). An opening no wider than a door (DOOR_OPENING) may take
    up to NARROWING_RATIO_DOOR of it: a WC or washroom 1.2-1.4 m wide is entered through a 0.7-0.9 m door
    (schema-ufficio-1: the 2.9 m² washroom opening onto the bar's back room stayed part of it)."""
    from scipy import ndimage

    for k in present:
        m = reg == k
        width = 2.0 * float(clearance[m].max())
        rim = m & ndimage.binary_dilation((reg != k) & inside)
        opening = 2.0 * min(t, float(clearance[rim].max())) if rim.any() else 2.0 * t
        ratio = NARROWING_RATIO_DOOR if opening <= DOOR_OPENING else NARROWING_RATIO
        if opening > ratio * width:
            return False
    return True


def _geodesic_regions(markers: np.ndarray, inside: np.ndarray, max_iter: int = 5000) -> np.ndarray:
    """Each pixel of ``inside`` takes the label of the marker nearest to it along ``inside`` (growth of
    one pixel per round, ties to the larger label)."""
    import cv2

    if int(markers.max()) >= 65535:
        return markers.copy()
    lab = markers.astype(np.uint16)
    # cross and square steps alternate: an octagonal metric, close to the Euclidean one
    kernels = (cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3)), np.ones((3, 3), np.uint8))
    todo = inside & (lab == 0)
    new = np.empty_like(todo)
    for it in range(max_iter):
        grown = cv2.dilate(lab, kernels[it % 2])
        np.logical_and(todo, grown > 0, out=new)
        if not new.any():
            break
        np.copyto(lab, grown, where=new)  # as lab[new] = grown[new], without gathering the pixels
        todo ^= new  # new lies in todo: as todo &= ~new
    return lab.astype(np.int32)


def _straighten(pieces, res: float):
    """Replace the pixel staircase between two pieces by its Douglas-Peucker simplification (1.5 px):
    the union of the two is cut again along the simplified line. Kept only when the cut gives exactly
    two parts whose areas stay within 5 % of the staircase pieces."""
    from shapely.ops import linemerge, unary_union

    pieces = list(pieces)
    for i in range(len(pieces)):
        for j in range(i + 1, len(pieces)):
            gi, gj = pieces[i][0], pieces[j][0]
            try:
                shared = gi.boundary.intersection(gj.boundary)
                lines = [g for g in getattr(shared, "geoms", [shared]) if g.geom_type == "LineString" and g.length > 0]
                if not lines:
                    continue
                chain = linemerge(lines)
                if chain.geom_type != "LineString" or len(chain.coords) <= 2:
                    continue
                simple = chain.simplify(1.5 * res, preserve_topology=False)
                c = np.asarray(simple.coords)
                d0, d1 = c[0] - c[1], c[-1] - c[-2]
                ext = 3 * res
                c0 = c[0] + d0 / max(np.hypot(*d0), 1e-12) * ext
                c1 = c[-1] + d1 / max(np.hypot(*d1), 1e-12) * ext
                cut = LineString([tuple(c0)] + [tuple(p) for p in c] + [tuple(c1)])
                both = unary_union([gi, gj])
                parts = [g for g in shp_split(both, cut).geoms if g.area > 0]
                if len(parts) != 2:
                    continue
                ni = max(parts, key=lambda g: g.intersection(gi).area)
                nj = parts[1] if ni is parts[0] else parts[0]
                if abs(ni.area - gi.area) > 0.05 * gi.area or abs(nj.area - gj.area) > 0.05 * gj.area:
                    continue
                pieces[i] = (ni, pieces[i][1])
                pieces[j] = (nj, pieces[j][1])
            except Exception:
                continue
    return pieces


def _finish(a: Area, pieces, areas: List[Area], passages, labels, grid, recs, t: float):
    from dataclasses import replace

    # the piece holding the best-ranked name keeps the area's id; unnamed pieces (corridors) come last
    best_rec = _competing(recs)[0]
    bk = _key(best_rec.text)
    pieces.sort(key=lambda pk: (0 if bk in pk[1] else 1 if pk[1] else 2))
    next_id = max(x.id for x in areas) + 1
    out = []
    for n, (g, _) in enumerate(pieces):
        if n == 0:
            a.polygon = g
            out.append(a)
        else:
            b = replace(a, id=next_id, polygon=g, name="", ref="", tags=dict(a.tags),
                        max_clearance=0.0)
            next_id += 1
            areas.append(b)
            out.append(b)
    # texts follow the piece they lie in (nearby texts: the nearest piece)
    for r in recs:
        p = Point(r.x, r.y)
        r.area_id = min(out, key=lambda b: b.polygon.distance(p)).id
    new_pass = []
    if passages is not None:
        for p in passages:
            for end in ("from_id", "to_id"):
                if getattr(p, end) == a.id:
                    mid = p.line.interpolate(0.5, normalized=True)
                    setattr(p, end, min(out, key=lambda b: b.polygon.distance(mid)).id)
        pid = max([p.id for p in passages] + [0]) + 1
        from shapely.ops import linemerge

        for i in range(len(out)):
            for j in range(i + 1, len(out)):
                shared = out[i].polygon.boundary.intersection(out[j].polygon.boundary)
                lines = [g for g in getattr(shared, "geoms", [shared]) if g.geom_type == "LineString" and g.length > 0]
                if not lines:
                    continue
                merged = linemerge(lines)
                for ln in getattr(merged, "geoms", [merged]):
                    if ln.length < 0.3:
                        continue
                    passages.append(Passage(id=pid, from_id=out[i].id, to_id=out[j].id,
                                            line=LineString([ln.coords[0], ln.coords[-1]])))
                    new_pass.append(pid)
                    pid += 1
        # a door the cut runs through follows its midpoint's piece: its line goes on the border it lies on
        from .anchors import refit_passage_ends

        new_pass += [q for q in refit_passage_ends(areas, passages, {b.id for b in out}) if q >= pid]
    if labels is not None and grid is not None:
        _relabel(labels, grid, a.id, out)
    a.tags["_new_passages"] = new_pass
    return out


def _relabel(labels: np.ndarray, grid, old_id: int, pieces: List[Area]) -> None:
    from .rasterize import repaint_polygon

    sel = labels == old_id
    if not sel.any():
        return
    for b in pieces[1:]:
        repaint_polygon(labels, grid, b.polygon, b.id, mask=sel)


__all__ = ["NameRules", "load_name_rules", "default_name_rules", "normalize_text", "strip_xref", "classify_text",
           "classify_labels", "group_lines", "room_name_points", "score", "assign_names", "NamesReport",
           "TextRecord", "type_of_name", "floor_figures", "missed_texts", "protect_labelled_areas", "restore_types", "auto_id", "osm_tags", "for_osm", "LABEL_FIELDS", "RHO_MAX", "D_MAX"]
