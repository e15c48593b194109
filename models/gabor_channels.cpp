#include "models/gabor_channels.hpp"

namespace ppsynth {

std::vector<GaborChannel> gabor_channels(int A, bool spatial_only) {
  std::vector<GaborChannel> ch;
  auto add_freqs = [&](int w) {
    if (!spatial_only)
      for (int f = 0; f < 9; ++f) ch.push_back({f, w});
  };
  if (A == 0) {
    ch.push_back({-1, -1});
    add_freqs(-1);
  } else if (A == 1) {
    ch.push_back({-1, 0});
    add_freqs(0);
  } else {
    ch.push_back({-1, -1});
    for (int a = 0; a < A; ++a) {
      if (spatial_only) ch.push_back({-1, a});
      add_freqs(a);
    }
  }
  return ch;
}

}  // namespace ppsynth
