#pragma once
// Spatially indexed random numbers for the PPTBF: the supplement's seeding(p) / seeding2(p)
// / rand(). Every cell and feature point must draw the SAME numbers whichever pixel asks, so
// the generator state is a pure function of (global seed, stream, integer keys): a
// splitmix64 hash seeds a counter-based splitmix64 sequence. (A std::mt19937_64 per cell
// would cost ~2.5 KB of state and ~1 us of seeding per cell per pixel; sequential sampling
// elsewhere in ppsynth does use std::mt19937_64.)
//
// rand() is uniform in [-1, 1) like the GPU implementation's next(); rand01() in [0, 1).
#include <cstdint>

namespace ppsynth::pptbf_impl {

inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

inline std::uint64_t hash_keys(std::uint64_t seed, std::uint64_t stream, std::int64_t a,
                               std::int64_t b = 0, std::int64_t c = 0) {
  std::uint64_t h = mix64(seed ^ 0x5851F42D4C957F2Dull);
  h = mix64(h ^ stream);
  h = mix64(h ^ static_cast<std::uint64_t>(a));
  h = mix64(h ^ static_cast<std::uint64_t>(b));
  return mix64(h ^ static_cast<std::uint64_t>(c));
}

// Streams: independent series at the same location (seeding vs seeding2 of the pseudo-code).
enum Stream : std::uint64_t {
  kStreamTileCutX = 1, kStreamTileCutY = 2, kStreamSubdivide = 3, kStreamJitter = 4,
  kStreamWindow = 5,   // seeding(p): Bezier start angle, J
  kStreamFeature = 6,  // seeding2(p): kernel priority, amplitude, position, angle, sigma
  kStreamNoiseX = 7, kStreamNoiseY = 8,
};

class CellRng {
 public:
  explicit CellRng(std::uint64_t state) : s_(state) {}
  CellRng(std::uint64_t seed, std::uint64_t stream, std::int64_t a, std::int64_t b = 0, std::int64_t c = 0)
      : s_(hash_keys(seed, stream, a, b, c)) {}
  std::uint64_t next_u64() { return mix64(s_ += 0x9E3779B97F4A7C15ull); }
  double rand01() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
  double rand() { return 2.0 * rand01() - 1.0; }

 private:
  std::uint64_t s_;
};

}  // namespace ppsynth::pptbf_impl
