#include "common/core/clock.h"
#include "common/core/log.h"
#include "common/radio/team_codecs.h"
#include "common/service/service.h"
#include "common/service/team_keys.h"
#include "common/transport/topics.h"

namespace hexplore::service {

transport::SocketOptions team_socket_options(const core::TeamConfig& team) {
  transport::SocketOptions options = transport::SocketOptions::from_config(team.transport);
  options.roster = transport::Roster::from_team(team);
  options.codecs = radio::team_codecs(team);
  return options;
}

ServiceContext::ServiceContext(const core::TeamConfig& team, const std::string& robot_id, core::ServiceKind kind,
                               transport::Context& transport, metrics::Registry& metrics,
                               const metrics::TransportFamilies& families,
                               const std::map<std::string, std::string>& arguments, const TeamWire& wire)
    : team_(&team),
      kind_(kind),
      transport_(&transport),
      metrics_(&metrics),
      arguments_(&arguments),
      wire_(&wire),
      accounting_(robot_id, std::string(core::service_name(kind)), &families),
      start_ns_(core::monotonic_ns()) {
  identity_.robot_id = robot_id;
  const core::RobotConfig* r = team.find_robot(robot_id);
  identity_.species = r != nullptr ? r->species : "";
  identity_.service = std::string(core::service_name(kind));
  curve_ = member_credentials(team, wire.keyring, robot_id);
}

const core::SpeciesConfig* ServiceContext::species() const {
  const core::RobotConfig* r = robot();
  return r == nullptr ? nullptr : team_->find_species(r->species);
}

transport::SocketOptions ServiceContext::socket_options() const {
  transport::SocketOptions options = transport::SocketOptions::from_config(team_->transport);
  options.roster = wire_->roster;
  options.codecs = wire_->codecs;
  options.radio = wire_->radio;
  options.receiver_robot = identity_.robot_id;
  options.curve = curve_;
  return options;
}

transport::Responder& ServiceContext::responder() {
  if (!responder_) {
    responder_ = std::make_unique<transport::Responder>(
        *transport_, identity_, core::bind_endpoint(*team_, identity_.robot_id, kind_, core::SocketRole::kRequest),
        socket_options(), &accounting_);
    loop_.add(*responder_);
  }
  return *responder_;
}

transport::Subscriber& ServiceContext::subscriber() {
  if (subscribers_.empty()) make_subscriber(socket_options());
  return *subscribers_.front();
}

transport::Subscriber& ServiceContext::make_subscriber(const transport::SocketOptions& options) {
  subscribers_.push_back(std::make_unique<transport::Subscriber>(*transport_, options, &accounting_));
  loop_.add(*subscribers_.back());
  return *subscribers_.back();
}

void ServiceContext::on_mission(std::function<void(const v1::MissionCommand&)> handler) {
  if (station_subscriber_ == nullptr) {
    station_subscriber_ = &make_subscriber(socket_options());
    const std::string station(core::kStationId);
    station_subscriber_->connect(
        core::connect_endpoint(*team_, station, core::ServiceKind::kStation, core::SocketRole::kPublish), station);
  }
  station_subscriber_->on<v1::MissionCommand>(
      std::string(transport::topics::kTeamMission),
      [handler = std::move(handler)](const transport::Received<v1::MissionCommand>& r) { handler(r.message); });
}

void ServiceContext::connect(const std::string& robot_id, core::ServiceKind service) {
  if (service == core::ServiceKind::kStation)
    throw std::invalid_argument("connect: the station's commands come through on_mission()");
  const std::string endpoint = core::connect_endpoint(*team_, robot_id, service, core::SocketRole::kPublish);
  if (connected_[endpoint]) return;
  subscriber().connect(endpoint, robot_id);
  connected_[endpoint] = true;
}

transport::Requester& ServiceContext::requester(const std::string& robot_id, core::ServiceKind service) {
  const std::string endpoint = core::connect_endpoint(*team_, robot_id, service, core::SocketRole::kRequest);
  auto& slot = requesters_[endpoint];
  if (!slot) {
    slot = std::make_unique<transport::Requester>(*transport_, identity_, endpoint, socket_options(), &accounting_,
                                                  robot_id);
    loop_.add(*slot);
  }
  return *slot;
}

void ServiceContext::set_state(v1::ServiceState state, std::string detail) {
  state_ = state;
  detail_ = std::move(detail);
}

double ServiceContext::uptime_s() const { return core::ns_to_s(core::monotonic_ns() - start_ns_); }

void ServiceContext::publish_status(Service& service) {
  v1::ServiceStatus status;
  status.set_service(identity_.service);
  status.set_state(state_);
  status.set_detail(detail_);
  status.set_uptime_s(uptime_s());
  service.fill_status(status);
  if (wire_->radio) {
    // What the radio model cost this service's sockets, for the experiment record.
    auto add = [&](const char* name, transport::DropReason reason) {
      auto* v = status.add_values();
      v->set_name(name);
      v->set_value(static_cast<double>(accounting_.dropped(reason)));
    };
    add("radio_expired", transport::DropReason::kRadioExpired);
    add("radio_lost", transport::DropReason::kRadioLost);
    add("radio_out_of_range", transport::DropReason::kRadioOutOfRange);
  }
  publisher_->publish(transport::topics::status(identity_.robot_id), status);
}

void ServiceContext::close_sockets() {
  for (auto& [endpoint, r] : requesters_) loop_.remove(*r);
  for (auto& s : subscribers_) loop_.remove(*s);
  if (responder_) loop_.remove(*responder_);
  if (publisher_) loop_.remove(*publisher_);
  requesters_.clear();
  subscribers_.clear();
  responder_.reset();
  publisher_.reset();  // sends delayed messages; ZeroMQ flushes the queue within linger
}

}  // namespace hexplore::service
