"""The translations ``update_ts.py`` writes into the .ts files: one table per language, keyed by the English
source text, in ``translations_<lang>.py`` (``T = {"English": "translation", ...}``; a key may also be a
``("Context", "English")`` pair when one context needs another word).

To translate new strings: ``python3 i18n/update_ts.py --missing`` lists them; add them to both tables and
run ``make translations``. The tables are the source of truth (a reworded English string simply shows up
as missing again); the .ts/.qm files are generated from them.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from translations_de import T as _DE  # noqa: E402
from translations_zh_CN import T as _ZH  # noqa: E402

SEED = {"de": _DE, "zh_CN": _ZH}
