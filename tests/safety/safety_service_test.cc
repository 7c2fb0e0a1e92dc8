// The safety service over real (inproc) sockets: the test plays the robot's driver and planner,
// a teammate's safety service and the station, and watches the motion commands and fragments.
#include "services/safety/safety_service.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/service/service.h"
#include "common/transport/publisher.h"
#include "common/transport/subscriber.h"
#include "common/transport/topics.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/motion.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/safety.pb.h"

#include "tests/support/feed_until.h"

namespace hexplore::safety {
namespace {

namespace topics = transport::topics;
using core::ServiceKind;
using core::SocketRole;

constexpr const char* kTeam = R"(
species:
  - builtin: SLUGCAT
  - builtin: MR1000
robots:
  - id: r1
    species: SLUGCAT
    start: [0, 0, 0]
  - id: r2
    species: MR1000
    start: [5, 5, 0]
)";

void set(v1::Vec3* v, double x, double y) {
  v->set_x(x);
  v->set_y(y);
  v->set_z(0);
}

class SafetyServiceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    service::HostOptions options;
    options.compose = true;
    options.metrics_port = 0;
    options.status_period = std::chrono::milliseconds(200);
    host_ = std::make_unique<service::ServiceHost>(core::parse_team_config(kTeam, "test team"), options);
    const auto& team = host_->team();
    auto bind = [&](const std::string& robot, ServiceKind kind) {
      return std::make_unique<transport::Publisher>(
          host_->transport(), transport::Identity{robot, "", std::string(core::service_name(kind))},
          core::bind_endpoint(team, robot, kind, SocketRole::kPublish));
    };
    sim_ = bind("r1", ServiceKind::kSim);
    planning_ = bind("r1", ServiceKind::kPlanning);
    peer_ = bind("r2", ServiceKind::kSafety);
    peer_sim_ = bind("r2", ServiceKind::kSim);
    station_ = bind(std::string(core::kStationId), ServiceKind::kStation);
    watch_ = std::make_unique<transport::Subscriber>(host_->transport(), host_->socket_options());
    watch_->on<v1::MotionCommand>(topics::motion("r1"), [this](const transport::Received<v1::MotionCommand>& r) {
      last_motion_ = r.message;
    });
    watch_->on<v1::PathFragment>(std::string(topics::kTeamPath), [this](const transport::Received<v1::PathFragment>& r) {
      last_fragment_ = r.message;
    });
    host_->add(std::make_unique<safety_service::SafetyService>(), "r1");
    host_->start();
    watch_->connect(core::connect_endpoint(team, "r1", ServiceKind::kSafety, SocketRole::kPublish));
  }

  void TearDown() override {
    watch_.reset();
    sim_.reset();
    planning_.reset();
    peer_.reset();
    peer_sim_.reset();
    station_.reset();
    host_.reset();
  }

  // Keeps feeding the inputs (late-joining subscriptions miss the first messages) until
  // `done` holds for the latest outputs, or `limit` passes.
  bool until(const std::function<void()>& feed, const std::function<bool()>& done,
             std::chrono::milliseconds limit = std::chrono::milliseconds(5000)) {
    return testing::feed_until(feed, [&] { watch_->receive_one(std::chrono::milliseconds(10)); }, done, limit);
  }

  // Each pose advances the driver's sim time by 50 ms (the feed runs every 50 ms of wall time).
  void send_pose(double x, double y) {
    v1::RobotPose pose;
    set(pose.mutable_pose()->mutable_position_m(), x, y);
    sim_time_ns_ += 50'000'000;
    sim_->publish(topics::pose("r1"), pose, sim_time_ns_);
  }
  void send_path(double x0, double y0, double x1, double y1) {
    v1::ExecutablePath path;
    set(path.add_waypoints_m(), x0, y0);
    set(path.add_waypoints_m(), x1, y1);
    path.set_speed_mps(0.4);
    planning_->publish(topics::path("r1"), path);
  }
  void send_mission(const v1::MissionCommand& command) { station_->publish(topics::kTeamMission, command); }

  bool following_to(double x, double y) const {
    if (!last_motion_ || !last_motion_->has_follow() || last_motion_->follow().waypoints_m().empty()) return false;
    const auto& end = *last_motion_->follow().waypoints_m().rbegin();
    return std::abs(end.x() - x) < 1e-6 && std::abs(end.y() - y) < 1e-6;
  }
  bool stopped() const { return last_motion_ && last_motion_->has_stop(); }
  // Every point of the approved path keeps both bodies apart from a robot standing at (x, y).
  void expect_clear_of(double x, double y) const {
    const auto& w = last_motion_->follow().waypoints_m();
    for (int i = 1; i < w.size(); ++i) {
      for (double t = 0.0; t <= 1.0; t += 0.05) {
        const double px = w[i - 1].x() + t * (w[i].x() - w[i - 1].x());
        const double py = w[i - 1].y() + t * (w[i].y() - w[i - 1].y());
        EXPECT_GT(std::hypot(px - x, py - y), 0.61 + 0.54) << px << "," << py;
      }
    }
  }

  std::unique_ptr<service::ServiceHost> host_;
  std::unique_ptr<transport::Publisher> sim_, planning_, peer_, peer_sim_, station_;
  std::unique_ptr<transport::Subscriber> watch_;
  std::optional<v1::MotionCommand> last_motion_;
  std::optional<v1::PathFragment> last_fragment_;
  int64_t sim_time_ns_ = 0;
};

TEST_F(SafetyServiceTest, ApprovesAFreePathAndSharesOnlyEtaP) {
  const auto feed = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
  };
  ASSERT_TRUE(until(feed, [&] { return following_to(10, 0) && last_fragment_.has_value(); }));
  EXPECT_NEAR(last_motion_->follow().speed_mps(), 0.4, 1e-9);
  ASSERT_GT(last_fragment_->waypoints_m_size(), 0);
  const auto& tip = *last_fragment_->waypoints_m().rbegin();
  EXPECT_NEAR(tip.x(), 2.0, 1e-6);  // eta_p = 2 m of the 10 m path
  EXPECT_FALSE(last_fragment_->stationary());
}

TEST_F(SafetyServiceTest, EmergencyStopHaltsAndRefusesPathsUntilStart) {
  const auto feed = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
  };
  ASSERT_TRUE(until(feed, [&] { return following_to(10, 0); }));
  v1::MissionCommand estop;
  estop.mutable_emergency_stop()->set_reason("test");
  ASSERT_TRUE(until([&] { send_mission(estop); }, [&] { return stopped(); }));
  EXPECT_NE(last_motion_->stop().reason().find("emergency stop"), std::string::npos);
  // New paths keep being refused while the emergency stop holds.
  last_motion_.reset();
  until(feed, [] { return false; }, std::chrono::milliseconds(1000));
  EXPECT_TRUE(stopped());
  ASSERT_TRUE(last_fragment_.has_value());
  EXPECT_TRUE(last_fragment_->stationary());
  v1::MissionCommand start;
  start.mutable_start();
  ASSERT_TRUE(until([&] { send_mission(start); feed(); }, [&] { return following_to(10, 0); }));
}

// r2 (an MR1000 body) standing still at (x, y), as its sim reports it on team/pose.
v1::RobotPose standing_mr1000(double x, double y) {
  v1::RobotPose pose;
  set(pose.mutable_pose()->mutable_position_m(), x, y);
  pose.mutable_body_half_extents_m()->set_x(0.5);
  pose.mutable_body_half_extents_m()->set_y(0.35);
  pose.mutable_body_half_extents_m()->set_z(0.4);
  return pose;
}

TEST_F(SafetyServiceTest, YieldsToATeammateArrivingFirst) {
  // r1 drives +x through the origin area; r2 (moving, closer to the crossing) drives +y.
  v1::PathFragment r2;
  set(r2.mutable_position_m(), 3, -1.0);
  set(r2.add_waypoints_m(), 3, 1.0);
  r2.set_speed_mps(0.5);
  r2.set_stationary(false);
  set(r2.mutable_body_box_m()->mutable_min_m(), 2.4, -1.6);
  set(r2.mutable_body_box_m()->mutable_max_m(), 3.6, -0.4);
  const auto feed = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
    peer_->publish(topics::kTeamPath, r2, sim_time_ns_);
  };
  ASSERT_TRUE(until(feed, [&] { return last_fragment_ && last_fragment_->yielding_to() == "r2"; }));
  // Either stopped or cut short well before r2's path.
  if (last_motion_->has_follow()) {
    EXPECT_LT(last_motion_->follow().waypoints_m().rbegin()->x(), 3.0 - 1.0);
  }
}

TEST_F(SafetyServiceTest, TeammateKnownOnlyByItsPoseIsDrivenAround) {
  // r2's safety service is silent; its driver's team/pose shows it standing on r1's path.
  const v1::RobotPose r2 = standing_mr1000(4, 0);
  const auto feed = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
    peer_sim_->publish(topics::kTeamPose, r2, sim_time_ns_);
  };
  ASSERT_TRUE(until(feed, [&] { return following_to(10, 0) && last_motion_->follow().waypoints_m_size() > 2; }));
  expect_clear_of(4, 0);
}

TEST_F(SafetyServiceTest, ANewerPoseMovesATeammateAwayFromItsLastFragment) {
  // r2's last fragment says it stands at (8, 0); its driver's pose, sent after it, measures it
  // at (3, 0) on r1's way (it rolled on after the stop was decided, or the newer fragment is
  // late). r1 must keep clear of (3, 0), not only of the box the fragment drew at (8, 0).
  v1::PathFragment fragment;
  set(fragment.mutable_position_m(), 8, 0);
  fragment.set_stationary(true);
  const v1::RobotPose r2 = standing_mr1000(3, 0);
  const auto feed = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
    // The fragment is always 100 ms older than the pose (older than the previous pose too,
    // so the order of arrival does not matter).
    peer_->publish(topics::kTeamPath, fragment, sim_time_ns_ - 100'000'000);
    peer_sim_->publish(topics::kTeamPose, r2, sim_time_ns_);
  };
  // Fed long enough for both teammate messages to have arrived and been decided on.
  ASSERT_TRUE(until(feed, [&] { return sim_time_ns_ > 2'000'000'000 && last_motion_.has_value(); },
                    std::chrono::milliseconds(10000)));
  if (last_motion_->has_follow()) expect_clear_of(3, 0);
}

TEST_F(SafetyServiceTest, ASilentTeammateStaysAnObstacleAtItsLastPose) {
  // r2 (services killed) was last seen standing on r1's path; long after its last message
  // its body is still there, so r1's approved path must still go around it.
  const v1::RobotPose r2 = standing_mr1000(4, 0);
  const auto own = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
  };
  ASSERT_TRUE(until([&] { own(); peer_sim_->publish(topics::kTeamPose, r2, sim_time_ns_); },
                    [&] { return following_to(10, 0) && last_motion_->follow().waypoints_m_size() > 2; }));
  const int64_t last_heard_ns = sim_time_ns_;
  ASSERT_TRUE(until(own, [&] { return sim_time_ns_ - last_heard_ns > 5'000'000'000 && following_to(10, 0); },
                    std::chrono::milliseconds(10000)));
  last_motion_.reset();
  ASSERT_TRUE(until(own, [&] { return following_to(10, 0); }));
  EXPECT_GT(last_motion_->follow().waypoints_m_size(), 2);
  expect_clear_of(4, 0);
}

TEST_F(SafetyServiceTest, StopMissionHaltsTheRobot) {
  const auto feed = [&] {
    send_pose(0, 0);
    send_path(0, 0, 10, 0);
  };
  ASSERT_TRUE(until(feed, [&] { return following_to(10, 0); }));
  v1::MissionCommand stop;
  stop.mutable_stop();
  ASSERT_TRUE(until([&] { send_mission(stop); }, [&] { return stopped(); }));
  EXPECT_EQ(last_motion_->stop().reason(), "mission stopped");
}

}  // namespace
}  // namespace hexplore::safety
