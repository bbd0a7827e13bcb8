# Sourced by the test installers (tools/web/install.sh, tools/cluster/install.sh):
#   apt_install_missing NAME PACKAGE...
# installs the packages from apt (as root, or through sudo), non-interactively and without
# recommends, saying so under NAME; does nothing given no package.
apt_install_missing() {
  local name=$1
  shift
  [ $# -gt 0 ] || return 0
  local sudo=
  if [ "$(id -u)" -ne 0 ]; then sudo=sudo; fi
  echo "$name: apt-get install $*"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}
