#!/usr/bin/env python3
"""Where a mission's late work comes from: the coverage targets that gained a task view between
consecutive open-target reports, by what they were before.

Reads a results folder's open_targets.csv written with periodic reports
(`--open-targets-period-s P`; one row per open target per robot per report, with its state:
has_view, given_up, no_viewpoint, occluded, unreachable, unassignable). For each report after
--since, a target with a view that had none in the previous report is an arrival:

- from_<state>: it was open in the previous report without a view (occluded, unreachable, ...);
- reopened: absent from the previous report (complete then) but open in some earlier one;
- new: never reported before (a surface first seen, or first incomplete);
- new_where_given_up: new, but within --near-m of a target of the same class and facing that
  an earlier report had as given up and that has since gone from the reports. Supervoxel keys
  are the smallest seed key of a group of merged seeds (highlevel/segmenter.cc, regroup), so a
  group that gains or loses a seed can come back under another key, and the team's give-up
  ledger, kept by key, no longer knows it. An upper bound: the old target may also have been
  completed, and the new one be its neighbour.

Prints one line per report (views open, arrivals by origin), then the totals with the median of
open voxels (voxels - covered_voxels) and how many are facade targets. Standard library only.

Usage: target_arrivals.py OPEN_TARGETS.csv --robot ID [--since SECONDS] [--near-m 1.0]
"""

import argparse
import collections
import csv
import math

CLASS_SHIFT = 60  # supervoxel keys: facing in bits 60-62, facade bit 63 (highlevel/supervoxel.h)


def position(row):
    return (float(row["x_m"]), float(row["y_m"]), float(row["z_m"]))


def near_a_gone_give_up(key, row, gone_given_up, near_m):
    """Whether a target given up earlier, now gone from the reports, of the same class and
    facing as `key`, lay within near_m of it."""
    here = position(row)
    return any(k >> CLASS_SHIFT == key >> CLASS_SHIFT and math.dist(here, p) <= near_m
               for k, p in gone_given_up.items())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("open_targets")
    ap.add_argument("--robot", required=True, help="whose reports to read (every robot reports the fused map)")
    ap.add_argument("--since", type=float, default=0.0, help="first report time counted (s)")
    ap.add_argument("--near-m", type=float, default=1.0,
                    help="how near a new target must lie to a gone given-up one to count as it (m)")
    args = ap.parse_args()

    reports = collections.OrderedDict()
    with open(args.open_targets) as f:
        for row in csv.DictReader(f):
            if row["robot"] == args.robot:
                reports.setdefault(float(row["sim_time_s"]), {})[int(row["key"])] = row
    if len(reports) < 2:
        raise SystemExit(f"{args.open_targets}: fewer than two reports of {args.robot} "
                         "(run with --open-targets-period-s)")

    seen = set()
    given_up = {}  # key -> position, of every target some report had as given up
    previous = None
    totals = collections.Counter()
    open_voxels = collections.defaultdict(list)
    facade = collections.Counter()
    for t, current in reports.items():
        gone_given_up = {k: p for k, p in given_up.items() if k not in current}
        if previous is not None and t > args.since:
            counts = collections.Counter()
            for key, row in current.items():
                if row["state"] != "has_view":
                    continue
                if key in previous and previous[key]["state"] == "has_view":
                    continue
                if key in previous:
                    origin = "from_" + previous[key]["state"]
                elif key in seen:
                    origin = "reopened"
                elif near_a_gone_give_up(key, row, gone_given_up, args.near_m):
                    origin = "new_where_given_up"
                else:
                    origin = "new"
                counts[origin] += 1
                open_voxels[origin].append(int(row["voxels"]) - int(row["covered_voxels"]))
                facade[origin] += row["facade"] == "1"
            totals.update(counts)
            views = sum(1 for r in current.values() if r["state"] == "has_view")
            detail = ", ".join(f"{k} {v}" for k, v in sorted(counts.items()))
            print(f"{t:8.0f} s  views {views:5d}  arrivals {sum(counts.values()):4d}  {detail}")
        seen |= set(current)
        given_up.update({k: position(r) for k, r in current.items() if r["state"] == "given_up"})
        previous = current

    print(f"\narrivals after {args.since:.0f} s: {sum(totals.values())}")
    for origin, n in totals.most_common():
        v = sorted(open_voxels[origin])
        print(f"  {origin:24s} {n:5d}  median open voxels {v[len(v) // 2]:4d}  facade {facade[origin]}")


if __name__ == "__main__":
    main()
