"""Writes i18n/cad2osmag_<lang>.ts from the plugin's sources (``make translations`` then compiles them
with Qt's ``lrelease``).

pylupdate5 only sees literal ``tr("...")`` calls; the algorithms' names, groups and help are class
attributes (DISPLAY_NAME, GROUP, HELP, MODES) translated at run time with the class name as context
(``Cad2OsmagAlgorithm.tr``), so this script reads the sources with ``ast`` and collects both:

* ``self.tr("...")`` inside a class -> context = the class name;
* ``tr("...")`` at module level in ``ui/*`` -> the context of that module's ``tr`` helper;
* ``QCoreApplication.translate("Context", "...")`` anywhere;
* DISPLAY_NAME / GROUP / HELP / MODES class attributes of every algorithm class;
* ``(key, "label")`` tuples looped into ``self.tr(label)`` (output labels);
* module-level lists translated in a comprehension, ``[self.tr(label) for _, label in CHOICES]``.

The translations live in one table per language, keyed by the English source text:
``translations_de.py`` and ``translations_zh_CN.py`` (read by ``seed_translations.py``; a key may also be
a ``(context, source)`` pair for a context-specific translation). The tables win; a translation found only
in a .ts file (e.g. made in Qt Linguist) is kept; anything else stays "unfinished" (Qt then shows the
English text). ``python3 i18n/update_ts.py --missing`` lists the strings without a translation as lines to
paste into both tables (an empty translation still counts as missing); ``--check`` exits 1 when there is one.
"""
import ast
import json
import os
import sys
import xml.etree.ElementTree as ET
from collections import OrderedDict

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
LANGUAGES = {"de": "de_DE", "zh_CN": "zh_CN"}
SOURCES = ["plugin.py", "processing_provider", "ui"]
MODELS = "models"  # *.model3: help and parameter descriptions, context Cad2OsmagModel (provider.translate_model)
MODEL_CONTEXT = "Cad2OsmagModel"
MODEL_HELP_KEYS_SKIPPED = {"ALG_CREATOR", "ALG_HELP_CREATOR", "ALG_VERSION", "EXAMPLES", "HELP_URL", "SHORT_DESCRIPTION"}

sys.path.insert(0, HERE)
from seed_translations import SEED  # noqa: E402


def _str(node):
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return None
    return None


def _module_tr_context(tree):
    """Context of a module-level ``def tr(text): return QCoreApplication.translate("Ctx", text)``."""
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name == "tr":
            for sub in ast.walk(node):
                if isinstance(sub, ast.Call) and getattr(sub.func, "attr", "") == "translate" and sub.args:
                    return _str(sub.args[0])
    return None


def collect(path):
    """[(context, source text, file)] of one Python file."""
    with open(path, encoding="utf-8") as fh:
        tree = ast.parse(fh.read(), path)
    rel = os.path.relpath(path, HERE)
    out = []
    module_ctx = _module_tr_context(tree)

    def visit(node, cls):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.ClassDef):
                for stmt in child.body:  # translated class attributes
                    if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 and isinstance(stmt.targets[0], ast.Name):
                        name = stmt.targets[0].id
                        if name in ("DISPLAY_NAME", "GROUP", "HELP") and _str(stmt.value):
                            out.append((child.name, _str(stmt.value), rel))
                        elif name == "MODES" and isinstance(stmt.value, ast.List):
                            out.extend((child.name, _str(e), rel) for e in stmt.value.elts if _str(e))
                visit(child, child.name)
                continue
            if isinstance(child, ast.Call):
                f = child.func
                if isinstance(f, ast.Attribute) and f.attr == "tr" and cls and child.args and _str(child.args[0]):
                    out.append((cls, _str(child.args[0]), rel))
                elif isinstance(f, ast.Attribute) and f.attr == "tr" and child.args and _str(child.args[0]) \
                        and isinstance(f.value, ast.Name) and f.value.id == "alg":
                    # alg.tr("...") in a helper shared by several algorithms: Cad2OsmagAlgorithm.tr falls back
                    # to this common context
                    out.append(("Cad2OsmagAlgorithm", _str(child.args[0]), rel))
                elif isinstance(f, ast.Name) and f.id == "tr_common" and child.args and _str(child.args[0]):
                    out.append(("Cad2OsmagAlgorithm", _str(child.args[0]), rel))  # base.tr_common
                elif isinstance(f, ast.Name) and f.id == "tr" and child.args and _str(child.args[0]):
                    ctx = module_ctx or cls
                    if ctx:
                        out.append((ctx, _str(child.args[0]), rel))
                elif isinstance(f, ast.Attribute) and f.attr == "translate" and len(child.args) >= 2 \
                        and _str(child.args[0]) and _str(child.args[1]):
                    out.append((_str(child.args[0]), _str(child.args[1]), rel))
            if isinstance(child, ast.For) and cls:  # for key, label in (("A", "Areas"), ...): self.tr(label)
                body_src = ast.dump(ast.Module(body=child.body, type_ignores=[]))
                if "attr='tr'" in body_src and isinstance(child.iter, (ast.Tuple, ast.List)):
                    for elt in child.iter.elts:
                        if isinstance(elt, ast.Tuple) and len(elt.elts) >= 2 and _str(elt.elts[1]):
                            out.append((cls, _str(elt.elts[1]), rel))
            visit(child, cls)

    visit(tree, None)
    out.extend(_translated_constants(tree, rel))
    # the provider's class-level name() uses the context Cad2OsmagProvider already (translate call)
    return out


def _translated_constants(tree, rel):
    """Strings of a module-level list translated in a comprehension inside a class:
    ``[self.tr(label) for _, label in CHOICES]`` / ``[self.tr(u) for u in UNITS]`` -> the labels / units."""
    constants = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name) \
                and isinstance(node.value, (ast.List, ast.Tuple)):
            constants[node.targets[0].id] = node.value.elts
    out = []
    for cls in (n for n in ast.walk(tree) if isinstance(n, ast.ClassDef)):
        for comp in (n for n in ast.walk(cls) if isinstance(n, (ast.ListComp, ast.GeneratorExp))):
            call, gen = comp.elt, comp.generators[0]
            if not (isinstance(call, ast.Call) and getattr(call.func, "attr", "") == "tr" and call.args
                    and isinstance(call.args[0], ast.Name) and isinstance(gen.iter, ast.Name)
                    and gen.iter.id in constants):
                continue
            var = call.args[0].id
            if isinstance(gen.target, ast.Name) and gen.target.id == var:
                index = None
            elif isinstance(gen.target, ast.Tuple):
                names = [getattr(e, "id", None) for e in gen.target.elts]
                if var not in names:
                    continue
                index = names.index(var)
            else:
                continue
            for elt in constants[gen.iter.id]:
                if index is not None and isinstance(elt, ast.Tuple) and len(elt.elts) > index:
                    elt = elt.elts[index]
                if _str(elt):
                    out.append((cls.name, _str(elt), rel))
    return out


def collect_model(path):
    """[(context, source text, file)] of a graphical model (.model3): its help texts and the descriptions of
    its parameters (outputs take theirs from the destination parameters)."""
    rel = os.path.relpath(path, HERE)
    root = ET.parse(path).getroot()
    out = []
    for top in root.findall("Option"):
        if top.get("name") == "help":
            out.extend((MODEL_CONTEXT, o.get("value"), rel) for o in top.findall("Option")
                       if o.get("value") and o.get("name") not in MODEL_HELP_KEYS_SKIPPED)
        elif top.get("name") == "parameterDefinitions":
            for param in top.findall("Option"):
                out.extend((MODEL_CONTEXT, o.get("value"), rel) for o in param.findall("Option")
                           if o.get("name") == "description" and o.get("value"))
    return out


def all_messages():
    messages = OrderedDict()  # (context, source) -> file
    for src in SOURCES:
        path = os.path.join(REPO, src)
        files = [path] if path.endswith(".py") else sorted(
            os.path.join(path, n) for n in os.listdir(path) if n.endswith(".py"))
        for f in files:
            for ctx, text, rel in collect(f):
                messages.setdefault((ctx, text), rel)
    models = os.path.join(REPO, MODELS)
    for name in sorted(os.listdir(models)) if os.path.isdir(models) else []:
        if name.endswith(".model3"):
            for ctx, text, rel in collect_model(os.path.join(models, name)):
                messages.setdefault((ctx, text), rel)
    return messages


def read_ts(path):
    """{(context, source): translation} of an existing .ts file (finished or not, non-empty)."""
    done = {}
    if not os.path.exists(path):
        return done
    root = ET.parse(path).getroot()
    for ctx in root.iter("context"):
        name = ctx.findtext("name")
        for msg in ctx.iter("message"):
            tr_el = msg.find("translation")
            if tr_el is not None and tr_el.text and tr_el.get("type") not in ("vanished", "obsolete"):
                done[(name, msg.findtext("source"))] = tr_el.text
    return done


def write_ts(path, lang, messages, existing, seed):
    root = ET.Element("TS", version="2.1", language=lang)
    by_ctx = OrderedDict()
    for (ctx, text), rel in messages.items():
        by_ctx.setdefault(ctx, []).append((text, rel))
    translated = 0
    for ctx in sorted(by_ctx):
        c = ET.SubElement(root, "context")
        ET.SubElement(c, "name").text = ctx
        for text, rel in by_ctx[ctx]:
            m = ET.SubElement(c, "message")
            ET.SubElement(m, "location", filename=rel)
            ET.SubElement(m, "source").text = text
            value = seed.get((ctx, text)) or seed.get(text) or existing.get((ctx, text))
            t = ET.SubElement(m, "translation")
            if value:
                t.text = value
                translated += 1
            else:
                t.set("type", "unfinished")
    ET.indent(root)
    with open(path, "w", encoding="utf-8") as fh:
        fh.write('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        fh.write(ET.tostring(root, encoding="unicode"))
        fh.write("\n")
    return translated


def missing(messages=None):
    """{language: [(context, source)]} of the strings the tables do not translate."""
    messages = all_messages() if messages is None else messages
    out = {}
    for suffix in LANGUAGES:
        seed = SEED.get(suffix, {})
        out[suffix] = [(ctx, text) for (ctx, text) in messages if not (seed.get((ctx, text)) or seed.get(text))]
    return out


def stale(messages=None):
    """{language: [source]} of table entries no source string uses any more (e.g. a reworded help)."""
    messages = all_messages() if messages is None else messages
    texts = {text for _, text in messages} | set(messages)
    return {suffix: [k for k in SEED.get(suffix, {}) if k not in texts] for suffix in LANGUAGES}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    messages = all_messages()
    if "--missing" in argv or "--check" in argv:
        gaps = missing(messages)
        for suffix, items in gaps.items():
            print(f"{suffix}: {len(items)} of {len(messages)} strings without a translation")
            shown = set()
            for ctx, text in items:  # lines to paste into translations_<lang>.py, then fill in
                if text not in shown:
                    shown.add(text)
                    print(f"    {json.dumps(text, ensure_ascii=False)}: \"\",  # {ctx}")
        return 1 if "--check" in argv and any(gaps.values()) else 0
    for suffix, lang in LANGUAGES.items():
        path = os.path.join(HERE, f"cad2osmag_{suffix}.ts")
        n = write_ts(path, lang, messages, read_ts(path), SEED.get(suffix, {}))
        print(f"{os.path.basename(path)}: {n} of {len(messages)} strings translated")
    for suffix, keys in stale(messages).items():
        if keys:
            print(f"translations_{suffix}.py: {len(keys)} entries no source uses any more (reworded or removed)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
