#!/usr/bin/env bash
# Runs every fuzz harness of tests/fuzz with libFuzzer and prints, per harness, the executions,
# executions per second, the corpus it grew and whether it crashed.
#
#   scripts/fuzz.sh [SECONDS_PER_HARNESS=20] [HARNESS ...]   # a search: random, for a while
#   scripts/fuzz.sh --ci [HARNESS ...]                       # what CI runs: a short, bounded search
#
# --ci runs each harness for a fixed number of inputs from a fixed seed (3-4 s each on an idle
# 2-core machine, 42 s for all twelve; the clang build before it about 3 minutes). It is meant to
# catch a regression near the seeds, not to hunt: a long random search in CI would make landing
# a matter of luck. It is not bit-for-bit the same search every time (two identical runs here
# grew the corpora by a few percent more or less, pointer hashes and reductions differ), so a
# rare input could still turn up; longer searches are for people, with the first form.
#
# Builds the "fuzz" preset (clang, ASan + UBSan, build-fuzz/; installs clang when missing).
# Each harness starts from its seed corpus (tests/fuzz/corpus/<name>, copied: the tree's
# corpus is not changed) plus its regressions; a crash leaves its input in
# build-fuzz/crashes/<name>/, and the script exits 1. To keep a fixed crash fixed, copy that
# input into tests/fuzz/regressions/<name>/ (ctest replays it in every build).
set -euo pipefail
cd "$(dirname "$0")/.."
ci=0
if [ "${1:-}" = --ci ]; then
  ci=1
  shift
fi
seconds=20
if [ $ci -eq 0 ] && [[ "${1:-}" =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(envelope scan voxel_delta map_update team_solution path_fragment pose mission_command requests
             team_yaml tsplib mesh)
fi
# Inputs per harness in --ci mode: a few seconds each at the rates measured on a 2-core machine
# (tests/fuzz/README.md).
declare -A ci_runs=([envelope]=600000 [scan]=400 [voxel_delta]=15000 [map_update]=150000
                    [team_solution]=400000 [path_fragment]=400000 [pose]=500000
                    [mission_command]=500000 [requests]=500000 [team_yaml]=15000 [tsplib]=150000
                    [mesh]=500)

# clang, and its sanitizer and libFuzzer runtimes (only recommended by clang on Debian 12).
missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=$([ "$(id -u)" -eq 0 ] && echo "" || echo sudo)
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
scripts/install_deps.sh >/dev/null
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)" | grep -E "error:|FAILED" || true
[ -x build-fuzz/tests/fuzz/fuzz_envelope ] || { echo "fuzz: the harnesses did not build" >&2; exit 1; }

printf '| harness | seconds | executions | executions/s | corpus (seeds -> after) | crashed |\n|---|---|---|---|---|---|\n'
failed=0
for name in "${harnesses[@]}"; do
  work=build-fuzz/corpus/$name
  crashes=build-fuzz/crashes/$name
  rm -rf "$work"
  mkdir -p "$work" "$crashes"
  cp tests/fuzz/corpus/"$name"/* "$work"/
  [ -d tests/fuzz/regressions/"$name" ] && cp tests/fuzz/regressions/"$name"/* "$work"/
  seeds=$(ls "$work" | wc -l)
  log=build-fuzz/fuzz-$name.log
  if [ $ci -eq 1 ]; then
    budget=(-seed=1 -runs="${ci_runs[$name]}")
  else
    budget=(-max_total_time="$seconds")
  fi
  # Debian's libassimp 5.2 leaks in its STL importer's error path (a few KB per broken file,
  # inside assimp, freed by no caller); a scene is loaded once per process, so leaks are not
  # what this harness looks for. Crashes and undefined behaviour still stop it.
  leaks=1
  [ "$name" = mesh ] && leaks=0
  status=no
  start=$(date +%s)
  if ! ASAN_OPTIONS="detect_leaks=$leaks" build-fuzz/tests/fuzz/fuzz_"$name" "$work" "${budget[@]}" \
       -print_final_stats=1 -timeout=10 -rss_limit_mb=2048 -detect_leaks=$leaks -artifact_prefix="$crashes/" \
       >"$log" 2>&1; then
    status="YES: $(ls -t "$crashes" | head -1) (log $log)"
    failed=1
  fi
  took=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo 0)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo 0)
  printf '| %s | %s | %s | %s | %s -> %s | %s |\n' "$name" "$took" "$execs" "$rate" "$seeds" "$(ls "$work" | wc -l)" "$status"
done
exit $failed
