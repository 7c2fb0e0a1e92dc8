#include "common/radio/fragment_codec.h"
#include "common/radio/vec3_proto.h"

#include "common/radio/wire_units.h"
#include "hexplore/v1/safety.pb.h"

namespace hexplore::radio {
namespace {

constexpr uint8_t kStationary = 0x01;
constexpr uint8_t kYielding = 0x02;
// A fragment is at most eta_p long; far more waypoints than that can hold is not a fragment.
constexpr uint64_t kMaxWaypoints = 1024;

}  // namespace

const std::string& FragmentCodec::type() const { return v1::PathFragment::descriptor()->full_name(); }

void FragmentCodec::encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
                           std::string& out) const {
  const auto& f = static_cast<const v1::PathFragment&>(message);
  uint8_t flags = 0;
  if (f.stationary()) flags |= kStationary;
  if (!f.yielding_to().empty()) flags |= kYielding;
  transport::ByteWriter w(out);
  w.u8(flags);
  Eigen::Vector3d previous = vec(f.position_m());
  write_cm(w, previous, Eigen::Vector3d::Zero());
  w.varint(static_cast<uint64_t>(f.waypoints_m_size()));
  for (const auto& p : f.waypoints_m()) {
    // Steps between rounded points, so that rounding errors do not add up along the path.
    write_cm(w, vec(p), previous);
    previous = vec(p);
  }
  w.varint(static_cast<uint64_t>(std::max<int64_t>(0, to_cm(f.speed_mps()))));
  if (flags & kYielding) write_robot(w, roster, f.yielding_to());
}

bool FragmentCodec::decode(std::string_view data, const transport::Roster* roster,
                           google::protobuf::MessageLite& message) const {
  auto& f = static_cast<v1::PathFragment&>(message);
  transport::ByteReader r(data);
  const uint8_t flags = r.u8();
  if (flags & ~(kStationary | kYielding)) return false;
  Eigen::Vector3d previous = read_cm(r, Eigen::Vector3d::Zero());
  set(f.mutable_position_m(), previous);
  const uint64_t n = r.bounded(kMaxWaypoints);
  for (uint64_t i = 0; i < n && !r.failed(); ++i) {
    previous = read_cm(r, previous);
    set(f.add_waypoints_m(), previous);
  }
  f.set_speed_mps(from_cm(static_cast<int64_t>(r.bounded(100'000))));
  f.set_stationary((flags & kStationary) != 0);
  if (flags & kYielding) {
    std::string id;
    if (!read_robot(r, roster, id)) return false;
    f.set_yielding_to(id);
  }
  return r.done();
}

}  // namespace hexplore::radio
