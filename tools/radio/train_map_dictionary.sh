#!/bin/bash
# Trains the zstd dictionary of map payloads on the radio (common/radio/dictionaries/map.zdict)
# from the map increments of two short lockstep missions on the tuning scenes (small-building
# and office; never the evaluation scenes), and prints how much it saves on them.
#
# Usage: tools/radio/train_map_dictionary.sh [BUILD_DIR] [OUT]   (defaults: build, the tree's file)
# (SECONDS_PER_MISSION=S in the environment samples S sim seconds per scene instead of 300.)
# Needs the zstd command (Debian package zstd). After retraining, bump the dictionary id below
# and hexplore.v1.SCHEMA_VERSION_CURRENT: robots with different dictionaries cannot read each
# other's maps (they refuse the frames and count them malformed), and the schema check says why.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
OUT=${2:-common/radio/dictionaries/map.zdict}
DICTIONARY_ID=1752694785  # "hx" 0x6878 << 16 | 1: the first map dictionary
SECONDS_PER_MISSION=${SECONDS_PER_MISSION:-300}  # sim seconds sampled per scene

command -v zstd > /dev/null || { echo "needs zstd (apt-get install zstd)" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
mkdir -p "$WORK/samples"
for team in small-building office; do
  echo "sampling ${SECONDS_PER_MISSION} s of $team ..."
  HEXPLORE_PAYLOAD_SAMPLES="$WORK/samples" "$BUILD/tools/experiment/hexplore_experiment" \
    --config "deploy/teams/$team.yaml" --seeds 1 --time-limit-s "$SECONDS_PER_MISSION" \
    --results "$WORK/results-$team" --report false > "$WORK/$team.log" 2>&1
done
increments=("$WORK"/samples/hexplore.v1.MapIncrement-*.bin)
echo "training on ${#increments[@]} map increments"
zstd -q -f --train -19 --maxdict=32768 --dictID="$DICTIONARY_ID" "${increments[@]}" -o "$OUT"
# What it saves on its own training set, as the transport compresses (level 19, payloads of
# 96 bytes or more); the evaluation scenes' figure is in README.md, "The team radio".
plain=0; with=0
for f in "${increments[@]}"; do
  n=$(stat -c %s "$f")
  if (( n < 96 )); then plain=$((plain + n)); with=$((with + n)); continue; fi
  p=$(zstd -q -19 -c "$f" | wc -c); d=$(zstd -q -19 -D "$OUT" -c "$f" | wc -c)
  plain=$((plain + (p < n ? p : n))); with=$((with + (d < n ? d : n)))
done
echo "wrote $OUT ($(stat -c %s "$OUT") bytes): increments $plain -> $with bytes compressed"
