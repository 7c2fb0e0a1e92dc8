// Grouping a dwell's facade targets into the aims of a gimbal (aim_windows.h).
#include <gtest/gtest.h>

#include <cmath>

#include "common/planning/aim_windows.h"

namespace hexplore::planning {
namespace {

// A point `range` m away from the origin at the given yaw and pitch (degrees).
Eigen::Vector3d at(double yaw_deg, double pitch_deg, double range) {
  const double y = yaw_deg * M_PI / 180.0, p = pitch_deg * M_PI / 180.0;
  return range * Eigen::Vector3d(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p));
}

double pitch_deg(const Eigen::Vector3d& v) { return std::atan2(v.z(), v.head<2>().norm()) * 180.0 / M_PI; }
double yaw_deg(const Eigen::Vector3d& v) { return std::atan2(v.y(), v.x()) * 180.0 / M_PI; }

TEST(AimWindows, WithoutAFieldOfViewEachTargetIsItsOwnAim) {
  const std::vector<AimTarget> t = {{1, at(0, 5, 20)}, {2, at(1, 6, 20)}};
  const auto w = aim_windows(Eigen::Vector3d::Zero(), t, 0.0, 0.0);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].targets, std::vector<uint64_t>{1});
  EXPECT_TRUE(w[1].at.isApprox(t[1].at));
}

TEST(AimWindows, TargetsInsideTheFieldOfViewShareOneAimAtTheirMiddle) {
  // A facade 20 m away, targets from 0 to 14 deg up and 30 deg either side: one 40 x 8.25 deg
  // half-window holds them all.
  const std::vector<AimTarget> t = {{1, at(-30, 0, 20)}, {2, at(0, 14, 20)}, {3, at(30, 7, 20)}};
  const auto w = aim_windows(Eigen::Vector3d::Zero(), t, 40.0, 8.25);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].targets, (std::vector<uint64_t>{1, 2, 3}));
  EXPECT_NEAR(pitch_deg(w[0].at), 7.0, 1e-6);
  EXPECT_NEAR(yaw_deg(w[0].at), 0.0, 1e-6);
  EXPECT_NEAR(w[0].at.norm(), 20.0, 1e-6);
}

TEST(AimWindows, ATallFacadeTakesOneAimPerBandAndEveryTargetIsAimedAtOnce) {
  // Targets every 3 deg from 0 to 30 deg up, straight ahead: a window is 16.5 deg tall, so two
  // bands; every target in exactly one, each band's members within the half-height of its aim.
  std::vector<AimTarget> t;
  for (int i = 0; i <= 10; ++i) t.push_back({uint64_t(i), at(0, 3.0 * i, 22)});
  const auto w = aim_windows(Eigen::Vector3d::Zero(), t, 40.0, 8.25);
  ASSERT_EQ(w.size(), 2u);
  size_t total = 0;
  for (const AimWindow& win : w) {
    total += win.targets.size();
    for (uint64_t k : win.targets) EXPECT_LE(std::abs(3.0 * double(k) - pitch_deg(win.at)), 8.25 + 1e-9);
  }
  EXPECT_EQ(total, t.size());
  EXPECT_EQ(w[0].targets.front(), 0u);  // windows in the order of their first target
}

TEST(AimWindows, YawWrapsAroundBehindTheRobot) {
  const std::vector<AimTarget> t = {{1, at(175, 0, 10)}, {2, at(-175, 0, 10)}};
  const auto w = aim_windows(Eigen::Vector3d::Zero(), t, 40.0, 8.25);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NEAR(std::abs(yaw_deg(w[0].at)), 180.0, 1e-6);
}

TEST(AimWindows, TheWindowHoldingMostTargetsIsAimedFirstInTheGreedyCover) {
  // One target alone to the left, four together to the right: the four share an aim, the
  // loner gets its own; nothing is aimed at twice.
  const std::vector<AimTarget> t = {{9, at(-80, 0, 15)}, {1, at(20, 1, 15)}, {2, at(25, 2, 15)}, {3, at(30, 3, 15)},
                                    {4, at(35, 4, 15)}};
  const auto w = aim_windows(Eigen::Vector3d::Zero(), t, 40.0, 8.25);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].targets, std::vector<uint64_t>{9});
  EXPECT_EQ(w[1].targets, (std::vector<uint64_t>{1, 2, 3, 4}));
}

}  // namespace
}  // namespace hexplore::planning
