# Sourced: seed_ctest_costs BUILD_DIR gives a build directory without CTest times of its own the
# committed ones (tests/ctest-costs.txt), so CTest starts the longest tests first rather than last.
seed_ctest_costs() {
  local costs=$1/Testing/Temporary/CTestCostData.txt
  if [ ! -s "$costs" ]; then
    mkdir -p "$(dirname "$costs")"
    { grep -v '^#' tests/ctest-costs.txt | awk 'NF == 2 {print $1, 1, $2}'; echo "---"; } >"$costs"
  fi
}
