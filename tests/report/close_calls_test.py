#!/usr/bin/env python3
"""tools/report/close_calls.py on synthetic safety traces whose figures are known: robot a
stops, yielding to b, while b's approved path leads away (+x) but b moves back (-x) towards a
in two steps of 0.1 m (the driver backing up); then, far apart, nothing.
Usage: close_calls_test.py SCRIPT"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def line(t, position, kind, reason, path, peer_id, peer_position, distance):
    return json.dumps({"t": t, "position": position, "kind": kind, "reason": reason, "yielding_to": "",
                       "detoured": False, "path": path,
                       "peers": [{"id": peer_id, "position": peer_position, "stationary": kind == "stop",
                                  "speed": 0.0, "distance": distance, "trail": 0, "yielding_to": ""}]}) + "\n"


def write_traces(root):
    with open(os.path.join(root, "safety-a.jsonl"), "w") as f:
        for t, d in ((10.0, 1.4), (10.2, 1.25), (10.4, 1.2)):
            f.write(line(t, [0, 0], "stop", "yield to b (crossing)", [], "b", [d, 0], d))
        f.write("{not json\n")
        f.write(line(50.0, [0, 0], "follow", "", [[0, 0], [0, 5]], "b", [9, 0], 9.0))
    with open(os.path.join(root, "safety-b.jsonl"), "w") as f:
        for t, x in ((10.0, 1.4), (10.2, 1.3), (10.4, 1.2)):
            f.write(line(t, [x, 0], "follow", "", [[x, 0], [x + 2, 0]], "a", [0, 0], x))


class CloseCallsTest(unittest.TestCase):
    def test_a_close_call_and_the_moves_nobody_approved(self):
        with tempfile.TemporaryDirectory() as root:
            write_traces(root)
            out = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True, check=True).stdout
        self.assertIn("1 close call(s) below 1.30 m", out)
        self.assertIn("(1 unreadable line(s) skipped)", out)
        self.assertIn("10.2-10.4 s: a and b, nearest 1.20 m", out)
        self.assertIn("a: stop: yield to b (crossing) x3", out)
        self.assertIn("10.20 s moved 0.10 m against its approved path", out)
        self.assertIn("10.40 s moved 0.10 m against its approved path", out)

    def test_unknown_robot_and_missing_traces_are_errors(self):
        with tempfile.TemporaryDirectory() as root:
            empty = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
            write_traces(root)
            unknown = subprocess.run([sys.executable, SCRIPT, root, "--robot", "c"], capture_output=True, text=True)
        self.assertNotEqual(empty.returncode, 0)
        self.assertIn("no safety-*.jsonl", empty.stderr)
        self.assertNotEqual(unknown.returncode, 0)
        self.assertIn("no robot 'c'", unknown.stderr)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
