#!/usr/bin/env python3
"""tools/report/tail_work.py on a synthetic run whose tail is known: the team reaches 97 % at
100 s, the mission ends at 200 s; the robot's rounds at 90, 150 and 180 s (the last with an
empty route) drive 30 m and reach 6 views after 100 s.
Usage: tail_work_test.py SCRIPT"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def round_line(t, odometry, reached, judged, complete, given_up, route):
    return json.dumps({"t": t, "odometry_m": odometry, "open_views": 40, "given_up": given_up,
                       "route": [{"p": [0, 0, 0], "facade": 1, "targets": 1}] * route,
                       "follower": {"reached": reached, "targets_judged": judged,
                                    "targets_complete_when_judged": complete, "skipped": 1}})


class TailWorkTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        results = os.path.join(self.dir.name, "results", "hexplore", "seed-3")
        traces = os.path.join(self.dir.name, "traces", "hexplore", "seed-3")
        os.makedirs(results)
        os.makedirs(traces)
        with open(os.path.join(results, "completeness.csv"), "w") as f:
            f.write("sim_time_s,team,team_observable\n0,0.1,0.2\n50,0.8,0.9\n100,0.9,0.97\n200,0.91,0.98\n")
        with open(os.path.join(results, "summary.json"), "w") as f:
            json.dump({"exploration_time_s": 200.0}, f)
        with open(os.path.join(traces, "planning-r1.jsonl"), "w") as f:
            f.write(round_line(90, 10.0, 4, 5, 2, 7, 3) + "\n")
            f.write(round_line(150, 25.0, 8, 9, 4, 9, 2) + "\n")
            f.write("cut off\n")
            f.write(round_line(180, 40.0, 10, 11, 5, 12, 0) + "\n")

    def tearDown(self):
        self.dir.cleanup()

    def run_script(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)

    def test_tail_figures(self):
        out = self.run_script(os.path.join(self.dir.name, "results"), os.path.join(self.dir.name, "traces"))
        self.assertEqual(out.returncode, 0, out.stderr)
        row = [line for line in out.stdout.splitlines() if "| r1 |" in line]
        self.assertEqual(len(row), 1, out.stdout)
        # 97 % at 100 s, end 200 s; from the round at 90 s: 30 m, 6 views (5.0 m each), 6 judged (3
        # complete), 0 skipped, 2 rounds after 100 s, route empty from 180 to 200 s, +5 given up.
        self.assertEqual(row[0], "| hexplore | 3 | 100 s | 200 s | r1 | 40 | 30 m | 6 | 5.0 | 6 (3) | 0 | 2 | 20 s | +5 |")

    def test_level_never_reached(self):
        out = self.run_script(os.path.join(self.dir.name, "results"), os.path.join(self.dir.name, "traces"),
                              "--level", "0.99")
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("| hexplore | 3 | never | 200 s |", out.stdout)

    def test_nothing_to_read(self):
        out = self.run_script(self.dir.name, self.dir.name)
        self.assertNotEqual(out.returncode, 0)
        self.assertIn("no run with both results and traces", out.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
