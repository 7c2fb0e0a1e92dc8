#!/usr/bin/env python3
"""How long was each robot held by a teammate on another storey? Reads one run's traces (the
services' --trace-dir: safety-<robot>.jsonl, a line per safety decision that changed and per
decision while a teammate is within 3 m, common/safety/decision_trace.h; planning-<robot>.jsonl,
a line per planning round with the robot's 3D position) and sums, per robot and teammate, the
time from a decision that held the robot back because of that teammate to the next decision,
while the two stood --apart metres or more apart in height (default 2: a storey, see
SafetyOptions::level_separation_m).

A decision holds the robot back because of a teammate when its reason or whom it waits for names
the teammate (yield to, blocked by, too close to, giving way to), or when it is a detour and the
teammate is the nearest stationary one it lists. Heights come from the planning rounds (the last
round at or before the decision), as the safety trace keeps only x and y. Written for stop 60:
before, a SLUGCAT on B3's second storey drove round a teammate idle on the ground floor beneath it.

Standard library only. Usage: cross_level_holds.py TRACE_DIR [--apart 2.0]
"""

import argparse
import bisect
import collections
import glob
import json
import os
import re
import sys


def read_lines(path, skipped):
    rows = []
    with open(path) as f:
        for text in f:
            try:
                rows.append(json.loads(text))
            except json.JSONDecodeError:
                skipped[0] += 1
    return rows


class Heights:
    """Each robot's height over time, from its planning rounds."""

    def __init__(self, root, skipped):
        self.times, self.z = {}, {}
        for path in glob.glob(os.path.join(root, "planning-*.jsonl")):
            robot = os.path.basename(path)[len("planning-"):-len(".jsonl")]
            rows = sorted((r["t"], r["position"][2]) for r in read_lines(path, skipped) if "position" in r)
            self.times[robot] = [t for t, _ in rows]
            self.z[robot] = [z for _, z in rows]

    def at(self, robot, t):
        times = self.times.get(robot)
        if not times:
            return None
        return self.z[robot][max(0, bisect.bisect_right(times, t) - 1)]


def held_by(decision, robots, me):
    """The teammates a decision held `me` back for, and why."""
    text = decision.get("reason", "") + " " + decision.get("yielding_to", "")
    named = [r for r in robots if r != me and re.search(r"\b" + re.escape(r) + r"\b", text)]
    if named:
        return named, re.sub(r"\s*\(.*\)", "", decision.get("reason", "") or "waits").strip()
    if decision.get("detoured"):
        stopped = [p for p in decision.get("peers", []) if p.get("stationary")]
        if stopped:
            return [min(stopped, key=lambda p: p.get("distance", 0.0))["id"]], "detour"
    return [], ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("trace_dir")
    parser.add_argument("--apart", type=float, default=2.0, help="height apart that counts as another storey (m)")
    args = parser.parse_args()
    skipped = [0]
    safety = sorted(glob.glob(os.path.join(args.trace_dir, "safety-*.jsonl")))
    heights = Heights(args.trace_dir, skipped)
    if not safety or not heights.times:
        sys.exit(f"cross_level_holds: {args.trace_dir} needs safety-*.jsonl and planning-*.jsonl (--trace-dir of a run)")
    robots = sorted(heights.times)
    for path in safety:
        me = os.path.basename(path)[len("safety-"):-len(".jsonl")]
        decisions = sorted(read_lines(path, skipped), key=lambda d: d.get("t", 0.0))
        held = collections.Counter()
        for decision, after in zip(decisions, decisions[1:]):
            teammates, why = held_by(decision, robots, me)
            for other in teammates:
                mine, theirs = heights.at(me, decision["t"]), heights.at(other, decision["t"])
                if mine is not None and theirs is not None and abs(mine - theirs) >= args.apart:
                    held[(other, why)] += after["t"] - decision["t"]
        detail = ", ".join(f"{other} ({why}) {s:.1f} s" for (other, why), s in held.most_common())
        print(f"{me}: {sum(held.values()):.1f} s held by a teammate on another storey" + (f": {detail}" if detail else ""))
    if skipped[0]:
        print(f"({skipped[0]} unreadable line(s) skipped)")


if __name__ == "__main__":
    main()
