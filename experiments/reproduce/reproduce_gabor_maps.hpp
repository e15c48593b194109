#pragma once
// Paper Fig. 3: what the Gabor transform (Eq. 5) makes of a point pattern.
//   gabor_frequencies.png : the 9 frequency maps (gamma = 1, nu on the 3x3 grid
//                           {-1.5, 0, 1.5}^2) at one sigma (paper: 0.078)
//   gabor_sigmas.png      : the spatial map (gamma = 0) at each of several sigmas
//   gabor_exemplar.png    : the pattern itself
// The maps come from the synthesis's own GaborFeatureMaps module (u = 1, k = min(M, k)),
// unweighted, all classes together. Image rows are flipped so that y points up as in the
// point plots. Frequency maps are signed (diverging color map), spatial maps positive (gray).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

// `maps`: {"sigma", "sigmas", "res", "quick_res", "k", "base_frequency"} (reproduce_config).
// Writes into `dir`; returns (file name relative to `dir`, caption) per image.
std::vector<std::pair<std::string, std::string>> render_gabor_map_figure(const PointSet& exemplar,
                                                                         const nlohmann::json& maps, bool quick,
                                                                         const std::string& dir);

}  // namespace ppsynth
