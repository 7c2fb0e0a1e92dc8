#include "common/planning/mtsp/tsplib.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace hexplore::planning {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// TSPLIB's nint(): round half up for non-negative distances.
// The largest TSPLIB instance (pla85900) has 85,900 nodes; the GA routes a few thousand.
constexpr int kMaxDimension = 1'000'000;

double nint(double v) { return std::floor(v + 0.5); }

double geo_radians(double v) {
  constexpr double kPi = 3.141592;  // the value TSPLIB prescribes
  const double deg = std::trunc(v);
  const double min = v - deg;
  return kPi * (deg + 5.0 * min / 3.0) / 180.0;
}

}  // namespace

TsplibInstance parse_tsplib(std::istream& in, const std::string& origin) {
  TsplibInstance inst;
  int dimension = -1;
  int line_no = 0;
  std::string line;
  auto fail = [&](const std::string& what) -> void {
    throw TsplibError(origin + ":" + std::to_string(line_no) + ": " + what);
  };
  enum class Section { kHeader, kCoords, kDepots, kDone } section = Section::kHeader;
  std::vector<char> seen;
  int coords_read = 0;
  bool have_type = false, have_metric = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t == "EOF") {
      section = Section::kDone;
      break;
    }
    if (section == Section::kCoords && coords_read < dimension) {
      std::istringstream ls(t);
      long id;
      double x, y;
      if (!(ls >> id >> x >> y)) fail("expected '<node id> <x> <y>', got '" + t + "'");
      std::string extra;
      if (ls >> extra) fail("unexpected trailing text '" + extra + "' after coordinates");
      if (id < 1 || id > dimension) fail("node id " + std::to_string(id) + " outside 1.." + std::to_string(dimension));
      if (seen[size_t(id - 1)]) fail("node id " + std::to_string(id) + " appears twice");
      seen[size_t(id - 1)] = 1;
      inst.x[size_t(id - 1)] = x;
      inst.y[size_t(id - 1)] = y;
      ++coords_read;
      continue;
    }
    if (section == Section::kDepots) {
      std::istringstream ls(t);
      long id;
      if (!(ls >> id)) fail("expected a depot node id or -1, got '" + t + "'");
      if (id == -1) {
        section = Section::kHeader;
        continue;
      }
      if (id < 1 || id > dimension) fail("depot " + std::to_string(id) + " outside 1.." + std::to_string(dimension));
      inst.depots.push_back(int(id - 1));
      continue;
    }
    if (t == "NODE_COORD_SECTION") {
      if (dimension <= 0) fail("NODE_COORD_SECTION before a positive DIMENSION");
      if (!have_metric) fail("NODE_COORD_SECTION before EDGE_WEIGHT_TYPE");
      section = Section::kCoords;
      inst.x.assign(size_t(dimension), 0.0);
      inst.y.assign(size_t(dimension), 0.0);
      seen.assign(size_t(dimension), 0);
      continue;
    }
    if (t == "DEPOT_SECTION") {
      if (dimension <= 0) fail("DEPOT_SECTION before a positive DIMENSION");
      section = Section::kDepots;
      continue;
    }
    if (section == Section::kCoords) fail("more than DIMENSION = " + std::to_string(dimension) + " coordinate lines");
    const auto colon = t.find(':');
    if (colon == std::string::npos) fail("expected 'KEY : value' or a section name, got '" + t + "'");
    const std::string key = trim(t.substr(0, colon));
    const std::string value = trim(t.substr(colon + 1));
    if (key == "NAME") {
      inst.name = value;
    } else if (key == "COMMENT") {
      inst.comment += (inst.comment.empty() ? "" : "\n") + value;
    } else if (key == "TYPE") {
      if (value != "TSP" && value != "ATSP" && value != "CVRP")
        fail("TYPE '" + value + "' is not supported (TSP, CVRP coordinates only)");
      have_type = true;
    } else if (key == "DIMENSION") {
      try {
        size_t used = 0;
        dimension = std::stoi(value, &used);
        if (used != value.size()) throw std::invalid_argument(value);
      } catch (const std::exception&) {
        fail("DIMENSION '" + value + "' is not an integer");
      }
      if (dimension < 1) fail("DIMENSION must be positive");
      // The coordinates are allocated when their section starts: a header may not make the
      // reader reserve gigabytes for nodes the file never holds (found by fuzz_tsplib).
      if (dimension > kMaxDimension)
        fail("DIMENSION " + std::to_string(dimension) + " above this reader's limit of " + std::to_string(kMaxDimension));
    } else if (key == "EDGE_WEIGHT_TYPE") {
      static const std::map<std::string, TsplibMetric> kMetrics = {
          {"EUC_2D", TsplibMetric::kEuc2d}, {"CEIL_2D", TsplibMetric::kCeil2d},
          {"ATT", TsplibMetric::kAtt}, {"GEO", TsplibMetric::kGeo}};
      const auto it = kMetrics.find(value);
      if (it == kMetrics.end()) fail("EDGE_WEIGHT_TYPE '" + value + "' is not supported (EUC_2D, CEIL_2D, ATT, GEO)");
      inst.metric = it->second;
      have_metric = true;
    } else if (key == "CAPACITY" || key == "NODE_COORD_TYPE" || key == "DISPLAY_DATA_TYPE") {
      // Accepted and not needed for routing by coordinates.
    } else {
      fail("unknown keyword '" + key + "'");
    }
  }
  (void)have_type;
  if (dimension <= 0) fail("no DIMENSION");
  if (inst.x.empty()) fail("no NODE_COORD_SECTION");
  if (coords_read < dimension)
    fail("NODE_COORD_SECTION ended after " + std::to_string(coords_read) + " of " + std::to_string(dimension) + " nodes");
  if (section == Section::kDepots) fail("DEPOT_SECTION not terminated by -1");
  return inst;
}

TsplibInstance load_tsplib(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw TsplibError(path + ": cannot open file");
  return parse_tsplib(in, path);
}

double tsplib_distance(const TsplibInstance& inst, int i, int j, bool rounded) {
  const double dx = inst.x[size_t(i)] - inst.x[size_t(j)];
  const double dy = inst.y[size_t(i)] - inst.y[size_t(j)];
  switch (inst.metric) {
    case TsplibMetric::kEuc2d: {
      const double d = std::sqrt(dx * dx + dy * dy);
      return rounded ? nint(d) : d;
    }
    case TsplibMetric::kCeil2d: {
      const double d = std::sqrt(dx * dx + dy * dy);
      return rounded ? std::ceil(d) : d;
    }
    case TsplibMetric::kAtt: {
      const double r = std::sqrt((dx * dx + dy * dy) / 10.0);
      const double t = nint(r);
      return t < r ? t + 1.0 : t;
    }
    case TsplibMetric::kGeo: {
      if (i == j) return 0.0;
      constexpr double kRrr = 6378.388;
      const double lat_i = geo_radians(inst.x[size_t(i)]), lon_i = geo_radians(inst.y[size_t(i)]);
      const double lat_j = geo_radians(inst.x[size_t(j)]), lon_j = geo_radians(inst.y[size_t(j)]);
      const double q1 = std::cos(lon_i - lon_j);
      const double q2 = std::cos(lat_i - lat_j);
      const double q3 = std::cos(lat_i + lat_j);
      return std::floor(kRrr * std::acos(0.5 * ((1.0 + q1) * q2 - (1.0 - q1) * q3)) + 1.0);
    }
  }
  return 0.0;
}

TsplibMtsp make_tsplib_mtsp(const TsplibInstance& inst, const std::vector<int>& robot_depots,
                            const std::vector<int>& robot_species, const std::vector<int>& node_species,
                            int num_species, RouteKind kind, bool rounded) {
  const int n = inst.dimension();
  if (robot_depots.empty()) throw std::invalid_argument("make_tsplib_mtsp: no robots");
  if (!robot_species.empty() && robot_species.size() != robot_depots.size())
    throw std::invalid_argument("make_tsplib_mtsp: robot_species size differs from robot_depots");
  if (!node_species.empty() && node_species.size() != size_t(n))
    throw std::invalid_argument("make_tsplib_mtsp: node_species size differs from DIMENSION");
  std::vector<char> is_depot(size_t(n), 0);
  for (int d : robot_depots) {
    if (d < 0 || d >= n) throw std::invalid_argument("make_tsplib_mtsp: depot node " + std::to_string(d + 1) + " outside 1.." + std::to_string(n));
    is_depot[size_t(d)] = 1;
  }
  TsplibMtsp out;
  MtspProblem& p = out.problem;
  for (int i = 0; i < n; ++i)
    if (!is_depot[size_t(i)]) out.city_node.push_back(i);
  p.num_cities = int(out.city_node.size());
  p.num_species = std::max(1, num_species);
  p.kind = kind;
  for (size_t r = 0; r < robot_depots.size(); ++r) p.robots.push_back({robot_species.empty() ? 0 : robot_species[r]});
  if (!node_species.empty()) {
    p.city_species.resize(size_t(p.num_cities));
    for (int c = 0; c < p.num_cities; ++c) p.city_species[size_t(c)] = node_species[size_t(out.city_node[size_t(c)])];
  }
  std::vector<int> node_of(size_t(p.num_nodes()));
  for (int c = 0; c < p.num_cities; ++c) node_of[size_t(c)] = out.city_node[size_t(c)];
  for (size_t r = 0; r < robot_depots.size(); ++r) node_of[size_t(p.num_cities) + r] = robot_depots[r];
  CostMatrix m(p.num_nodes());
  for (int a = 0; a < p.num_nodes(); ++a)
    for (int b = 0; b < p.num_nodes(); ++b) m.set(a, b, a == b ? 0.0 : tsplib_distance(inst, node_of[size_t(a)], node_of[size_t(b)], rounded));
  p.travel.push_back(std::move(m));
  p.positions.resize(size_t(p.num_nodes()));
  for (int a = 0; a < p.num_nodes(); ++a) p.positions[size_t(a)] = {inst.x[size_t(node_of[size_t(a)])], inst.y[size_t(node_of[size_t(a)])], 0.0};
  return out;
}

}  // namespace hexplore::planning
