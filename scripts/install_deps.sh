#!/usr/bin/env bash
# Installs the Debian 12 packages hexplore builds and runs with. Idempotent: installs only
# what is missing, so a second run costs a few seconds.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  protobuf-compiler libprotobuf-dev
  libzmq3-dev cppzmq-dev
  libzstd-dev  # compression of team payloads on the radio (common/transport/compression)
  libeigen3-dev libpcl-dev liboctomap-dev
  prometheus-cpp-dev libyaml-cpp-dev
  libembree-dev libassimp-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  curl python3
  python3-matplotlib  # figures of the planner comparison (tools/report/compare_report.py)
  python3-zmq python3-protobuf  # the Python client (clients/python) and its tests (tests/client)
)
# Tools the rig and observability tests use (docker-compose validates without an engine).
PACKAGES+=(prometheus docker-compose)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install_deps: installing ${missing[*]}"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
