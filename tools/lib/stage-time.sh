# Sourced: stage NAME COMMAND... runs the command and prints one "CI-time" line with its wall
# time, so a change that makes CI slower shows in which stage (docs/performance/ci-time.md).
# stage_summary prints every stage's line again at the end. The command's exit status is kept.
GLOBE_STAGE_LINES=${GLOBE_STAGE_LINES:-}
stage() {
  local name=$1
  shift
  local start=$SECONDS status=0
  "$@" || status=$?
  local line
  line=$(printf 'CI-time: %-28s %5d s%s' "$name" $((SECONDS - start)) \
    "$([ "$status" = 0 ] || echo "  (failed: exit $status)")")
  echo "$line"
  GLOBE_STAGE_LINES+="$line"$'\n'
  if [ -n "${GLOBE_STAGE_LOG:-}" ]; then echo "$line" >>"$GLOBE_STAGE_LOG"; fi
  return "$status"
}
