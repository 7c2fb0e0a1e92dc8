#!/usr/bin/env python3
"""tools/report/plan_horizon.py on a synthetic trace whose figures are known: two robots, rounds
every 100 s to 1,000 s, a plan that shrinks by 200 s per round, plus an unreadable line and a
round without a team solution. Usage: plan_horizon_test.py SCRIPT"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def round_line(t, planned):
    return json.dumps({"t": t, "open_views": int(planned / 10), "cost_s_per_robot": [planned, planned / 2]}) + "\n"


class PlanHorizonTest(unittest.TestCase):
    def test_samples_and_thresholds(self):
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "planning-a.jsonl"), "w") as f:
                for t in range(100, 1001, 100):
                    f.write(round_line(t, max(2000 - 200 * (t // 100), 50)))
                f.write("cut off mid-li")
            with open(os.path.join(root, "planning-b.jsonl"), "w") as f:
                f.write(json.dumps({"t": 150, "open_views": 0, "cost_s_per_robot": []}) + "\n")
            out = subprocess.run([sys.executable, SCRIPT, root, "--every", "300", "--thresholds", "1000,10"],
                                 capture_output=True, text=True, check=True).stdout
        # At 300 s the plan is 2000 - 600 = 1400 s; the mission ends at 1,000 s, 700 s later.
        self.assertIn("| 300 | 140 | 1400 | 700 |", out)
        self.assertIn("| 900 | 20 | 200 | 100 |", out)
        # 2000 - 200 * 6 = 800 < 1000 first at 600 s, 400 s before the end.
        self.assertIn("plan under 1000 s first at 600 s; the mission went on 400 s (end 1000 s)", out)
        self.assertIn("plan under 10 s: never", out)

    def test_no_team_solution_is_an_error(self):
        with tempfile.TemporaryDirectory() as root:
            run = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("no planning rounds with a team solution", run.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
