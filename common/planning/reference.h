#pragma once
// Reference routes (paper eq. minMax): every robot shares its previous solution; each robot
// picks, by the same rule, the one whose longest route is shortest, and the GA's fitness then
// pulls new routes towards it so that the robots' independent solutions agree.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hexplore::planning {

// One robot's route in a shared solution.
struct ReferenceRoute {
  std::string robot_id;
  std::vector<uint64_t> cluster_ids;
  std::vector<Eigen::Vector3d> centers;  // p(tau) of each cluster, in order
  double length_m = 0.0;                 // length() of the sequence
};

// One robot's previous solution for the whole team.
struct ReferenceSolution {
  std::string source_robot;
  uint64_t round = 0;
  std::vector<ReferenceRoute> routes;

  double max_length() const;
  const ReferenceRoute* route_of(const std::string& robot_id) const;
};

// argmin over solutions of the longest route length; ties go to the newer round, then to
// the smaller source id, so the choice does not depend on the order solutions arrived in.
// nullopt when there is no solution.
std::optional<size_t> select_reference(const std::vector<ReferenceSolution>& solutions);

// Whether a robot's new solution `mine` need travel to teammates that use nothing but
// select_reference's choice. They hold `teammates` (each robot's last solution sent) and
// `held`, the last one this robot sent (none yet: nullopt). Should neither `mine` nor `held`
// be chosen among them, every teammate chooses among `teammates` with or without `mine`:
// it changes nothing there. Else it must go, to be chosen or to replace `held`.
bool reference_worth_sending(const std::vector<ReferenceSolution>& teammates, const ReferenceSolution& mine,
                             const std::optional<ReferenceSolution>& held);

}  // namespace hexplore::planning
