"""What the client needs of a team file: the robots in team order (the roster that compact
headers number senders by) and the transport block (where every service listens). Only
Debian's python3-zmq and python3-protobuf are allowed, so this reads the block-style YAML of
deploy/teams/ itself instead of depending on a YAML library; anything else it does not
understand is ignored (the services validate the file in full).
"""

import os
from dataclasses import dataclass, field
from typing import Dict, List, Tuple

# common/core/endpoints.h: ServiceKind order; each service binds PUB (role 0) and ROUTER (role 1).
SERVICES = ("sim", "mapping", "hlmap", "planning", "safety", "station")
ROBOT_SERVICES = SERVICES[:5]
STATION_ID = "station"


class TeamFileError(ValueError):
    pass


@dataclass
class Team:
    path: str
    robots: List[Tuple[str, str]]  # (id, species) in team-file order
    transport: Dict[str, str] = field(default_factory=dict)

    @property
    def roster(self):
        """roster.cc: slot 0 is the station, slots 1..N the robots in team order."""
        return [(STATION_ID, "")] + self.robots

    @property
    def robot_ids(self):
        return [r for r, _ in self.robots]

    def endpoint(self, robot_id: str, service: str, role: int, host: str = None) -> str:
        """endpoints.cc connect_endpoint. The station counts as one slot after the last robot."""
        t = self.transport
        scheme = t.get("scheme", "tcp")
        slot = len(self.robots) if robot_id == STATION_ID else self.robot_ids.index(robot_id)
        name = f"{robot_id}-{service}-{'pub' if role == 0 else 'req'}"
        if scheme == "ipc":
            return f"ipc://{t.get('ipc_dir', '/tmp/hexplore')}/{name}"
        if scheme != "tcp":
            raise TeamFileError(f"{self.path}: transport.scheme '{scheme}' lives inside one process "
                                "(the --compose fast mode); only tcp and ipc teams can be watched from outside")
        port = (int(t.get("base_port", 17000)) + slot * int(t.get("ports_per_robot", 20))
                + SERVICES.index(service) * 2 + role)
        h = host or t.get("host_template", "127.0.0.1").replace("{robot}", robot_id).replace("{service}", service)
        return f"tcp://{h}:{port}"

    def keys_dir(self):
        """transport.curve_keys_dir, relative to the team file's folder; None on plain links."""
        d = self.transport.get("curve_keys_dir", "")
        if not d or self.transport.get("scheme", "tcp") != "tcp":
            return None
        return d if os.path.isabs(d) else os.path.normpath(os.path.join(os.path.dirname(self.path), d))

    def secure(self, sock, peer: str, member: str = STATION_ID):
        """Before sock.connect() to a socket of `peer`: on authenticated links (ZeroMQ CURVE,
        common/transport/curve_keys.h) the client speaks as `member` (an operator holds the
        station's pair: the only key the station takes commands from) and checks that the server
        holds `peer`'s secret. A plain team: nothing to do."""
        d = self.keys_dir()
        if d is None:
            return

        def read(name):
            path = os.path.join(d, name)
            try:
                with open(path) as f:
                    return f.readline().strip().encode()
            except OSError as e:
                raise TeamFileError(f"{self.path}: the team's links are authenticated (transport.curve_keys_dir) "
                                    f"but {path} cannot be read ({e.strerror}); hexplore_launch or "
                                    f"hexplore_keys --config {self.path} makes the keys") from e

        sock.setsockopt(zmq_option("CURVE_SERVERKEY"), read(f"{peer}.public"))
        sock.setsockopt(zmq_option("CURVE_PUBLICKEY"), read(f"{member}.public"))
        sock.setsockopt(zmq_option("CURVE_SECRETKEY"), read(f"{member}.secret"))

    def publishers(self, host: str = None):
        """(robot, service, endpoint) of every PUB socket of the team, the station's last."""
        out = [(r, s, self.endpoint(r, s, 0, host)) for r in self.robot_ids for s in ROBOT_SERVICES]
        return out + [(STATION_ID, "station", self.endpoint(STATION_ID, "station", 0, host))]


def zmq_option(name):
    """A pyzmq socket option by name (imported here: reading a team file needs no zmq)."""
    import zmq
    return getattr(zmq, name)


def _strip_comment(line: str) -> str:
    quote = None
    for i, c in enumerate(line):
        if c in "\"'" and quote in (None, c):
            quote = None if quote else c
        elif c == "#" and quote is None and (i == 0 or line[i - 1].isspace()):
            return line[:i]
    return line.rstrip()


def _scalar(text: str) -> str:
    text = text.strip()
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "\"'":
        return text[1:-1]
    return text


def load_team(path: str) -> Team:
    try:
        with open(path) as f:
            lines = [_strip_comment(line) for line in f]
    except OSError as e:
        raise TeamFileError(f"cannot read team file: {e}") from e
    robots, transport = [], {}
    section, child_indent = None, None
    for line in lines:
        if not line.strip():
            continue
        indent = len(line) - len(line.lstrip())
        text = line.strip()
        if indent == 0 and not text.startswith("- "):  # "- " at column 0 is a list item too
            section, child_indent = text.split(":", 1)[0], None
            continue
        if section == "robots":
            if text.startswith("- "):
                robots.append({})
                text = text[2:].strip()
            if robots and ":" in text:
                key, value = text.split(":", 1)
                robots[-1].setdefault(key.strip(), _scalar(value))
        elif section == "transport":
            # Direct children only (radio: has its own block below).
            child_indent = indent if child_indent is None else child_indent
            if indent == child_indent and ":" in text:
                key, value = text.split(":", 1)
                transport[key.strip()] = _scalar(value)
    bad = [i for i, r in enumerate(robots) if not r.get("id") or not r.get("species")]
    if not robots or bad:
        raise TeamFileError(f"{path}: no robots with id and species found (this reader knows the block-style "
                            f"YAML of deploy/teams/: 'robots:' then '  - id: ...' lines)")
    return Team(path, [(r["id"], r["species"]) for r in robots], transport)
