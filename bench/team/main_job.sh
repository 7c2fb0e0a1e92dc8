#!/usr/bin/env bash
# Benchmark of the main job: runs the default team (deploy/teams/default.yaml) once and prints
# the figures issue 7 asks for: wall time, sim time to completion and how it ended,
# completeness reached, team bytes per second per robot, and mean/max single-round planning time.
#
#   bench/team/main_job.sh [processes|lockstep] [RESULTS_DIR]
#
# processes (default): every service its own process, as ./scripts/run_main.sh runs it (sims at
# HEXPLORE_RTF, default 3x real time). lockstep: the whole team in one process on sim time
# (hexplore_team), as fast as the machine allows and the same on every run.
# Expects a build in $HEXPLORE_BUILD_DIR (default build); run ./scripts/build.sh first.
set -euo pipefail
cd "$(dirname "$0")/../.."
mode=${1:-processes}
results=${2:-$(mktemp -d /tmp/hexplore-main-job.XXXXXX)}
build=${HEXPLORE_BUILD_DIR:-build}
team=${HEXPLORE_TEAM:-deploy/teams/default.yaml}
rtf=${HEXPLORE_RTF:-3}
robots=$(sed -n 's/^  - id: *\([A-Za-z0-9_-]*\).*/\1/p' "$team")

mkdir -p "$results"
start=$(date +%s.%N)
case $mode in
  processes)
    "$build/tools/launcher/hexplore_launch" --config "$team" --log-dir "$results/logs" \
      --child-args "--results $results --real-time-factor $rtf" --exit-on-failure > "$results/launch.log" 2>&1 ;;
  lockstep)
    robot_args=()
    for r in $robots; do robot_args+=(--robot "$r"); done
    "$build/tools/team/hexplore_team" --config "$team" "${robot_args[@]}" --results "$results" \
      --metrics-port 0 --log-level warn > "$results/launch.log" 2>&1 ;;
  *) echo "usage: $0 [processes|lockstep] [RESULTS_DIR]" >&2; exit 2 ;;
esac
end=$(date +%s.%N)

python3 - "$results/summary.json" "$mode" "$start" "$end" "$(nproc)" <<'PY'
import json, sys
path, mode, cores = sys.argv[1], sys.argv[2], sys.argv[5]
wall = float(sys.argv[4]) - float(sys.argv[3])
s = json.load(open(path))
t = s["exploration_time_s"]
print(f"main job ({mode}, {s['scene']}, planner {s['planner']}, seed {s['seed']}, {cores} cores)")
print(f"  wall time            {wall:8.1f} s (mission {s['wall_time_s']:.1f} s, the rest is start-up and shutdown)")
print(f"  sim time             {t:8.1f} s, ended by: {s['end_reason']}")
print(f"  completeness         {100 * s['final_completeness']:8.1f} % team, "
      f"{100 * s['final_observable_completeness']:.1f} % of what is observable")
for robot, r in sorted(s["robots"].items()):
    kb = sum(r["communication_kb"].values())
    print(f"  {robot:<12} {r['species']:<8} {kb / t:6.2f} KB/s team traffic, {r['trajectory_length_m']:.1f} m, "
          f"{r['collisions']} collisions")
print(f"  team traffic         {s['team_kb_per_s']:8.2f} KB/s")
p = s["planning_time_s"]
print(f"  planning round       {p['mean']:8.3f} s mean, {p['max']:.3f} s max over {p['rounds']} rounds")
PY
echo "  results              $results"
