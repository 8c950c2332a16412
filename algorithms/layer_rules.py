"""Configurable layer filter: which DXF layers hold the permanent structure.

The rules live in a JSON file (``default_layer_rules.json`` beside this module is the default)::

    {
      "preserve": ["0", "Defpoints"],          # exact names (case-insensitive) kept as "reference"
      "exclude": ["text", "dim", ...],         # a layer containing one of these is dropped
      "kinds": {"wall": ["a-wall", "wall", "muro", ...], "door": [...], ...},
      "raster_kinds": ["wall", "column", ...]  # kinds drawn into the occupancy raster
    }

Matching is case-insensitive substring matching. ``exclude`` wins over ``kinds``; the first kind (in
file order) with a matching keyword gives the layer its category. Door layers are classified like any
other kind but are rasterized only when the caller asks for closed doors.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

from .errors import InputError
from .model import KINDS

DEFAULT_RULES_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "default_layer_rules.json")
DEFAULT_RASTER_KINDS = ("wall", "column", "window", "stair", "elevator", "reference")


@dataclass
class LayerRules:
    kinds: List[Tuple[str, List[str]]]  # ordered (kind, keywords)
    exclude: List[str] = field(default_factory=list)
    preserve: List[str] = field(default_factory=lambda: ["0", "defpoints"])
    raster_kinds: Tuple[str, ...] = DEFAULT_RASTER_KINDS
    source: str = ""  # file the rules came from

    def __post_init__(self):
        self.kinds = [(k, [w.lower() for w in words if w]) for k, words in self.kinds]
        self.exclude = [w.lower() for w in self.exclude if w]
        self.preserve = [w.lower() for w in self.preserve if w]
        self._cache: Dict[str, Tuple[Optional[str], str]] = {}

    def classify(self, layer: str) -> Tuple[Optional[str], str]:
        """Return ``(kind, rule)`` for a layer name; kind is None when the layer is dropped.

        ``rule`` says why, e.g. ``"wall: 'muro'"``, ``"exclude: 'text'"`` or ``"no keyword"``.
        """
        hit = self._cache.get(layer)
        if hit is not None:
            return hit
        low = layer.lower().strip()
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

    def kind_of(self, layer: str) -> Optional[str]:
        return self.classify(layer)[0]

    def keywords(self, kind: str) -> List[str]:
        for k, words in self.kinds:
            if k == kind:
                return list(words)
        return []


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
        if isinstance(words, str):
            words = [words]
        if not isinstance(words, list) or not all(isinstance(w, str) for w in words):
            raise InputError(f"layer rules '{source}': the keywords of '{kind}' must be a list of strings")
        items.append((kind, words))

    def str_list(key, default):
        val = data.get(key, default)
        if isinstance(val, str):
            val = [val]
        if not isinstance(val, list) or not all(isinstance(w, str) for w in val):
            raise InputError(f"layer rules '{source}': '{key}' must be a list of strings")
        return val

    raster = str_list("raster_kinds", list(DEFAULT_RASTER_KINDS))
    bad = [k for k in raster if k not in KINDS]
    if bad:
        raise InputError(f"layer rules '{source}': unknown raster kind(s) {bad}; use {', '.join(KINDS)}")
    return LayerRules(kinds=items, exclude=str_list("exclude", []), preserve=str_list("preserve", ["0", "Defpoints"]),
                      raster_kinds=tuple(raster), source=source)


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
