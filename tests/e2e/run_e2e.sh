#!/usr/bin/env bash
# One end-to-end case: a SLUGCAT and an MR1000 explore the generated yard-and-room scene
# (make_scene.sh) through the launcher (every service its own process), and the results
# folder's summary.json must show the stated completeness and no collision.
#   run_e2e.sh CASE LAUNCHER STATION WORKDIR BASE_PORT [EXPERIMENT]
# CASE: explore (plain run), switch (planner switched to no-mnss mid-run via the station's
# --send), kill (every service of mr1000a killed mid-run; slugcat1 must finish the work),
# lockstep (the one-process fast mode through the launcher, then the same seed again through
# hexplore_experiment with two CPU hogs beside it: the trajectories, completeness and
# communication records must be byte-identical, and the experiment writes its summary),
# baselines (the comparison command: hexplore_experiment --planners with the paper's three
# comparison planners, two at a time as child processes; each mission must run out of task
# views without collision, and the comparison report must be written).
set -euo pipefail
case=$1 launch=$2 station=$3 work=$4 port=$5 experiment=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
min_observable=${E2E_MIN_OBSERVABLE:-0.70}
rm -rf "$work"
mkdir -p "$work"
bash "$here/make_scene.sh" "$work/yard_room.obj"
cat > "$work/team.yaml" <<YAML
scene: yard_room.obj
time_limit_s: 900
exploration_region:
  min: [-3.0, -3.0, -0.5]
  max: [13.0, 9.0, 3.0]
metrics_base_port: 0
species:
  - builtin: SLUGCAT
  - builtin: MR1000
robots:
  - id: slugcat1
    species: SLUGCAT
    start: [0.0, 0.0, 0.0]
    yaw_deg: 90
  - id: mr1000a
    species: MR1000
    start: [2.0, 0.0, 0.0]
    yaw_deg: 90
transport:
  scheme: tcp
  base_port: $port
  # Authenticated links, as the deploy/teams files: the launcher makes the keys in $work/keys.
  curve_keys_dir: keys
params:
  seed: 1
  # As in deploy/teams: the simulated LiDARs fire at 2 Hz, a fifth of the paper's point rate.
  rho_th: 0.06
  min_ise_patch_voxels: 5
YAML

fail() {
  echo "E2E FAIL ($case): $*" >&2
  echo "--- launch.log (tail)" >&2
  tail -n 30 "$work/launch.log" >&2 || true
  exit 1
}

# check_summary SUMMARY WHAT MIN_OBSERVABLE
source "$here/summary_checks.sh"

if [ "$case" = baselines ]; then
  [ -n "$experiment" ] || fail "no hexplore_experiment given"
  "$experiment" --config "$work/team.yaml" --seeds 1 --planners mdvrp+,mromt+,tspga+ --jobs 2 \
    --results "$work/compare" --trace-dir "$work/traces" > "$work/compare.log" 2>&1 \
    || { tail -n 30 "$work/compare.log"; fail "the comparison failed"; }
  for planner in mdvrp+ mromt+ tspga+; do
    check_summary "$work/compare/$planner/seed-1/summary.json" "$planner" "$min_observable"
    # Each planner's rounds in its own trace folder (side by side they once shared one).
    for trace in "$work/traces/$planner/seed-1/planning-slugcat1.jsonl" "$work/traces/$planner/seed-1/planning-mr1000a.jsonl"; do
      [ -s "$trace" ] || fail "no planning trace $trace"
      others=$(grep -vc "\"planner\": \"$planner\"" "$trace" || true)
      [ "$others" = 0 ] || fail "$trace holds $others rounds of another planner (or broken lines)"
    done
  done
  [ -s "$work/compare/comparison.md" ] || fail "no comparison report"
  rows=$(tail -n +2 "$work/compare/comparison.csv" | cut -d, -f1 | tr '\n' ' ')
  [ "$rows" = "mdvrp+ mromt+ tspga+ " ] || fail "comparison.csv rows are '$rows'"
  cat "$work/compare/comparison.md"
  echo "E2E PASS ($case)"
  exit 0
fi

mode=()
[ "$case" = lockstep ] && mode=(--compose)
"$launch" "${mode[@]}" --config "$work/team.yaml" --log-dir "$work/logs" \
  --child-args "--results $work/results --log-level debug --real-time-factor ${E2E_RTF:-3}" > "$work/launch.log" 2>&1 &
launcher=$!
cleanup() { kill "$launcher" 2>/dev/null || true; }
trap cleanup EXIT

# Sim time of the station's latest progress line (0 before the first one).
sim_time() { { grep -o 't= *[0-9.]*s' "$work/launch.log" || true; } | tail -n 1 | tr -dc '0-9.' ; }
wait_sim_time() {
  local target=$1
  for _ in $(seq 1 600); do
    kill -0 "$launcher" 2>/dev/null || return 0
    local t
    t=$(sim_time)
    if [ -n "$t" ] && awk -v t="$t" -v g="$target" 'BEGIN { exit !(t >= g) }'; then return 0; fi
    sleep 0.5
  done
}

case $case in
  explore | lockstep) ;;
  switch)
    wait_sim_time 20
    "$station" --config "$work/team.yaml" --send planner=no-mnss || fail "could not send the planner switch"
    ;;
  kill)
    wait_sim_time 20
    pids=$(sed -n 's/^\[launch\] started mr1000a\/[a-z]* (pid \([0-9]*\)).*/\1/p' "$work/launch.log")
    [ -n "$pids" ] || fail "no mr1000a process found in the launch log"
    for pid in $pids; do kill -KILL "$pid" 2>/dev/null || true; done
    echo "killed mr1000a's services: $pids"
    ;;
  *) fail "unknown case" ;;
esac

wait "$launcher" || true
trap - EXIT
cat "$work/results/summary.json"
check_summary "$work/results/summary.json" "$case" "$min_observable"
case $case in
  switch)
    grep -q "planner switched from hexplore to no-mnss" "$work/logs/slugcat1-planning.log" ||
      fail "slugcat1's planner did not switch"
    grep -q "planner switched from hexplore to no-mnss" "$work/logs/mr1000a-planning.log" ||
      fail "mr1000a's planner did not switch"
    ;;
  kill)
    # The survivor planned for itself alone after the loss, and went on to cover more.
    grep -q "1 live" "$work/logs/slugcat1-planning.log" || fail "slugcat1 never planned without mr1000a"
    ;;
  lockstep)
    hogs=()
    for _ in 1 2; do yes > /dev/null & hogs+=($!); done
    "$experiment" --config "$work/team.yaml" --seeds 1 --results "$work/experiment" > "$work/experiment.log" 2>&1 ||
      { kill "${hogs[@]}"; tail -n 20 "$work/experiment.log"; fail "hexplore_experiment failed"; }
    kill "${hogs[@]}"
    for f in trajectories.csv completeness.csv communication.csv; do
      cmp "$work/results/$f" "$work/experiment/seed-1/$f" || fail "$f differs between two lockstep runs of seed 1"
    done
    grep -q '"seeds": \[1\]' "$work/experiment/summary.json" || fail "no experiment summary for seed 1"
    echo "two lockstep runs (the second beside two CPU hogs) recorded identical trajectories, completeness and traffic"
    ;;
esac
echo "E2E PASS ($case)"
