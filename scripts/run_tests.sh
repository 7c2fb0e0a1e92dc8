#!/usr/bin/env bash
# Installs dependencies, builds, and runs the whole test suite (unit, service-level and rig tests).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
./scripts/build.sh
cd "${HEXPLORE_BUILD_DIR:-build}"
ctest --output-on-failure --timeout 600 -j "${HEXPLORE_TEST_JOBS:-2}"
