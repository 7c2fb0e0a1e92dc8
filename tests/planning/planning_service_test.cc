// The planning service over real (inproc) sockets: the test plays its hlmap (serving the fused
// map), the robot driver, a teammate's planning and the station, and watches team/plan, the
// route and the executable path.
#include "services/planning/planning_service.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/highlevel/map_proto.h"
#include "common/planning/planner_registry.h"
#include "common/planning/route_follower.h"
#include "common/radio/plan_codec.h"
#include "common/service/options.h"
#include "common/service/service.h"
#include "common/transport/publisher.h"
#include "common/transport/request_reply.h"
#include "common/transport/subscriber.h"
#include "common/transport/topics.h"

#include "tests/support/feed_until.h"
#include "tests/support/planning_scene.h"

namespace hexplore::planning_service {
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
    start: [1.5, 1.5, 0]
  - id: r2
    species: MR1000
    start: [20.5, 1.5, 0]
params:
  ga_max_generations: 100
  ga_time_budget_s: 0
)";

class PlanningServiceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    service::HostOptions options;
    options.compose = true;
    options.metrics_port = 0;
    options.arguments = {{"cycle-ms", "50"}, {"min-replan-s", "0.2"}};
    for (const auto& [k, v] : extra_arguments_) options.arguments[k] = v;
    host_ = std::make_unique<service::ServiceHost>(core::parse_team_config(team_yaml_, "test team"), options);
    const auto& team = host_->team();
    // The fused map that hlmap would serve.
    planning::SyntheticSceneOptions scene;
    scene.width_cells = 30;
    scene.depth_cells = 20;
    scene.buildings = {{5, 5, 14, 13, 5}};
    scene.rubble = {};
    map_ = std::make_unique<highlevel::HighLevelMap>(highlevel::species_levels(team));
    if (!empty_map_) map_->apply(planning::synthetic_scene(scene));
    hlmap_ = std::make_unique<transport::Responder>(
        host_->transport(), transport::Identity{"r1", "", "hlmap"},
        core::bind_endpoint(team, "r1", ServiceKind::kHlmap, SocketRole::kRequest));
    hlmap_->serve<v1::FusedMapRequest, v1::FusedMapUpdate>([this](const transport::Received<v1::FusedMapRequest>&) {
      ++snapshot_requests_;
      return highlevel::to_fused_update(map_->snapshot(), *map_);
    });
    auto bind = [&](const std::string& robot, ServiceKind kind) {
      return std::make_unique<transport::Publisher>(
          host_->transport(), transport::Identity{robot, "", std::string(core::service_name(kind))},
          core::bind_endpoint(team, robot, kind, SocketRole::kPublish));
    };
    station_ = bind(std::string(core::kStationId), ServiceKind::kStation);
    peer_sim_ = bind("r2", ServiceKind::kSim);
    watch_ = std::make_unique<transport::Subscriber>(host_->transport(), host_->socket_options());
    watch_->on<v1::TeamSolution>(std::string(topics::kTeamPlan),
                                 [this](const transport::Received<v1::TeamSolution>& r) {
                                   plan_ = r.message;
                                   ++plans_received_;
                                 });
    watch_->on<v1::ExplorationRoute>(topics::route("r1"), [this](const transport::Received<v1::ExplorationRoute>& r) {
      route_ = r.message;
      ++routes_received_;
    });
    watch_->on<v1::ExecutablePath>(topics::path("r1"),
                                   [this](const transport::Received<v1::ExecutablePath>& r) { path_ = r.message; });
    auto service = std::make_unique<PlanningService>();
    service_ = service.get();
    host_->add(std::move(service), "r1");
    host_->start();
    watch_->connect(core::connect_endpoint(team, "r1", ServiceKind::kPlanning, SocketRole::kPublish));
  }

  void TearDown() override {
    watch_.reset();
    station_.reset();
    peer_sim_.reset();
    hlmap_.reset();  // every socket of the shared context closes before the host terminates it
    host_.reset();
  }

  // Serves hlmap requests and collects outputs until `done` or `limit`.
  bool until(const std::function<void()>& feed, const std::function<bool()>& done,
             std::chrono::milliseconds limit = std::chrono::milliseconds(8000)) {
    const auto pump = [&] {
      hlmap_->drain(16);
      watch_->receive_one(std::chrono::milliseconds(5));
    };
    return testing::feed_until(feed, pump, done, limit);
  }

  std::string team_yaml_ = kTeam;
  std::map<std::string, std::string> extra_arguments_;
  bool empty_map_ = false;  // hlmap serves a map with nothing in it
  std::unique_ptr<service::ServiceHost> host_;
  std::unique_ptr<highlevel::HighLevelMap> map_;
  std::unique_ptr<transport::Responder> hlmap_;
  std::unique_ptr<transport::Publisher> station_, peer_sim_;
  std::unique_ptr<transport::Subscriber> watch_;
  PlanningService* service_ = nullptr;
  int snapshot_requests_ = 0;
  std::optional<v1::TeamSolution> plan_;
  std::optional<v1::ExplorationRoute> route_;
  std::optional<v1::ExecutablePath> path_;
  int plans_received_ = 0;   // team solutions
  int routes_received_ = 0;  // routes: one per round
};

TEST_F(PlanningServiceTest, FetchesTheMapPlansAndPublishesSolutionRouteAndPath) {
  ASSERT_TRUE(until([] {}, [&] { return plan_ && route_ && path_; })) << "requests " << snapshot_requests_;
  EXPECT_GE(snapshot_requests_, 1);
  EXPECT_EQ(plan_->planner(), "hexplore");
  ASSERT_EQ(plan_->sequences_size(), 2);
  EXPECT_EQ(plan_->sequences(0).robot_id(), "r1");
  EXPECT_GT(plan_->sequences(0).cluster_ids_size() + plan_->sequences(1).cluster_ids_size(), 0);
  EXPECT_GT(route_->views_size(), 0);
  ASSERT_GT(path_->waypoints_m_size(), 0);
  EXPECT_NEAR(path_->waypoints_m(0).x(), 1.5, 1.0);
  // The path leads to the first view of the route the robot has not reached yet: the views
  // before it lie within reach of where it stands (a ground view at the edge of the synthetic
  // map, a frontier target, may stand a metre from the start).
  int goal = -1;
  for (int i = 0; i < route_->views_size() && goal < 0; ++i)
    if (route_->views(i).ground_supervoxel() == path_->goal().ground_supervoxel()) goal = i;
  ASSERT_GE(goal, 0) << "the path's goal is not a view of the route";
  for (int i = 0; i < goal; ++i) {
    const auto& p = route_->views(i).position_m();
    EXPECT_LE(std::hypot(p.x() - 1.5, p.y() - 1.5), planning::FollowerOptions{}.reach_m + 1e-6) << "view " << i << " skipped";
  }
}

TEST_F(PlanningServiceTest, SwitchesPlannerAtRunTime) {
  ASSERT_TRUE(until([] {}, [&] { return plan_.has_value(); }));
  v1::MissionCommand unknown;
  unknown.mutable_switch_planner()->set_planner("teleport");
  v1::MissionCommand cmd;
  cmd.mutable_switch_planner()->set_planner("no-mnss");
  ASSERT_TRUE(until(
      [&] {
        station_->publish(topics::kTeamMission, unknown);
        station_->publish(topics::kTeamMission, cmd);
      },
      [&] { return plan_ && plan_->planner() == "no-mnss"; }));
  EXPECT_EQ(service_->active_planner(), "no-mnss");
}

// A planner without a radio code costs its name's bytes in every team solution.
TEST(PlannerCodes, EveryBuiltInPlannerHasOneOnTheRadio) {
  for (const std::string& name : planning::PlannerRegistry::builtin().names())
    EXPECT_TRUE(radio::planner_code(name)) << name << " travels as a string: append it to plan_codec.cc's kPlanners";
}

// MROMT+ and TSPGA+ share no route: their team solution goes out without sequences (the
// given-up set still travels in it); MDVRP+ shares every robot's view sequence.
TEST_F(PlanningServiceTest, BaselinesShareTheirRouteOrNot) {
  ASSERT_TRUE(until([] {}, [&] { return plan_.has_value(); }));
  for (const std::string name : {"tspga+", "mdvrp+", "mromt+"}) {
    v1::MissionCommand cmd;
    cmd.mutable_switch_planner()->set_planner(name);
    route_.reset();
    ASSERT_TRUE(until([&] { station_->publish(topics::kTeamMission, cmd); },
                      [&] { return plan_ && plan_->planner() == name && route_; }))
        << name;
    EXPECT_EQ(service_->active_planner(), name);
    if (name == "mdvrp+") {
      ASSERT_EQ(plan_->sequences_size(), 2);
      EXPECT_GT(plan_->sequences(0).cluster_ids_size() + plan_->sequences(1).cluster_ids_size(), 0);
    } else {
      EXPECT_EQ(plan_->sequences_size(), 0) << name;
    }
    EXPECT_GT(route_->views_size(), 0) << name;
  }
}

TEST_F(PlanningServiceTest, ATeammateFinishingItsRouteTriggersARound) {
  // Rounds are counted on the route (one per round; an unchanged team solution is not resent).
  ASSERT_TRUE(until([] {}, [&] { return route_.has_value(); }));
  const uint64_t first = route_->round();
  v1::RobotPose pose;
  pose.mutable_pose()->mutable_position_m()->set_x(20.5);
  pose.mutable_pose()->mutable_position_m()->set_y(1.5);
  int sent = 0;
  ASSERT_TRUE(until(
      [&] {
        // Moving for a while, then idle: the teammate reached the end of its route.
        pose.set_state(sent++ < 4 ? v1::MOTION_STATE_MOVING : v1::MOTION_STATE_IDLE);
        peer_sim_->publish(topics::kTeamPose, pose);
      },
      [&] { return route_->round() > first; }, std::chrono::milliseconds(5000)));
}

// A teammate whose services died still stands where it was last heard, and no safety layer
// reports it any more: once it is silent, our paths keep off the vertices its body and ours
// could share (e2e 'kill': the survivor drove into the dead robot).
class SilentTeammateTest : public PlanningServiceTest {
 protected:
  SilentTeammateTest() {
    team_yaml_ = std::string(kTeam) + "  eta_t_s: 1\n";
    extra_arguments_ = {{"peer-timeout-s", "0.5"}};
  }
};

TEST_F(SilentTeammateTest, PathsKeepOffASilentTeammate) {
  // The teammate is heard at `at`, then falls silent; returns the next path planned after.
  auto silent_at = [&](const Eigen::Vector3d& at) {
    v1::RobotPose pose;
    pose.mutable_pose()->mutable_position_m()->set_x(at.x());
    pose.mutable_pose()->mutable_position_m()->set_y(at.y());
    pose.set_state(v1::MOTION_STATE_IDLE);
    int sent = 0;
    until([&] { if (sent++ < 5) peer_sim_->publish(topics::kTeamPose, pose); }, [] { return false; },
          std::chrono::milliseconds(300));
    until([] {}, [] { return false; }, std::chrono::milliseconds(1200));  // silent for longer than the time-out
    path_.reset();
    // The next path to drive (not an aim at a view the robot stands at).
    EXPECT_TRUE(until([] {}, [&] { return path_.has_value() && !path_->observing(); }, std::chrono::milliseconds(4000)));
    return path_.value_or(v1::ExecutablePath{});
  };
  // Alone (the teammate silent far away), our path; then the teammate dies on it.
  const v1::ExecutablePath alone = silent_at({28.5, 18.5, 0});
  ASSERT_GE(alone.waypoints_m_size(), 2) << alone.ShortDebugString();
  const auto& w = alone.waypoints_m(std::max(1, alone.waypoints_m_size() - 2));
  const Eigen::Vector3d at(w.x(), w.y(), 0.0);
  const v1::ExecutablePath after = silent_at(at);
  ASSERT_GT(after.waypoints_m_size(), 0);
  const double reach = core::builtin_slugcat().body_half_extents_m.head<2>().norm() +
                       core::builtin_mr1000().body_half_extents_m.head<2>().norm();
  for (const auto& p : after.waypoints_m())
    EXPECT_GE((Eigen::Vector3d(p.x(), p.y(), 0) - at).norm(), reach - 1e-6) << p.x() << ", " << p.y();
}

// Given-up targets travel incrementally (planning::GiveUpSharing): what a teammate gave up is
// passed on in our next messages and then no more, until that teammate's planner restarts (its
// round numbers start again) and needs the whole set.
class GivenUpSharingTest : public PlanningServiceTest {
 protected:
  GivenUpSharingTest() { team_yaml_ = std::string(kTeam) + "  eta_t_s: 0.5\n"; }
};

TEST_F(GivenUpSharingTest, ATeammatesGiveUpsArePassedOnAndGoWholeToARestartedPlanner) {
  const auto& team = host_->team();
  transport::Publisher peer_planning(host_->transport(), transport::Identity{"r2", "", "planning"},
                                     core::bind_endpoint(team, "r2", ServiceKind::kPlanning, SocketRole::kPublish));
  ASSERT_TRUE(until([] {}, [&] { return plan_.has_value(); }));
  constexpr uint64_t kGivenUp = 0x0123456789ull;
  const auto carries = [&] {
    return plan_ && std::count(plan_->given_up_supervoxels().begin(), plan_->given_up_supervoxels().end(), kGivenUp) > 0;
  };
  v1::TeamSolution theirs;
  theirs.set_round(40);
  theirs.set_planner("hexplore");
  theirs.add_given_up_supervoxels(kGivenUp);
  theirs.add_given_up_voxel_counts(12);
  ASSERT_TRUE(until([&] { peer_planning.publish(topics::kTeamPlan, theirs); }, carries)) << "never passed on";
  // Later messages carry only what changed lately: the target leaves them.
  theirs.clear_given_up_supervoxels();
  theirs.clear_given_up_voxel_counts();
  ASSERT_TRUE(until([] {}, [&] { return plan_ && !carries(); })) << "the whole set in every message";
  // The teammate's planner restarts: round 1 after round 40.
  theirs.set_round(1);
  ASSERT_TRUE(until([&] { peer_planning.publish(topics::kTeamPlan, theirs); }, carries))
      << "a restarted teammate did not get the whole set";
}

// A robot with nothing to do replans every min-replan-s ("route finished" holds while its route
// is empty) and gets the same solution each time: it goes on the radio once, then once per eta_t
// (SolutionGate), not once per round.
class IdleRobotTest : public PlanningServiceTest {
 protected:
  IdleRobotTest() {
    team_yaml_ = std::string(kTeam) + "  eta_t_s: 30\n";
    empty_map_ = true;
  }
};

TEST_F(IdleRobotTest, AnUnchangedSolutionIsNotSentEveryRound) {
  ASSERT_TRUE(until([] {}, [&] { return routes_received_ >= 6; })) << routes_received_ << " rounds";
  EXPECT_EQ(route_->views_size(), 0);
  EXPECT_EQ(plans_received_, 1) << routes_received_ << " rounds";
}

// A bad option stops the service before it starts, with an error naming the flag (the process
// then exits with 2 and says which flag and why).
TEST(PlanningServiceOptions, ABadOptionIsAnErrorNamingTheFlag) {
  for (const auto& [key, value] : std::map<std::string, std::string>{
           {"dwell", "sideways"}, {"give-up-views", "1.5"}, {"cycle-ms", "0"}, {"wait-for-start", "maybe"}}) {
    service::HostOptions options;
    options.compose = true;
    options.metrics_port = 0;
    options.arguments = {{key, value}};
    service::ServiceHost host(core::parse_team_config(kTeam, "test team"), options);
    host.add(std::make_unique<PlanningService>(), "r1");
    try {
      host.start();
      ADD_FAILURE() << "--" << key << " " << value << " was accepted";
    } catch (const service::OptionError& e) {
      EXPECT_EQ(e.key(), "--" + key);
    }
  }
}

}  // namespace
}  // namespace hexplore::planning_service
