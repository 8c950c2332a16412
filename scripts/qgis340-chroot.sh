#!/usr/bin/env bash
# Helpers (sourced) to enter the Debian 13 root filesystem: /proc, /sys, /dev bind-mounted, and the
# checkout bind-mounted at /src. Every mount is undone by chroot_umount, also after a failure.

chroot_mount() {  # chroot_mount ROOTFS [SRC]
  local rfs="$1" src="${2:-}"
  mountpoint -q "$rfs/proc" || mount -t proc proc "$rfs/proc"
  mountpoint -q "$rfs/sys" || mount --rbind /sys "$rfs/sys"
  mountpoint -q "$rfs/dev" || mount --rbind /dev "$rfs/dev"
  if [ -n "$src" ]; then
    mkdir -p "$rfs/src"
    mountpoint -q "$rfs/src" || mount --bind "$src" "$rfs/src"
  fi
}

chroot_umount() {  # chroot_umount ROOTFS
  local rfs="$1" m
  for m in src dev sys proc; do
    if mountpoint -q "$rfs/$m" 2>/dev/null; then
      umount -R "$rfs/$m" 2>/dev/null || umount -R -l "$rfs/$m" 2>/dev/null || true
    fi
  done
}

in_chroot() {  # in_chroot ROOTFS CMD...: a clean environment, Debian's PATH, the host's proxy/pip settings
  local rfs="$1"; shift
  local pass=() v
  for v in http_proxy https_proxy no_proxy HTTP_PROXY HTTPS_PROXY NO_PROXY PIP_INDEX_URL PIP_DEFAULT_TIMEOUT CI; do
    [ -n "${!v:-}" ] && pass+=("$v=${!v}")
  done
  env -i HOME=/root TERM="${TERM:-dumb}" LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    PIP_CERT=/etc/ssl/certs/ca-certificates.crt "${pass[@]}" \
    chroot "$rfs" "$@"
}
