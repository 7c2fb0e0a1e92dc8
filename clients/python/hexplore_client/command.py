"""Mission commands the way `hexplore_station --send` gives them: a MissionCommand request to
the station's ROUTER socket, which the station answers and publishes on team/mission. The
robots' services subscribe to the station's PUB socket only, so the station is the one way in.
The station relays any command without judging it (a planning service ignores a planner name
it does not know), so the client then watches the team to confirm that it reacted."""

import time

import zmq

from . import wire
from .team import STATION_ID

CLIENT_ID = "hexplore-client"  # the sender name of our requests (off the roster, so by name)


class CommandError(RuntimeError):
    pass


def parse_command(text, messages, target_robot=""):
    """start | stop | estop | planner=<name>, as the station's --send reads them."""
    command = messages.MissionCommand(target_robot=target_robot)
    if text == "start":
        command.start.SetInParent()
    elif text == "stop":
        command.stop.SetInParent()
    elif text == "estop":
        command.emergency_stop.reason = "operator (hexplore_client)"
    elif text.startswith("planner=") and len(text) > len("planner="):
        command.switch_planner.planner = text[len("planner="):]
    else:
        raise ValueError(f"expected start, stop, estop or planner=<name>, got '{text}'")
    return command


def send(team, messages, command, host=None, timeout_s=3.0, context=None):
    """Sends `command` to the station's ROUTER; returns the station's reply detail."""
    endpoint = team.endpoint(STATION_ID, "station", 1, host)
    sock = (context or zmq.Context.instance()).socket(zmq.DEALER)
    sock.setsockopt(zmq.LINGER, 0)
    try:
        team.secure(sock, STATION_ID)
        sock.connect(endpoint)
        header = wire.encode_named_header(CLIENT_ID, "", "client", command.DESCRIPTOR.full_name, 1,
                                          wall_time_us=time.time_ns() // 1000)
        # [empty][header][payload] after the routing id the ROUTER adds (request_reply.h).
        sock.send_multipart([b"", header, command.SerializeToString()])
        if not sock.poll(int(timeout_s * 1000)):
            raise CommandError(f"no station answered at {endpoint} within {timeout_s:g} s (is the team running, "
                               f"and is {team.path} its team file?)")
        frames = sock.recv_multipart()
    finally:
        sock.close(0)
    if len(frames) != 3 or frames[0]:
        raise CommandError(f"the station's reply has {len(frames)} frames, expected [empty][header][payload]")
    try:
        header = wire.decode_header(frames[1], team.roster)
    except wire.WireError as e:
        raise CommandError(f"the reply from {endpoint} does not decode: {e}") from e
    if header.type_id == 0:
        raise CommandError(f"{endpoint} does not serve MissionCommand requests (not a station?)")
    reply = messages.ServiceStatus()
    try:
        reply.ParseFromString(frames[2])
    except Exception as e:  # google.protobuf.message.DecodeError
        raise CommandError(f"the reply from {endpoint} is no ServiceStatus") from e
    return reply.detail


def expectation(command):
    """(what the team should show, check(robot view) -> bool) for a command, after it applied."""
    kind = command.WhichOneof("command")
    if kind == "switch_planner":
        name = command.switch_planner.planner
        return f"planning status 'planner {name}'", lambda v: v.planner == name
    states = {"emergency_stop": ("EMERGENCY_STOP",), "stop": ("STOPPED", "EMERGENCY_STOP")}
    if kind in states:
        wanted = states[kind]
        return f"motion state {' or '.join(wanted)}", lambda v: v.pose is not None and v.pose.state_name in wanted
    # A start releases an emergency stop; a robot that was only stopped stays STOPPED until its
    # planner sends a path, so leaving EMERGENCY_STOP is all a start can be held to at once.
    return "no EMERGENCY_STOP", lambda v: v.pose is not None and v.pose.state_name != "EMERGENCY_STOP"


def confirm(watcher, command, sent_at, timeout_s):
    """Watches until every addressed robot shows what `command` should cause, in a message
    received after `sent_at`. Returns (ok, what was expected, one line per robot)."""
    what, check = expectation(command)
    on_status = command.WhichOneof("command") == "switch_planner"
    robots = [command.target_robot] if command.target_robot else list(watcher.robots)

    def fresh(view):
        at = view.services.get("planning", (None, None))[1] if on_status else view.pose_at
        return at is not None and at > sent_at

    def shown(view):
        if on_status:
            return f"planner {view.planner}" if view.planner else "no planning status"
        return view.pose.state_name if view.pose else "no pose"

    end = time.monotonic() + timeout_s
    while True:
        views = {r: watcher.robots[r] for r in robots}
        ok = {r: fresh(v) and check(v) for r, v in views.items()}
        if all(ok.values()) or time.monotonic() >= end:
            break
        watcher.poll(min(0.2, max(0.0, end - time.monotonic())))
    lines = [f"{r}: {'ok' if ok[r] else 'NOT'} {shown(v)}{'' if fresh(v) else ' (nothing heard since the command)'}"
             for r, v in views.items()]
    seen = watcher.last_mission
    if seen and seen[2] > sent_at and seen[0] == command:
        lines.insert(0, f"seen on team/mission at sim time {seen[1] / 1000:.1f} s")
    return all(ok.values()), what, lines
