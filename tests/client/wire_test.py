#!/usr/bin/env python3
"""The Python client's wire decoders against bytes the C++ side produced
(client_wire_fixture): payload type ids, team topic codes, compact headers, the team/pose
codec, a tool's request header byte for byte, and the endpoints of every team file in
deploy/teams/ as the client's small YAML reader derives them.

usage: wire_test.py FIXTURE PB_DIR CLIENT_DIR TEAM_FILE...
Exit 77 (ctest skip) when this interpreter lacks protobuf (scripts/install_deps.sh).
"""
import json
import subprocess
import sys


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    fixture, pb_dir, client_dir, team_files = argv[1], argv[2], argv[3], argv[4:]
    try:
        import google.protobuf  # noqa: F401
    except ImportError:
        print(f"SKIP: {sys.executable} lacks Debian's python3-protobuf")
        return 77
    sys.path.insert(0, client_dir)
    from hexplore_client import wire
    from hexplore_client.messages import Messages
    from hexplore_client.team import load_team

    messages = Messages(pb_dir)
    names = sorted(messages.by_name)
    args = [fixture] + [a for t in team_files for a in ("--team", t)] + names
    data = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    check(len(names) >= 20, f"only {len(names)} message types generated")
    for name in names:
        check(wire.type_id(name) == data["type_ids"][name], f"type id of {name}")
    for topic, code in data["wire_topics"].items():
        check(wire.wire_topic(topic).hex() == code, f"wire code of {topic}")
        check(wire.topic_from_wire(bytes.fromhex(code)) == topic, f"topic of code {code}")
    check(wire.topic_from_wire(b"\x06") is None, "unknown code 6 accepted")

    roster = [tuple(m) for m in data["roster"]]
    for h in data["headers"]:
        got = wire.decode_header(bytes.fromhex(h["bytes"]), roster)
        want = (h["robot"], h["species"], h["service"], wire.type_id(h["type"]), h["flags"], h["sequence"],
                h["sim_ms"], h["wall_us"])
        have = (got.robot_id, got.species, got.service, got.type_id, got.flags, got.sequence, got.sim_time_ms,
                got.wall_time_us)
        check(have == want, f"header {h['bytes']}: {have} != {want}")
    request = data["headers"][-1]
    ours = wire.encode_named_header(request["robot"], request["species"], request["service"], request["type"],
                                    request["sequence"], request["sim_ms"], request["wall_us"])
    check(ours.hex() == request["bytes"], f"request header {ours.hex()} != C++ {request['bytes']}")
    for bad, why in ((b"\x28\x00\x00", "schema version 1"), (data["headers"][0]["bytes"], "no roster")):
        try:
            wire.decode_header(bad if isinstance(bad, bytes) else bytes.fromhex(bad), None)
            failures.append(f"header accepted with {why}")
        except wire.WireError:
            pass

    for p in data["poses"]:
        raw = bytes.fromhex(p["bytes"])
        got = wire.decode_pose_codec(raw)
        for field in ("x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz"):
            check(abs(getattr(got, field) - p[field]) < 1e-12, f"pose {p['bytes']}: {field} {getattr(got, field)} "
                                                               f"!= {p[field]}")
        check(got.state == p["state"], f"pose {p['bytes']}: state")
        for n in range(len(raw)):  # every truncation is refused, as the C++ codec refuses it
            try:
                wire.decode_pose_codec(raw[:n])
                failures.append(f"pose {p['bytes']} truncated to {n} bytes accepted")
            except wire.WireError:
                pass

    for path, expected in data["endpoints"].items():
        team = load_team(path)
        for robot, service, role, endpoint in expected:
            ours = team.endpoint(robot, service, role)
            check(ours == endpoint, f"{path}: {robot}/{service}/{role}: {ours} != {endpoint}")
    check(len(data["endpoints"]) == len(team_files), "not every team file checked")

    for f in failures:
        print("FAIL:", f)
    print(f"{len(names)} type ids, {len(data['headers'])} headers, {len(data['poses'])} poses, "
          f"{len(data['endpoints'])} team files checked; {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
