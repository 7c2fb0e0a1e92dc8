#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include <gtest/gtest.h>

#include "common/core/team_config.h"
#include "common/highlevel/supervoxel.h"
#include "common/planning/clustering.h"
#include "common/planning/cost_model.h"
#include "common/planning/executable_path.h"
#include "common/planning/frontier.h"
#include "common/planning/labels.h"
#include "common/planning/planner_registry.h"
#include "common/core/rng.h"
#include "common/planning/round_inputs.h"
#include "tests/planning/planner_fixture.h"
#include "tests/support/planning_scene.h"

namespace hexplore::planning {
namespace {

// The four-robot team on the 30 x 20 m rubble-band scene (planner_fixture.h).
using Fixture = testing::PlannerFixture;
using testing::four_robot_team;
using testing::rubble_band_scene;

TEST(Labels, MatchingReadsRequirementAtMostCapability) {
  const core::TeamConfig team = four_robot_team();
  const TeamCapabilities caps = capabilities_from(team);
  // SLUGCAT: traversal 2, observation level 1 (10 m); MR1000: traversal 1, observation 2 (27 m).
  ASSERT_EQ(caps.species[0].traversal_level, 2);
  ASSERT_EQ(caps.species[0].observation_level, 1);
  ASSERT_EQ(caps.species[1].observation_level, 2);
  EXPECT_EQ(task_label(1, 1, caps, 10, 1), kPublic);
  EXPECT_EQ(task_label(1, 2, caps, 10, 1), 0);   // rubble: SLUGCAT only
  EXPECT_EQ(task_label(2, 1, caps, 10, 1), 1);   // far facade: MR1000 only
  EXPECT_EQ(task_label(2, 2, caps, 10, 1), kUnassignable);
  EXPECT_EQ(observation_requirement(5.0, caps), 1);
  EXPECT_EQ(observation_requirement(15.0, caps), 2);
  EXPECT_EQ(observation_requirement(30.0, caps), 0);
  // With three species, the weakest matching one gets a private view.
  TeamCapabilities three = caps;
  three.species.push_back({"heavy", 3, 2, 27.0, 0.3, 1.0});
  EXPECT_EQ(task_label(2, 1, three, 10, 1), 1);  // MR1000 (score 12) beats heavy (32)
}

// The three built-in species as the campus team files give them (SLUGCAT raised to traversal
// level 3 above the QUADRUPED's 2): requirements, labels and the NoHetero flattening rank them.
TEST(Labels, ThreeBuiltinSpeciesGiveTheWeakestMatchingOneItsViews) {
  core::TeamConfig team;
  core::SpeciesConfig slugcat = core::builtin_slugcat();
  slugcat.traversal_level = 3;
  team.species = {slugcat, core::builtin_quadruped(), core::builtin_mr1000()};
  team.robots = {{"s", "SLUGCAT", {0, 0, 0}, 0}, {"q", "QUADRUPED", {2, 0, 0}, 0}, {"m", "MR1000", {4, 0, 0}, 0}};
  ASSERT_NO_THROW(core::validate(team));
  const TeamCapabilities caps = capabilities_from(team);
  // Traversal 3 / 2 / 1; observation by range, 10 / 20 / 27 m: 1 / 2 / 3.
  EXPECT_EQ(highlevel::species_levels(team), (std::vector<int>{3, 2, 1}));
  EXPECT_EQ(caps.species[0].observation_level, 1);
  EXPECT_EQ(caps.species[1].observation_level, 2);
  EXPECT_EQ(caps.species[2].observation_level, 3);
  // Ground low-risk for the climbers only (stairs) needs level 2, for the SLUGCAT only (masonry) 3.
  EXPECT_EQ(highlevel::traversal_requirement(0b011u, highlevel::species_levels(team)), 2);
  EXPECT_EQ(highlevel::traversal_requirement(0b001u, highlevel::species_levels(team)), 3);
  EXPECT_EQ(highlevel::traversal_requirement(0b111u, highlevel::species_levels(team)), 1);
  EXPECT_EQ(task_label(1, 1, caps, 10, 1), kPublic);
  EXPECT_EQ(task_label(1, 2, caps, 10, 1), 1);  // upstairs: the QUADRUPED before the SLUGCAT
  EXPECT_EQ(task_label(1, 3, caps, 10, 1), 0);  // behind the masonry: the SLUGCAT only
  EXPECT_EQ(task_label(2, 1, caps, 10, 1), 2);  // 10-20 m: the MR1000 (score 13) before the QUADRUPED (22)
  EXPECT_EQ(task_label(3, 1, caps, 10, 1), 2);  // beyond 20 m: the MR1000 only
  EXPECT_EQ(task_label(2, 2, caps, 10, 1), 1);
  EXPECT_EQ(task_label(2, 3, caps, 10, 1), kUnassignable);
  EXPECT_EQ(observation_requirement(5.0, caps), 1);
  EXPECT_EQ(observation_requirement(15.0, caps), 2);
  EXPECT_EQ(observation_requirement(25.0, caps), 3);
  EXPECT_EQ(observation_requirement(30.0, caps), 0);
  const TeamCapabilities flat = caps.homogeneous();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(flat.species[size_t(k)].traversal_level, 1);
    EXPECT_EQ(flat.graph_species_of(k), 2);  // the MR1000's terrain for everyone
  }
}

TEST(TaskViews, FacadeViewsAreVisibleAndRespectRequirements) {
  Fixture f;
  const MapContext ctx(f.map, f.options);
  ViewGenerationStats stats;
  const auto views = generate_task_views(ctx, f.caps, f.options, &stats);
  ASSERT_GT(stats.facade_views, 0);
  ASSERT_GT(stats.ground_views, 0);
  std::set<uint64_t> targets;
  for (const auto& v : views) {
    for (uint64_t t : v.targets) EXPECT_TRUE(targets.insert(t).second) << "target seen by two task views";
    const auto* g = f.map.find(v.ground_key);
    ASSERT_NE(g, nullptr);
    EXPECT_TRUE(g->traversable());
    EXPECT_EQ(v.traversal_requirement, g->traversal_requirement);
    if (v.facade) {
      const auto* t = f.map.find(v.key);
      ASSERT_TRUE(t && t->facade() && !t->covered);
      EXPECT_TRUE(ctx.occlusion.clear(g->center + Eigen::Vector3d(0, 0, f.options.sensor_height_m), *t));
      EXPECT_LT((t->center - g->center).norm(), f.caps.max_observation_range() + 1.0);
    }
  }
  EXPECT_TRUE(std::is_sorted(views.begin(), views.end(), [](auto& a, auto& b) { return a.key < b.key; }));
}

// Adds one supervoxel to a snapshot: ground is traversable by every species; by default ground
// is covered and a facade an open target.
highlevel::Supervoxel add_supervoxel(highlevel::MapUpdate& up, const Eigen::Vector3d& c, highlevel::SurfaceClass s,
                                     const Eigen::Vector3d& n, std::optional<bool> covered = std::nullopt) {
  highlevel::Supervoxel sv;
  sv.center = c;
  sv.normal = n;
  sv.surface = s;
  sv.covered = covered.value_or(s == highlevel::SurfaceClass::kGround);
  sv.traversal_requirement = s == highlevel::SurfaceClass::kGround ? 1 : 0;
  sv.key = highlevel::supervoxel_key(core::cell_of(c, 1.0), s);
  up.upserts.push_back(sv);
  return sv;
}

TEST(TaskViews, WallsOccludeTheirBackSide) {
  // A facade target behind a thick wall, seen from one side only.
  highlevel::MapUpdate up;
  up.full_snapshot = true;
  auto add = [&](Eigen::Vector3d c, highlevel::SurfaceClass s, Eigen::Vector3d n, bool covered) {
    return add_supervoxel(up, c, s, n, covered).key;
  };
  // The target faces west: the far west ground is behind the occluder, the near west ground
  // (between the occluder and the target) sees it, the east ground sees its back.
  const uint64_t west = add({1.5, 0.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ(), true);
  const uint64_t near_west = add({5.5, 0.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ(), true);
  add({9.5, 0.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ(), true);
  add({4.5, 0.5, 1.5}, highlevel::SurfaceClass::kFacade, -Eigen::Vector3d::UnitX(), true);  // occluder
  const uint64_t target = add({7.5, 0.5, 1.5}, highlevel::SurfaceClass::kFacade, -Eigen::Vector3d::UnitX(), false);
  highlevel::HighLevelMap map({2, 1});
  map.apply(up);
  Fixture f;
  const MapContext ctx(map, f.options);
  const auto views = generate_task_views(ctx, f.caps, f.options);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].key, target);
  EXPECT_NE(views[0].ground_key, west);  // the west view is behind the occluder
  EXPECT_EQ(views[0].ground_key, near_west);  // the east one behind the target
}

// The frontier of the known ground (common/planning/frontier.h): on a patch of covered ground,
// the vertices whose side opens onto unseen ground inside the exploration region get a ground
// view; sides facing out of the region, and covered ground inside, get none. Without clearance
// options (no rim known) the same map has no view at all.
TEST(TaskViews, GroundWhereTheKnownGroundEndsInsideTheRegionGetsAView) {
  highlevel::MapUpdate up;
  up.full_snapshot = true;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) add_supervoxel(up, {i + 0.5, j + 0.5, 0.0}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ());
  for (size_t a = 0; a < up.upserts.size(); ++a)
    for (size_t b = a + 1; b < up.upserts.size(); ++b)
      if ((up.upserts[a].center - up.upserts[b].center).norm() < 1.5)
        up.edge_upserts.push_back(highlevel::EdgeKey::of(up.upserts[a].key, up.upserts[b].key));
  Fixture f;
  PlannerOptions o = f.options;
  // Beyond x = 5 is inside the region, beyond x = 0 and the y sides outside it.
  o.region = Eigen::AlignedBox3d(Eigen::Vector3d(0.2, 0.2, -1.0), Eigen::Vector3d(10.0, 2.8, 3.0));
  highlevel::ClearanceOptions clearance;
  clearance.body_radius_m = {0.5, 0.5};
  clearance.body_half_width_m = {0.3, 0.3};
  highlevel::HighLevelMap map({2, 1}, clearance);
  map.apply(up);
  const MapContext ctx(map, o);
  ViewGenerationStats stats;
  const auto views = generate_task_views(ctx, f.caps, o, &stats);
  EXPECT_EQ(stats.frontier_views, 3);
  std::set<double> xs;
  for (const auto& v : views) {
    EXPECT_FALSE(v.facade);
    EXPECT_TRUE(v.frontier);
    xs.insert(v.position.x());
    EXPECT_TRUE(at_frontier(map, *map.find(v.key), o.region));
  }
  EXPECT_EQ(views.size(), 3u);
  EXPECT_EQ(xs, std::set<double>{4.5});

  highlevel::HighLevelMap no_rims({2, 1});
  no_rims.apply(up);
  const MapContext plain(no_rims, o);
  EXPECT_TRUE(generate_task_views(plain, f.caps, o).empty());
}

// A target that stayed incomplete when observed from its best view gets its next view from
// another spot; with no other spot that sees it, the same spot serves again (the ledger's
// attempts give it up, and every robot's ledger learns of that).
TEST(TaskViews, ATargetObservedInVainFromASpotIsNextViewedFromAnother) {
  highlevel::MapUpdate up;
  up.full_snapshot = true;
  auto add = [&](Eigen::Vector3d c, highlevel::SurfaceClass s, Eigen::Vector3d n) { return add_supervoxel(up, c, s, n); };
  const auto far = add({1.5, 0.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ());
  const auto near = add({4.5, 0.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ());
  const auto target = add({7.5, 0.5, 1.5}, highlevel::SurfaceClass::kFacade, -Eigen::Vector3d::UnitX());
  highlevel::HighLevelMap map({2, 1});
  map.apply(up);
  Fixture f;
  GiveUpLedger ledger{GiveUpRules{.views = 2}};  // two looks: a first look is judged without giving up
  const MapContext fresh(map, f.options, std::nullopt, &ledger);
  auto views = generate_task_views(fresh, f.caps, f.options);
  ASSERT_EQ(views.size(), 1u);
  ASSERT_EQ(views[0].ground_key, far.key);  // the lower incidence scores best (Vis, degrees)

  ledger.observed(target.key, far.center + Eigen::Vector3d(0, 0, 0.4), target.voxel_count);
  const MapContext once(map, f.options, std::nullopt, &ledger);
  views = generate_task_views(once, f.caps, f.options);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].ground_key, near.key);

  // Without the near ground, no untried spot sees it.
  highlevel::HighLevelMap far_only({2, 1});
  up.upserts.erase(up.upserts.begin() + 1);
  far_only.apply(up);
  const MapContext alone(far_only, f.options, std::nullopt, &ledger);
  views = generate_task_views(alone, f.caps, f.options);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].ground_key, far.key);
}

// A wall patch seen frontally from 13 m (only the MR1000's 27 m reaches) and obliquely from
// 3.7 m (the SLUGCAT's 10 m does): Vis prefers the far frontal spot, which would make the
// target the MR1000's alone; the task view is the best the weakest species can take, so the
// target stays public (PlannerOptions::weakest_species_views). "best_score" keeps Vis alone.
TEST(TaskViews, ATargetTheWeakerSpeciesCanSeeStaysPublic) {
  highlevel::MapUpdate up;
  up.full_snapshot = true;
  auto add = [&](Eigen::Vector3d c, highlevel::SurfaceClass s, Eigen::Vector3d n) { return add_supervoxel(up, c, s, n); };
  const auto far = add({-5.5, 0.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ());
  const auto near = add({4.5, 2.5, 0.1}, highlevel::SurfaceClass::kGround, Eigen::Vector3d::UnitZ());
  add({7.5, 0.5, 1.5}, highlevel::SurfaceClass::kFacade, -Eigen::Vector3d::UnitX());
  highlevel::HighLevelMap map({2, 1});
  map.apply(up);
  Fixture f;
  const MapContext ctx(map, f.options);
  ASSERT_TRUE(f.options.weakest_species_views) << "the default";
  auto views = generate_task_views(ctx, f.caps, f.options);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].ground_key, near.key);
  EXPECT_EQ(views[0].label, kPublic);

  core::TeamConfig literal = four_robot_team();
  literal.params.task_view_choice = "best_score";
  const PlannerOptions best_score = PlannerOptions::from(literal.params);
  views = generate_task_views(ctx, f.caps, best_score);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].ground_key, far.key);
  EXPECT_EQ(views[0].label, 1) << "the MR1000's alone";
}

// Facade normals face the side their sensors saw (one facing per supervoxel): a view behind
// the surface would see its back, so it is no view.
TEST(TaskViews, AViewStandsInFrontOfTheSurface) {
  for (const double facing_x : {1.0, -1.0}) {
    highlevel::MapUpdate up;
    up.full_snapshot = true;
    highlevel::Supervoxel east;
    east.center = {9.5, 0.5, 0.1};
    east.surface = highlevel::SurfaceClass::kGround;
    east.traversal_requirement = 1;
    east.covered = true;
    east.key = highlevel::supervoxel_key(core::cell_of(east.center, 1.0), east.surface);
    highlevel::Supervoxel wall;
    wall.center = {6.5, 0.5, 1.5};
    wall.normal = {facing_x, 0.0, 0.0};
    wall.surface = highlevel::SurfaceClass::kFacade;
    wall.key = highlevel::supervoxel_key(core::cell_of(wall.center, 1.0), wall.surface,
                                         facing_x > 0 ? highlevel::Facing::kPlusX : highlevel::Facing::kMinusX);
    up.upserts = {east, wall};
    highlevel::HighLevelMap map({2, 1});
    map.apply(up);
    Fixture f;
    const MapContext ctx(map, f.options);
    std::vector<TargetRecord> outcomes;
    const auto views = generate_task_views(ctx, f.caps, f.options, nullptr, &outcomes);
    if (facing_x > 0) {
      ASSERT_EQ(views.size(), 1u) << "the wall faces the ground east of it";
      EXPECT_EQ(views[0].ground_key, east.key);
    } else {
      EXPECT_TRUE(views.empty()) << "only its back is seen from the east";
      ASSERT_EQ(outcomes.size(), 1u);
      EXPECT_EQ(outcomes[0].outcome, TargetOutcome::kNoViewpoint);
    }
  }
}

std::set<std::vector<uint64_t>> cluster_key_sets(const std::vector<TaskView>& views, const std::vector<TaskCluster>& cs) {
  std::set<std::vector<uint64_t>> out;
  for (const auto& c : cs) {
    std::vector<uint64_t> keys;
    for (int v : c.views) keys.push_back(views[size_t(v)].key);
    EXPECT_EQ(c.id, keys.front());
    out.insert(keys);
  }
  return out;
}

TEST(Clustering, IndependentOfInputOrderAndPerLabel) {
  Fixture f;
  const MapContext ctx(f.map, f.options);
  auto views = generate_task_views(ctx, f.caps, f.options);
  const auto clusters = cluster_views(views, f.options.eta_r_m);
  const auto reference = cluster_key_sets(views, clusters);
  for (const auto& c : clusters)
    for (int v : c.views) {
      EXPECT_EQ(views[size_t(v)].label, c.label);
      EXPECT_LE((views[size_t(v)].position - c.center).norm(), 2 * f.options.eta_r_m);
    }
  core::PlanRng rng(5);
  for (int trial = 0; trial < 5; ++trial) {
    rng.shuffle(views);
    EXPECT_EQ(cluster_key_sets(views, cluster_views(views, f.options.eta_r_m)), reference);
  }
}

TEST(Planner, EveryClusterGoesToExactlyOneMatchingReachableRobot) {
  Fixture f;
  for (const std::string name : {"hexplore", "no-hetero", "no-mnss"}) {
    auto planner = f.planner(name);
    const PlanResult res = planner->plan(f.request(0));
    const TeamCapabilities caps = name == "no-hetero" ? f.caps.homogeneous() : f.caps;
    const RoundInputs in = prepare_round(f.request(0), caps, f.options);  // the planner's own views
    const auto& views = in.views;
    const auto clusters = cluster_views(views, f.options.eta_r_m);
    std::map<uint64_t, const TaskCluster*> by_id;
    for (const auto& c : clusters) by_id[c.id] = &c;
    std::map<uint64_t, int> times;
    const auto req = f.request(0);
    for (size_t r = 0; r < res.robots.size(); ++r) {
      const int k = req.robots[r].species;
      const auto start = f.map.graph().nearest(req.robots[r].position, k);
      ASSERT_TRUE(start);
      for (uint64_t id : res.robots[r].cluster_ids) {
        ++times[id];
        const TaskCluster* c = by_id.at(id);
        EXPECT_TRUE(c->label == kPublic || c->label == k) << name << ": cluster " << id << " to robot " << r;
        const auto anchor = f.map.graph().nearest(c->center, k);
        ASSERT_TRUE(anchor);
        EXPECT_TRUE(std::isfinite(f.map.graph().dist(*start, *anchor, k))) << name << ": unreachable cluster";
        for (int v : c->views)  // every view of it is reachable for this species
          EXPECT_TRUE(std::isfinite(f.map.graph().dist(*start, views[size_t(v)].ground_key, k)));
      }
    }
    for (const auto& [id, n] : times) EXPECT_EQ(n, 1) << name << ": cluster " << id;
    EXPECT_EQ(int(times.size()) + res.dropped_clusters, res.clusters) << name;
    EXPECT_GT(res.robots[0].route.size(), 0u);
    // The route's first view can be driven to from where the robot stands.
    const ExecutablePlan path =
        executable_path(f.map.graph(), req.robots[0].position, req.robots[0].species, res.robots[0].route.front());
    ASSERT_TRUE(path.valid) << name;
    EXPECT_LT((path.waypoints.front() - req.robots[0].position).norm(), 1.5);
    EXPECT_EQ(path.goal.ground_key, res.robots[0].route.front().ground_key);
  }
}

TEST(Planner, WheeledRobotsNeverGetClustersBehindRubble) {
  Fixture f;
  const PlanResult res = f.planner("hexplore")->plan(f.request(2));
  for (size_t r = 2; r < 4; ++r)  // the MR1000 robots
    for (const auto& c : res.robots[r].cluster_centers) EXPECT_LT(c.x(), 24.0);
  bool east = false;
  for (size_t r = 0; r < 2; ++r)
    for (const auto& c : res.robots[r].cluster_centers) east |= c.x() > 26.0;
  EXPECT_TRUE(east) << "the tracked robots cover the east end";
}

TEST(Planner, SameInputSameRoutesOnEveryRobot) {
  Fixture f;
  // Two robots plan independently (separate planner instances, maps fed in different order).
  highlevel::HighLevelMap other(highlevel::species_levels(f.team));
  auto up = synthetic_scene(rubble_band_scene());
  std::reverse(up.upserts.begin(), up.upserts.end());
  std::reverse(up.edge_upserts.begin(), up.edge_upserts.end());
  other.apply(up);
  PlanRequest a = f.request(0), b = f.request(3);
  b.map = &other;
  const PlanResult ra = f.planner("hexplore")->plan(a);
  const PlanResult rb = f.planner("hexplore")->plan(b);
  ASSERT_EQ(ra.robots.size(), rb.robots.size());
  for (size_t r = 0; r < ra.robots.size(); ++r) EXPECT_EQ(ra.robots[r].cluster_ids, rb.robots[r].cluster_ids);
  EXPECT_EQ(ra.fitness, rb.fitness);
  // Re-planning with the shared solution as reference keeps the assignment.
  PlanRequest next = f.request(0);
  next.round = 1;
  next.shared = {ra.as_reference("slug1"), rb.as_reference("mr2")};
  const PlanResult rc = f.planner("hexplore")->plan(next);
  ASSERT_TRUE(rc.agreement.has_value());
  EXPECT_GE(*rc.agreement, 0.9);
}

TEST(Planner, AblationsPlanAndRegistryNamesThem) {
  Fixture f;
  const PlannerRegistry reg = PlannerRegistry::builtin();
  EXPECT_EQ(reg.names(), (std::vector<std::string>{"hexplore", "mdvrp+", "mromt+", "no-assign", "no-cluster", "no-hetero",
                                                    "no-mnss", "tspga+"}));
  try {
    reg.create("greedy");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "unknown planner 'greedy'; known planners: hexplore, mdvrp+, mromt+, no-assign, no-cluster, no-hetero, "
                 "no-mnss, tspga+");
  }
  for (const auto& name : reg.names()) {
    auto p = f.planner(name);
    EXPECT_EQ(p->name(), name);
    const PlanResult res = p->plan(f.request(1));
    EXPECT_EQ(res.planner, name);
    EXPECT_GT(res.views, 0) << name;
    EXPECT_FALSE(res.robots[1].route.empty()) << name;
    const PlanRequest req = f.request(1);
    EXPECT_TRUE(executable_path(f.map.graph(), req.robots[1].position, req.robots[1].species,
                                res.robots[1].route.front())
                    .valid)
        << name;
  }
  // no-hetero sees fewer, all-public views (weakest traversal, shortest range).
  const PlanResult full = f.planner("hexplore")->plan(f.request(0));
  const PlanResult flat = f.planner("no-hetero")->plan(f.request(0));
  EXPECT_LT(flat.views, full.views);
}

// NoHetero treats every robot as the weakest species in every mechanism: with every robot
// west of the rubble strip (x 24-25 m, traversal requirement 2) that only the tracked species
// could cross, no view stands on or beyond it, and paths use the wheeled species' terrain;
// the full planner gives the tracked robot the far side.
TEST(Planners, NoHeteroUsesTheWeakestSpeciesTerrainForEveryone) {
  Fixture f;
  f.team.robots.erase(f.team.robots.begin() + 1);  // slug2 starts east of the strip
  f.caps = capabilities_from(f.team);
  const int mr1000 = *f.team.species_index("MR1000");
  bool east_for_full = false;
  for (int self = 0; self < int(f.team.robots.size()); ++self) {
    const PlanRequest req = f.request(self);
    const PlanResult flat = f.planner("no-hetero")->plan(req);
    EXPECT_EQ(flat.path_species, mr1000);
    for (const auto& v : flat.robots[size_t(self)].route) {
      EXPECT_LT(v.position.x(), 24.0) << req.robots[size_t(self)].id << ": a view across the rubble";
      EXPECT_LE(v.traversal_requirement, 1);
    }
    const PlanResult full = f.planner("hexplore")->plan(req);
    EXPECT_EQ(full.path_species, req.robots[size_t(self)].species);
    for (const auto& v : full.robots[size_t(self)].route) east_for_full |= v.position.x() > 25.0;
  }
  EXPECT_TRUE(east_for_full) << "the full planner never uses the tracked robot's terrain";
}

}  // namespace
}  // namespace hexplore::planning
