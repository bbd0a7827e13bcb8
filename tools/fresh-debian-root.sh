# shellcheck shell=bash
# Sourced by the scripts that try globe on a new machine: makes a minimal Debian 12
# (`debootstrap --variant=minbase bookworm`, nothing beyond the base) in a temporary directory,
# with /proc, /dev and the host's resolver, and removes it on exit. Needs root and the mirror.
#
#   source tools/fresh-debian-root.sh; makeFreshDebian PREFIX    → sets ROOT
MIRROR=${MIRROR:-http://deb.debian.org/debian}

removeFreshDebian() {
  umount "$ROOT/proc" "$ROOT/dev" 2>/dev/null || true
  rm -rf --one-file-system "$ROOT"
}

makeFreshDebian() {
  command -v debootstrap >/dev/null || apt-get install -y -q debootstrap >/dev/null
  ROOT=$(mktemp -d "/tmp/$1.XXXXXX")
  trap removeFreshDebian EXIT
  echo "== debootstrap --variant=minbase bookworm $ROOT"
  debootstrap --variant=minbase bookworm "$ROOT" "$MIRROR" >/dev/null
  cp /etc/resolv.conf "$ROOT/etc/resolv.conf"
  mount --bind /proc "$ROOT/proc"
  mount --bind /dev "$ROOT/dev"
}
