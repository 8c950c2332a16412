#!/usr/bin/env bash
# Idempotent installer: Debian packages (QGIS 3.22 LTR and tools), a venv from Debian's system
# python3 with --system-site-packages (so `qgis` and `osgeo` import), pinned Python deps, and the
# plugin linked into a project-local QGIS profile with the plugin enabled.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
APT_PACKAGES="${1:-qgis python3-qgis qgis-providers python3-venv python3-gdal gdal-bin osmium-tool xvfb python3-dev build-essential libproj-dev proj-bin}"

missing=()
for p in $APT_PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[install] Debian packages missing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Debian's interpreter, never whatever `python3` is first on PATH (it may not import qgis).
SYSPY=/usr/bin/python3
if [ ! -x "$ROOT/.venv/bin/python" ]; then
  echo "[install] creating .venv from $SYSPY --system-site-packages"
  "$SYSPY" -m venv --system-site-packages "$ROOT/.venv"
fi
# pyproj is compiled against the system PROJ (see requirements.txt); pin its build tools.
PIP_CONSTRAINT="$ROOT/constraints-build.txt" "$ROOT/.venv/bin/python" -m pip install -q --disable-pip-version-check \
  -r "$ROOT/requirements-dev.txt"
# shapely must be the wheel (bundled GEOS >= 3.11.2): Debian's GEOS 3.11.1 gets Hausdorff distances wrong
if ! "$ROOT/.venv/bin/python" -c "import shapely, sys; sys.exit(0 if shapely.geos_version >= (3, 11, 2) else 1)"; then
  "$ROOT/.venv/bin/python" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps \
    --only-binary shapely "$(grep -E '^shapely==' "$ROOT/requirements.txt")"
fi
"$ROOT/.venv/bin/python" -c "import qgis.core, osgeo.gdal, numpy, cv2, shapely, ezdxf, pyproj, scipy; assert numpy.__version__ < '2'; assert pyproj.proj_version_str.startswith('9.1'), 'pyproj must use the system PROJ'" \
  || { echo "[install] the venv cannot import its dependencies" >&2; exit 1; }

bash "$ROOT/scripts/setup-profile.sh"
echo "[install] done"
