"""Help texts: every algorithm of the provider (and the shipped model) explains every parameter and every
output by name, with units where there are numbers."""
import re

import pytest

from .conftest import plugin_package

UNITS = ("metre", " m ", " m)", " m,", " m.", " m;", "(m)", "m²", "degrees", "pixel", "px", "%", "0-1",
         "milliseconds", "megapixels")


def _algorithms():
    plugin_package()
    from cad2osmag.processing_provider.provider import algorithm_classes

    return algorithm_classes()


def _names():
    from .conftest import REPO

    # the algorithm names without importing qgis at collection time: NAME = "..." of every alg_*.py
    names = []
    for path in sorted((REPO / "processing_provider").glob("alg_*.py")):
        names += re.findall(r'^    NAME = "([a-z0-9_]+)"', path.read_text(encoding="utf-8"), re.M)
    assert names
    return names


@pytest.mark.parametrize("name", _names())
def test_help_names_every_parameter_and_output(qgis_app, name):
    cls = {c.NAME: c for c in _algorithms()}[name]
    alg = cls()
    alg.initAlgorithm()
    text = alg.shortHelpString()
    assert text and text == alg.tr(cls.HELP)
    missing = [p.name() for p in alg.parameterDefinitions() if p.name() not in text and p.description() not in text]
    assert not missing, f"{name}: the help does not explain the parameters {missing}"
    outputs = [o.name() for o in alg.outputDefinitions() if o.name() not in text and o.description() not in text]
    assert not outputs, f"{name}: the help does not say what the outputs {outputs} hold"
    # the Processing dialog shows the help as HTML (one <p> per line): a <word> would silently vanish
    assert not re.search(r"<[A-Za-z/]", text), f"{name}: write NAME, not <name>, in the help"
    numeric = [p.name() for p in alg.parameterDefinitions() if p.type() == "number"]
    if numeric:
        assert any(unit in text for unit in UNITS), f"{name}: numeric parameters {numeric} but no unit in the help"


def test_every_algorithm_is_checked(qgis_app):
    assert sorted(_names()) == sorted(c.NAME for c in _algorithms())


def test_shipped_model_explains_every_parameter(qgis_app):
    plugin_package()
    from cad2osmag.processing_provider.provider import shipped_models

    models = shipped_models()
    assert models, "models/*.model3 is missing"
    for model in models:
        help_content = model.helpContent()
        assert help_content.get("ALG_DESC"), model.name()
        missing = [p.name() for p in model.parameterDefinitions() if not help_content.get(p.name())]
        assert not missing, f"{model.name()}: no help for {missing}"
