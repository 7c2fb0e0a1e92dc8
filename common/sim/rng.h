#pragma once
// A small deterministic random source for scene generation and sampling. Unlike the
// std:: distributions its output is fixed by the seed alone (no library-defined algorithm),
// so a scene generated from a seed is bit-identical on every machine.

#include <cmath>
#include <cstdint>

namespace hexplore::sim {

class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed ^ 0x9E3779B97F4A7C15ull) {}

  // SplitMix64: statistically sound, trivially reproducible.
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [lo, hi].
  int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<uint64_t>(hi - lo + 1)); }
  bool chance(double p) { return uniform() < p; }
  // Standard normal (Box-Muller).
  double normal() {
    const double u1 = std::max(uniform(), 1e-300);
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  uint64_t state_;
};

// Mixes several values into one seed (scene seed + robot index + sensor index ...).
inline uint64_t mix_seed(uint64_t a, uint64_t b) {
  Rng r(a * 0x100000001B3ull + b);
  return r.next();
}

}  // namespace hexplore::sim
