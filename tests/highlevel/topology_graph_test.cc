#include "common/highlevel/topology_graph.h"

#include <cmath>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "common/highlevel/graph_export.h"
#include "common/highlevel/high_level_map.h"
#include "common/highlevel/segmenter.h"

#include "tests/highlevel/synthetic_map.h"
#include "tests/support/floyd_warshall.h"

namespace hexplore::highlevel {
namespace {

const std::vector<int> kLevels = {1, 2, 3};

// Random geometric graph: vertices in a box, edges between close ones, random requirements.
TopologyGraph random_graph(int n, uint32_t seed, double radius = 2.5) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(0.0, 20.0);
  std::uniform_int_distribution<int> req(1, 3);
  TopologyGraph g(kLevels);
  std::vector<Eigen::Vector3d> pos;
  for (int i = 0; i < n; ++i) {
    pos.emplace_back(coord(rng), coord(rng), 0.2 * coord(rng));
    g.upsert_vertex(1000 + 7 * i, pos.back(), req(rng));
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((pos[i] - pos[j]).norm() < radius) g.upsert_edge(1000 + 7 * i, 1000 + 7 * j, (pos[i] - pos[j]).norm());
  return g;
}

// dist equals Floyd–Warshall's for every pair and species; path is a valid walk of that length.
void expect_matches_floyd_warshall(const TopologyGraph& g) {
  const auto keys = g.vertex_keys();
  for (int species = 0; species < g.species_count(); ++species) {
    const auto fw = floyd_warshall<double>(g, species);
    for (uint64_t a : keys) {
      for (uint64_t b : keys) {
        const double d = g.dist(a, b, species);
        const double ref = fw.dist(a, b);
        if (std::isinf(ref)) {
          ASSERT_TRUE(std::isinf(d)) << a << "->" << b << " species " << species;
          ASSERT_TRUE(g.path(a, b, species).empty());
          continue;
        }
        ASSERT_NEAR(d, ref, 1e-9) << a << "->" << b << " species " << species;
        const auto p = g.path(a, b, species);
        ASSERT_FALSE(p.empty());
        ASSERT_EQ(p.front(), a);
        ASSERT_EQ(p.back(), b);
        double len = 0.0;
        for (size_t i = 1; i < p.size(); ++i) {
          ASSERT_TRUE(g.passable(p[i], species));
          bool adjacent = false;
          for (const auto& [k, l] : g.neighbours(p[i - 1]))
            if (k == p[i]) {
              adjacent = true;
              len += l;
            }
          ASSERT_TRUE(adjacent);
        }
        ASSERT_NEAR(len, ref, 1e-9);
      }
    }
  }
}

TEST(TopologyGraph, DistanceAndPathEqualFloydWarshallOnRandomGraphs) {
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    const auto g = random_graph(60 + 20 * static_cast<int>(seed), seed);
    ASSERT_GT(g.edge_count(), 0u);
    expect_matches_floyd_warshall(g);
  }
}

// distances_to answers what dist() would, by a search that stops early (nothing cached yet)
// and from the cached search once there is one; clearance costs included.
TEST(TopologyGraph, DistancesToEqualDistWithAndWithoutACachedSearch) {
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    auto g = random_graph(80 + 20 * static_cast<int>(seed), seed);
    g.set_body_radii({0.5, 0.6, 0.7});
    const auto keys = g.vertex_keys();
    for (size_t i = 0; i < keys.size(); i += 3) g.set_clearance(keys[i], 0.1 * double(i % 7), {});
    for (int species = 0; species < g.species_count(); ++species)
      for (size_t a = 0; a < keys.size(); a += 9) {
        std::vector<uint64_t> targets = {keys[a], 999999};  // itself, and a key not in the graph
        for (size_t b = (a * 7) % keys.size(), n = 0; n < 6; b = (b + 11) % keys.size(), ++n) targets.push_back(keys[b]);
        const auto early = g.distances_to(keys[a], targets, species);
        for (size_t t = 0; t < targets.size(); ++t)  // dist() caches the whole search of keys[a]
          EXPECT_EQ(early[t], g.dist(keys[a], targets[t], species)) << seed << " " << species << " " << a << " " << t;
        EXPECT_EQ(g.distances_to(keys[a], targets, species), early);
      }
  }
}

TEST(TopologyGraph, CachedAnswersFollowGraphChanges) {
  auto g = random_graph(120, 42);
  std::mt19937 rng(5);
  const auto keys = g.vertex_keys();
  std::uniform_int_distribution<size_t> pick(0, keys.size() - 1);
  for (int round = 0; round < 5; ++round) {
    expect_matches_floyd_warshall(g);  // fills the cache
    for (int k = 0; k < 10; ++k) {
      const uint64_t a = keys[pick(rng)];
      const uint64_t b = keys[pick(rng)];
      switch (k % 4) {
        case 0: g.remove_vertex(a); break;
        case 1: g.remove_edge(a, b); break;
        case 2:
          if (g.contains(a)) g.upsert_vertex(a, *g.position(a), 1 + (round + k) % 3);
          break;
        default:
          if (g.contains(a) && g.contains(b)) g.upsert_edge(a, b, (*g.position(a) - *g.position(b)).norm() + 0.5);
      }
    }
  }
  expect_matches_floyd_warshall(g);
}

TEST(TopologyGraph, UnknownOrForbiddenVerticesAreUnreachable) {
  TopologyGraph g({1, 2});
  g.upsert_vertex(1, {0, 0, 0}, 1);
  g.upsert_vertex(2, {1, 0, 0}, 2);
  g.upsert_vertex(3, {2, 0, 0}, 1);
  g.upsert_edge(1, 2, 1.0);
  g.upsert_edge(2, 3, 1.0);
  EXPECT_TRUE(std::isinf(g.dist(1, 3, 0)));  // level-1 species may not cross vertex 2
  EXPECT_DOUBLE_EQ(g.dist(1, 3, 1), 2.0);
  EXPECT_EQ(g.path(1, 3, 1), (std::vector<uint64_t>{1, 2, 3}));
  EXPECT_TRUE(std::isinf(g.dist(1, 99, 1)));
  EXPECT_TRUE(std::isinf(g.dist(1, 3, 7)));
  EXPECT_DOUBLE_EQ(g.dist(3, 3, 0), 0.0);
  EXPECT_FALSE(g.upsert_edge(1, 99, 1.0));
}

TEST(TopologyGraph, NearestIsTheEuclideanNearestVertex) {
  auto g = random_graph(300, 9);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-30.0, 50.0);
  const auto keys = g.vertex_keys();
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d p(coord(rng), coord(rng), coord(rng) * 0.1);
    for (int species : {-1, 0, 1, 2}) {
      uint64_t best = 0;
      double best_d = 1e300;
      for (uint64_t k : keys) {
        if (species >= 0 && !g.passable(k, species)) continue;
        const double d = (*g.position(k) - p).norm();
        if (d < best_d || (d == best_d && k < best)) {
          best_d = d;
          best = k;
        }
      }
      const auto got = species < 0 ? g.nearest(p) : g.nearest(p, species);
      ASSERT_TRUE(got.has_value());
      EXPECT_EQ(*got, best);
    }
  }
  EXPECT_FALSE(TopologyGraph().nearest(Eigen::Vector3d::Zero()).has_value());
}

TEST(TopologyGraph, RealMapGraphMatchesFloydWarshall) {
  testing::CampusSpec spec;
  spec.size_m = 20.0;
  spec.buildings = 1;
  spec.building_m = 8.0;
  SupervoxelSegmenter seg({}, {1, 2});
  seg.update(testing::campus_voxels(spec));
  HighLevelMap map({1, 2});
  MapUpdate all;
  for (const auto& [k, sv] : seg.supervoxels()) all.upserts.push_back(sv);
  all.edge_upserts = seg.edges();
  map.apply(all);
  const TopologyGraph& g = map.graph();
  ASSERT_GT(g.vertex_count(), 300u);
  ASSERT_GT(g.edge_count(), 1000u);
  expect_matches_floyd_warshall(g);
  // The indoor ground floor is reachable from outside through the door; the upper floor is not.
  const auto outside = g.nearest(Eigen::Vector3d(1.0, 1.0, 0.0), 0);
  const auto indoor = g.nearest(Eigen::Vector3d(10.0, 10.0, 0.0), 0);
  const auto upstairs = g.nearest(Eigen::Vector3d(10.0, 10.0, 3.0), 0);
  ASSERT_TRUE(outside && indoor && upstairs);
  // The door lies in a rough patch (requirement 2): only the level-2 species gets in.
  EXPECT_LT(g.dist(*outside, *indoor, 1), 40.0);
  EXPECT_TRUE(std::isinf(g.dist(*outside, *indoor, 0)));
  EXPECT_TRUE(std::isinf(g.dist(*outside, *upstairs, 1)));
}

TEST(GraphExport, PlyHoldsEveryVertexWithItsRequirementAndEveryEdgeOnce) {
  TopologyGraph g({1, 2});
  g.upsert_vertex(30, {0, 0, 0}, 1);
  g.upsert_vertex(10, {1, 0, 0.5}, 2);
  g.upsert_vertex(20, {2, 0, 1}, 1);
  g.upsert_edge(30, 10, 1.1);
  g.upsert_edge(10, 20, 1.1);
  g.set_clearance(20, 0.75, {});
  std::ostringstream out;
  write_graph_ply(g, out);
  const std::string ply = out.str();
  EXPECT_NE(ply.find("element vertex 3\n"), std::string::npos) << ply;
  EXPECT_NE(ply.find("element edge 2\n"), std::string::npos) << ply;
  // Rows in key order: 10, 20, 30; edges 10-20 and 10-30 as rows 0-1 and 0-2.
  const std::string body = ply.substr(ply.find("end_header\n") + 11);
  EXPECT_EQ(body, "1 0 0.5 2 -1\n2 0 1 1 0.75\n0 0 0 1 -1\n0 1\n0 2\n");
}

}  // namespace
}  // namespace hexplore::highlevel
