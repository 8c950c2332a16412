"""cad2osmag:loadosmag — open an osmAG file as styled AREAS and PASSAGES layers."""
import os

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCategorizedSymbolRenderer,
    QgsFeature,
    QgsFeatureSink,
    QgsFillSymbol,
    QgsLineSymbol,
    QgsPalLayerSettings,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingLayerPostProcessorInterface,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterCrs,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFile,
    QgsRendererCategory,
    QgsTextFormat,
    QgsVectorLayerSimpleLabeling,
    QgsWkbTypes,
)
from qgis.PyQt.QtGui import QColor

from ..algorithms.osmag import get_tag
from .alg_georeference import qgs_crs_to_pyproj
from .base import Cad2OsmagAlgorithm, FIELD_LONG, FIELD_STRING, make_fields, to_qgs, tr_common

AREA_COLOURS = {  # osmAG:areatype -> (fill RGBA, outline)
    "room": ("255,235,160,180", "120,100,40"),
    "corridor": ("170,210,250,180", "60,100,150"),
    "stairs": ("250,170,90,200", "150,80,20"),
    "elevator": ("200,150,230,200", "110,60,140"),
    "structure": ("0,0,0,0", "90,90,90"),
}
FIRST_KEYS = ["osmAG:type", "osmAG:areatype", "name", "level", "height", "indoor", "osmAG:parent",
              "osmAG:from", "osmAG:to"]


def _labels(layer, size=9.0, colour="30,30,30"):
    settings = QgsPalLayerSettings()
    settings.fieldName = "name"
    settings.enabled = True
    fmt = QgsTextFormat()
    fmt.setSize(size)
    fmt.setColor(QColor(*[int(c) for c in colour.split(",")]))
    settings.setFormat(fmt)
    layer.setLabeling(QgsVectorLayerSimpleLabeling(settings))
    layer.setLabelsEnabled(True)


STYLES_DIR = os.path.join(os.path.dirname(os.path.dirname(__file__)), "styles")


def apply_osmag_style(layer, kind):
    """Style a layer made by loadosmag: ``kind`` 'areas' (categorized by osmAG:areatype, labels on
    name) or 'passages' (bold red lines, vertical passages highlighted, labels on name). The shipped
    QML ``styles/osmag_<kind>.qml`` is used when present, else the same style is built here."""
    qml = os.path.join(STYLES_DIR, f"osmag_{kind}.qml")
    if os.path.isfile(qml):
        _, ok = layer.loadNamedStyle(qml)
        if ok:
            layer.triggerRepaint()
            return
    build_osmag_style(layer, kind)


def build_osmag_style(layer, kind):
    """The osmAG style built in code (styles/build_styles.py saves it as the shipped QML files)."""
    if kind == "areas":
        cats = []
        for value, (fill, outline) in AREA_COLOURS.items():
            if value == "structure":
                sym = QgsFillSymbol.createSimple({"style": "no", "outline_color": outline, "outline_width": "0.8",
                                                  "outline_style": "dash"})
            else:
                sym = QgsFillSymbol.createSimple({"color": fill, "outline_color": outline, "outline_width": "0.3"})
            cats.append(QgsRendererCategory(value, sym, value))
        other = QgsFillSymbol.createSimple({"color": "220,220,220,160", "outline_color": "100,100,100"})
        cats.append(QgsRendererCategory("", other, "other"))  # "" = all other values
        layer.setRenderer(QgsCategorizedSymbolRenderer("osmAG:areatype", cats))
        _labels(layer)
    else:
        from qgis.core import QgsRuleBasedRenderer

        root = QgsRuleBasedRenderer.Rule(None)
        vertical = QgsLineSymbol.createSimple({"color": "0,90,255", "width": "2.4", "capstyle": "round"})
        root.appendChild(QgsRuleBasedRenderer.Rule(vertical, 0, 0, "\"vertical\" = 'yes'",
                                                   "vertical passage (stairs / lift)"))
        door = QgsLineSymbol.createSimple({"color": "220,20,20", "width": "1.2", "capstyle": "round"})
        root.appendChild(QgsRuleBasedRenderer.Rule(door, 0, 0, "", "passage", "", True))  # ELSE rule
        layer.setRenderer(QgsRuleBasedRenderer(root))
        _labels(layer, 8.0, "160,0,0")
    layer.triggerRepaint()


class OsmagStyler(QgsProcessingLayerPostProcessorInterface):
    def __init__(self, kind):
        super().__init__()
        self.kind = kind

    def postProcessLayer(self, layer, context, feedback):  # noqa: N802
        if layer is not None and layer.isValid():
            apply_osmag_style(layer, self.kind)
            save_default_style(layer, feedback)


def save_default_style(layer, feedback=None):
    """Store the style in the layer's GeoPackage as its default, so reopening the file shows it styled.
    Other formats keep the style for this session only. Returns True when stored."""
    if layer.providerType() != "ogr" or ".gpkg" not in layer.source().lower():
        return False
    error = layer.saveStyleToDatabase("cad2osmag", "osmAG style (cad2osmag)", True, "")
    if error and feedback is not None:
        feedback.pushInfo(tr_common("style not stored in {}: {}").format(layer.source(), error))
    return not error


def _keys(objs):
    """Tag keys as field names, in a stable order. Keys equal but for case (osmAG:areatype and
    osmAG:areaType) become one field: most formats (GeoPackage, Shapefile) ignore case in field names."""
    keys, seen = [], {"osm_id", "from_id", "to_id"}
    for o in objs:
        for k in o.tags:
            if k.lower() == "osmag:areatype":
                k = "osmAG:areatype"  # the styles categorize on this spelling
            if k.lower() not in seen:
                seen.add(k.lower())
                keys.append(k)
    first = [k for k in FIRST_KEYS if k in keys]
    return first + sorted(k for k in keys if k not in first)


def osmag_to_sinks(alg, parameters, context, feedback, path, tcrs, areas_key, passages_key):
    """Read an osmAG file and write its areas and passages into the feature sinks ``areas_key`` and
    ``passages_key`` of ``alg`` (in ``tcrs``), styled when QGIS loads them. Used by loadosmag and by
    dxftoosmag to show the converted floor. Returns (areas dest, passages dest, areas, passages, root,
    read report)."""
    from ..algorithms.georef import transform_geometry
    from ..algorithms.osmag import read_osmag

    areas, passages, root, report = alg.call(feedback, read_osmag, path)
    target = qgs_crs_to_pyproj(tcrs)
    convert = tcrs.authid() != "EPSG:4326"
    try:
        agoms = [transform_geometry(a.polygon, "EPSG:4326", target) if convert else a.polygon for a in areas]
        pgoms = [transform_geometry(p.line, "EPSG:4326", target) if convert else p.line for p in passages]
    except Exception as exc:
        raise QgsProcessingException(alg.tr("cannot convert to {}: {}").format(tcrs.authid(), exc))
    # everything computed: create the outputs
    akeys = _keys(areas)
    afields = make_fields(("osm_id", FIELD_LONG), *((k, FIELD_STRING) for k in akeys))
    pkeys = _keys(passages)
    pfields = make_fields(("osm_id", FIELD_LONG), ("from_id", FIELD_LONG), ("to_id", FIELD_LONG),
                          ("vertical", FIELD_STRING), *((k, FIELD_STRING) for k in pkeys))
    # a vertical passage joins two stair / lift areas (of adjacent levels): the style highlights it
    shaft = {a.id for a in areas if a.type in ("stairs", "elevator")}
    sink, adest = alg.parameterAsSink(parameters, areas_key, context, afields, QgsWkbTypes.Type.Polygon,
                                       tcrs)
    for a, g in zip(areas, agoms if sink is not None else []):  # an optional output may be skipped
        f = QgsFeature(afields)
        f.setGeometry(to_qgs(g))
        f["osm_id"] = int(a.id)
        for k in akeys:
            v = get_tag(a.tags, k)
            if v is not None:
                f[k] = v
        sink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
    psink, pdest = alg.parameterAsSink(parameters, passages_key, context, pfields,
                                        QgsWkbTypes.Type.LineString, tcrs)
    for p, g in zip(passages, pgoms if psink is not None else []):
        f = QgsFeature(pfields)
        f.setGeometry(to_qgs(g))
        f["osm_id"] = int(p.id)
        f["from_id"] = int(p.from_id)
        f["to_id"] = int(p.to_id)
        f["vertical"] = "yes" if p.from_id in shaft and p.to_id in shaft else "no"
        for k in pkeys:
            v = get_tag(p.tags, k)
            if v is not None:
                f[k] = v
        psink.addFeature(f, QgsFeatureSink.Flag.FastInsert)
    dangling = len(report["dangling_nodes"]) + len(report["dangling_refs"])
    if report["unclosed"]:
        feedback.pushWarning(alg.tr("unclosed area ways (skipped): {}").format(report["unclosed"]))
    if dangling:
        feedback.pushWarning(alg.tr("dangling references (skipped): nodes {} refs {}").format(
            report["dangling_nodes"], report["dangling_refs"]))
    # style the layers when they are loaded into the project (GUI runs)
    alg._stylers = []
    for dest, kind in ((adest, "areas"), (pdest, "passages")):
        if dest and context.willLoadLayerOnCompletion(dest):
            styler = OsmagStyler(kind)
            alg._stylers.append(styler)  # keep a reference: QGIS does not own Python post-processors
            context.layerToLoadOnCompletionDetails(dest).setPostProcessor(styler)
    return adest, pdest, areas, passages, root, report


class LoadOsmagAlgorithm(Cad2OsmagAlgorithm):
    NAME = "loadosmag"
    DISPLAY_NAME = "Load osmAG (.osm)"
    GROUP = "Tools"
    GROUP_ID = "tools"
    HELP = ("Opens an osmAG file (semantic or fix-id variant; written by this plugin, JOSM or other osmAG "
            "tools) as an areas polygon layer and a passages line layer with every tag as a field (plus osm_id, "
            "and from_id / to_id resolving each passage's areas to their way ids, and vertical = yes for a "
            "passage between two stair or lift areas). Areas are coloured by osmAG:areatype, passages drawn as "
            "bold red lines and vertical passages thick blue (styles/osmag_*.qml), both labelled with their "
            "name; GeoPackage outputs keep the style. Dangling references (missing nodes, passages naming "
            "unknown areas) and unclosed area ways are reported and skipped. A file without any osmAG area is "
            "rejected.\n"
            "INPUT: the osmAG file (.osm, OpenStreetMap XML, coordinates in WGS84 degrees).\n"
            "TARGET_CRS: CRS of the output layers (default WGS84, EPSG:4326); choose a projected CRS in metres "
            "to measure or edit the areas.\n"
            "OUTPUT_AREAS / OUTPUT_PASSAGES: the two layers (temporary, GeoPackage, …).\n"
            "Outputs: the number of areas and passages loaded (AREA_COUNT, PASSAGE_COUNT), the unclosed area ways "
            "(UNCLOSED) and dangling references (DANGLING) skipped, the root node's position (ROOT_LON, "
            "ROOT_LAT, degrees) and the VARIANT detected.")

    INPUT = "INPUT"
    TARGET_CRS = "TARGET_CRS"
    OUTPUT_AREAS = "OUTPUT_AREAS"
    OUTPUT_PASSAGES = "OUTPUT_PASSAGES"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterFile(self.INPUT, self.tr("osmAG file"), extension="osm"))
        self.addParameter(QgsProcessingParameterCrs(self.TARGET_CRS, self.tr("Output CRS"), "EPSG:4326", optional=True))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_AREAS, self.tr("osmAG areas"), QgsProcessing.SourceType.TypeVectorPolygon))
        self.addParameter(QgsProcessingParameterFeatureSink(
            self.OUTPUT_PASSAGES, self.tr("osmAG passages"), QgsProcessing.SourceType.TypeVectorLine))
        for name, label in (("AREA_COUNT", "Areas loaded"), ("PASSAGE_COUNT", "Passages loaded"),
                            ("UNCLOSED", "Unclosed area ways (skipped)"),
                            ("DANGLING", "Dangling references (skipped)"),
                            ("ROOT_LON", "Root node longitude"), ("ROOT_LAT", "Root node latitude")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))
        self.addOutput(QgsProcessingOutputString("VARIANT", self.tr("Variant detected")))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        path = self.parameterAsFile(parameters, self.INPUT, context)
        tcrs = self.parameterAsCrs(parameters, self.TARGET_CRS, context)
        if not tcrs.isValid():  # not given (qgis_process does not apply CRS defaults): WGS84
            tcrs = QgsCoordinateReferenceSystem("EPSG:4326")
        adest, pdest, areas, passages, root, report = osmag_to_sinks(
            self, parameters, context, feedback, path, tcrs, self.OUTPUT_AREAS, self.OUTPUT_PASSAGES)
        dangling = len(report["dangling_nodes"]) + len(report["dangling_refs"])
        return {self.OUTPUT_AREAS: adest, self.OUTPUT_PASSAGES: pdest, "AREA_COUNT": len(areas),
                "PASSAGE_COUNT": len(passages), "UNCLOSED": len(report["unclosed"]), "DANGLING": dangling,
                "ROOT_LON": root[0] if root else None, "ROOT_LAT": root[1] if root else None,
                "VARIANT": report["variant"]}
