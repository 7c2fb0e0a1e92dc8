// Pose, path-fragment and team-solution codecs: what they carry round-trips at the stated
// precision, what they leave out decodes as unset, robots travel as roster slots (or by name
// off the roster), and malformed input is refused without crashing.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "common/highlevel/supervoxel.h"
#include "common/radio/fragment_codec.h"
#include "common/radio/key_steps.h"
#include "common/radio/plan_codec.h"
#include "common/radio/pose_codec.h"
#include "common/radio/team_codecs.h"
#include "common/transport/type_id.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/safety.pb.h"
#include "tests/radio/codec_fixtures.h"

namespace hexplore::radio {
namespace {

using testing::decode;
using testing::encode;

void set(v1::Vec3* v, double x, double y, double z) {
  v->set_x(x);
  v->set_y(y);
  v->set_z(z);
}
Eigen::Vector3d vec(const v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

v1::RobotPose moving_pose() {
  v1::RobotPose p;
  set(p.mutable_pose()->mutable_position_m(), 17.234, -3.456, 0.31);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitZ()));
  auto* o = p.mutable_pose()->mutable_orientation();
  o->set_w(q.w());
  o->set_x(q.x());
  o->set_y(q.y());
  o->set_z(q.z());
  set(p.mutable_velocity_mps(), 0.18, 0.46, 0.0);
  p.set_state(v1::MOTION_STATE_MOVING);
  set(p.mutable_body_half_extents_m(), 0.45, 0.3, 0.2);
  p.set_odometry_m(123.4);
  p.set_collisions(2);
  return p;
}

double yaw_of(const v1::RobotPose& p) {
  const auto& o = p.pose().orientation();
  const Eigen::Matrix3d m = Eigen::Quaterniond(o.w(), o.x(), o.y(), o.z()).toRotationMatrix();
  return std::atan2(m(1, 0), m(0, 0));
}

// A key step is added to the previous cell: a step near the int64 limit is malformed input,
// refused before the sum (which would overflow).
TEST(KeySteps, AStepBeyondTheKeyRangeIsRefusedNotSummed) {
  for (const int64_t step : {INT64_MAX, INT64_MIN + 1, int64_t{1} << 40}) {
    std::string bytes;
    transport::ByteWriter w(bytes);
    w.varint(0);       // no x step, class 0
    w.svarint(step);   // y
    w.svarint(0);      // z
    transport::ByteReader r(bytes);
    core::GridCell previous{5, 5, 0};
    uint64_t key = 0;
    EXPECT_FALSE(read_key(r, key, previous)) << step;
    EXPECT_TRUE(r.failed());
  }
}

TEST(PoseCodec, CarriesPositionHeadingVelocityAndStateInAFewBytes) {
  const PoseCodec codec;
  const v1::RobotPose in = moving_pose();
  const std::string wire = encode(codec, in, nullptr);
  EXPECT_LE(wire.size(), 12u);  // level: no vertical speed
  EXPECT_LT(wire.size() * 8, in.ByteSizeLong());
  v1::RobotPose out;
  ASSERT_TRUE(decode(codec, wire, nullptr, out));
  EXPECT_LE((vec(out.pose().position_m()) - vec(in.pose().position_m())).norm(), 0.01);
  EXPECT_NEAR(yaw_of(out), 1.2, M_PI / 256.0 + 1e-9);
  EXPECT_LE((vec(out.velocity_mps()) - vec(in.velocity_mps())).norm(), 0.01);
  EXPECT_EQ(out.state(), v1::MOTION_STATE_MOVING);
  // Left to the team file and the sim's status.
  EXPECT_FALSE(out.has_body_half_extents_m());
  EXPECT_EQ(out.odometry_m(), 0.0);
  EXPECT_EQ(out.collisions(), 0u);
}

TEST(PoseCodec, AStandingLevelRobotSendsNoVelocityOrTilt) {
  const PoseCodec codec;
  v1::RobotPose in = moving_pose();
  in.clear_velocity_mps();
  in.set_state(v1::MOTION_STATE_IDLE);
  const std::string wire = encode(codec, in, nullptr);
  EXPECT_LE(wire.size(), 8u);
  v1::RobotPose out;
  ASSERT_TRUE(decode(codec, wire, nullptr, out));
  EXPECT_EQ(out.state(), v1::MOTION_STATE_IDLE);
  EXPECT_EQ(vec(out.velocity_mps()), Eigen::Vector3d::Zero());
}

TEST(PoseCodec, AClimbingRobotKeepsItsVerticalSpeed) {
  const PoseCodec codec;
  v1::RobotPose in = moving_pose();
  set(in.mutable_velocity_mps(), 0.18, 0.46, -0.23);
  const std::string level = encode(codec, moving_pose(), nullptr);
  const std::string wire = encode(codec, in, nullptr);
  EXPECT_EQ(wire.size(), level.size() + 1);
  v1::RobotPose out;
  ASSERT_TRUE(decode(codec, wire, nullptr, out));
  EXPECT_LE((vec(out.velocity_mps()) - vec(in.velocity_mps())).norm(), 0.01);
}

TEST(PoseCodec, ATiltedBodyKeepsPitchAndRoll) {
  const PoseCodec codec;
  v1::RobotPose in = moving_pose();
  const Eigen::Quaterniond q = Eigen::AngleAxisd(-0.7, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitX());
  auto* o = in.mutable_pose()->mutable_orientation();
  o->set_w(q.w());
  o->set_x(q.x());
  o->set_y(q.y());
  o->set_z(q.z());
  v1::RobotPose out;
  ASSERT_TRUE(decode(codec, encode(codec, in, nullptr), nullptr, out));
  const auto& p = out.pose().orientation();
  const Eigen::Quaterniond back(p.w(), p.x(), p.y(), p.z());
  EXPECT_LT(back.angularDistance(q), 3.0 * 2.0 * M_PI / 256.0);
}

TEST(PoseCodec, RefusesMalformedInput) {
  const PoseCodec codec;
  testing::survives_malformed<v1::RobotPose>(codec, encode(codec, moving_pose(), nullptr), nullptr);
  v1::RobotPose out;
  EXPECT_FALSE(decode(codec, std::string("\x07\x00\x00\x00\x00", 5), nullptr, out));  // state 7 does not exist
  EXPECT_FALSE(decode(codec, std::string("\x80\x00\x00\x00\x00", 5), nullptr, out));  // unknown flag
  EXPECT_FALSE(decode(codec, std::string("\x20\x00\x00\x00\x00\x00", 6), nullptr, out));  // climbing, not moving
}

v1::PathFragment fragment() {
  v1::PathFragment f;
  set(f.mutable_position_m(), 5.03, 7.91, 0.0);
  set(f.add_waypoints_m(), 5.83, 8.41, 0.0);
  set(f.add_waypoints_m(), 6.42, 9.77, 0.1);
  f.set_speed_mps(0.4);
  f.set_stationary(false);
  set(f.mutable_body_box_m()->mutable_min_m(), 4.5, 7.4, -0.2);
  set(f.mutable_body_box_m()->mutable_max_m(), 5.5, 8.4, 0.2);
  f.set_yielding_to("mr1000a");
  return f;
}

TEST(FragmentCodec, CarriesThePathToTheCentimetreAndTheYieldAsASlot) {
  const FragmentCodec codec;
  const auto roster = testing::roster();
  const v1::PathFragment in = fragment();
  const std::string wire = encode(codec, in, &roster);
  EXPECT_LE(wire.size(), 18u);
  v1::PathFragment out;
  ASSERT_TRUE(decode(codec, wire, &roster, out));
  EXPECT_LE((vec(out.position_m()) - vec(in.position_m())).norm(), 0.01);
  ASSERT_EQ(out.waypoints_m_size(), 2);
  for (int i = 0; i < 2; ++i) EXPECT_LE((vec(out.waypoints_m(i)) - vec(in.waypoints_m(i))).norm(), 0.01);
  EXPECT_NEAR(out.speed_mps(), 0.4, 0.005);
  EXPECT_FALSE(out.stationary());
  EXPECT_EQ(out.yielding_to(), "mr1000a");
  EXPECT_FALSE(out.has_body_box_m());  // receivers rebuild it from the sender's species
}

TEST(FragmentCodec, RobotsOffTheRosterGoByName) {
  const FragmentCodec codec;
  v1::PathFragment in = fragment();
  in.set_yielding_to("visitor");
  in.set_stationary(true);
  const auto roster = testing::roster();
  v1::PathFragment out;
  ASSERT_TRUE(decode(codec, encode(codec, in, &roster), &roster, out));
  EXPECT_EQ(out.yielding_to(), "visitor");
  EXPECT_TRUE(out.stationary());
  ASSERT_TRUE(decode(codec, encode(codec, in, nullptr), nullptr, out));  // no roster at all
  EXPECT_EQ(out.yielding_to(), "visitor");
}

TEST(FragmentCodec, RefusesMalformedInputAndSlotsBeyondTheRoster) {
  const FragmentCodec codec;
  const auto roster = testing::roster();
  testing::survives_malformed<v1::PathFragment>(codec, encode(codec, fragment(), &roster), &roster);
  // A slot only means something with the sender's roster.
  v1::PathFragment out;
  EXPECT_FALSE(decode(codec, encode(codec, fragment(), &roster), nullptr, out));
}

v1::TeamSolution solution() {
  v1::TeamSolution s;
  s.set_round(17);
  s.set_planner("hexplore");
  s.set_fitness(812.5);
  s.set_planning_time_s(0.21);
  auto* a = s.add_sequences();
  a->set_robot_id("slugcat1");
  const uint64_t base = core::seed_key({10, 4, 0});
  for (int i = 0; i < 6; ++i) {
    a->add_cluster_ids(core::seed_key({10 + i, 4 + (i % 2), 0}) | (i == 3 ? highlevel::kFacadeKeyBit : 0));
    set(a->add_cluster_centers_m(), 10.5 + i + 0.237, 4.5 + 0.31 * i, 0.05 * i);
  }
  a->set_route_length_m(23.456);
  auto* b = s.add_sequences();
  b->set_robot_id("mr1000a");
  b->add_cluster_ids(base);
  set(b->add_cluster_centers_m(), 10.1, 4.9, 0.0);
  b->set_route_length_m(3.2);
  for (int i = 0; i < 40; ++i) {
    s.add_given_up_supervoxels(core::seed_key({i * 2, 30 + i / 10, 1}));
    s.add_given_up_voxel_counts(static_cast<uint32_t>(20 + i));
  }
  return s;
}

TEST(PlanCodec, ABuiltInPlannerTakesOneByteAndAnyOtherNameTravelsWhole) {
  const PlanCodec codec(1.0);
  v1::TeamSolution s;
  s.set_round(3);
  for (const std::string name : {"hexplore", "tspga+", "my-planner", ""}) {
    s.set_planner(name);
    const std::string wire = encode(codec, s, nullptr);
    EXPECT_EQ(wire.size(), planner_code(name) ? 5u : 6u + name.size()) << name;  // round, planner, 3 counts
    v1::TeamSolution out;
    ASSERT_TRUE(decode(codec, wire, nullptr, out)) << name;
    EXPECT_EQ(out.planner(), name);
  }
  std::string past_the_table = encode(codec, s, nullptr);
  past_the_table[1] = 9;  // codes run 0 (a name follows) to 8
  v1::TeamSolution out;
  EXPECT_FALSE(decode(codec, past_the_table, nullptr, out));
}

TEST(PlanCodec, CarriesSequencesCentresAndTheGivenUpSet) {
  const PlanCodec codec(1.0);
  const auto roster = testing::roster();
  const v1::TeamSolution in = solution();
  const std::string wire = encode(codec, in, &roster);
  EXPECT_LT(wire.size() * 5, in.ByteSizeLong() * 2);  // before compression
  v1::TeamSolution out;
  ASSERT_TRUE(decode(codec, wire, &roster, out));
  EXPECT_EQ(out.round(), 17u);
  EXPECT_EQ(out.planner(), "hexplore");
  // Not carried: no teammate reads the fitness, and a measured time would make runs differ.
  EXPECT_EQ(out.fitness(), 0.0);
  EXPECT_EQ(out.planning_time_s(), 0.0);
  ASSERT_EQ(out.sequences_size(), 2);
  for (int k = 0; k < 2; ++k) {
    const auto& a = in.sequences(k);
    const auto& b = out.sequences(k);
    EXPECT_EQ(b.robot_id(), a.robot_id());
    ASSERT_EQ(b.cluster_ids_size(), a.cluster_ids_size());
    ASSERT_EQ(b.cluster_centers_m_size(), a.cluster_centers_m_size());
    for (int i = 0; i < a.cluster_ids_size(); ++i) {
      EXPECT_EQ(b.cluster_ids(i), a.cluster_ids(i));
      EXPECT_LE((vec(b.cluster_centers_m(i)) - vec(a.cluster_centers_m(i))).norm(), 0.05 * std::sqrt(3.0) + 1e-9);  // decimetres
    }
    EXPECT_NEAR(b.route_length_m(), a.route_length_m(), 0.005);
  }
  ASSERT_EQ(out.given_up_supervoxels_size(), in.given_up_supervoxels_size());
  for (int i = 0; i < in.given_up_supervoxels_size(); ++i) {
    EXPECT_EQ(out.given_up_supervoxels(i), in.given_up_supervoxels(i));
    EXPECT_EQ(out.given_up_voxel_counts(i), in.given_up_voxel_counts(i));
  }
}

TEST(PlanCodec, RefusesMalformedInput) {
  const PlanCodec codec(1.0);
  const auto roster = testing::roster();
  testing::survives_malformed<v1::TeamSolution>(codec, encode(codec, solution(), &roster), &roster);
}

TEST(TeamCodecs, OneCodecPerTeamMessageWithDistinctTypeIds) {
  core::TeamConfig team;
  const auto table = team_codecs(team);
  EXPECT_EQ(table->size(), 5u);
  for (const std::string& name : {v1::RobotPose::descriptor()->full_name(), v1::PathFragment::descriptor()->full_name(),
                                  v1::MapIncrement::descriptor()->full_name(), v1::MapSnapshot::descriptor()->full_name(),
                                  v1::TeamSolution::descriptor()->full_name()}) {
    const transport::PayloadCodec* codec = table->find(transport::type_id(name));
    ASSERT_NE(codec, nullptr) << name;
    EXPECT_EQ(codec->type(), name);
  }
  EXPECT_EQ(table->find(transport::type_id("hexplore.v1.MissionCommand")), nullptr);  // rare: plain protobuf
}

}  // namespace
}  // namespace hexplore::radio
