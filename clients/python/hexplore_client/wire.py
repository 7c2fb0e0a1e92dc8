"""hexplore's wire format, read from Python: one-byte codes of the team topics, the compact
header frame, 16-bit payload type ids and the team/pose compact codec. Each function mirrors
the C++ code named in its docstring; tests/client/wire_test.py checks them against bytes that
the C++ side produced. Standard library only, so that this module loads without the generated
protobuf modules.
"""

import math
from dataclasses import dataclass
from typing import Optional

SCHEMA_VERSION = 6  # hexplore.v1.SCHEMA_VERSION_CURRENT (messages.py checks the two agree)

# common/transport/topics.cc: team topics travel as one control byte, code = index + 1.
TEAM_TOPICS = ("team/pose", "team/map", "team/plan", "team/path", "team/mission")

# common/transport/envelope.h: header flags (byte 0, bits 4..0).
NAMED, WALL_TIME, COMPRESSED, CODEC, RESERVED = 0x01, 0x02, 0x04, 0x08, 0x10

# common/core/endpoints.cc: service codes on the wire are ServiceKind + 1.
SERVICES = ("sim", "mapping", "hlmap", "planning", "safety", "station")

# hexplore.v1.MotionState, for poses decoded without the generated modules.
MOTION_STATES = ("UNSPECIFIED", "IDLE", "MOVING", "STOPPED", "BLOCKED", "EMERGENCY_STOP")

_MAX_NAME_BYTES = 128
_MAX_HEADER_BYTES = 512
_U64 = (1 << 64) - 1


class WireError(ValueError):
    """A frame that does not decode (the C++ side counts and drops such frames)."""


def wire_topic(topic: str) -> bytes:
    """topics::wire_topic: the first frame a topic travels as."""
    if topic in TEAM_TOPICS:
        return bytes([TEAM_TOPICS.index(topic) + 1])
    return topic.encode()


def topic_from_wire(frame: bytes) -> Optional[str]:
    """topics::topic_from_wire: the topic a first frame stands for; None for an unknown code."""
    if not frame or frame[0] >= 0x20:
        return frame.decode("utf-8", "replace")
    if len(frame) != 1 or frame[0] - 1 >= len(TEAM_TOPICS):
        return None
    return TEAM_TOPICS[frame[0] - 1]


def wire_prefixes(prefix: str):
    """topics::wire_prefixes: the ZeroMQ subscriptions a prefix needs (itself plus codes)."""
    out = [prefix.encode()]
    out += [wire_topic(t) for t in TEAM_TOPICS if t.startswith(prefix)]
    return out


def type_id(full_name: str) -> int:
    """type_id.cc: FNV-1a of the full protobuf name folded to 16 bits; 0 is "no payload"."""
    h = 2166136261
    for b in full_name.encode():
        h = ((h ^ b) * 16777619) & 0xFFFFFFFF
    folded = (h >> 16) ^ (h & 0xFFFF)
    return folded or 1


class Reader:
    """byte_codec.h ByteReader: never reads past the end; any overrun raises WireError."""

    def __init__(self, data: bytes):
        self.data, self.pos = data, 0

    def u8(self) -> int:
        if self.pos >= len(self.data):
            raise WireError("truncated")
        self.pos += 1
        return self.data[self.pos - 1]

    def u16(self) -> int:
        lo = self.u8()
        return lo | self.u8() << 8

    def varint(self) -> int:
        value = 0
        for shift in range(0, 64, 7):
            b = self.u8()
            value |= (b & 0x7F) << shift
            if not b & 0x80:
                return value & _U64
        raise WireError("varint longer than ten bytes")

    def svarint(self) -> int:
        v = self.varint()
        return (v >> 1) ^ -(v & 1)

    def bounded_svarint(self, max_abs: int) -> int:
        v = self.svarint()
        if abs(v) > max_abs:
            raise WireError("step out of range")
        return v

    def bytes(self, max_size: int) -> bytes:
        n = self.varint()
        if n > max_size or n > len(self.data) - self.pos:
            raise WireError("length out of range")
        self.pos += n
        return self.data[self.pos - n:self.pos]

    def done(self) -> bool:
        return self.pos == len(self.data)


class Writer:
    """byte_codec.h ByteWriter (what a request header needs)."""

    def __init__(self):
        self.out = bytearray()

    def u8(self, v):
        self.out.append(v & 0xFF)

    def u16(self, v):
        self.u8(v)
        self.u8(v >> 8)

    def varint(self, v):
        while v >= 0x80:
            self.u8(v | 0x80)
            v >>= 7
        self.u8(v)

    def bytes(self, s: bytes):
        self.varint(len(s))
        self.out += s


@dataclass
class Header:
    """A decoded header frame (the fields of hexplore.v1.Header the wire carries)."""
    robot_id: str
    species: str
    service: str
    type_id: int
    flags: int  # COMPRESSED | CODEC
    sequence: int
    sim_time_ms: int
    wall_time_us: Optional[int]


def decode_header(frame: bytes, roster) -> Header:
    """envelope.cc decode_header. `roster`: [(id, species)] with the station as slot 0, as
    roster.cc builds it; team topics name their sender by slot, so they need it."""
    if not frame or len(frame) > _MAX_HEADER_BYTES:
        raise WireError("not a header frame")
    r = Reader(frame)
    first = r.u8()
    if first >> 5 != SCHEMA_VERSION:
        raise WireError(f"schema version {first >> 5}, this client reads {SCHEMA_VERSION}")
    flags = first & 0x1F
    if flags & RESERVED:
        raise WireError("reserved flag set")
    tid = r.u16()
    if flags & NAMED:
        robot = r.bytes(_MAX_NAME_BYTES).decode("utf-8", "replace")
        species = r.bytes(_MAX_NAME_BYTES).decode("utf-8", "replace")
        service = r.bytes(_MAX_NAME_BYTES).decode("utf-8", "replace")
    else:
        sender = r.varint()
        slot, code = sender >> 3, sender & 0x7
        if roster is None or slot >= len(roster) or not 1 <= code <= 6:
            raise WireError("sender slot not on this team's roster (another team file?)")
        robot, species = roster[slot]
        service = SERVICES[code - 1]
    sequence = r.varint()
    sim_ms = r.varint()
    wall_us = r.varint() if flags & WALL_TIME else None
    if not r.done():
        raise WireError("trailing bytes after the header")
    return Header(robot, species, service, tid, flags & (COMPRESSED | CODEC), sequence, sim_ms, wall_us)


def encode_named_header(robot_id: str, species: str, service: str, payload_type: str, sequence: int,
                        sim_time_ms: int = 0, wall_time_us: Optional[int] = None) -> bytes:
    """envelope.cc encode_header for a sender off the roster (a tool): by name, plain payload."""
    w = Writer()
    flags = NAMED | (WALL_TIME if wall_time_us is not None else 0)
    w.u8(SCHEMA_VERSION << 5 | flags)
    w.u16(type_id(payload_type) if payload_type else 0)
    for s in (robot_id, species, service):
        w.bytes(s.encode())
    w.varint(sequence)
    w.varint(max(0, sim_time_ms))
    if wall_time_us is not None:
        w.varint(max(0, wall_time_us))
    return bytes(w.out)


@dataclass
class Pose:
    """A robot pose as a watcher needs it, from either a RobotPose or the team/pose codec."""
    x: float
    y: float
    z: float
    qw: float
    qx: float
    qy: float
    qz: float
    vx: float
    vy: float
    vz: float
    state: int  # hexplore.v1.MotionState
    odometry_m: Optional[float] = None  # not on the radio

    @property
    def yaw_rad(self) -> float:
        return math.atan2(2 * (self.qw * self.qz + self.qx * self.qy), 1 - 2 * (self.qy ** 2 + self.qz ** 2))

    @property
    def state_name(self) -> str:
        return MOTION_STATES[self.state] if 0 <= self.state < len(MOTION_STATES) else str(self.state)


# common/radio/pose_codec.cc flags.
_STATE_MASK, _TILTED, _MOVING, _CLIMBING = 0x07, 0x08, 0x10, 0x20
_MAX_CM_STEP = int(2e7 * 100)  # wire_units.h read_fixed: twice to_steps' clamp


def _angle_from_byte(b: int) -> float:
    """wire_units.h angle_from_byte: 256ths of a turn, in (-pi, pi]."""
    a = b / 256.0 * 2.0 * math.pi
    return a - 2.0 * math.pi if a > math.pi else a


def decode_pose_codec(data: bytes) -> Pose:
    """radio::PoseCodec::decode: flags, position in cm, yaw byte, [pitch, roll bytes],
    [velocity in cm/s]. Body extents, odometry and collisions are not on the radio."""
    r = Reader(data)
    flags = r.u8()
    if flags & ~(_STATE_MASK | _TILTED | _MOVING | _CLIMBING):
        raise WireError("unknown pose flags")
    if flags & _CLIMBING and not flags & _MOVING:
        raise WireError("climbing without moving")
    state = flags & _STATE_MASK
    if state >= len(MOTION_STATES):
        raise WireError(f"motion state {state}")
    x, y, z = (r.bounded_svarint(_MAX_CM_STEP) / 100.0 for _ in range(3))
    yaw = _angle_from_byte(r.u8())
    pitch = roll = 0.0
    if flags & _TILTED:
        pitch = _angle_from_byte(r.u8())
        roll = _angle_from_byte(r.u8())
    vx = vy = vz = 0.0
    if flags & _MOVING:
        vx = r.svarint() / 100.0
        vy = r.svarint() / 100.0
        if flags & _CLIMBING:
            vz = r.svarint() / 100.0
    if not r.done():
        raise WireError("trailing bytes after the pose")
    # Rz(yaw) * Ry(pitch) * Rx(roll), as the C++ side composes Eigen::AngleAxisd.
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    return Pose(x, y, z,
                cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr,
                cy * sp * cr + sy * cp * sr, sy * cp * cr - cy * sp * sr,
                vx, vy, vz, state)


def pose_from_proto(message) -> Pose:
    """A hexplore.v1.RobotPose as a Pose."""
    p, q, v = message.pose.position_m, message.pose.orientation, message.velocity_mps
    return Pose(p.x, p.y, p.z, q.w, q.x, q.y, q.z, v.x, v.y, v.z, int(message.state), message.odometry_m)
