#pragma once
// A random block of TCP ports for a test's team file, so that tests running in parallel rarely
// pick the same one, and never inside the kernel's ephemeral range (32768-60999 on Linux by
// default), where another test's outgoing connection may hold a port at the moment this one
// binds it ("Address already in use": HlmapService.ConvergeWithThirtyPercent..., stop 52).
// 120 blocks of 100 ports from 20000: the highest team (base + robots x ports_per_robot, a few
// dozen ports) still ends below 32100.

#include <random>

namespace hexplore::testing {

inline int random_base_port() {
  std::random_device device;
  return 20000 + static_cast<int>(device() % 120) * 100;
}

}  // namespace hexplore::testing
