# Sourced by the e2e scripts: what every mission's summary.json must show. The caller defines
# fail MESSAGE (prints its context and exits).
#   check_summary SUMMARY_JSON WHAT MIN_OBSERVABLE
# The mission ended because no task view was left (not on its time limit), with at least
# MIN_OBSERVABLE observable completeness and no robot colliding.
check_summary() {
  local summary=$1 what=$2 min_observable=$3 end obs time_s
  [ -f "$summary" ] || fail "$what: no $summary"
  end=$(sed -n 's/.*"end_reason": *"\([^"]*\)".*/\1/p' "$summary" | head -n 1)
  obs=$(sed -n 's/.*"final_observable_completeness": *\([^,}]*\).*/\1/p' "$summary" | head -n 1)
  time_s=$(sed -n 's/.*"exploration_time_s": *\([^,}]*\).*/\1/p' "$summary" | head -n 1)
  echo "$what: end: $end after $time_s s sim time, observable completeness: $obs (required >= $min_observable)"
  [ "$end" = "no task views remain" ] || fail "$what: mission ended by '$end', not by exhausted task views"
  awk -v c="$obs" -v m="$min_observable" 'BEGIN { exit !(c >= m) }' ||
    fail "$what: observable completeness $obs < $min_observable"
  if grep -o '"collisions": *[0-9]*' "$summary" | grep -qv '"collisions": *0$'; then fail "$what: a robot collided"; fi
}
