// The sim service over real (inproc) sockets: the test plays the robot's safety service, a
// teammate's sim and the station, and watches the scans and poses.
#include "services/sim/sim_service.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <optional>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/service/service.h"
#include "common/transport/publisher.h"
#include "common/transport/subscriber.h"
#include "common/transport/topics.h"

#include "tests/support/feed_until.h"

namespace hexplore::sim {
namespace {

namespace topics = transport::topics;
using core::ServiceKind;
using core::SocketRole;

constexpr const char* kTeam = R"(
scene: single-building
species:
  - builtin: SLUGCAT
  - builtin: MR1000
robots:
  - id: r1
    species: SLUGCAT
    start: [2.0, -3.0, 0.0]
    yaw_deg: 90
  - id: r2
    species: MR1000
    start: [4.0, -3.0, 0.0]
    yaw_deg: 90
)";

class SimServiceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    service::HostOptions options;
    options.compose = true;
    options.metrics_port = 0;
    options.arguments = {{"real-time-factor", "4"}, {"scan-hz", "2"}};
    host_ = std::make_unique<service::ServiceHost>(core::parse_team_config(kTeam, "test team"), options);
    const auto& team = host_->team();
    auto bind = [&](const std::string& robot, ServiceKind kind) {
      return std::make_unique<transport::Publisher>(
          host_->transport(), transport::Identity{robot, "", std::string(core::service_name(kind))},
          core::bind_endpoint(team, robot, kind, SocketRole::kPublish));
    };
    safety_ = bind("r1", ServiceKind::kSafety);
    mate_ = bind("r2", ServiceKind::kSim);
    station_ = bind(std::string(core::kStationId), ServiceKind::kStation);
    watch_ = std::make_unique<transport::Subscriber>(host_->transport(), host_->socket_options());
    watch_->on<v1::RobotPose>(topics::pose("r1"), [this](const transport::Received<v1::RobotPose>& r) {
      pose_ = r.message;
      pose_sim_ns_ = r.header.sim_time_ns();
    });
    watch_->on<v1::ScanFrame>(topics::scan("r1"), [this](const transport::Received<v1::ScanFrame>& r) {
      scan_ = r.message;
      ++scans_;
    });
    host_->add(std::make_unique<sim_service::SimService>(), "r1");
    host_->start();
    watch_->connect(core::connect_endpoint(team, "r1", ServiceKind::kSim, SocketRole::kPublish));
  }

  void TearDown() override {
    watch_.reset();
    safety_.reset();
    mate_.reset();
    station_.reset();
    host_.reset();
  }

  bool until(const std::function<void()>& feed, const std::function<bool()>& done,
             std::chrono::milliseconds limit = std::chrono::milliseconds(8000)) {
    return testing::feed_until(feed, [&] { watch_->receive_one(std::chrono::milliseconds(10)); }, done, limit);
  }

  void follow_to(double x, double y) {
    v1::MotionCommand c;
    auto* w = c.mutable_follow()->add_waypoints_m();
    w->set_x(x);
    w->set_y(y);
    safety_->publish(topics::motion("r1"), c);
  }

  std::unique_ptr<service::ServiceHost> host_;
  std::unique_ptr<transport::Publisher> safety_, mate_, station_;
  std::unique_ptr<transport::Subscriber> watch_;
  std::optional<v1::RobotPose> pose_;
  int64_t pose_sim_ns_ = 0;
  std::optional<v1::ScanFrame> scan_;
  int scans_ = 0;
};

TEST_F(SimServiceTest, PublishesPosesAndScansWithSimTime) {
  ASSERT_TRUE(until([] {}, [&] { return pose_ && scans_ >= 2; }));
  EXPECT_GT(pose_sim_ns_, 0);
  EXPECT_NEAR(pose_->pose().position_m().x(), 2.0, 1e-6);
  EXPECT_NEAR(pose_->pose().position_m().z(), 0.2, 1e-4);  // body centre above the ground
  EXPECT_EQ(pose_->state(), v1::MOTION_STATE_IDLE);
  ASSERT_TRUE(scan_);
  EXPECT_EQ(scan_->sensor_name(), "panoramic");
  EXPECT_GT(scan_->point_count(), 10000u);
  EXPECT_EQ(scan_->points_xyz_f32().size(), scan_->point_count() * 12u);
  EXPECT_NEAR(scan_->sensor_origin_m().z(), 0.2 + 0.35, 1e-4);
}

TEST_F(SimServiceTest, FollowsMotionCommandsAndObeysEmergencyStop) {
  ASSERT_TRUE(until([&] { follow_to(2.0, 0.0); },
                    [&] { return pose_ && pose_->pose().position_m().y() > -2.5; }));
  v1::MissionCommand estop;
  estop.mutable_emergency_stop()->set_reason("test");
  ASSERT_TRUE(until([&] { station_->publish(topics::kTeamMission, estop); },
                    [&] { return pose_ && pose_->state() == v1::MOTION_STATE_EMERGENCY_STOP; }));
  const double y = pose_->pose().position_m().y();
  until([&] { follow_to(2.0, 0.0); }, [] { return false; }, std::chrono::milliseconds(500));
  EXPECT_NEAR(pose_->pose().position_m().y(), y, 1e-9);  // motion ignored until start
  v1::MissionCommand start;
  start.mutable_start();
  ASSERT_TRUE(until(
      [&] {
        station_->publish(topics::kTeamMission, start);
        follow_to(2.0, 0.0);
      },
      [&] { return pose_ && pose_->pose().position_m().y() > y + 0.1; }));
}

TEST_F(SimServiceTest, TeammateProxiesAppearInScans) {
  // r2 reports itself 3 m in front of r1 (r1 faces +y): its box must show up in r1's scans.
  v1::RobotPose mate;
  mate.mutable_pose()->mutable_position_m()->set_x(2.0);
  mate.mutable_pose()->mutable_position_m()->set_y(0.0);
  mate.mutable_pose()->mutable_position_m()->set_z(0.4);
  mate.mutable_pose()->mutable_orientation()->set_w(1.0);
  auto* half = mate.mutable_body_half_extents_m();
  half->set_x(0.5);
  half->set_y(0.35);
  half->set_z(0.4);
  auto on_box = [&] {
    if (!scan_) return 0;
    int n = 0;
    const std::string& bytes = scan_->points_xyz_f32();
    for (size_t i = 0; i + 12 <= bytes.size(); i += 12) {
      float p[3];
      std::memcpy(p, bytes.data() + i, 12);
      if (std::abs(p[0] - 2.0f) < 0.52f && std::abs(p[1]) < 0.37f && p[2] > 0.05f && p[2] < 0.82f) ++n;
    }
    return n;
  };
  // Teammates are solid in the simulated world through the other sims' sim/body.
  ASSERT_TRUE(until([&] { mate_->publish(topics::kSimBody, mate); }, [&] { return on_box() > 100; }));
}

}  // namespace
}  // namespace hexplore::sim
