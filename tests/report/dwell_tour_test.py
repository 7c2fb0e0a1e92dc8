#!/usr/bin/env python3
"""tools/report/dwell_tour.py on a synthetic run whose figures are known: robot a starts at the
origin, drives to (10, 0) and stands there 10 s, drives back to (1, 0) and stands there 10 s
(driven 19 m, visit-order tour 10 + 9 = 19 m, best tour 1 + 9 = 10 m); robot b stands 4 s only
(no dwell of 8 s).
Usage: dwell_tour_test.py SCRIPT"""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def write_run(root):
    run = os.path.join(root, "run")
    os.makedirs(run)
    with open(os.path.join(run, "trajectories.csv"), "w") as f:
        f.write("robot,sim_time_s,x_m,y_m,z_m\n")
        for t, x in ((0, 0), (2, 5), (4, 10), (14, 10), (16, 5.5), (18, 1), (28, 1)):
            f.write(f"a,{t},{x},0,0.4\n")
        f.write("b,0,3,3,0\nb,4,3,3,0\nb,6,4,3,0\n")
        f.write("a,not-a-number,0,0,0\n")  # a bad row is skipped
    return run


class DwellTourTest(unittest.TestCase):
    def test_driven_visit_order_and_best_tour(self):
        with tempfile.TemporaryDirectory() as root:
            run = write_run(root)
            out = subprocess.run([sys.executable, SCRIPT, run, "--segments"], capture_output=True, text=True,
                                 check=True).stdout
        self.assertIn("| a | 19 | 2 | 19 | 10 | 1.00 | 1.90 | 18 / 28 |", out)
        self.assertIn("| b | 1 | 0 | 0 | 0 | nan | nan | - / 6 |", out)
        self.assertIn("4-    18 s: driven     9 m, straight     9 m, (10, 0) -> (1, 0)", out)

    def test_unknown_robot_and_missing_run_are_errors(self):
        with tempfile.TemporaryDirectory() as root:
            run = write_run(root)
            unknown = subprocess.run([sys.executable, SCRIPT, run, "--robot", "c"], capture_output=True, text=True)
            missing = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        self.assertNotEqual(unknown.returncode, 0)
        self.assertIn("no robot 'c'", unknown.stderr)
        self.assertNotEqual(missing.returncode, 0)
        self.assertIn("no such file", missing.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
