#!/usr/bin/env python3
"""tools/report/run_report.py on synthetic results folders: one run, and a seeds folder of two
runs (as hexplore_experiment writes it); a malformed map file is an error that names it.
The figures need matplotlib; without it the script must say so and exit 3.
Usage: run_report_test.py SCRIPT"""

import csv
import json
import os
import struct
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def write_ply(path, points):
    """A binary PLY laid out as PCL writes one (x, y, z floats, then red, green, blue)."""
    header = ("ply\nformat binary_little_endian 1.0\ncomment PCL generated\n"
              f"element vertex {len(points)}\nproperty float x\nproperty float y\nproperty float z\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\nelement camera 1\n"
              "property float view_px\nend_header\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        for x, y, z in points:
            f.write(struct.pack("<fffBBB", x, y, z, 10, 20, 30))
        f.write(struct.pack("<f", 0.0))


def write_run(d, seed, final):
    os.makedirs(d)
    summary = {"scene": "yard", "planner": "hexplore", "mode": "lockstep", "seed": seed,
               "end_reason": "time limit", "exploration_time_s": 100.0,
               "robots": {"a": {"species": "SLUGCAT", "trajectory_length_m": 12.0},
                          "b": {"species": "MR1000", "trajectory_length_m": 30.0}}}
    with open(os.path.join(d, "summary.json"), "w") as f:
        json.dump(summary, f)
    with open(os.path.join(d, "completeness.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["sim_time_s", "team", "team_observable", "a", "b"])
        for i in range(6):
            w.writerow([20 * i, final * i / 5, min(1.0, 1.1 * final) * i / 5, 0.5 * final * i / 5, 0.7 * final * i / 5])
    with open(os.path.join(d, "trajectories.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["robot", "sim_time_s", "x_m", "y_m", "z_m"])
        for i in range(10):
            w.writerow(["a", i, i, 0, 0])
            w.writerow(["b", i, 0, i, 0])
    with open(os.path.join(d, "open_targets.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["sim_time_s", "robot", "key", "x_m", "y_m", "z_m", "facade", "voxels", "covered_voxels", "gap",
                    "state", "attempts"])
        w.writerow([50, "a", 1, 3, 3, 1, 1, 10, 2, "angle", "has_view", 0])  # an earlier report: not drawn
        w.writerow([100, "a", 2, 4, 4, 1, 1, 10, 2, "angle", "given_up", 2])
        w.writerow([100, "b", 2, 4, 4, 1, 1, 10, 2, "angle", "given_up", 2])
    write_ply(os.path.join(d, "map.ply"), [(x * 0.5, y * 0.5, (x + y) * 0.1) for x in range(20) for y in range(20)])


def run(folder):
    return subprocess.run([sys.executable, SCRIPT, folder], capture_output=True, text=True)


def has_matplotlib():
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
        return True
    except ImportError:
        return False


class RunReport(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_one_run_gets_its_figures_and_report(self):
        d = os.path.join(self.root, "run")
        write_run(d, 1, 0.8)
        r = run(d)
        if not has_matplotlib():
            self.assertEqual(r.returncode, 3, r.stderr)
            self.assertIn("python3-matplotlib", r.stderr)
            return
        self.assertEqual(r.returncode, 0, r.stderr)
        for name in ("completeness.png", "completeness.svg", "topdown.png", "topdown.svg", "report.md"):
            self.assertGreater(os.path.getsize(os.path.join(d, name)), 100, name)
        with open(os.path.join(d, "report.md")) as f:
            report = f.read()
        self.assertIn("| 1 | time limit | 100 | 80.0 | 88.0 | a 12 m, b 30 m |", report)
        self.assertIn("![topdown.png](topdown.png)", report)
        with open(os.path.join(d, "topdown.svg")) as f:
            svg = f.read()
        self.assertIn("open: given_up (1)", svg)   # the latest report of the first robot only
        self.assertNotIn("open: has_view", svg)

    def test_a_seeds_folder_gets_every_seed_and_the_spread(self):
        for seed, final in ((1, 0.6), (2, 0.9)):
            write_run(os.path.join(self.root, f"seed-{seed}"), seed, final)
        with open(os.path.join(self.root, "summary.json"), "w") as f:
            json.dump({"runs": 2}, f)  # the experiment's summary over the seeds is not a run
        if not has_matplotlib():
            self.skipTest("matplotlib is not installed")
        r = run(self.root)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("2 run(s)", r.stdout)
        self.assertGreater(os.path.getsize(os.path.join(self.root, "completeness_seeds.png")), 100)
        for seed in (1, 2):
            self.assertTrue(os.path.exists(os.path.join(self.root, f"seed-{seed}", "topdown.png")))
        with open(os.path.join(self.root, "report.md")) as f:
            report = f.read()
        self.assertIn("| 2 | time limit | 100 | 90.0 |", report)
        self.assertIn("(seed-2/topdown.png)", report)

    def test_a_map_file_it_cannot_read_is_named(self):
        if not has_matplotlib():
            self.skipTest("matplotlib is not installed")
        d = os.path.join(self.root, "run")
        write_run(d, 1, 0.8)
        with open(os.path.join(d, "map.ply"), "w") as f:
            f.write("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n")
        r = run(d)
        self.assertEqual(r.returncode, 1)
        self.assertIn("map.ply: format ascii is not supported", r.stderr)

    def test_a_folder_without_runs_is_an_error(self):
        r = run(self.root)
        if r.returncode == 3:  # no matplotlib: said before looking
            return
        self.assertEqual(r.returncode, 1)
        self.assertIn("no summary.json", r.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
