#pragma once
// The communication part of a mission's results: per robot and category what it put on the
// team radio (messages, KB, KB/s; table 4-4), what the three map-transmission strategies cost
// (table 4-5: the increments actually sent against what the whole high-level map and the whole
// perception map every eta_c would have cost), and what the radio model and the map re-sync
// counted. Volumes follow the paper: summed over robots, divided by their number, then by the
// exploration time for the rate.

#include <string>
#include <vector>

#include "common/evaluation/experiment_record.h"

namespace hexplore::evaluation {

struct StrategyVolume {
  std::string strategy;  // incremental_high_level, full_high_level, full_perception
  double cumulative_kb = 0.0;
  double kb_per_s = 0.0;
};

// Table 4-5 of one mission, in that order.
std::vector<StrategyVolume> map_strategies(const ExperimentRecord& record);

// summary.json's "map_transmission" object: the three strategies and the incremental map's
// saving against the two others (fractions).
std::string map_transmission_json(const ExperimentRecord& record);
// Per robot: messages per category, map re-sync counters, radio drops, as JSON members
// ("communication_messages": {...}, "map_sync": {...}, "radio_drops": {...}).
std::string robot_communication_json(const ExperimentRecord& record, const std::string& robot);

// communication.csv: robot,category,messages,cumulative_kb,average_kb_per_s.
std::string communication_csv(const ExperimentRecord& record);
// map_transmission.csv: strategy,cumulative_kb,average_kb_per_s (per robot, as the paper).
std::string map_transmission_csv(const ExperimentRecord& record);

}  // namespace hexplore::evaluation
