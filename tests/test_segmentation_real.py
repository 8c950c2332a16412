"""Area Graph segmentation on real data: robot maps with ground truth, the sample building, CAD floors."""
import json
from pathlib import Path

import numpy as np
import pytest

from algorithms import segmentation as seg
from algorithms.evaluate import evaluate, read_gt_image
from algorithms.raster_io import read_grid

pytestmark = pytest.mark.slow

MCC_MEAN_TARGET = 0.85
MCC_MAP_TARGET = 0.60


@pytest.fixture(scope="module")
def grid_scores(shared_data):
    """Score every grid_gt map with the maps.csv widths and with the default widths."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
    from evaluate_grids import load_maps

    folder = shared_data / "grid_gt"
    scores = {}
    for m in load_maps(folder):
        grid = read_grid(str(folder / "input" / f"{m['name']}.png"), resolution=m["resolution"])
        gt = read_gt_image(str(folder / "gt" / f"{m['name']}.png"))
        for setting, dw, cw in (("csv", m["door"], m["corridor"]),
                                ("default", seg.DEFAULT_DOOR_WIDTH, seg.DEFAULT_CORRIDOR_WIDTH)):
            ag = seg.segment(grid, door_width=dw, corridor_width=cw)
            scores[(m["name"], setting)] = (evaluate(ag.labels, gt), ag)
    return scores


def test_grid_gt_mcc(grid_scores):
    mccs = {k: v[0]["mcc"] for k, v in grid_scores.items()}
    assert len(mccs) == 10
    for setting in ("csv", "default"):  # the target holds for each width setting on its own
        mean = np.mean([v for (name, s), v in mccs.items() if s == setting])
        assert mean >= MCC_MEAN_TARGET, (setting, mccs)
    assert min(mccs.values()) >= MCC_MAP_TARGET, mccs


def _largest_inside_free_component(grid):
    """The largest 4-connected free component inside the building (on these maps the outside is free
    space too, reached through open doors, so "inside" is the building interior segmentation found)."""
    from scipy import ndimage

    free = grid.data == 0
    interior_free, _ = seg.building_interior(free, grid.resolution)
    comp, n = ndimage.label(interior_free)
    sizes = ndimage.sum_labels(np.ones_like(comp), comp, index=np.arange(1, n + 1))
    return comp == 1 + int(np.argmax(sizes))


def test_grid_gt_coverage_and_connectivity(grid_scores):
    """Areas cover >= 97 % of the free pixels of the largest free component inside the building, and the
    areas in that component form one connected Area Graph (each passage an edge)."""
    for (name, setting), (_, ag) in grid_scores.items():
        inside = _largest_inside_free_component(ag.grid)
        covered = float((ag.labels[inside] > 0).mean())
        assert covered >= 0.97, (name, setting, covered)
        ids = set(np.unique(ag.labels[inside]).tolist()) - {0}
        adj = {i: set() for i in ids}
        for p in ag.passages:
            if p.from_id in ids and p.to_id in ids:
                adj[p.from_id].add(p.to_id)
                adj[p.to_id].add(p.from_id)
        start = next(iter(ids))
        seen, todo = {start}, [start]
        while todo:
            for j in adj[todo.pop()] - seen:
                seen.add(j)
                todo.append(j)
        assert seen == ids, (name, setting, len(ids) - len(seen))


def test_furnished_rooms_are_one_area_each(grid_scores):
    """Issue 14: lab_d's rooms hold tables standing free in them; each room is one area, not one per
    side of a table (before the furniture rule: F1 0.69 with 43 areas for 13 rooms)."""
    ev, ag = grid_scores[("lab_d", "default")]
    # 0.923 until session 9; the position-free wall faces (segmentation.FACE_FRAME) cost lab_d recall at every
    # shift (F1 0.889, MCC 0.955 -> 0.952; intel_map's spread 0.734-0.831 -> 0.821 is what they buy)
    assert ev["f1"] >= 0.88, ev["f1"]
    assert ev["mcc"] >= 0.95, ev["mcc"]
    assert len(ag.areas) <= 30
    # no other map got worse than before the rule (default widths, measured 2026-12-01)
    floors = {"Freiburg101_scan": 0.90, "freiburg_building52": 0.96, "intel_map": 0.62, "lab_a": 0.91}
    for name, floor in floors.items():
        assert grid_scores[(name, "default")][0]["mcc"] >= floor, name


def test_grid_gt_properties(grid_scores):
    for (name, setting), (ev, ag) in grid_scores.items():
        assert ev["recall"] > 0.8, (name, setting)
        labels, grid = ag.labels, ag.grid
        # labels only on free cells, polygons are the label outlines, one polygon per area
        assert (labels[grid.data != 0] == 0).all()
        for a in ag.areas:
            assert a.polygon.geom_type == "Polygon" and a.polygon.is_valid
        total = sum(a.polygon.area for a in ag.areas)
        assert total == pytest.approx((labels > 0).sum() * grid.resolution ** 2, rel=1e-9)
        assert {p.from_id for p in ag.passages} | {p.to_id for p in ag.passages} <= {a.id for a in ag.areas}


@pytest.fixture(scope="module")
def sample_floor(tmp_path_factory):
    from algorithms.cad_import import import_dxf
    from algorithms.rasterize import rasterize
    from algorithms.sample_building import generate_building

    out = generate_building(str(tmp_path_factory.mktemp("sample")), floors=2, seed=0)
    floors = []
    for dxf, gt in zip(out["dxf"], out["ground_truth"]):
        grid = rasterize(import_dxf(dxf).geometries)
        floors.append((grid, seg.segment(grid), json.load(open(gt, encoding="utf-8"))))
    return floors


def test_sample_building_rooms_and_doors(sample_floor):
    from shapely.geometry import shape

    for grid, ag, gt in sample_floor:
        feats = gt["features"]
        # every ground-truth space, stair core and lift shaft included (their symbols are not obstacles)
        rooms = [f for f in feats if f["properties"]["kind"] == "room"]
        assert {"stairs", "elevator", "corridor", "room"} <= {f["properties"]["areatype"] for f in rooms}
        area_of = {}
        for f in rooms:
            g = shape(f["geometry"])
            best = max(ag.areas, key=lambda a: a.polygon.intersection(g).area)
            iou = best.polygon.intersection(g).area / best.polygon.union(g).area
            assert iou >= 0.8, (f["properties"]["name"], iou)
            area_of[f["properties"]["name"]] = best.id
        assert len(set(area_of.values())) == len(area_of)  # one area per room
        doors = [f for f in feats if f["properties"]["kind"] == "door"
                 and f["properties"]["from"] in area_of and f["properties"]["to"] in area_of]
        assert len(doors) >= 10
        for f in doors:
            line = shape(f["geometry"])
            near = [p for p in ag.passages if p.line.distance(line.centroid) < 0.6]
            assert len(near) == 1, f["properties"]
            p = near[0]
            assert {p.from_id, p.to_id} == {area_of[f["properties"]["from"]], area_of[f["properties"]["to"]]}
            assert abs(p.width - f["properties"]["width"]) < 0.35


def _envelope_by_closing(grid, radius_m=1.0):
    """An independent building envelope: walls closed with a disk, holes filled."""
    import cv2
    from scipy import ndimage as ndi

    walls = (grid.data == 255).astype(np.uint8)
    f = max(1, int(round(0.1 / grid.resolution)))  # work at ~0.1 m/px
    small = cv2.resize(walls, (walls.shape[1] // f, walls.shape[0] // f), interpolation=cv2.INTER_AREA) > 0
    r = max(1, int(round(radius_m / (grid.resolution * f))))
    k = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * r + 1, 2 * r + 1))
    closed = cv2.morphologyEx(small.astype(np.uint8), cv2.MORPH_CLOSE, k) > 0
    filled = ndi.binary_fill_holes(closed)
    env = cv2.resize(filled.astype(np.uint8), (walls.shape[1], walls.shape[0]), interpolation=cv2.INTER_NEAREST) > 0
    return env & (grid.data == 0)


def _cad_files(shared_data):
    return (sorted((shared_data / "dxf" / "sist").glob("*.dxf"))
            + sorted((shared_data / "dxf" / "archweb").glob("*.dxf")))


@pytest.fixture(scope="module")
def cad_results(shared_data, floor_cache):
    """Stage 3 of every shared DXF plan as the pipeline runs it (walls and sheet boundary rasterised, door hints,
    room-name points inside): the session's conversions (tests/conftest.py ``floor_cache``, which test_real_plans
    and test_building share), not a segmentation of its own."""
    out = {}
    for path in _cad_files(shared_data):
        floor = floor_cache.process_floor(path)
        out[path.stem] = (floor.grid, floor.segmented)
    return out


def test_cad_floors_cover_the_building(cad_results):
    """Areas cover >= 90 % of the free space inside the building envelope, on every floor."""
    assert len(cad_results) >= 13
    for name, (grid, ag) in cad_results.items():
        covered = ag.labels > 0
        st = ag.stats
        assert covered.sum() * grid.resolution ** 2 >= 0.9 * st["interior_area_m2"], name
        env = _envelope_by_closing(grid)
        frac = covered[env].mean()
        assert frac >= 0.9, (name, frac)


def test_cad_floors_properties(cad_results):
    for name, (grid, ag) in cad_results.items():
        ids = [a.id for a in ag.areas]
        assert ids == list(range(1, len(ids) + 1)), name
        assert len(ag.areas) >= 5, name
        for p in ag.passages:
            assert p.from_id != p.to_id and len(p.line.coords) == 2
        if name.startswith("SIST"):
            assert 40 <= len(ag.areas) <= 400, (name, len(ag.areas))
            assert ag.stats["interior_area_m2"] > 3000, name


def test_sist_floor_connected(cad_results):
    grid, ag = cad_results["SIST-F3"]
    # the biggest connected group of areas holds most of the floor
    adj = {a.id: set() for a in ag.areas}
    for p in ag.passages:
        adj[p.from_id].add(p.to_id)
        adj[p.to_id].add(p.from_id)
    best = 0
    seen = set()
    area = {a.id: a.area for a in ag.areas}
    for start in adj:
        if start in seen:
            continue
        comp, todo = set(), [start]
        while todo:
            i = todo.pop()
            if i not in comp:
                comp.add(i)
                todo.extend(adj[i] - comp)
        seen |= comp
        best = max(best, sum(area[i] for i in comp))
    assert best >= 0.8 * sum(area.values())


def test_plain_segmentation_of_a_real_plan_is_deterministic_and_covers_it(cad_results):
    """``segment(grid)`` with nothing but the raster (the Processing path from a rasterised layer, no texts or
    door hints), twice on the smallest shared plan's grid: the same labels, and the checks above hold."""
    name = min(cad_results, key=lambda k: cad_results[k][0].data.size)
    grid = cad_results[name][0]
    ag, again = seg.segment(grid), seg.segment(grid)
    assert np.array_equal(again.labels, ag.labels)
    assert [a.polygon.wkt for a in again.areas] == [a.polygon.wkt for a in ag.areas]
    assert [a.id for a in ag.areas] == list(range(1, len(ag.areas) + 1)) and len(ag.areas) >= 5, name
    covered = ag.labels > 0
    assert covered.sum() * grid.resolution ** 2 >= 0.9 * ag.stats["interior_area_m2"], name
    assert covered[_envelope_by_closing(grid)].mean() >= 0.9, name
