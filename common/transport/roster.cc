#include "common/transport/roster.h"

#include "common/core/endpoints.h"

namespace hexplore::transport {

Roster::Roster(const std::vector<Member>& robots) {
  members_.reserve(robots.size() + 1);
  members_.push_back({std::string(core::kStationId), ""});
  members_.insert(members_.end(), robots.begin(), robots.end());
}

std::shared_ptr<const Roster> Roster::from_team(const core::TeamConfig& team) {
  std::vector<Member> robots;
  for (const auto& r : team.robots) robots.push_back({r.id, r.species});
  return std::make_shared<const Roster>(robots);
}

std::optional<uint32_t> Roster::slot(std::string_view id) const {
  // Teams are small (a handful of robots): a scan beats a map here.
  for (size_t i = 0; i < members_.size(); ++i)
    if (members_[i].id == id) return static_cast<uint32_t>(i);
  return std::nullopt;
}

const Roster::Member* Roster::member(uint32_t slot) const {
  return slot < members_.size() ? &members_[slot] : nullptr;
}

}  // namespace hexplore::transport
