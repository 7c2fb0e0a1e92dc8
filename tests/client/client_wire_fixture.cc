// Bytes of the C++ wire format for the Python client's decoders (wire_test.py): payload type
// ids, team topic codes, compact headers, team/pose codec frames with what the C++ codec
// decodes from them, and the endpoints the C++ side derives from team files.
//   client_wire_fixture [--team FILE]... [FULL_TYPE_NAME]...   -> one JSON document on stdout
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/radio/pose_codec.h"
#include "common/transport/envelope.h"
#include "common/transport/topics.h"
#include "common/transport/type_id.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/status.pb.h"

namespace {

using namespace hexplore;

std::string hex(const std::string& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (unsigned char c : bytes) {
    out.push_back(digits[c >> 4]);
    out.push_back(digits[c & 15]);
  }
  return out;
}

std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }  // ids and names need no escaping

v1::RobotPose make_pose(Eigen::Vector3d at, double yaw, double pitch, double roll, Eigen::Vector3d velocity,
                        v1::MotionState state) {
  v1::RobotPose p;
  auto* position = p.mutable_pose()->mutable_position_m();
  position->set_x(at.x());
  position->set_y(at.y());
  position->set_z(at.z());
  const Eigen::Quaterniond q = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  auto* o = p.mutable_pose()->mutable_orientation();
  o->set_w(q.w());
  o->set_x(q.x());
  o->set_y(q.y());
  o->set_z(q.z());
  p.mutable_velocity_mps()->set_x(velocity.x());
  p.mutable_velocity_mps()->set_y(velocity.y());
  p.mutable_velocity_mps()->set_z(velocity.z());
  p.set_state(state);
  return p;
}

// One encoded pose and what the C++ codec decodes from it.
std::string pose_case(const radio::PoseCodec& codec, const v1::RobotPose& in) {
  std::string bytes;
  codec.encode(in, nullptr, bytes);
  v1::RobotPose out;
  if (!codec.decode(bytes, nullptr, out)) return "null";
  const auto& p = out.pose().position_m();
  const auto& q = out.pose().orientation();
  const auto& v = out.velocity_mps();
  return "{\"bytes\": " + quoted(hex(bytes)) + ", \"x\": " + num(p.x()) + ", \"y\": " + num(p.y()) +
         ", \"z\": " + num(p.z()) + ", \"qw\": " + num(q.w()) + ", \"qx\": " + num(q.x()) + ", \"qy\": " + num(q.y()) +
         ", \"qz\": " + num(q.z()) + ", \"vx\": " + num(v.x()) + ", \"vy\": " + num(v.y()) + ", \"vz\": " + num(v.z()) +
         ", \"state\": " + std::to_string(out.state()) + "}";
}

std::string poses() {
  const radio::PoseCodec codec;
  std::vector<v1::RobotPose> cases = {
      make_pose({2.0, -3.0, 0.0}, M_PI / 2, 0, 0, {0, 0, 0}, v1::MOTION_STATE_IDLE),
      make_pose({12.345, -6.789, 0.4}, -2.34, 0, 0, {0.3, -0.35, 0}, v1::MOTION_STATE_MOVING),
      make_pose({-40.5, 77.77, 3.21}, 0.17, 0.21, -0.09, {0.1, 0.2, 0.15}, v1::MOTION_STATE_BLOCKED),
      make_pose({1000.0, -2000.0, 5.0}, M_PI, 0, 0, {0, 0, 0}, v1::MOTION_STATE_EMERGENCY_STOP),
      make_pose({0.004, -0.006, 0.0}, -M_PI / 3, 0, 0, {-0.004, 0.006, 0}, v1::MOTION_STATE_STOPPED),
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> site(-80.0, 80.0), angle(-M_PI, M_PI), tilt(-0.4, 0.4), speed(-0.6, 0.6);
  for (int i = 0; i < 20; ++i)
    cases.push_back(make_pose({site(rng), site(rng), site(rng) / 10}, angle(rng), i % 2 ? tilt(rng) : 0.0,
                              i % 3 ? tilt(rng) : 0.0, {speed(rng), speed(rng), i % 4 ? 0.0 : speed(rng)},
                              static_cast<v1::MotionState>(1 + i % 5)));
  std::string out;
  for (const auto& c : cases) out += (out.empty() ? "" : ", ") + pose_case(codec, c);
  return "[" + out + "]";
}

v1::Header header(const std::string& robot, const std::string& species, const std::string& service, uint64_t sequence,
                  const std::string& type, int64_t sim_ns, int64_t wall_ns) {
  v1::Header h;
  h.set_robot_id(robot);
  h.set_species(species);
  h.set_service(service);
  h.set_sequence(sequence);
  h.set_payload_type(type);
  h.set_sim_time_ns(sim_ns);
  h.set_send_time_ns(wall_ns);
  h.set_schema_version(transport::current_schema_version());
  return h;
}

std::string header_case(const v1::Header& h, const transport::Roster* roster, uint8_t flags, bool wall) {
  std::string bytes;
  transport::encode_header(h, roster, flags, wall, bytes);
  return "{\"bytes\": " + quoted(hex(bytes)) + ", \"robot\": " + quoted(h.robot_id()) + ", \"species\": " +
         quoted(h.species()) + ", \"service\": " + quoted(h.service()) + ", \"type\": " + quoted(h.payload_type()) +
         ", \"flags\": " + std::to_string(flags) + ", \"sequence\": " + std::to_string(h.sequence()) +
         ", \"sim_ms\": " + std::to_string((h.sim_time_ns() + 500'000) / 1'000'000) + ", \"wall_us\": " +
         (wall ? std::to_string(h.send_time_ns() / 1000) : "null") + "}";
}

std::string headers(const transport::Roster& roster) {
  const std::string pose = v1::RobotPose::descriptor()->full_name();
  const std::string mission = v1::MissionCommand::descriptor()->full_name();
  const std::string status = v1::ServiceStatus::descriptor()->full_name();
  const int64_t wall = 1'733'350'000'123'456'789;
  std::vector<std::string> cases = {
      // Team topics: sender by roster slot, no wall time.
      header_case(header("mr1000a", "MR1000", "sim", 300, pose, 123'456'789, 0), &roster, transport::kPayloadCodec, false),
      header_case(header("station", "", "station", 2, mission, 5'000'000'000, 0), &roster, 0, false),
      header_case(header("slugcat1", "SLUGCAT", "hlmap", 70'000, "hexplore.v1.MapIncrement", 3'600'000'000'000, 0),
                  &roster, transport::kPayloadCodec | transport::kPayloadCompressed, false),
      // Robot-local topics: sender by name, with the wall send time.
      header_case(header("slugcat1", "SLUGCAT", "planning", 12, status, 61'000'000'000, wall), nullptr, 0, true),
      // A request as a tool sends it (hexplore_station --send, the Python client).
      header_case(header("hexplore-client", "", "client", 7, mission, 0, wall), nullptr, 0, true),
  };
  std::string out;
  for (const auto& c : cases) out += (out.empty() ? "" : ", ") + c;
  return "[" + out + "]";
}

std::string endpoints(const std::string& path) {
  const core::TeamConfig team = core::load_team_config(path);
  std::vector<std::string> ids;
  for (const auto& r : team.robots) ids.push_back(r.id);
  ids.emplace_back(core::kStationId);
  std::string out;
  for (const auto& id : ids) {
    const bool station = id == core::kStationId;
    for (int s = station ? 5 : 0; s < (station ? 6 : 5); ++s)
      for (int role = 0; role < 2; ++role) {
        const auto kind = static_cast<core::ServiceKind>(s);
        out += std::string(out.empty() ? "" : ", ") + "[" + quoted(id) + ", " +
               quoted(std::string(core::service_name(kind))) + ", " + std::to_string(role) + ", " +
               quoted(core::connect_endpoint(team, id, kind, static_cast<core::SocketRole>(role))) + "]";
      }
  }
  return "[" + out + "]";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> teams, types;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--team" && i + 1 < argc) teams.push_back(argv[++i]);
    else types.push_back(argv[i]);
  }
  const transport::Roster roster({{"slugcat1", "SLUGCAT"}, {"mr1000a", "MR1000"}});
  std::string type_ids, topics, team_endpoints;
  for (const auto& t : types)
    type_ids += (type_ids.empty() ? "" : ", ") + quoted(t) + ": " + std::to_string(transport::type_id(t));
  for (auto t : {transport::topics::kTeamPose, transport::topics::kTeamMap, transport::topics::kTeamPlan,
                 transport::topics::kTeamPath, transport::topics::kTeamMission})
    topics += (topics.empty() ? "" : ", ") + quoted(std::string(t)) + ": " +
              quoted(hex(std::string(transport::topics::wire_topic(t))));
  for (const auto& path : teams)
    team_endpoints += (team_endpoints.empty() ? "" : ", ") + quoted(path) + ": " + endpoints(path);
  std::printf("{\"roster\": [[\"station\", \"\"], [\"slugcat1\", \"SLUGCAT\"], [\"mr1000a\", \"MR1000\"]],\n"
              " \"type_ids\": {%s},\n \"wire_topics\": {%s},\n \"poses\": %s,\n \"headers\": %s,\n"
              " \"endpoints\": {%s}}\n",
              type_ids.c_str(), topics.c_str(), poses().c_str(), headers(roster).c_str(), team_endpoints.c_str());
  return 0;
}
