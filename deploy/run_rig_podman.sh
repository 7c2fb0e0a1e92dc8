#!/usr/bin/env bash
# Brings compose.yaml up for real with podman and podman-compose (no daemon), checks that the rig
# works, and takes it down again:
#   1. the one-shot `keys` container makes the team's CURVE key pairs and exits 0;
#   2. every robot's five service containers come up and pass their healthcheck;
#   3. the station (and Prometheus, from Debian's package: deploy/podman/) come up healthy;
#   4. the station's team completeness is above zero and rises while the team explores;
#   5. Prometheus scrapes every service of the team and the station ("up").
# Needs root, podman, podman-compose and runc (apt-get install podman podman-compose runc), and
# the services image localhost/hexplore/services:latest, built without a registry by
#   sudo STORAGE_DRIVER=overlay deploy/build_image_offline.sh
# (the same storage driver as here). Not part of CI: it takes minutes and a container engine.
#
# usage: sudo deploy/run_rig_podman.sh [--seconds N] [--no-prometheus] [--keep]
#   --seconds N      how long the team explores between the two completeness readings (default 60)
#   --no-prometheus  leave Prometheus out (and so check 5)
#   --keep           leave the rig running (take it down with the podman-compose line it prints)
# env: STORAGE_DRIVER (default overlay), HEXPLORE_RIG_WORK (logs, default /tmp/hexplore-rig).
#
# Why the containers.conf below: on the machine this was written on (a Firecracker VM whose root
# lacks CAP_SYS_RESOURCE) podman's default container limits (nofile 1048576, nproc unlimited) are
# refused with "setrlimit: Operation not permitted", and crun refuses the hybrid cgroup v1/v2
# layout ("cgroups in hybrid mode not supported"); runc and limits within the machine's run.
set -euo pipefail
export STORAGE_DRIVER=${STORAGE_DRIVER:-overlay}

root=$(cd "$(dirname "$0")/.." && pwd)
work=${HEXPLORE_RIG_WORK:-/tmp/hexplore-rig}
seconds=60
prometheus=1
keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=${2:?--seconds needs a number}; shift ;;
    --no-prometheus) prometheus=0 ;;
    --keep) keep=1 ;;
    *) echo "run_rig_podman: unknown argument '$1' (see the header of $0)" >&2; exit 64 ;;
  esac
  shift
done
for tool in podman podman-compose runc python3; do
  command -v "$tool" >/dev/null || { echo "run_rig_podman: $tool is missing (apt-get install podman podman-compose runc)" >&2; exit 69; }
done
[ "$(id -u)" -eq 0 ] || { echo "run_rig_podman: run as root (rootful podman, bridge network)" >&2; exit 77; }
mkdir -p "$work"

fail() { echo "FAIL $*" >&2; exit 1; }
ok() { echo "ok   $*"; }

# Container settings for every podman call below, podman-compose's included.
nofile=$(ulimit -Hn)
[ "$nofile" = unlimited ] && nofile=1048576
cat > "$work/containers.conf" <<EOF
[containers]
default_ulimits = ["nofile=$nofile:$nofile", "nproc=4096:4096"]

[engine]
runtime = "runc"
EOF
export CONTAINERS_CONF="$work/containers.conf"

image=localhost/hexplore/services:latest
podman image exists "$image" || fail "no image $image in $STORAGE_DRIVER storage: build it with
  sudo STORAGE_DRIVER=$STORAGE_DRIVER deploy/build_image_offline.sh"
# compose.yaml names the image hexplore/services; give it that name so no registry is asked.
podman tag "$image" docker.io/hexplore/services:latest

project=hexplore-rig
pc=(podman-compose -p "$project" -f "$root/compose.yaml" -f "$root/deploy/podman/compose.podman.yaml")
# podman-compose 1.0's container names; the station has its own (compose.yaml: container_name).
container() { if [ "$1" = station ]; then echo station-station; else echo "${project}_$1_1"; fi; }
echo "run_rig_podman: take it down by hand with: CONTAINERS_CONF=$CONTAINERS_CONF ${pc[*]} down -v"

if [ "$prometheus" -eq 1 ]; then
  # Layers are cached: after the first build this takes a second.
  echo "run_rig_podman: Prometheus from Debian's package (deploy/podman/prometheus.Containerfile)"
  podman build --pull=never -q -t localhost/hexplore/prometheus-debian:latest \
    -f "$root/deploy/podman/prometheus.Containerfile" "$root/deploy/podman" > "$work/prometheus-build.log" 2>&1 \
    || fail "Prometheus image build, see $work/prometheus-build.log"
fi

"${pc[@]}" down -v > "$work/down-before.log" 2>&1 || true
if [ "$keep" -eq 0 ]; then trap '"${pc[@]}" down -v > "$work/down.log" 2>&1 || true' EXIT; fi

# Start each step only after the one before is done: podman-compose 1.0 starts dependencies in
# order but does not wait for `service_healthy` or `service_completed_successfully`.
start=$(date +%s)
"${pc[@]}" up -d --no-build keys > "$work/up-keys.log" 2>&1 || fail "podman-compose up keys, see $work/up-keys.log"
code=$(podman wait "$(container keys)")
podman logs "$(container keys)" > "$work/keys.log" 2>&1 || true
[ "$code" = 0 ] || fail "the keys container exited $code: $(tail -n 3 "$work/keys.log")"
ok "keys: the team's key pairs are made ($(tail -n 1 "$work/keys.log"))"

robots=$(python3 - "$root/compose.yaml" <<'PY'
import re, sys
names = re.findall(r"^  ([a-z0-9]+)-(?:sim|mapping|hlmap|planning|safety):", open(sys.argv[1]).read(), re.M)
print(" ".join(dict.fromkeys(names)))
PY
)
services=()
for r in $robots; do for s in sim mapping hlmap planning safety; do services+=("$r-$s"); done; done
"${pc[@]}" up -d --no-build "${services[@]}" > "$work/up-team.log" 2>&1 || fail "podman-compose up (team), see $work/up-team.log"

# Healthy: the container's own healthcheck (hexplore-healthcheck: its metrics exposer answers).
wait_healthy() {
  local deadline=$(( $(date +%s) + $1 )); shift
  local pending=("$@") still
  while [ ${#pending[@]} -gt 0 ] && [ "$(date +%s)" -lt "$deadline" ]; do
    still=()
    for s in "${pending[@]}"; do podman healthcheck run "$(container "$s")" > /dev/null 2>&1 || still+=("$s"); done
    pending=("${still[@]+"${still[@]}"}")
    [ ${#pending[@]} -gt 0 ] && sleep 2
  done
  [ ${#pending[@]} -eq 0 ] || { for s in "${pending[@]}"; do podman logs --tail 5 "$(container "$s")" > "$work/$s.log" 2>&1 || true; done
                                  fail "not healthy: ${pending[*]} (last lines in $work/<service>.log)"; }
}
wait_healthy 180 "${services[@]}"
ok "team: ${#services[@]} service containers of $(echo $robots | wc -w) robots healthy after $(( $(date +%s) - start )) s"

last=(station)
[ "$prometheus" -eq 1 ] && last+=(prometheus)
"${pc[@]}" up -d --no-build "${last[@]}" > "$work/up-station.log" 2>&1 || fail "podman-compose up (${last[*]}), see $work/up-station.log"
wait_healthy 120 "${last[@]}"
ok "${last[*]} healthy"

# The station's team completeness, read inside its container (bash /dev/tcp, as the healthcheck).
completeness() {
  podman exec "$(container station)" bash -c 'exec 3<>/dev/tcp/127.0.0.1/$HEXPLORE_METRICS_PORT;
    printf "GET /metrics HTTP/1.0\r\n\r\n" >&3; cat <&3' 2>/dev/null \
    | sed -n 's/^hexplore_station_completeness_ratio{[^}]*scope="team"[^}]*} \([0-9.e+-]*\).*/\1/p' | head -n 1
}
sleep 10
first=$(completeness); first=${first:-0}
sleep "$seconds"
second=$(completeness); second=${second:-0}
python3 -c "import sys; a, b = map(float, sys.argv[1:]); sys.exit(0 if 0 < a < b else 1)" "$first" "$second" \
  || fail "team completeness did not rise: $first, then $second after $seconds s"
ok "mission: team completeness $first, $seconds s later $second"

if [ "$prometheus" -eq 1 ]; then
  expected=$(( ${#services[@]} + 1 ))
  for _ in $(seq 20); do
    up=$(podman exec "$(container prometheus)" bash -c 'exec 3<>/dev/tcp/127.0.0.1/9090;
      printf "GET /api/v1/targets?state=active HTTP/1.0\r\n\r\n" >&3; cat <&3' 2>/dev/null \
      | grep -o '"health":"up"' | wc -l)
    [ "$up" -ge "$expected" ] && break
    sleep 3
  done
  [ "$up" -ge "$expected" ] || fail "Prometheus has $up of $expected targets up"
  ok "Prometheus scrapes all $up targets"
fi

podman ps --filter "name=${project}_" --format '{{.Names}} {{.Status}}' > "$work/containers.txt"
ok "$(wc -l < "$work/containers.txt") containers running; the whole check took $(( $(date +%s) - start )) s (list in $work/containers.txt)"
