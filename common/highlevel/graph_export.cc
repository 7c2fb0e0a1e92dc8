#include "common/highlevel/graph_export.h"

#include <cmath>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hexplore::highlevel {

void write_graph_ply(const TopologyGraph& graph, std::ostream& out) {
  const std::vector<uint64_t> keys = graph.vertex_keys();
  std::unordered_map<uint64_t, size_t> row;
  for (size_t i = 0; i < keys.size(); ++i) row[keys[i]] = i;
  std::vector<std::pair<size_t, size_t>> edges;
  for (size_t i = 0; i < keys.size(); ++i)
    for (const auto& neighbour : graph.neighbours(keys[i])) {
      const auto it = row.find(neighbour.first);
      if (it != row.end() && it->second > i) edges.emplace_back(i, it->second);
    }
  out << "ply\nformat ascii 1.0\ncomment hexplore traversal-topology graph\n"
      << "element vertex " << keys.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property uchar requirement\nproperty float clearance\n"
      << "element edge " << edges.size() << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (uint64_t key : keys) {
    const Eigen::Vector3d p = *graph.position(key);
    const double clearance = graph.clearance(key);
    out << float(p.x()) << ' ' << float(p.y()) << ' ' << float(p.z()) << ' ' << graph.traversal_requirement(key).value_or(0)
        << ' ' << (std::isfinite(clearance) ? float(clearance) : -1.0f) << '\n';
  }
  for (const auto& [a, b] : edges) out << a << ' ' << b << '\n';
}

}  // namespace hexplore::highlevel
