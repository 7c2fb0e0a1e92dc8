#!/usr/bin/env python3
"""How steady are the plans of a mission? Reads the planning traces of one run (the planning
service's --trace-dir, one planning-<robot>.jsonl line per round) and, when given, the run's
results folder (open_targets.csv), and prints per robot:

- rounds, replanning reasons and the mean time between rounds;
- route-head jumps: how far the first view of a round's route lies from the first view of the
  round before (a robot that keeps its plan shows short jumps; one whose plan is rebuilt every
  round is pulled back and forth between distant views), for the planner's route and, where the
  trace has it (follower.next), for the view the robot heads to after the follower merged it;
- reference flips: rounds whose reference solution came from another robot than the round before;
- open-target flows between consecutive open-target reports: targets that left "has_view" (and
  to what: complete, given_up, ...) and targets that came into it from another open state, which
  keeps the number of views flat while the team works;
- with --area X0,Y0,X1,Y1: when the robot's routes held views inside that box and how far back
  in the route (why a part of the site is never visited: no view there, or views only at the
  tail of a long route).

Standard library only. Usage: route_churn.py TRACE_DIR [RESULTS_SEED_DIR] [--jump-m 5] [--area X0,Y0,X1,Y1]
"""

import collections
import csv
import glob
import json
import math
import os
import sys


def load_rounds(path):
    rounds = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                rounds.append(json.loads(line))
            except json.JSONDecodeError as e:
                print(f"{path}:{number}: skipped, not JSON ({e})", file=sys.stderr)
    return rounds


def percentile(values, q):
    if not values:
        return float("nan")
    s = sorted(values)
    return s[min(len(s) - 1, int(round(q * (len(s) - 1))))]


def jump_line(label, heads, jump_m):
    jumps = [math.dist(a[:2], b[:2]) for a, b in zip(heads, heads[1:])]
    if not jumps:
        return
    far = sum(1 for j in jumps if j > jump_m)
    print(f"   {label} jump (m): median {percentile(jumps, 0.5):.1f}, p90 {percentile(jumps, 0.9):.1f}, "
          f"max {max(jumps):.1f}; {far} of {len(jumps)} rounds ({100.0 * far / len(jumps):.0f} %) "
          f"moved it more than {jump_m:g} m")


def route_report(robot, rounds, jump_m):
    times = [r["t"] for r in rounds]
    gaps = [b - a for a, b in zip(times, times[1:])]
    refs = [r.get("reference", "") for r in rounds]
    flips = sum(1 for a, b in zip(refs, refs[1:]) if a and b and a != b)
    reasons = collections.Counter(r.get("reason", "?") for r in rounds)
    print(f"== {robot}: {len(rounds)} rounds, mean {sum(gaps) / len(gaps) if gaps else float('nan'):.1f} s apart")
    print("   reasons: " + ", ".join(f"{k} {v}" for k, v in reasons.most_common()))
    jump_line("route-head", [r["route"][0]["p"] for r in rounds if r.get("route")], jump_m)
    jump_line("heading (follower)", [r["follower"]["next"][0] for r in rounds if r.get("follower", {}).get("next")],
              jump_m)
    if len(refs) > 1:
        print(f"   reference from another robot than the round before: {flips} of {len(refs) - 1} rounds")


def parse_area(text):
    try:
        x0, y0, x1, y1 = (float(v) for v in text.split(","))
    except ValueError:
        raise SystemExit(f"--area: expected X0,Y0,X1,Y1 (four numbers), got '{text}'")
    return min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)


def area_report(rounds, area):
    x0, y0, x1, y1 = area
    inside = lambda p: x0 <= p[0] <= x1 and y0 <= p[1] <= y1
    held = []  # (t, views inside, position of the first one, route length)
    for r in rounds:
        route = r.get("route", [])
        where = [i for i, v in enumerate(route) if inside(v["p"])]
        if where:
            held.append((r["t"], len(where), where[0], len(route)))
    label = f"area x {x0:g}..{x1:g}, y {y0:g}..{y1:g}"
    if not held:
        print(f"   {label}: in no round's route")
        return
    firsts = [h[2] for h in held]
    print(f"   {label}: in {len(held)} of {len(rounds)} rounds' routes, first at {held[0][0]:.1f} s; "
          f"views there {min(h[1] for h in held)}-{max(h[1] for h in held)}, the first of them at route position "
          f"median {percentile(firsts, 0.5):.0f} (min {min(firsts)}, max {max(firsts)}) of "
          f"{min(h[3] for h in held)}-{max(h[3] for h in held)}")


def flow_report(results_dir):
    path = os.path.join(results_dir, "open_targets.csv")
    if not os.path.exists(path):
        print(f"(no {path}: open-target flows skipped)")
        return
    reports = collections.defaultdict(lambda: collections.defaultdict(dict))
    with open(path) as f:
        for row in csv.DictReader(f):
            reports[row["robot"]][float(row["sim_time_s"])][row["key"]] = row["state"]
    for robot in sorted(reports):
        times = sorted(reports[robot])
        print(f"== {robot}: open-target flows between {len(times)} reports")
        for a, b in zip(times, times[1:]):
            before, after = reports[robot][a], reports[robot][b]
            out = collections.Counter(after.get(k, "complete") for k, s in before.items()
                                      if s == "has_view" and after.get(k) != "has_view")
            came = collections.Counter(before[k] for k, s in after.items()
                                       if s == "has_view" and k in before and before[k] != "has_view")
            fresh = sum(1 for k, s in after.items() if s == "has_view" and k not in before)
            has_view = sum(1 for s in after.values() if s == "has_view")
            print(f"   {a:7.1f} -> {b:7.1f} s: has_view {has_view:5d} | left {sum(out.values()):4d} "
                  f"({', '.join(f'{k} {v}' for k, v in out.most_common())}) | came back {sum(came.values()):4d} "
                  f"({', '.join(f'{k} {v}' for k, v in came.most_common())}) | new {fresh:4d}")


def main(argv):
    args = list(argv[1:])
    jump_m = 5.0
    area = None
    for flag in ("--jump-m", "--area"):
        if flag in args:
            i = args.index(flag)
            if i + 1 >= len(args):
                print(f"{flag}: missing value", file=sys.stderr)
                return 2
            value = args[i + 1]
            del args[i:i + 2]
            if flag == "--jump-m":
                jump_m = float(value)
            else:
                area = parse_area(value)
    if not args or len(args) > 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    traces = sorted(glob.glob(os.path.join(args[0], "planning-*.jsonl")))
    if not traces:
        print(f"no planning-*.jsonl in {args[0]}", file=sys.stderr)
        return 1
    for path in traces:
        robot = os.path.basename(path)[len("planning-"):-len(".jsonl")]
        rounds = load_rounds(path)
        if rounds:
            route_report(robot, rounds, jump_m)
            if area:
                area_report(rounds, area)
    if len(args) == 2:
        flow_report(args[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
