"""The shipped graphical model models/cad_to_osmag.model3: it chains the individual algorithms, loads in
QGIS (as the modeler does), is offered by the provider, and runs headless on the sample building."""
import json
import subprocess

import pytest

from algorithms import osmag
from algorithms.georef import LocalFrame
from algorithms.sample_building import generate_building

from .conftest import REPO, plugin_package

MODEL = REPO / "models" / "cad_to_osmag.model3"
ANCHOR = (121.5906, 31.1790)
CHAIN = ["cad2osmag:extractstructure", "cad2osmag:rasterize", "cad2osmag:segment", "cad2osmag:refine",
         "cad2osmag:assignnames", "cad2osmag:georeference", "cad2osmag:exportosmag"]


def test_model_file_chains_the_stages_in_order(qgis_app):
    from qgis.core import QgsProcessingModelAlgorithm

    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    assert model.name() == "cad_to_osmag"
    children = model.childAlgorithms()
    assert sorted(c.algorithmId() for c in children.values()) == sorted(CHAIN)
    # every stage after the first takes the previous stage's output
    deps = {cid: {d.childId for d in c.dependencies()} | {
        s.outputChildId() for srcs in c.parameterSources().values() for s in srcs if s.outputChildId()}
        for cid, c in children.items()}
    assert deps["rasterize"] == {"extract"}
    assert deps["segment"] == {"rasterize", "extract"}
    assert deps["refine"] == {"segment"}
    assert deps["names"] == {"refine", "extract"}
    assert deps["georef"] == {"names"}
    assert deps["export"] == {"georef"}
    names = {p.name() for p in model.parameterDefinitions()}
    assert {"DXF", "ANCHOR", "ROTATION", "SCALE", "LEVEL", "RESOLUTION", "DOOR_WIDTH", "CORRIDOR_WIDTH",
            "MIN_AREA"} <= names
    assert set(children["export"].modelOutputs()) == {"OSM"}
    assert set(children["georef"].modelOutputs()) == {"Areas", "Passages"}
    assert "ANCHOR" in model.helpContent() and "SCALE" in model.helpContent()


def test_provider_offers_the_shipped_model(qgis_app, qgis_processing):
    from qgis.core import QgsApplication

    plugin_package()
    from cad2osmag.processing_provider.provider import Cad2OsmagProvider

    registry = QgsApplication.processingRegistry()
    added = registry.providerById("cad2osmag") is None
    provider = Cad2OsmagProvider() if added else registry.providerById("cad2osmag")
    if added:
        registry.addProvider(provider)
    try:
        alg = registry.algorithmById("cad2osmag:cad_to_osmag")
        assert alg is not None
        assert alg.provider() is provider
        assert alg.displayName() == "cad_to_osmag" and alg.group() == "Models"
    finally:
        if added:
            registry.removeProvider(provider)


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    return generate_building(str(tmp_path_factory.mktemp("model_sample")), floors=1, seed=0)


@pytest.mark.qgis_process
def test_model_runs_headless_on_the_sample_building(sample, tmp_path):
    out = tmp_path / "floor-1.osm"
    args = [str(REPO / "scripts" / "qgis-process"), "--json", "run", str(MODEL), "--",
            f"DXF={sample['dxf'][0]}", f"ANCHOR={ANCHOR[0]},{ANCHOR[1]} [EPSG:4326]", "ROTATION=30", "SCALE=1",
            "LEVEL=1", "RESOLUTION=0.044", "DOOR_WIDTH=2.8", "CORRIDOR_WIDTH=8", "MIN_AREA=10",
            f"export:OSM={out}", f"georef:Areas={tmp_path / 'areas.gpkg'}",
            f"georef:Passages={tmp_path / 'passages.gpkg'}"]
    proc = subprocess.run(args, capture_output=True, text=True, timeout=600, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, (proc.stdout + proc.stderr)[-4000:]
    results = json.loads(proc.stdout[proc.stdout.find("{"):])["results"]
    assert results["export:OSM"] == str(out)
    areas, passages, root, _ = osmag.read_osmag(str(out))
    assert root == pytest.approx(ANCHOR, abs=1e-8)  # the root node is the drawing origin
    kinds = {a.type for a in areas}
    assert {"room", "corridor", "stairs", "elevator"} <= kinds
    assert len(areas) >= 15 and len(passages) >= 15
    # room names from the drawing's texts (assignnames), not generated ids
    named = {a.name for a in areas if a.name and not a.name.startswith(("L1-", "1-"))}
    assert len(named) >= 10, sorted(a.name for a in areas)
    # placed with the rotation: the building's long side (CAD x) points 30 degrees clockwise from east
    import math

    import shapely

    north_up = LocalFrame(*ANCHOR, 0.0)
    floor = shapely.union_all([north_up.geometry_from_crs(a.polygon) for a in areas])
    rect = list(floor.minimum_rotated_rectangle.exterior.coords)
    sides = [(rect[i], rect[i + 1]) for i in range(2)]
    (x0, y0), (x1, y1) = max(sides, key=lambda s: math.dist(*s))
    assert math.degrees(math.atan2(x1 - x0, y1 - y0)) % 180.0 == pytest.approx(120.0, abs=1.0)
    assert 500 < floor.area < 1100  # m², the sample floor (not squared degrees)
    assert (tmp_path / "areas.gpkg").is_file() and (tmp_path / "passages.gpkg").is_file()


@pytest.mark.slow
def test_model_runs_headless_on_a_dwg_sheet(shared_data, tmp_path):
    """The model takes a DWG sheet as delivered (title frame, legends, details): the main plan is converted."""
    sheet = shared_data / "dwg" / "sist-original" / "SIST-F3.dwg"
    if not sheet.is_file():
        pytest.skip("SIST-F3.dwg not in ../shared")
    out = tmp_path / "SIST-F3.osm"
    args = [str(REPO / "scripts" / "qgis-process"), "--json", "run", str(MODEL), "--",
            f"DXF={sheet}", f"ANCHOR={ANCHOR[0]},{ANCHOR[1]} [EPSG:4326]", "ROTATION=0", "SCALE=1",
            "LEVEL=3", "RESOLUTION=0.044", "DOOR_WIDTH=2.8", "CORRIDOR_WIDTH=8", "MIN_AREA=10",
            f"export:OSM={out}", f"georef:Areas={tmp_path / 'areas.gpkg'}",
            f"georef:Passages={tmp_path / 'passages.gpkg'}"]
    proc = subprocess.run(args, capture_output=True, text=True, timeout=1200, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, (proc.stdout + proc.stderr)[-4000:]
    areas, passages, root, _ = osmag.read_osmag(str(out))
    assert root == pytest.approx(ANCHOR, abs=1e-8)
    assert len(areas) >= 40 and len(passages) >= 40
    kinds = {a.type for a in areas}
    assert {"room", "corridor", "stairs"} <= kinds, kinds
    # Chinese room names from the sheet's texts and block attributes
    assert sum(1 for a in areas if a.name and any("\u4e00" <= c <= "\u9fff" for c in a.name)) >= 10
