#include "optim/gabor/settings/quick_options.hpp"

#include "core/config/config.hpp"

namespace ppsynth {

namespace {
constexpr const char* k_key = "method.quick";
}  // namespace

nlohmann::json QuickOptions::defaults() { return {{"res", 24}, {"channels", 8}, {"max_iterations", 4}, {"num_sigmas", 2}}; }

nlohmann::json QuickOptions::bounds() {
  return {{"res", "int [8, 8192]"}, {"channels", "int [1, 4096]"}, {"max_iterations", "int [1, 1000000000]"},
          {"num_sigmas", "int [1, 64]"}};
}

QuickOptions QuickOptions::resolve(const nlohmann::json& block) {
  QuickOptions o;
  o.res = get_int(block, "res", k_key);
  o.channels = get_int(block, "channels", k_key);
  o.max_iterations = get_int(block, "max_iterations", k_key);
  o.num_sigmas = get_int(block, "num_sigmas", k_key);
  return o;
}

}  // namespace ppsynth
