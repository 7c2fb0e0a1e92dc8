#pragma once
// The traversal-topology graph as a PLY file a viewer opens (MeshLab, CloudCompare): one vertex
// per graph vertex with its traversal requirement and clearance, one edge per graph edge. For
// finding out, from a mission's planning traces, why a place had no path (the planning
// service writes one now and then with --trace-graph-period-s).

#include <ostream>

#include "common/highlevel/topology_graph.h"

namespace hexplore::highlevel {

// ASCII PLY: element vertex (float x, y, z; uchar requirement; float clearance, -1 when
// unknown) in ascending key order, element edge (int vertex1, vertex2) each edge once.
void write_graph_ply(const TopologyGraph& graph, std::ostream& out);

}  // namespace hexplore::highlevel
