#!/usr/bin/env python3
"""Where each robot's mission time went: moving, observing (dwelling at facade views), and
standing otherwise (idle with no route, waiting, yielding, blocked).

A mission ends when the last view is done, so the robot that is never idle bounds it: on the
default team the MR1000 moves or observes for 89-99 % of every run under every planner, and its
metres driven explain most of the spread in exploration time (common/planning/README.md, "What
bounds the default mission").

Reads one run's results folder (trajectories.csv: a pose per robot when it moves, every 2 s at
least) and, when given, its planning-trace folder (the experiment's --trace-dir; the last
round's follower counters give the time spent observing). Moving time: the sum of the intervals
between consecutive poses more than 5 cm apart (poses are up to 2 s apart, so a share can pass
100 % by the start of a dwell counted as moving). Prints one Markdown row per robot.

Standard library only. Usage: robot_time.py RESULTS_RUN_DIR [TRACE_RUN_DIR]
  e.g. robot_time.py results/hexplore/seed-1 traces/hexplore/seed-1
"""
import csv
import json
import math
import os
import sys

MOVED_M = 0.05  # two poses this far apart: the robot moved in between


def moving_time(results_dir):
    """Per robot: (seconds moving, metres driven, last pose time)."""
    last, out = {}, {}
    with open(os.path.join(results_dir, "trajectories.csv")) as f:
        for row in csv.DictReader(f):
            robot, t = row["robot"], float(row["sim_time_s"])
            p = (float(row["x_m"]), float(row["y_m"]), float(row["z_m"]))
            moving, metres, _ = out.get(robot, (0.0, 0.0, 0.0))
            if robot in last:
                t0, p0 = last[robot]
                step = math.dist(p0, p)
                if step > MOVED_M:
                    moving += t - t0
                    metres += step
            last[robot] = (t, p)
            out[robot] = (moving, metres, t)
    return out


def observing_time(trace_dir, robot):
    """The follower's observing seconds in the robot's last planning round, or None."""
    path = os.path.join(trace_dir, f"planning-{robot}.jsonl")
    if not os.path.exists(path):
        return None
    last = None
    with open(path) as f:
        for line in f:
            try:
                last = json.loads(line)
            except ValueError:
                continue
    return None if last is None else last.get("follower", {}).get("observing_s")


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    results_dir = argv[1]
    trace_dir = argv[2] if len(argv) == 3 else None
    for name in ("summary.json", "trajectories.csv"):
        if not os.path.exists(os.path.join(results_dir, name)):
            sys.exit(f"robot_time: no {name} in {results_dir} (a run's results folder, e.g. RESULTS/hexplore/seed-1)")
    with open(os.path.join(results_dir, "summary.json")) as f:
        mission_s = float(json.load(f)["exploration_time_s"])
    print(f"mission {mission_s:.1f} s ({results_dir})")
    print("| robot | moving (s) | driven (m) | observing (s) | moving + observing | standing otherwise (s) |")
    print("|---|---|---|---|---|---|")
    for robot, (moving, metres, _) in sorted(moving_time(results_dir).items()):
        observing = observing_time(trace_dir, robot) if trace_dir else None
        busy = moving + (observing or 0.0)
        obs = "-" if observing is None else f"{observing:.0f}"
        print(f"| {robot} | {moving:.0f} | {metres:.0f} | {obs} | {100 * busy / mission_s:.0f} % |"
              f" {max(0.0, mission_s - busy):.0f} |")


if __name__ == "__main__":
    main(sys.argv)
