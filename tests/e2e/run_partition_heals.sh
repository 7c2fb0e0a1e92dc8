#!/usr/bin/env bash
# A partition heals: the small-building team in lockstep, its MR1000 cut off from the radio
# (transport.radio.outages) from 20 to 80 s of a 140 s mission. While cut off, its teammates'
# map increments do not reach it and its own do not reach them; after it, the sequence gaps must
# be detected and repaired: within 3 eta_c (3 s) of the heal every robot holds exactly what the
# other sent (its copy's digest equal to the one sent with the last increment; summary.json
# robots.<id>.map_sync.out_of_sync.<peer>.last_resynced_s), and at the end every robot must
# have applied every teammate's increments (increments_behind at most 1, the one a status may
# catch in flight; the outage leaves about 60 behind when nothing repairs it).
#   run_partition_heals.sh EXPERIMENT TEAM_FILE WORKDIR
# E2E_OUTAGE_TO_S (default 80) moves the end of the outage: 140 or later never heals, and the
# check must fail (how this test was checked).
set -euo pipefail
experiment=$1 team=$2 work=$3
outage_to=${E2E_OUTAGE_TO_S:-80}
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "E2E FAIL (partition heals): $*" >&2
  tail -n 20 "$work/experiment.log" >&2 || true
  exit 1
}

# The team file with the outage and a short mission (the scene and robots as they are).
grep -q '^time_limit_s:' "$team" || fail "$team has no time_limit_s line to replace"
grep -q '^  base_port:' "$team" || fail "$team has no transport.base_port line to add the radio after"
sed -e 's/^time_limit_s:.*/time_limit_s: 140/' \
    -e "s/^\(  base_port:.*\)/\1\n  radio:\n    outages: [{robot: mr1000a, from_s: 20, to_s: $outage_to}]/" \
    -e '/^  curve_keys_dir:/d' "$team" > "$work/team.yaml"

"$experiment" --config "$work/team.yaml" --seeds 1 --results "$work/results" --report false > "$work/experiment.log" 2>&1 ||
  fail "hexplore_experiment exited with $?"
python3 - "$work/results/seed-1/summary.json" "$outage_to" <<'PY' || fail "see above"
import json, sys
robots = json.load(open(sys.argv[1]))["robots"]
heal_s = float(sys.argv[2])
ok = True
def check(condition, message):
    global ok
    print(("ok   " if condition else "FAIL ") + message)
    ok &= condition
cut = robots["mr1000a"]
check(cut["radio_drops"]["out_of_range"] > 0,
      f"the outage cut mr1000a off: {cut['radio_drops']['out_of_range']:.0f} messages out of range")
for robot, r in robots.items():
    sync = r["map_sync"]
    # Repairs also count the snapshot each hlmap asks for when it starts.
    check(0 < sync["gaps_detected"] <= sync["gaps_repaired"],
          f"{robot}: {sync['gaps_detected']:.0f} sequence gaps detected, {sync['gaps_repaired']:.0f} repaired")
    for source, behind in sync["increments_behind"].items():
        check(behind is not None and behind <= 1, f"{robot} applied {source}'s increments: {behind} behind at the end")
    # Every copy of a teammate's contribution is compared with the digest the teammate sent;
    # within 3 eta_c (3 s) of the heal each robot holds exactly what the other sent.
    check(sync["digests_checked"] > 0 and sync["digest_mismatches"] == 0,
          f"{robot}: {sync['digests_checked']:.0f} digests compared, {sync['digest_mismatches']:.0f} differed")
    for source, stretch in sync["out_of_sync"].items():
        resynced = stretch["last_resynced_s"]
        check(resynced is not None and heal_s <= resynced <= heal_s + 3.0,
              f"{robot} holds {source}'s contribution (digest equal) again at {resynced} s, the heal at {heal_s:.0f} s "
              f"(at most 3 s later)")
sys.exit(0 if ok else 1)
PY
