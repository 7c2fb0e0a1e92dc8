#include <gtest/gtest.h>

#include "common/core/config_error.h"
#include "common/core/endpoints.h"

namespace hexplore::core {
namespace {

TeamConfig two_robots(const std::string& scheme) {
  auto c = parse_team_config("species: [{builtin: SLUGCAT}]\nrobots: [{id: a, species: SLUGCAT}, {id: b, species: SLUGCAT}]\n"
                             "transport: {scheme: " + scheme + ", host_template: '{robot}-{service}'}\n",
                             "test");
  return c;
}

TEST(Endpoints, TcpPortsAreDistinctPerRobotServiceAndRole) {
  const auto c = two_robots("tcp");
  std::set<int> ports;
  for (const std::string id : {"a", "b", "station"})
    for (int s = 0; s <= 5; ++s)
      for (int r = 0; r <= 1; ++r)
        ports.insert(endpoint_port(c, id, static_cast<ServiceKind>(s), static_cast<SocketRole>(r)));
  EXPECT_EQ(ports.size(), 3u * 6u * 2u);
  EXPECT_EQ(connect_endpoint(c, "b", ServiceKind::kHlmap, SocketRole::kPublish), "tcp://b-hlmap:17024");
  EXPECT_EQ(bind_endpoint(c, "b", ServiceKind::kHlmap, SocketRole::kPublish), "tcp://*:17024");
}

TEST(Endpoints, InprocNamesAreStable) {
  const auto c = two_robots("inproc");
  EXPECT_EQ(connect_endpoint(c, "a", ServiceKind::kMapping, SocketRole::kRequest), "inproc://a-mapping-req");
}

TEST(Endpoints, UnknownRobotIsAConfigError) {
  const auto c = two_robots("tcp");
  EXPECT_THROW(endpoint_port(c, "zz", ServiceKind::kSim, SocketRole::kPublish), ConfigError);
}

TEST(Endpoints, ServiceNamesRoundTrip) {
  for (int s = 0; s <= 5; ++s) {
    const auto kind = static_cast<ServiceKind>(s);
    EXPECT_EQ(service_from_name(service_name(kind)), kind);
  }
  EXPECT_FALSE(service_from_name("nope").has_value());
}

}  // namespace
}  // namespace hexplore::core
