#include <atomic>
#include <future>
#include <thread>

#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/metrics/prometheus_registry.h"
#include "common/service/service.h"

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
  if (options_.compose) team_.transport.scheme = "inproc";
  auto registry = std::make_unique<metrics::PrometheusRegistry>();
  registry_ = std::move(registry);
  families_ = metrics::TransportFamilies::create(*registry_);
}

ServiceHost::~ServiceHost() {
  stop();
  wait();
  entries_.clear();  // sockets are closed by now; transport_ (destroyed last) waits out linger
}

metrics::Registry& ServiceHost::metrics() { return *registry_; }

void ServiceHost::add(std::unique_ptr<Service> service, const std::string& robot_id) {
  if (robot_id != core::kStationId && team_.find_robot(robot_id) == nullptr)
    throw core::ConfigError(team_.source_file, "robots",
                            "unknown robot id '" + robot_id + "' (known: " + known_robots(team_) + ")");
  auto entry = std::make_unique<Entry>();
  const core::ServiceKind kind = service->kind();
  entry->service = std::move(service);
  entry->context = std::unique_ptr<ServiceContext>(
      new ServiceContext(team_, robot_id, kind, transport_, *registry_, families_, options_.arguments));
  entry->process = std::make_unique<metrics::ProcessMetrics>(*registry_, robot_id, std::string(core::service_name(kind)));
  entries_.push_back(std::move(entry));
}

void ServiceHost::start() {
  if (entries_.empty()) throw std::logic_error("service: ServiceHost::start() with no service added");
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

  std::vector<std::future<void>> ready;
  for (auto& entry_ptr : entries_) {
    Entry& entry = *entry_ptr;
    auto promise = std::make_shared<std::promise<void>>();
    ready.push_back(promise->get_future());
    entry.thread = std::thread([this, &entry, promise] {
      ServiceContext& ctx = *entry.context;
      bool setup_done = false;
      try {
        ctx.publisher_ = std::make_unique<transport::Publisher>(
            transport_, ctx.identity_,
            core::bind_endpoint(team_, ctx.robot_id(), ctx.kind(), core::SocketRole::kPublish), publisher_options(ctx),
            &ctx.accounting_);
        ctx.loop_.add(*ctx.publisher_);
        entry.service->setup(ctx);
        if (ctx.state_ == v1::SERVICE_STATE_STARTING) ctx.state_ = v1::SERVICE_STATE_RUNNING;
        ctx.loop_.add_timer(options_.status_period, [&entry] {
          entry.process->update();
          entry.context->publish_status(*entry.service);
        });
        setup_done = true;
        promise->set_value();
        ctx.publish_status(*entry.service);
        ctx.loop_.run();
        ctx.state_ = v1::SERVICE_STATE_STOPPING;
        entry.service->on_shutdown(ctx);
        ctx.publish_status(*entry.service);
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
