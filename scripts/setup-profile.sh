#!/usr/bin/env bash
# Link the plugin into a project-local QGIS profile (.qgis-profile/profiles/default) and enable it.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PROFILE="$ROOT/.qgis-profile/profiles/default"
mkdir -p "$PROFILE/python/plugins" "$PROFILE/QGIS"
ln -sfn "$ROOT" "$PROFILE/python/plugins/cad2osmag"
INI="$PROFILE/QGIS/QGIS3.ini"
touch "$INI"
if ! grep -q '^cad2osmag=true' "$INI"; then
  if grep -q '^\[PythonPlugins\]' "$INI"; then
    sed -i '/^\[PythonPlugins\]/a cad2osmag=true' "$INI"
  else
    printf '\n[PythonPlugins]\ncad2osmag=true\n' >> "$INI"
  fi
fi
