#include "optim/baselines/pcf2017/pcf2017_options.hpp"

#include "core/error.hpp"

namespace ppsynth::pcf2017 {

const ParamTable<Pcf2017Options>& Pcf2017Options::params() {
  using O = Pcf2017Options;
  using P = PcfParams;
  using D = DescentOptions;
  static const ParamTable<O> t("method", {
      param("iterations", &O::descent, &D::iterations, "int [0, inf)", "descent iterations at most"),
      param("quick_iterations", &O::quick_iterations, "int [0, inf)", "--quick caps the iterations at this"),
      param("step", &O::descent, &D::step, "(0, inf)", "the first step, in units of r_max"),
      param("max_step", &O::descent, &D::max_step, "(0, inf)", "the largest step, in units of r_max (>= step)"),
      param("grow", &O::descent, &D::grow, "[1, inf)", "an accepted step grows by this"),
      param("line_search_halvings", &O::descent, &D::line_search_halvings, "int [0, 64]", "halvings of a step that raises the energy"),
      param("bins", &O::pcf, &P::bins, "int [2, 100000]", "PCF samples"),
      param("r_a", &O::pcf, &P::r_a, "(0, inf)", "the PCF's least radius, in units of r_max (< r_b)"),
      param("r_b", &O::pcf, &P::r_b, "(0, inf)", "the PCF's largest radius, in units of r_max"),
      param("sigma_factor", &O::pcf, &P::sigma_factor, "(0, inf)", "the kernel's width s / r_max"),
  });
  return t;
}

void Pcf2017Options::check(const std::string& key) const {
  if (!(pcf.r_b > pcf.r_a)) throw config_error(key + ".r_a", "need r_a < r_b");
  if (!(descent.max_step >= descent.step)) throw config_error(key + ".max_step", "must be >= step");
}

}  // namespace ppsynth::pcf2017
