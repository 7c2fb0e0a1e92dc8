#!/usr/bin/env python3
"""tools/report/route_churn.py on a synthetic trace and open-target report whose figures are
known: three rounds whose route heads jump 0 m and 10 m while the follower's heading moves 0 m and
3 m, one reference flip, and target flows
(one completed, one given up, one back from occluded, one new), and the rounds whose route holds
a view inside an area (--area).
Usage: route_churn_test.py SCRIPT"""

import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def round_line(t, head, reference, heading=None):
    line = {"t": t, "reason": "route timed out", "reference": reference,
            "route": [{"p": head + [0.0], "facade": 1, "targets": 1}]}
    if heading is not None:
        line["follower"] = {"next": [heading + [0.0]]}
    return json.dumps(line)


class RouteChurnTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        root = self.dir.name
        with open(os.path.join(root, "planning-r1.jsonl"), "w") as f:
            f.write(round_line(0.0, [0.0, 0.0], "r1", [0.0, 0.0]) + "\n")
            f.write(round_line(10.0, [0.0, 0.0], "r1", [0.0, 0.0]) + "\n")
            f.write("not json\n")
            f.write(round_line(20.0, [6.0, 8.0], "r2", [0.0, 3.0]) + "\n")
        with open(os.path.join(root, "open_targets.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["sim_time_s", "robot", "key", "state"])
            for key, state in [("1", "has_view"), ("2", "has_view"), ("3", "occluded")]:
                w.writerow(["60.0", "r1", key, state])
            for key, state in [("2", "given_up"), ("3", "has_view"), ("4", "has_view")]:
                w.writerow(["120.0", "r1", key, state])

    def tearDown(self):
        self.dir.cleanup()

    def run_script(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)

    def test_area(self):
        out = self.run_script(self.dir.name, "--area", "7,9,5,7")  # corners in any order
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("area x 5..7, y 7..9: in 1 of 3 rounds' routes, first at 20.0 s; views there 1-1, "
                      "the first of them at route position median 0 (min 0, max 0) of 1-1", out.stdout)
        out = self.run_script(self.dir.name, "--area", "40,40,41,41")
        self.assertIn("area x 40..41, y 40..41: in no round's route", out.stdout)
        bad = self.run_script(self.dir.name, "--area", "1,2,3")
        self.assertNotEqual(bad.returncode, 0)
        self.assertIn("--area: expected X0,Y0,X1,Y1", bad.stderr)

    def test_figures(self):
        out = self.run_script(self.dir.name, self.dir.name)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("r1: 3 rounds, mean 10.0 s apart", out.stdout)
        self.assertIn("route-head jump (m): median 0.0, p90 10.0, max 10.0; 1 of 2 rounds (50 %) moved it more than 5 m",
                      out.stdout)
        # The follower kept its heading within 3 m while the planner's head jumped 10 m.
        self.assertIn("heading (follower) jump (m): median 0.0, p90 3.0, max 3.0; 0 of 2 rounds (0 %)", out.stdout)
        self.assertIn("another robot than the round before: 1 of 2 rounds", out.stdout)
        self.assertIn("has_view     2 | left    2 (complete 1, given_up 1) | came back    1 (occluded 1) | new    1",
                      out.stdout)
        self.assertIn("not JSON", out.stderr)  # a broken line is reported and skipped

    def test_threshold_option(self):
        out = self.run_script(self.dir.name, "--jump-m", "20")
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("0 of 2 rounds (0 %) moved it more than 20 m", out.stdout)

    def test_missing_traces(self):
        with tempfile.TemporaryDirectory() as empty:
            out = self.run_script(empty)
        self.assertEqual(out.returncode, 1)
        self.assertIn("no planning-*.jsonl", out.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
