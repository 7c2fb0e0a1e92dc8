#!/usr/bin/env python3
"""tools/report/cross_level_holds.py on synthetic traces whose figures are known: robot a stands
on the storey above b (4.2 m against 0.2 m) and c (0.2 m, beside b). a yields to b for 5 s, then
detours round b (the nearest stopped teammate it lists) for 2 s; b yields to c for 3 s (same
storey: not counted).
Usage: cross_level_holds_test.py SCRIPT"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def decision(t, reason="", yielding_to="", detoured=False, peers=()):
    return json.dumps({"t": t, "position": [0, 0], "kind": "follow", "reason": reason, "yielding_to": yielding_to,
                       "detoured": detoured, "path": [],
                       "peers": [{"id": i, "position": [d, 0], "stationary": True, "speed": 0.0, "distance": d,
                                  "trail": 0, "yielding_to": ""} for i, d in peers]}) + "\n"


def write_traces(root):
    for robot, z in (("a", 4.2), ("b", 0.2), ("c", 0.2)):
        with open(os.path.join(root, f"planning-{robot}.jsonl"), "w") as f:
            for t in (0.0, 10.0, 20.0):
                f.write(json.dumps({"t": t, "position": [0.0, 0.0, z]}) + "\n")
    with open(os.path.join(root, "safety-a.jsonl"), "w") as f:
        f.write(decision(10.0, "yield to b (following)", "b"))
        f.write(decision(15.0, detoured=True, peers=(("c", 2.5), ("b", 1.0))))
        f.write(decision(17.0))
        f.write("{not json\n")
    with open(os.path.join(root, "safety-b.jsonl"), "w") as f:
        f.write(decision(10.0, "yield to c (crossing)", "c"))
        f.write(decision(13.0))


class CrossLevelHoldsTest(unittest.TestCase):
    def test_holds_by_a_teammate_on_another_storey_are_summed_and_others_are_not(self):
        with tempfile.TemporaryDirectory() as root:
            write_traces(root)
            out = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True, check=True).stdout
        self.assertIn("a: 7.0 s held by a teammate on another storey: b (yield to b) 5.0 s, b (detour) 2.0 s", out)
        self.assertIn("b: 0.0 s held by a teammate on another storey", out)
        self.assertIn("(1 unreadable line(s) skipped)", out)

    def test_a_folder_without_traces_is_an_error(self):
        with tempfile.TemporaryDirectory() as root:
            empty = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        self.assertNotEqual(empty.returncode, 0)
        self.assertIn("needs safety-*.jsonl and planning-*.jsonl", empty.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
