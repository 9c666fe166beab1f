// Seeded random streams: the one utility behind every random draw of the
// library, the benchmarks and the stress tool (noisy batches, rack jitter,
// seeded layouts and breaks).
//
// Reproducibility. A seed gives the same numbers with every compiler and
// standard library: std::mt19937_64's output is specified by the standard
// ([rand.eng.mers], the 10000th value of the default seed is fixed), and the
// uniforms and normals below are built from its bits here rather than by
// std::uniform_real_distribution or std::normal_distribution, whose
// algorithms are left to the implementation.
//
// Streams. splitmix64 (S. Vigna, "An experimental exploration of
// Marsaglia's xorshift generators, scrambled", ACM TOMS 42 (2016), and
// G. Steele, D. Lea, C. Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014) scrambles a seed, so that neighbouring seeds
// (S, S + 1, ...) start unrelated engines; stream_seed(seed, k) gives the
// k-th independent stream of one seed (the break, the noise screen, the
// measurement of one rack draw from different streams).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "cueball/core/vec.hpp"

namespace cueball {

/// SplitMix64's finaliser: a bijection of 64-bit words that scrambles
/// neighbouring seeds into unrelated ones.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The seed of stream `stream` of `seed`: streams of one seed and the same
/// stream of neighbouring seeds are unrelated.
constexpr std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t stream) {
  return splitmix64(splitmix64(seed) ^ (stream * 0x632be59bd9b4e019ULL));
}

/// std::mt19937_64 with uniform and normal draws built from its bits (the
/// header comment). The engine is seeded with `engine_seed` as given: pass
/// splitmix64(seed) or stream_seed(seed, k) for streams of a user's seed.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t engine_seed) : engine_(engine_seed) {}

  /// 64 random bits.
  std::uint64_t bits() { return engine_(); }
  /// Uniform on [0, 1), from the 53 high bits.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform on (0, 1), the midpoints of unit()'s grid (never 0 or 1).
  double open_unit() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  /// Uniform on [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  /// Log-uniform on [lo, hi), 0 < lo < hi.
  double log_uniform(double lo, double hi) { return lo * std::exp(std::log(hi / lo) * unit()); }
  /// A uniform integer in [lo, hi].
  int integer(int lo, int hi) { return lo + static_cast<int>(unit() * static_cast<double>(hi - lo + 1)); }
  /// True with probability p.
  bool chance(double p) { return unit() < p; }
  /// +1 or -1, evenly.
  double sign() { return chance(0.5) ? 1.0 : -1.0; }
  /// Two independent standard normals by the Box-Muller transform
  /// (G. E. P. Box, M. E. Muller, Ann. Math. Statist. 29 (1958) 610-611),
  /// from two open_unit() draws: radius first, then angle.
  Vec2 normal_pair() {
    const double radius = std::sqrt(-2.0 * std::log(open_unit()));
    const double angle = 2.0 * std::numbers::pi * open_unit();
    return {radius * std::cos(angle), radius * std::sin(angle)};
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace cueball
