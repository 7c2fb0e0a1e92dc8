#include "common/radio/map_codec.h"

#include <vector>

#include "common/core/seed_key.h"
#include "common/highlevel/supervoxel.h"
#include "common/highlevel/wire_precision.h"
#include "common/radio/key_steps.h"
#include "common/radio/map_dictionary.h"
#include "common/radio/wire_units.h"
#include "hexplore/v1/hlmap.pb.h"

namespace hexplore::radio {
namespace {

// A centre is sent as its offset from where its key predicts it; an offset of more than 2^40
// quanta (17 million km) is malformed.
constexpr int64_t kMaxCentreStep = int64_t{1} << 40;

using google::protobuf::RepeatedPtrField;
using transport::ByteReader;
using transport::ByteWriter;

constexpr uint8_t kRemoved = 0x01;
constexpr uint8_t kCovered = 0x02;
constexpr int kSurfaceShift = 2;  // two bits: hexplore.v1.SurfaceClass
// What the two message types share, as references into either of them.
struct MapFields {
  RepeatedPtrField<v1::Supervoxel>* supervoxels;
  RepeatedPtrField<v1::TopologyEdge>* edges;
};
struct ConstMapFields {
  const RepeatedPtrField<v1::Supervoxel>& supervoxels;
  const RepeatedPtrField<v1::TopologyEdge>& edges;
};

Eigen::Vector3d predicted_centre(uint64_t key, double eta_s_m) {
  return core::cell_center(highlevel::seed_cell_of(key), eta_s_m);
}

void encode_fields(const ConstMapFields& m, double eta_s_m, ByteWriter& w) {
  const auto& svs = m.supervoxels;
  w.varint(static_cast<uint64_t>(svs.size()));
  w.varint(static_cast<uint64_t>(m.edges.size()));
  core::GridCell previous;
  for (const auto& s : svs) write_key(w, s.key(), previous);
  for (const auto& s : svs) {
    uint8_t flags = static_cast<uint8_t>((static_cast<int>(s.surface()) & 0x3) << kSurfaceShift);
    if (s.removed()) flags |= kRemoved;
    if (s.covered()) flags |= kCovered;
    w.u8(flags);
  }
  for (const auto& s : svs) {
    if (s.removed()) continue;
    const Eigen::Vector3d p = predicted_centre(s.key(), eta_s_m);
    w.svarint(highlevel::centre_steps(s.center_x()) - highlevel::centre_steps(p.x()));
    w.svarint(highlevel::centre_steps(s.center_y()) - highlevel::centre_steps(p.y()));
    w.svarint(highlevel::centre_steps(s.center_z()) - highlevel::centre_steps(p.z()));
  }
  for (const auto& s : svs) {
    if (s.removed()) continue;
    const highlevel::PackedNormal n = highlevel::pack_normal({s.normal_x(), s.normal_y(), s.normal_z()});
    w.u8(static_cast<uint8_t>(n.u));
    w.u8(static_cast<uint8_t>(n.v));
  }
  for (const auto& s : svs)
    if (!s.removed()) w.varint(s.traversal_requirement());
  for (const auto& s : svs)
    if (!s.removed()) w.varint(s.voxel_count());
  for (const auto& s : svs)
    if (!s.removed() && !s.covered()) w.varint(s.covered_voxels());
  for (const auto& s : svs)
    if (!s.removed() && !s.covered()) w.u8(static_cast<uint8_t>(s.coverage_gap()));
  for (const auto& e : m.edges) w.u8(e.removed() ? 1 : 0);
  core::GridCell previous_a;
  for (const auto& e : m.edges) {
    write_key(w, e.a(), previous_a);
    core::GridCell from_a = highlevel::seed_cell_of(e.a());
    write_key(w, e.b(), from_a);
  }
}

bool decode_fields(ByteReader& r, double eta_s_m, MapFields m) {
  // Every supervoxel takes at least four bytes and every edge seven: counts that the rest of
  // the frame cannot hold are a malformed frame, not an allocation.
  const uint64_t n = r.bounded(r.remaining() / 4);
  const uint64_t n_edges = r.bounded(r.remaining() / 7);
  if (r.failed()) return false;
  m.supervoxels->Reserve(static_cast<int>(n));
  core::GridCell previous;
  for (uint64_t i = 0; i < n; ++i) {
    uint64_t key = 0;
    if (!read_key(r, key, previous)) return false;
    m.supervoxels->Add()->set_key(key);
  }
  for (auto& s : *m.supervoxels) {
    const uint8_t flags = r.u8();
    const int surface = (flags >> kSurfaceShift) & 0x3;
    if ((flags & ~(kRemoved | kCovered | (0x3 << kSurfaceShift))) != 0 || !v1::SurfaceClass_IsValid(surface))
      return false;
    s.set_surface(static_cast<v1::SurfaceClass>(surface));
    s.set_removed((flags & kRemoved) != 0);
    s.set_covered((flags & kCovered) != 0);
  }
  for (auto& s : *m.supervoxels) {
    if (s.removed()) continue;
    const Eigen::Vector3d p = predicted_centre(s.key(), eta_s_m);
    s.set_center_x(static_cast<float>(highlevel::centre_from_steps(highlevel::centre_steps(p.x()) + r.bounded_svarint(kMaxCentreStep))));
    s.set_center_y(static_cast<float>(highlevel::centre_from_steps(highlevel::centre_steps(p.y()) + r.bounded_svarint(kMaxCentreStep))));
    s.set_center_z(static_cast<float>(highlevel::centre_from_steps(highlevel::centre_steps(p.z()) + r.bounded_svarint(kMaxCentreStep))));
  }
  for (auto& s : *m.supervoxels) {
    if (s.removed()) continue;
    highlevel::PackedNormal packed;
    packed.u = static_cast<int8_t>(r.u8());
    packed.v = static_cast<int8_t>(r.u8());
    const Eigen::Vector3d normal = highlevel::unpack_normal(packed);
    s.set_normal_x(static_cast<float>(normal.x()));
    s.set_normal_y(static_cast<float>(normal.y()));
    s.set_normal_z(static_cast<float>(normal.z()));
  }
  for (auto& s : *m.supervoxels)
    if (!s.removed()) s.set_traversal_requirement(static_cast<uint32_t>(r.bounded(1u << 16)));
  for (auto& s : *m.supervoxels)
    if (!s.removed()) s.set_voxel_count(static_cast<uint32_t>(r.bounded(UINT32_MAX)));
  for (auto& s : *m.supervoxels)
    if (!s.removed() && !s.covered()) s.set_covered_voxels(static_cast<uint32_t>(r.bounded(UINT32_MAX)));
  for (auto& s : *m.supervoxels) {
    if (s.removed() || s.covered()) continue;
    const int gap = r.u8();
    if (!v1::CoverageGap_IsValid(gap)) return false;
    s.set_coverage_gap(static_cast<v1::CoverageGap>(gap));
  }
  if (r.failed()) return false;
  m.edges->Reserve(static_cast<int>(n_edges));
  for (uint64_t i = 0; i < n_edges; ++i) {
    const uint8_t removed = r.u8();
    if (removed > 1) return false;
    m.edges->Add()->set_removed(removed != 0);
  }
  core::GridCell previous_a;
  for (auto& e : *m.edges) {
    uint64_t a = 0, b = 0;
    if (!read_key(r, a, previous_a)) return false;
    core::GridCell from_a = previous_a;
    if (!read_key(r, b, from_a)) return false;
    e.set_a(a);
    e.set_b(b);
  }
  return r.done();
}

}  // namespace

const std::string& MapCodec::type() const {
  return snapshot_ ? v1::MapSnapshot::descriptor()->full_name() : v1::MapIncrement::descriptor()->full_name();
}

const transport::CompressionDictionary* MapCodec::dictionary() const { return &map_dictionary(); }

void MapCodec::encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
                      std::string& out) const {
  ByteWriter w(out);
  if (snapshot_) {
    const auto& m = static_cast<const v1::MapSnapshot&>(message);
    write_robot(w, roster, m.source_robot());
    w.varint(m.upto_seq());
    w.varint(m.incarnation());
    w.u32(m.contribution_digest());
    encode_fields({m.supervoxels(), m.edges()}, eta_s_m_, w);
  } else {
    const auto& m = static_cast<const v1::MapIncrement&>(message);
    write_robot(w, roster, m.source_robot());
    w.varint(m.increment_seq());
    w.varint(m.incarnation());
    w.u32(m.contribution_digest());
    encode_fields({m.supervoxels(), m.edges()}, eta_s_m_, w);
  }
}

bool MapCodec::decode(std::string_view data, const transport::Roster* roster,
                      google::protobuf::MessageLite& message) const {
  ByteReader r(data);
  std::string source;
  if (!read_robot(r, roster, source)) return false;
  const uint64_t seq = r.varint();
  const uint64_t incarnation = r.varint();
  const uint32_t digest = r.u32();
  if (snapshot_) {
    auto& m = static_cast<v1::MapSnapshot&>(message);
    m.set_source_robot(source);
    m.set_upto_seq(seq);
    m.set_incarnation(incarnation);
    m.set_contribution_digest(digest);
    return decode_fields(r, eta_s_m_, {m.mutable_supervoxels(), m.mutable_edges()});
  }
  auto& m = static_cast<v1::MapIncrement&>(message);
  m.set_source_robot(source);
  m.set_increment_seq(seq);
  m.set_incarnation(incarnation);
  m.set_contribution_digest(digest);
  return decode_fields(r, eta_s_m_, {m.mutable_supervoxels(), m.mutable_edges()});
}

}  // namespace hexplore::radio
