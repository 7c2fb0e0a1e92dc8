#include "common/highlevel/map_proto.h"

#include <algorithm>
#include <cstdint>

#include "common/core/world_bounds.h"

namespace hexplore::highlevel {
namespace {

template <typename CentreOf>
void add_edges(const MapUpdate& u, const CentreOf& centre_of,
               google::protobuf::RepeatedPtrField<v1::TopologyEdge>* out) {
  auto length = [&](const EdgeKey& e) -> float {
    const Eigen::Vector3d* a = centre_of(e.a);
    const Eigen::Vector3d* b = centre_of(e.b);
    return (a != nullptr && b != nullptr) ? static_cast<float>((*a - *b).norm()) : 0.0f;
  };
  for (const EdgeKey& e : u.edge_upserts) {
    v1::TopologyEdge* m = out->Add();
    m->set_a(e.a);
    m->set_b(e.b);
    m->set_length_m(length(e));
  }
  for (const EdgeKey& e : u.edge_removals) {
    v1::TopologyEdge* m = out->Add();
    m->set_a(e.a);
    m->set_b(e.b);
    m->set_removed(true);
  }
}

template <typename Message>
void fill_update(const Message& m, MapUpdate* u) {
  for (const v1::Supervoxel& s : m.supervoxels()) {
    if (s.removed()) {
      u->removals.push_back(s.key());
      continue;
    }
    Supervoxel sv = from_proto(s);
    if (core::within_world(sv.center) && core::plausible_normal(sv.normal)) {
      u->upserts.push_back(std::move(sv));
    } else {
      ++u->malformed;
    }
  }
  for (const v1::TopologyEdge& e : m.edges()) {
    (e.removed() ? u->edge_removals : u->edge_upserts).push_back(EdgeKey::of(e.a(), e.b()));
  }
}

template <typename Message>
void fill_message(const MapUpdate& u, const Contribution& current, Message* m) {
  for (const Supervoxel& sv : u.upserts) to_proto(sv, m->add_supervoxels());
  for (uint64_t key : u.removals) {
    v1::Supervoxel* s = m->add_supervoxels();
    s->set_key(key);
    s->set_removed(true);
  }
  add_edges(
      u,
      [&](uint64_t key) -> const Eigen::Vector3d* {
        auto it = current.supervoxels.find(key);
        return it == current.supervoxels.end() ? nullptr : &it->second.center;
      },
      m->mutable_edges());
}

}  // namespace

VoxelSample from_proto(const v1::Voxel& v) {
  VoxelSample s;
  s.key = {v.ix(), v.iy(), v.iz()};
  s.mean = Eigen::Vector3f(v.mean_x(), v.mean_y(), v.mean_z());
  s.normal = Eigen::Vector3f(v.normal_x(), v.normal_y(), v.normal_z());
  s.flags = v.flags();
  s.low_risk_species_mask = v.low_risk_species_mask();
  s.gap = core::coverage_gap_from_wire(uint32_t(v.coverage_gap()));
  return s;
}

std::vector<VoxelSample> voxel_samples(const v1::VoxelDelta& delta, size_t* malformed) {
  std::vector<VoxelSample> out;
  out.reserve(delta.voxels_size());
  size_t dropped = 0;
  for (const v1::Voxel& v : delta.voxels()) {
    VoxelSample s = from_proto(v);
    if (core::within_world(s.mean) && core::plausible_normal(s.normal)) {
      out.push_back(s);
    } else {
      ++dropped;
    }
  }
  if (malformed != nullptr) *malformed = dropped;
  return out;
}

Supervoxel from_proto(const v1::Supervoxel& s) {
  Supervoxel sv;
  sv.key = s.key();
  sv.center = Eigen::Vector3d(s.center_x(), s.center_y(), s.center_z());
  sv.normal = Eigen::Vector3d(s.normal_x(), s.normal_y(), s.normal_z());
  sv.covered = s.covered();
  // Beyond every species' level is as strict as a requirement gets; the cap keeps it an int.
  sv.traversal_requirement = static_cast<int>(std::min<uint32_t>(s.traversal_requirement(), 1u << 16));
  // An unknown class (proto3 enums take any number) is read from the key, like an unset one.
  const bool known_surface = s.surface() == v1::SURFACE_CLASS_GROUND || s.surface() == v1::SURFACE_CLASS_FACADE;
  sv.surface = known_surface ? static_cast<SurfaceClass>(s.surface()) : surface_of_key(sv.key);
  sv.voxel_count = static_cast<int>(std::min<uint32_t>(s.voxel_count(), INT32_MAX));
  sv.covered_voxels = sv.covered ? sv.voxel_count : static_cast<int>(std::min<uint32_t>(s.covered_voxels(), uint32_t(sv.voxel_count)));
  sv.gap = sv.covered ? core::CoverageGap::kNone : core::coverage_gap_from_wire(uint32_t(s.coverage_gap()));
  return sv;
}

// Floats on the wire: attributes are rounded once here, at the source, so every receiver
// fuses the same values.
void to_proto(const Supervoxel& s, v1::Supervoxel* out) {
  out->set_key(s.key);
  out->set_center_x(static_cast<float>(s.center.x()));
  out->set_center_y(static_cast<float>(s.center.y()));
  out->set_center_z(static_cast<float>(s.center.z()));
  out->set_normal_x(static_cast<float>(s.normal.x()));
  out->set_normal_y(static_cast<float>(s.normal.y()));
  out->set_normal_z(static_cast<float>(s.normal.z()));
  out->set_covered(s.covered);
  out->set_traversal_requirement(static_cast<uint32_t>(std::max(0, s.traversal_requirement)));
  out->set_surface(static_cast<v1::SurfaceClass>(s.surface));
  out->set_voxel_count(static_cast<uint32_t>(std::max(0, s.voxel_count)));
  if (!s.covered) {
    out->set_covered_voxels(static_cast<uint32_t>(std::max(0, s.covered_voxels)));
    out->set_coverage_gap(static_cast<v1::CoverageGap>(s.gap));
  }
}

v1::MapIncrement to_increment(const SourcedUpdate& inc, const Contribution& current) {
  v1::MapIncrement m;
  m.set_source_robot(inc.source);
  m.set_increment_seq(inc.seq);
  m.set_incarnation(inc.incarnation);
  m.set_contribution_digest(inc.digest);
  fill_message(inc.update, current, &m);
  return m;
}

v1::MapSnapshot to_snapshot(const SourcedUpdate& snap, const Contribution& current) {
  v1::MapSnapshot m;
  m.set_source_robot(snap.source);
  m.set_upto_seq(snap.seq);
  m.set_incarnation(snap.incarnation);
  m.set_contribution_digest(snap.digest);
  fill_message(snap.update, current, &m);
  return m;
}

SourcedUpdate from_proto(const v1::MapIncrement& inc) {
  SourcedUpdate u;
  u.source = inc.source_robot();
  u.seq = inc.increment_seq();
  u.incarnation = inc.incarnation();
  u.digest = inc.contribution_digest();
  fill_update(inc, &u.update);
  return u;
}

SourcedUpdate from_proto(const v1::MapSnapshot& snap) {
  SourcedUpdate u;
  u.source = snap.source_robot();
  u.seq = snap.upto_seq();
  u.incarnation = snap.incarnation();
  u.digest = snap.contribution_digest();
  u.update.full_snapshot = true;
  fill_update(snap, &u.update);
  return u;
}

v1::FusedMapUpdate to_fused_update(const MapUpdate& update, const HighLevelMap& map) {
  v1::FusedMapUpdate m;
  m.set_full_snapshot(update.full_snapshot);
  m.set_version(update.version);
  for (const Supervoxel& sv : update.upserts) to_proto(sv, m.add_supervoxels());
  for (uint64_t key : update.removals) {
    v1::Supervoxel* s = m.add_supervoxels();
    s->set_key(key);
    s->set_removed(true);
  }
  add_edges(
      update,
      [&](uint64_t key) -> const Eigen::Vector3d* {
        const Supervoxel* sv = map.find(key);
        return sv == nullptr ? nullptr : &sv->center;
      },
      m.mutable_edges());
  return m;
}

MapUpdate from_proto(const v1::FusedMapUpdate& update) {
  MapUpdate u;
  u.full_snapshot = update.full_snapshot();
  u.version = update.version();
  fill_update(update, &u);
  return u;
}

}  // namespace hexplore::highlevel
