#include "common/safety/resolver.h"

#include <gtest/gtest.h>

namespace hexplore::safety {
namespace {

using V = Eigen::Vector3d;
const V kHalf(0.45, 0.3, 0.2);  // SLUGCAT-sized body, radius ~0.54 m

Fragment moving(const std::string& id, const V& from, const V& to, double speed, const std::string& yielding_to = "") {
  Fragment f;
  f.robot_id = id;
  f.position_m = from;
  f.waypoints_m = truncate_to_length({from, to}, 2.0);
  f.waypoints_m.erase(f.waypoints_m.begin());
  f.speed_mps = speed;
  f.stationary = false;
  f.yielding_to = yielding_to;
  body_box_any_yaw(from, kHalf, f.box_min_m, f.box_max_m);
  return f;
}

Fragment standing(const std::string& id, const V& at, const std::string& yielding_to = "") {
  Fragment f;
  f.robot_id = id;
  f.position_m = at;
  f.stationary = true;
  f.yielding_to = yielding_to;
  body_box_any_yaw(at, kHalf, f.box_min_m, f.box_max_m);
  return f;
}

// A resolver that has already been moving (so its own arrival time is finite).
ConflictResolver moving_resolver(const std::string& id, const V& at, const Path& plan, double speed) {
  ConflictResolver r(id, kHalf, SafetyOptions{});
  r.decide(at, plan, speed, {}, 0.0);
  return r;
}

TEST(Resolver, FreePathIsApprovedWhole) {
  ConflictResolver r("a", kHalf, SafetyOptions{});
  const Path plan{V(0, 0, 0), V(10, 0, 0)};
  const auto d = r.decide(V(0, 0, 0), plan, 0.5, {moving("b", V(0, 8, 0), V(10, 8, 0), 0.5)}, 0.0);
  EXPECT_EQ(d.kind, DecisionKind::kFollow);
  EXPECT_NEAR(path_length(d.waypoints), 10.0, 1e-9);
  EXPECT_TRUE(d.reason.empty());
  const Fragment f = r.fragment(V(0, 0, 0));
  EXPECT_NEAR(path_length(f.path()), 2.0, 1e-9);  // only eta_p is shared
  EXPECT_FALSE(f.stationary);
}

TEST(Resolver, LaterArrivalYieldsEarlierGoes) {
  // a is 1.5 m from the crossing, b 2.5 m: b yields and stops before the zone; a goes.
  const Path plan_a{V(-1.5, 0, 0), V(5, 0, 0)};
  const Path plan_b{V(0, -2.5, 0), V(0, 5, 0)};
  auto a = moving_resolver("a", plan_a[0], plan_a, 0.5);
  auto b = moving_resolver("b", plan_b[0], plan_b, 0.5);
  const auto fa = a.fragment(plan_a[0]);
  const auto fb = b.fragment(plan_b[0]);
  const auto da = a.decide(plan_a[0], plan_a, 0.5, {fb}, 0.1);
  const auto db = b.decide(plan_b[0], plan_b, 0.5, {fa}, 0.1);
  EXPECT_EQ(da.kind, DecisionKind::kFollow);
  EXPECT_TRUE(da.yielding_to.empty());
  EXPECT_EQ(db.yielding_to, "a");
  EXPECT_EQ(b.counters().yields, 1u);
  EXPECT_EQ(b.counters().conflicts_detected, 1u);
  // b's approved path ends before it comes within the safety distance of a's path.
  const V b_end = db.kind == DecisionKind::kFollow ? db.waypoints.back() : plan_b[0];
  EXPECT_LT(b_end.y(), -(2 * 0.5408 + 0.5) + 0.2);
}

TEST(Resolver, TieGoesToTheLowerId) {
  const Path plan_a{V(-3, 0, 0), V(5, 0, 0)};
  const Path plan_b{V(0, -3, 0), V(0, 5, 0)};
  auto a = moving_resolver("a", plan_a[0], plan_a, 0.5);
  auto b = moving_resolver("b", plan_b[0], plan_b, 0.5);
  const auto fa = a.fragment(plan_a[0]);
  const auto fb = b.fragment(plan_b[0]);
  EXPECT_TRUE(a.decide(plan_a[0], plan_a, 0.5, {fb}, 0.1).yielding_to.empty());
  EXPECT_EQ(b.decide(plan_b[0], plan_b, 0.5, {fa}, 0.1).yielding_to, "a");
}

TEST(Resolver, PeerThatYieldsToMeIsNotYieldedTo) {
  const Path plan_b{V(0, -1.5, 0), V(0, 5, 0)};
  auto b = moving_resolver("b", plan_b[0], plan_b, 0.5);
  // a would have priority by id and time, but it declares that it waits for b.
  const auto d = b.decide(plan_b[0], plan_b, 0.5, {moving("a", V(-1.5, 0, 0), V(5, 0, 0), 0.5, "b")}, 0.1);
  EXPECT_TRUE(d.yielding_to.empty());
}

TEST(Resolver, MutualWaitIsBrokenByTheLowerId) {
  const Path plan_a{V(-3, 0, 0), V(5, 0, 0)};
  const Path plan_b{V(0, -3, 0), V(0, 5, 0)};
  // Make both yield: each sees the other as already moving and closer.
  auto a = moving_resolver("a", plan_a[0], plan_a, 0.5);
  auto b = moving_resolver("b", plan_b[0], plan_b, 0.5);
  a.decide(plan_a[0], plan_a, 0.5, {moving("b", V(0, -1.6, 0), V(0, 5, 0), 0.5)}, 0.1);
  b.decide(plan_b[0], plan_b, 0.5, {moving("a", V(-3, 0, 0), V(5, 0, 0), 0.5)}, 0.1);
  ASSERT_EQ(a.fragment(plan_a[0]).yielding_to, "b");
  ASSERT_EQ(b.fragment(plan_b[0]).yielding_to, "a");
  // Now each hears that the other waits for it (both still short of the crossing).
  const auto da = a.decide(plan_a[0], plan_a, 0.5, {moving("b", V(0, -1.6, 0), V(0, 5, 0), 0.5, "a")}, 0.2);
  const auto db = b.decide(plan_b[0], plan_b, 0.5, {moving("a", V(-1.6, 0, 0), V(5, 0, 0), 0.5, "b")}, 0.2);
  EXPECT_TRUE(da.yielding_to.empty());
  EXPECT_EQ(da.kind, DecisionKind::kFollow);
  EXPECT_EQ(db.yielding_to, "a");
  EXPECT_EQ(a.counters().deadlock_breaks, 1u);
}

TEST(Resolver, YieldToARobotStoppedForItsOwnReasonsEndsAfterTheTimeout) {
  const Path plan{V(0, -3, 0), V(0, 5, 0)};
  auto b = moving_resolver("b", plan[0], plan, 0.5);
  // a (lower id, equal time) is moving: b yields.
  ASSERT_EQ(b.decide(plan[0], plan, 0.5, {moving("a", V(-3, 0, 0), V(5, 0, 0), 0.5)}, 0.0).yielding_to, "a");
  // a stops right at the crossing, waiting for nobody (e.g. scanning or blocked).
  const auto a_stopped = standing("a", V(-0.4, 0, 0));
  EXPECT_EQ(b.decide(plan[0], plan, 0.5, {a_stopped}, 1.0).yielding_to, "a");
  const auto after = b.decide(plan[0], plan, 0.5, {a_stopped}, 5.0);
  EXPECT_TRUE(after.yielding_to.empty());
  EXPECT_EQ(after.kind, DecisionKind::kFollow);
  EXPECT_TRUE(after.detoured);  // and it drives around a's box
  EXPECT_EQ(b.counters().deadlock_breaks, 1u);
}

TEST(Resolver, ATeammateThatClaimsToDriveButDoesNotMoveIsTakenAsStopped) {
  const Path plan{V(0, -3, 0), V(0, 5, 0)};
  auto b = moving_resolver("b", plan[0], plan, 0.5);
  // a's fragment keeps saying it drives across b's path, but a stays where it is.
  const auto a_claims = moving("a", V(-1.0, 0, 0), V(5, 0, 0), 0.5);
  ASSERT_EQ(b.decide(plan[0], plan, 0.5, {a_claims}, 0.0).yielding_to, "a");
  EXPECT_EQ(b.decide(plan[0], plan, 0.5, {a_claims}, 10.0).yielding_to, "a") << "an honest wait is kept";
  b.decide(plan[0], plan, 0.5, {a_claims}, 16.0);  // frozen for 15 s: taken as stopped
  const auto later = b.decide(plan[0], plan, 0.5, {a_claims}, 20.0);
  EXPECT_TRUE(later.yielding_to.empty()) << "a has not moved for 20 s";
  EXPECT_EQ(later.kind, DecisionKind::kFollow);
}

TEST(Resolver, StationaryRobotOnThePathIsDetoured) {
  ConflictResolver r("a", kHalf, SafetyOptions{});
  const Path plan{V(-5, 0, 0), V(5, 0, 0)};
  const auto d = r.decide(plan[0], plan, 0.5, {standing("c", V(0, 0, 0))}, 0.0);
  ASSERT_EQ(d.kind, DecisionKind::kFollow);
  EXPECT_TRUE(d.detoured);
  EXPECT_TRUE(d.waypoints.back().isApprox(plan.back()));
  const double clearance = 2 * body_radius_of(kHalf);
  for (const auto& s : sample_path(d.waypoints, 0.02)) EXPECT_GT(distance_xy(s.point, V(0, 0, 0)), clearance);
  EXPECT_EQ(r.counters().detours, 1u);
}

TEST(Resolver, GoalOccupiedByAStoppedRobotStopsBeforeIt) {
  ConflictResolver r("a", kHalf, SafetyOptions{});
  const Path plan{V(-5, 0, 0), V(0, 0, 0)};
  const auto d = r.decide(plan[0], plan, 0.5, {standing("c", V(0, 0, 0))}, 0.0);
  ASSERT_EQ(d.kind, DecisionKind::kFollow);
  EXPECT_NE(d.reason.find("blocked by stationary robot c"), std::string::npos);
  EXPECT_LT(d.waypoints.back().x(), -2 * body_radius_of(kHalf));
  const auto at_box = r.decide(d.waypoints.back(), plan, 0.5, {standing("c", V(0, 0, 0))}, 1.0);
  EXPECT_EQ(at_box.kind, DecisionKind::kStop);
}

TEST(Resolver, BlockedRobotSharesWhereItWantsToGoAndWhomItWaitsFor) {
  ConflictResolver r("a", kHalf, SafetyOptions{});
  const Path plan{V(-5, 0, 0), V(0, 0, 0)};
  r.decide(V(-1.3, 0, 0), plan, 0.5, {standing("c", V(0, 0, 0))}, 0.0);
  const Fragment f = r.fragment(V(-1.3, 0, 0));
  EXPECT_TRUE(f.stationary);
  EXPECT_EQ(f.yielding_to, "c");
  ASSERT_FALSE(f.waypoints_m.empty());
  EXPECT_TRUE(f.waypoints_m.back().isApprox(V(0, 0, 0)));
}

TEST(Resolver, HigherIdStepsAsideForALowerIdItBlocksWhileBlockedByIt) {
  ConflictResolver b("b", kHalf, SafetyOptions{});
  const Path plan{V(2.5, 0, 0), V(0, 0, 0)};
  Fragment a = standing("a", V(0, 0, 0), "b");
  a.waypoints_m = {V(2.5, 0, 0)};
  const auto d = b.decide(V(2.5, 0, 0), plan, 0.5, {a}, 0.0);
  ASSERT_EQ(d.kind, DecisionKind::kFollow);
  EXPECT_EQ(d.yielding_to, "a");
  EXPECT_NE(d.reason.find("giving way to a"), std::string::npos);
  EXPECT_EQ(b.counters().give_ways, 1u);
  // The spot is off a's wanted path (and its continuation) by more than both bodies.
  const V spot = d.waypoints.back();
  EXPECT_GT(std::abs(spot.y()), 2 * body_radius_of(kHalf));
  EXPECT_LT(distance_xy(spot, V(2.5, 0, 0)), 4.0 + 1e-9);
  // The lower id never steps aside.
  ConflictResolver a_resolver("a", kHalf, SafetyOptions{});
  Fragment b_frag = standing("b", V(2.5, 0, 0), "a");
  b_frag.waypoints_m = {V(0, 0, 0)};
  a_resolver.decide(V(0, 0, 0), {V(0, 0, 0), V(2.5, 0, 0)}, 0.5, {b_frag}, 0.0);
  EXPECT_EQ(a_resolver.counters().give_ways, 0u);
}

TEST(Resolver, GiveWayToASpotOutOfReachIsAbandonedForAnotherDirection) {
  // The map-less safety layer picked a spot behind something the body cannot pass (in the
  // single-building run: under a low obstacle 0.75 m north of slugcat1): the driver is blocked
  // and the robot never gets closer. The give-way must end and look elsewhere, not hold the
  // robot there for good, ignoring every path planning sends.
  ConflictResolver b("b", kHalf, SafetyOptions{});
  const Path plan{V(2.5, 0, 0), V(0, 0, 0)};
  Fragment a = standing("a", V(0, 0, 0), "b");
  a.waypoints_m = {V(2.5, 0, 0)};
  const auto first = b.decide(plan[0], plan, 0.5, {a}, 0.0);
  ASSERT_NE(first.reason.find("giving way to a"), std::string::npos);
  const V spot1 = first.waypoints.back();
  // It gets 0.3 m on the way, then stands blocked.
  const V stuck = plan[0] + 0.3 * (spot1 - plan[0]).normalized();
  Decision d = first;
  double t = 0.0;
  for (; t < 10.0 && d.waypoints.back().isApprox(spot1); t += 0.2) d = b.decide(t < 0.6 ? plan[0] : stuck, plan, 0.5, {a}, t);
  EXPECT_LE(t, 0.6 + SafetyOptions{}.give_way_timeout_s + 0.5) << "still heading for the unreachable spot";
  EXPECT_EQ(b.counters().give_ways_abandoned, 1u);
  ASSERT_EQ(d.kind, DecisionKind::kFollow);
  EXPECT_NE(d.reason.find("giving way to a"), std::string::npos);  // the standoff still needs room
  const Eigen::Vector2d dir1 = (spot1 - stuck).head<2>().normalized();
  const Eigen::Vector2d dir2 = (d.waypoints.back() - stuck).head<2>().normalized();
  EXPECT_LT(dir1.dot(dir2), std::cos(50.0 * M_PI / 180.0));  // a different direction
  EXPECT_EQ(b.counters().give_ways, 2u);
}

TEST(Resolver, GiveWayWaitingForAMovingTeammateIsNotAbandoned) {
  // Stopped on the way to the spot by a yield (time that is nobody's fault) is not "no progress".
  ConflictResolver b("b", kHalf, SafetyOptions{});
  const Path plan{V(2.5, 0, 0), V(0, 0, 0)};
  Fragment a = standing("a", V(0, 0, 0), "b");
  a.waypoints_m = {V(2.5, 0, 0)};
  const V spot = b.decide(plan[0], plan, 0.5, {a}, 0.0).waypoints.back();
  // A third robot (lower id) is about to cross b's way to the spot for 10 s: b stops for it,
  // then goes on to the same spot.
  const Eigen::Vector3d along = (spot - plan[0]).normalized(), across(-along.y(), along.x(), 0.0);
  const V crossing = plan[0] + 0.8 * along;
  const Fragment c = moving("a1", crossing - 1.0 * across, crossing + 3.0 * across, 0.5);
  for (double t = 0.2; t < 10.0; t += 0.2) {
    const auto d = b.decide(plan[0], plan, 0.5, {a, c}, t);
    EXPECT_EQ(d.kind, DecisionKind::kStop) << "t=" << t;
  }
  const auto after = b.decide(plan[0], plan, 0.5, {a}, 10.0);
  ASSERT_EQ(after.kind, DecisionKind::kFollow);
  EXPECT_TRUE(after.waypoints.back().isApprox(spot));
  EXPECT_EQ(b.counters().give_ways_abandoned, 0u);
}

TEST(Resolver, TracksProgressInsteadOfJumpingToANearbyLaterPartOfThePath) {
  ConflictResolver r("a", kHalf, SafetyOptions{});
  const Path plan{V(0, 0, 0), V(10, 0, 0), V(10, 0.6, 0), V(0, 0.6, 0)};  // U around a thin wall
  for (double x = 0.0; x < 3.0; x += 0.1) r.decide(V(x, 0, 0), plan, 0.5, {}, x);
  const auto d = r.decide(V(3, 0.35, 0), plan, 0.5, {}, 3.0);  // drifted towards the return leg
  ASSERT_EQ(d.kind, DecisionKind::kFollow);
  ASSERT_GE(d.waypoints.size(), 3u);
  EXPECT_TRUE(d.waypoints[1].isApprox(V(3, 0, 0)));
  EXPECT_NEAR(path_length(d.waypoints), 0.35 + 7.0 + 0.6 + 10.0, 1e-6);
}

TEST(Resolver, ATeammateOnTheStoreyBelowIsNeitherYieldedToNorDrivenRound) {
  // Multi-building seed 5: a SLUGCAT on B3's second storey (4.2 m) drove back and forth for 140 s
  // round an idle teammate standing on the ground floor beneath it.
  ConflictResolver r("b", kHalf, SafetyOptions{});
  const Path plan{V(-5, 0, 4.0), V(5, 0, 4.0)};
  const auto below_standing = r.decide(V(-5, 0, 4.2), plan, 0.5, {standing("a", V(0, 0, 0.2))}, 0.0);
  ASSERT_EQ(below_standing.kind, DecisionKind::kFollow);
  EXPECT_FALSE(below_standing.detoured);
  EXPECT_TRUE(below_standing.reason.empty());
  EXPECT_NEAR(path_length(below_standing.waypoints), 10.0, 1e-9);
  // Crossing right under it, sooner there, with the lower id: no yield either.
  const auto below_crossing =
      r.decide(V(-1, 0, 4.2), plan, 0.5, {moving("a", V(0, -0.5, 0.2), V(0, 5, 0.2), 0.5)}, 0.2);
  ASSERT_EQ(below_crossing.kind, DecisionKind::kFollow);
  EXPECT_TRUE(below_crossing.yielding_to.empty());
  EXPECT_EQ(r.counters().conflicts_detected, 0u);
}

TEST(Resolver, ATeammateComingUpTheFlightTowardsTheRobotStillCounts) {
  // b stands at the top of a flight (4.2 m) about to go down it; a climbs it towards b, 1.4 m
  // below b's body: the same flight, so a head-on conflict as on flat ground.
  const Path down{V(0, 0, 4.0), V(-6.4, 0, 0.0)};
  ConflictResolver r("b", kHalf, SafetyOptions{});
  r.decide(V(0, 0, 4.2), down, 0.5, {}, 0.0);
  r.decide(V(0, 0, 4.2), down, 0.5, {moving("a", V(-2.3, 0, 2.8), V(0, 0, 4.2), 0.5)}, 0.2);
  EXPECT_EQ(r.counters().conflicts_detected, 1u);
}

TEST(Resolver, OptionsAreValidated) {
  SafetyOptions bad;
  bad.eta_p_m = -1;
  EXPECT_THROW(ConflictResolver("a", kHalf, bad), std::invalid_argument);
  SafetyOptions no_levels;
  no_levels.level_separation_m = 0.0;
  EXPECT_THROW(ConflictResolver("a", kHalf, no_levels), std::invalid_argument);
  EXPECT_THROW(ConflictResolver("", kHalf, SafetyOptions{}), std::invalid_argument);
}

TEST(Resolver, NoPathMeansStop) {
  ConflictResolver r("a", kHalf, SafetyOptions{});
  const auto d = r.decide(V(0, 0, 0), {}, 0.5, {}, 0.0);
  EXPECT_EQ(d.kind, DecisionKind::kStop);
  EXPECT_TRUE(r.fragment(V(0, 0, 0)).stationary);
}

}  // namespace
}  // namespace hexplore::safety
