// Writes the fuzz harnesses' seed corpora (tests/fuzz/corpus/<harness>/) from real messages:
// a synthetic scan of a wall and a floor goes through the perception map, the segmenter, the
// contribution log and the fusion, as in a mission, and each wire message on the way is
// written in the form the harness reads (payload flags byte, then the payload: once as the
// radio's compact form where the type has one, once as protobuf). Rerun after a wire change:
//   build/tests/fuzz/fuzz_write_seeds tests/fuzz/corpus deploy/teams

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "common/highlevel/contribution_log.h"
#include "common/highlevel/map_fusion.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/segmenter.h"
#include "common/perception/map_params.h"
#include "common/perception/perception_map.h"
#include "common/perception/voxel_proto.h"
#include "common/planning/plan_proto.h"
#include "common/radio/vec3_proto.h"
#include "common/transport/topics.h"
#include "common/safety/fragment_proto.h"
#include "common/sim/sim_proto.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "tests/fuzz/fuzz_team.h"

namespace {

using namespace hexplore;
namespace fs = std::filesystem;

fs::path g_out;

void write(const std::string& harness, const std::string& name, const std::string& bytes) {
  const fs::path dir = g_out / harness;
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
}

// The harness input for `message`: [prefix][flags][payload], as the radio sends it (compact
// codec, compressed when that pays) and as protobuf.
template <typename Message>
void write_payload(const std::string& harness, const std::string& name, const Message& message,
                   const std::string& prefix = "") {
  const uint16_t type = transport::type_id(Message::descriptor()->full_name());
  std::string radio;
  const uint8_t flags = transport::encode_payload(message, type, true, fuzz::team_socket_options(), radio);
  write(harness, name + "-radio", prefix + std::string(1, char(flags)) + radio);
  write(harness, name + "-protobuf", prefix + std::string(1, '\0') + message.SerializeAsString());
}

// A wall at x = 4 m (2 m high) and the floor before it, seen from (0, 0, 0.9).
sim::LidarScan synthetic_scan() {
  sim::LidarScan scan;
  scan.sensor_name = "fuzz";
  scan.origin = Eigen::Vector3d(0.0, 0.0, 0.9);
  scan.sensor_pose.translation() = scan.origin;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) {
      scan.points.emplace_back(4.0f, -2.0f + 0.1f * float(i), 0.1f * float(j));
      scan.points.emplace_back(0.5f + 0.09f * float(i), -1.0f + 0.1f * float(j), 0.0f);
    }
  scan.rays = scan.points.size();
  return scan;
}

void write_map_messages() {
  const sim::LidarScan lidar = synthetic_scan();
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
  const v1::ScanFrame frame = sim::to_scan_frame(lidar, body, 40.0);
  write_payload("scan", "wall-and-floor", frame);

  perception::PerceptionMap map(perception::make_map_params(fuzz::team(), "slugcat1"));
  std::vector<float> storage;
  perception::ScanPoints points;
  perception::decode_scan(frame, storage, points);
  for (int k = 0; k < 3; ++k) map.integrate(points, {});
  const auto voxels = map.take_changes();
  const v1::VoxelDelta delta = perception::to_voxel_delta(voxels, map.resolution(), false);
  write_payload("voxel_delta", "increment", delta);
  write_payload("voxel_delta", "snapshot", perception::to_voxel_delta(voxels, map.resolution(), true));

  const highlevel::SegmenterParams params = highlevel::SegmenterParams::from(fuzz::team().params);
  highlevel::SupervoxelSegmenter segmenter(params, highlevel::species_levels(fuzz::team()));
  highlevel::ContributionLog log("mr1000a");
  log.record(segmenter, segmenter.update(highlevel::voxel_samples(delta)));
  const highlevel::SourcedUpdate inc = log.take_increment();
  write_payload("map_update", "increment", highlevel::to_increment(inc, log.contribution()), std::string(1, '\0'));
  write_payload("map_update", "snapshot", highlevel::to_snapshot(log.snapshot(), log.contribution()),
                std::string(1, '\1'));
  highlevel::MapFusion fusion(highlevel::species_levels(fuzz::team()));
  fusion.apply(inc.source, inc.update);
  highlevel::MapUpdate fused = fusion.take_changes();
  fused.full_snapshot = true;
  write_payload("map_update", "fused", highlevel::to_fused_update(fused, fusion.map()), std::string(1, '\2'));
}

void write_team_messages() {
  planning::PlanResult plan;
  plan.round = 12;
  plan.planner = "hexplore";
  plan.fitness = 310.5;
  planning::RobotPlan a;
  a.robot_id = "slugcat1";
  a.cluster_ids = {0x0000000100020003ull, 0x8000000100020004ull};
  a.cluster_centers = {{1.2, 3.4, 0.0}, {5.0, 6.5, 1.5}};
  a.route_length_m = 14.2;
  planning::RobotPlan b;
  b.robot_id = "mr1000a";
  b.cluster_ids = {0x0000000200020003ull};
  b.cluster_centers = {{10.0, -2.0, 0.0}};
  b.route_length_m = 9.0;
  plan.robots = {a, b};
  v1::TeamSolution solution = planning::to_proto(plan);
  solution.add_given_up_supervoxels(0x8000000300040005ull);
  solution.add_given_up_voxel_counts(17);
  write_payload("team_solution", "two-robots", solution);

  safety::Fragment fragment;
  fragment.robot_id = "mr1000a";
  fragment.position_m = {2.0, 1.0, 0.0};
  fragment.waypoints_m = {{2.5, 1.0, 0.0}, {3.5, 1.5, 0.0}};
  fragment.speed_mps = 0.5;
  fragment.stationary = false;
  fragment.box_min_m = {1.5, 0.5, 0.0};
  fragment.box_max_m = {2.5, 1.5, 0.8};
  write_payload("path_fragment", "moving", safety::to_proto(fragment));

  v1::RobotPose pose;
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
  body.translation() = Eigen::Vector3d(3.0, -1.0, 0.4);
  sim::set_pose(pose.mutable_pose(), body);
  radio::set(pose.mutable_velocity_mps(), Eigen::Vector3d(0.4, 0.1, 0.0));
  pose.set_state(v1::MOTION_STATE_MOVING);
  radio::set(pose.mutable_body_half_extents_m(), Eigen::Vector3d(0.5, 0.35, 0.4));
  pose.set_odometry_m(120.5);
  write_payload("pose", "moving", pose);

  v1::MissionCommand start;
  start.mutable_start();
  write_payload("mission_command", "start", start);
  v1::MissionCommand estop;
  estop.set_target_robot("slugcat1");
  estop.mutable_emergency_stop()->set_reason("operator");
  write_payload("mission_command", "estop", estop);
  v1::MissionCommand planner;
  planner.mutable_switch_planner()->set_planner("no-mnss");
  write_payload("mission_command", "planner", planner);

  v1::MapRepairRequest repair;
  repair.set_source_robot("mr1000a");
  repair.set_from_seq(7);
  write_payload("requests", "repair", repair, std::string(1, '\0'));
  v1::FusedMapRequest fused;
  fused.set_requester("planning");
  write_payload("requests", "fused", fused, std::string(1, '\1'));
  write_payload("requests", "open-targets", v1::OpenTargetsRequest(), std::string(1, '\2'));
  write_payload("requests", "occupied", v1::OccupiedVoxelsRequest(), std::string(1, '\3'));
}

void write_envelopes() {
  v1::Header header;
  header.set_robot_id("mr1000a");
  header.set_species("MR1000");
  header.set_sequence(42);
  header.set_sim_time_ns(123456789);
  header.set_schema_version(v1::SCHEMA_VERSION_CURRENT);
  header.set_payload_type(v1::RobotPose::descriptor()->full_name());
  header.set_service("sim");
  const auto frame = [&](const std::string& topic, const transport::Roster* roster, uint8_t flags, bool wall) {
    const std::string wire(transport::topics::wire_topic(topic));
    const zmq::message_t h = transport::header_frame(header, roster, flags, wall);
    return std::string(1, char(wire.size())) + wire + std::string(static_cast<const char*>(h.data()), h.size());
  };
  const transport::Roster* roster = fuzz::team_socket_options().roster.get();
  write("envelope", "team-pose", frame("team/pose", roster, transport::kPayloadCodec, false));
  write("envelope", "local-pose", frame("robot/mr1000a/pose", nullptr, 0, true));
  header.set_robot_id("visitor");
  write("envelope", "unknown-robot", frame("team/map", roster, transport::kPayloadCompressed, false));
}

void write_files(const fs::path& teams) {
  for (const char* name : {"default.yaml", "multi-building.yaml", "office.yaml"}) {
    std::ifstream in(teams / name, std::ios::binary);
    write("team_yaml", name, std::string(std::istreambuf_iterator<char>(in), {}));
  }
  write("tsplib", "square.tsp",
        "NAME : square\nTYPE : TSP\nDIMENSION : 4\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n"
        "1 0 0\n2 10 0\n3 10 10\n4 0 10\nEOF\n");
  write("mesh", "triangle-ply",
        std::string(1, '\0') +
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  write("mesh", "triangle-obj", std::string(1, '\1') + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("mesh", "triangle-stl",
        std::string(1, '\2') +
            "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
            "endfacet\nendsolid t\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fuzz_write_seeds CORPUS_DIR TEAMS_DIR (e.g. tests/fuzz/corpus deploy/teams)\n";
    return 64;
  }
  g_out = argv[1];
  write_map_messages();
  write_team_messages();
  write_envelopes();
  write_files(argv[2]);
  std::cout << "seeds written under " << g_out << "\n";
  return 0;
}
