#pragma once
// Shared by the codec tests: a team roster, and a malformed-input battery every codec must
// survive (a bad message is counted and dropped by the transport, never a crash).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "common/transport/payload_codec.h"
#include "common/transport/roster.h"

namespace hexplore::radio::testing {

inline transport::Roster roster() {
  return transport::Roster({{"slugcat1", "SLUGCAT"}, {"mr1000a", "MR1000"}, {"slugcat2", "SLUGCAT"}});
}

template <typename M>
std::string encode(const transport::PayloadCodec& codec, const M& message, const transport::Roster* r) {
  std::string out;
  codec.encode(message, r, out);
  return out;
}

template <typename M>
bool decode(const transport::PayloadCodec& codec, std::string_view data, const transport::Roster* r, M& out) {
  out.Clear();
  return codec.decode(data, r, out);
}

// Every truncation must fail; bit flips and random bytes must not crash (they may decode to
// something else, which the receivers' own checks then judge).
template <typename M>
void survives_malformed(const transport::PayloadCodec& codec, const std::string& valid, const transport::Roster* r) {
  M out;
  for (size_t n = 0; n < valid.size(); ++n)
    EXPECT_FALSE(decode(codec, std::string_view(valid).substr(0, n), r, out)) << "truncated to " << n << " bytes";
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    std::string bad = valid;
    bad[rng() % bad.size()] ^= static_cast<char>(1 + rng() % 255);
    (void)decode(codec, bad, r, out);
    std::string noise(rng() % 64, '\0');
    for (char& c : noise) c = static_cast<char>(rng());
    (void)decode(codec, noise, r, out);
  }
  EXPECT_FALSE(decode(codec, valid + std::string("\x01", 1), r, out)) << "trailing byte accepted";
}

}  // namespace hexplore::radio::testing
