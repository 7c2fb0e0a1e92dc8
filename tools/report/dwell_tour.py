#!/usr/bin/env python3
"""How far a robot drove against how far the spots it looked from lie apart.

A facade look is a dwell: the robot stands still while its sensor observes (the MR1000 for
10 s). Reads one run's trajectories.csv (a pose per robot when it moves, every 2 s at least)
and prints per robot:

- driven: the metres between consecutive poses;
- dwells: the places it stood still for at least --still-s (8 s unless told), in time order;
- visit-order tour: straight lines from the start through the dwell spots in the order it
  visited them (driven / this = the detour of its paths and the views it passed without a dwell);
- best tour: the shortest open tour from the start through the same spots, straight lines
  (nearest neighbour, then 2-opt): what the order of the looks cost (visit-order / best);
- the time of its last dwell.

Straight lines cut through buildings, so both tours are lower bounds of a drive; their ratio
still says how much of the driving the order of the looks made (common/planning/README.md, "The
last tenth of a point"). With --segments, the metres driven and the straight distance between
consecutive dwells. Standard library only.

Usage: dwell_tour.py RESULTS_RUN_DIR [--robot ID] [--still-s 8] [--segments]
"""

import argparse
import csv
import math
import os
import sys

STILL_M = 0.05  # poses nearer than this to the first of a run are the same place


def read_poses(path):
    """robot -> [(t, x, y)] in file order."""
    poses = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            try:
                poses.setdefault(row["robot"], []).append(
                    (float(row["sim_time_s"]), float(row["x_m"]), float(row["y_m"])))
            except (KeyError, ValueError):
                continue
    return poses


def dwell_spots(poses, still_s):
    """(x, y, t_start) of each run of poses within STILL_M of its first that lasts >= still_s."""
    spots, i = [], 0
    while i < len(poses) - 1:
        j = i
        while j + 1 < len(poses) and math.hypot(poses[j + 1][1] - poses[i][1], poses[j + 1][2] - poses[i][2]) < STILL_M:
            j += 1
        if poses[j][0] - poses[i][0] >= still_s:
            spots.append((poses[i][1], poses[i][2], poses[i][0]))
            i = j
        i += 1
    return spots


def dist(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def path_length(points):
    return sum(dist(points[k], points[k + 1]) for k in range(len(points) - 1))


def best_open_tour(points):
    """Order of points (points[0] first, fixed) for a short open tour: nearest neighbour, 2-opt."""
    n = len(points)
    order, left = [0], set(range(1, n))
    while left:
        k = min(left, key=lambda j: (dist(points[order[-1]], points[j]), j))
        order.append(k)
        left.remove(k)
    improved = True
    while improved:
        improved = False
        for i in range(1, n - 1):
            for j in range(i + 1, n):
                a, b, c = points[order[i - 1]], points[order[i]], points[order[j]]
                after = points[order[j + 1]] if j + 1 < n else None
                old = dist(a, b) + (dist(c, after) if after else 0.0)
                new = dist(a, c) + (dist(b, after) if after else 0.0)
                if new < old - 1e-9:
                    order[i:j + 1] = reversed(order[i:j + 1])
                    improved = True
    return order


def robot_row(robot, poses, still_s):
    spots = dwell_spots(poses, still_s)
    driven = path_length([(p[1], p[2]) for p in poses])
    points = [(poses[0][1], poses[0][2])] + [(x, y) for x, y, _ in spots]
    visit = path_length(points)
    best = path_length([points[k] for k in best_open_tour(points)])
    last = f"{spots[-1][2]:.0f}" if spots else "-"
    return (f"| {robot} | {driven:.0f} | {len(spots)} | {visit:.0f} | {best:.0f} | "
            f"{driven / visit if visit > 0 else float('nan'):.2f} | {visit / best if best > 0 else float('nan'):.2f} | "
            f"{last} / {poses[-1][0]:.0f} |"), spots


def segments(poses, spots):
    marks = [poses[0][0]] + [t for _, _, t in spots] + [poses[-1][0]]
    out = []
    for a, b in zip(marks, marks[1:]):
        seg = [p for p in poses if a <= p[0] <= b]
        if len(seg) < 2:
            continue
        out.append(f"  {a:6.0f}-{b:6.0f} s: driven {path_length([(p[1], p[2]) for p in seg]):5.0f} m, straight "
                   f"{dist(seg[0][1:], seg[-1][1:]):5.0f} m, ({seg[0][1]:.0f}, {seg[0][2]:.0f}) -> "
                   f"({seg[-1][1]:.0f}, {seg[-1][2]:.0f})")
    return out


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("--robot")
    parser.add_argument("--still-s", type=float, default=8.0)
    parser.add_argument("--segments", action="store_true")
    args = parser.parse_args(argv[1:])
    path = os.path.join(args.run, "trajectories.csv")
    if not os.path.isfile(path):
        sys.exit(f"dwell_tour.py: {path}: no such file (give a run's results folder)")
    poses = read_poses(path)
    robots = [args.robot] if args.robot else sorted(poses)
    if args.robot and args.robot not in poses:
        sys.exit(f"dwell_tour.py: no robot '{args.robot}' in {path} (robots: {', '.join(sorted(poses))})")
    print(f"{args.run}: dwells of at least {args.still_s:g} s")
    print("| robot | driven (m) | dwells | visit-order tour (m) | best tour (m) | driven / visit | visit / best | "
          "last dwell / end (s) |")
    print("|---|---|---|---|---|---|---|---|")
    details = []
    for robot in robots:
        if len(poses[robot]) < 2:
            continue
        row, spots = robot_row(robot, poses[robot], args.still_s)
        print(row)
        if args.segments:
            details += [f"{robot}:"] + segments(poses[robot], spots)
    for line in details:
        print(line)


if __name__ == "__main__":
    main(sys.argv)
