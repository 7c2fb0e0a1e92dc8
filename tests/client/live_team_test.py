#!/usr/bin/env python3
"""The Python client against a real team: starts deploy/teams/small-building.yaml (one
SLUGCAT, one MR1000, every service its own process) through hexplore_launch on free loopback
ports, on authenticated links (the team file's transport.curve_keys_dir: the launcher makes the
keys, the client uses the station's pair), and checks that

- `watch` sees every robot's pose (robot/<id>/pose, and team/pose through the client's own
  decoder of the radio codec, matching the sim's pose of the same instant to the centimetre),
  every service's status, the mission time, planning rounds and nonzero byte rates;
- `send planner=no-mnss` is relayed by the station and every planning service reports the new
  planner; an unknown planner name is relayed but not adopted, and the client says so (exit 3);
- `send estop` halts every robot (EMERGENCY_STOP) and `send start` releases them;
- a team that is not there is reported (exit 1) by both commands.

usage: live_team_test.py LAUNCHER TEAM_FILE CLIENT_DIR PB_DIR
Exit 77 (ctest skip) when this interpreter lacks zmq or protobuf (scripts/install_deps.sh).
"""
import json
import os
import pathlib
import random
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

SKIP = 77
PORTS_PER_ROBOT = 20


def port_free(port):
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(("127.0.0.1", port))
            return True
        except OSError:
            return False


def pick_base(slots, avoid=()):
    """A base port below the kernel's ephemeral range (where outgoing connections could take
    one of ours between this check and the bind) whose every derived port is free."""
    try:
        low_ephemeral = int(pathlib.Path("/proc/sys/net/ipv4/ip_local_port_range").read_text().split()[0])
    except (OSError, ValueError, IndexError):
        low_ephemeral = 32768
    span = slots * PORTS_PER_ROBOT
    for _ in range(200):
        base = random.randrange(20000, low_ephemeral - span, 100)
        if base not in avoid and all(port_free(base + i) for i in range(span)):
            return base
    sys.exit("no free port range on 127.0.0.1")


class Failed(Exception):
    pass


def expect(ok, what):
    if not ok:
        raise Failed(what)


def main(argv):
    if len(argv) != 5:
        sys.exit(__doc__)
    launcher, team_file, client_dir, pb_dir = argv[1:]
    try:
        import google.protobuf  # noqa: F401
        import zmq  # noqa: F401
    except ImportError as e:
        print(f"SKIP: {sys.executable} lacks {e.name} (Debian's python3-zmq and python3-protobuf)")
        return SKIP
    text = pathlib.Path(team_file).read_text()
    robots = re.findall(r"^\s*- id: (\S+)", text, re.M)
    base = pick_base(len(robots) + 1)
    nobody = pick_base(len(robots) + 1, avoid=(base,))
    work = pathlib.Path(tempfile.mkdtemp(prefix="hexplore-client-"))
    team = work / "team.yaml"
    def with_base(port):  # transport.base_port only (metrics_base_port stays 0: metrics off)
        return re.sub(r"^(\s+)base_port: \d+", rf"\g<1>base_port: {port}", text, flags=re.M)

    # The test ends the team itself: the time limit is only a safety net.
    team.write_text(re.sub(r"^time_limit_s: .*$", "time_limit_s: 600", with_base(base), flags=re.M))
    absent = work / "absent.yaml"
    absent.write_text(with_base(nobody))
    env = dict(os.environ, PYTHONPATH=client_dir, HEXPLORE_PB_DIR=pb_dir)

    def client(*args, timeout=30):
        started = time.monotonic()
        r = subprocess.run([sys.executable, "-m", "hexplore_client", *args], env=env, capture_output=True,
                           text=True, timeout=timeout)
        print(f"$ hexplore_client {' '.join(args)}  -> exit {r.returncode} after {time.monotonic() - started:.1f} s")
        for line in (r.stdout if "--json" not in args else "").splitlines() + r.stderr.splitlines():
            print(f"    {line}")
        return r

    def snapshot(*args):
        r = client("watch", "--config", str(team), "--once", "--json", *args)
        expect(r.returncode == 0, f"watch exited {r.returncode}: {r.stderr.strip()}")
        return json.loads(r.stdout.strip().splitlines()[-1])

    # Sim seconds per wall second; a sanitizer build keeps up only at 1 (HEXPLORE_TEST_RTF=1).
    rtf = os.environ.get("HEXPLORE_TEST_RTF", "3")
    log = open(work / "launch.log", "w")
    team_process = subprocess.Popen(
        [launcher, "--config", str(team), "--log-dir", str(work / "logs"),
         "--child-args", f"--results {work / 'results'} --real-time-factor {rtf} --report false"],
        stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    ok = False
    try:
        start = time.monotonic()
        # 1. Watch: every robot, every service, poses both ways, planning rounds, byte rates. The
        # 10 s window opens once every sender is heard: a slow start (a loaded machine, a
        # sanitizer build) must not eat into it.
        for _ in range(20):
            warm = snapshot("--window", "3")
            if len(warm["senders_heard"]) == warm["senders_expected"] and (warm["mission_time_s"] or 0) > 0:
                break
        s = snapshot("--window", "10")
        # The team file names transport.curve_keys_dir: the launcher made the keys, and the client
        # watches and commands over CURVE with the station's pair.
        expect((work / "keys" / "small-building" / "station.secret").exists(),
               "no keys in the team's folder: the team did not run on authenticated links")
        expect(len(s["senders_heard"]) == s["senders_expected"],
               f"heard {s['senders_heard']}, expected {s['senders_expected']} senders")
        expect((s["mission_time_s"] or 0) > 0, "no mission time from the station's status")
        for rid in robots:
            r = s["robots"][rid]
            expect(r["pose"] is not None, f"{rid}: no robot/{rid}/pose")
            expect(r["team_pose"] is not None, f"{rid}: no team/pose decoded")
            expect(r["team_pose_matches"] > 0 and r["team_pose_error_m"] < 0.01,
                   f"{rid}: team/pose vs the sim's pose: {r['team_pose_matches']} matches, "
                   f"error {r['team_pose_error_m']} m")
            expect(set(r["services"]) == {"sim", "mapping", "hlmap", "planning", "safety"},
                   f"{rid}: statuses of {sorted(r['services'])}")
            expect(r["planner"] == "hexplore", f"{rid}: planner {r['planner']}")
            for topic in (f"robot/{rid}/pose", f"robot/{rid}/status"):
                expect(s["topics"].get(topic, {}).get("bytes_per_s", 0) > 0, f"no bytes/s on {topic}")
        expect(any((s["robots"][rid]["round"] or 0) > 0 for rid in robots), "no planning round reported")
        for topic in ("team/pose", "team/map"):
            expect(s["topics"].get(topic, {}).get("bytes_per_s", 0) > 0, f"no bytes/s on {topic}")
        expect(not s["dropped"], f"frames not decoded: {s['dropped']}")

        # 2. A known planner is adopted by every planning service.
        r = client("send", "planner=no-mnss", "--config", str(team))
        expect(r.returncode == 0 and "confirmed" in r.stdout, f"planner switch: exit {r.returncode}")
        expect("seen on team/mission" in r.stdout, "the station's relay not seen on team/mission")
        s = snapshot("--window", "2")
        expect(all(s["robots"][rid]["planner"] == "no-mnss" for rid in robots), "planner not no-mnss in watch")

        # 3. An unknown one is relayed, ignored by the team, and reported as not adopted.
        r = client("send", "planner=no-such-planner", "--config", str(team), "--confirm-s", "3")
        expect(r.returncode == 3 and "not confirmed" in r.stderr, f"unknown planner: exit {r.returncode}")
        expect(r.stdout.count("NOT planner no-mnss") == len(robots), "the unknown planner's report")

        # 4. Emergency stop, then start.
        r = client("send", "estop", "--config", str(team))
        expect(r.returncode == 0 and "confirmed" in r.stdout, f"estop: exit {r.returncode}")
        s = snapshot("--window", "1.5")
        for rid in robots:
            expect(s["robots"][rid]["pose"]["state"] == "EMERGENCY_STOP", f"{rid} after estop: "
                   f"{s['robots'][rid]['pose']['state']}")
        r = client("send", "start", "--config", str(team))
        expect(r.returncode == 0 and "confirmed" in r.stdout, f"start: exit {r.returncode}")

        # 5. Nobody there.
        r = client("send", "stop", "--config", str(absent), "--timeout", "1", "--confirm-s", "0")
        expect(r.returncode == 1 and "no station answered" in r.stderr, f"absent station: exit {r.returncode}")
        r = client("watch", "--config", str(absent), "--duration", "2", "--period", "5")
        expect(r.returncode == 1 and "no pose heard" in r.stderr, f"absent team: exit {r.returncode}")

        expect(team_process.poll() is None, f"the team ended early (exit {team_process.returncode})")
        print(f"PASS after {time.monotonic() - start:.1f} s")
        ok = True
    except (Failed, subprocess.TimeoutExpired, json.JSONDecodeError) as e:
        print(f"FAIL: {e}")
        print("--- launch.log (tail)")
        print("\n".join((work / "launch.log").read_text().splitlines()[-30:]))
    finally:
        if team_process.poll() is None:
            team_process.send_signal(signal.SIGTERM)  # the launcher stops its children
            try:
                team_process.wait(15)
            except subprocess.TimeoutExpired:
                os.killpg(team_process.pid, signal.SIGKILL)
                team_process.wait()
        log.close()
        if ok:
            shutil.rmtree(work, ignore_errors=True)
        else:
            print(f"logs kept in {work}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
