# Sourced: use_test_tmpdir puts the tests' scratch files (TMPDIR) on a RAM-backed tmpfs when
# /dev/shm is one with 4 GiB free, in a folder of the user's own (GLOBE_TEST_TMPDIR names another;
# GLOBE_TEST_TMPDIR=/tmp keeps them on disk). Why: the programs fsync every pack and file they
# write (durable atomic writes), which on a virtual disk is half of a tiler test's wall time
# (the bundled world tiled in 8.2 s on this machine's ext4, 5.1 s on tmpfs, the same 4 s of CPU);
# on tmpfs fsync returns at once. What the tests check does not hang on the disk: the disk-full
# tests mount tmpfs of their own, and the durability of a write is the kernel's. The folder
# stays (a stable path, so the build directory's configuration does not change run to run); each
# test removes its own scratch files.
use_test_tmpdir() {
  local dir=${GLOBE_TEST_TMPDIR:-}
  if [ -z "$dir" ]; then
    local shm=/dev/shm free
    [ "$(stat -f -c %T "$shm" 2>/dev/null)" = tmpfs ] && [ -w "$shm" ] || return 0
    free=$(df -Pk "$shm" | awk 'NR == 2 {print $4}')
    [ "${free:-0}" -ge 4194304 ] || return 0
    dir=$shm/globe-tests-$(id -u)
  fi
  mkdir -p "$dir" && chmod 755 "$dir" && export TMPDIR=$dir
}
