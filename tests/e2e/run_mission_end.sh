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
source "$(dirname "$0")/summary_checks.sh"
check_summary "$work/results/seed-$seed/summary.json" mission "$min_observable"
