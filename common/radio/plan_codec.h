#pragma once
// team/plan on the radio: a robot's team solution (paper: the reference solution) with its
// cluster sequences and the team's given-up targets. Cluster ids and given-up keys are
// supervoxel keys as seed-cell steps (key_steps.h); cluster centres are decimetre steps from
// their cluster id's seed cell (within 5 cm); route lengths centimetres; robots roster slots;
// the planner as its code below (which planner a robot runs is told by its solutions). Not
// carried, so they decode as zero: fitness (no teammate reads it; wire schema 6) and
// planning_time_s (a measured compute time, which would make the traffic of reproducible runs
// differ; the station has it from the planners' statuses).

#include <cstdint>
#include <optional>
#include <string_view>

#include "common/transport/payload_codec.h"

namespace hexplore::radio {

// A built-in planner's one-byte code on the radio (planning::PlannerRegistry::builtin(); wire
// schema 6: new planners are appended, codes never change); any other name travels as a string.
std::optional<uint8_t> planner_code(std::string_view name);

class PlanCodec : public transport::PayloadCodec {
 public:
  // `eta_s_m`: the team's seed interval, which places a key's seed cell (encoding size only).
  explicit PlanCodec(double eta_s_m) : eta_s_m_(eta_s_m) {}
  const std::string& type() const override;
  void encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
              std::string& out) const override;
  bool decode(std::string_view data, const transport::Roster* roster,
              google::protobuf::MessageLite& message) const override;

 private:
  double eta_s_m_;
};

}  // namespace hexplore::radio
