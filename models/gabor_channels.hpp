#pragma once
// The channels of the Gabor maps (models/gabor_feature_maps.hpp): which frequency and which
// weight column each output map takes. Its own file because both the maps and the numbers
// one evaluation hands its backward (models/gabor_maps_params.hpp) list them.
#include <vector>

namespace ppsynth {

// One output channel: which frequency (-1 = spatial map) and which weight column (-1 = none).
struct GaborChannel {
  int freq = -1;  // 0..8 -> nu = ((freq % 3) - 1, (freq / 3) - 1) * f
  int weight = -1;
};
std::vector<GaborChannel> gabor_channels(int num_attributes, bool spatial_only);

}  // namespace ppsynth
