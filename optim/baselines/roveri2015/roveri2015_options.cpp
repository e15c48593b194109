#include "optim/baselines/roveri2015/roveri2015_options.hpp"

namespace ppsynth::roveri2015 {

const ParamTable<Roveri2015Options>& Roveri2015Options::params() {
  using O = Roveri2015Options;
  using R = RoveriParams;
  static const ParamTable<O> t("method", {
      param("sigma_factor", &O::roveri, &R::sigma_factor, "(0, inf)", "sigma / d_nn (the exemplar's mean nearest-neighbor distance)"),
      param("window_factor", &O::roveri, &R::window_factor, "(0, inf)", "the first window size delta / d_nn"),
      choice("window", &O::roveri, &R::window, {{"box", WindowKind::Box}, {"gaussian", WindowKind::Gaussian}},
             "the window function: the thesis's box, or a Gaussian"),
      param("window_cutoff", &O::roveri, &R::window_cutoff, "(0, inf)", "a Gaussian window ignores points past cutoff x delta"),
      param("pair_cutoff", &O::roveri, &R::pair_cutoff, "(0, inf)", "pairs farther apart than this x sigma are skipped"),
      param("attribute_weight", &O::roveri, &R::attribute_weight, "[0, inf)", "a standardized attribute channel's weight"),
      param("quad_spacing", &O::roveri, &R::quad_spacing, "(0, inf)", "the quadrature grid's spacing / sigma"),
      param("match_restarts", &O::roveri, &R::match_restarts, "int [1, 10000]", "random starts per quadrature point"),
      param("match_iterations", &O::roveri, &R::match_iterations, "int [0, inf)", "descent steps per start"),
      param("aligned_starts", &O::roveri, &R::aligned_starts, "int [0, 10000]", "the best point-aligned offsets added as starts"),
      param("match_step", &O::roveri, &R::match_step, "(0, inf)", "the first matching move / sigma"),
      param("match_margin", &O::roveri, &R::match_margin, "[0, inf)", "a match keeps this x delta inside the exemplar's window"),
      param("merge_iterations", &O::roveri, &R::merge_iterations, "int [0, inf)", "merging descent iterations at most"),
      param("merge_step", &O::roveri, &R::merge_step, "(0, inf)", "the first largest merging move / sigma"),
      param("merge_tolerance", &O::roveri, &R::merge_tolerance, "[0, inf)", "merging stops when the mean move / sigma falls below this"),
      param("attribute_iterations", &O::roveri, &R::attribute_iterations, "int [0, inf)", "gradient steps on the attributes"),
      param("local_global_iterations", &O::roveri, &R::local_global_iterations, "int [1, inf)", "matching + merging rounds per sampling-control round"),
      param("sampling_control_iterations", &O::roveri, &R::sampling_control_iterations, "int [1, inf)", "sampling-control rounds per scale"),
      param("scale_factor", &O::roveri, &R::scale_factor, "(0, 1)", "delta shrinks by this per scale"),
      param("min_window_ratio", &O::roveri, &R::min_window_ratio, "(0, 1]", "stop once delta < this x the first delta"),
      param("sampling_epsilon", &O::roveri, &R::sampling_epsilon, "[0, inf)", "sampling control's |P| threshold"),
      param("candidate_iterations", &O::roveri, &R::candidate_iterations, "int [0, inf)", "gradient steps on a newly added point"),
      param("max_candidate_fraction", &O::roveri, &R::max_candidate_fraction, "[0, 1]", "the share of quadrature points tried per round at most"),
      param("patch_size", &O::roveri, &R::patch_size, "(0, 1]", "the random patch copy's square side / the exemplar's shorter side"),
      param("periodic_output", &O::roveri, &R::periodic_output, "", "synthesize on a torus (else a plain rectangle)"),
      param("quick_scales", &O::quick_scales, "int [1, 64]", "--quick: the scales at most"),
  });
  return t;
}

}  // namespace ppsynth::roveri2015
