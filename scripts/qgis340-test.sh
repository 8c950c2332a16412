#!/usr/bin/env bash
# Run the test suite on QGIS 3.40 LTR (Debian 13 trixie, Python 3.13, numpy 2) in a chroot.
#
#   scripts/qgis340-test.sh [pytest arguments]      (make test-qgis340 PYTEST_ARGS=...)
#
# Builds the root filesystem first when needed (scripts/qgis340-rootfs.sh, idempotent), copies this
# checkout into it (tracked and untracked files, no .venv/.qgis-profile/out/dist: the host's venv is
# for Debian 12's Python), links the chroot's venv and a fresh QGIS profile, mounts ../shared
# read-only when it exists, and runs pytest there. The log is also written to out/qgis340-pytest.log.
set -euo pipefail
ROOT="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
RFS="${CAD2OSMAG_TRIXIE:-/var/cache/cad2osmag/trixie}"
[ "$(id -u)" -eq 0 ] || { echo "run as root (chroot needs it)" >&2; exit 2; }
# shellcheck source=scripts/qgis340-chroot.sh
source "$ROOT/scripts/qgis340-chroot.sh"

start=$(date +%s)
bash "$ROOT/scripts/qgis340-rootfs.sh"
echo "[qgis340-test] root filesystem ready after $(( $(date +%s) - start )) s"

DEST=/work/cad2osmag          # inside the chroot
SHARED="$(cd "$ROOT/.." && pwd)/shared"
cleanup() {
  mountpoint -q "$RFS/work/shared" 2>/dev/null && umount "$RFS/work/shared"
  chroot_umount "$RFS"
}
trap cleanup EXIT
chroot_mount "$RFS"

rm -rf "$RFS$DEST"
mkdir -p "$RFS$DEST"
tar -C "$ROOT" --exclude=./.venv --exclude=./.qgis-profile --exclude=./out --exclude=./dist \
    --exclude='__pycache__' --exclude=./.pytest_cache --exclude=./.git -cf - . | tar -C "$RFS$DEST" -xf -
if [ -d "$SHARED" ]; then
  mkdir -p "$RFS/work/shared"
  mountpoint -q "$RFS/work/shared" || mount --bind -o ro "$SHARED" "$RFS/work/shared"
fi

mkdir -p "$ROOT/out"
set +e
in_chroot "$RFS" bash -c "set -e; cd $DEST
  ln -sfn /opt/cad2osmag-venv .venv
  bash scripts/setup-profile.sh
  export QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=/tmp/runtime-root CI=\${CI:-}
  mkdir -p \$XDG_RUNTIME_DIR && chmod 700 \$XDG_RUNTIME_DIR
  .venv/bin/python -c 'import sys, numpy; from qgis.core import Qgis; print(\"[qgis340-test] QGIS\", Qgis.QGIS_VERSION, \"Python\", sys.version.split()[0], \"numpy\", numpy.__version__)'
  exec .venv/bin/python -m pytest tests -ra -p no:cacheprovider $(printf '%q ' "$@")" 2>&1 | tee "$ROOT/out/qgis340-pytest.log"
rc=${PIPESTATUS[0]}
set -e
echo "[qgis340-test] pytest exit $rc after $(( $(date +%s) - start )) s in total (log: out/qgis340-pytest.log)"
exit "$rc"
