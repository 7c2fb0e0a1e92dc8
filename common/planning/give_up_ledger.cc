#include "common/planning/give_up_ledger.h"

#include <algorithm>
#include <cmath>

namespace hexplore::planning {

bool GiveUpLedger::observed(uint64_t key, const Eigen::Vector3d& spot, int voxels) {
  Record& r = records_[key];
  ++r.attempts;
  if (!near_a_spot(r, spot)) r.spots.push_back(spot);
  return decide(key, r, voxels);
}

bool GiveUpLedger::failed(uint64_t key, int voxels) {
  Record& r = records_[key];
  ++r.attempts;
  return decide(key, r, voxels);
}

bool GiveUpLedger::decide(uint64_t key, const Record& r, int voxels) {
  if (int(r.spots.size()) < rules_.views && r.attempts < rules_.attempts) return false;
  if (given_up(key, voxels)) return false;  // already
  set_given_up(key, voxels, true);
  records_.erase(key);  // if it comes back, it gets a fresh set of tries
  return true;
}

void GiveUpLedger::merge(uint64_t key, int voxels) {
  const auto it = given_up_.find(key);
  if (it == given_up_.end() || voxels > it->second.voxels) set_given_up(key, voxels, false);
}

void GiveUpLedger::set_given_up(uint64_t key, int voxels, bool mine) {
  given_up_[key] = GivenUp{voxels, ++revision_, mine};
  if (mine) own_revision_ = revision_;
}

std::vector<std::pair<uint64_t, int>> GiveUpLedger::given_up_since(uint64_t revision, bool mine_only) const {
  std::vector<std::pair<uint64_t, int>> out;
  for (const auto& [key, entry] : given_up_)
    if (entry.revision > revision && (entry.mine || !mine_only)) out.emplace_back(key, entry.voxels);
  std::sort(out.begin(), out.end());
  return out;
}

bool GiveUpLedger::given_up(uint64_t key, int current_voxels) const {
  const auto it = given_up_.find(key);
  if (it == given_up_.end()) return false;
  return current_voxels <= std::ceil(rules_.regrowth_ratio * std::max(1, it->second.voxels));
}

bool GiveUpLedger::tried_from(uint64_t key, const Eigen::Vector3d& spot) const {
  const auto it = records_.find(key);
  return it != records_.end() && near_a_spot(it->second, spot);
}

bool GiveUpLedger::near_a_spot(const Record& r, const Eigen::Vector3d& spot) const {
  const double d2 = rules_.distinct_m * rules_.distinct_m;
  return std::any_of(r.spots.begin(), r.spots.end(), [&](const Eigen::Vector3d& s) { return (s - spot).squaredNorm() < d2; });
}

int GiveUpLedger::attempts(uint64_t key) const {
  const auto it = records_.find(key);
  return it == records_.end() ? 0 : it->second.attempts;
}

std::unordered_map<uint64_t, int> GiveUpLedger::attempt_counts() const {
  std::unordered_map<uint64_t, int> out;
  for (const auto& [key, r] : records_) out[key] = r.attempts;
  return out;
}

}  // namespace hexplore::planning
