#pragma once
// The base every hexplore service builds on. A Service only wires sockets to algorithms in
// setup(); the ServiceHost gives it config, identity, an event loop, a PUB socket, metrics and
// a periodic ServiceStatus, and stops it cleanly. The same Service class runs as its own
// process (run_service_main) or composed with others in one process over inproc transport
// (ServiceHost with compose = true, or run_composition_main).

#include <chrono>
#include <functional>
#include <optional>
#include <vector>
#include <map>
#include <memory>
#include <string>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"
#include "common/metrics/registry.h"
#include "common/metrics/standard_families.h"
#include "common/service/lockstep_driver.h"
#include "common/transport/accounting.h"
#include "common/transport/context.h"
#include "common/transport/event_loop.h"
#include "common/transport/publisher.h"
#include "common/transport/request_reply.h"
#include "common/transport/socket_options.h"
#include "common/transport/subscriber.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/status.pb.h"

namespace hexplore::service {

class ServiceContext;

class Service {
 public:
  virtual ~Service() = default;
  // Which service this is; decides endpoints, metrics port and the `service` label.
  virtual core::ServiceKind kind() const = 0;
  std::string name() const { return std::string(core::service_name(kind())); }
  // Called once on the service's loop thread before the loop runs: subscribe, add timers,
  // serve requests. Throwing core::ConfigError or std::exception aborts the start.
  virtual void setup(ServiceContext& context) = 0;
  // Called on the loop thread after the loop stopped, before the sockets close: last words.
  virtual void on_shutdown(ServiceContext& context) {}
  // Adds service-specific values (completeness, views left, ...) to the periodic status.
  virtual void fill_status(v1::ServiceStatus& status) {}
};

using ServiceFactory = std::function<std::unique_ptr<Service>()>;

// Socket options that read and write the team's radio traffic as its services do: the team's
// limits, its roster and its team codecs (no radio model). For tools and test harnesses that
// talk to a team's services from outside a ServiceHost.
transport::SocketOptions team_socket_options(const core::TeamConfig& team);

// Per-service view of the host: everything setup() needs. Sockets made here are owned by the
// context, registered with the loop, and live until the service shuts down. Use from the
// service's loop thread only.
class ServiceContext {
 public:
  const core::TeamConfig& team() const { return *team_; }
  const std::string& robot_id() const { return identity_.robot_id; }
  // nullptr for the station.
  const core::RobotConfig* robot() const { return team_->find_robot(identity_.robot_id); }
  const core::SpeciesConfig* species() const;
  core::ServiceKind kind() const { return kind_; }
  const transport::Identity& identity() const { return identity_; }
  // Unrecognised "--name value" command-line pairs, for service-specific options.
  const std::map<std::string, std::string>& arguments() const { return *arguments_; }

  transport::Context& transport() { return *transport_; }
  transport::EventLoop& loop() { return loop_; }
  metrics::Registry& metrics() { return *metrics_; }
  // The team's limits and wire context (roster, team codecs, radio), for this service's sockets.
  transport::SocketOptions socket_options() const;
  // The radio model when the team file sets one (transport.radio), else nullptr. The sim
  // reports its robot's true position to it (positions()) for the range check.
  transport::RadioMedium* radio() const { return wire_->radio.get(); }
  // Accounting of all of this service's sockets (labels robot and service).
  transport::Accounting& accounting() { return accounting_; }

  // This service's PUB socket, bound at core::bind_endpoint(team, robot, kind, kPublish).
  transport::Publisher& publisher() { return *publisher_; }
  // This service's ROUTER socket, bound on first use at core::bind_endpoint(..., kRequest).
  transport::Responder& responder();
  // This service's SUB socket; connect() it to the publishers it listens to.
  transport::Subscriber& subscriber();
  // Connects subscriber() to the PUB socket of (robot_id, service); idempotent. The station's
  // is not among them: mission commands come through on_mission().
  void connect(const std::string& robot_id, core::ServiceKind service);
  // Calls `handler` for every mission command (start, stop, estop, planner switch) the station
  // publishes. They arrive on a SUB socket of their own connected to the station alone, so on
  // authenticated links (transport.curve_keys_dir) only the holder of the station's key can
  // command a robot: a teammate's publisher cannot inject one on team/mission.
  void on_mission(std::function<void(const v1::MissionCommand&)> handler);
  // An extra SUB socket (e.g. its own high-water mark), owned and polled like subscriber().
  transport::Subscriber& make_subscriber(const transport::SocketOptions& options);
  // A DEALER connected to the ROUTER of (robot_id, service); one per target, reused.
  transport::Requester& requester(const std::string& robot_id, core::ServiceKind service);

  // State and detail reported in the next ServiceStatus (default RUNNING).
  void set_state(v1::ServiceState state, std::string detail = "");
  // Seconds since this service started.
  double uptime_s() const;
  // True in the reproducible fast mode (HostOptions::lockstep): the loop's clock is sim time,
  // so timer periods are sim seconds and nothing may depend on wall time (e.g. time budgets).
  bool lockstep() const { return loop_.in_lockstep(); }
  // Now on the loop's clock: use for time-outs and ages (monotonic, or sim time in lockstep).
  int64_t now_ns() const { return loop_.now_ns(); }

 private:
  friend class ServiceHost;
  // What every socket of a team shares: built once per process by the ServiceHost.
  struct TeamWire {
    std::shared_ptr<const transport::Roster> roster;
    std::shared_ptr<const transport::CodecTable> codecs;
    std::shared_ptr<transport::RadioMedium> radio;
    std::shared_ptr<const transport::CurveKeyring> keyring;  // null: plain ZeroMQ
  };
  ServiceContext(const core::TeamConfig& team, const std::string& robot_id, core::ServiceKind kind,
                 transport::Context& transport, metrics::Registry& metrics, const metrics::TransportFamilies& families,
                 const std::map<std::string, std::string>& arguments, const TeamWire& wire);
  void publish_status(Service& service);
  void close_sockets();

  const core::TeamConfig* team_;
  core::ServiceKind kind_;
  transport::Identity identity_;
  transport::Context* transport_;
  metrics::Registry* metrics_;
  const std::map<std::string, std::string>* arguments_;
  const TeamWire* wire_;
  std::shared_ptr<const transport::CurveCredentials> curve_;  // this member's keys; null: plain
  transport::Accounting accounting_;
  transport::EventLoop loop_;
  std::unique_ptr<transport::Publisher> publisher_;
  std::unique_ptr<transport::Responder> responder_;
  std::vector<std::unique_ptr<transport::Subscriber>> subscribers_;  // [0] is subscriber()
  transport::Subscriber* station_subscriber_ = nullptr;               // on_mission()'s, station only
  std::map<std::string, std::unique_ptr<transport::Requester>> requesters_;
  std::map<std::string, bool> connected_;
  v1::ServiceState state_ = v1::SERVICE_STATE_STARTING;
  std::string detail_;
  int64_t start_ns_;
};

struct HostOptions {
  // Prometheus exposer port: nullopt = from the team config (core::metrics_port of the first
  // service added), 0 = off, -1 = any free port (see ServiceHost::metrics_port()).
  std::optional<int> metrics_port;
  std::string metrics_bind_address = "0.0.0.0";
  std::chrono::milliseconds status_period{1000};
  // Composition: rewrite transport.scheme to inproc so that all services share this process's Context.
  bool compose = false;
  std::map<std::string, std::string> arguments;
  // Fault injection on every service's PUB socket (rig tests of radio drop-outs).
  transport::FaultInjection publisher_faults;
  // Reproducible fast mode (needs compose): every loop steps together on a virtual clock;
  // see lockstep_driver.h.
  bool lockstep = false;
};

// Runs one or several services in this process, each on its own loop thread.
class ServiceHost {
 public:
  // Throws core::ConfigError for a config that cannot be hosted.
  ServiceHost(core::TeamConfig team, HostOptions options);
  // Stops and joins every service, then closes the transport (waits up to linger for queued messages).
  ~ServiceHost();
  ServiceHost(const ServiceHost&) = delete;
  ServiceHost& operator=(const ServiceHost&) = delete;

  // Adds a service for robot `robot_id` (or core::kStationId). Throws core::ConfigError for an
  // unknown robot. Call before start().
  void add(std::unique_ptr<Service> service, const std::string& robot_id);
  // Starts the metrics exposer, then each service: setup() on its loop thread, then the loop.
  // Throws (after stopping what started) if a setup() threw.
  void start();
  // Asks every loop to stop. Thread-safe and async-signal-safe.
  void stop();
  // Joins all loop threads (they end after stop(), or when a service stops its own loop).
  void wait();
  // True once every service loop has returned.
  bool finished() const;
  // True once at least one service loop has returned.
  bool any_finished() const;
  // True when a service stopped because a callback threw (logged); run_service_main exits 1.
  bool failed() const;

  const core::TeamConfig& team() const { return team_; }
  transport::Context& transport() { return transport_; }
  // team_socket_options() of the hosted team (its sockets also carry the radio model).
  transport::SocketOptions socket_options() const;
  metrics::Registry& metrics();
  // Bound metrics port, 0 when off.
  int metrics_port() const { return metrics_port_; }

 private:
  struct Entry;
  class LockstepEntry;
  transport::SocketOptions publisher_options(const ServiceContext& ctx) const;
  // Binds the publisher, runs the service's setup() and adds the status timer; throws.
  void setup_entry(Entry& entry);
  // Runs on_shutdown(), publishes the last status and closes the sockets.
  void finish_entry(Entry& entry);
  void start_threads();
  void start_lockstep();
  // Range only where every robot is simulated; logs what the radio model applies here.
  void configure_radio();
  // First member, so it is destroyed last: zmq_ctx_term waits for every socket to close.
  transport::Context transport_;
  core::TeamConfig team_;
  HostOptions options_;
  std::unique_ptr<metrics::Registry> registry_;
  metrics::TransportFamilies families_;
  int metrics_port_ = 0;
  std::vector<std::unique_ptr<Entry>> entries_;
  std::vector<std::unique_ptr<LockstepEntry>> lockstep_entries_;
  std::unique_ptr<LockstepDriver> lockstep_;
  ServiceContext::TeamWire wire_;
};

// main() of a single-service process:
//   <exe> --config FILE --robot ID [--log-level debug|info|warn|error] [--metrics-port N]
//         [--status-period-ms N] [--fault-drop FRACTION] [--fault-delay-ms N]
//         [--fault-topics PREFIX,PREFIX] [--fault-seed N] [--<name> <value> ...service-specific]
// Bad config: prints "error: <what>" on one line, returns 2. SIGINT/SIGTERM, or every service
// stopping its own loop: clean stop, returns 0. A service stopped by an exception: returns 1.
int run_service_main(int argc, char** argv, const ServiceFactory& factory);

// main() of a composed process: every factory for every --robot given (repeatable), inproc transport.
int run_composition_main(int argc, char** argv, const std::vector<ServiceFactory>& factories);

// main() of a whole team in one process (the reproducible fast mode): every robot factory for
// every --robot, plus one station; inproc transport, all loops in lockstep on sim time (see
// lockstep_driver.h), as fast as the machine allows. Ends when the station ends (mission over)
// or any service fails, stopping the rest.
int run_team_main(int argc, char** argv, const std::vector<ServiceFactory>& robot_factories,
                  const ServiceFactory& station);

}  // namespace hexplore::service
