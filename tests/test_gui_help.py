"""Help texts: the algorithms whose help this task owns explain every parameter by name (with units)."""
import pytest

from .conftest import plugin_package

DOCUMENTED = ["samplebuilding", "georeference", "exportosmag", "loadosmag", "evaluatesegmentation",
              "dxftoosmagbatch"]


@pytest.mark.parametrize("name", DOCUMENTED)
def test_help_names_every_parameter(qgis_app, name):
    plugin_package()
    from cad2osmag.processing_provider.provider import algorithm_classes

    cls = {c.NAME: c for c in algorithm_classes()}[name]
    alg = cls()
    alg.initAlgorithm()
    text = alg.shortHelpString()
    missing = [p.name() for p in alg.parameterDefinitions() if p.name() not in text]
    assert not missing, f"{name}: help does not explain {missing}"
    assert any(unit in text for unit in ("metre", " m ", "m²", "degrees", "pixels")), name
