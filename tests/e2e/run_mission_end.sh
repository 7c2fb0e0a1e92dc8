#!/usr/bin/env bash
# A mission on a scene of the default scene's character must end because no task view is left,
# not on its time limit (a safety net): one lockstep run of a team file through
# hexplore_experiment, then its summary.json must show that end, the stated observable
# completeness and no collision.
#   run_mission_end.sh EXPERIMENT TEAM_FILE WORKDIR [SEED]
set -euo pipefail
experiment=$1 team=$2 work=$3 seed=${4:-1}
min_observable=${E2E_MIN_OBSERVABLE:-0.95}
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "E2E FAIL (mission end, $(basename "$team") seed $seed): $*" >&2
  tail -n 20 "$work/experiment.log" >&2 || true
  exit 1
}

"$experiment" --config "$team" --seeds "$seed" --results "$work/results" --report false > "$work/experiment.log" 2>&1 ||
  fail "hexplore_experiment exited with $?"
summary="$work/results/seed-$seed/summary.json"
[ -f "$summary" ] || fail "no $summary"
value() { sed -n "s/.*\"$1\": *\"\{0,1\}\([^\",}]*\).*/\1/p" "$summary" | head -n 1; }
end=$(value end_reason)
time_s=$(value exploration_time_s)
observable=$(value final_observable_completeness)
collisions=$(grep -o '"collisions": *[0-9]*' "$summary" | awk -F: '{s += $2} END {print s + 0}')
echo "end: '$end' at ${time_s} s sim, observable completeness ${observable}, collisions ${collisions}"
[ "$end" = "no task views remain" ] || fail "mission ended by '$end', not by exhausted task views"
awk -v o="$observable" -v m="$min_observable" 'BEGIN { exit !(o >= m) }' ||
  fail "observable completeness $observable below $min_observable"
[ "$collisions" = 0 ] || fail "$collisions collisions"
