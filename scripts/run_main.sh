#!/usr/bin/env bash
# The main job: installs the Debian packages, builds, and runs the richest thing that exists.
# The team exploration demo does not exist yet; until it does, this runs the transport
# benchmark and a short two-process demo of the service base (two robots exchanging team
# messages over tcp, with their /metrics scraped).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
./scripts/build.sh
BUILD_DIR=${HEXPLORE_BUILD_DIR:-build}

echo "=== hexplore main job: the team exploration demo is not there yet; running the transport benchmark and a two-process demo ==="

echo "--- transport benchmark (two processes, tcp loopback) ---"
"$BUILD_DIR/bench/transport/transport_bench" --count 1000000 --latency-seconds 5

echo "--- two-process demo: robots slugcat1 and mr1000a (deploy/teams/default.yaml) ---"
LOG_DIR=$(mktemp -d)
ECHO="$BUILD_DIR/tests/service/echo_service"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT
for robot in slugcat1 mr1000a; do
  "$ECHO" --config deploy/teams/default.yaml --robot "$robot" --kind hlmap --metrics-port -1 \
    >"$LOG_DIR/$robot.log" 2>&1 &
  pids+=($!)
done
port=""
for _ in $(seq 1 100); do
  port=$(sed -n 's/.*serving \/metrics on port \([0-9]*\).*/\1/p' "$LOG_DIR/slugcat1.log" | head -1)
  [ -n "$port" ] && break
  sleep 0.1
done
if [ -z "$port" ]; then
  echo "demo: slugcat1 did not start:"; cat "$LOG_DIR/slugcat1.log"; exit 1
fi
sleep 3
echo "demo: team/echo traffic of slugcat1 after 3 s (from http://127.0.0.1:$port/metrics):"
curl -s "http://127.0.0.1:$port/metrics" | grep -E '^hexplore_(transport_(sent|received)_messages_total|process_uptime_seconds).*' \
  | grep -E 'team/echo|uptime' || true
cleanup
trap - EXIT
echo "demo: both services stopped on SIGTERM; logs:"
cat "$LOG_DIR"/*.log
rm -rf "$LOG_DIR"
echo "=== done (team exploration demo not there yet) ==="
