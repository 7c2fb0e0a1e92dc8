#!/usr/bin/env bash
# Builds the services image (deploy/Dockerfile) without a Docker engine and without a registry:
# buildah (chroot isolation, vfs storage) on a Debian 12 base made locally by debootstrap from
# the apt mirror. Then runs the image's executables once and prints its size. For machines
# that reach a Debian mirror but no container registry; needs root, buildah and debootstrap
# (apt-get install buildah debootstrap). Not part of CI.
#
# usage: sudo deploy/build_image_offline.sh [--keep-base | --check-only] [--team-check] [--export FILE.tar]
#   --keep-base      reuse docker.io/library/debian:12 if this machine already has it
#   --check-only     build nothing: only run the checks below on the image built before
#   --team-check     also run a two-robot team and the station from the image on loopback (host
#                    network, as chroot isolation has it): every healthcheck must pass and the
#                    station must measure completeness
#   --export FILE    also write the image as a docker-archive (docker load -i FILE)
# env: HEXPLORE_MIRROR (default: the first Debian URI of /etc/apt/sources*), HEXPLORE_JOBS
#      (compile jobs, default nproc), HEXPLORE_IMAGE (default localhost/hexplore/services:latest),
#      HEXPLORE_WORK (scratch folder, default /tmp/hexplore-image), STORAGE_DRIVER (containers
#      storage, default vfs, which works everywhere; overlay where the kernel allows it, as
#      deploy/run_rig_podman.sh wants: vfs copies the whole image for each of its 22 containers).
set -euo pipefail
export STORAGE_DRIVER=${STORAGE_DRIVER:-vfs}

root=$(cd "$(dirname "$0")/.." && pwd)
work=${HEXPLORE_WORK:-/tmp/hexplore-image}
image=${HEXPLORE_IMAGE:-localhost/hexplore/services:latest}
jobs=${HEXPLORE_JOBS:-$(nproc)}
keep_base=0
check_only=0
team_check=0
export_to=""
while [ $# -gt 0 ]; do
  case "$1" in
    --keep-base) keep_base=1 ;;
    --team-check) team_check=1 ;;
    --check-only) check_only=1 ;;
    --export) export_to=${2:?--export needs a file name}; shift ;;
    *) echo "build_image_offline: unknown argument '$1' (see the header of $0)" >&2; exit 64 ;;
  esac
  shift
done
for tool in buildah debootstrap git python3; do
  command -v "$tool" >/dev/null || { echo "build_image_offline: $tool is missing (apt-get install buildah debootstrap)" >&2; exit 69; }
done
[ "$(id -u)" -eq 0 ] || { echo "build_image_offline: run as root (debootstrap, buildah chroot isolation)" >&2; exit 77; }

mirror=${HEXPLORE_MIRROR:-$(cat /etc/apt/sources.list /etc/apt/sources.list.d/* 2>/dev/null \
  | grep -oE '^(URIs:|deb) +https?://[^ ]+/debian/?( |$)' | grep -oE 'https?://[^ ]+' | head -n 1 || true)}
mirror=${mirror:-http://deb.debian.org/debian}
mkdir -p "$work"

# ---- 1. the base image the Dockerfile names: debian:12 and debian:12-slim, from debootstrap
if [ "$check_only" -eq 1 ]; then
  echo "build_image_offline: checking $image as built before"
elif [ "$keep_base" -eq 1 ] && buildah inspect --type image docker.io/library/debian:12 >/dev/null 2>&1; then
  echo "build_image_offline: reusing docker.io/library/debian:12"
else
  echo "build_image_offline: debootstrap bookworm from $mirror"
  rm -rf "$work/rootfs"
  debootstrap --variant=minbase bookworm "$work/rootfs" "$mirror" > "$work/debootstrap.log" 2>&1 \
    || { echo "build_image_offline: debootstrap failed, see $work/debootstrap.log" >&2; exit 1; }
  rm -rf "$work"/rootfs/var/cache/apt/archives/*.deb "$work"/rootfs/var/lib/apt/lists/*
  security=${mirror%/debian}/debian-security
  printf 'deb %s bookworm main\ndeb %s bookworm-updates main\ndeb %s bookworm-security main\n' \
    "$mirror" "$mirror" "$security" > "$work/rootfs/etc/apt/sources.list"
  tar -C "$work/rootfs" -cf "$work/rootfs.tar" .
  base=$(buildah from scratch)
  buildah add "$base" "$work/rootfs.tar" / >/dev/null
  buildah config --cmd /bin/bash --env PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "$base"
  buildah commit -q "$base" docker.io/library/debian:12 >/dev/null
  buildah rm "$base" >/dev/null
  # The runtime stage's debian:12-slim: the same minimal system (minbase has no docs to strip).
  buildah tag docker.io/library/debian:12 docker.io/library/debian:12-slim
  rm -rf "$work/rootfs" "$work/rootfs.tar"
fi

# ---- 2. the image, from the committed tree (what a reviewer sees, not work in progress)
if [ "$check_only" -eq 0 ]; then
  rm -rf "$work/context" && mkdir -p "$work/context"
  git -C "$root" archive HEAD | tar -x -C "$work/context"
  echo "build_image_offline: building $image from $(git -C "$root" rev-parse --short HEAD) with $jobs jobs"
  start=$(date +%s)
  buildah bud --isolation chroot --pull-never --format docker --layers=false \
    --build-arg HEXPLORE_JOBS="$jobs" -f deploy/Dockerfile -t "$image" "$work/context"
  echo "build_image_offline: built in $(( $(date +%s) - start )) s"
fi

# ---- 3. the executables start inside the image
check=$(buildah from --pull-never "$image")
trap 'buildah rm "$check" >/dev/null 2>&1 || true' EXIT
for s in sim mapping hlmap planning safety station; do
  # No arguments: each prints its usage and exits 2, which proves every library loads.
  out=$(buildah run --isolation chroot "$check" -- "hexplore_$s" 2>&1 || true)
  case "$out" in
    *usage:*) echo "ok   hexplore_$s loads its libraries and prints its usage" ;;
    *) echo "FAIL hexplore_$s: $out" >&2; exit 1 ;;
  esac
done
out=$(buildah run --isolation chroot --env HEXPLORE_SERVICE=station --env HEXPLORE_CONFIG=/etc/hostname "$check" \
  -- hexplore-entrypoint 2>&1) && { echo "FAIL the station accepted /etc/hostname as a team file" >&2; exit 1; }
echo "ok   station with a bad team file: ${out%%$'\n'*}"
echo "ok   runs as $(buildah run --isolation chroot "$check" -- id -un), teams: $(buildah run --isolation chroot "$check" -- ls /etc/hexplore/teams | tr '\n' ' ')"

# ---- 4. optionally, the team itself: every service of two robots plus the station
if [ "$team_check" -eq 1 ]; then
  team="$work/team-check"
  rm -rf "$team" && mkdir -p "$team"
  # The loopback team and its ports, exactly as the live observability test makes them.
  python3 - "$root/tests/rig" "$team" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import live_observability_test as live
base, metrics, _ = live.pick_ports()
open(f"{sys.argv[2]}/team.yaml", "w").write(live.team_yaml(base, metrics))
open(f"{sys.argv[2]}/targets", "w").write("".join(f"{r} {s} {p}\n" for r, s, p in live.targets(metrics)))
PY
  # Each process ends itself (timeout sends SIGTERM), so nothing outlives the check.
  while read -r robot service port; do
    env=(--env "HEXPLORE_SERVICE=$service" --env HEXPLORE_CONFIG=/team/team.yaml)
    [ "$service" = station ] || env+=(--env "HEXPLORE_ROBOT=$robot")
    buildah run --isolation chroot -v "$team:/team:ro" "${env[@]}" "$check" \
      -- timeout 45 hexplore-entrypoint --log-level warn < /dev/null > "$team/$robot-$service.log" 2>&1 &
  done < "$team/targets"
  healthy=0
  for _ in $(seq 30); do
    sleep 1
    healthy=0
    while read -r robot service port; do
      buildah run --isolation chroot --env "HEXPLORE_METRICS_PORT=$port" "$check" -- hexplore-healthcheck \
        < /dev/null > /dev/null 2>&1 && healthy=$((healthy + 1))
    done < "$team/targets"
    [ "$healthy" -eq "$(wc -l < "$team/targets")" ] && break
  done
  echo "team: $healthy of $(wc -l < "$team/targets") services healthy"
  station_port=$(awk '$2 == "station" {print $3}' "$team/targets")
  completeness=$(python3 - "$station_port" <<'PY'
import re, sys, time, urllib.request
for _ in range(30):
    try:
        text = urllib.request.urlopen(f"http://127.0.0.1:{sys.argv[1]}/metrics", timeout=3).read().decode()
    except OSError:
        text = ""
    m = re.search(r'hexplore_station_completeness_ratio\{[^}]*scope="team"[^}]*\} (\S+)', text)
    if m and float(m.group(1)) > 0:
        print(m.group(1))
        break
    time.sleep(1)
else:
    print(0)
PY
)
  wait
  echo "team: the station measured team completeness $completeness; logs in $team"
  if [ "$healthy" -ne "$(wc -l < "$team/targets")" ] || [ "$completeness" = 0 ]; then
    echo "FAIL the team in the image did not come up or explore; see $team/*.log" >&2
    exit 1
  fi
fi

buildah images --format '{{.Name}}:{{.Tag}} {{.Size}}' "$image"
if [ -n "$export_to" ]; then
  rm -f "$export_to"
  buildah push -q "$image" "docker-archive:$export_to:hexplore/services:latest"
  echo "build_image_offline: wrote $export_to ($(du -h "$export_to" | cut -f1)); docker load -i $export_to"
fi
