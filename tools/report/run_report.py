#!/usr/bin/env python3
"""The figures and short report of one mission's results folder, or of several seeds.

One run (a folder with summary.json, as the station writes it):
  DIR/completeness.{png,svg}  completeness vs time: the team, its observable variant, each robot
  DIR/topdown.{png,svg}       the reconstruction (map.ply) from above, coloured by height, each
                              robot's trajectory in its colour (start marked), and the coverage
                              targets still open at the end coloured by why (open_targets.csv)
  DIR/report.md               end reason, exploration time, completeness, per robot figures
Several seeds (a folder of seed-<n>/ runs, as hexplore_experiment writes it): the above for
every seed, plus DIR/completeness_seeds.{png,svg} (team and observable completeness, mean and
min-max band over the seeds) and DIR/report.md with one row per seed.

Usage: run_report.py DIR
Needs matplotlib and numpy (Debian: python3-matplotlib); without them it says so and exits 3.
"""

import argparse
import csv
import json
import os
import sys

OPEN_TARGET_COLOURS = {
    "has_view": "#e68c00",
    "given_up": "#960096",
    "no_viewpoint": "#009696",
    "occluded": "#005ac8",
    "unreachable": "#787800",
    "unassignable": "#c80000",
}
PLY_TYPES = {"float": "<f4", "float32": "<f4", "double": "<f8", "float64": "<f8", "uchar": "u1", "uint8": "u1",
             "char": "i1", "int8": "i1", "ushort": "<u2", "uint16": "<u2", "short": "<i2", "int16": "<i2",
             "uint": "<u4", "uint32": "<u4", "int": "<i4", "int32": "<i4"}


class ReportError(Exception):
    pass


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_ply_points(path, np):
    """x, y, z of a binary little-endian PLY's vertices (as PCL writes them), or None without a file."""
    if not os.path.exists(path):
        return None
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ReportError(f"{path}: not a PLY file")
        count, properties, in_vertex, fmt = 0, [], False, None
        while True:
            line = f.readline()
            if not line:
                raise ReportError(f"{path}: header without end_header")
            words = line.decode("ascii", "replace").split()
            if not words:
                continue
            if words[0] == "end_header":
                break
            if words[0] == "format":
                fmt = words[1]
            elif words[0] == "element":
                in_vertex = words[1] == "vertex"
                if in_vertex:
                    count = int(words[2])
            elif words[0] == "property" and in_vertex:
                if words[1] == "list" or words[1] not in PLY_TYPES:
                    raise ReportError(f"{path}: vertex property '{' '.join(words[1:])}' is not supported")
                properties.append((words[2], PLY_TYPES[words[1]]))
        if fmt != "binary_little_endian":
            raise ReportError(f"{path}: format {fmt} is not supported (binary_little_endian is)")
        dtype = np.dtype(properties)
        data = np.frombuffer(f.read(count * dtype.itemsize), dtype=dtype, count=count)
    return np.stack([data["x"], data["y"], data["z"]], axis=1).astype(float)


def grid_spacing(points, np):
    """The map's cell size: the smallest step between the distinct x of its voxel centres."""
    xs = np.unique(np.round(points[:, 0], 4))
    steps = np.diff(xs)
    steps = steps[steps > 1e-3]
    return float(steps.min()) if len(steps) else 0.15


def load_run(run_dir):
    path = os.path.join(run_dir, "summary.json")
    if not os.path.exists(path):
        raise ReportError(f"{run_dir}: no summary.json")
    with open(path) as f:
        summary = json.load(f)
    completeness = read_csv(os.path.join(run_dir, "completeness.csv"))
    robots = sorted(summary.get("robots", {}))
    series = {"t": [float(r["sim_time_s"]) for r in completeness],
              "team": [float(r["team"]) for r in completeness],
              "observable": [float(r["team_observable"]) for r in completeness],
              "robots": {robot: [float(r.get(robot, 0.0)) for r in completeness] for robot in robots}}
    tracks = {}
    for row in read_csv(os.path.join(run_dir, "trajectories.csv")):
        tracks.setdefault(row["robot"], []).append((float(row["x_m"]), float(row["y_m"])))
    # The open targets of each robot's latest report; drawn for the first robot that reported.
    latest = {}
    for row in read_csv(os.path.join(run_dir, "open_targets.csv")):
        t = float(row["sim_time_s"])
        if row["robot"] not in latest or t > latest[row["robot"]][0]:
            latest[row["robot"]] = (t, [])
        if t == latest[row["robot"]][0]:
            latest[row["robot"]][1].append(row)
    reporter = sorted(latest)[0] if latest else None
    open_targets = latest[reporter][1] if reporter else []
    return {"dir": run_dir, "summary": summary, "series": series, "tracks": tracks,
            "open_reporter": reporter, "open_targets": open_targets}


def save(fig, stem):
    fig.savefig(stem + ".png", dpi=110)
    fig.savefig(stem + ".svg")
    return [stem + ".png", stem + ".svg"]


def completeness_figure(run, plt):
    s = run["series"]
    fig, ax = plt.subplots(figsize=(8, 4.8), constrained_layout=True)
    ax.plot(s["t"], [100 * v for v in s["team"]], color="black", linewidth=2.2, label="team")
    ax.plot(s["t"], [100 * v for v in s["observable"]], color="black", linewidth=1.5, linestyle="--",
            label="team, observable")
    for robot, values in s["robots"].items():
        species = run["summary"]["robots"][robot].get("species", "")
        ax.plot(s["t"], [100 * v for v in values], linewidth=1.5, label=f"{robot} ({species})" if species else robot)
    ax.set_xlabel("sim time (s)")
    ax.set_ylabel("completeness (%)")
    ax.set_ylim(0, 100)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title(f"{run['summary'].get('scene', '')}, {run['summary'].get('planner', '')}, "
                 f"seed {run['summary'].get('seed', '?')}: {run['summary'].get('end_reason', '')}")
    paths = save(fig, os.path.join(run["dir"], "completeness"))
    plt.close(fig)
    return paths


def topdown_figure(run, plt, np):
    points = read_ply_points(os.path.join(run["dir"], "map.ply"), np)
    fig, ax = plt.subplots(figsize=(8, 8), constrained_layout=True)
    if points is not None and len(points):
        # A height image: the highest mapped point of each cell, so roofs and upper floors show.
        cell = grid_spacing(points, np)
        lo = points[:, :2].min(axis=0)
        # Points are voxel centres, whole cells apart from the lowest: round, not floor (float32
        # centres land a hair either side of a cell boundary and would leave empty stripes).
        ij = np.rint((points[:, :2] - lo) / cell).astype(int)
        image = np.full((ij[:, 1].max() + 1, ij[:, 0].max() + 1), np.nan)
        np.fmax.at(image, (ij[:, 1], ij[:, 0]), points[:, 2])
        lo = lo - cell / 2  # cell edges, not centres
        hi = lo + cell * np.array(image.shape[::-1])
        im = ax.imshow(image, origin="lower", extent=(lo[0], hi[0], lo[1], hi[1]), cmap="viridis",
                       interpolation="nearest")
        fig.colorbar(im, ax=ax, shrink=0.7, label="height (m)")
    for robot, track in sorted(run["tracks"].items()):
        xs, ys = zip(*track)
        line, = ax.plot(xs, ys, linewidth=2, label=robot)
        ax.plot(xs[0], ys[0], marker="s", markersize=7, color=line.get_color())
    for state, colour in OPEN_TARGET_COLOURS.items():
        rows = [r for r in run["open_targets"] if r["state"] == state]
        if rows:
            ax.scatter([float(r["x_m"]) for r in rows], [float(r["y_m"]) for r in rows], s=6, color=colour,
                       label=f"open: {state} ({len(rows)})", zorder=3)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(alpha=0.2)
    ax.legend(loc="upper left", fontsize=7, markerscale=1.5)
    title = "top-down map and trajectories"
    if run["open_reporter"]:
        title += f"; open targets as {run['open_reporter']} saw them"
    ax.set_title(title, fontsize=10)
    paths = save(fig, os.path.join(run["dir"], "topdown"))
    plt.close(fig)
    return paths


def seeds_figure(root, runs, plt, np):
    grid = np.linspace(0, max(r["series"]["t"][-1] for r in runs if r["series"]["t"]), 200)
    fig, ax = plt.subplots(figsize=(8, 4.8), constrained_layout=True)
    for key, style, label in (("team", "-", "team"), ("observable", "--", "team, observable")):
        curves = np.array([np.interp(grid, r["series"]["t"], r["series"][key]) * 100 for r in runs])
        ax.plot(grid, curves.mean(axis=0), color="black", linestyle=style, label=f"{label}: mean of {len(runs)} seeds")
        ax.fill_between(grid, curves.min(axis=0), curves.max(axis=0), color="grey", alpha=0.25 if key == "team" else 0.15,
                        label=f"{label}: min-max")
    ax.set_xlabel("sim time (s)")
    ax.set_ylabel("completeness (%)")
    ax.set_ylim(0, 100)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    paths = save(fig, os.path.join(root, "completeness_seeds"))
    plt.close(fig)
    return paths


def run_row(run):
    s = run["summary"]
    obs = run["series"]["observable"][-1] * 100 if run["series"]["observable"] else float("nan")
    team = run["series"]["team"][-1] * 100 if run["series"]["team"] else float("nan")
    lengths = ", ".join(f"{r} {v.get('trajectory_length_m', 0):.0f} m" for r, v in sorted(s.get("robots", {}).items()))
    return (f"| {s.get('seed', '?')} | {s.get('end_reason', '')} | {s.get('exploration_time_s', 0):.0f} | {team:.1f} | "
            f"{obs:.1f} | {lengths} |")


def markdown(title, runs, figures):
    lines = [f"# {title}", "", "| seed | end | exploration time (s) | team (%) | observable (%) | trajectory |",
             "|---|---|---|---|---|---|"]
    lines += [run_row(r) for r in runs]
    lines += [""] + [f"![{os.path.basename(f)}]({f})" for f in figures if f.endswith(".png")] + [""]
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", help="a results folder, or a folder of seed-<n>/ results folders")
    args = ap.parse_args(argv)
    root = args.results
    if not os.path.isdir(root):
        print(f"run_report: {root} is not a folder", file=sys.stderr)
        return 1
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as e:
        print(f"run_report: figures not drawn: {e.name} is not installed (Debian: apt-get install python3-matplotlib)",
              file=sys.stderr)
        return 3
    try:
        # A seeds folder holds seed-<n>/ runs (its own summary.json is the summary over them).
        seeds = sorted((d for d in os.listdir(root) if d.startswith("seed-") and d[5:].isdigit()
                        and os.path.exists(os.path.join(root, d, "summary.json"))), key=lambda d: int(d[5:]))
        if seeds:
            runs = [load_run(os.path.join(root, d)) for d in seeds]
        elif os.path.exists(os.path.join(root, "summary.json")):
            runs = [load_run(root)]
        else:
            runs = []
        if not runs:
            print(f"run_report: no summary.json in {root} or its seed-<n>/ folders", file=sys.stderr)
            return 1
        summary = runs[0]["summary"]
        title = f"{summary.get('scene', '')}, {summary.get('planner', '')}"
        if seeds:
            for run in runs:
                figures = [os.path.basename(p) for p in completeness_figure(run, plt) + topdown_figure(run, plt, np)]
                with open(os.path.join(run["dir"], "report.md"), "w") as f:
                    f.write(markdown(f"{title}, {os.path.basename(run['dir'])}", [run], figures))
            figures = [os.path.basename(p) for p in seeds_figure(root, runs, plt, np)]
            figures += [f"{d}/{name}.png" for d in seeds for name in ("completeness", "topdown")]
        else:
            figures = [os.path.basename(p) for p in completeness_figure(runs[0], plt) + topdown_figure(runs[0], plt, np)]
        with open(os.path.join(root, "report.md"), "w") as f:
            f.write(markdown(title, runs, figures))
    except (ReportError, KeyError, ValueError) as e:
        print(f"run_report: {e}", file=sys.stderr)
        return 1
    print(f"run_report: {len(runs)} run(s) in {root}: figures and report.md written")
    return 0


if __name__ == "__main__":
    sys.exit(main())
