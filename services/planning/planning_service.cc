#include "services/planning/planning_service.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/core/clock.h"
#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/highlevel/graph_export.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/supervoxel.h"
#include "common/planning/executable_path.h"
#include "common/planning/hexplore_planner.h"
#include "common/planning/open_targets.h"
#include "common/planning/plan_proto.h"
#include "common/planning/round_inputs.h"
#include "common/planning/round_trace.h"
#include "common/radio/as_received.h"
#include "common/service/status_values.h"
#include "common/transport/topics.h"
#include "services/planning/execution_options.h"

namespace hexplore::planning_service {

namespace topics = transport::topics;

namespace {
Eigen::Vector3d position_of(const v1::RobotPose& p) {
  return {p.pose().position_m().x(), p.pose().position_m().y(), p.pose().position_m().z()};
}
}  // namespace

void PlanningService::setup(service::ServiceContext& context) {
  context_ = &context;
  robot_id_ = context.robot_id();
  const core::TeamConfig& team = context.team();
  const auto index = team.robot_index(robot_id_);
  const core::SpeciesConfig* species = context.species();
  if (!index || species == nullptr)
    throw core::ConfigError(team.source_file, "robots." + robot_id_, "planning: robot or its species is unknown");
  self_ = *index;
  speed_mps_ = species->speed_mps;
  capabilities_ = planning::capabilities_from(team);
  options_ = planning::PlannerOptions::from(team.params);
  // A wall-clock budget would make the assignment depend on machine load; in lockstep only
  // the generation budget bounds the GA.
  if (context.lockstep()) options_.ga_time_budget_s = 0.0;
  options_.region = team.exploration_region;
  eta_t_s_ = team.params.eta_t_s;
  solution_gate_ = SolutionGate(eta_t_s_);
  // Paths keep the bodies clear of the obstacles the map knows (common/highlevel/clearance.h).
  map_ = std::make_unique<highlevel::HighLevelMap>(highlevel::species_levels(team), highlevel::clearance_options(team));
  for (const auto& r : team.robots) positions_[r.id] = r.start_position_m;

  const service::Options opts(context.arguments());
  trace_ = service::open_trace_file(opts, "planning-" + robot_id_ + ".jsonl");
  if (trace_.is_open()) {
    trace_dir_ = opts.text("trace-dir");
    trace_graph_period_s_ = opts.number("trace-graph-period-s", 0.0, 0.0);
  }
  mission_ = service::MissionState(opts.flag("wait-for-start", false));
  const double cycle_ms = opts.positive("cycle-ms", 200.0);
  min_replan_s_ = opts.positive("min-replan-s", 1.0);
  teammates_ = core::Liveness(opts.positive("peer-timeout-s", team.params.liveness.planning_team_s));
  for (const auto& r : team.robots) teammates_.heard(r.id, context.now_ns());  // time to show up
  species_index_ = team.species_index(species->name).value_or(0);
  ExecutionOptions exec =
      execution_options(opts, *species, capabilities_.species[size_t(species_index_)], options_);
  exec.follow.record_judgements = trace_.is_open();
  ledger_ = planning::GiveUpLedger(exec.give_up);
  // Teammates' given-up targets are passed on only where some robot may not hear their source.
  give_up_sharing_ = planning::GiveUpSharing(3, 100, /*relay=*/team.transport.radio.range_m > 0.0);
  follower_ = std::make_unique<planning::RouteFollower>(exec.follow, species_index_);
  passing_ = std::make_unique<planning::PassingObserver>(exec.passing, options_);
  peer_stuck_s_ = opts.positive("peer-stuck-s", 30.0);

  auto& m = context.metrics();
  labels_ = {{"robot", robot_id_}};
  const auto buckets = metrics::latency_buckets_s();
  auto* stage = m.histogram_family("hexplore_planning_stage_seconds", "Single-round planning time per stage", buckets);
  auto with = [&](const char* k, const char* v) {
    metrics::Labels l = labels_;
    l[k] = v;
    return l;
  };
  stage_views_ = stage->add(with("stage", "views"));
  stage_clustering_ = stage->add(with("stage", "clustering"));
  stage_assignment_ = stage->add(with("stage", "assignment"));
  stage_mnss_ = stage->add(with("stage", "mnss"));
  stage_total_ = stage->add(with("stage", "total"));
  views_ = m.gauge_family("hexplore_planning_views", "Task views in the last round")->add(labels_);
  clusters_ = m.gauge_family("hexplore_planning_clusters", "Task clusters in the last round")->add(labels_);
  generations_ = m.gauge_family("hexplore_planning_ga_generations", "GA generations in the last round")->add(labels_);
  fitness_ = m.gauge_family("hexplore_planning_ga_best_fitness", "Best GA fitness in the last round")->add(labels_);
  agreement_ = m.gauge_family("hexplore_planning_assignment_agreement_ratio",
                              "Share of clusters assigned to the same robot as in the reference solution")
                   ->add(labels_);
  malformed_supervoxels_ = m.counter_family("hexplore_planning_malformed_supervoxels_total",
                                            "Supervoxels of the fused map dropped: centre off the world or not finite, bad normal")
                               ->add(labels_);
  rounds_ = m.counter_family("hexplore_planning_rounds_total", "Planning rounds run, by planner");
  switches_ = m.counter_family("hexplore_planning_planner_switches_total", "Run-time planner switches, by new planner");
  active_gauge_ = m.gauge_family("hexplore_planning_planner_active", "1 for the active planner, 0 for the others");

  if (!registry_.contains(team.params.planner)) registry_.create(team.params.planner);  // throws, listing the known ones
  if (!switch_planner(team.params.planner)) throw std::invalid_argument("planning: cannot activate planner");

  context.connect(robot_id_, core::ServiceKind::kHlmap);
  context.connect(robot_id_, core::ServiceKind::kSim);
  for (const auto& r : team.robots) {
    context.connect(r.id, core::ServiceKind::kSim);
    if (r.id != robot_id_) context.connect(r.id, core::ServiceKind::kPlanning);
  }

  auto& sub = context.subscriber();
  sub.on<v1::FusedMapUpdate>(topics::hlmap(robot_id_),
                             [this](const transport::Received<v1::FusedMapUpdate>& r) { on_map(r.message); });
  sub.on<v1::RobotPose>(topics::pose(robot_id_), [this](const transport::Received<v1::RobotPose>& r) {
    positions_[robot_id_] = position_of(r.message);
    odometry_m_ = r.message.odometry_m();
    if (r.header.sim_time_ns() > 0) {
      // From the first stamped pose on, teammates' silences are timed in sim time (below):
      // their time to show up starts again on that clock.
      if (sim_time_ns_ == 0)
        for (const auto& t : context_->team().robots) teammates_.heard(t.id, r.header.sim_time_ns());
      sim_time_ns_ = r.header.sim_time_ns();
    }
    own_motion_ = r.message.state();
  });
  sub.on<v1::RobotPose>(std::string(topics::kTeamPose), [this](const transport::Received<v1::RobotPose>& r) {
    const std::string& id = r.header.robot_id();
    if (!context_->team().find_robot(id)) return;
    positions_[id] = position_of(r.message);
    // Back after a silence (out of range, a partition): it missed the given-up changes meanwhile.
    if (id != robot_id_ && !teammates_.alive(id, now_ns())) give_up_sharing_.whole_set_next();
    teammates_.heard(id, now_ns());
    if (id == robot_id_) return;
    // A teammate that stops moving and goes idle has finished its route.
    const int state = r.message.state();
    const Eigen::Vector3d at = position_of(r.message);
    auto anchor = peer_anchor_.find(id);
    if (anchor == peer_anchor_.end() || (at - anchor->second).head<2>().norm() > 0.5 ||
        (state != v1::MOTION_STATE_MOVING && state != v1::MOTION_STATE_BLOCKED)) {
      peer_anchor_[id] = at;  // moving, or not trying to: not stuck
      peer_moved_ns_[id] = now_ns();
    }
    auto [it, fresh] = peer_motion_.emplace(id, state);
    if (!fresh && it->second == v1::MOTION_STATE_MOVING && state == v1::MOTION_STATE_IDLE) peer_finished_ = true;
    it->second = state;
  });
  sub.on<v1::TeamSolution>(std::string(topics::kTeamPlan), [this](const transport::Received<v1::TeamSolution>& r) {
    const std::string& source = r.header.robot_id();
    if (source == robot_id_ || !context_->team().find_robot(source)) return;
    // Only a candidate reference for our next round: replanning on every teammate solution
    // makes robots replan each other in a loop and never finish a route (paper: replan on
    // route time-out or when a robot finishes its route).
    // A solution without sequences (its planner shares no route) is no reference.
    // A round number that went back: its planner restarted and knows nothing the team gave up.
    if (const auto it = shared_rounds_.find(source); it != shared_rounds_.end() && r.message.round() < it->second)
      give_up_sharing_.whole_set_next();
    shared_rounds_[source] = r.message.round();
    if (r.message.sequences_size() > 0) shared_[source] = planning::reference_from_proto(r.message, source);
    const auto& keys = r.message.given_up_supervoxels();
    const auto& counts = r.message.given_up_voxel_counts();
    for (int i = 0; i < keys.size(); ++i) ledger_.merge(keys[i], i < counts.size() ? int(counts[i]) : 0);
  });
  context.on_mission([this](const v1::MissionCommand& command) { on_mission(command); });
  context.responder().serve<v1::OpenTargetsRequest, v1::OpenTargetsReport>(
      [this](const transport::Received<v1::OpenTargetsRequest>&) { return open_targets_report(); });
  request_snapshot();
  context.loop().add_timer(std::chrono::microseconds(int64_t(cycle_ms * 1000)), [this] { cycle(); });
  context.set_state(v1::SERVICE_STATE_RUNNING, "planner " + active_name_);
}

bool PlanningService::switch_planner(const std::string& name) {
  if (name == active_name_ && active_) return true;
  if (!registry_.contains(name)) {
    core::log_once(core::LogLevel::kWarn, "planning", "unknown-planner/" + name,
                   robot_id_ + ": ignoring switch to unknown planner '" + name + "'");
    return false;
  }
  auto& slot = planners_[name];
  if (!slot) {
    slot = registry_.create(name);
    slot->configure({capabilities_, options_});
  }
  if (active_) {
    active_->deactivate();
    if (active_gauge_) active_gauge_->add({{"robot", robot_id_}, {"planner", active_name_}})->set(0.0);
  }
  const std::string previous = active_name_;
  active_ = slot.get();
  active_name_ = name;
  active_->activate();
  if (active_gauge_) active_gauge_->add({{"robot", robot_id_}, {"planner", name}})->set(1.0);
  if (!previous.empty()) {
    if (switches_) switches_->add({{"robot", robot_id_}, {"planner", name}})->increment();
    core::LogLine(core::LogLevel::kInfo, "planning") << robot_id_ << ": planner switched from " << previous << " to " << name;
    follower_->clear();  // plan again with the new planner at the next cycle
  }
  return true;
}

void PlanningService::request_snapshot() {
  if (snapshot_pending_) return;
  snapshot_pending_ = true;
  v1::FusedMapRequest req;
  req.set_requester(robot_id_);
  context_->requester(robot_id_, core::ServiceKind::kHlmap)
      .request<v1::FusedMapRequest, v1::FusedMapUpdate>(
          req,
          [this](const transport::Received<v1::FusedMapUpdate>* reply) {
            snapshot_pending_ = false;
            if (reply) on_map(reply->message);
          },
          std::chrono::milliseconds(2000));
}

void PlanningService::on_map(const v1::FusedMapUpdate& update) {
  switch (map_order_.on_update(update.incarnation(), update.version(), update.full_snapshot())) {
    case FusedMapOrder::Action::kApply: break;
    case FusedMapOrder::Action::kDrop: return;
    case FusedMapOrder::Action::kRequestSnapshot: request_snapshot(); return;
  }
  const highlevel::MapUpdate change = highlevel::from_proto(update);
  if (change.malformed > 0) {
    malformed_supervoxels_->increment(static_cast<double>(change.malformed));
    core::log_once(core::LogLevel::kWarn, "planning", "malformed-supervoxels",
                   robot_id_ + ": dropping malformed supervoxels of the fused map (hexplore_planning_malformed_supervoxels_total)");
  }
  map_->apply(change);
  map_order_.applied(update.incarnation(), update.version());
}

void PlanningService::on_mission(const v1::MissionCommand& command) {
  mission_.apply(command, robot_id_);
  if (command.has_switch_planner() && service::addressed_to(command, robot_id_))
    switch_planner(command.switch_planner().planner());
}

std::vector<planning::RobotState> PlanningService::team_states(int& self) const {
  std::vector<planning::RobotState> out;
  const auto& team = context_->team();
  const int64_t now = now_ns();
  self = 0;
  for (const auto& r : team.robots) {
    const bool me = r.id == robot_id_;
    if (!me && !teammates_.alive(r.id, now)) continue;  // gone silent: not in the team
    if (!me && peer_moved_ns_.count(r.id) && core::ns_to_s(now_ns() - peer_moved_ns_.at(r.id)) > peer_stuck_s_)
      continue;  // trying to move for long without moving: stuck, its work goes to the others
    if (me) self = int(out.size());
    out.push_back({r.id, team.species_index(r.species).value_or(0), positions_.at(r.id)});
  }
  return out;
}

bool PlanningService::team_shrank() const {
  int self = 0;
  const auto now = team_states(self);
  return std::any_of(planned_team_.begin(), planned_team_.end(), [&](const std::string& id) {
    return std::none_of(now.begin(), now.end(), [&](const planning::RobotState& r) { return r.id == id; });
  });
}

std::unordered_set<uint64_t> PlanningService::avoided_vertices() const {
  std::unordered_set<uint64_t> out;
  const auto& team = context_->team();
  const int64_t now = now_ns();
  const auto radii = highlevel::body_radii(team);
  const auto own = team.species_index(team.robots[size_t(self_)].species);
  const double own_radius = own ? radii[size_t(*own)] : 0.0;
  std::vector<uint64_t> keys;
  for (const auto& r : team.robots) {
    if (r.id == robot_id_ || teammates_.alive(r.id, now)) continue;
    const auto species = team.species_index(r.species);
    const double reach = own_radius + (species ? radii[size_t(*species)] : 0.0);
    if (keys.empty()) keys = map_->graph().vertex_keys();
    const Eigen::Vector3d& at = positions_.at(r.id);
    for (uint64_t k : keys)
      if (const auto p = map_->graph().position(k); p && (*p - at).head<2>().norm() < reach && planning::same_level(*p, at))
        out.insert(k);
  }
  return out;
}

int64_t PlanningService::now_ns() const { return sim_time_ns_ > 0 ? sim_time_ns_ : context_->now_ns(); }

planning::DriveState PlanningService::drive_state() const {
  switch (own_motion_) {
    case v1::MOTION_STATE_MOVING: return planning::DriveState::kMoving;
    case v1::MOTION_STATE_BLOCKED: return planning::DriveState::kBlocked;
    case v1::MOTION_STATE_STOPPED:
    case v1::MOTION_STATE_EMERGENCY_STOP: return planning::DriveState::kStopped;
    default: return planning::DriveState::kIdle;
  }
}

void PlanningService::follow_route() {
  const double now_s = core::ns_to_s(now_ns());
  if (now_s - last_look_s_ >= 1.0) {
    last_look_s_ = now_s;
    passing_->step(now_s, positions_.at(robot_id_), *map_, ledger_);
  }
  const auto order = follower_->step(core::ns_to_s(now_ns()), positions_.at(robot_id_), drive_state(), *map_,
                                     avoided_vertices(), ledger_);
  if (!order) return;
  core::LogLine(core::LogLevel::kDebug, "planning")
      << robot_id_ << ": at (" << positions_.at(robot_id_).head<2>().transpose() << ") "
      << (order->observing ? "observing, aim " : "path to ") << "(" << order->path.goal.position.head<2>().transpose()
      << "), " << order->path.waypoints.size() << " waypoints";
  v1::ExecutablePath path = planning::path_to_proto(round_, order->path, speed_mps_);
  path.set_observing(order->observing);
  context_->publisher().publish(topics::path(robot_id_), path);
}

void PlanningService::cycle() {
  if (!map_order_.have_map()) request_snapshot();  // hlmap may have started after us, or a reply was lost
  if (!mission_.active() || !map_order_.have_map() || !active_) return;
  follow_route();
  const double age_s = since_last_plan_s();
  std::string reason;
  if (last_plan_ns_ == 0) reason = "first round";
  else if (follower_->finished() && age_s >= min_replan_s_) reason = "route finished";
  else if (team_shrank() && age_s >= min_replan_s_) reason = "teammate lost";  // its share is ours now
  else if (age_s >= eta_t_s_ && !follower_->observing()) reason = "route timed out";  // not mid-observation
  else if (peer_finished_ && age_s >= min_replan_s_) reason = "teammate finished its route";
  if (!reason.empty()) replan(reason);
}

double PlanningService::since_last_plan_s() const {
  if (sim_time_ns_ > 0 && last_plan_sim_ns_ > 0) return core::ns_to_s(sim_time_ns_ - last_plan_sim_ns_);
  return core::ns_to_s(context_->now_ns() - last_plan_ns_);
}

void PlanningService::replan(const std::string& reason) {
  planning::PlanRequest req;
  req.map = map_.get();
  req.robots = team_states(req.self);
  planned_team_.clear();
  for (const auto& r : req.robots) planned_team_.push_back(r.id);
  req.round = ++round_;
  req.given_up = &ledger_;
  for (const auto& [source, s] : shared_) req.shared.push_back(s);
  peer_finished_ = false;
  last_plan_ns_ = context_->now_ns();
  last_plan_sim_ns_ = sim_time_ns_;
  planning::PlanResult res;
  try {
    res = active_->plan(req);
  } catch (const std::exception& e) {
    core::LogLine(core::LogLevel::kError, "planning") << robot_id_ << ": round " << round_ << " failed: " << e.what();
    return;
  }
  v1::TeamSolution solution = planning::to_proto(res);
  // Our own solution is a reference candidate next round, like the teammates', at the precision
  // they decode it with (the radio rounds coordinates), so that every robot weighs the same numbers.
  if (active_->route_sharing() != planning::RouteSharing::kNone) {
    const transport::SocketOptions wire = context_->socket_options();
    shared_[robot_id_] = planning::reference_from_proto(
        radio::as_received(solution, wire.codecs.get(), wire.roster.get()), robot_id_);
  }
  const std::vector<planning::TaskView>& route = res.robots[size_t(req.self)].route;

  stage_views_->observe(res.times.views_s);
  stage_clustering_->observe(res.times.clustering_s);
  stage_assignment_->observe(res.times.assignment_s);
  stage_mnss_->observe(res.times.mnss_s);
  stage_total_->observe(res.times.total_s);
  last_views_ = size_t(res.open_views);
  last_planning_time_s_ = res.times.total_s;
  views_->set(res.views);
  clusters_->set(res.clusters);
  generations_->set(res.ga_generations);
  fitness_->set(res.fitness);
  if (res.agreement) agreement_->set(*res.agreement);
  rounds_->add({{"robot", robot_id_}, {"planner", active_name_}})->increment();
  core::LogLine(core::LogLevel::kDebug, "planning")
      << robot_id_ << ": round " << round_ << " (" << reason << ", " << active_name_ << "): " << res.views << " views, "
      << res.clusters << " clusters (" << res.dropped_clusters << " dropped), " << res.open_views << " open, "
      << route.size() << " route views, " << req.robots.size() << " live, " << ledger_.given_up_count()
      << " given up, "
      << res.view_stats.outside_region << " outside, " << res.view_stats.unreachable_ground << " unreachable ground, "
      << res.times.total_s * 1e3 << " ms";
  if (!route.empty()) {
    const Eigen::Vector3d& me = positions_.at(robot_id_);
    const Eigen::Vector3d& first = route.front().position;
    core::LogLine(core::LogLevel::kDebug, "planning")
        << robot_id_ << ": at (" << me.x() << ", " << me.y() << ", " << me.z() << "), first view (" << first.x()
        << ", " << first.y() << ", " << first.z() << ")";
  }

  auto& pub = context_->publisher();
  // Sequences travel only where a teammate makes something of them (planning::RouteSharing).
  // Without them the message still carries the given-up targets below, so every robot agrees on
  // what is left (what changed lately, and now and then the whole set: planning::GiveUpSharing).
  if (!sequences_worth_sending()) solution.clear_sequences();
  // The same solution again (an idle robot replans every second) waits for eta_t.
  if (solution_gate_.should_send(solution, give_up_sharing_.has_news(ledger_), core::ns_to_s(now_ns()))) {
    for (const auto& [key, voxels] : give_up_sharing_.next(ledger_)) {
      solution.add_given_up_supervoxels(key);
      solution.add_given_up_voxel_counts(uint32_t(std::max(0, voxels)));
    }
    pub.publish(std::string(topics::kTeamPlan), solution);
    if (solution.sequences_size() > 0) held_by_teammates_ = shared_.at(robot_id_);
  }
  pub.publish(topics::route(robot_id_), planning::route_to_proto(round_, route));
  follower_->set_path_species(res.path_species >= 0 ? res.path_species : species_index_);
  follower_->set_route(route, positions_.at(robot_id_), *map_);
  // Traced after the follower merged the route: the trace shows where the robot heads next.
  if (trace_.is_open()) write_trace(reason, req, res);
  follow_route();  // the path to the first view at once
}

bool PlanningService::sequences_worth_sending() const {
  switch (active_->route_sharing()) {
    case planning::RouteSharing::kNone: return false;
    case planning::RouteSharing::kEverySolution: return true;
    case planning::RouteSharing::kReferenceOnly: break;
  }
  std::vector<planning::ReferenceSolution> teammates;
  for (const auto& [source, s] : shared_)
    if (source != robot_id_) teammates.push_back(s);
  return planning::reference_worth_sending(teammates, shared_.at(robot_id_), held_by_teammates_);
}

void PlanningService::write_trace(const std::string& reason, const planning::PlanRequest& req,
                                  const planning::PlanResult& res) {
  planning::RoundTrace round;
  round.t_s = core::ns_to_s(now_ns());
  round.round = round_;
  round.reason = reason;
  round.planner = active_name_;
  round.position = positions_.at(robot_id_);
  round.odometry_m = odometry_m_;
  round.given_up = ledger_.given_up_count();
  round.passing_observations = uint64_t(passing_->observations());
  const auto ahead = follower_->views_ahead();
  for (const auto& v : ahead.first(std::min<size_t>(3, ahead.size()))) round.follower_next.push_back(v.position);
  round.judged = follower_->take_judgements();
  trace_ << planning::round_trace_json(round, req, res, follower_->counters(), *map_, options_.region);
  trace_.flush();
  if (trace_graph_period_s_ > 0.0 && round.t_s - graph_traced_s_ >= trace_graph_period_s_) {
    graph_traced_s_ = round.t_s;
    const std::string path = trace_dir_ + "/graph-" + robot_id_ + "-" + std::to_string(int64_t(round.t_s)) + ".ply";
    std::ofstream graph(path);
    highlevel::write_graph_ply(map_->graph(), graph);
    if (!graph) core::log_once(core::LogLevel::kWarn, "planning", "graph-trace", "cannot write the graph trace " + path);
  }
}

v1::OpenTargetsReport PlanningService::open_targets_report() const {
  std::vector<planning::OpenTarget> targets;
  if (map_order_.have_map()) {
    planning::PlanRequest req;
    req.map = map_.get();
    req.robots = team_states(req.self);
    req.given_up = &ledger_;
    const planning::RoundInputs in = planning::prepare_round(req, capabilities_, options_, /*record_targets=*/true);
    const auto attempts = ledger_.attempt_counts();
    targets = planning::open_targets(*map_, in.targets, &attempts);
  }
  return planning::to_proto(robot_id_, core::ns_to_s(now_ns()), round_, targets);
}

void PlanningService::fill_status(v1::ServiceStatus& status) {
  status.set_detail("planner " + active_name_);
  const service::StatusValues add(status);
  add("round", double(round_));
  // The station's mission monitor and recorder read these two (common/evaluation/team_recorder.h).
  if (round_ > 0) {
    add("views_remaining", double(last_views_));
    add("planning_time_s", last_planning_time_s_);
  }
  add("route_views_left", double(follower_ ? follower_->views_left() : 0));
  add("map_version", double(map_order_.version()));
}

}  // namespace hexplore::planning_service
