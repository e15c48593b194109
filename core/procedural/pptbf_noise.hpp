#pragma once
// brownnoise of the supplement (step [1], "Brownian deformation"): a 2-D vector fractal
// value noise used to displace the lookup position, x += ampli[0] * brown(ampli[1]*x*zoom,
// ampli[2]). Four octaves (frequency doubling), octave o weighted by falloff^o, each
// component a smooth (C1, smoothstep) interpolation of hashed lattice values in [-1,1].
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth::pptbf_impl {

// Scalar value noise in [-1,1] at v (lattice spacing 1), stream selects an independent field.
double value_noise(std::uint64_t seed, std::uint64_t stream, double x, double y);
// Vector fBm: (sum_o falloff^o * noise_x(2^o v), same for y), o = 0..3.
Vec2 brownnoise(std::uint64_t seed, Vec2 v, double falloff);

}  // namespace ppsynth::pptbf_impl
