#pragma once
// Fixed filter banks for the Fig. 10 ablation, in place of the random filters.
//   gaussian   : 4 low-pass Gaussians, sigma evenly spaced in [0.5, 2] px
//   sobel      : 4 band-pass Sobel filters (x, y, two diagonals)
//   derivative : 4 high-pass second-derivative filters (xx, yy, xy, Laplacian)
//   all        : the 12 together
// Every filter is applied to every input map (depthwise, groups = C): block l applies the
// bank with stride 2^(l-1) to the maps, then instance norm and ReLU, giving C x B channels
// at full, 1/2 and 1/4 resolution, the same pyramid as the random network.
#include <string>

#include "models/feature_net.hpp"

namespace ppsynth {

// B x 1 x K x K filters of a named bank ("gaussian", "sobel", "derivative", "all"); K odd and
// >= 3. A flaw is a config error naming key_path + ".bank" or ".kernel_size".
torch::Tensor filter_bank(const std::string& name, int kernel_size, const std::string& key_path);

}  // namespace ppsynth
