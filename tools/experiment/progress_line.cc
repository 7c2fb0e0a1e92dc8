#include "tools/experiment/progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace hexplore::experiment {
namespace {

// "1:05:09", "4:10": hours only when there are any.
std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

}  // namespace

bool is_terminal(FILE* out) { return isatty(fileno(out)) == 1; }

ProgressLine::ProgressLine(FILE* out, std::string label, double time_limit_s)
    : out_(out), label_(std::move(label)), time_limit_s_(time_limit_s) {}

ProgressLine::~ProgressLine() {
  if (drawn_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

std::string ProgressLine::text(const std::string& label, const station_service::StationProgress& progress,
                               double time_limit_s, double wall_s) {
  char buf[256];
  if (!progress.started) {
    std::snprintf(buf, sizeof buf, "[experiment] %s: starting (%s wall)", label.c_str(), clock_text(wall_s).c_str());
    return buf;
  }
  const double t = progress.mission_time_s;
  const double rate = wall_s > 0.0 ? t / wall_s : 0.0;  // sim seconds per wall second
  std::string rest = "-";
  if (rate > 0.0) rest = clock_text((time_limit_s - t) / rate);  // clock_text clamps past the limit to 0
  std::snprintf(buf, sizeof buf,
                "[experiment] %s: t=%.0f of %.0f s, completeness %.1f%%, %d live, %.2fx real time, %s wall, "
                "at most %s left",
                label.c_str(), t, time_limit_s, 100.0 * progress.team_completeness, progress.live_robots, rate,
                clock_text(wall_s).c_str(), rest.c_str());
  return buf;
}

void ProgressLine::update(const station_service::StationProgress& progress) {
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_draw_ < std::chrono::seconds(1)) return;
  last_draw_ = now;
  drawn_ = true;
  const double wall_s = std::chrono::duration<double>(now - start_).count();
  // Carriage return and erase-to-end-of-line: the line is redrawn in place.
  std::fprintf(out_, "\r%s\033[K", text(label_, progress, time_limit_s_, wall_s).c_str());
  std::fflush(out_);
}

}  // namespace hexplore::experiment
