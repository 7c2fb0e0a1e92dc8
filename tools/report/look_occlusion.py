#!/usr/bin/env python3
"""Were the targets a robot looked at hidden from where it stood? For every target a planning
trace judged after a look (the `judged` list of each round, written with --trace-dir), rays go
from the robot's sensor to 27 points of the target's seed cell in the true scene mesh, and the
look is counted by the share of those rays that hit something before the cell (the scene hid
the target from that spot). The planner's own line of sight (OcclusionGrid, over the map's
supervoxels) said the target was visible; this says how often the scene disagreed, and how
often such looks completed their target.

Facade targets only (a ground cell's lower points lie under the ground itself). The scene mesh is the one the mission ran in: `hexplore_scene --scene NAME --seed N --out
FILE.ply` for a built-in scene and the mission's seed. The robot's position is the round's (at
the judgement, the robot is still at or near the spot it looked from). Pure Python (standard
library): about a minute per thousand judged targets on a scene of ten thousand triangles.

Usage: look_occlusion.py TRACE.jsonl SCENE.ply [--sensor-dz 0.9] [--since S] [--list]
"""

import argparse
import collections
import json
import math
import struct

SEED_AXIS_BITS = 20


def load_triangles(path):
    """Triangles of a binary little-endian PLY (the format hexplore_scene writes)."""
    with open(path, "rb") as f:
        vertices = faces = 0
        while True:
            line = f.readline().decode("ascii", "replace").strip()
            if line.startswith("element vertex"):
                vertices = int(line.split()[-1])
            elif line.startswith("element face"):
                faces = int(line.split()[-1])
            elif line == "end_header":
                break
            elif line.startswith("format") and "binary_little_endian" not in line:
                raise SystemExit(f"{path}: only binary little-endian PLY is read ({line})")
        points = [struct.unpack("<3f", f.read(12)) for _ in range(vertices)]
        triangles = []
        for _ in range(faces):
            n = f.read(1)[0]
            index = struct.unpack(f"<{n}I", f.read(4 * n))
            for k in range(1, n - 1):
                triangles.append((points[index[0]], points[index[k]], points[index[k + 1]]))
    return triangles


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def first_hit(triangles, origin, direction, t_max):
    """Distance to the nearest triangle along a unit ray (Moller-Trumbore), or t_max."""
    best = t_max
    for a, b, c in triangles:
        e1, e2 = sub(b, a), sub(c, a)
        p = cross(direction, e2)
        det = dot(e1, p)
        if abs(det) < 1e-12:
            continue
        inv = 1.0 / det
        s = sub(origin, a)
        u = dot(s, p) * inv
        if u < 0.0 or u > 1.0:
            continue
        q = cross(s, e1)
        v = dot(direction, q) * inv
        if v < 0.0 or u + v > 1.0:
            continue
        t = dot(e2, q) * inv
        if 1e-6 < t < best:
            best = t
    return best


def seed_cell(key):
    """The seed cell (1 m grid) and facing of a supervoxel key (common/highlevel/supervoxel.h)."""
    mask, offset = (1 << SEED_AXIS_BITS) - 1, 1 << (SEED_AXIS_BITS - 1)

    def axis(bits):
        return (bits & mask) - offset

    return (axis(key), axis(key >> SEED_AXIS_BITS), axis(key >> 2 * SEED_AXIS_BITS)), (key >> 60) & 7


FACINGS = {0: "none", 1: "+x", 2: "-x", 3: "+y", 4: "-y", 5: "up", 6: "down"}


def hidden_share(triangles, sensor, cell):
    """Share of 27 rays to the cell's points that hit the scene before reaching the cell."""
    before = 0
    for i in range(3):
        for j in range(3):
            for k in range(3):
                point = (cell[0] + (1 + 2 * i) / 6, cell[1] + (1 + 2 * j) / 6, cell[2] + (1 + 2 * k) / 6)
                d = sub(point, sensor)
                n = math.sqrt(dot(d, d))
                u = (d[0] / n, d[1] / n, d[2] / n)
                t = first_hit(triangles, sensor, u, n + 2.0)
                hit = (sensor[0] + u[0] * t, sensor[1] + u[1] * t, sensor[2] + u[2] * t)
                in_cell = all(c - 0.2 <= h <= c + 1.2 for c, h in zip(cell, hit))
                if t < n and not in_cell:
                    before += 1
    return before / 27.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("trace")
    parser.add_argument("scene")
    parser.add_argument("--sensor-dz", type=float, default=0.9, help="sensor above the trace's position (m)")
    parser.add_argument("--since", type=float, default=0.0, help="only judgements from this sim time on")
    parser.add_argument("--list", action="store_true", help="one line per judged target")
    args = parser.parse_args()

    triangles = load_triangles(args.scene)
    bins = collections.OrderedDict((name, [0, 0, 0.0]) for name in ("hidden < 20 %", "hidden 20-50 %", "hidden >= 50 %"))
    by_facing = collections.defaultdict(lambda: [0, 0])
    with open(args.trace) as f:
        for line in f:
            try:
                round_ = json.loads(line)
            except ValueError:
                continue  # a line cut off when the run was stopped
            if round_["t"] < args.since:
                continue
            x, y, z = round_["position"]
            sensor = (x, y, z + args.sensor_dz)
            for judged in round_.get("judged", []):
                if not judged["target"] >> 63:
                    continue  # ground: the cell's lower points lie under the ground it is
                cell, facing = seed_cell(judged["target"])
                share = hidden_share(triangles, sensor, cell)
                name = "hidden >= 50 %" if share >= 0.5 else "hidden 20-50 %" if share >= 0.2 else "hidden < 20 %"
                covered = judged["covered"] / max(1, judged["voxels"])
                bins[name][0] += 1
                bins[name][1] += judged["complete"]
                bins[name][2] += covered
                by_facing[FACINGS.get(facing, "?")][0] += 1
                by_facing[FACINGS.get(facing, "?")][1] += judged["complete"]
                if args.list:
                    print(f"{round_['t']:8.1f} cell {cell} facing {FACINGS.get(facing)} hidden {share:.2f} "
                          f"covered {judged['covered']}/{judged['voxels']} gap {judged['gap']} "
                          f"at {judged['distance_m']:.1f} m")
    total = sum(b[0] for b in bins.values())
    print(f"| judged facade targets ({total}) | looks | complete | mean covered |")
    print("|---|---|---|---|")
    for name, (n, complete, covered) in bins.items():
        share = f"{100.0 * n / total:.0f} %" if total else "-"
        mean = f"{covered / n:.2f}" if n else "-"
        print(f"| {name} | {n} ({share}) | {complete} | {mean} |")
    print("by facing (looks, complete): " +
          ", ".join(f"{k} {v[0]}/{v[1]}" for k, v in sorted(by_facing.items())))


if __name__ == "__main__":
    main()
