#!/usr/bin/env python3
"""What each robot did in the tail of a mission: from the moment the team's observable
completeness first reaches a level (97 % unless --level) to the end.

Reads the results folders (completeness.csv, summary.json) and the planning traces (the
experiment's --trace-dir, one planning-<robot>.jsonl line per round) of several runs laid out
as hexplore_experiment writes them, RESULTS/<planner>/seed-N and TRACES/<planner>/seed-N, and
prints one Markdown row per run and robot:

- when the level was reached, the end, and the views the robot's planner had open then;
- after it: metres driven, views reached, metres per view reached, targets judged after a look
  and how many of them were complete, views skipped (blocked or stuck), rounds, and the time its
  route was empty while the mission went on (a robot with nothing to do while a teammate works
  through the last views);
- targets the team gave up after it.

The tail is where the missions' end times differ most (common/planning/README.md, "Where mdvrp+
gains in the tail"); this puts the figures of every run side by side. Standard library only.

Usage: tail_work.py RESULTS_ROOT TRACE_ROOT [--level 0.97] [--planners a,b]
"""

import csv
import glob
import json
import os
import re
import sys


def first_time_at(results_dir, level):
    with open(os.path.join(results_dir, "completeness.csv")) as f:
        for row in csv.DictReader(f):
            if float(row["team_observable"]) >= level:
                return float(row["sim_time_s"])
    return None


def read_rounds(path):
    """The rounds of a trace; a line that is not a round (cut off when the run was stopped) is skipped."""
    rounds = []
    with open(path) as f:
        for line in f:
            try:
                rounds.append(json.loads(line))
            except ValueError:
                continue
    return rounds


def at_or_before(rounds, t):
    """The last round at or before t (the state the robot was in then), else the first one."""
    best = rounds[0]
    for r in rounds:
        if r["t"] <= t:
            best = r
    return best


def empty_route_s(rounds, start, end):
    """Time in [start, end] during which the robot's latest route held no view."""
    idle = 0.0
    for i, r in enumerate(rounds):
        until = rounds[i + 1]["t"] if i + 1 < len(rounds) else end
        a, b = max(r["t"], start), min(until, end)
        if b > a and not r["route"]:
            idle += b - a
    return idle


def tail_of(rounds, start, end):
    before = at_or_before(rounds, start)
    last = rounds[-1]
    f0, f1 = before["follower"], last["follower"]
    driven = last["odometry_m"] - before["odometry_m"]
    reached = f1["reached"] - f0["reached"]
    return {
        "open_views": before["open_views"],
        "driven_m": driven,
        "reached": reached,
        "m_per_view": driven / reached if reached else float("nan"),
        "judged": f1["targets_judged"] - f0["targets_judged"],
        "complete": f1["targets_complete_when_judged"] - f0["targets_complete_when_judged"],
        "skipped": f1["skipped"] - f0["skipped"],
        "rounds": sum(1 for r in rounds if r["t"] > start),
        "idle_s": empty_route_s(rounds, start, end),
        "given_up": last["given_up"] - before["given_up"],
    }


def runs(results_root, trace_root, planners):
    for seed_dir in sorted(glob.glob(os.path.join(results_root, "*", "seed-*"))):
        planner = os.path.basename(os.path.dirname(seed_dir))
        if planners and planner not in planners:
            continue
        traces = os.path.join(trace_root, planner, os.path.basename(seed_dir))
        if os.path.exists(os.path.join(seed_dir, "summary.json")) and glob.glob(os.path.join(traces, "planning-*.jsonl")):
            yield planner, int(re.sub(r"\D", "", os.path.basename(seed_dir))), seed_dir, traces


def main(argv):
    args, level, planners = [], 0.97, None
    it = iter(argv[1:])
    for a in it:
        if a == "--level":
            level = float(next(it))
        elif a == "--planners":
            planners = set(next(it).split(","))
        else:
            args.append(a)
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    print(f"| planner | seed | t({level:.0%}) | end | robot | views open then | driven after | views reached | m per view "
          "| judged (complete) | skipped | rounds | route empty | given up (team) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    found = False
    for planner, seed, results, traces in sorted(runs(args[0], args[1], planners), key=lambda r: (r[0], r[1])):
        found = True
        with open(os.path.join(results, "summary.json")) as f:
            end = float(json.load(f)["exploration_time_s"])
        start = first_time_at(results, level)
        if start is None:
            print(f"| {planner} | {seed} | never | {end:.0f} s | | | | | | | | | | |")
            continue
        for path in sorted(glob.glob(os.path.join(traces, "planning-*.jsonl"))):
            robot = os.path.basename(path)[len("planning-"):-len(".jsonl")]
            rounds = read_rounds(path)
            if not rounds:
                continue
            t = tail_of(rounds, start, end)
            print(f"| {planner} | {seed} | {start:.0f} s | {end:.0f} s | {robot} | {t['open_views']} | {t['driven_m']:.0f} m "
                  f"| {t['reached']} | {t['m_per_view']:.1f} | {t['judged']} ({t['complete']}) | {t['skipped']} "
                  f"| {t['rounds']} | {t['idle_s']:.0f} s | +{t['given_up']} |")
    if not found:
        print(f"no run with both results and traces under {args[0]} and {args[1]}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
