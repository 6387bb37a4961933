// SOFA's pseudo-random generator (sofa::helper::RandomGenerator): the 48-bit
// linear congruential generator of drand48 (multiplier 0x5deece66d, increment
// 0xb), seeded as SOFA seeds it, giving the same sequence on every platform.
// Engines that draw random points (RandomPointDistributionInSurface) use it so
// that a scene with a fixed `randomSeed` gives SOFA's points.
#pragma once

#include <cstdint>

namespace sinew {

class Rand48 {
 public:
  explicit Rand48(long seed = 0) { seed_with(seed); }

  // SOFA's initSeed: low word 0x330e, then the seed's two low 16-bit halves.
  void seed_with(long seed) {
    state_ = (static_cast<std::uint64_t>(static_cast<std::uint16_t>(seed >> 16)) << 32) |
             (static_cast<std::uint64_t>(static_cast<std::uint16_t>(seed)) << 16) | 0x330eu;
  }
  // The next 32 high bits of the state (SOFA's randomBase).
  std::uint32_t next() {
    state_ = (state_ * 0x5deece66dull + 0xbu) & 0xffffffffffffull;
    return static_cast<std::uint32_t>(state_ >> 16);
  }
  // Uniform in [min, max], as SOFA's random<double>(min, max).
  double uniform(double min, double max) {
    return min + (max - min) * (static_cast<double>(next()) / 4294967295.0);
  }

 private:
  std::uint64_t state_ = 0;
};

}  // namespace sinew
