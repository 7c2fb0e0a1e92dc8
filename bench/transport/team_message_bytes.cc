#include "bench/transport/team_message_bytes.h"

#include <cstdio>
#include <random>
#include <string>

#include "common/core/clock.h"
#include "common/core/team_config.h"
#include "common/highlevel/supervoxel.h"
#include "common/radio/team_codecs.h"
#include "common/transport/envelope.h"
#include "common/transport/payload_wire.h"
#include "common/transport/topics.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/safety.pb.h"

namespace hexplore::bench {
namespace {

void set(v1::Vec3* v, double x, double y, double z) {
  v->set_x(x);
  v->set_y(y);
  v->set_z(z);
}

v1::RobotPose pose(bool moving) {
  v1::RobotPose p;
  set(p.mutable_pose()->mutable_position_m(), 23.417, 11.902, 0.284);
  auto* q = p.mutable_pose()->mutable_orientation();
  q->set_w(0.8253);
  q->set_z(0.5646);
  if (moving) set(p.mutable_velocity_mps(), 0.27, 0.42, 0.0);
  p.set_state(moving ? v1::MOTION_STATE_MOVING : v1::MOTION_STATE_IDLE);
  set(p.mutable_body_half_extents_m(), 0.5, 0.35, 0.4);
  p.set_odometry_m(187.31);
  return p;
}

v1::PathFragment fragment() {
  v1::PathFragment f;
  set(f.mutable_position_m(), 23.417, 11.902, 0.0);
  set(f.add_waypoints_m(), 24.1, 12.95, 0.0);
  set(f.add_waypoints_m(), 24.43, 13.82, 0.0);
  f.set_speed_mps(0.5);
  set(f.mutable_body_box_m()->mutable_min_m(), 22.8, 11.29, -0.4);
  set(f.mutable_body_box_m()->mutable_max_m(), 24.03, 12.51, 0.4);
  return f;
}

// One eta_c window of a robot exploring: supervoxels of a patch of neighbouring seed cells,
// a third of them facade, and the edges between the ground ones.
v1::MapIncrement increment(int supervoxels) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45), unit(-1.0, 1.0);
  v1::MapIncrement m;
  m.set_source_robot("mr1000a");
  m.set_increment_seq(212);
  uint64_t previous_ground = 0;
  for (int i = 0; i < supervoxels; ++i) {
    const core::GridCell cell{14 + i % 8, 6 + i / 8, i % 7 == 0 ? 1 : 0};
    const bool facade = i % 3 == 0;
    highlevel::Supervoxel s;
    s.surface = facade ? highlevel::SurfaceClass::kFacade : highlevel::SurfaceClass::kGround;
    s.key = highlevel::supervoxel_key(cell, s.surface);
    s.center = core::cell_center(cell, 1.0) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    s.normal = facade ? Eigen::Vector3d(unit(rng), unit(rng), 0.1 * unit(rng)).normalized() : Eigen::Vector3d::UnitZ();
    s.covered = i % 5 == 0;
    s.traversal_requirement = facade ? 0 : 1;
    s.voxel_count = 20 + static_cast<int>(rng() % 120);
    s.covered_voxels = s.covered ? s.voxel_count : s.voxel_count / 2;
    s.gap = s.covered ? core::CoverageGap::kNone : core::CoverageGap::kAngle;
    s = highlevel::wire_rounded(s);
    v1::Supervoxel* out = m.add_supervoxels();
    out->set_key(s.key);
    out->set_center_x(float(s.center.x()));
    out->set_center_y(float(s.center.y()));
    out->set_center_z(float(s.center.z()));
    out->set_normal_x(float(s.normal.x()));
    out->set_normal_y(float(s.normal.y()));
    out->set_normal_z(float(s.normal.z()));
    out->set_covered(s.covered);
    out->set_traversal_requirement(uint32_t(s.traversal_requirement));
    out->set_surface(static_cast<v1::SurfaceClass>(s.surface));
    out->set_voxel_count(uint32_t(s.voxel_count));
    if (!s.covered) {
      out->set_covered_voxels(uint32_t(s.covered_voxels));
      out->set_coverage_gap(v1::COVERAGE_GAP_ANGLE);
    }
    if (!facade) {
      if (previous_ground != 0) {
        auto* e = m.add_edges();
        e->set_a(std::min(previous_ground, s.key));
        e->set_b(std::max(previous_ground, s.key));
        e->set_length_m(1.0f);
      }
      previous_ground = s.key;
    }
  }
  return m;
}

v1::TeamSolution solution(int clusters_per_robot, int given_up) {
  v1::TeamSolution s;
  s.set_round(31);
  s.set_planner("hexplore");
  s.set_fitness(1432.7);
  s.set_planning_time_s(0.18);
  for (const char* id : {"slugcat1", "mr1000a"}) {
    auto* seq = s.add_sequences();
    seq->set_robot_id(id);
    for (int i = 0; i < clusters_per_robot; ++i) {
      seq->add_cluster_ids(core::seed_key({5 + 2 * i, 10 + (i * 3) % 7, 0}));
      // A cluster's centre is the mean of its views, up to eta_r = 5 m from its seed cell.
      set(seq->add_cluster_centers_m(), 5.5 + 2 * i + 0.83 * ((i * 7) % 9 - 4), 10.5 + (i * 3) % 7 + 0.9 * ((i * 5) % 7 - 3),
          0.4);
    }
    seq->set_route_length_m(41.7);
  }
  for (int i = 0; i < given_up; ++i) {
    s.add_given_up_supervoxels(core::seed_key({i, 20 + i % 3, 0}) | highlevel::kFacadeKeyBit);
    s.add_given_up_voxel_counts(uint32_t(30 + i));
  }
  return s;
}

struct Wire {
  size_t v1 = 0;
  size_t v2 = 0;
};

template <typename M>
Wire bytes(std::string_view topic, const M& message, const transport::SocketOptions& options) {
  v1::Header header = transport::make_header({"mr1000a", "MR1000", "hlmap"}, 212, transport::type_name<M>(),
                                             431'250'000'000);
  Wire w;
  header.set_schema_version(1);
  w.v1 = topic.size() + header.ByteSizeLong() + message.ByteSizeLong();
  header.set_schema_version(transport::current_schema_version());
  std::string payload, compact;
  const uint8_t flags =
      transport::encode_payload(message, transport::type_id(transport::type_name<M>()), true, options, payload);
  transport::encode_header(header, options.roster.get(), flags, false, compact);
  w.v2 = transport::topics::wire_topic(topic).size() + compact.size() + payload.size();
  return w;
}

void row(const char* what, const Wire& w) {
  std::printf("  %-44s %6zu B  %6zu B  %5.1fx\n", what, w.v1, w.v2, static_cast<double>(w.v1) / static_cast<double>(w.v2));
}

}  // namespace

void print_team_message_bytes() {
  core::TeamConfig team = core::parse_team_config(
      "species: [{builtin: SLUGCAT}, {builtin: MR1000}]\n"
      "robots: [{id: slugcat1, species: SLUGCAT}, {id: mr1000a, species: MR1000}]\n",
      "transport_bench");
  transport::SocketOptions options;
  options.roster = transport::Roster::from_team(team);
  options.codecs = radio::team_codecs(team);
  namespace topics = transport::topics;
  std::printf("team messages on the radio (topic + header + payload, bytes): schema v1 vs v2\n");
  std::printf("  %-44s %8s  %8s  %6s\n", "message", "v1", "v2", "ratio");
  row("team/pose, moving", bytes(topics::kTeamPose, pose(true), options));
  row("team/pose, standing", bytes(topics::kTeamPose, pose(false), options));
  row("team/path, 2 waypoints", bytes(topics::kTeamPath, fragment(), options));
  row("team/map, empty window (heartbeat)", bytes(topics::kTeamMap, increment(0), options));
  row("team/map, 12 supervoxels", bytes(topics::kTeamMap, increment(12), options));
  row("team/map, 60 supervoxels", bytes(topics::kTeamMap, increment(60), options));
  row("team/plan, 2 x 12 clusters, 40 given up", bytes(topics::kTeamPlan, solution(12, 40), options));
  // What a team solution usually carries of the given-up set: the changes of its last few
  // messages (planning::GiveUpSharing), not the whole set.
  row("team/plan, 2 x 12 clusters, 3 given-up changes", bytes(topics::kTeamPlan, solution(12, 3), options));
  std::fflush(stdout);
}

}  // namespace hexplore::bench
