// hexplore_unseen: the observable ground-truth samples a finished mission never mapped, and
// where they are. Observable completeness stops short of 100 % on every mission; this says
// whether the rest is high up (above what a sensor's field of view reaches from close by), far
// from where any robot drove, or beside its path (seen from nowhere the robots stood).
//
//   hexplore_unseen --config deploy/teams/multi-building.yaml --run results/x/seed-5
//
// Reads the run's summary.json (seed), map.pcd (the team's union map) and trajectories.csv;
// recomputes the scene's samples and observable mask as the station does (the same seed gives
// the same ones) and prints the counts by height and by the nearest any robot drove, with the
// run's own observable completeness beside ours as a check. Writes RUN/unseen_observable.ply.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/core/team_config.h"
#include "common/evaluation/completeness_evaluator.h"
#include "common/evaluation/map_export.h"
#include "common/sim/ground_truth.h"
#include "common/sim/observability.h"
#include "common/sim/ray_caster.h"
#include "common/sim/scenes.h"

namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A number field of summary.json ("seed": 5), or NaN when absent.
double summary_number(const std::string& json, const std::string& field) {
  const std::regex re("\"" + field + "\": *([-0-9.eE]+)");
  std::smatch m;
  return std::regex_search(json, m, re) ? std::stod(m[1].str()) : std::nan("");
}

// Every robot's driven positions (x, y), one kept per half metre moved.
std::vector<std::array<float, 2>> driven_positions(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  if (!in) throw std::runtime_error("cannot read " + csv.string());
  std::string line;
  std::getline(in, line);  // robot,sim_time_s,x_m,y_m,z_m
  std::vector<std::array<float, 2>> kept;
  std::string last_robot;
  std::array<float, 2> last{};
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string robot, t, x, y;
    if (!std::getline(row, robot, ',') || !std::getline(row, t, ',') || !std::getline(row, x, ',') ||
        !std::getline(row, y, ','))
      continue;
    const std::array<float, 2> p{std::stof(x), std::stof(y)};
    if (robot != last_robot || std::hypot(p[0] - last[0], p[1] - last[1]) >= 0.5f) {
      kept.push_back(p);
      last = p;
      last_robot = robot;
    }
  }
  return kept;
}

// Index of the band [edges[i], edges[i+1]) holding v; the last band is open.
size_t band_of(double v, const std::vector<double>& edges) {
  size_t i = 0;
  while (i + 1 < edges.size() && v >= edges[i + 1]) ++i;
  return i;
}

void print_bands(const std::string& title, const std::vector<double>& edges, const std::vector<size_t>& unseen,
                 const std::vector<size_t>& observable) {
  std::printf("\n%s\n| band | observable samples | unseen | unseen share of the band | share of all unseen |\n|---|---|---|---|---|\n",
              title.c_str());
  size_t total = 0;
  for (size_t n : unseen) total += n;
  for (size_t i = 0; i < edges.size(); ++i) {
    char band[48];
    if (i == 0) std::snprintf(band, sizeof band, "< %g", edges[1]);
    else if (i + 1 == edges.size()) std::snprintf(band, sizeof band, ">= %g", edges[i]);
    else std::snprintf(band, sizeof band, "%g-%g", edges[i], edges[i + 1]);
    std::printf("| %s m | %zu | %zu | %.1f %% | %.1f %% |\n", band, observable[i], unseen[i],
                observable[i] ? 100.0 * unseen[i] / observable[i] : 0.0, total ? 100.0 * unseen[i] / total : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string config, run;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--config") config = argv[i + 1];
    else if (a == "--run") run = argv[i + 1];
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  if (config.empty() || run.empty()) {
    std::cerr << "usage: hexplore_unseen --config TEAM.yaml --run RESULTS/seed-N\n";
    return 2;
  }
  try {
    using namespace hexplore;
    const std::filesystem::path dir(run);
    const std::string summary = read_file(dir / "summary.json");
    const double seed = summary_number(summary, "seed");
    if (std::isnan(seed)) throw std::runtime_error((dir / "summary.json").string() + " has no seed");
    core::TeamConfig team = core::load_team_config(config);
    team.params.seed = static_cast<uint64_t>(seed);
    const sim::SceneInfo scene = sim::load_team_scene(team);
    const sim::SurfaceSamples samples = sim::sample_surface(scene.mesh, evaluation::EvaluatorOptions{}.sample_spacing_m,
                                                                team.params.seed, &scene.site);
    const sim::RayCaster caster(scene.mesh);
    const std::vector<uint8_t> mask = sim::observable_mask(caster, samples, team, scene.site);
    const auto map = sim::VoxelSet::from_points(team.params.map_resolution_m,
                                                evaluation::load_map_points((dir / "map.pcd").string()));
    const auto driven = driven_positions(dir / "trajectories.csv");

    const std::vector<double> heights{-1e9, 0.5, 2.0, 5.0, 10.0};  // the first band is open below
    const std::vector<double> distances{0.0, 2.0, 5.0, 10.0, 20.0};  // "< 2" is the first band
    std::vector<size_t> h_obs(heights.size()), h_unseen(heights.size()), d_obs(distances.size()),
        d_unseen(distances.size());
    size_t observable = 0, seen = 0;
    std::vector<Eigen::Vector3f> unseen_points;
    for (size_t i = 0; i < samples.points.size(); ++i) {
      if (!mask[i]) continue;
      const Eigen::Vector3f& p = samples.points[i];
      float nearest = std::numeric_limits<float>::max();
      for (const auto& q : driven) nearest = std::min(nearest, std::hypot(p.x() - q[0], p.y() - q[1]));
      const size_t hb = band_of(p.z(), heights), db = band_of(nearest, distances);
      ++observable;
      ++h_obs[hb];
      ++d_obs[db];
      if (map.near(p)) {
        ++seen;
        continue;
      }
      ++h_unseen[hb];
      ++d_unseen[db];
      unseen_points.push_back(p);
    }
    std::printf("%s: seed %.0f, %zu samples, %zu observable, %zu mapped: %.2f %% observable completeness (the run "
                "reported %.2f %%), %zu unseen\n",
                run.c_str(), seed, samples.points.size(), observable, seen, 100.0 * seen / std::max<size_t>(1, observable),
                100.0 * summary_number(summary, "final_observable_completeness"), unseen_points.size());
    print_bands("By height of the sample (z):", heights, h_unseen, h_obs);
    print_bands("By the nearest any robot drove (horizontal):", distances, d_unseen, d_obs);

    const std::filesystem::path out = dir / "unseen_observable.ply";
    std::ofstream ply(out);
    ply << "ply\nformat ascii 1.0\nelement vertex " << unseen_points.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    for (const auto& p : unseen_points) ply << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    if (!ply) throw std::runtime_error("cannot write " + out.string());
    std::printf("\nwrote %s\n", out.string().c_str());
  } catch (const std::exception& e) {
    std::cerr << "hexplore_unseen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
