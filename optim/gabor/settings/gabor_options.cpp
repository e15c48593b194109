#include "optim/gabor/settings/gabor_options.hpp"

#include "models/gabor_feature_maps.hpp"

namespace ppsynth {

int gabor_maps_default_k() { return GaborMapsOptions{}.k; }

// The published code's settings (method.md §2-5), and what the paper does not have (measure,
// map_terms, terms, the windows) set so that it is the paper's.
const ParamTable<GaborOptions>& GaborOptions::params() {
  using G = GaborOptions;
  using M = G::Measure;
  static const ParamTable<G> t("method", {
      param("c1", &G::c1, "(0, inf)", "the coarsest sigma is d / c1 (d: the exemplar's mean nearest-neighbor distance)"),
      param("c2", &G::c2, "(0, inf)", "the finest sigma is d / c2"),
      param("num_sigmas", &G::num_sigmas, "int [1, 64]", "sigma stages, evenly spaced from the coarsest to the finest"),
      param("k", &G::k, "int [1, 1000000]", "neighbors per grid position: min(M, k)"),
      // M = the exemplar points of the classes in play at a class stage (the published disk and
      // multi-attribute optimizers); false: M = all exemplar points (its point optimizer).
      param("k_per_stage", &G::k_per_stage, "", "M = the exemplar points of the stage's classes (false: all)"),
      param("jitter", &G::jitter, "", "grid positions jittered every iteration"),
      param("max_iterations", &G::max_iterations, "int [1, 1000000000]", "iterations per sigma stage at most"),
      param("class_order", &G::class_order, "int [0, 1000000]", "the order the classes are synthesized in; [] = file order"),
      param("fresh_net_per_class", &G::fresh_net_per_class, "", "a new random network per class group"),
      // "grid" (its whole grid, as published: points park on its border), "tiles" (u x u tiles
      // of the exemplar's size cut at a random offset every iteration, each rasterized and
      // measured as the exemplar is) or "rolled" (the whole grid of the torus rolled by a random
      // offset every iteration: the grid's edge never stays where a point could park on it).
      choice("measure", &G::measure, {{"grid", M::grid}, {"tiles", M::tiles}, {"rolled", M::rolled}},
             "where the losses measure the u x u output: its grid, random tiles, or the grid rolled"),
      param("map_attributes", &G::map_attributes, "", "null or \"auto\": every non-constant attribute; or a list of names ([] = none)"),
      block("grid", &G::grid),
      block("window", &G::window),
      block("quick", &G::quick),
      param("rasterizer", &G::rasterizer, "", "points -> maps (a rasterizer spec)"),
      param("feature_net", &G::feature_net, "", "maps -> features (a feature_net spec)"),
      param("losses", &G::losses, "", "the feature losses and their weights (loss specs)"),
      param("optimizer", &G::optimizer, "", "moves the points (an optimizer spec)"),
      // "loss" (the paper's) or "pattern" (the PCF stops improving): optim/steps/stopping_rule.hpp.
      param("convergence", &G::convergence, "", "when a sigma stage stops before max_iterations (a convergence spec)"),
      param("init", &G::init, "", "the output's first points (an initializer spec)"),
      // Not in the paper (optim/gabor/stages/map_term.hpp).
      param("map_terms", &G::map_terms, "",
            "losses on maps of their own, by registered name; class_own is on (weight 1) unless set to 0, and acts "
            "from a second class on; {\"class_own\": {\"weight\": 0}} = the paper"),
      // Not in the paper (optim/terms/point_term.hpp): {"separation": {"weight": 1}, "pcf_match": {"weight": 10}}.
      param("terms", &G::terms, "", "losses on the positions themselves, by registered name; {} = the paper"),
  });
  return t;
}

const char* measure_name(GaborOptions::Measure m) {
  switch (m) {
    case GaborOptions::Measure::tiles: return "tiles";
    case GaborOptions::Measure::rolled: return "rolled";
    default: return "grid";
  }
}

}  // namespace ppsynth
