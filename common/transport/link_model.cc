#include "common/transport/link_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace hexplore::transport {
namespace {

uint64_t mix(uint64_t x) {  // splitmix64 finaliser
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

uint64_t hash_text(std::string_view s) {
  uint64_t h = 1469598103934665603ull;
  for (char c : s) h = (h ^ static_cast<uint8_t>(c)) * 1099511628211ull;
  return h;
}

}  // namespace

void PositionBoard::update(uint32_t slot, int64_t time_ns, const Eigen::Vector3d& position) {
  std::lock_guard lock(mutex_);
  auto& ring = samples_[slot];
  if (ring.size() < kHistory) {
    ring.push_back({time_ns, position});
  } else {
    // Overwrite the oldest.
    auto oldest = std::min_element(ring.begin(), ring.end(),
                                   [](const Sample& a, const Sample& b) { return a.time_ns < b.time_ns; });
    *oldest = {time_ns, position};
  }
}

std::optional<Eigen::Vector3d> PositionBoard::before(uint32_t slot, int64_t time_ns) const {
  std::lock_guard lock(mutex_);
  auto it = samples_.find(slot);
  if (it == samples_.end()) return std::nullopt;
  const Sample* best = nullptr;
  for (const Sample& s : it->second)
    if (s.time_ns < time_ns && (best == nullptr || s.time_ns > best->time_ns)) best = &s;
  if (best == nullptr) return std::nullopt;
  return best->position;
}

RadioMedium::RadioMedium(core::RadioConfig config, std::shared_ptr<const Roster> roster, uint64_t seed, bool lockstep)
    : config_(config), roster_(std::move(roster)), seed_(seed), lockstep_(lockstep) {
  for (const auto& o : config_.outages) {
    const auto slot = roster_->slot(o.robot);
    if (!slot) throw std::invalid_argument("radio: outage of '" + o.robot + "', who is not on the roster");
    outages_.push_back({*slot, static_cast<int64_t>(std::llround(o.from_s * 1e9)),
                        static_cast<int64_t>(std::llround(o.to_s * 1e9))});
  }
}

bool RadioMedium::cut_off(uint32_t slot, int64_t now_ns) const {
  return std::any_of(outages_.begin(), outages_.end(),
                     [&](const Outage& o) { return o.slot == slot && now_ns >= o.from_ns && now_ns < o.to_ns; });
}

void RadioMedium::submit(Submission submission) {
  std::lock_guard lock(mutex_);
  if (lockstep_) {
    pending_.push_back(std::move(submission));
    return;
  }
  schedule(submission);
}

void RadioMedium::commit() {
  std::vector<Submission> batch;
  {
    std::lock_guard lock(mutex_);
    batch.swap(pending_);
  }
  // One step's submissions all carry the step's time; the rest of the key fixes the order.
  std::stable_sort(batch.begin(), batch.end(), [](const Submission& a, const Submission& b) {
    return std::tie(a.submit_ns, a.sender_slot, a.service, a.order) <
           std::tie(b.submit_ns, b.sender_slot, b.service, b.order);
  });
  std::lock_guard lock(mutex_);
  for (Submission& s : batch) schedule(s);
}

void RadioMedium::schedule(Submission& s) {
  const int64_t latency_ns = static_cast<int64_t>(std::llround(config_.latency_s * 1e9));
  if (config_.bandwidth_bytes_per_s <= 0.0) {
    s.schedule(s.submit_ns + latency_ns);
    return;
  }
  int64_t& free_at = free_at_ns_[s.sender_slot];
  const int64_t start = std::max(free_at, s.submit_ns);
  if (static_cast<double>(start - s.submit_ns) > config_.max_queue_age_s * 1e9) {
    s.expire();
    return;
  }
  const auto airtime_ns =
      static_cast<int64_t>(std::ceil(static_cast<double>(s.bytes) / config_.bandwidth_bytes_per_s * 1e9));
  free_at = start + airtime_ns;
  s.schedule(free_at + latency_ns);
}

RadioVerdict RadioMedium::receive(uint32_t sender_slot, uint32_t receiver_slot, std::string_view topic,
                                  uint64_t sequence, int64_t now_ns) const {
  if (config_.loss > 0.0) {
    const uint64_t h = mix(mix(mix(mix(seed_ ^ hash_text(topic)) ^ sender_slot) ^ (uint64_t{receiver_slot} << 32)) ^ sequence);
    const double u = static_cast<double>(h >> 11) * 0x1.0p-53;  // uniform in [0, 1)
    if (u < config_.loss) return RadioVerdict::kLost;
  }
  // A partition is a robot out of everyone's range for a while: counted the same way.
  if (outages_enabled_ && (cut_off(sender_slot, now_ns) || cut_off(receiver_slot, now_ns)))
    return RadioVerdict::kOutOfRange;
  if (range_enabled_) {
    const auto a = positions_.before(sender_slot, now_ns);
    const auto b = positions_.before(receiver_slot, now_ns);
    // Until both sims have reported, nobody can say the robots are apart.
    if (a && b && (*a - *b).norm() > config_.range_m) return RadioVerdict::kOutOfRange;
  }
  return RadioVerdict::kDelivered;
}

}  // namespace hexplore::transport
