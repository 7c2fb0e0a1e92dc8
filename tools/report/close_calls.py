#!/usr/bin/env python3
"""Where did two robots come close, and what did their safety layers decide meanwhile? Reads
the safety decision traces of one run (the safety service's --trace-dir: safety-<robot>.jsonl,
a line per decision that changed and per decision while a teammate is within 3 m;
common/safety/decision_trace.h) and prints one block per close call: a stretch of time in which
a robot believed a teammate's centre nearer than --below metres (default 1.3: the MR1000 and
SLUGCAT body radii, 0.61 + 0.54, plus the resolver's 0.1 m hard margin).

Per close call and robot: the decisions (kind and reason, with how many lines each held) and
the moves the driver made that its safety layer did not approve: a move of more than 2 cm
against the direction of the approved path (the body went backwards), or any move of more
than 5 cm while the decision was a stop. Such moves are outside the conflict resolution (the
multi-building contact traced in stop 52: a SLUGCAT backing up to find room to turn, into the MR1000
that was yielding to it; services/sim/README.md).

Standard library only. Usage: close_calls.py TRACE_DIR [--below 1.3] [--robot ID]
"""

import argparse
import collections
import glob
import json
import math
import os
import sys

GAP_S = 1.0          # lines further apart than this start a new close call
BACKWARDS_M = 0.02   # a move this long against the approved direction counts
WHILE_STOPPED_M = 0.05


def read_trace(path):
    """The decision lines of one robot's trace, in time order; broken lines are counted."""
    lines, bad = [], 0
    with open(path) as f:
        for text in f:
            try:
                lines.append(json.loads(text))
            except ValueError:
                bad += 1
    lines.sort(key=lambda d: d["t"])
    return lines, bad


def first_direction(path):
    """Unit direction of the approved path from its start, or None for a stop or a stub."""
    if not path:
        return None
    x0, y0 = path[0]
    for x, y in path[1:]:
        length = math.hypot(x - x0, y - y0)
        if length > 0.05:
            return ((x - x0) / length, (y - y0) / length)
    return None


def unapproved_moves(lines):
    """Moves between consecutive decisions that the earlier decision did not approve."""
    out = []
    for before, after in zip(lines, lines[1:]):
        dx = after["position"][0] - before["position"][0]
        dy = after["position"][1] - before["position"][1]
        moved = math.hypot(dx, dy)
        if before["kind"] == "stop":
            if moved > WHILE_STOPPED_M:
                out.append((after["t"], f"moved {moved:.2f} m while stopped ({before['reason']})"))
            continue
        direction = first_direction(before["path"])
        if direction and dx * direction[0] + dy * direction[1] < -BACKWARDS_M:
            out.append((after["t"], f"moved {moved:.2f} m against its approved path"))
    return out


def close_calls(traces, below):
    """Stretches [t0, t1] per robot pair in which either robot believed the other nearer than
    `below`, with the nearest distance believed; sorted by start."""
    found = collections.defaultdict(list)  # (robot, peer) sorted -> [(t, distance)]
    for robot, lines in traces.items():
        for d in lines:
            for peer in d.get("peers", []):
                if peer["distance"] < below:
                    found[tuple(sorted((robot, peer["id"])))].append((d["t"], peer["distance"]))
    calls = []  # [pair, t0, t1, nearest]
    for pair, events in found.items():
        events.sort()
        for t, distance in events:
            if calls and calls[-1][0] == pair and t - calls[-1][2] <= GAP_S:
                calls[-1][2] = t
                calls[-1][3] = min(calls[-1][3], distance)
            else:
                calls.append([pair, t, t, distance])
    return sorted(calls, key=lambda c: c[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("trace_dir")
    parser.add_argument("--below", type=float, default=1.3, help="centre distance of a close call (m)")
    parser.add_argument("--robot", help="only close calls this robot is in")
    args = parser.parse_args()

    paths = sorted(glob.glob(os.path.join(args.trace_dir, "safety-*.jsonl")))
    if not paths:
        sys.exit(f"close_calls: no safety-*.jsonl in {args.trace_dir} (run with --trace-dir)")
    traces, bad = {}, 0
    for path in paths:
        robot = os.path.basename(path)[len("safety-"):-len(".jsonl")]
        traces[robot], broken = read_trace(path)
        bad += broken
    if args.robot and args.robot not in traces:
        sys.exit(f"close_calls: no robot '{args.robot}' in {args.trace_dir} (robots: {', '.join(sorted(traces))})")

    calls = [c for c in close_calls(traces, args.below) if not args.robot or args.robot in c[0]]
    print(f"{len(calls)} close call(s) below {args.below:.2f} m in {args.trace_dir}" +
          (f" ({bad} unreadable line(s) skipped)" if bad else ""))
    for (a, b), t0, t1, nearest in calls:
        print(f"\n{t0:.1f}-{t1:.1f} s: {a} and {b}, nearest {nearest:.2f} m")
        for robot in (a, b):
            lines = [d for d in traces.get(robot, []) if t0 - GAP_S <= d["t"] <= t1 + GAP_S]
            decisions = collections.Counter(f"{d['kind']}: {d['reason'] or 'free'}" for d in lines)
            print(f"  {robot}: " + "; ".join(f"{what} x{n}" for what, n in decisions.most_common()))
            for t, what in unapproved_moves(lines):
                print(f"    {t:.2f} s {what}")


if __name__ == "__main__":
    main()
