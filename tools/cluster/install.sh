#!/usr/bin/env bash
# What the cluster tests (tests/cluster) need, on Debian 12, from apt where any is missing (as
# root, or through sudo): Slurm and munge (a one-node cluster the Slurm test starts and stops
# itself; the packages' own services are not used), GNU parallel and python3-yaml. Only tests use
# them, so this is the test command's install step, not tools/install-deps.sh's.
set -euo pipefail
. "$(dirname "$0")/../lib/apt-install-missing.sh"
PATH=$PATH:/usr/sbin:/sbin
missing=()
for cmd in slurmctld slurmd sbatch; do
  command -v "$cmd" >/dev/null 2>&1 || { missing+=(slurm-wlm); break; }
done
command -v munged >/dev/null 2>&1 || missing+=(munge)
# moreutils has a `parallel` too, which the tests cannot use.
parallel --version 2>/dev/null | grep -q 'GNU parallel' || missing+=(parallel)
python3 -c 'import yaml' 2>/dev/null || missing+=(python3-yaml)
if [ ${#missing[@]} -gt 0 ]; then
  apt_install_missing tools/cluster/install.sh "${missing[@]}"
else
  echo "tools/cluster/install.sh: slurm-wlm, munge, parallel and python3-yaml are installed"
fi
