# Sourced: gtest_results DIR counts the GoogleTest tests that ran, from the XML reports each CTest
# test of a test program writes there (one per suite or solo test: cmake/GlobeTestGroupsScript.cmake),
# and names every one that failed or was skipped. CTest counts processes; this counts tests.
# Exit status 1 when a test failed, or when there is no report at all (a skip is only named).
gtest_results() {
  local dir=$1
  if ! compgen -G "$dir/*.xml" >/dev/null; then
    echo "gtest: no reports in $dir"
    return 1
  fi
  awk '
    /<testcase / {
      name = $0; sub(/.*<testcase name="/, "", name); sub(/".*/, "", name)
      suite = $0; sub(/.*classname="/, "", suite); sub(/".*/, "", suite)
      current = suite "." name; ++tests
      if ($0 ~ /result="skipped"/) { ++skipped; skips = skips "\n  skipped: " current }
      open = $0 !~ /\/>[[:space:]]*$/; failed = 0; next
    }
    open && /<failure/ && !failed { failed = 1; ++failures; fails = fails "\n  FAILED:  " current }
    /<\/testcase>/ { open = 0 }
    END {
      printf "gtest: %d tests ran (%d reports): %d passed, %d failed, %d skipped%s%s\n",
        tests, FILENAME == "" ? 0 : ARGC - 1, tests - failures - skipped, failures, skipped, fails, skips
      exit (failures > 0)
    }' "$dir"/*.xml
}
