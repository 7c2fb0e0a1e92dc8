#!/usr/bin/env python3
"""Does the plan know when the mission ends? Reads the planning traces of one run (the
experiment's --trace-dir for one seed: planning-<robot>.jsonl, one line per round) and compares
what the team solution prices the open work at (`cost_s_per_robot`: seconds of driving and
observation per robot, the largest of them is the plan's time to the end) with the time that
was actually left (the last round's time minus the round's).

Prints, every --every seconds, the views open, the planned time to the end and the time left;
then, for each threshold, the first time the plan fell below it and how long the mission went on.
A plan that falls far short of the time left means work kept arriving that no plan held (new,
reopened or newly visible surfaces: tools/report/target_arrivals.py says which).

Only for planners whose team solution holds all open work (hexplore and its ablations, MDVRP+,
TSPGA+); MROMT+ prices only the views it matched this round. Lines that are not JSON (a run
stopped mid-line) are skipped. Standard library only.

Usage: plan_horizon.py TRACE_DIR [--every 200] [--thresholds 1000,400,200]
"""

import argparse
import glob
import json
import os


def read_rounds(trace_dir):
    rounds = []
    for path in sorted(glob.glob(os.path.join(trace_dir, "planning-*.jsonl"))):
        with open(path) as f:
            for line in f:
                try:
                    r = json.loads(line)
                except json.JSONDecodeError:
                    continue
                if r.get("cost_s_per_robot"):
                    rounds.append(r)
    if not rounds:
        raise SystemExit(f"{trace_dir}: no planning rounds with a team solution (planning-*.jsonl)")
    rounds.sort(key=lambda r: r["t"])
    return rounds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("trace_dir")
    ap.add_argument("--every", type=float, default=200.0, help="sample period (s)")
    ap.add_argument("--thresholds", default="1000,400,200", help="planned times to report (s)")
    args = ap.parse_args()

    rounds = read_rounds(args.trace_dir)
    end = rounds[-1]["t"]
    print("| t (s) | views open | planned to the end (s) | actually left (s) |")
    print("|---|---|---|---|")
    t = args.every
    while t < end:
        r = min(rounds, key=lambda x: abs(x["t"] - t))
        print(f"| {r['t']:.0f} | {r['open_views']} | {max(r['cost_s_per_robot']):.0f} | {end - r['t']:.0f} |")
        t += args.every
    print()
    for threshold in (float(x) for x in args.thresholds.split(",")):
        # Skip the first rounds: before the map holds much, the plan is short because little is known.
        first = next((r for r in rounds if r["t"] > args.every and max(r["cost_s_per_robot"]) < threshold), None)
        if first is None:
            print(f"plan under {threshold:.0f} s: never")
        else:
            print(f"plan under {threshold:.0f} s first at {first['t']:.0f} s; the mission went on {end - first['t']:.0f} s "
                  f"(end {end:.0f} s)")


if __name__ == "__main__":
    main()
