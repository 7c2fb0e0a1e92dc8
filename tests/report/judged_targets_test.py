#!/usr/bin/env python3
"""tools/report/judged_targets.py on a synthetic trace whose figures are known: three judged
targets (one complete, two open by angle and density) over two rounds and one unreadable line.
Usage: judged_targets_test.py SCRIPT"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def judged(target, complete, gap, distance):
    return {"target": target, "complete": complete, "voxels": 10, "covered": 10 if complete else 4,
            "gap": gap, "distance_m": distance, "incidence_deg": 30.0, "elevation_deg": 10.0}


class JudgedTargetsTest(unittest.TestCase):
    def test_counts_shares_and_gaps(self):
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "planning-mr1.jsonl"), "w") as f:
                f.write(json.dumps({"t": 1, "judged": [judged(1, 1, "none", 12.0)]}) + "\n")
                f.write("not json\n")
                f.write(json.dumps({"t": 2, "judged": [judged(2, 0, "angle", 16.0), judged(3, 0, "density", 18.0)]}) + "\n")
            out = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True, check=True).stdout
        self.assertIn("mr1: 3 judged, 1 complete (33 %), 1 unreadable lines", out)
        self.assertIn("open by gap: angle 1, density 1", out)
        self.assertIn("complete distance m 12.0 / 12.0 / 12.0", out)
        self.assertIn("open     distance m 16.0 / 16.0 / 16.0", out)

    def test_an_empty_folder_is_an_error(self):
        with tempfile.TemporaryDirectory() as root:
            run = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("no planning-*.jsonl", run.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
