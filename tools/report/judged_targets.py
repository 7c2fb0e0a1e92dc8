#!/usr/bin/env python3
"""What do the robots' observations achieve? Reads the planning traces of one run (the planning
service's --trace-dir, one planning-<robot>.jsonl line per round, whose "judged" list has every
target the route follower judged a settle time after observing it) and prints per robot: how
many targets were judged and how many were complete by then, the open ones by coverage gap, and
the distance, incidence and elevation from the observing spot (10th, 50th and 90th percentile)
of the complete and of the open ones. Lines that are not JSON are skipped and counted.

Standard library only. Usage: judged_targets.py TRACE_DIR
"""
import collections
import glob
import json
import os
import sys


def percentiles(values):
    values = sorted(values)
    if not values:
        return "-"
    pick = lambda q: values[int(q * (len(values) - 1))]
    return f"{pick(0.1):.1f} / {pick(0.5):.1f} / {pick(0.9):.1f}"


def read_judged(path):
    judged, bad = [], 0
    with open(path) as f:
        for line in f:
            try:
                judged += json.loads(line).get("judged", [])
            except (ValueError, AttributeError):
                bad += 1
    return judged, bad


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    paths = sorted(glob.glob(os.path.join(argv[1], "planning-*.jsonl")))
    if not paths:
        sys.exit(f"no planning-*.jsonl in {argv[1]}")
    for path in paths:
        robot = os.path.basename(path)[len("planning-"):-len(".jsonl")]
        judged, bad = read_judged(path)
        complete = [j for j in judged if j.get("complete")]
        still_open = [j for j in judged if not j.get("complete")]
        share = 100.0 * len(complete) / len(judged) if judged else 0.0
        print(f"{robot}: {len(judged)} judged, {len(complete)} complete ({share:.0f} %)"
              + (f", {bad} unreadable lines" if bad else ""))
        gaps = collections.Counter(j.get("gap", "?") for j in still_open)
        print("  open by gap: " + (", ".join(f"{g} {n}" for g, n in gaps.most_common()) or "-"))
        for name, group in (("complete", complete), ("open", still_open)):
            print(f"  {name:8s} distance m {percentiles([j['distance_m'] for j in group])}"
                  f"  incidence deg {percentiles([j['incidence_deg'] for j in group])}"
                  f"  elevation deg {percentiles([j['elevation_deg'] for j in group])}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
