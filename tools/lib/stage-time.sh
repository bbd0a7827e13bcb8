# Sourced: stage NAME COMMAND... runs the command and prints one "CI-time" line with its wall
# time, so a change that makes CI slower shows in which stage (docs/performance/ci-time.md). With
# GLOBE_STAGE_LOG set, the line is appended to that file too (.ci/run repeats them at the end).
# The command's exit status is kept.
stage() {
  local name=$1
  shift
  local start=$SECONDS status=0
  "$@" || status=$?
  local line
  line=$(printf 'CI-time: %-28s %5d s%s' "$name" $((SECONDS - start)) \
    "$([ "$status" = 0 ] || echo "  (failed: exit $status)")")
  echo "$line"
  if [ -n "${GLOBE_STAGE_LOG:-}" ]; then echo "$line" >>"$GLOBE_STAGE_LOG"; fi
  return "$status"
}
