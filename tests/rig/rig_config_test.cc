// The rig's configuration files agree with the team file and with core::endpoints: every
// robot's five services and the station appear in compose.yaml under the host names the
// services connect to, with the metrics port their exposer binds (which the healthcheck
// probes), and deploy/prometheus.yml scrapes exactly those addresses.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "common/core/endpoints.h"
#include "common/core/team_config.h"

namespace hexplore::core {
namespace {

const std::string kSource = HEXPLORE_SOURCE_DIR;
const std::string kTeamFile = "multi-building.yaml";
constexpr ServiceKind kRobotServices[] = {ServiceKind::kSim, ServiceKind::kMapping, ServiceKind::kHlmap,
                                          ServiceKind::kPlanning, ServiceKind::kSafety};

// yaml-cpp 0.7 reads anchors and aliases but not merge keys ("<<: *x"); compose relies on them.
YAML::Node resolve_merges(const YAML::Node& node) {
  if (node.IsSequence()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const auto& item : node) out.push_back(resolve_merges(item));
    return out;
  }
  if (!node.IsMap()) return node;
  YAML::Node out(YAML::NodeType::Map);
  auto merge_from = [&](const YAML::Node& source) {
    for (const auto& kv : resolve_merges(source)) out[kv.first.as<std::string>()] = kv.second;
  };
  if (const auto merge = node["<<"]; merge) {
    if (merge.IsSequence())
      for (const auto& source : merge) merge_from(source);
    else
      merge_from(merge);
  }
  for (const auto& kv : node)
    if (kv.first.as<std::string>() != "<<") out[kv.first.as<std::string>()] = resolve_merges(kv.second);
  return out;
}

// "tcp://slugcat1-sim:17000" -> "slugcat1-sim".
std::string host_of(const std::string& endpoint) {
  const auto start = endpoint.find("://") + 3;
  return endpoint.substr(start, endpoint.rfind(':') - start);
}

std::string container_of(const std::string& robot, ServiceKind service) {
  return robot == kStationId ? std::string(kStationId) : robot + "-" + std::string(service_name(service));
}

class RigConfigTest : public ::testing::Test {
 protected:
  void SetUp() override {
    team_ = load_team_config(kSource + "/deploy/teams/" + kTeamFile);
    compose_ = resolve_merges(YAML::LoadFile(kSource + "/compose.yaml"));
    prometheus_ = YAML::LoadFile(kSource + "/deploy/prometheus.yml");
  }

  // Every (robot, service) of the team, the station included.
  std::vector<std::pair<std::string, ServiceKind>> all_services() const {
    std::vector<std::pair<std::string, ServiceKind>> out;
    for (const auto& robot : team_.robots)
      for (auto s : kRobotServices) out.emplace_back(robot.id, s);
    out.emplace_back(std::string(kStationId), ServiceKind::kStation);
    return out;
  }

  TeamConfig team_;
  YAML::Node compose_;
  YAML::Node prometheus_;
};

TEST_F(RigConfigTest, TeamIsTwoSlugcatsAndTwoMr1000sOnTheMultiBuildingScene) {
  EXPECT_EQ(team_.scene, "multi-building");
  int slugcats = 0, mr1000s = 0;
  for (const auto& r : team_.robots) {
    slugcats += r.species == "SLUGCAT";
    mr1000s += r.species == "MR1000";
  }
  EXPECT_EQ(slugcats, 2);
  EXPECT_EQ(mr1000s, 2);
  for (size_t i = 0; i < team_.robots.size(); ++i)
    for (size_t j = i + 1; j < team_.robots.size(); ++j)
      EXPECT_GE((team_.robots[i].start_position_m - team_.robots[j].start_position_m).norm(), 2.0 - 1e-9)
          << team_.robots[i].id << " and " << team_.robots[j].id << " start closer than 2 m";
  EXPECT_NE(team_.metrics_base_port, 0) << "the rig's healthchecks and Prometheus need metrics on";
  EXPECT_EQ(team_.transport.scheme, "tcp");
}

TEST_F(RigConfigTest, ComposeRunsEveryServiceUnderTheHostItsPeersConnectTo) {
  const auto services = compose_["services"];
  ASSERT_TRUE(services.IsMap()) << "compose.yaml has no services";
  for (const auto& [robot, kind] : all_services()) {
    const std::string name = container_of(robot, kind);
    SCOPED_TRACE("compose service " + name);
    const auto s = services[name];
    ASSERT_TRUE(s.IsMap()) << "missing";
    // Peers connect to the PUB and ROUTER of this service through this host name.
    const std::string host = host_of(connect_endpoint(team_, robot, kind, SocketRole::kPublish));
    std::set<std::string> names = {name, s["hostname"].as<std::string>(""), s["container_name"].as<std::string>("")};
    if (const auto team_net = s["networks"]; team_net.IsMap() && team_net["team"]["aliases"])
      for (const auto& alias : team_net["team"]["aliases"]) names.insert(alias.as<std::string>());
    EXPECT_TRUE(names.count(host)) << "no container name, hostname or alias '" << host << "'";
    const auto env = s["environment"];
    ASSERT_TRUE(env.IsMap());
    EXPECT_EQ(env["HEXPLORE_CONFIG"].as<std::string>(""), "/etc/hexplore/teams/" + kTeamFile);
    EXPECT_EQ(env["HEXPLORE_SERVICE"].as<std::string>(""), std::string(service_name(kind)));
    if (kind != ServiceKind::kStation) {
      EXPECT_EQ(env["HEXPLORE_ROBOT"].as<std::string>(""), robot);
    }
    EXPECT_EQ(env["HEXPLORE_METRICS_PORT"].as<int>(0), metrics_port(team_, robot, kind))
        << "the healthcheck would probe another port than the exposer binds";
    bool mounts_teams = false, mounts_keys = false;
    for (const auto& v : s["volumes"]) {
      mounts_teams |= v.as<std::string>().rfind("./deploy/teams:/etc/hexplore/teams", 0) == 0;
      mounts_keys |= v.as<std::string>() == "team-keys:/etc/hexplore/teams/keys:ro";
    }
    EXPECT_TRUE(mounts_teams) << "deploy/teams is not mounted at /etc/hexplore/teams";
    EXPECT_TRUE(mounts_keys) << "the team-keys volume is not mounted read-only at /etc/hexplore/teams/keys";
    const auto health = s["healthcheck"];
    ASSERT_TRUE(health.IsMap()) << "no healthcheck";
    for (const char* key : {"test", "interval", "timeout", "retries"}) EXPECT_TRUE(health[key]) << "healthcheck." << key;
    const auto nets = s["networks"];
    const bool on_team = nets.IsMap() ? static_cast<bool>(nets["team"])
                                      : std::any_of(nets.begin(), nets.end(), [](const YAML::Node& n) {
                                          return n.as<std::string>() == "team";
                                        });
    EXPECT_TRUE(on_team) << "not on the team network";
  }
}

TEST_F(RigConfigTest, DependenciesWaitForHealthyServicesThatExist) {
  const auto services = compose_["services"];
  int with_dependencies = 0;
  for (const auto& kv : services) {
    const auto depends = kv.second["depends_on"];
    if (!depends) continue;
    SCOPED_TRACE("compose service " + kv.first.as<std::string>());
    ASSERT_TRUE(depends.IsMap()) << "depends_on must name conditions";
    ++with_dependencies;
    for (const auto& dep : depends) {
      const auto name = dep.first.as<std::string>();
      EXPECT_TRUE(services[name]) << name << " is not a service";
      // The one-shot key maker is waited for until it has finished; services until they are healthy.
      EXPECT_EQ(dep.second["condition"].as<std::string>(""),
                name == "keys" ? "service_completed_successfully" : "service_healthy")
          << name;
    }
  }
  EXPECT_GE(with_dependencies, static_cast<int>(team_.robots.size() * 4 + 1));
  EXPECT_TRUE(services["station"]["depends_on"]) << "the station starts the mission: it must wait for the team";
}

TEST_F(RigConfigTest, AuthenticatedTeamsMakeTheirKeysBeforeAnyServiceStarts) {
  ASSERT_FALSE(team_.transport.curve_keys_dir.empty()) << "the rig's team runs on authenticated links";
  const auto services = compose_["services"];
  const auto keys = services["keys"];
  ASSERT_TRUE(keys.IsMap()) << "no keys service";
  std::string command;
  for (const auto& word : keys["entrypoint"]) command += word.as<std::string>() + " ";
  EXPECT_NE(command.find("hexplore_keys --config /etc/hexplore/teams/multi-building.yaml"), std::string::npos) << command;
  // It writes into the team-keys volume, not into the host's tree: the services' user (uid 10001)
  // cannot write a checkout's folder, and a read-only bind mount needs its nested mount point in
  // the tree (deploy/teams/keys, kept by its README).
  bool writes_volume = false;
  for (const auto& v : keys["volumes"]) writes_volume |= v.as<std::string>() == "team-keys:/etc/hexplore/teams/keys";
  EXPECT_TRUE(writes_volume) << "the keys service does not write the team-keys volume";
  EXPECT_TRUE(std::filesystem::is_directory(kSource + "/deploy/teams/keys"))
      << "deploy/teams/keys (the volume's mount point) is missing from the tree";
  // Every chain starts after it: each robot's sim (its other services wait for their sim) and the station.
  for (const auto& robot : team_.robots)
    EXPECT_TRUE(services[robot.id + "-sim"]["depends_on"]["keys"]) << robot.id << "-sim does not wait for the keys";
  EXPECT_TRUE(services["station"]["depends_on"]["keys"]) << "the station does not wait for the keys";
}

TEST_F(RigConfigTest, ObservabilityIsAnOptInProfile) {
  for (const char* name : {"prometheus", "grafana"}) {
    const auto s = compose_["services"][name];
    ASSERT_TRUE(s.IsMap()) << name;
    ASSERT_TRUE(s["profiles"].IsSequence()) << name;
    EXPECT_EQ(s["profiles"][0].as<std::string>(), "observability") << name;
    EXPECT_TRUE(s["healthcheck"]["interval"]) << name;
  }
  for (const auto& kv : compose_["services"]) {
    const auto name = kv.first.as<std::string>();
    if (name != "prometheus" && name != "grafana") {
      EXPECT_FALSE(kv.second["profiles"]) << name << " must run without a profile";
    }
  }
}

TEST_F(RigConfigTest, PrometheusScrapesEveryServiceAtItsMetricsPort) {
  // target -> (robot, service) labels as configured.
  std::map<std::string, std::pair<std::string, std::string>> targets;
  for (const auto& job : prometheus_["scrape_configs"])
    for (const auto& sc : job["static_configs"])
      for (const auto& t : sc["targets"])
        targets[t.as<std::string>()] = {sc["labels"]["robot"].as<std::string>(""),
                                        sc["labels"]["service"].as<std::string>("")};
  for (const auto& [robot, kind] : all_services()) {
    const std::string target = host_of(connect_endpoint(team_, robot, kind, SocketRole::kPublish)) + ":" +
                               std::to_string(metrics_port(team_, robot, kind));
    SCOPED_TRACE(target);
    ASSERT_TRUE(targets.count(target)) << "deploy/prometheus.yml does not scrape it";
    EXPECT_EQ(targets[target].first, robot);
    EXPECT_EQ(targets[target].second, std::string(service_name(kind)));
    targets.erase(target);
  }
  for (const auto& [t, labels] : targets) ADD_FAILURE() << "deploy/prometheus.yml scrapes unknown target " << t;
}

}  // namespace
}  // namespace hexplore::core
