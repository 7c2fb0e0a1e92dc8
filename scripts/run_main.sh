#!/usr/bin/env bash
# The main job: installs the Debian packages, builds, and runs the default heterogeneous team
# (one tracked SLUGCAT, one wheeled MR1000; deploy/teams/default.yaml) exploring the
# single-building scene to completion: every service of every robot is its own process on
# loopback. The station prints progress and writes the results folder when the mission ends
# (no task views remain, or the team file's time limit).
#
# The simulators run at 3x real time (HEXPLORE_RTF): every process keeps up on 2 cores, and the
# default mission runs until no task views remain (stop 37: 3,169 s of sim time, 17.7 minutes of
# wall time; the team file's 5,400 s limit is a safety net).
#
# HEXPLORE_MODE=lockstep runs the same team as one process in the reproducible fast mode instead
# (hexplore_team: every service in lockstep on sim time, as fast as the machine allows; the same
# seed gives the same trajectories and metrics on every run).
#
# Environment: HEXPLORE_TEAM (team file), HEXPLORE_RESULTS (results folder), HEXPLORE_RTF,
# HEXPLORE_MODE (processes, the default, or lockstep).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
./scripts/build.sh
BUILD_DIR=${HEXPLORE_BUILD_DIR:-build}
TEAM=${HEXPLORE_TEAM:-deploy/teams/default.yaml}
RESULTS=${HEXPLORE_RESULTS:-results/$(date -u +%Y%m%d-%H%M%S)}
RTF=${HEXPLORE_RTF:-3}
MODE=${HEXPLORE_MODE:-processes}
mkdir -p "$RESULTS"
case $MODE in
  processes) launch_args=() ;;
  lockstep) launch_args=(--compose) ;;
  *) echo "error: HEXPLORE_MODE must be processes or lockstep, got '$MODE'" >&2; exit 2 ;;
esac

echo "=== hexplore main job ($MODE): team $TEAM; results in $RESULTS (service logs in $RESULTS/logs) ==="
start=$(date +%s)
"$BUILD_DIR/tools/launcher/hexplore_launch" "${launch_args[@]}" --config "$TEAM" --log-dir "$RESULTS/logs" \
  --child-args "--results $RESULTS --real-time-factor $RTF" --exit-on-failure && status=0 || status=$?
echo "=== main job finished in $(( $(date +%s) - start )) s wall time (exit $status); results: $RESULTS ==="
ls "$RESULTS"
exit $status
