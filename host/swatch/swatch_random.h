#pragma once
//! The one seeded random source of the swatch generators: std::mt19937_64 (whose output sequence
//! the C++ standard fixes) with distributions written here, because std:: distributions differ
//! between standard library versions and would break "same seed, same bytes".

#include <cstdint>
#include <random>

namespace meshquilt {

//! Portable random numbers from a seed; the same seed gives the same sequence everywhere.
class SwatchRandom {
 public:
  explicit SwatchRandom(uint64_t seed) : engine_(seed) {}

  //! Uniform double in [0, 1), from the top 53 bits of one draw.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  //! Uniform double in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  //! Uniform integer in [0, n); n > 0. Rejection sampling, so no modulo bias.
  uint64_t below(uint64_t n) {
    const uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    uint64_t x = engine_();
    while (x >= limit) x = engine_();
    return x % n;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace meshquilt
