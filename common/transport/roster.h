#pragma once
// Who a compact header may name by number instead of by string: slot 0 is the station, slots
// 1..N are the team's robots in team-file order. Every process of a team builds the same roster
// from the same team file, so a one-byte slot identifies the sender on every robot.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/core/team_config.h"

namespace hexplore::transport {

class Roster {
 public:
  struct Member {
    std::string id;
    std::string species;  // "" for the station
  };

  // `robots` in team order; the station is added as slot 0.
  explicit Roster(const std::vector<Member>& robots);
  static std::shared_ptr<const Roster> from_team(const core::TeamConfig& team);

  // nullopt for an id that is not on the roster.
  std::optional<uint32_t> slot(std::string_view id) const;
  // nullptr for a slot beyond the roster.
  const Member* member(uint32_t slot) const;
  size_t size() const { return members_.size(); }
  // Robot slots are 1..size()-1.
  size_t robot_count() const { return members_.size() - 1; }

 private:
  std::vector<Member> members_;
};

}  // namespace hexplore::transport
