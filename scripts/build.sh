#!/usr/bin/env bash
# Configures and builds hexplore into ./build (Release-with-debug-info, Ninja, both cores).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${HEXPLORE_BUILD_DIR:-build}
JOBS=${HEXPLORE_JOBS:-$(nproc)}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"
