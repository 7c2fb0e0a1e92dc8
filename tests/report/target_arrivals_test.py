#!/usr/bin/env python3
"""tools/report/target_arrivals.py on a synthetic open_targets.csv whose arrivals are known:
three reports of robot r1 (and one of r2, ignored). Between the second and third report,
key 1 gains a view after being occluded, key 2 reopens (absent, i.e. complete, in the second),
key 4 is new, and key 3 keeps the view it had; then new keys near a gone given-up target.
Usage: target_arrivals_test.py SCRIPT"""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None
HEADER = "sim_time_s,robot,key,x_m,y_m,z_m,facade,voxels,covered_voxels,gap,state,attempts\n"


def row(t, robot, key, state, voxels=20, covered=5, x=0.0):
    return f"{t},{robot},{key},{x},0,0,1,{voxels},{covered},angle,{state},0\n"


class TargetArrivalsTest(unittest.TestCase):
    def run_script(self, text, *args):
        with tempfile.TemporaryDirectory() as root:
            path = os.path.join(root, "open_targets.csv")
            with open(path, "w") as f:
                f.write(text)
            return subprocess.run([sys.executable, SCRIPT, path, *args], capture_output=True, text=True)

    def test_classifies_arrivals_by_origin(self):
        text = HEADER
        text += row(50, "r1", 2, "given_up") + row(50, "r1", 3, "has_view") + row(50, "r2", 9, "has_view")
        text += row(100, "r1", 1, "occluded") + row(100, "r1", 3, "has_view")
        text += (row(150, "r1", 1, "has_view", 30, 10) + row(150, "r1", 2, "has_view", 12, 8) +
                 row(150, "r1", 3, "has_view") + row(150, "r1", 4, "has_view", 8, 0))
        out = self.run_script(text, "--robot", "r1", "--since", "120")
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("arrivals after 120 s: 3", out.stdout)
        self.assertRegex(out.stdout, r"from_occluded\s+1\s+median open voxels\s+20")
        self.assertRegex(out.stdout, r"reopened\s+1\s+median open voxels\s+4")
        self.assertRegex(out.stdout, r"new\s+1\s+median open voxels\s+8")
        # Only the report after --since gets a line (the one at 100 s is the comparison base).
        self.assertEqual(out.stdout.count(" s  views "), 1)

    def test_a_new_key_where_a_given_up_target_was_is_told_apart(self):
        # Key 5 is given up at 50 s and gone at 100 s; key 6 (same class bits: 0) appears 0.5 m
        # from it, key 7 12 m away, key 8 beside it but of another facing (bit 60 set).
        facing = 1 << 60
        text = HEADER + row(50, "r1", 5, "given_up", x=10.0)
        text += row(100, "r1", 6, "has_view", x=10.5) + row(100, "r1", 7, "has_view", x=22.0)
        text += row(100, "r1", facing | 8, "has_view", x=10.2)
        out = self.run_script(text, "--robot", "r1")
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertRegex(out.stdout, r"new_where_given_up\s+1\s")
        self.assertRegex(out.stdout, r"\bnew\s+2\s")
        # Nearer than 0.4 m only: all three are plainly new.
        out = self.run_script(text, "--robot", "r1", "--near-m", "0.4")
        self.assertRegex(out.stdout, r"\bnew\s+3\s")
        self.assertNotIn("new_where_given_up", out.stdout)

    def test_needs_periodic_reports(self):
        out = self.run_script(HEADER + row(50, "r1", 1, "has_view"), "--robot", "r1")
        self.assertNotEqual(out.returncode, 0)
        self.assertIn("--open-targets-period-s", out.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
