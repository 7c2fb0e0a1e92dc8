#include "common/radio/pose_schedule.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hexplore::radio {

void PoseScheduleOptions::validate() const {
  auto fail = [](const std::string& field, const std::string& problem) {
    throw std::invalid_argument("radio: PoseScheduleOptions." + field + " " + problem);
  };
  if (!(threshold_m > 0.0)) fail("threshold_m", "must be > 0");
  if (!(heading_deg > 0.0)) fail("heading_deg", "must be > 0");
  if (!(min_interval_s >= 0.0)) fail("min_interval_s", "must be >= 0");
  if (!(heartbeat_s > 0.0)) fail("heartbeat_s", "must be > 0");
  if (!(max_extrapolation_s >= 0.0)) fail("max_extrapolation_s", "must be >= 0");
}

Eigen::Vector3d extrapolate_pose(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double age_s,
                                 double max_s) {
  if (!(age_s > 0.0) || !velocity.allFinite()) return position;
  return position + velocity * std::min(age_s, max_s);
}

PoseSchedule::PoseSchedule(PoseScheduleOptions options) : options_(options) { options_.validate(); }

bool PoseSchedule::due(double now_s, const Eigen::Vector3d& position, double heading_rad, int state) const {
  if (!last_) return true;
  const double age = now_s - last_->time_s;
  if (state != last_->state || age >= options_.heartbeat_s || age < 0.0) return true;
  if (age < options_.min_interval_s) return false;
  const Eigen::Vector3d predicted =
      extrapolate_pose(last_->position, last_->velocity, age, options_.max_extrapolation_s);
  if ((predicted - position).norm() > options_.threshold_m) return true;
  const double turn = std::remainder(heading_rad - last_->heading_rad, 2.0 * M_PI);
  return std::abs(turn) > options_.heading_deg * M_PI / 180.0;
}

void PoseSchedule::sent(double now_s, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                        double heading_rad, int state) {
  last_ = Sent{now_s, position, velocity, heading_rad, state};
}

}  // namespace hexplore::radio
