#include "common/radio/plan_codec.h"

#include <iterator>

#include "common/highlevel/supervoxel.h"
#include "common/radio/key_steps.h"
#include "common/radio/vec3_proto.h"
#include "common/radio/wire_units.h"
#include "hexplore/v1/plan.pb.h"

namespace hexplore::radio {
namespace {

using transport::ByteReader;
using transport::ByteWriter;

// Code k is kPlanners[k - 1]; code 0: the name follows as a string.
constexpr std::string_view kPlanners[] = {"hexplore", "no-hetero", "no-cluster", "no-mnss",
                                          "no-assign", "mdvrp+",    "mromt+",     "tspga+"};
constexpr uint64_t kPlannerCount = std::size(kPlanners);

void write_planner(ByteWriter& w, const std::string& name) {
  if (const auto code = planner_code(name)) {
    w.varint(*code);
    return;
  }
  w.varint(0);
  w.bytes(name);
}

bool read_planner(ByteReader& r, std::string& name) {
  const uint64_t code = r.varint();
  if (r.failed() || code > kPlannerCount) return r.fail(), false;
  if (code == 0) {
    name.assign(r.bytes(128));
  } else {
    name.assign(kPlanners[code - 1]);
  }
  return !r.failed();
}

}  // namespace

std::optional<uint8_t> planner_code(std::string_view name) {
  for (uint64_t i = 0; i < kPlannerCount; ++i)
    if (kPlanners[i] == name) return static_cast<uint8_t>(i + 1);
  return std::nullopt;
}

const std::string& PlanCodec::type() const { return v1::TeamSolution::descriptor()->full_name(); }

void PlanCodec::encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
                       std::string& out) const {
  const auto& s = static_cast<const v1::TeamSolution&>(message);
  ByteWriter w(out);
  w.varint(s.round());
  write_planner(w, s.planner());
  w.varint(static_cast<uint64_t>(s.sequences_size()));
  for (const auto& seq : s.sequences()) {
    write_robot(w, roster, seq.robot_id());
    w.varint(static_cast<uint64_t>(seq.cluster_ids_size()));
    w.varint(static_cast<uint64_t>(seq.cluster_centers_m_size()));
    core::GridCell previous;
    for (uint64_t id : seq.cluster_ids()) write_key(w, id, previous);
    // Each centre in decimetres from its cluster id's seed cell (a centre without an id: from
    // the origin): within 6.3 m of it, a byte per axis.
    for (int i = 0; i < seq.cluster_centers_m_size(); ++i) {
      const Eigen::Vector3d origin = i < seq.cluster_ids_size()
                                         ? core::cell_center(highlevel::seed_cell_of(seq.cluster_ids(i)), eta_s_m_)
                                         : Eigen::Vector3d::Zero();
      write_fixed(w, vec(seq.cluster_centers_m(i)), origin, kDmPerM);
    }
    w.varint(static_cast<uint64_t>(std::max<int64_t>(0, to_cm(seq.route_length_m()))));
  }
  w.varint(static_cast<uint64_t>(s.given_up_supervoxels_size()));
  w.varint(static_cast<uint64_t>(s.given_up_voxel_counts_size()));
  core::GridCell previous;
  for (uint64_t key : s.given_up_supervoxels()) write_key(w, key, previous);
  for (uint32_t count : s.given_up_voxel_counts()) w.varint(count);
}

bool PlanCodec::decode(std::string_view data, const transport::Roster* roster,
                       google::protobuf::MessageLite& message) const {
  auto& s = static_cast<v1::TeamSolution&>(message);
  ByteReader r(data);
  s.set_round(r.varint());
  if (!read_planner(r, *s.mutable_planner())) return false;
  // Every element takes at least one byte: counts beyond what is left are malformed.
  const uint64_t n = r.bounded(r.remaining());
  for (uint64_t i = 0; i < n && !r.failed(); ++i) {
    auto* seq = s.add_sequences();
    std::string robot;
    if (!read_robot(r, roster, robot)) return false;
    seq->set_robot_id(robot);
    const uint64_t ids = r.bounded(r.remaining());
    const uint64_t centres = r.bounded(r.remaining());
    core::GridCell previous;
    for (uint64_t k = 0; k < ids; ++k) {
      uint64_t key = 0;
      if (!read_key(r, key, previous)) return false;
      seq->add_cluster_ids(key);
    }
    for (uint64_t k = 0; k < centres && !r.failed(); ++k) {
      const Eigen::Vector3d origin =
          k < ids ? core::cell_center(highlevel::seed_cell_of(seq->cluster_ids(static_cast<int>(k))), eta_s_m_)
                  : Eigen::Vector3d::Zero();
      set(seq->add_cluster_centers_m(), read_fixed(r, origin, kDmPerM));
    }
    seq->set_route_length_m(from_cm(static_cast<int64_t>(r.bounded(uint64_t{1} << 40))));
  }
  const uint64_t keys = r.bounded(r.remaining());
  const uint64_t counts = r.bounded(r.remaining());
  core::GridCell previous;
  for (uint64_t k = 0; k < keys; ++k) {
    uint64_t key = 0;
    if (!read_key(r, key, previous)) return false;
    s.add_given_up_supervoxels(key);
  }
  for (uint64_t k = 0; k < counts && !r.failed(); ++k)
    s.add_given_up_voxel_counts(static_cast<uint32_t>(r.bounded(UINT32_MAX)));
  return r.done();
}

}  // namespace hexplore::radio
