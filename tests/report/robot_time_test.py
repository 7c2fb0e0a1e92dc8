#!/usr/bin/env python3
"""tools/report/robot_time.py on a synthetic run whose figures are known: robot a drives 1 m
every 2 s for 10 s, then stands; its trace says it observed for 6 s of the 20 s mission; robot b
never moves and has no trace.
Usage: robot_time_test.py SCRIPT"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


class RobotTimeTest(unittest.TestCase):
    def test_moving_observing_and_standing(self):
        with tempfile.TemporaryDirectory() as root:
            run, trace = os.path.join(root, "run"), os.path.join(root, "trace")
            os.makedirs(run)
            os.makedirs(trace)
            with open(os.path.join(run, "summary.json"), "w") as f:
                json.dump({"exploration_time_s": 20.0}, f)
            with open(os.path.join(run, "trajectories.csv"), "w") as f:
                f.write("robot,sim_time_s,x_m,y_m,z_m\n")
                for i in range(6):
                    f.write(f"a,{2 * i},{i},0,0\n")
                f.write("a,20,5,0,0\n")
                f.write("b,0,9,9,0\nb,20,9,9,0\n")
            with open(os.path.join(trace, "planning-a.jsonl"), "w") as f:
                f.write(json.dumps({"t": 1, "follower": {"observing_s": 2.0}}) + "\n")
                f.write(json.dumps({"t": 19, "follower": {"observing_s": 6.0}}) + "\n")
            out = subprocess.run([sys.executable, SCRIPT, run, trace], capture_output=True, text=True,
                                 check=True).stdout
        self.assertIn("mission 20.0 s", out)
        self.assertIn("| a | 10 | 5 | 6 | 80 % | 4 |", out)
        self.assertIn("| b | 0 | 0 | - | 0 % | 20 |", out)

    def test_a_folder_without_a_run_is_an_error(self):
        with tempfile.TemporaryDirectory() as root:
            run = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("no summary.json", run.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
