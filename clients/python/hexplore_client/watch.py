"""Watching a live team: one SUB socket connected to every service's PUB socket, decoding
poses, statuses and mission commands, and counting the bytes of every topic as received
(topic + header + payload frames, what the C++ accounting counts)."""

import collections
import json
import math
import sys
import time

import zmq

from . import wire

STALE_S = 3.0  # a pose older than this is shown with its age (sims publish many a second)


class RobotView:
    """What the watcher knows of one robot (or of the station: services only)."""

    def __init__(self, species=""):
        self.species = species
        self.pose = self.pose_sim_ms = self.pose_at = None       # robot/<id>/pose (sim: exact)
        self.team_pose = self.team_pose_sim_ms = self.team_pose_at = None  # team/pose (radio codec)
        self.recent = collections.OrderedDict()  # sim ms -> Pose of robot/<id>/pose, to check team/pose
        self.team_pose_error_m = None
        self.team_pose_matches = 0
        self.services = {}  # service -> (ServiceStatus, monotonic time received)

    def value(self, service, name):
        status = self.services.get(service, (None, None))[0]
        for v in status.values if status else ():
            if v.name == name:
                return v.value
        return None

    @property
    def planner(self):
        status = self.services.get("planning", (None, None))[0]
        if status and status.detail.startswith("planner "):
            return status.detail[len("planner "):]
        return None


class Watcher:
    def __init__(self, team, messages, host=None, all_topics=False, window_s=5.0, context=None):
        self.team, self.m, self.window_s = team, messages, window_s
        self.roster = team.roster
        self.context = context or zmq.Context.instance()
        self.sock = self.context.socket(zmq.SUB)
        self.sock.setsockopt(zmq.LINGER, 0)
        # The default watches the team radio, poses and statuses; scans, voxels and fused maps
        # are robot-local and heavy, so only --all-topics asks for them.
        prefixes = [b""] if all_topics else wire.wire_prefixes("team/") + [b"robot/station/status"] + [
            f"robot/{r}/{leaf}".encode() for r in team.robot_ids for leaf in ("pose", "status")]
        for p in prefixes:
            self.sock.setsockopt(zmq.SUBSCRIBE, p)
        self.endpoints = [e for _, _, e in team.publishers(host)]
        for robot, _, e in team.publishers(host):
            team.secure(self.sock, robot)  # the server key of each connection, set before it
            self.sock.connect(e)
        self.robots = {r: RobotView(s) for r, s in team.robots}
        self.station = RobotView()
        self.heard = set()  # (robot, service) of every sender heard
        self.samples = collections.deque()  # (time, topic, bytes) within the rate window
        self.totals = collections.defaultdict(lambda: [0, 0])  # topic -> [bytes, messages]
        self.dropped = collections.Counter()  # why frames did not decode
        self.last_mission = None
        self.started = time.monotonic()
        self.last_message_at = None

    def close(self):
        self.sock.close(0)

    def poll(self, timeout_s):
        """Receives and handles messages for up to timeout_s seconds."""
        end = time.monotonic() + timeout_s
        while True:
            left = end - time.monotonic()
            if left <= 0:
                return
            if not self.sock.poll(math.ceil(left * 1000)):
                continue  # timed out: `left` is then <= 0
            while True:
                try:
                    frames = self.sock.recv_multipart(zmq.NOBLOCK)
                except zmq.Again:
                    break
                self.handle(frames, time.monotonic())

    def handle(self, frames, now):
        self.last_message_at = now
        topic = wire.topic_from_wire(frames[0]) if frames else None
        if topic is None or len(frames) != 3:
            self.dropped["not [topic][header][payload]"] += 1
            return
        self.samples.append((now, topic, sum(len(f) for f in frames)))
        total = self.totals[topic]
        total[0] += self.samples[-1][2]
        total[1] += 1
        try:
            header = wire.decode_header(frames[1], self.roster)
            self.heard.add((header.robot_id, header.service))
            self.dispatch(topic, header, frames[2], now)
        except wire.WireError as e:
            self.dropped[str(e)] += 1

    def parse(self, header, payload, cls):
        """A protobuf payload of type `cls`; WireError for anything this client cannot read."""
        if header.type_id != wire.type_id(cls.DESCRIPTOR.full_name):
            raise wire.WireError(f"payload type id {header.type_id:#06x} is not {cls.DESCRIPTOR.full_name}")
        if header.flags & wire.COMPRESSED:
            raise wire.WireError("zstd-compressed payload (not decoded: the standard library has no zstd)")
        if header.flags & wire.CODEC:
            raise wire.WireError(f"compact codec form of {cls.DESCRIPTOR.full_name} (not decoded)")
        message = cls()
        try:
            message.ParseFromString(payload)
        except Exception as e:  # google.protobuf.message.DecodeError, or upb's own
            raise wire.WireError(f"payload does not parse as {cls.DESCRIPTOR.full_name}") from e
        return message

    def dispatch(self, topic, header, payload, now):
        parts = topic.split("/")
        if topic == "team/pose":
            view = self.robots.get(header.robot_id)
            if view is None:
                raise wire.WireError(f"team/pose from '{header.robot_id}', not on the team file")
            if header.flags == wire.CODEC and header.type_id == wire.type_id("hexplore.v1.RobotPose"):
                pose = wire.decode_pose_codec(payload)
            else:
                pose = wire.pose_from_proto(self.parse(header, payload, self.m.RobotPose))
            view.team_pose, view.team_pose_sim_ms, view.team_pose_at = pose, header.sim_time_ms, now
            # The sim sends team/pose right after robot/<id>/pose of the same instant: their
            # distance is what the radio's centimetre grid lost (a live check of this decoder).
            exact = view.recent.get(header.sim_time_ms)
            if exact is not None:
                error = math.dist((pose.x, pose.y, pose.z), (exact.x, exact.y, exact.z))
                view.team_pose_error_m = max(error, view.team_pose_error_m or 0.0)
                view.team_pose_matches += 1
        elif topic == "team/mission":
            command = self.parse(header, payload, self.m.MissionCommand)
            self.last_mission = (command, header.sim_time_ms, now)
        elif len(parts) == 3 and parts[0] == "robot" and parts[2] in ("pose", "status"):
            view = self.station if parts[1] == "station" else self.robots.get(parts[1])
            if view is None:
                return  # a robot of another team file: counted, not shown
            if parts[2] == "status":
                status = self.parse(header, payload, self.m.ServiceStatus)
                view.services[status.service or header.service] = (status, now)
            elif view is not self.station:
                pose = wire.pose_from_proto(self.parse(header, payload, self.m.RobotPose))
                view.pose, view.pose_sim_ms, view.pose_at = pose, header.sim_time_ms, now
                view.recent[header.sim_time_ms] = pose
                while len(view.recent) > 64:
                    view.recent.popitem(last=False)

    def rates(self, now):
        """topic -> (bytes/s, messages/s) over the last window_s seconds (less at the start)."""
        while self.samples and self.samples[0][0] < now - self.window_s:
            self.samples.popleft()
        span = max(0.5, min(self.window_s, now - self.started))
        out = collections.defaultdict(lambda: [0.0, 0.0])
        for _, topic, n in self.samples:
            out[topic][0] += n / span
            out[topic][1] += 1 / span
        return out

    def unheard(self):
        """Robots of the team file whose pose never arrived."""
        return [r for r, v in self.robots.items() if v.pose is None and v.team_pose is None]

    def snapshot(self, now=None):
        """Everything the watcher shows, as plain data (what --json prints)."""
        now = now or time.monotonic()

        def pose_dict(pose, sim_ms, at):
            if pose is None:
                return None
            d = {"x": round(pose.x, 3), "y": round(pose.y, 3), "z": round(pose.z, 3),
                 "yaw_deg": round(math.degrees(pose.yaw_rad), 1), "speed_mps": round(math.hypot(pose.vx, pose.vy), 3),
                 "state": pose.state_name, "sim_time_s": sim_ms / 1000.0, "age_s": round(now - at, 2)}
            if pose.odometry_m is not None:
                d["odometry_m"] = round(pose.odometry_m, 2)
            return d

        state_names = self.m.ServiceStatus.DESCRIPTOR.fields_by_name["state"].enum_type.values_by_number

        def services(view):
            return {s: {"state": state_names[st.state].name[len("SERVICE_STATE_"):] if st.state in state_names
                        else str(st.state),
                        "detail": st.detail, "age_s": round(now - at, 2),
                        "values": {v.name: v.value for v in st.values}}
                    for s, (st, at) in sorted(view.services.items())}

        robots = {}
        for rid, v in self.robots.items():
            rounds = v.value("planning", "round")
            robots[rid] = {
                "species": v.species,
                "pose": pose_dict(v.pose, v.pose_sim_ms, v.pose_at),
                "team_pose": pose_dict(v.team_pose, v.team_pose_sim_ms, v.team_pose_at),
                "team_pose_error_m": v.team_pose_error_m, "team_pose_matches": v.team_pose_matches,
                "planner": v.planner, "round": None if rounds is None else int(rounds),
                "planning_time_s": v.value("planning", "planning_time_s"),
                "views_remaining": v.value("planning", "views_remaining"),
                "services": services(v)}
        rates = self.rates(now)
        topics = {t: {"bytes_per_s": round(rates[t][0], 1) if t in rates else 0.0,
                      "msgs_per_s": round(rates[t][1], 2) if t in rates else 0.0,
                      "bytes_total": b, "msgs_total": n} for t, (b, n) in sorted(self.totals.items())}
        mission = None
        if self.last_mission:
            command, sim_ms, at = self.last_mission
            mission = {"command": str(command).replace("\n", " ").strip(), "sim_time_s": sim_ms / 1000.0,
                       "age_s": round(now - at, 2)}
        return {"elapsed_s": round(now - self.started, 2),
                "mission_time_s": self.station.value("station", "mission_time_s"),
                "completeness": self.station.value("station", "completeness"),
                "senders_heard": sorted(f"{r}/{s}" for r, s in self.heard),
                "senders_expected": len(self.endpoints),
                "robots": robots, "station": services(self.station), "topics": topics,
                "last_mission": mission, "dropped": dict(self.dropped)}


def _fmt(value, spec, none="-"):
    return none if value is None else format(value, spec)


def render(snap):
    """The snapshot as a few lines of text."""
    mission_t, completeness = snap["mission_time_s"], snap["completeness"]
    lines = [f"[watch {snap['elapsed_s']:.0f}s] mission t={_fmt(mission_t, '.1f')}s"
             f"  completeness {_fmt(None if completeness is None else 100 * completeness, '.1f')}%"
             f"  senders {len(snap['senders_heard'])}/{snap['senders_expected']}"
             + (f"  last command: {snap['last_mission']['command']}" if snap["last_mission"] else "")]
    lines.append(f"{'robot':<12}{'x':>8}{'y':>8}{'z':>7}{'yaw':>6}  {'state':<15}{'m/s':>5}{'odom m':>8}"
                 f"  {'planner':<11}{'round':>6}{'plan s':>8}{'views':>6}")
    for rid, r in snap["robots"].items():
        p = r["pose"] or r["team_pose"]
        if p is None:
            lines.append(f"{rid:<12}  (no pose heard)")
            continue
        state = p["state"] + (f" ({p['age_s']:.0f}s old)" if p["age_s"] > STALE_S else "")
        lines.append(f"{rid:<12}{p['x']:8.2f}{p['y']:8.2f}{p['z']:7.2f}{p['yaw_deg']:6.0f}  {state:<15}"
                     f"{p['speed_mps']:5.2f}{_fmt(p.get('odometry_m'), '8.1f', '       -')}"
                     f"  {r['planner'] or '-':<11}{_fmt(r['round'], '6d', '     -')}"
                     f"{_fmt(r['planning_time_s'], '8.3f', '       -')}{_fmt(r['views_remaining'], '6.0f', '     -')}")
    lines.append(f"{'topic':<28}{'B/s':>10}{'msg/s':>8}{'total KB':>10}")
    team_first = sorted(snap["topics"].items(), key=lambda kv: (not kv[0].startswith("team/"), kv[0]))
    for topic, t in team_first:
        lines.append(f"{topic:<28}{t['bytes_per_s']:10.1f}{t['msgs_per_s']:8.1f}{t['bytes_total'] / 1000:10.1f}")
    if snap["dropped"]:
        lines.append("not decoded: " + ", ".join(f"{why} x{n}" for why, n in snap["dropped"].items()))
    return "\n".join(lines)


def run(watcher, period_s, duration_s, once, as_json, quiet_s=5.0, out=sys.stdout):
    """The watch command's loop; returns the exit code."""
    refresh = out.isatty() and not as_json
    end = None if duration_s is None else watcher.started + duration_s
    next_print = watcher.started + period_s
    warned = False
    while True:
        deadline = next_print if end is None else min(next_print, end)
        if not warned:
            deadline = min(deadline, watcher.started + quiet_s)
        watcher.poll(deadline - time.monotonic())
        now = time.monotonic()
        if watcher.last_message_at is None and now - watcher.started >= quiet_s and not warned:
            warned = True
            print(f"hexplore_client: nothing heard from any of the {len(watcher.endpoints)} publishers "
                  f"({watcher.endpoints[0]} ... {watcher.endpoints[-1]}) for {quiet_s:.0f} s: is the team "
                  f"running, and is {watcher.team.path} its team file?", file=sys.stderr)
        last = end is not None and now >= end
        if (not once and now >= next_print) or last:
            snap = watcher.snapshot(now)
            text = json.dumps(snap) if as_json else render(snap)
            out.write(("\033[H\033[J" if refresh else "") + text + ("\n" if as_json or refresh else "\n\n"))
            out.flush()
        while next_print <= now:
            next_print += period_s
        if last:
            missing = watcher.unheard()
            if missing:
                print(f"hexplore_client: no pose heard from {', '.join(missing)} in {duration_s:.0f} s",
                      file=sys.stderr)
            return 1 if missing else 0
