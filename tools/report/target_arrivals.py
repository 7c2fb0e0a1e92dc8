#!/usr/bin/env python3
"""Where a mission's late work comes from: the coverage targets that gained a task view between
consecutive open-target reports, by what they were before.

Reads a results folder's open_targets.csv written with periodic reports
(`--open-targets-period-s P`; one row per open target per robot per report, with its state:
has_view, given_up, no_viewpoint, occluded, unreachable, unassignable). For each report after
--since, a target with a view that had none in the previous report is an arrival:

- from_<state>: it was open in the previous report without a view (occluded, unreachable, ...);
- reopened: absent from the previous report (complete then) but open in some earlier one;
- new: never reported before (a surface first seen, or first incomplete).

Prints one line per report (views open, arrivals by origin), then the totals with the median of
open voxels (voxels - covered_voxels) and how many are facade targets. Standard library only.

Usage: target_arrivals.py OPEN_TARGETS.csv --robot ID [--since SECONDS]
"""

import argparse
import collections
import csv


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("open_targets")
    ap.add_argument("--robot", required=True, help="whose reports to read (every robot reports the fused map)")
    ap.add_argument("--since", type=float, default=0.0, help="first report time counted (s)")
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
    previous = None
    totals = collections.Counter()
    open_voxels = collections.defaultdict(list)
    facade = collections.Counter()
    for t, current in reports.items():
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
        previous = current

    print(f"\narrivals after {args.since:.0f} s: {sum(totals.values())}")
    for origin, n in totals.most_common():
        v = sorted(open_voxels[origin])
        print(f"  {origin:24s} {n:5d}  median open voxels {v[len(v) // 2]:4d}  facade {facade[origin]}")


if __name__ == "__main__":
    main()
