#pragma once
// The planner's random source: a seeded 64-bit Mersenne twister with hand-written draws, so
// the same seed gives the same sequence on every robot and every standard library.

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace hexplore::planning {

class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  // Uniform integer in [0, n); n must be positive. The modulo bias is below 2^-40 for the
  // sizes used here and, unlike std::uniform_int_distribution, identical on every platform.
  uint64_t below(uint64_t n) { return engine_() % n; }
  int index(size_t n) { return static_cast<int>(below(n)); }
  // Uniform double in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  template <typename T>
  void shuffle(std::vector<T>& v, size_t first, size_t last) {
    for (size_t i = last; i > first + 1; --i) {
      size_t j = first + below(i - first);
      std::swap(v[i - 1], v[j]);
    }
  }
  template <typename T>
  void shuffle(std::vector<T>& v) {
    shuffle(v, 0, v.size());
  }

 private:
  std::mt19937_64 engine_;
};

// Mixes a base seed with a round counter (splitmix64), so consecutive rounds draw
// unrelated sequences while every robot with the same (seed, round) draws the same one.
inline uint64_t mix_seed(uint64_t seed, uint64_t salt) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (salt + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace hexplore::planning
