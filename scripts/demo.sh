#!/usr/bin/env bash
# make demo: generate the built-in sample building and convert it to osmAG, headless through
# scripts/qgis-process. Every result goes to out/demo/.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
OUT="$ROOT/out/demo"
QP="$ROOT/scripts/qgis-process"
ANCHOR="121.5906,31.1790 [EPSG:4326]"   # where the drawing origin lies (lon, lat)
ROTATION=0
rm -rf "$OUT"
mkdir -p "$OUT/dxf" "$OUT/stages" "$OUT/log"

run() {  # run ALG PARAM=VALUE ... ; the log goes to out/demo/log/ALG.log
  local alg="$1"; shift
  local log="$OUT/log/$alg${LOGSUFFIX:-}.log"
  printf '[demo] %-28s' "cad2osmag:$alg"
  local t0=$SECONDS
  if "$QP" run "cad2osmag:$alg" -- "$@" </dev/null >"$log" 2>&1; then
    echo " ok ($((SECONDS - t0)) s)"
  else
    echo " FAILED — last lines of $log:"; tail -25 "$log"; exit 1
  fi
}

# 1. the sample building: 3 floors of DXF (mm, NCS layers, blocks, text) + ground truth
run samplebuilding FLOORS=3 SEED=0 OUTPUT_FOLDER="$OUT/dxf"

# 2. floor 1 stage by stage, keeping every intermediate layer (open them in QGIS)
S="$OUT/stages"
run listlayers INPUT="$OUT/dxf/sample-F1.dxf" OUTPUT="$S/layers.csv"
run extractstructure INPUT="$OUT/dxf/sample-F1.dxf" WALLS="$S/walls.gpkg" TEXTS="$S/texts.gpkg"
run rasterize WALLS="$S/walls.gpkg" OCCUPANCY="$S/occupancy.tif"
run segment INPUT="$S/occupancy.tif" STRUCTURE="$S/walls.gpkg" AREAS="$S/areas.gpkg" PASSAGES="$S/passages.gpkg" LABELS="$S/labels.tif"
run refine AREAS="$S/areas.gpkg" PASSAGES="$S/passages.gpkg" RESOLUTION=0.044 \
    OUTPUT_AREAS="$S/refined_areas.gpkg" OUTPUT_PASSAGES="$S/refined_passages.gpkg"
run georeference AREAS="$S/refined_areas.gpkg" PASSAGES="$S/refined_passages.gpkg" MODE=0 \
    ANCHOR="$ANCHOR" ROTATION=$ROTATION TARGET_CRS=EPSG:4326 \
    OUTPUT_AREAS="$S/areas_wgs84.gpkg" OUTPUT_PASSAGES="$S/passages_wgs84.gpkg"
run exportosmag AREAS="$S/areas_wgs84.gpkg" PASSAGES="$S/passages_wgs84.gpkg" LEVEL=1 \
    ANCHOR_LON=121.5906 ANCHOR_LAT=31.1790 OUTPUT="$S/floor-1.osm"   # the root node at the anchor

# 3. every floor in one step each, then the building file and the preview image
floors=()
for k in 1 2 3; do
  extra=()
  [ "$k" = 1 ] && extra=(PREVIEW="$OUT/preview.png")
  LOGSUFFIX="-$k" run dxftoosmag INPUT="$OUT/dxf/sample-F$k.dxf" LEVEL=$k ANCHOR="$ANCHOR" ROTATION=$ROTATION \
      OUTPUT="$OUT/floor-$k.osm" "${extra[@]}"
  floors+=(INPUT="$OUT/floor-$k.osm")
done
run mergefloors "${floors[@]}" BUILDING="Sample building" OUTPUT="$OUT/building.osm"
run loadosmag INPUT="$OUT/building.osm" OUTPUT_AREAS="$S/building_areas.gpkg" OUTPUT_PASSAGES="$S/building_passages.gpkg"

echo
echo "Results in $OUT:"
echo "  building.osm          osmAG of the whole building (open it in JOSM or with cad2osmag:loadosmag)"
echo "  floor-1..3.osm        osmAG per floor"
echo "  preview.png           floor 1: areas, passages and walls"
echo "  dxf/                  the sample building's DXF files and ground truth (GeoJSON)"
echo "  stages/               floor 1 after each stage (walls, raster, areas, refined, georeferenced)"
echo "  log/                  the output of every algorithm"
