#pragma once
// The traversal-topology graph (paper "Traversal-Topology Graph"): vertices are traversable
// ground supervoxels, edges join spatially adjacent ones and weigh their Euclidean distance;
// species k may use a vertex when its traversal requirement <= a_zeta(k).
//
// Distances are exact shortest paths. Instead of the paper's N^2-per-species Floyd–Warshall
// matrices, each (source, species) query runs one Dijkstra whose result (distance and
// predecessor arrays, O(N)) is cached until the graph changes; memory is O(N) per cached
// source, and answers equal Floyd–Warshall's (tests/highlevel/topology_graph_test.cc).
// Queries are const and thread-safe; mutation must not run concurrently with queries.
//
// Body clearance: a vertex may carry its clearance (distance to the nearest obstacle, set by
// HighLevelMap) and, per species, a waypoint pushed away from obstacles. With body radii set
// per species, a vertex closer to an obstacle than the species' radius costs extra to enter
// (kClearancePenaltyM at zero clearance, falling linearly to 0 at the radius), so paths keep
// the body clear where the map has room and still pass narrow spots (doors) where it has not.

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace hexplore::highlevel {

class TopologyGraph {
 public:
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();
  static constexpr double kClearancePenaltyM = 4.0;

  // levels[k] = traversal capability level a_zeta(k) of species index k.
  explicit TopologyGraph(std::vector<int> species_levels = {1});

  // Adds or updates a vertex (traversal_requirement >= 1).
  void upsert_vertex(uint64_t key, const Eigen::Vector3d& position, int traversal_requirement);
  // Body radius per species index (half-diagonal of its footprint); empty: no clearance costs.
  // Half-widths (optional): the least clearance a body of the species can stand in.
  void set_body_radii(std::vector<double> radii_m, std::vector<double> half_widths_m = {});
  const std::vector<double>& body_radii() const { return radii_; }
  // Whether the species' body has room to stand at vertex `key` (its clearance is at least
  // the half-width; true where either is unknown). Paths may still squeeze through where
  // not (the clearance estimate is coarse); goals should not lie there.
  bool room_to_stand(uint64_t key, int species_index) const;
  // Clearance of a vertex and its waypoint per species index (the position a path of that
  // species passes through); ignored for a key that is not a vertex.
  void set_clearance(uint64_t key, double clearance_m, std::vector<Eigen::Vector3d> waypoints);
  // Clearance of a vertex (infinity when never set or not a vertex).
  double clearance(uint64_t key) const;
  // Where a path of the species passes vertex `key`: its clearance waypoint, else its position.
  std::optional<Eigen::Vector3d> waypoint(uint64_t key, int species_index) const;
  // Extra cost of entering vertex `key` for a species (0 without radii or with room).
  double clearance_penalty(uint64_t key, int species_index) const;
  // Removes a vertex and its edges; no-op when absent.
  void remove_vertex(uint64_t key);
  // Adds or updates the undirected edge a-b; ignored (returns false) unless both are vertices.
  bool upsert_edge(uint64_t a, uint64_t b, double length_m);
  void remove_edge(uint64_t a, uint64_t b);
  void clear();

  bool contains(uint64_t key) const { return index_.count(key) != 0; }
  size_t vertex_count() const { return index_.size(); }
  size_t edge_count() const { return edge_count_; }
  int species_count() const { return static_cast<int>(levels_.size()); }
  std::optional<Eigen::Vector3d> position(uint64_t key) const;
  std::optional<int> traversal_requirement(uint64_t key) const;
  // Whether species `species_index` may stand on vertex `key`.
  bool passable(uint64_t key, int species_index) const;
  // Neighbour keys and edge lengths of a vertex (all species).
  std::vector<std::pair<uint64_t, double>> neighbours(uint64_t key) const;
  // Every vertex key, ascending.
  std::vector<uint64_t> vertex_keys() const;

  // Shortest-path length from a to b for a species; kUnreachable when either is not a
  // vertex passable for the species or no path exists; 0 when a == b (and passable).
  double dist(uint64_t a, uint64_t b, int species_index) const;
  // Vertex keys from a to b inclusive along a shortest path; empty when unreachable.
  std::vector<uint64_t> path(uint64_t a, uint64_t b, int species_index) const;
  // Distances from a to all vertices at once (key -> metres, reachable ones only).
  std::unordered_map<uint64_t, double> distances_from(uint64_t a, int species_index) const;
  // Distances from a to each of `targets` (kUnreachable where dist() would say so): from the
  // cached search of a when there is one, else by a search that stops once every target is
  // settled and is not cached. For a few nearby targets (the views of one task cluster) that
  // is a small part of the graph: ordering hexplore's cluster views cost 24 ms a round with a
  // whole search per view and 10 ms with this (bench_planning_round, MNSS stage).
  std::vector<double> distances_to(uint64_t a, const std::vector<uint64_t>& targets, int species_index) const;
  // Vertex nearest (Euclidean) to p; nullopt when the graph is empty. Ties: smaller key.
  std::optional<uint64_t> nearest(const Eigen::Vector3d& p) const;
  // Nearest vertex the species may stand on.
  std::optional<uint64_t> nearest(const Eigen::Vector3d& p, int species_index) const;

  // Bumped on every structural or weight change; cached searches of older versions are dropped.
  uint64_t version() const { return version_; }
  // Bytes held by cached single-source results (for metrics and the benchmark).
  size_t cache_bytes() const;
  size_t cached_sources() const;

 private:
  struct Vertex {
    uint64_t key = 0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    int requirement = 0;
    bool alive = false;
    double clearance = std::numeric_limits<double>::infinity();
    std::vector<Eigen::Vector3d> waypoints;  // per species; empty: the position
    std::vector<std::pair<int, double>> adjacent;  // (vertex index, length)
  };
  struct Search {  // one Dijkstra tree
    std::vector<double> distance;
    std::vector<int> predecessor;
  };

  int index_of(uint64_t key) const;
  std::shared_ptr<const Search> search(int source, int species_index) const;
  void changed();
  void grid_insert(int index);
  void grid_erase(int index);
  std::optional<uint64_t> nearest_impl(const Eigen::Vector3d& p, int species_index) const;
  double penalty(const Vertex& v, int species_index) const;

  std::vector<int> levels_;
  std::vector<double> radii_;
  std::vector<double> half_widths_;
  std::vector<Vertex> vertices_;
  std::vector<int> free_;
  std::unordered_map<uint64_t, int> index_;
  size_t edge_count_ = 0;
  uint64_t version_ = 0;
  // Uniform grid of vertex indices for nearest-vertex queries.
  double grid_cell_m_ = 1.0;
  std::unordered_map<uint64_t, std::vector<int>> grid_;

  // Cached searches keyed by (source, species). Copies of a graph start with an empty cache.
  struct Cache {
    std::mutex mutex;
    std::unordered_map<uint64_t, std::shared_ptr<const Search>> searches;
    size_t bytes = 0;
    Cache() = default;
    Cache(const Cache&) {}
    Cache& operator=(const Cache&) {
      std::lock_guard lock(mutex);
      searches.clear();
      bytes = 0;
      return *this;
    }
  };
  mutable Cache cache_;
  size_t max_cached_sources_ = 4096;
};

}  // namespace hexplore::highlevel
