// Metrics facade: in-memory backend, Prometheus backend, and the /metrics exposer over HTTP.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/metrics/prometheus_registry.h"
#include "common/metrics/registry.h"
#include "common/metrics/standard_families.h"

namespace hexplore::metrics {
namespace {

TEST(NullRegistry, KeepsValuesInMemory) {
  auto registry = make_null_registry();
  Counter* c = registry->counter_family("hexplore_test_total", "help")->add({{"robot", "r1"}});
  c->increment();
  c->increment(2.5);
  EXPECT_DOUBLE_EQ(c->value(), 3.5);
  EXPECT_EQ(registry->counter_family("hexplore_test_total", "help")->add({{"robot", "r1"}}), c);  // same child
  Gauge* g = registry->gauge_family("hexplore_test_gauge", "help")->add({});
  g->set(4);
  g->add(-1);
  EXPECT_DOUBLE_EQ(g->value(), 3);
  Histogram* h = registry->histogram_family("hexplore_test_seconds", "help", latency_buckets_s())->add({});
  h->observe(0.001);
  EXPECT_EQ(h->count(), 1u);
}

TEST(PrometheusRegistry, SerializesFamiliesWithLabels) {
  PrometheusRegistry registry;
  registry.counter_family("hexplore_test_bytes_total", "bytes")->add({{"robot", "r1"}, {"topic", "team/map"}})->increment(7);
  registry.histogram_family("hexplore_test_seconds", "latency", {0.001, 0.01})->add({{"robot", "r1"}})->observe(0.005);
  ProcessMetrics process(registry, "r1", "hlmap");
  process.update();
  const std::string text = registry.serialize();
  EXPECT_NE(text.find("# TYPE hexplore_test_bytes_total counter"), std::string::npos) << text;
  EXPECT_NE(text.find("hexplore_test_bytes_total{robot=\"r1\",topic=\"team/map\"} 7"), std::string::npos);
  EXPECT_NE(text.find("hexplore_test_seconds_bucket{robot=\"r1\",le=\"0.01\"} 1"), std::string::npos);
  EXPECT_NE(text.find("hexplore_process_uptime_seconds{robot=\"r1\",service=\"hlmap\"}"), std::string::npos);
  EXPECT_NE(text.find("hexplore_process_cpu_seconds_total{robot=\"r1\",service=\"hlmap\"}"), std::string::npos);
}

TEST(PrometheusRegistry, ExposesOnAnEphemeralPortOverHttp) {
  PrometheusRegistry registry;
  TransportFamilies::create(registry).sent_bytes->add({{"robot", "r1"}, {"service", "sim"}, {"topic", "team/pose"}, {"peer", "broadcast"}})->increment(123);
  const int port = registry.expose(0, "127.0.0.1");
  ASSERT_GT(port, 0);
  EXPECT_EQ(registry.exposed_port(), port);
  EXPECT_THROW(registry.expose(0, "127.0.0.1"), std::runtime_error);  // one exposer per registry
  const std::string file = ::testing::TempDir() + "/scrape_" + std::to_string(port);
  const std::string command = "curl -s -f -m 5 -o '" + file + "' http://127.0.0.1:" + std::to_string(port) + "/metrics";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(file);
  std::stringstream body;
  body << in.rdbuf();
  std::remove(file.c_str());
  EXPECT_NE(body.str().find("hexplore_transport_sent_bytes_total{peer=\"broadcast\",robot=\"r1\",service=\"sim\",topic=\"team/pose\"} 123"),
            std::string::npos)
      << body.str();
}

TEST(PrometheusRegistry, BadAddressIsAClearError) {
  PrometheusRegistry registry;
  try {
    registry.expose(1, "203.0.113.7");  // not a local address
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("203.0.113.7:1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hexplore::metrics
