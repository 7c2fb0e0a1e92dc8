// The mapping service over real (inproc) sockets: the test plays r1's and r2's drivers and the
// hlmap, and watches voxel deltas, rejection counters, snapshot replies and the map file.
#include "services/mapping/mapping_service.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <set>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/service/service.h"
#include "common/transport/publisher.h"
#include "common/transport/request_reply.h"
#include "common/transport/subscriber.h"
#include "common/transport/topics.h"
#include "tests/perception/synthetic_scene.h"

#include "tests/support/feed_until.h"

namespace hexplore::mapping {
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

v1::ScanFrame frame_of(const std::vector<float>& pts, const Eigen::Vector3d& origin) {
  v1::ScanFrame f;
  f.set_points_xyz_f32(std::string(reinterpret_cast<const char*>(pts.data()), pts.size() * sizeof(float)));
  f.set_point_count(static_cast<uint32_t>(pts.size() / 3));
  f.mutable_sensor_origin_m()->set_x(origin.x());
  f.mutable_sensor_origin_m()->set_y(origin.y());
  f.mutable_sensor_origin_m()->set_z(origin.z());
  f.mutable_body_pose()->mutable_orientation()->set_w(1.0);
  f.set_max_range_m(40.0);
  return f;
}

class MappingServiceTest : public ::testing::Test {
 protected:
  void SetUp() override { start({}); }
  void TearDown() override { stop(); }

  void start(const std::map<std::string, std::string>& arguments) {
    service::HostOptions options;
    options.compose = true;
    options.metrics_port = 0;
    options.status_period = std::chrono::milliseconds(200);
    options.arguments = arguments;
    options.arguments.emplace("publish-period-s", "0.05");
    host_ = std::make_unique<service::ServiceHost>(core::parse_team_config(kTeam, "test team"), options);
    const auto& team = host_->team();
    auto bind = [&](const std::string& robot) {
      return std::make_unique<transport::Publisher>(host_->transport(), transport::Identity{robot, "", "sim"},
                                                    core::bind_endpoint(team, robot, ServiceKind::kSim, SocketRole::kPublish));
    };
    sim1_ = bind("r1");
    sim2_ = bind("r2");
    watch_ = std::make_unique<transport::Subscriber>(host_->transport(), host_->socket_options());
    watch_->on<v1::VoxelDelta>(topics::voxels("r1"), [this](const transport::Received<v1::VoxelDelta>& r) {
      if (r.message.full_snapshot()) {
        ++full_snapshots_;
        voxels_.clear();
      }
      for (const v1::Voxel& v : r.message.voxels()) {
        voxels_[{v.ix(), v.iy(), v.iz()}] = v;
      }
    });
    host_->add(std::make_unique<mapping_service::MappingService>(), "r1");
    host_->start();
    watch_->connect(core::connect_endpoint(team, "r1", ServiceKind::kMapping, SocketRole::kPublish));
  }

  void stop() {
    watch_.reset();
    sim1_.reset();
    sim2_.reset();
    host_.reset();
    voxels_.clear();
  }

  bool until(const std::function<void()>& feed, const std::function<bool()>& done,
             std::chrono::milliseconds limit = std::chrono::milliseconds(5000)) {
    return testing::feed_until(feed, [&] { watch_->receive_one(std::chrono::milliseconds(10)); }, done, limit);
  }

  double counter(const std::string& name, const metrics::Labels& labels) {
    return host_->metrics().counter_family(name, "")->add(labels)->value();
  }
  double rejected(const std::string& reason) {
    return counter("hexplore_mapping_scans_rejected_total", {{"robot", "r1"}, {"reason", reason}});
  }

  std::optional<v1::OccupiedVoxels> occupied() {
    transport::Requester requester(host_->transport(), transport::Identity{"station", "", "test"},
                                   core::connect_endpoint(host_->team(), "r1", ServiceKind::kMapping, SocketRole::kRequest));
    v1::OccupiedVoxelsRequest request;
    request.set_requester("test");
    return requester.call<v1::OccupiedVoxelsRequest, v1::OccupiedVoxels>(request, std::chrono::milliseconds(2000));
  }

  std::unique_ptr<service::ServiceHost> host_;
  std::unique_ptr<transport::Publisher> sim1_, sim2_;
  std::unique_ptr<transport::Subscriber> watch_;
  std::map<std::tuple<int, int, int>, v1::Voxel> voxels_;
  int full_snapshots_ = 0;
};

TEST_F(MappingServiceTest, IntegratesScansPublishesDeltasAndFiltersTeammates) {
  std::vector<float> pts;
  perception::testing::add_floor(pts, -2, 2, -2, 2, 0.05, 0.03);
  // r2 stands at (1, 0) and is seen by r1's LiDAR.
  perception::testing::add_patch(pts, {0.6, -0.3, 0.3}, {0.8, 0, 0}, {0, 0.6, 0}, 0.02);
  v1::RobotPose r2;
  r2.mutable_pose()->mutable_position_m()->set_x(1.0);
  r2.mutable_pose()->mutable_position_m()->set_z(0.3);
  r2.mutable_pose()->mutable_orientation()->set_w(1.0);
  const v1::ScanFrame frame = frame_of(pts, {0, 0, 1});
  // Poses alone first (a subscription misses what is sent before it is joined), then scans.
  until([&] { sim2_->publish(topics::kTeamPose, r2); }, [] { return false; }, std::chrono::milliseconds(300));
  ASSERT_TRUE(until(
      [&] {
        sim2_->publish(topics::kTeamPose, r2);
        sim1_->publish(topics::scan("r1"), frame);
      },
      [&] { return voxels_.size() > 500; }));
  for (const auto& [key, v] : voxels_) {
    EXPECT_EQ(std::get<2>(key), 0) << "only the floor layer: the teammate's body is filtered";
    EXPECT_NE(v.flags() & 1u, 0u) << "floor is ground";
  }
  EXPECT_GT(counter("hexplore_mapping_points_dropped_total", {{"robot", "r1"}, {"reason", "teammate_body"}}), 0.0);
  const auto snapshot = occupied();
  ASSERT_TRUE(snapshot.has_value());
  EXPECT_EQ(snapshot->keys_xyz_size() / 3, static_cast<int>(voxels_.size()));
  EXPECT_NEAR(snapshot->resolution_m(), 0.15, 1e-12);
}

TEST_F(MappingServiceTest, RejectsBadScansWithACountedReason) {
  std::vector<float> pts;
  perception::testing::add_floor(pts, -1, 1, -1, 1, 0.05, 0.05);
  v1::ScanFrame good = frame_of(pts, {0, 0, 1});
  v1::ScanFrame short_bytes = good;
  short_bytes.set_point_count(good.point_count() + 1);
  v1::ScanFrame no_origin = good;
  no_origin.mutable_sensor_origin_m()->set_x(std::numeric_limits<double>::quiet_NaN());
  v1::ScanFrame jumped = frame_of(pts, {100, 0, 1});
  ASSERT_TRUE(until([&] { sim1_->publish(topics::scan("r1"), good); }, [&] { return !voxels_.empty(); }));
  const size_t before = voxels_.size();
  ASSERT_TRUE(until(
      [&] {
        sim1_->publish(topics::scan("r1"), short_bytes);
        sim1_->publish(topics::scan("r1"), no_origin);
        sim1_->publish(topics::scan("r1"), jumped);
        sim2_->publish(topics::scan("r1"), good);  // r2's driver speaking on r1's topic
      },
      [&] {
        return rejected("size_mismatch") > 0 && rejected("implausible_pose") > 0 && rejected("pose_jump") > 0 &&
               rejected("foreign_robot") > 0;
      }));
  EXPECT_EQ(voxels_.size(), before);
  const auto snapshot = occupied();
  ASSERT_TRUE(snapshot.has_value());
  EXPECT_EQ(snapshot->keys_xyz_size() / 3, static_cast<int>(before)) << "the map is untouched by refused scans";
}

TEST_F(MappingServiceTest, SavesOnShutdownAndResumesFromTheMapFile) {
  stop();
  const std::string path = (std::filesystem::temp_directory_path() / "hexplore_mapping_service_test.map").string();
  std::filesystem::remove(path);
  start({{"map-file", path}});
  std::vector<float> pts;
  perception::testing::add_floor(pts, -1, 1, -1, 1, 0.05, 0.03);
  ASSERT_TRUE(until([&] { sim1_->publish(topics::scan("r1"), frame_of(pts, {0, 0, 1})); },
                    [&] { return voxels_.size() > 100; }));
  const auto before = occupied();
  ASSERT_TRUE(before.has_value());
  stop();
  ASSERT_TRUE(std::filesystem::exists(path));
  start({{"map-file", path}, {"full-snapshot-period-s", "0.2"}});
  // The resumed map reaches a late-joining hlmap whole, through the periodic full snapshot.
  ASSERT_TRUE(until([] {}, [&] { return full_snapshots_ > 0 && voxels_.size() * 3 == size_t(before->keys_xyz().size()); }));
  const auto after = occupied();
  ASSERT_TRUE(after.has_value());
  std::multiset<int> a(before->keys_xyz().begin(), before->keys_xyz().end());
  std::multiset<int> b(after->keys_xyz().begin(), after->keys_xyz().end());
  EXPECT_EQ(a, b);
  EXPECT_GT(after->keys_xyz_size(), 300);
  stop();
  std::filesystem::remove(path);
}

// One --map-file for a whole team (a launcher passes the same options to every process):
// "{robot}" names each robot's own file.
TEST_F(MappingServiceTest, MapFileNamesTheRobot) {
  stop();
  const auto dir = std::filesystem::temp_directory_path();
  const std::string robot_file = (dir / "hexplore_mapping_service_test_r1.map").string();
  std::filesystem::remove(robot_file);
  start({{"map-file", (dir / "hexplore_mapping_service_test_{robot}.map").string()}});
  stop();
  EXPECT_TRUE(std::filesystem::exists(robot_file));
  EXPECT_FALSE(std::filesystem::exists(dir / "hexplore_mapping_service_test_{robot}.map"));
  std::filesystem::remove(robot_file);
}

}  // namespace
}  // namespace hexplore::mapping
