#include "optim/gabor/settings/quick_options.hpp"

namespace ppsynth {

const ParamTable<QuickOptions>& QuickOptions::params() {
  using Q = QuickOptions;
  static const ParamTable<Q> t("method.quick", {
      param("res", &Q::res, "int [8, 8192]", "--quick caps method.grid's resolved res at this"),
      param("channels", &Q::channels, "int [1, 4096]", "--quick caps the filters of a network with a count of them"),
      param("max_iterations", &Q::max_iterations, "int [1, 1000000000]", "--quick caps the iterations per sigma stage"),
      param("num_sigmas", &Q::num_sigmas, "int [1, 64]", "--quick caps the sigma stages"),
  });
  return t;
}

}  // namespace ppsynth
