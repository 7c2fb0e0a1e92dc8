#pragma once
// Reader for TSPLIB coordinate files (TYPE TSP, NODE_COORD_SECTION, optional DEPOT_SECTION)
// and the TSPLIB distance functions EUC_2D (nint-rounded or unrounded), CEIL_2D, ATT, GEO.
// Errors name the file and line.

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::planning {

class TsplibError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class TsplibMetric { kEuc2d, kCeil2d, kAtt, kGeo };

struct TsplibInstance {
  std::string name;
  std::string comment;
  TsplibMetric metric = TsplibMetric::kEuc2d;
  std::vector<double> x, y;  // node i (0-based) = TSPLIB node id i + 1
  std::vector<int> depots;   // DEPOT_SECTION, 0-based; empty when absent

  int dimension() const { return static_cast<int>(x.size()); }
};

// `origin` names the source in errors ("file.tsp:12: ...").
TsplibInstance parse_tsplib(std::istream& in, const std::string& origin);
TsplibInstance load_tsplib(const std::string& path);

// Distance between nodes i and j (0-based). rounded = false gives the exact Euclidean value
// for EUC_2D / CEIL_2D (the "unrounded" convention of many mTSP papers); ATT and GEO are
// always integral as TSPLIB defines them.
double tsplib_distance(const TsplibInstance& instance, int i, int j, bool rounded = true);

// An mTSP over a TSPLIB instance: every node that is no robot's depot becomes a city.
struct TsplibMtsp {
  MtspProblem problem;
  std::vector<int> city_node;  // city index -> TSPLIB node (0-based)
};
// robot_depots: depot node (0-based) per robot; robot_species: species per robot (empty = 0);
// node_species: label per node (kPublic or species; empty = all public). Throws
// std::invalid_argument on out-of-range nodes or sizes.
TsplibMtsp make_tsplib_mtsp(const TsplibInstance& instance, const std::vector<int>& robot_depots,
                            const std::vector<int>& robot_species, const std::vector<int>& node_species,
                            int num_species, RouteKind kind, bool rounded);

}  // namespace hexplore::planning
