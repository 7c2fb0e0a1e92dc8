#include <atomic>
#include <set>
#include <future>
#include <thread>

#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/metrics/prometheus_registry.h"
#include "common/service/option_catalogue.h"
#include "common/service/service.h"
#include "common/service/team_keys.h"

namespace hexplore::service {

struct ServiceHost::Entry {
  std::unique_ptr<Service> service;
  std::unique_ptr<ServiceContext> context;
  std::unique_ptr<metrics::ProcessMetrics> process;
  std::thread thread;
  std::atomic<bool> finished{false};
  std::atomic<bool> failed{false};
};

namespace {

std::string known_robots(const core::TeamConfig& team) {
  std::string list;
  for (const auto& r : team.robots) list += (list.empty() ? "" : ", ") + r.id;
  return list + (list.empty() ? "" : ", ") + std::string(core::kStationId);
}

}  // namespace

transport::SocketOptions ServiceHost::publisher_options(const ServiceContext& ctx) const {
  transport::SocketOptions options = ctx.socket_options();
  options.faults = options_.publisher_faults;
  return options;
}

ServiceHost::ServiceHost(core::TeamConfig team, HostOptions options)
    : team_(std::move(team)), options_(std::move(options)) {
  require_service_options(options_.arguments);  // a typo must not run a mission without its option
  if (options_.compose) team_.transport.scheme = "inproc";
  auto registry = std::make_unique<metrics::PrometheusRegistry>();
  registry_ = std::move(registry);
  families_ = metrics::TransportFamilies::create(*registry_);
  const transport::SocketOptions team_options = team_socket_options(team_);
  wire_.roster = team_options.roster;
  wire_.codecs = team_options.codecs;
  // Authenticated team links: the guard admits only the team's keys to this process's servers.
  // Only tcp sockets use them (ipc and inproc stay on the host), so a composed team needs no keys.
  if (team_.transport.scheme == "tcp") wire_.keyring = team_keyring(team_);
  if (wire_.keyring) {
    metrics::CounterFamily* refused = registry_->counter_family(
        "hexplore_transport_rejected_peers_total",
        "Peers refused by the CURVE guard: reason=unknown_key (handshake with a key not in the team), handshake (no or wrong keys)");
    metrics::Counter* unknown = refused->add({{"reason", "unknown_key"}});
    metrics::Counter* handshake = refused->add({{"reason", "handshake"}});
    transport_.enable_curve(wire_.keyring, [unknown, handshake](transport::CurveGuard::Refusal why, const std::string&) {
      (why == transport::CurveGuard::Refusal::kUnknownKey ? unknown : handshake)->increment();
    });
  }
  if (team_.transport.radio.active())
    wire_.radio = std::make_shared<transport::RadioMedium>(team_.transport.radio, wire_.roster, team_.params.seed,
                                                           options_.lockstep);
}

ServiceHost::~ServiceHost() {
  stop();
  wait();
  lockstep_.reset();
  lockstep_entries_.clear();
  entries_.clear();  // sockets are closed by now; transport_ (destroyed last) waits out linger
}

metrics::Registry& ServiceHost::metrics() { return *registry_; }

transport::SocketOptions ServiceHost::socket_options() const {
  transport::SocketOptions options = transport::SocketOptions::from_config(team_.transport);
  options.roster = wire_.roster;
  options.codecs = wire_.codecs;
  return options;
}

void ServiceHost::add(std::unique_ptr<Service> service, const std::string& robot_id) {
  if (robot_id != core::kStationId && team_.find_robot(robot_id) == nullptr)
    throw core::ConfigError(team_.source_file, "robots",
                            "unknown robot id '" + robot_id + "' (known: " + known_robots(team_) + ")");
  auto entry = std::make_unique<Entry>();
  const core::ServiceKind kind = service->kind();
  entry->service = std::move(service);
  entry->context = std::unique_ptr<ServiceContext>(
      new ServiceContext(team_, robot_id, kind, transport_, *registry_, families_, options_.arguments, wire_));
  entry->process = std::make_unique<metrics::ProcessMetrics>(*registry_, robot_id, std::string(core::service_name(kind)));
  entries_.push_back(std::move(entry));
}

// One service as the lockstep driver sees it.
class ServiceHost::LockstepEntry : public LockstepWorker {
 public:
  LockstepEntry(ServiceHost& host, Entry& entry) : host_(host), entry_(entry) {}
  void setup() override {
    entry_.context->loop_.enter_lockstep();
    host_.setup_entry(entry_);
    set_up_ = true;
  }
  size_t collect() override { return entry_.context->loop_.collect(); }
  void discard() override { entry_.context->loop_.discard_collected(); }
  void dispatch(int64_t now_ns, bool run_due) override {
    try {
      entry_.context->loop_.dispatch(now_ns, run_due);
    } catch (const std::exception& e) {
      entry_.failed.store(true);
      core::LogLine(core::LogLevel::kError, entry_.context->identity().service) << "stopped by an exception: " << e.what();
      throw;
    }
  }
  std::optional<int64_t> next_due_ns() const override { return entry_.context->loop_.next_due_ns(); }
  bool stop_requested() const override { return entry_.context->loop_.stop_requested(); }
  void finish() override {
    if (set_up_) {
      try {
        host_.finish_entry(entry_);
      } catch (const std::exception& e) {
        core::LogLine(core::LogLevel::kError, entry_.context->identity().service) << "shutdown failed: " << e.what();
      }
    }
    entry_.context->close_sockets();
    entry_.finished.store(true);
  }

 private:
  ServiceHost& host_;
  Entry& entry_;
  bool set_up_ = false;
};

void ServiceHost::setup_entry(Entry& entry) {
  ServiceContext& ctx = *entry.context;
  ctx.publisher_ = std::make_unique<transport::Publisher>(
      transport_, ctx.identity_, core::bind_endpoint(team_, ctx.robot_id(), ctx.kind(), core::SocketRole::kPublish),
      publisher_options(ctx), &ctx.accounting_);
  ctx.loop_.add(*ctx.publisher_);
  entry.service->setup(ctx);
  if (ctx.state_ == v1::SERVICE_STATE_STARTING) ctx.state_ = v1::SERVICE_STATE_RUNNING;
  ctx.loop_.add_timer(options_.status_period, [&entry] {
    entry.process->update();
    entry.context->publish_status(*entry.service);
  });
}

void ServiceHost::finish_entry(Entry& entry) {
  ServiceContext& ctx = *entry.context;
  ctx.state_ = v1::SERVICE_STATE_STOPPING;
  entry.service->on_shutdown(ctx);
  ctx.publish_status(*entry.service);
}

void ServiceHost::start() {
  if (entries_.empty()) throw std::logic_error("service: ServiceHost::start() with no service added");
  if (options_.lockstep && !options_.compose)
    throw std::logic_error("service: lockstep needs every service in one process (HostOptions::compose)");
  int port = 0;
  if (options_.metrics_port) {
    port = *options_.metrics_port;
  } else {
    const auto& first = *entries_.front()->context;
    port = core::metrics_port(team_, first.robot_id(), first.kind());
  }
  if (port != 0) {
    auto& prometheus = static_cast<metrics::PrometheusRegistry&>(*registry_);
    metrics_port_ = prometheus.expose(port < 0 ? 0 : port, options_.metrics_bind_address);
    core::LogLine(core::LogLevel::kInfo, "service") << "serving /metrics on port " << metrics_port_;
  }
  if (wire_.radio) configure_radio();
  if (options_.lockstep) start_lockstep();
  else start_threads();
}

void ServiceHost::configure_radio() {
  // The range needs every robot's true position, which only the sims report: model it when
  // this process simulates the whole team (lockstep, --compose), not in one process of many.
  std::set<std::string> simulated;
  for (const auto& entry : entries_)
    if (entry->context->kind() == core::ServiceKind::kSim) simulated.insert(entry->context->robot_id());
  const bool whole_team = simulated.size() == team_.robots.size();
  wire_.radio->enable_range(whole_team);
  wire_.radio->enable_outages(options_.lockstep);
  const auto& radio = team_.transport.radio;
  core::LogLine(core::LogLevel::kInfo, "service")
      << "radio model: " << (radio.bandwidth_bytes_per_s > 0 ? std::to_string(radio.bandwidth_bytes_per_s) + " B/s" : "unlimited")
      << " per robot, latency " << radio.latency_s << " s, loss " << radio.loss << ", range "
      << (radio.range_m > 0 ? std::to_string(radio.range_m) + " m" : "unlimited");
  if (!radio.outages.empty() && !options_.lockstep)
    core::log(core::LogLevel::kWarn, "service",
              "transport.radio.outages are not modelled here: they are in sim seconds, which only lockstep's clock is");
  if (radio.range_m > 0 && !whole_team)
    core::log(core::LogLevel::kWarn, "service",
              "transport.radio.range_m is not modelled here: this process does not simulate every robot");
  if (radio.bandwidth_bytes_per_s > 0 && entries_.size() > 1 && !whole_team)
    core::log(core::LogLevel::kInfo, "service", "radio bandwidth is shared by the services of this process only");
  else if (radio.bandwidth_bytes_per_s > 0 && entries_.size() == 1)
    core::log(core::LogLevel::kWarn, "service",
              "transport.radio.bandwidth_bytes_per_s applies to this one service: a robot's services in separate "
              "processes cannot share one transmitter");
}

void ServiceHost::start_lockstep() {
  std::vector<LockstepWorker*> workers;
  for (auto& entry : entries_) {
    lockstep_entries_.push_back(std::make_unique<LockstepEntry>(*this, *entry));
    workers.push_back(lockstep_entries_.back().get());
  }
  // The radio schedules what a step's services sent once the step is over, in a fixed order.
  std::function<void()> after_step;
  if (wire_.radio) after_step = [radio = wire_.radio] { radio->commit(); };
  lockstep_ = std::make_unique<LockstepDriver>(std::move(workers), std::move(after_step));
  lockstep_->start();  // rethrows a setup's exception after everything closed
  core::LogLine(core::LogLevel::kInfo, "service") << "lockstep: " << entries_.size()
                                                   << " services step together on sim time";
}

void ServiceHost::start_threads() {
  std::vector<std::future<void>> ready;
  for (auto& entry_ptr : entries_) {
    Entry& entry = *entry_ptr;
    auto promise = std::make_shared<std::promise<void>>();
    ready.push_back(promise->get_future());
    entry.thread = std::thread([this, &entry, promise] {
      ServiceContext& ctx = *entry.context;
      bool setup_done = false;
      try {
        setup_entry(entry);
        setup_done = true;
        promise->set_value();
        ctx.publish_status(*entry.service);
        ctx.loop_.run();
        finish_entry(entry);
      } catch (...) {
        if (!setup_done) {
          promise->set_exception(std::current_exception());
        } else {
          entry.failed.store(true);
          try {
            throw;
          } catch (const std::exception& e) {
            core::LogLine(core::LogLevel::kError, ctx.identity().service) << "stopped by an exception: " << e.what();
          } catch (...) {
            core::LogLine(core::LogLevel::kError, ctx.identity().service) << "stopped by an unknown exception";
          }
        }
      }
      ctx.close_sockets();
      entry.finished.store(true);
    });
  }
  std::exception_ptr first_error;
  for (auto& f : ready) {
    try {
      f.get();
    } catch (...) {
      if (!first_error) first_error = std::current_exception();
    }
  }
  if (first_error) {
    stop();
    wait();
    std::rethrow_exception(first_error);
  }
}

bool ServiceHost::any_finished() const {
  for (const auto& entry : entries_)
    if (entry->finished.load()) return true;
  return false;
}

void ServiceHost::stop() {
  for (auto& entry : entries_) entry->context->loop_.stop();
}

void ServiceHost::wait() {
  if (lockstep_) lockstep_->join();
  for (auto& entry : entries_)
    if (entry->thread.joinable()) entry->thread.join();
}

bool ServiceHost::failed() const {
  for (const auto& entry : entries_)
    if (entry->failed.load()) return true;
  return false;
}

bool ServiceHost::finished() const {
  for (const auto& entry : entries_)
    if (!entry->finished.load()) return false;
  return true;
}

}  // namespace hexplore::service
