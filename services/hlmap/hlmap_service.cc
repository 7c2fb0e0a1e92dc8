#include "services/hlmap/hlmap_service.h"

#include <chrono>
#include <stdexcept>

#include "common/core/clock.h"
#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/highlevel/map_proto.h"
#include "common/service/status_values.h"
#include "common/transport/payload_wire.h"
#include "common/transport/topics.h"

namespace hexplore::hlmap_service {
namespace {

namespace topics = transport::topics;

class Stopwatch {
 public:
  double seconds() const { return core::ns_to_s(core::monotonic_ns() - start_); }

 private:
  int64_t start_ = core::monotonic_ns();
};

}  // namespace

double HlmapService::now_s() const { return core::ns_to_s(context_->now_ns()); }

void HlmapService::setup(service::ServiceContext& context) {
  context_ = &context;
  robot_id_ = context.robot_id();
  const auto& team = context.team();
  if (context.robot() == nullptr) {
    throw core::ConfigError(team.source_file, "robots", "hlmap: '" + robot_id_ + "' is not a robot of the team");
  }
  levels_ = highlevel::species_levels(team);
  if (levels_.empty()) throw core::ConfigError(team.source_file, "species", "hlmap: the team has no species");
  params_ = highlevel::SegmenterParams::from(team.params);
  try {
    params_.validate();
  } catch (const std::invalid_argument& e) {
    throw core::ConfigError(team.source_file, "params", std::string("hlmap: ") + e.what());
  }
  segmenter_ = std::make_unique<highlevel::SupervoxelSegmenter>(params_, levels_);
  // The start time marks this run's increments: peers tell them from a previous run's (a
  // restart numbers from 1 again) even when they miss increment 1. Lockstep runs restart
  // nothing and may not depend on wall time (compressed increments would change size).
  const auto started_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::system_clock::now().time_since_epoch());
  const uint64_t incarnation = context.lockstep() ? 1 : static_cast<uint64_t>(started_ms.count());
  highlevel::PublishTolerance tolerance;
  tolerance.center_m = team.params.map_resolution_m;
  log_ = std::make_unique<highlevel::ContributionLog>(robot_id_, incarnation, tolerance);
  fusion_ = std::make_unique<highlevel::MapFusion>(levels_);
  repair_timeout_s_ = std::max(0.5, 2.0 * team.params.eta_c_s);
  sync_ = std::make_unique<highlevel::PeerSync>(robot_id_, repair_timeout_s_);

  auto& m = context.metrics();
  const metrics::Labels labels{{"robot", robot_id_}};
  const auto buckets = metrics::latency_buckets_s();
  metrics_.segmentation_s =
      m.histogram_family("hexplore_hlmap_segmentation_seconds", "Supervoxel segmentation time per voxel delta", buckets)
          ->add(labels);
  metrics_.topology_s = m.histogram_family("hexplore_hlmap_topology_update_seconds",
                                           "Own contribution fused into the map and topology graph per window", buckets)
                            ->add(labels);
  metrics_.fusion_s =
      m.histogram_family("hexplore_hlmap_fusion_seconds", "Fusion of one peer increment or snapshot", buckets)
          ->add(labels);
  auto gauge = [&](const std::string& name, const std::string& help, const metrics::Labels& l) {
    return m.gauge_family(name, help)->add(l);
  };
  metrics_.supervoxels = gauge("hexplore_hlmap_supervoxels", "Supervoxels in the fused map", labels);
  metrics_.own_supervoxels = gauge("hexplore_hlmap_own_supervoxels", "Supervoxels this robot segmented", labels);
  metrics_.edges = gauge("hexplore_hlmap_edges", "Topology edges in the fused map", labels);
  metrics_.graph_vertices = gauge("hexplore_hlmap_graph_vertices", "Traversable vertices of the topology graph", labels);
  metrics_.voxels = gauge("hexplore_hlmap_voxels", "Perception voxels held by the segmenter", labels);
  auto window_bytes = [&](std::string_view topic) {
    return gauge("hexplore_hlmap_window_bytes", "Bytes sent in the last eta_c window, by topic",
                 {{"robot", robot_id_}, {"topic", std::string(topic)}});
  };
  metrics_.window_bytes_team_map = window_bytes(topics::kTeamMap);
  metrics_.window_bytes_hlmap = window_bytes(topics::kHlmap);
  metrics_.window_bytes_snapshots = window_bytes("repair");
  auto facades = [&](std::string_view held_by) {
    return gauge("hexplore_hlmap_incomplete_facades",
                 "Incomplete facade supervoxels of the fused map, by whose maps hold them (own: only this robot's; "
                 "teammates_own_cell: teammates' only, while this robot's map holds the same cell under another key)",
                 {{"robot", robot_id_}, {"held_by", std::string(held_by)}});
  };
  metrics_.facades_own_only = facades("own");
  metrics_.facades_shared = facades("shared");
  metrics_.facades_teammates_only = facades("teammates");
  metrics_.facades_teammates_own_cell = facades("teammates_own_cell");
  auto counter = [&](const std::string& name, const std::string& help) { return m.counter_family(name, help)->add(labels); };
  metrics_.gaps_detected = counter("hexplore_hlmap_gaps_detected_total", "Gaps in peers' increment sequences");
  metrics_.gaps_repaired = counter("hexplore_hlmap_gaps_repaired_total", "Gaps closed by a repair snapshot");
  metrics_.repair_requests = counter("hexplore_hlmap_repair_requests_total", "MapRepairRequests sent to peers");
  metrics_.peer_restarts = counter("hexplore_hlmap_peer_restarts_total", "Peers' hlmaps seen restarted (contribution replaced)");
  metrics_.stale_updates = counter("hexplore_hlmap_stale_updates_total", "Peers' updates from before their hlmap restarted, dropped");
  metrics_.digest_mismatches = counter("hexplore_hlmap_digest_mismatches_total",
                                       "Peers' contributions that differed here from the digest they sent (a snapshot is fetched)");
  metrics_.snapshots_served = counter("hexplore_hlmap_snapshots_served_total", "MapSnapshots served to peers");
  metrics_.bad_deltas = counter("hexplore_hlmap_bad_voxel_deltas_total", "Voxel deltas dropped (wrong resolution)");
  metrics_.malformed_voxels = counter("hexplore_hlmap_malformed_voxels_total",
                                      "Voxels dropped from deltas: mean off the world or not finite, normal not a unit vector");
  metrics_.malformed_supervoxels = counter("hexplore_hlmap_malformed_supervoxels_total",
                                           "Teammates' supervoxels dropped: centre off the world or not finite, bad normal");
  metrics_.full_map_bytes = counter("hexplore_hlmap_full_map_equivalent_bytes_total",
                                    "Bytes that broadcasting the whole contribution every eta_c would have cost");

  // Own mapping's voxels; every peer's hlmap for team/map.
  context.connect(robot_id_, core::ServiceKind::kMapping);
  for (const auto& robot : team.robots) {
    if (robot.id == robot_id_) continue;
    peers_.push_back(robot.id);
    context.connect(robot.id, core::ServiceKind::kHlmap);
    sync_->want_snapshot(robot.id);  // a (re)started hlmap fetches what it missed
  }
  auto& sub = context.subscriber();
  sub.on<v1::VoxelDelta>(topics::voxels(robot_id_),
                         [this](const transport::Received<v1::VoxelDelta>& r) { on_voxels(r.message); });
  sub.on<v1::MapIncrement>(std::string(topics::kTeamMap), [this](const transport::Received<v1::MapIncrement>& r) {
    if (r.header.robot_id() == robot_id_ || r.message.source_robot() == robot_id_) return;
    on_increment(r.message);
  });
  context.responder().serve<v1::MapRepairRequest, v1::MapSnapshot>(
      [this](const transport::Received<v1::MapRepairRequest>& r) { return serve_repair(r.message); });
  context.responder().serve<v1::FusedMapRequest, v1::FusedMapUpdate>(
      [this](const transport::Received<v1::FusedMapRequest>& r) { return serve_fused(r.message); });

  const auto period = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::duration<double>(team.params.eta_c_s));
  context.loop().add_timer(period, [this] { window(); });
  context.set_state(v1::SERVICE_STATE_RUNNING, "waiting for voxels");
}

void HlmapService::on_voxels(const v1::VoxelDelta& delta) {
  if (std::abs(delta.resolution_m() - params_.resolution_m) > 1e-9 * params_.resolution_m &&
      segmenter_->voxel_count() == 0 && delta.resolution_m() > 0.0 &&
      delta.resolution_m() * 2.0 <= params_.eta_s_m) {
    // Mapping runs at another resolution than the team default: adopt it before any voxel.
    core::LogLine(core::LogLevel::kInfo, "hlmap")
        << robot_id_ << ": perception resolution " << delta.resolution_m() << " m (team default " << params_.resolution_m
        << " m)";
    params_.resolution_m = delta.resolution_m();
    segmenter_ = std::make_unique<highlevel::SupervoxelSegmenter>(params_, levels_);
  }
  if (std::abs(delta.resolution_m() - params_.resolution_m) > 1e-9 * params_.resolution_m) {
    metrics_.bad_deltas->increment();
    core::LogLine(core::LogLevel::kWarn, "hlmap")
        << robot_id_ << ": voxel delta at resolution " << delta.resolution_m() << " m dropped (map resolution "
        << params_.resolution_m << " m)";
    return;
  }
  size_t malformed = 0;
  const auto samples = highlevel::voxel_samples(delta, &malformed);
  if (malformed > 0) {
    metrics_.malformed_voxels->increment(static_cast<double>(malformed));
    core::log_once(core::LogLevel::kWarn, "hlmap", "malformed-voxels",
                   robot_id_ + ": dropping malformed voxels from mapping (counted in hexplore_hlmap_malformed_voxels_total)");
  }
  const Stopwatch watch;
  const auto change = delta.full_snapshot() ? segmenter_->replace_all(samples) : segmenter_->update(samples);
  metrics_.segmentation_s->observe(watch.seconds());
  log_->record(*segmenter_, change);
  metrics_.voxels->set(static_cast<double>(segmenter_->voxel_count()));
  metrics_.own_supervoxels->set(static_cast<double>(segmenter_->supervoxels().size()));
}

void HlmapService::apply_ready(std::vector<highlevel::SourcedUpdate> ready) {
  std::map<std::string, const highlevel::SourcedUpdate*> last_with_digest;  // per source
  for (const auto& u : ready) {
    const Stopwatch watch;
    fusion_->apply(u.source, u.update);
    metrics_.fusion_s->observe(watch.seconds());
    if (u.digest != 0) last_with_digest[u.source] = &u;
  }
  for (const auto& [source, update] : last_with_digest) verify_digest(*update);
  const auto& stats = sync_->stats();
  metrics_.gaps_detected->increment(static_cast<double>(stats.gaps_detected - reported_.gaps_detected));
  metrics_.gaps_repaired->increment(static_cast<double>(stats.gaps_repaired - reported_.gaps_repaired));
  metrics_.repair_requests->increment(static_cast<double>(stats.repair_requests - reported_.repair_requests));
  metrics_.peer_restarts->increment(static_cast<double>(stats.restarts - reported_.restarts));
  metrics_.stale_updates->increment(static_cast<double>(stats.stale - reported_.stale));
  reported_ = stats;
}

void HlmapService::verify_digest(const highlevel::SourcedUpdate& update) {
  const highlevel::Contribution* copy = fusion_->contribution(update.source);
  ++digests_checked_;
  if (copy != nullptr && copy->digest() == update.digest) {
    diverged_.erase(update.source);
    unrepairable_.erase(update.source);
    return;
  }
  ++digest_mismatches_;
  metrics_.digest_mismatches->increment();
  diverged_.insert(update.source);
  const std::string peer(transport::topics::peer_label(update.source));
  if (update.update.full_snapshot) {
    // Even the whole contribution differs here (supervoxels dropped as malformed): asking
    // again would bring the same, so no snapshot is asked for until a digest matches again.
    unrepairable_.insert(update.source);
    core::log_once(core::LogLevel::kWarn, "hlmap", "digest-snapshot/" + peer,
                   robot_id_ + ": '" + update.source + "''s snapshot differs from its digest; not asked again (logged once)");
    return;
  }
  if (unrepairable_.contains(update.source)) return;
  core::log_once(core::LogLevel::kWarn, "hlmap", "digest/" + peer,
                 robot_id_ + ": '" + update.source + "''s contribution differs here from its digest at increment " +
                     std::to_string(update.seq) + "; fetching a snapshot (counted in "
                     "hexplore_hlmap_digest_mismatches_total, logged once)");
  sync_->want_snapshot(update.source);
}

bool HlmapService::in_sync(const std::string& peer) const { return sync_->in_sync(peer) && !diverged_.contains(peer); }

void HlmapService::on_increment(const v1::MapIncrement& increment) {
  highlevel::SourcedUpdate update = highlevel::from_proto(increment);
  count_malformed(update);
  apply_ready(sync_->on_increment(std::move(update)));
}

void HlmapService::on_snapshot(const v1::MapSnapshot& snapshot) {
  highlevel::SourcedUpdate update = highlevel::from_proto(snapshot);
  count_malformed(update);
  apply_ready(sync_->on_snapshot(std::move(update)));
}

void HlmapService::count_malformed(const highlevel::SourcedUpdate& update) {
  if (update.update.malformed == 0) return;
  metrics_.malformed_supervoxels->increment(static_cast<double>(update.update.malformed));
  core::log_once(core::LogLevel::kWarn, "hlmap", "malformed-supervoxels/" + std::string(transport::topics::peer_label(update.source)),
                 robot_id_ + ": dropping malformed supervoxels from '" + update.source +
                     "' (counted in hexplore_hlmap_malformed_supervoxels_total)");
}

v1::MapSnapshot HlmapService::serve_repair(const v1::MapRepairRequest& request) {
  v1::MapSnapshot reply;
  if (request.source_robot() == robot_id_) {
    // Always the whole contribution: increments carry absolute state, so a snapshot repairs
    // any gap and needs no history of past increments.
    reply = highlevel::to_snapshot(log_->snapshot(), log_->contribution());
  } else if (const auto* c = fusion_->contribution(request.source_robot());
             c != nullptr && in_sync(request.source_robot())) {
    // Relay a teammate's contribution we hold completely (helps when the source is out of reach).
    highlevel::SourcedUpdate relay{request.source_robot(), sync_->applied_seq(request.source_robot()), c->snapshot(),
                                   sync_->incarnation(request.source_robot()), c->digest()};
    reply = highlevel::to_snapshot(relay, *c);
  }
  metrics_.snapshots_served->increment();
  window_snapshot_bytes_ += reply.ByteSizeLong();
  return reply;
}

v1::FusedMapUpdate HlmapService::serve_fused(const v1::FusedMapRequest&) {
  highlevel::MapUpdate all = fusion_->map().snapshot();
  all.version = fused_version_;
  v1::FusedMapUpdate reply = highlevel::to_fused_update(all, fusion_->map());
  reply.set_incarnation(log_->incarnation());
  return reply;
}

void HlmapService::window() {
  // 1. Own contribution: publish this window's increment (a heartbeat when empty) and fuse it.
  const auto inc = log_->take_increment();
  const Stopwatch watch;
  fusion_->apply(robot_id_, inc.update);
  metrics_.topology_s->observe(watch.seconds());
  const v1::MapIncrement message = highlevel::to_increment(inc, log_->contribution());
  context_->publisher().publish(topics::kTeamMap, message);
  metrics_.window_bytes_team_map->set(static_cast<double>(message.ByteSizeLong()));
  count_full_map(!inc.update.empty());

  // 2. Repairs that are due.
  for (const auto& req : sync_->due_requests(now_s())) {
    v1::MapRepairRequest request;
    request.set_source_robot(req.source);
    request.set_from_seq(req.from_seq);
    context_->requester(req.source, core::ServiceKind::kHlmap)
        .request<v1::MapRepairRequest, v1::MapSnapshot>(
            request,
            [this, source = req.source](const transport::Received<v1::MapSnapshot>* reply) {
              if (reply == nullptr || reply->message.source_robot() != source) return;  // timeout: asked again later
              on_snapshot(reply->message);
            },
            std::chrono::milliseconds(static_cast<int64_t>(repair_timeout_s_ * 1000)));
  }
  apply_ready({});

  // 3. Fused changes for this robot's planning.
  highlevel::MapUpdate changes = fusion_->take_changes();
  size_t hlmap_bytes = 0;
  if (!changes.empty()) {
    changes.version = ++fused_version_;
    v1::FusedMapUpdate update = highlevel::to_fused_update(changes, fusion_->map());
    update.set_incarnation(log_->incarnation());
    context_->publisher().publish(topics::hlmap(robot_id_), update);
    hlmap_bytes = update.ByteSizeLong();
  }
  metrics_.window_bytes_hlmap->set(static_cast<double>(hlmap_bytes));
  metrics_.window_bytes_snapshots->set(static_cast<double>(window_snapshot_bytes_));
  window_snapshot_bytes_ = 0;

  const auto& map = fusion_->map();
  metrics_.supervoxels->set(static_cast<double>(map.size()));
  metrics_.edges->set(static_cast<double>(map.edges().size()));
  metrics_.graph_vertices->set(static_cast<double>(map.graph().vertex_count()));
  facade_holders_ = highlevel::incomplete_facade_holders(*fusion_, robot_id_);
  metrics_.facades_own_only->set(static_cast<double>(facade_holders_.own_only));
  metrics_.facades_shared->set(static_cast<double>(facade_holders_.shared));
  metrics_.facades_teammates_only->set(static_cast<double>(facade_holders_.teammates_only));
  metrics_.facades_teammates_own_cell->set(static_cast<double>(facade_holders_.teammates_only_own_cell));
  if (map.size() > 0) context_->set_state(v1::SERVICE_STATE_RUNNING);
}

void HlmapService::count_full_map(bool changed) {
  if (changed || full_map_window_bytes_ == 0) {
    // The whole contribution in the increments' own wire form (codec, compression), plus the
    // envelope an increment carries: topic code and a compact header.
    const v1::MapIncrement full = highlevel::to_increment(log_->snapshot(), log_->contribution());
    std::string payload;
    transport::SocketOptions options = context_->socket_options();
    options.compress_level = 3;  // a whole map every second would not be squeezed at level 19
    transport::encode_payload(full, transport::type_id(transport::type_name<v1::MapIncrement>()), true, options,
                              payload);
    constexpr size_t kEnvelopeBytes = 1 + 10;
    full_map_window_bytes_ = payload.size() + kEnvelopeBytes;
  }
  full_map_bytes_ += static_cast<double>(full_map_window_bytes_);
  metrics_.full_map_bytes->increment(static_cast<double>(full_map_window_bytes_));
}

void HlmapService::fill_status(v1::ServiceStatus& status) {
  const service::StatusValues add(status);
  const auto& map = fusion_->map();
  add("supervoxels", static_cast<double>(map.size()));
  add("edges", static_cast<double>(map.edges().size()));
  add("graph_vertices", static_cast<double>(map.graph().vertex_count()));
  add("own_supervoxels", static_cast<double>(segmenter_->supervoxels().size()));
  add("fused_version", static_cast<double>(fused_version_));
  add("own_increment_seq", static_cast<double>(log_->seq()));
  // How far this robot has applied each teammate's increments: against the teammate's own
  // own_increment_seq it says whether the maps converged (after a partition, a restart).
  for (const auto& peer : peers_) add("synced_seq." + peer, static_cast<double>(sync_->applied_seq(peer)));
  // 1 while this robot holds exactly what each teammate last sent (sequence and digest): how
  // long it was 0 after a partition or a restart is the time the maps took to converge.
  for (const auto& peer : peers_) add("in_sync." + peer, in_sync(peer) ? 1.0 : 0.0);
  add("digests_checked", digests_checked_);
  add("digest_mismatches", digest_mismatches_);
  add("gaps_detected", static_cast<double>(sync_->stats().gaps_detected));
  add("gaps_repaired", static_cast<double>(sync_->stats().gaps_repaired));
  add("repair_requests", static_cast<double>(sync_->stats().repair_requests));
  add("snapshots_applied", static_cast<double>(sync_->stats().snapshots_applied));
  add("peer_restarts", static_cast<double>(sync_->stats().restarts));
  add("full_map_bytes", full_map_bytes_);
  add("incomplete_facades.own", static_cast<double>(facade_holders_.own_only));
  add("incomplete_facades.shared", static_cast<double>(facade_holders_.shared));
  add("incomplete_facades.teammates", static_cast<double>(facade_holders_.teammates_only));
  add("incomplete_facades.teammates_own_cell", static_cast<double>(facade_holders_.teammates_only_own_cell));
}

}  // namespace hexplore::hlmap_service
