"""Combine per-floor osmAG files into one building file.

Floors converted with the same anchor share one local frame, so their files can be merged as they are:
ids are renumbered (negative, unique per element type across the building), one root node is kept,
and a building structure area that encloses every floor becomes the ``osmAG:parent`` of each floor's
outline. References in the fix-id variant (way ids in ``osmAG:parent/from/to``) are renumbered too.
Aligning floors on their stairs/lifts and adding vertical passages is the multi-floor fusion stage's job.
"""
from __future__ import annotations

import math
import os
import xml.etree.ElementTree as ET
from typing import Dict, List, Sequence

from shapely.geometry import Polygon
from shapely.ops import unary_union

from .errors import InputError
from .io_utils import atomic_write
from .progress import ensure

REF_KEYS = ("osmAG:parent", "osmAG:from", "osmAG:to")
ROOT_TOLERANCE_DEG = 1e-9  # ~0.1 mm: floors must share the root node to share a frame


def _tags(elem) -> Dict[str, str]:
    return {t.get("k"): t.get("v") for t in elem.findall("tag")}


def _set_tag(elem, key, value):
    for t in elem.findall("tag"):
        if t.get("k") == key:
            t.set("v", value)
            return
    ET.SubElement(elem, "tag", {"k": key, "v": value})


def merge_floor_files(paths: Sequence[str], out_path: str, building_name: str = "Building",
                      progress=None) -> Dict[str, object]:
    """Merge osmAG floor files (same root node) into ``out_path``. Returns figures for the log."""
    progress = ensure(progress)
    if not paths:
        raise InputError("no floor files to merge")
    root_pos = None
    next_node, next_way = -1, -1
    out_nodes: List[ET.Element] = []
    out_ways: List[ET.Element] = []
    floor_outlines: List[Polygon] = []
    floor_ways: List[ET.Element] = []
    levels: List[str] = []
    fixid = False
    for i, path in enumerate(paths):
        progress.step(100.0 * i / len(paths), f"merging {os.path.basename(path)}")
        try:
            osm = ET.parse(path).getroot()
        except (ET.ParseError, OSError) as exc:
            raise InputError(f"cannot read osmAG floor file '{path}': {exc}") from exc
        nodes = {n.get("id"): n for n in osm.findall("node")}
        roots = [n for n in nodes.values() if _tags(n).get("name") == "root"]
        if len(roots) != 1:
            raise InputError(f"'{os.path.basename(path)}' has {len(roots)} root nodes; an osmAG file has exactly one")
        pos = (float(roots[0].get("lon")), float(roots[0].get("lat")))
        if root_pos is None:
            root_pos = pos
            root = ET.Element("node", {"id": str(next_node), "lat": roots[0].get("lat"), "lon": roots[0].get("lon"),
                                       "version": "1", "visible": "true"})
            ET.SubElement(root, "tag", {"k": "name", "v": "root"})
            out_nodes.append(root)
            next_node -= 1
        elif max(abs(pos[0] - root_pos[0]), abs(pos[1] - root_pos[1])) > ROOT_TOLERANCE_DEG:
            raise InputError(f"'{os.path.basename(path)}' has its root node at {pos}, not at {root_pos}: "
                             "convert every floor with the same anchor before merging")
        node_map: Dict[str, str] = {}
        for nid, n in nodes.items():
            if n is roots[0]:
                continue
            node_map[nid] = str(next_node)
            n.set("id", str(next_node))
            out_nodes.append(n)
            next_node -= 1
        way_map: Dict[str, str] = {}
        ways = osm.findall("way")
        for w in ways:
            way_map[w.get("id")] = str(next_way)
            next_way -= 1
        coords = {n.get("id"): (float(n.get("lon")), float(n.get("lat"))) for n in out_nodes}
        for w in ways:
            w.set("id", way_map[w.get("id")])
            for nd in w.findall("nd"):
                ref = nd.get("ref")
                if ref not in node_map:
                    raise InputError(f"way {w.get('id')} of '{os.path.basename(path)}' references missing node {ref}")
                nd.set("ref", node_map[ref])
            tags = _tags(w)
            for key in REF_KEYS:
                if key in tags and tags[key] in way_map:  # fix-id variant
                    _set_tag(w, key, way_map[tags[key]])
                    fixid = True
            if tags.get("osmAG:areatype") == "structure" and not tags.get("osmAG:parent"):
                ring = [coords[nd.get("ref")] for nd in w.findall("nd")]
                if len(ring) >= 4:
                    floor_outlines.append(Polygon(ring))
                    floor_ways.append(w)
            if tags.get("level") and tags["level"] not in levels:
                levels.append(tags["level"])
            out_ways.append(w)
    if not floor_ways:
        raise InputError("the floor files have no floor outline (structure area without parent) to attach "
                         "to the building")
    # the building outline: the union of the floor outlines (it contains each of them)
    outline = unary_union([p.buffer(0) for p in floor_outlines])
    parts = list(getattr(outline, "geoms", [outline]))
    shell = Polygon(max(parts, key=lambda p: p.area).exterior) if len(parts) == 1 else outline.convex_hull
    ring = list(shell.exterior.coords)[:-1]
    building_way = ET.Element("way", {"id": str(next_way), "version": "1", "visible": "true"})
    first = None
    for lon, lat in ring:
        n = ET.Element("node", {"id": str(next_node), "lat": f"{lat:.10f}", "lon": f"{lon:.10f}",
                                "version": "1", "visible": "true"})
        out_nodes.append(n)
        ET.SubElement(building_way, "nd", {"ref": str(next_node)})
        first = first or str(next_node)
        next_node -= 1
    ET.SubElement(building_way, "nd", {"ref": first})
    level_list = sorted(levels, key=lambda s: (float(s) if _is_number(s) else math.inf, s))
    for k, v in (("osmAG:type", "area"), ("osmAG:areatype", "structure"), ("indoor", "area"),
                 ("area", "yes"), ("building", "yes"), ("name", building_name), ("level", ";".join(level_list))):
        ET.SubElement(building_way, "tag", {"k": k, "v": v})
    for w in floor_ways:
        _set_tag(w, "osmAG:parent", building_way.get("id") if fixid else building_name)
    osm_out = ET.Element("osm", {"version": "0.6", "generator": "cad2osmag"})
    osm_out.extend(out_nodes)
    osm_out.append(building_way)
    osm_out.extend(out_ways)
    ET.indent(osm_out)
    with atomic_write(out_path) as fh:
        fh.write('<?xml version="1.0" encoding="UTF-8"?>\n')
        fh.write(ET.tostring(osm_out, encoding="unicode"))
        fh.write("\n")
    progress.step(100, f"building: {len(paths)} floors, {len(out_ways) + 1} ways, {len(out_nodes)} nodes "
                       f"written to {out_path}")
    return {"floors": len(paths), "ways": len(out_ways) + 1, "nodes": len(out_nodes), "levels": level_list,
            "variant": "fix-id" if fixid else "semantic"}


def _is_number(s: str) -> bool:
    try:
        float(s)
        return True
    except ValueError:
        return False
