#pragma once
// The experiment's progress on a terminal: one line, redrawn in place about once a second,
// with the run (i of n), the mission's sim time against its limit, the team's completeness,
// how fast sim time goes, the wall time so far and the most it can still take (a mission ends
// when no task view remains, which nobody can foresee, so the time limit bounds the rest).
// Off a terminal (CI logs, a child's log file) it draws nothing: the station's periodic lines
// (--progress-period-s) say what happens there.

#include <chrono>
#include <cstdio>
#include <string>

#include "services/station/station_progress.h"

namespace hexplore::experiment {

class ProgressLine {
 public:
  // `label`: "run 1/5 seed 3"; `time_limit_s`: the mission's safety net.
  ProgressLine(FILE* out, std::string label, double time_limit_s);
  ~ProgressLine();  // ends the line, so what follows starts on a fresh one

  // Redraws when a second has passed since the last drawing.
  void update(const station_service::StationProgress& progress);

  // The text of one drawing (without the carriage return): a function of its inputs, for tests.
  static std::string text(const std::string& label, const station_service::StationProgress& progress,
                          double time_limit_s, double wall_s);

 private:
  FILE* out_;
  std::string label_;
  double time_limit_s_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_draw_{};
  bool drawn_ = false;
};

// Whether `out` is a terminal (the progress line is drawn only there).
bool is_terminal(FILE* out);

}  // namespace hexplore::experiment
