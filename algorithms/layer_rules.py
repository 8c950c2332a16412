"""Configurable layer filter: which DXF layers hold the permanent structure.

The rules live in a JSON file (``default_layer_rules.json`` beside this module is the default)::

    {
      "preserve": ["0", "Defpoints"],          # exact names (case-insensitive) kept as "reference"
      "exclude": ["text", "dim", ...],         # a layer containing one of these is dropped
      "kinds": {"wall": ["a-wall", "wall", "muro", ...], "door": [...], ...},
      "raster_kinds": ["wall", "column", ...]  # kinds drawn into the occupancy raster
    }

Matching is case-insensitive substring matching on the *meaningful part* of the name: the layer name
without the prefix that binding external references adds (``E1-RI-1F$0$A-WALL``, ``X$0$$2$A-WALL``,
``$1$A-WALL`` -> ``A-WALL``; ``XREF|A-WALL`` -> ``A-WALL``), so a keyword in the xref's file name never
decides. Prefixes and suffixes around a keyword (``1F-WALL-NEW``) do not matter.

Optional sections: ``"blocks"`` maps entity classes (door, window, furniture) to keywords of *block*
names, used when walls, doors and furniture share unhelpful layers (see cad_classify);
``"sheet"`` lists layer keywords of title frames/blocks (``frame``), legends (``legend``) and the title
keywords of plans and details (``plan_titles``, ``detail_titles``), used by cad_sheet. ASCII keywords of
up to 4 letters match only where no letter touches them (``wc`` matches ``WC_01``, not ``SWC``). ``exclude`` wins over ``kinds``; the first kind (in
file order) with a matching keyword gives the layer its category. Door layers are classified like any
other kind but are rasterized only when the caller asks for closed doors.
"""
from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

from .errors import InputError
from .model import KINDS

DEFAULT_RULES_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "default_layer_rules.json")
DEFAULT_RASTER_KINDS = ("wall", "column", "window", "stair", "elevator", "reference")
BLOCK_CLASSES = ("door", "window", "furniture")
SHEET_KEYS = ("frame", "legend", "plan_titles", "detail_titles", "legend_titles")

_XREF_PREFIX = re.compile(r"^.*\$\d+\$")


def meaningful_part(layer: str) -> str:
    """The layer name without the prefix bound external references add: ``E1-RI-1F$0$A-WALL``,
    ``X$0$$2$A-WALL`` and ``$1$A-WALL`` give ``A-WALL``; ``XREF|A-WALL`` gives ``A-WALL``."""
    name = layer.strip()
    if "|" in name:
        name = name.rsplit("|", 1)[1]
    m = _XREF_PREFIX.match(name)
    if m and m.end() < len(name):
        name = name[m.end():]
    return name.strip() or layer.strip()


def keyword_in(word: str, low: str) -> bool:
    """Whether a (lower-case) keyword occurs in a (lower-case) name. ASCII keywords of up to 4 letters
    must not touch another letter (``wc`` in ``wc_01`` but not in ``swc``); others are substrings."""
    if len(word) <= 4 and word.isascii():
        return re.search(r"(?<![a-z])" + re.escape(word) + r"(?![a-z])", low) is not None
    return word in low


@dataclass
class LayerRules:
    kinds: List[Tuple[str, List[str]]]  # ordered (kind, keywords)
    exclude: List[str] = field(default_factory=list)
    preserve: List[str] = field(default_factory=lambda: ["0", "defpoints"])
    raster_kinds: Tuple[str, ...] = DEFAULT_RASTER_KINDS
    source: str = ""  # file the rules came from
    blocks: Dict[str, List[str]] = field(default_factory=dict)  # block-name keywords per entity class
    sheet: Dict[str, List[str]] = field(default_factory=dict)  # frame / legend layers, title keywords

    def __post_init__(self):
        self.kinds = [(k, [w.lower() for w in words if w]) for k, words in self.kinds]
        self.exclude = [w.lower() for w in self.exclude if w]
        self.preserve = [w.lower() for w in self.preserve if w]
        self.blocks = {k: [w.lower() for w in v if w] for k, v in (self.blocks or {}).items()}
        self.sheet = {k: [w.lower() for w in v if w] for k, v in (self.sheet or {}).items()}
        self._cache: Dict[str, Tuple[Optional[str], str]] = {}
        self._block_cache: Dict[str, Tuple[Optional[str], str]] = {}

    def classify(self, layer: str) -> Tuple[Optional[str], str]:
        """Return ``(kind, rule)`` for a layer name; kind is None when the layer is dropped.

        ``rule`` says why, e.g. ``"wall: 'muro'"``, ``"exclude: 'text'"`` or ``"no keyword"``. Only the
        meaningful part of the name is matched (see ``meaningful_part``).
        """
        hit = self._cache.get(layer)
        if hit is not None:
            return hit
        low = meaningful_part(layer).lower()
        if low in self.preserve:
            res: Tuple[Optional[str], str] = ("reference", f"preserve: '{layer}'")
        else:
            res = (None, "no keyword")
            for word in self.exclude:
                if word in low:
                    res = (None, f"exclude: '{word}'")
                    break
            else:
                for kind, words in self.kinds:
                    w = next((w for w in words if w in low), None)
                    if w is not None:
                        res = (kind, f"{kind}: '{w}'")
                        break
        self._cache[layer] = res
        return res

    def block_class(self, chain: Sequence[str]) -> Tuple[Optional[str], str]:
        """Class (door / window / furniture) of an entity exploded from blocks ``chain`` (outermost
        first) by the block-name keywords; the innermost block with a matching name decides.
        Returns ``(class or None, matching block name)``."""
        for name in reversed(list(chain)):
            if not name:
                continue
            hit = self._block_cache.get(name)
            if hit is None:
                hit = (None, "")
                low = name.lower()
                for cls, words in self.blocks.items():
                    if any(keyword_in(w, low) for w in words):
                        hit = (cls, name)
                        break
                self._block_cache[name] = hit
            if hit[0] is not None:
                return hit
        return None, ""

    def sheet_words(self, key: str) -> List[str]:
        return list(self.sheet.get(key, []))

    def layer_is(self, layer: str, key: str) -> bool:
        """Whether a layer's meaningful part holds a keyword of sheet section ``key`` (frame, legend)."""
        low = meaningful_part(layer).lower()
        return any(keyword_in(w, low) for w in self.sheet.get(key, []))

    def kind_of(self, layer: str) -> Optional[str]:
        return self.classify(layer)[0]

    def keywords(self, kind: str) -> List[str]:
        for k, words in self.kinds:
            if k == kind:
                return list(words)
        return []


def _keywords(val, source: str, what: str) -> List[str]:
    """``val`` as a list of keywords (one string is a list of one); an InputError saying ``what`` it is for
    when it is something else."""
    if isinstance(val, str):
        val = [val]
    if not isinstance(val, list) or not all(isinstance(w, str) for w in val):
        raise InputError(f"layer rules '{source}': {what} must be a list of strings")
    return val


def _parse(data, source: str) -> LayerRules:
    if not isinstance(data, dict):
        raise InputError(f"layer rules '{source}' must be a JSON object with a 'kinds' mapping")
    kinds = data.get("kinds")
    if not isinstance(kinds, dict) or not kinds:
        raise InputError(f"layer rules '{source}': 'kinds' must map categories ({', '.join(KINDS)}) "
                         "to lists of keywords, e.g. {\"kinds\": {\"wall\": [\"wall\", \"muro\"]}}")
    items = []
    for kind, words in kinds.items():
        if kind not in KINDS:
            raise InputError(f"layer rules '{source}': unknown category '{kind}'; use one of {', '.join(KINDS)}")
        items.append((kind, _keywords(words, source, f"the keywords of '{kind}'")))

    def str_list(key, default):
        return _keywords(data.get(key, default), source, f"'{key}'")

    raster = str_list("raster_kinds", list(DEFAULT_RASTER_KINDS))
    bad = [k for k in raster if k not in KINDS]
    if bad:
        raise InputError(f"layer rules '{source}': unknown raster kind(s) {bad}; use {', '.join(KINDS)}")
    def str_map(key, allowed):
        val = data.get(key, {})
        if not isinstance(val, dict):
            raise InputError(f"layer rules '{source}': '{key}' must map {', '.join(allowed)} to lists of keywords")
        out = {}
        for k, words in val.items():
            if k not in allowed:
                raise InputError(f"layer rules '{source}': unknown '{key}' entry '{k}'; use {', '.join(allowed)}")
            out[k] = _keywords(words, source, f"'{key}.{k}'")
        return out

    blocks = str_map("blocks", BLOCK_CLASSES)
    sheet = str_map("sheet", SHEET_KEYS)
    if "blocks" not in data or "sheet" not in data:  # older rule files: the built-in defaults fill in
        defaults = _default_sections()
        blocks = blocks if "blocks" in data else defaults[0]
        sheet = sheet if "sheet" in data else defaults[1]
    return LayerRules(kinds=items, exclude=str_list("exclude", []), preserve=str_list("preserve", ["0", "Defpoints"]),
                      raster_kinds=tuple(raster), source=source, blocks=blocks, sheet=sheet)


def _default_sections():
    with open(DEFAULT_RULES_PATH, encoding="utf-8") as fh:
        data = json.load(fh)
    return dict(data.get("blocks", {})), dict(data.get("sheet", {}))


def load_rules(path: Optional[str] = None) -> LayerRules:
    """Load layer rules from a JSON file; ``None`` or ``""`` gives the defaults."""
    src = path or DEFAULT_RULES_PATH
    try:
        with open(src, encoding="utf-8") as fh:
            data = json.load(fh)
    except FileNotFoundError as exc:
        raise InputError(f"layer rules file '{src}' does not exist") from exc
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read layer rules file '{src}': {exc}") from exc
    except json.JSONDecodeError as exc:
        raise InputError(f"layer rules file '{src}' is not valid JSON (line {exc.lineno}, column {exc.colno}: "
                         f"{exc.msg}); start from algorithms/default_layer_rules.json") from exc
    return _parse(data, src)


def rules_from_dict(data: dict, source: str = "<dict>") -> LayerRules:
    return _parse(data, source)


_DEFAULT: Optional[LayerRules] = None


def default_rules() -> LayerRules:
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = load_rules(None)
    return _DEFAULT


def describe_kinds(rules: LayerRules, kinds: Sequence[str] = ("wall",)) -> str:
    return "; ".join(f"{k}: {', '.join(rules.keywords(k)[:8])}…" for k in kinds)
