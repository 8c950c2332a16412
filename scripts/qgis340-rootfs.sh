#!/usr/bin/env bash
# Build (idempotently) a Debian 13 (trixie) root filesystem with QGIS 3.40 LTR, Python 3.13, numpy 2
# and the plugin's dependencies, outside the repository. Each stage leaves a stamp; a rerun skips
# what is done and redoes a stage whose inputs changed (the requirements file for the venv).
#
#   scripts/qgis340-rootfs.sh            build or update the root filesystem
#   CAD2OSMAG_TRIXIE=/path ...           build it somewhere else (default /var/cache/cad2osmag/trixie)
#   CAD2OSMAG_DEBIAN_MIRROR=URL ...      Debian mirror for debootstrap (default: debootstrap's own)
#
# Runs as root (debootstrap, chroot, mount). Needs ~3 GB of disk.
set -euo pipefail
ROOT="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
RFS="${CAD2OSMAG_TRIXIE:-/var/cache/cad2osmag/trixie}"
SUITE=trixie
# Debian's own builds of what must match QGIS's libraries: numpy (GDAL's bindings are built against
# it), pyproj (against trixie's PROJ, the one QGIS links), GDAL. The rest comes from pip, pinned in

APT_PACKAGES="qgis python3-qgis qgis-providers python3-gdal python3-numpy python3-pyproj python3-venv \
python3-pip gdal-bin proj-data proj-bin osmium-tool xauth xvfb locales ca-certificates"
VENV=/opt/cad2osmag-venv
log() { echo "[qgis340-rootfs] $*"; }

[ "$(id -u)" -eq 0 ] || { echo "run as root (debootstrap and chroot need it)" >&2; exit 2; }
# shellcheck source=scripts/qgis340-chroot.sh
source "$ROOT/scripts/qgis340-chroot.sh"

# 1. the base system
if [ ! -e "$RFS/.stage-debootstrap" ]; then
  command -v debootstrap >/dev/null || { apt-get update -qq; DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap; }
  if [ -e "$RFS" ]; then  # a half-finished earlier run: start again from nothing
    log "removing the unfinished $RFS"
    chroot_umount "$RFS"
    rm -rf --one-file-system "$RFS"
  fi
  mkdir -p "$RFS"
  log "debootstrap $SUITE into $RFS"
  # shellcheck disable=SC2086
  debootstrap --variant=minbase "$SUITE" "$RFS" ${CAD2OSMAG_DEBIAN_MIRROR:-}
  touch "$RFS/.stage-debootstrap"
fi

trap 'chroot_umount "$RFS"' EXIT
chroot_mount "$RFS"

# 2. QGIS and Debian's Python packages
if [ ! -e "$RFS/.stage-apt" ] || [ "$(cat "$RFS/.stage-apt")" != "$APT_PACKAGES" ]; then
  log "apt-get install QGIS 3.40 and Python packages"
  cp /etc/resolv.conf "$RFS/etc/resolv.conf" 2>/dev/null || true
  in_chroot "$RFS" bash -c "export DEBIAN_FRONTEND=noninteractive; apt-get update -qq && \
    apt-get install -y -qq --no-install-recommends $APT_PACKAGES && apt-get clean"
  echo "$APT_PACKAGES" > "$RFS/.stage-apt"
fi

# 2b. the host's local certificate authorities (a TLS-inspecting proxy's CA): pip in the chroot must
#     trust what pip on the host trusts. Rerun every time: cheap, and the host's CAs may change.
if ls /usr/local/share/ca-certificates/*.crt >/dev/null 2>&1; then
  mkdir -p "$RFS/usr/local/share/ca-certificates"
  cp /usr/local/share/ca-certificates/*.crt "$RFS/usr/local/share/ca-certificates/"
  in_chroot "$RFS" update-ca-certificates >/dev/null 2>&1 || log "update-ca-certificates failed"
fi

# 3. the venv: Debian's python3 with --system-site-packages (qgis, osgeo, numpy, pyproj), pinned pip
#    packages on top; numpy is held at Debian's build so pip never replaces it.
REQ="$ROOT/requirements-qgis340.txt"
REQ_SUM="$(sha256sum "$REQ" | cut -d' ' -f1)"
if [ ! -e "$RFS/.stage-venv" ] || [ "$(cat "$RFS/.stage-venv")" != "$REQ_SUM" ]; then
  log "venv $VENV with requirements-qgis340.txt"
  cp "$REQ" "$RFS/tmp/requirements-qgis340.txt"
  in_chroot "$RFS" bash -c "set -e
    [ -x $VENV/bin/python ] || /usr/bin/python3 -m venv --system-site-packages $VENV
    /usr/bin/python3 -c 'import numpy; print(\"numpy==\" + numpy.__version__)' > /tmp/constraints-debian.txt
    /usr/bin/python3 -c 'import pyproj; print(\"pyproj==\" + pyproj.__version__)' >> /tmp/constraints-debian.txt
    $VENV/bin/python -m pip install -q --disable-pip-version-check -c /tmp/constraints-debian.txt \
      -r /tmp/requirements-qgis340.txt
    $VENV/bin/python -c 'import qgis.core, osgeo.gdal, numpy, cv2, shapely, ezdxf, ezdwg, pyproj, scipy, pytest
import sys; from qgis.core import Qgis
print(\"QGIS\", Qgis.QGIS_VERSION, \"Python\", sys.version.split()[0], \"numpy\", numpy.__version__,
      \"GDAL\", osgeo.gdal.__version__, \"PROJ\", pyproj.proj_version_str, \"GEOS (shapely)\", shapely.geos_version_string)'"
  echo "$REQ_SUM" > "$RFS/.stage-venv"
fi
log "ready: $RFS"
