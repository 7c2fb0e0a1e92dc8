#!/usr/bin/env python3
"""The comparison report of `hexplore_experiment --planners a,b,c --results DIR`.

Reads DIR/<planner>/seed-<n>/ (summary.json, completeness.csv, planning.csv,
communication.csv, as the station writes them) and writes, per planner, the paper's metrics
(Simulations section): exploration time and the reduction of the reference planner's
(hexplore's) exploration time against each other planner, team and observable completeness,
accumulated completeness, trajectory length per robot and in total, single-round planning
time (mean, max), communication per category (cumulative KB and average KB/s per robot).

  DIR/comparison.json   every number, per planner (mean, stddev, min, max over the seeds)
  DIR/comparison.csv    one row per planner
  DIR/comparison.md     the tables
  DIR/figures/          completeness vs time, trajectory length, accumulated completeness,
                        planning time distribution (PNG and SVG; needs matplotlib, e.g.
                        Debian's python3-matplotlib; without it the tables are still written)

Usage: compare_report.py DIR [--reference hexplore] [--no-figures]
Only the standard library is needed for the tables.
"""

import argparse
import csv
import json
import math
import os
import sys

CATEGORIES = ["pose", "incremental_map", "executable_path", "exploration_route"]
OBSERVABLE_LEVELS = [0.5, 0.7, 0.8, 0.9, 0.95, 0.97]
# The tail: from when observable completeness first comes within this much of its final value
# to the end. Every planner's default missions spend a fifth to a third of their time there
# (common/planning/README.md, "The last tenth of a point"), so it sets much of the spread of
# exploration times.
TAIL_POINTS = 0.001


def stats(values):
    values = [v for v in values if v is not None and not (isinstance(v, float) and math.isnan(v))]
    if not values:
        return {"mean": None, "stddev": None, "min": None, "max": None, "n": 0}
    mean = sum(values) / len(values)
    std = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1)) if len(values) > 1 else 0.0
    return {"mean": mean, "stddev": std, "min": min(values), "max": max(values), "n": len(values)}


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def load_run(seed_dir):
    with open(os.path.join(seed_dir, "summary.json")) as f:
        summary = json.load(f)
    completeness = read_csv(os.path.join(seed_dir, "completeness.csv"))
    robots = sorted(summary.get("robots", {}))
    series = {"t": [], "team": [], "observable": [], "accumulated": []}
    for row in completeness:
        series["t"].append(float(row["sim_time_s"]))
        series["team"].append(float(row["team"]))
        series["observable"].append(float(row["team_observable"]))
        series["accumulated"].append(sum(float(row[r]) for r in robots if r in row))
    planning = [float(r["planning_time_s"]) for r in read_csv(os.path.join(seed_dir, "planning.csv"))]
    communication = {}
    for row in read_csv(os.path.join(seed_dir, "communication.csv")):
        communication.setdefault(row["robot"], {})[row["category"]] = float(row["cumulative_kb"])
    return {"summary": summary, "series": series, "planning": planning, "communication": communication}


def load_planner(planner_dir):
    runs = []
    for name in sorted(os.listdir(planner_dir), key=lambda n: (len(n), n)):
        seed_dir = os.path.join(planner_dir, name)
        if name.startswith("seed-") and os.path.isfile(os.path.join(seed_dir, "summary.json")):
            runs.append(load_run(seed_dir))
    return runs


def planner_order(root):
    listed = os.path.join(root, "planners.txt")
    found = [d for d in sorted(os.listdir(root)) if os.path.isdir(os.path.join(root, d)) and load_planner_quick(root, d)]
    if os.path.exists(listed):
        with open(listed) as f:
            order = [p for p in f.read().strip().split(",") if p]
        return [p for p in order if p in found] + [p for p in found if p not in order]
    return found


def load_planner_quick(root, name):
    d = os.path.join(root, name)
    return any(n.startswith("seed-") and os.path.isfile(os.path.join(d, n, "summary.json")) for n in os.listdir(d))


def first_time_at(series, key, level):
    for t, v in zip(series["t"], series[key]):
        if v >= level:
            return t
    return None


def tail_of(run):
    """(time observable completeness first came within TAIL_POINTS of its final value, the
    seconds from then to the end), or None without a series."""
    t, obs = run["series"]["t"], run["series"]["observable"]
    if not t:
        return None
    final = obs[-1]
    reached = first_time_at(run["series"], "observable", final - TAIL_POINTS)
    return reached, run["summary"]["exploration_time_s"] - reached


def metrics(runs):
    """The paper's metrics of one planner over its runs (seeds)."""
    summaries = [r["summary"] for r in runs]
    m = {
        "runs": len(runs),
        "seeds": [s.get("seed") for s in summaries],
        "scene": summaries[0].get("scene") if summaries else None,
        "mode": summaries[0].get("mode") if summaries else None,
        "end_reasons": {},
        "exploration_time_s": stats([s["exploration_time_s"] for s in summaries]),
        "final_completeness": stats([s["final_completeness"] for s in summaries]),
        "final_observable_completeness": stats([s["final_observable_completeness"] for s in summaries]),
        "accumulated_completeness": stats([s["accumulated_completeness"] for s in summaries]),
        "collisions": sum(r.get("collisions", 0) for s in summaries for r in s.get("robots", {}).values()),
    }
    for s in summaries:
        m["end_reasons"][s["end_reason"]] = m["end_reasons"].get(s["end_reason"], 0) + 1
    robots = sorted({r for s in summaries for r in s.get("robots", {})})
    m["trajectory_length_m"] = {
        "per_robot": {r: stats([s["robots"][r]["trajectory_length_m"] for s in summaries if r in s["robots"]]) for r in robots},
        "total": stats([sum(v["trajectory_length_m"] for v in s["robots"].values()) for s in summaries]),
    }
    all_rounds = [t for r in runs for t in r["planning"]]
    m["planning_time_s"] = {
        "mean": sum(all_rounds) / len(all_rounds) if all_rounds else None,
        "max": max(all_rounds) if all_rounds else None,
        "rounds": len(all_rounds),
        "run_means": stats([sum(r["planning"]) / len(r["planning"]) for r in runs if r["planning"]]),
    }
    # Communication as the paper counts it: each robot's volume, averaged over the robots
    # (cumulative KB), and that divided by the exploration time (average KB/s per robot).
    comm = {}
    for category in CATEGORIES + ["total"]:
        kb, rate = [], []
        for r, s in zip(runs, summaries):
            per_robot = r["communication"]
            if not per_robot:
                continue
            values = [sum(c.values()) if category == "total" else c.get(category, 0.0) for c in per_robot.values()]
            mean_kb = sum(values) / len(values)
            kb.append(mean_kb)
            rate.append(mean_kb / max(s["exploration_time_s"], 1e-9))
        comm[category] = {"cumulative_kb_per_robot": stats(kb), "kb_per_s_per_robot": stats(rate)}
    m["communication"] = comm
    # A radio budget binds every robot, not their mean: the highest single robot's average
    # total rate over all the runs (issue 14's bar is per robot).
    busiest = None
    for r, s in zip(runs, summaries):
        for robot, c in r["communication"].items():
            rate = sum(c.values()) / max(s["exploration_time_s"], 1e-9)
            if busiest is None or rate > busiest["kb_per_s"]:
                busiest = {"kb_per_s": rate, "robot": robot, "seed": s.get("seed")}
    m["busiest_robot_communication"] = busiest
    m["time_to_observable_completeness_s"] = {
        str(level): stats([first_time_at(r["series"], "observable", level) for r in runs]) for level in OBSERVABLE_LEVELS
    }
    tails = [tail_of(r) for r in runs]
    m["tail"] = {
        "within_points": 100.0 * TAIL_POINTS,
        "reached_s": stats([x[0] for x in tails if x]),
        "tail_s": stats([x[1] for x in tails if x]),
        "share_of_mission": stats([x[1] / r["summary"]["exploration_time_s"] for x, r in zip(tails, runs)
                                   if x and r["summary"]["exploration_time_s"] > 0]),
    }
    return m


def add_reductions(result, reference):
    """Reduction of the reference planner's mean exploration time against each other planner, in %
    (the paper's "reduced exploration time by x %": (T_other - T_reference) / T_other)."""
    if reference not in result:
        return
    t_ref = result[reference]["exploration_time_s"]["mean"]
    result[reference]["exploration_time_reduction_pct"] = {}
    for name, m in result.items():
        if name == reference:
            continue
        t = m["exploration_time_s"]["mean"]
        pct = None if not t or t_ref is None else 100.0 * (t - t_ref) / t
        m["reference_exploration_time_reduction_pct"] = pct
        result[reference]["exploration_time_reduction_pct"][name] = pct


def fmt(v, digits=1, scale=1.0):
    if v is None:
        return "-"
    return f"{v * scale:.{digits}f}"


def pm(s, digits=1, scale=1.0):
    if s["mean"] is None:
        return "-"
    if s["n"] > 1:
        return f"{fmt(s['mean'], digits, scale)} ± {fmt(s['stddev'], digits, scale)}"
    return fmt(s["mean"], digits, scale)


def markdown(result, order, reference):
    lines = []
    first = result[order[0]]
    seeds = sorted({s for m in result.values() for s in m["seeds"] if s is not None})
    lines.append(f"# Planner comparison: {first['scene']} ({first['mode']}), seeds {', '.join(map(str, seeds))}")
    lines.append("")
    lines.append("Mean ± standard deviation over the seeds. Reduction: how much shorter the exploration time of "
                 f"`{reference}` is than this planner's, (T - T_{reference}) / T.")
    censored = {n: m["end_reasons"].get("time limit", 0) for n, m in result.items()}
    if any(censored.values()):
        lines.append("")
        lines.append("**Note:** runs that end on the time limit have that limit as exploration time (censored); "
                     "compare completeness and the time to reach a completeness level there. Time-limited runs: " +
                     ", ".join(f"{n} {c}/{result[n]['runs']}" for n, c in censored.items()) + ".")
    lines.append("")
    lines.append(f"| planner | runs | exploration time (s) | {reference}'s reduction | team completeness (%) | "
                 "observable (%) | accumulated (%) | trajectory, total (m) | planning mean / max (ms) | "
                 "collisions | end reasons |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for n in order:
        m = result[n]
        red = m.get("reference_exploration_time_reduction_pct")
        reasons = ", ".join(f"{k} x{v}" for k, v in sorted(m["end_reasons"].items()))
        lines.append(
            f"| {n} | {m['runs']} | {pm(m['exploration_time_s'])} | {'-' if n == reference else fmt(red) + ' %'} | "
            f"{pm(m['final_completeness'], 1, 100)} | {pm(m['final_observable_completeness'], 1, 100)} | "
            f"{pm(m['accumulated_completeness'], 1, 100)} | {pm(m['trajectory_length_m']['total'])} | "
            f"{fmt(m['planning_time_s']['mean'], 1, 1e3)} / {fmt(m['planning_time_s']['max'], 1, 1e3)} | "
            f"{m['collisions']} | {reasons} |")
    lines.append("")
    lines.append("## Communication per robot (cumulative KB / average KB/s)")
    lines.append("")
    lines.append("| planner | " + " | ".join(CATEGORIES + ["total"]) + " | busiest robot (KB/s) |")
    lines.append("|---|" + "---|" * (len(CATEGORIES) + 2))
    for n in order:
        c = result[n]["communication"]
        cells = [f"{fmt(c[k]['cumulative_kb_per_robot']['mean'])} / {fmt(c[k]['kb_per_s_per_robot']['mean'], 3)}"
                 for k in CATEGORIES + ["total"]]
        b = result[n]["busiest_robot_communication"]
        cells.append(f"{fmt(b['kb_per_s'], 3)} ({b['robot']}, seed {b['seed']})" if b else "-")
        lines.append(f"| {n} | " + " | ".join(cells) + " |")
    lines.append("")
    lines.append("## Trajectory length per robot (m)")
    lines.append("")
    robots = sorted({r for m in result.values() for r in m["trajectory_length_m"]["per_robot"]})
    lines.append("| planner | " + " | ".join(robots) + " | total |")
    lines.append("|---|" + "---|" * (len(robots) + 1))
    for n in order:
        t = result[n]["trajectory_length_m"]
        cells = [pm(t["per_robot"][r]) if r in t["per_robot"] else "-" for r in robots]
        lines.append(f"| {n} | " + " | ".join(cells) + f" | {pm(t['total'])} |")
    lines.append("")
    lines.append("## Time to reach an observable completeness (s; runs that reached it)")
    lines.append("")
    lines.append("| planner | " + " | ".join(f"{int(l * 100)} %" for l in OBSERVABLE_LEVELS) + " |")
    lines.append("|---|" + "---|" * len(OBSERVABLE_LEVELS))
    for n in order:
        t = result[n]["time_to_observable_completeness_s"]
        cells = [f"{pm(t[str(l)])} ({t[str(l)]['n']}/{result[n]['runs']})" for l in OBSERVABLE_LEVELS]
        lines.append(f"| {n} | " + " | ".join(cells) + " |")
    lines.append("")
    lines.append(f"## The tail: from within {100 * TAIL_POINTS:.1f} point of the final observable completeness to the end")
    lines.append("")
    lines.append("| planner | reached (s) | tail (s) | share of the mission (%) |")
    lines.append("|---|---|---|---|")
    for n in order:
        t = result[n]["tail"]
        lines.append(f"| {n} | {pm(t['reached_s'])} | {pm(t['tail_s'])} | {pm(t['share_of_mission'], 1, 100)} |")
    lines.append("")
    return "\n".join(lines)


def write_csv(path, result, order):
    robots = sorted({r for m in result.values() for r in m["trajectory_length_m"]["per_robot"]})
    header = ["planner", "runs", "exploration_time_s_mean", "exploration_time_s_stddev", "reference_reduction_pct",
              "final_completeness_mean", "final_observable_completeness_mean", "accumulated_completeness_mean",
              "trajectory_total_m_mean"] + [f"trajectory_{r}_m_mean" for r in robots] + [
              "planning_time_mean_s", "planning_time_max_s", "planning_rounds"]
    for k in CATEGORIES + ["total"]:
        header += [f"{k}_cumulative_kb_per_robot", f"{k}_kb_per_s_per_robot"]
    header += ["busiest_robot_kb_per_s", "collisions", "time_limited_runs", "tail_reached_s_mean", "tail_s_mean"]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for n in order:
            m = result[n]
            row = [n, m["runs"], m["exploration_time_s"]["mean"], m["exploration_time_s"]["stddev"],
                   m.get("reference_exploration_time_reduction_pct"), m["final_completeness"]["mean"],
                   m["final_observable_completeness"]["mean"], m["accumulated_completeness"]["mean"],
                   m["trajectory_length_m"]["total"]["mean"]]
            row += [m["trajectory_length_m"]["per_robot"].get(r, {}).get("mean") for r in robots]
            row += [m["planning_time_s"]["mean"], m["planning_time_s"]["max"], m["planning_time_s"]["rounds"]]
            for k in CATEGORIES + ["total"]:
                c = m["communication"][k]
                row += [c["cumulative_kb_per_robot"]["mean"], c["kb_per_s_per_robot"]["mean"]]
            busiest = m["busiest_robot_communication"]
            row += [busiest["kb_per_s"] if busiest else None, m["collisions"], m["end_reasons"].get("time limit", 0), m["tail"]["reached_s"]["mean"],
                    m["tail"]["tail_s"]["mean"]]
            w.writerow(["" if v is None else v for v in row])


def resample(runs, key, step):
    """Every run's series on one time grid; a run that ended keeps its last value."""
    end = max((r["series"]["t"][-1] for r in runs if r["series"]["t"]), default=0.0)
    grid = [i * step for i in range(int(end / step) + 2)]
    out = []
    for r in runs:
        t, v = r["series"]["t"], r["series"][key]
        if not t:
            continue
        values, j = [], 0
        for g in grid:
            while j + 1 < len(t) and t[j + 1] <= g:
                j += 1
            values.append(v[j] if t[j] <= g else 0.0)
        out.append(values)
    return grid, out


def figures(root, runs_by_planner, order):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = os.path.join(root, "figures")
    os.makedirs(out, exist_ok=True)
    written = []
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]

    def save(fig, name):
        for ext in ("png", "svg"):
            path = os.path.join(out, f"{name}.{ext}")
            fig.savefig(path, dpi=120, bbox_inches="tight")
            written.append(path)
        plt.close(fig)

    def band(ax, key, scale=100.0):
        for i, n in enumerate(order):
            runs = runs_by_planner[n]
            grid, series = resample(runs, key, 2.0)
            if not series:
                continue
            cols = list(zip(*series))
            mean = [scale * sum(c) / len(c) for c in cols]
            ax.plot(grid, mean, color=colours[i % len(colours)], label=f"{n} ({len(series)})")
            if len(series) > 1:
                ax.fill_between(grid, [scale * min(c) for c in cols], [scale * max(c) for c in cols],
                                color=colours[i % len(colours)], alpha=0.2, linewidth=0)
        ax.set_xlabel("sim time (s)")
        ax.grid(True, alpha=0.3)

    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    band(axes[0], "team")
    axes[0].set_ylabel("team completeness (%)")
    axes[0].set_title("Completeness vs time (mean, min-max band)")
    band(axes[1], "observable")
    axes[1].set_ylabel("observable completeness (%)")
    axes[1].legend(loc="lower right", fontsize=8)
    save(fig, "completeness_vs_time")

    fig, ax = plt.subplots(figsize=(6, 4))
    band(ax, "accumulated")
    ax.set_ylabel("accumulated completeness (%)")
    ax.set_title("Accumulated completeness (sum over robots)")
    ax.legend(loc="lower right", fontsize=8)
    save(fig, "accumulated_completeness")

    fig, ax = plt.subplots(figsize=(max(5, 1.2 * len(order)), 4))
    robots = sorted({r for n in order for run in runs_by_planner[n] for r in run["summary"]["robots"]})
    bottoms = [0.0] * len(order)
    for j, robot in enumerate(robots):
        heights = []
        for n in order:
            vals = [run["summary"]["robots"][robot]["trajectory_length_m"] for run in runs_by_planner[n]
                    if robot in run["summary"]["robots"]]
            heights.append(sum(vals) / len(vals) if vals else 0.0)
        ax.bar(order, heights, bottom=bottoms, label=robot, color=colours[j % len(colours)])
        bottoms = [b + h for b, h in zip(bottoms, heights)]
    totals = [[sum(v["trajectory_length_m"] for v in run["summary"]["robots"].values()) for run in runs_by_planner[n]]
              for n in order]
    errs = [stats(t)["stddev"] or 0.0 for t in totals]
    ax.errorbar(order, bottoms, yerr=errs, fmt="none", ecolor="black", capsize=4)
    ax.set_ylabel("trajectory length (m)")
    ax.set_title("Trajectory length per robot (mean; bar: total ± stddev)")
    ax.legend(fontsize=8)
    ax.tick_params(axis="x", rotation=30)
    save(fig, "trajectory_length")

    fig, ax = plt.subplots(figsize=(max(5, 1.2 * len(order)), 4))
    data = [[1e3 * t for run in runs_by_planner[n] for t in run["planning"]] or [0.0] for n in order]
    ax.boxplot(data, labels=order, showfliers=True)
    ax.set_yscale("log")
    ax.set_ylabel("single-round planning time (ms)")
    ax.set_title("Planning time per round")
    ax.grid(True, axis="y", alpha=0.3)
    ax.tick_params(axis="x", rotation=30)
    save(fig, "planning_time")
    return written


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", help="the --results folder of hexplore_experiment --planners")
    ap.add_argument("--reference", default="hexplore", help="the planner whose exploration-time reduction is reported")
    ap.add_argument("--no-figures", action="store_true", help="tables only")
    args = ap.parse_args(argv)
    root = args.results
    if not os.path.isdir(root):
        print(f"compare_report: {root} is not a folder", file=sys.stderr)
        return 1
    order = planner_order(root)
    if not order:
        print(f"compare_report: no <planner>/seed-<n>/summary.json under {root}", file=sys.stderr)
        return 1
    runs_by_planner = {n: load_planner(os.path.join(root, n)) for n in order}
    result = {n: metrics(runs_by_planner[n]) for n in order}
    add_reductions(result, args.reference)
    with open(os.path.join(root, "comparison.json"), "w") as f:
        json.dump({"reference": args.reference, "planners": order, "metrics": result}, f, indent=2)
    write_csv(os.path.join(root, "comparison.csv"), result, order)
    md = markdown(result, order, args.reference)
    with open(os.path.join(root, "comparison.md"), "w") as f:
        f.write(md)
    print(md)
    print(f"compare_report: wrote {root}/comparison.json, comparison.csv, comparison.md")
    if args.no_figures:
        return 0
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("compare_report: figures skipped: matplotlib is not installed (Debian: apt-get install python3-matplotlib)")
        return 0
    written = figures(root, runs_by_planner, order)
    print(f"compare_report: wrote {len(written)} figure files in {root}/figures")
    return 0


if __name__ == "__main__":
    sys.exit(main())
