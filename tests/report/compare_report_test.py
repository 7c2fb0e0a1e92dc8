#!/usr/bin/env python3
"""tools/report/compare_report.py on a tiny synthetic results folder: two planners, two seeds
each, numbers chosen so every metric is known; the tables without matplotlib (an import that
fails), the figures with it when the interpreter has it.
Usage: compare_report_test.py SCRIPT"""

import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def write_run(root, planner, seed, time_s, final, robots):
    """One station results folder. robots: id -> (length_m, final completeness, kb per category)."""
    d = os.path.join(root, planner, f"seed-{seed}")
    os.makedirs(d)
    ids = sorted(robots)
    summary = {
        "scene": "yard", "planner": planner, "mode": "lockstep", "seed": seed,
        "end_reason": "no task views remain" if time_s < 600 else "time limit",
        "exploration_time_s": time_s, "wall_time_s": 1.0, "final_completeness": final,
        "final_observable_completeness": min(1.0, final + 0.1),
        "accumulated_completeness": sum(r[1] for r in robots.values()),
        "planning_time_s": {"mean": 0.0, "max": 0.0, "rounds": 0}, "team_kb_per_s": 0.0,
        "robots": {r: {"species": "S", "trajectory_length_m": v[0], "collisions": 0, "final_completeness": v[1],
                       "communication_kb": dict(zip(["pose", "incremental_map", "executable_path",
                                                     "exploration_route"], v[2]))} for r, v in robots.items()},
    }
    with open(os.path.join(d, "summary.json"), "w") as f:
        json.dump(summary, f)
    with open(os.path.join(d, "completeness.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["sim_time_s", "team", "team_observable"] + ids)
        for i in range(5):  # linear up to the final value at time_s
            t = time_s * i / 4
            w.writerow([t, final * i / 4, min(1.0, final + 0.1) * i / 4] + [robots[r][1] * i / 4 for r in ids])
    with open(os.path.join(d, "planning.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["robot", "round", "planning_time_s"])
        for r in ids:
            for k, t in enumerate([0.01, 0.03]):
                w.writerow([r, k, t * (2 if planner == "slow" else 1)])
    with open(os.path.join(d, "communication.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["robot", "category", "cumulative_kb", "average_kb_per_s"])
        for r in ids:
            for c, kb in zip(["pose", "incremental_map", "executable_path", "exploration_route"], robots[r][2]):
                w.writerow([r, c, kb, kb / time_s])


def make_results(root):
    # hexplore: 200 s and 300 s (mean 250); slow: 400 s and 600 s (mean 500, one time-limited).
    for seed, t in ((1, 200.0), (2, 300.0)):
        write_run(root, "hexplore", seed, t, 0.9,
                  {"a": (100.0, 0.6, [10, 100, 5, 2]), "b": (50.0, 0.5, [10, 80, 5, 2])})
    for seed, t in ((1, 400.0), (2, 600.0)):
        write_run(root, "slow", seed, t, 0.8,
                  {"a": (150.0, 0.7, [20, 200, 10, 0]), "b": (150.0, 0.6, [20, 100, 10, 0])})
    with open(os.path.join(root, "planners.txt"), "w") as f:
        f.write("hexplore,slow\n")


def run(root, env=None):
    return subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True, env=env)


class CompareReport(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = os.path.join(self.tmp.name, "results")
        make_results(self.root)

    def tearDown(self):
        self.tmp.cleanup()

    def test_metrics(self):
        res = run(self.root, self.no_matplotlib_env())
        self.assertEqual(res.returncode, 0, res.stderr)
        self.assertIn("figures skipped", res.stdout)
        with open(os.path.join(self.root, "comparison.json")) as f:
            data = json.load(f)
        self.assertEqual(data["planners"], ["hexplore", "slow"])
        hx, slow = data["metrics"]["hexplore"], data["metrics"]["slow"]
        self.assertAlmostEqual(hx["exploration_time_s"]["mean"], 250.0)
        self.assertAlmostEqual(slow["exploration_time_s"]["mean"], 500.0)
        # (500 - 250) / 500
        self.assertAlmostEqual(slow["reference_exploration_time_reduction_pct"], 50.0)
        self.assertAlmostEqual(hx["exploration_time_reduction_pct"]["slow"], 50.0)
        self.assertEqual(slow["end_reasons"], {"no task views remain": 1, "time limit": 1})
        self.assertAlmostEqual(hx["accumulated_completeness"]["mean"], 1.1)
        self.assertAlmostEqual(hx["trajectory_length_m"]["total"]["mean"], 150.0)
        self.assertAlmostEqual(slow["trajectory_length_m"]["per_robot"]["b"]["mean"], 150.0)
        self.assertAlmostEqual(hx["planning_time_s"]["mean"], 0.02)
        self.assertAlmostEqual(slow["planning_time_s"]["max"], 0.06)
        self.assertEqual(hx["planning_time_s"]["rounds"], 8)
        # Per robot: hexplore's map KB (100 + 80) / 2 = 90; rate per seed 90/200 and 90/300.
        c = hx["communication"]["incremental_map"]
        self.assertAlmostEqual(c["cumulative_kb_per_robot"]["mean"], 90.0)
        self.assertAlmostEqual(c["kb_per_s_per_robot"]["mean"], (90 / 200 + 90 / 300) / 2)
        self.assertAlmostEqual(slow["communication"]["exploration_route"]["cumulative_kb_per_robot"]["mean"], 0.0)
        self.assertAlmostEqual(hx["communication"]["total"]["cumulative_kb_per_robot"]["mean"], (117 + 97) / 2)
        # The busiest robot: a's 117 KB in seed 1's 200 s, above its mean.
        self.assertEqual(hx["busiest_robot_communication"], {"kb_per_s": 117 / 200, "robot": "a", "seed": 1})
        # Linear completeness: 0.5 observable reached at 0.5 / 1.0 of the way, on the 5-sample grid.
        self.assertEqual(hx["time_to_observable_completeness_s"]["0.5"]["n"], 2)
        with open(os.path.join(self.root, "comparison.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["planner"] for r in rows], ["hexplore", "slow"])
        self.assertAlmostEqual(float(rows[1]["reference_reduction_pct"]), 50.0)
        with open(os.path.join(self.root, "comparison.md")) as f:
            md = f.read()
        self.assertIn("| slow | 2 | 500.0 ± 141.4 | 50.0 % |", md)
        self.assertIn("censored", md)
        self.assertIn("| 0.585 (a, seed 1) |", md)
        self.assertFalse(os.path.exists(os.path.join(self.root, "figures")))

    def test_tail_is_the_time_spent_within_a_tenth_of_a_point_of_the_end(self):
        # slow's seed 1 (400 s): at 0.9 observable by 100 s, then +0.08 point in the last 300 s.
        with open(os.path.join(self.root, "slow", "seed-1", "completeness.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["sim_time_s", "team", "team_observable", "a", "b"])
            for t, obs in ((0, 0.0), (100, 0.9), (150, 0.9005), (400, 0.9008)):
                w.writerow([t, obs, obs, obs, obs])
        res = run(self.root, self.no_matplotlib_env())
        self.assertEqual(res.returncode, 0, res.stderr)
        with open(os.path.join(self.root, "comparison.json")) as f:
            tail = json.load(f)["metrics"]["slow"]["tail"]
        # Seed 1: reached at 100 s, tail 300 s (75 %); seed 2 (linear) reaches it at its end.
        self.assertAlmostEqual(tail["reached_s"]["min"], 100.0)
        self.assertAlmostEqual(tail["tail_s"]["max"], 300.0)
        self.assertAlmostEqual(tail["tail_s"]["min"], 0.0)
        self.assertAlmostEqual(tail["share_of_mission"]["max"], 0.75)
        with open(os.path.join(self.root, "comparison.md")) as f:
            self.assertIn("| slow | 350.0 ± 353.6 | 150.0 ± 212.1 | 37.5 ± 53.0 |", f.read())

    def test_figures_when_matplotlib_is_there(self):
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            self.skipTest("matplotlib not installed for " + sys.executable)
        res = run(self.root)
        self.assertEqual(res.returncode, 0, res.stderr)
        for name in ("completeness_vs_time", "trajectory_length", "accumulated_completeness", "planning_time"):
            for ext in ("png", "svg"):
                path = os.path.join(self.root, "figures", f"{name}.{ext}")
                self.assertTrue(os.path.getsize(path) > 1000, path)

    def test_empty_folder_is_an_error(self):
        empty = os.path.join(self.tmp.name, "empty")
        os.makedirs(empty)
        res = run(empty)
        self.assertEqual(res.returncode, 1)
        self.assertIn("no <planner>/seed-<n>/summary.json", res.stderr)

    def no_matplotlib_env(self):
        """An environment whose `import matplotlib` fails."""
        fake = os.path.join(self.tmp.name, "fake")
        os.makedirs(os.path.join(fake, "matplotlib"), exist_ok=True)
        with open(os.path.join(fake, "matplotlib", "__init__.py"), "w") as f:
            f.write("raise ImportError('matplotlib hidden by the test')\n")
        env = dict(os.environ)
        env["PYTHONPATH"] = fake + os.pathsep + env.get("PYTHONPATH", "")
        return env


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
