#include "common/safety/decision_trace.h"

#include <cstdio>
#include <sstream>

namespace hexplore::safety {
namespace {

std::string xy(const Eigen::Vector3d& p) {
  char b[64];
  std::snprintf(b, sizeof(b), "[%.2f, %.2f]", p.x(), p.y());
  return std::string(b);
}

// Reasons and ids are plain text from this program, but a team file may name robots freely.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

constexpr size_t kWaypointsShown = 6;

}  // namespace

bool worth_tracing(const Decision& decision, const Decision& previous, const Eigen::Vector3d& position,
                   const std::vector<Fragment>& peers, const DecisionTraceOptions& options) {
  if (decision.kind != previous.kind || decision.reason != previous.reason ||
      decision.yielding_to != previous.yielding_to || decision.detoured != previous.detoured)
    return true;
  for (const Fragment& p : peers)
    if (p.distance_to(position) < options.near_m) return true;
  return false;
}

std::string decision_trace_json(double t_s, const Eigen::Vector3d& position, const Decision& decision,
                                const std::vector<Fragment>& peers, const DecisionTraceOptions& options) {
  std::ostringstream j;
  char t[32];
  std::snprintf(t, sizeof(t), "%.2f", t_s);
  j << "{\"t\": " << t << ", \"position\": " << xy(position) << ", \"kind\": \""
    << (decision.kind == DecisionKind::kFollow ? "follow" : "stop") << "\", \"reason\": " << quoted(decision.reason)
    << ", \"yielding_to\": " << quoted(decision.yielding_to) << ", \"detoured\": " << (decision.detoured ? "true" : "false")
    << ", \"path\": [";
  for (size_t i = 0; i < decision.waypoints.size() && i < kWaypointsShown; ++i)
    j << (i ? ", " : "") << xy(decision.waypoints[i]);
  j << "], \"peers\": [";
  bool first = true;
  for (const Fragment& p : peers) {
    const double d = p.distance_to(position);
    if (d >= 2.0 * options.near_m) continue;
    char numbers[96];
    std::snprintf(numbers, sizeof(numbers), "\"speed\": %.2f, \"distance\": %.2f, \"trail\": %zu", p.speed_mps, d,
                  p.trail_m.size());
    j << (first ? "" : ", ") << "{\"id\": " << quoted(p.robot_id) << ", \"position\": " << xy(p.position_m)
      << ", \"stationary\": " << (p.stationary ? "true" : "false") << ", " << numbers
      << ", \"yielding_to\": " << quoted(p.yielding_to) << "}";
    first = false;
  }
  j << "]}\n";
  return j.str();
}

}  // namespace hexplore::safety
