#!/usr/bin/env python3
"""Observability end to end: starts a short two-robot team (one SLUGCAT, one MR1000) on
loopback with metrics on, starts a real Prometheus server scraping every service, and checks
through Prometheus's HTTP API that every PromQL expression of the dashboards parses and
returns data, and that the team makes progress (PROGRESS: mission started, completeness
measured, a robot moving).

usage: live_observability_test.py SOURCE_DIR PROMETHEUS_BIN service=EXECUTABLE...
       (service: sim, mapping, hlmap, planning, safety, station)

To see the rejected-messages panels fed, one malformed request is sent to a ROUTER socket
with a minimal ZMTP 3 client. Messages *lost* in transport (fault injection, time-outs, full
queues) and scans the mapping service refuses do not happen in a healthy run, so those
expressions only have to parse. Exit 77
(ctest skip) when Prometheus or an executable is missing.
"""
import json
import os
import pathlib
import random
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.parse
import urllib.request

SKIP = 77
ROBOT_SERVICES = ["sim", "mapping", "hlmap", "planning", "safety"]
SERVICE_INDEX = {"sim": 0, "mapping": 1, "hlmap": 2, "planning": 3, "safety": 4, "station": 5}
PORTS_PER_ROBOT = 20
ROBOTS = [("slugcat1", "SLUGCAT", "[17.0, 2.0, 0.0]"), ("mr1000a", "MR1000", "[21.0, 2.0, 0.0]")]
RATE_WINDOW = "15s"          # stands in for Grafana's $__rate_interval at a 1 s scrape interval
# Expressions about things a healthy run does not do: they only have to parse.
EVENTS_OF_A_FAULTY_RUN = ("fault_injected", "hexplore_mapping_scans_rejected_total")
# From the first service start to the last expression with data; HEXPLORE_TEST_TIME_SCALE
# stretches it for slow builds (a sanitizer build needs about 3).
DEADLINE_S = 45.0 * float(os.environ.get("HEXPLORE_TEST_TIME_SCALE", "1"))
# The team really runs, not only exports zeros: the station started the mission and its first
# snapshot round measured completeness, and a robot moved.
PROGRESS = {
    "progress: the station started the mission": "max(hexplore_station_mission_started) == 1",
    "progress: team completeness measured": 'max(hexplore_station_completeness_ratio{scope="team"}) > 0',
    "progress: every robot's own completeness measured": f"count(hexplore_station_robot_completeness_ratio > 0) == {len(ROBOTS)}",
    "progress: a robot is moving": 'max(hexplore_sim_motion_state{state="moving"}) == 1',
}


def port_free(port):
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(("127.0.0.1", port))
            return True
        except OSError:
            return False


def ephemeral_range():
    """The kernel's range for the local ports of outgoing connections (Linux default 32768-60999)."""
    try:
        low, high = map(int, pathlib.Path("/proc/sys/net/ipv4/ip_local_port_range").read_text().split())
        return low, high
    except (OSError, ValueError):
        return 32768, 60999


def pick_ports():
    """A transport base, a metrics base and a Prometheus port whose every derived port is free.

    All of them lie below the kernel's ephemeral range: a port inside it can be taken, between
    our check and our bind, by the local end of any outgoing connection (the services connect to
    each other and Prometheus scrapes them), and then Prometheus or a service fails to bind."""
    slots = len(ROBOTS) + 1
    span = slots * PORTS_PER_ROBOT + 10 + slots * 10 + 10 + 1
    low = 20000
    high = min(ephemeral_range()[0], 65536) - span
    if high <= low:
        low, high = 10000, 20000 - span
    for _ in range(200):
        base = random.randrange(low, high, 100)
        metrics = base + slots * PORTS_PER_ROBOT + 10
        prom = metrics + slots * 10 + 10
        wanted = [base + i for i in range(slots * PORTS_PER_ROBOT)]
        wanted += [metrics + slot * 10 + i for slot in range(slots) for i in range(6)] + [prom]
        if all(port_free(p) for p in wanted):
            return base, metrics, prom
    sys.exit("no free port range found on 127.0.0.1")


def team_yaml(base, metrics):
    robots = "".join(f"  - id: {rid}\n    species: {species}\n    start: {start}\n    yaw_deg: 90\n"
                     for rid, species, start in ROBOTS)
    return (f"# written by tests/rig/live_observability_test.py: two robots of the multi-building team\n"
            f"scene: multi-building\ntime_limit_s: 600\nmetrics_base_port: {metrics}\n"
            f"exploration_region:\n  min: [-1.0, -1.0, -0.5]\n  max: [40.4, 40.4, 14.0]\n"
            f"species:\n  - builtin: SLUGCAT\n  - builtin: MR1000\nrobots:\n{robots}"
            f"transport:\n  scheme: tcp\n  host_template: 127.0.0.1\n  base_port: {base}\n"
            f"  ports_per_robot: {PORTS_PER_ROBOT}\n  linger_ms: 100\nparams:\n  seed: 1\n")


def targets(metrics):
    """(robot, service, metrics port) of every process."""
    out = [(rid, s, metrics + slot * 10 + SERVICE_INDEX[s]) for slot, (rid, _, _) in enumerate(ROBOTS)
           for s in ROBOT_SERVICES]
    out.append(("station", "station", metrics + len(ROBOTS) * 10 + SERVICE_INDEX["station"]))
    return out


def prometheus_yml(metrics):
    jobs = []
    for robot, service, port in targets(metrics):
        jobs.append(f"  - job_name: {robot}-{service}\n    honor_labels: true\n    static_configs:\n"
                    f"      - targets: ['127.0.0.1:{port}']\n        labels: {{robot: {robot}, service: {service}}}\n")
    return "global:\n  scrape_interval: 1s\n  scrape_timeout: 900ms\nscrape_configs:\n" + "".join(jobs)


def send_malformed_request(port):
    """Speaks just enough ZMTP 3.0 (NULL mechanism, DEALER) to hand a ROUTER a one-frame request."""
    with socket.create_connection(("127.0.0.1", port), timeout=3) as s:
        greeting = b"\xff" + b"\x00" * 8 + b"\x7f" + b"\x03\x00" + b"NULL".ljust(20, b"\x00") + b"\x00" + b"\x00" * 31
        s.sendall(greeting)
        received = b""
        while len(received) < 64:
            chunk = s.recv(64 - len(received))
            if not chunk:
                raise ConnectionError("ROUTER closed the connection during the greeting")
            received += chunk
        prop = b"\x0bSocket-Type" + struct.pack(">I", 6) + b"DEALER"
        body = b"\x05READY" + prop
        s.sendall(b"\x04" + bytes([len(body)]) + body)
        s.sendall(b"\x00\x07garbage")  # one frame: the ROUTER sees [id][garbage], not [id][][header][payload]
        time.sleep(0.3)


def dashboard_expressions(source):
    out = []
    for f in sorted((source / "dashboards").glob("*.json")):
        d = json.loads(f.read_text())
        for p in d.get("panels", []):
            for t in p.get("targets", []):
                expr = t["expr"].replace("$__rate_interval", RATE_WINDOW).replace('"$robot"', '".*"')
                out.append((f"{f.name}: '{p['title']}' {t['refId']}", expr))
    return out


def query(prom_port, expr):
    url = f"http://127.0.0.1:{prom_port}/api/v1/query?" + urllib.parse.urlencode({"query": expr})
    try:
        with urllib.request.urlopen(url, timeout=5) as r:
            return json.loads(r.read())
    except urllib.error.HTTPError as e:
        return json.loads(e.read() or b"{}") or {"status": "error", "error": str(e)}


def targets_up(prom_port):
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{prom_port}/api/v1/targets", timeout=3) as r:
            active = json.loads(r.read())["data"]["activeTargets"]
        return sum(t["health"] == "up" for t in active), len(active)
    except (urllib.error.URLError, OSError, KeyError, ValueError):
        return 0, -1


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    source, prometheus = pathlib.Path(argv[1]), argv[2]
    exes = {k: os.path.abspath(v) for k, v in (a.split("=", 1) for a in argv[3:])}
    missing = [s for s in ROBOT_SERVICES + ["station"] if not os.path.isfile(exes.get(s, ""))]
    if not os.path.isfile(prometheus) or missing:
        print(f"SKIP: needs prometheus and every service executable (missing: {missing or prometheus})")
        return SKIP
    base, metrics, prom_port = pick_ports()
    work = pathlib.Path(tempfile.mkdtemp(prefix="hexplore-live-"))
    (work / "team.yaml").write_text(team_yaml(base, metrics))
    (work / "prometheus.yml").write_text(prometheus_yml(metrics))
    processes = []
    keep_logs = False
    try:
        start = time.monotonic()
        # Prometheus first: its port must be ours before the services open connections.
        log = open(work / "prometheus.log", "w")
        processes.append(("prometheus", subprocess.Popen(
            [prometheus, f"--config.file={work / 'prometheus.yml'}", f"--storage.tsdb.path={work / 'tsdb'}",
             f"--web.listen-address=127.0.0.1:{prom_port}"], stdout=log, stderr=subprocess.STDOUT)))
        for robot, service, _ in targets(metrics):
            cmd = [exes[service], "--config", str(work / "team.yaml"), "--robot", robot, "--log-level", "warn"]
            log = open(work / f"{robot}-{service}.log", "w")
            processes.append((f"{robot}-{service}", subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, cwd=work)))
        expected = len(targets(metrics))
        while time.monotonic() - start < DEADLINE_S:
            dead = [(n, p.returncode) for n, p in processes if p.poll() is not None]
            if dead:
                keep_logs = True
                tail = (work / "prometheus.log").read_text()[-1500:] if any(n == "prometheus" for n, _ in dead) else ""
                raise RuntimeError(f"exited early: {dead}; logs in {work}" + (f"\nprometheus.log ends:\n{tail}" if tail else ""))
            up, total = targets_up(prom_port)
            if up == expected:
                break
            time.sleep(0.5)
        else:
            keep_logs = True
            raise RuntimeError(f"only {up} of {expected} scrape targets came up in {DEADLINE_S:.0f} s; logs in {work}")
        print(f"all {expected} services scraped after {time.monotonic() - start:.1f} s")
        send_malformed_request(base + 0 * PORTS_PER_ROBOT + SERVICE_INDEX["hlmap"] * 2 + 1)

        pending = dict(dashboard_expressions(source))
        pending.update(PROGRESS)
        only_parse = {w for w, e in pending.items() if any(m in e for m in EVENTS_OF_A_FAULTY_RUN)}
        errors = {}
        while pending and time.monotonic() - start < DEADLINE_S:
            for where, expr in list(pending.items()):
                answer = query(prom_port, expr)
                if answer.get("status") != "success":
                    errors[where] = f"does not evaluate: {answer.get('error', answer)}\n    {expr}"
                    del pending[where]
                elif answer["data"]["result"] or where in only_parse:
                    del pending[where]
            if pending:
                time.sleep(1.0)
        for where, expr in pending.items():
            errors[where] = f"returned no data within {DEADLINE_S:.0f} s\n    {expr}"
        total = len(dashboard_expressions(source)) + len(PROGRESS)
        print(f"{total - len(errors)} of {total} dashboard and progress expressions evaluate with data "
              f"({len(only_parse)} about faults only had to parse) after {time.monotonic() - start:.1f} s")
        for where in sorted(errors):
            print(f"FAIL {where}: {errors[where]}", file=sys.stderr)
        if errors:
            print(f"logs in {work}", file=sys.stderr)
            keep_logs = True
        return 1 if errors else 0
    finally:
        for _, p in processes:
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
        stop_by = time.monotonic() + 5
        for name, p in processes:
            try:
                p.wait(timeout=max(0.1, stop_by - time.monotonic()))
            except subprocess.TimeoutExpired:
                print(f"{name} ignored SIGTERM for 5 s; killing it", file=sys.stderr)
                p.kill()
                p.wait()
        if not keep_logs:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
