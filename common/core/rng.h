#pragma once
// hexplore's seeded random source. Its draws are written out here rather than taken from the
// std:: distributions (whose algorithms each standard library chooses), so a seed gives the same
// sequence on every machine and on every robot of a team: scenes are bit-identical everywhere,
// and every robot's planner draws what its teammates draw.
//
// Two engines feed the same draws, each kept from when its user was written (changing one would
// change every generated scene or every plan, and with them every recorded figure):
//   SimRng  = SplitMix64, for the simulated world (scene generation, LiDAR noise, sampling);
//   PlanRng = std::mt19937_64 (its sequence is fixed by the standard), for the planners (GA,
//             MNSS, VRP search, test scenes).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace hexplore::core {

inline constexpr uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ull;

// SplitMix64's output function: a 64-bit mix in which every input bit moves every output bit.
inline uint64_t splitmix_finalize(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// SplitMix64 (Steele, Lea, Flood 2014): statistically sound, trivially reproducible.
class SplitMix64 {
 public:
  using result_type = uint64_t;
  explicit SplitMix64(uint64_t seed) : state_(seed ^ kGoldenGamma) {}
  uint64_t operator()() { return splitmix_finalize(state_ += kGoldenGamma); }

 private:
  uint64_t state_;
};

template <typename Engine>
class SeededRng {
 public:
  explicit SeededRng(uint64_t seed) : engine_(seed) {}

  uint64_t next() { return engine_(); }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n); n must be positive. The modulo bias is below 2^-40 for the
  // sizes used here and, unlike std::uniform_int_distribution, identical on every platform.
  uint64_t below(uint64_t n) { return next() % n; }
  int index(size_t n) { return static_cast<int>(below(n)); }
  // Uniform integer in [lo, hi].
  int integer(int lo, int hi) { return lo + static_cast<int>(below(static_cast<uint64_t>(hi - lo + 1))); }
  bool chance(double p) { return uniform() < p; }
  // Standard normal (Box-Muller).
  double normal() {
    const double u1 = std::max(uniform(), 1e-300);
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  // Fisher-Yates over [first, last).
  template <typename T>
  void shuffle(std::vector<T>& v, size_t first, size_t last) {
    for (size_t i = last; i > first + 1; --i) {
      const size_t j = first + below(i - first);
      std::swap(v[i - 1], v[j]);
    }
  }
  template <typename T>
  void shuffle(std::vector<T>& v) {
    shuffle(v, 0, v.size());
  }

 private:
  Engine engine_;
};

using SimRng = SeededRng<SplitMix64>;
using PlanRng = SeededRng<std::mt19937_64>;

// Seeds derived from a base seed and a salt (a round counter, a robot index, a scene number):
// different salts give unrelated sequences, the same (seed, salt) the same one everywhere.
// mix_seed is the planners'; sim_seed, the simulated world's, is the first SimRng draw of
// seed * FNV prime + salt (kept apart because every scene is generated from it).
inline uint64_t mix_seed(uint64_t seed, uint64_t salt) { return splitmix_finalize(seed + kGoldenGamma * (salt + 1)); }
inline uint64_t sim_seed(uint64_t seed, uint64_t salt) { return SimRng(seed * 0x100000001B3ull + salt).next(); }

}  // namespace hexplore::core
