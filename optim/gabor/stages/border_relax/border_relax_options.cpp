#include "optim/gabor/stages/border_relax/border_relax_options.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace ppsynth {

namespace {
// "auto" on the u x u square: the count the clean-border criterion was measured with
// (docs/lab/large_outputs.md).
constexpr int k_auto_iterations = 60;
constexpr const char* k_key = "method.border_relax";
}  // namespace

// Not in the paper: after each class's sigma stages on the u x u torus, `iterations` more at
// the finest sigma that move only that class's points within `band` mean nearest-neighbor
// spacings (of the output) of the grid's edge, the rest frozen, with the grid rolled by a
// random offset every iteration as "rolled" does: the points the published grid parked on its
// edge go back into the pattern around them (Adam at `lr`, null: the finest sigma's rate). 0
// iterations: the paper's border. `separation`: the weight of the separation point term
// (optim/terms/separation_term.hpp) in the relax stages only, beside any method.terms: across
// the rolled seam the Gabor losses pull a class's close pairs into one point (lemon_4c_v2's
// class 0: docs/lab/large_outputs.md), and the term keeps the exemplar's spacing while the
// sigma stages stay the paper's. 0: off. `parked`: a class is relaxed only when more of its
// points lie within 1 % of the grid's edge (the border band) than `parked` x what
// uniform points put there (1.5: the bound; 0: every class), or when an earlier class
// was relaxed (its pairs with that class across the seam were never measured). Where no class
// parks there is no pile to take apart, and a relax would only spread the band (it keeps the
// band's count): poisson_n64c2_point at the full settings parks nowhere and came out thinner
// at the seam (docs/lab/large_outputs.md). `after`: "all" puts the relaxes after every class's
// sigma stages, which then are the paper's bit for bit as on a one-class exemplar: class by
// class in class order, its band moving, every other point of every class frozen, against the
// targets of all classes. "class" puts each class's relax right after its own sigma stages,
// so the later classes are synthesized beside the relaxed ones: lemon_4c_v2 scored worse so
// (docs/lab/large_outputs.md). One class: the same. `iterations` null or "auto" (the default:
// the clean border, the published one kept as an option): 60 on the u x u square measured as
// one grid (map terms sit its stages out: their maps are the unrolled grid's), 0 where there
// is no fixed grid edge to relax (rectangles take output.border instead; "tiles" and "rolled"
// move the edge). 0: the paper's border, as the shipped configs/runs set it to reproduce the
// paper (configs/paper runs them).
const ParamTable<BorderRelaxOptions>& BorderRelaxOptions::params() {
  using B = BorderRelaxOptions;
  static const ParamTable<B> t(k_key, {
      param("iterations", &B::iterations, "int [0, 1000000000]",
            "relax iterations per class; null or \"auto\": 60 where the u x u grid has an edge, else 0; 0: the paper's border"),
      param("band", &B::band, "(0, inf)", "the points within this many mean spacings of the grid's edge move"),
      param("lr", &B::lr, "(0, inf)", "Adam's rate in the relax stages; null: the finest sigma's"),
      param("separation", &B::separation, "[0, inf)", "the separation term's weight in the relax stages (0: off)"),
      param("parked", &B::parked, "[0, 1000]", "relax a class whose share within 1 % of the edge exceeds this x uniform's (0: always)"),
      choice("after", &B::after_all, {{"class", false}, {"all", true}},
             "the relaxes after each class's own sigma stages, or after every class's"),
  });
  return t;
}

BorderRelaxSettings BorderRelaxSettings::resolve(const BorderRelaxOptions& b, const BorderRelaxContext& where) {
  const bool has_grid_edge = !where.rectangle && where.measured_whole;
  BorderRelaxSettings o;
  o.iterations = b.iterations ? *b.iterations : has_grid_edge ? k_auto_iterations : 0;
  if (where.quick) o.iterations = std::min(o.iterations, where.max_iterations);
  o.band = b.band * where.mean_nn_distance / where.upscale;
  o.lr = b.lr ? *b.lr : 0.0;
  o.parked = b.parked;
  o.separation = b.separation;
  o.after_all = b.after_all;
  if (o.iterations > 0 && where.rectangle)
    throw config_error(k_key, "relaxes the border of the paper's u x u square; a rectangle output "
                              "(output.size or output.points) takes output.border instead");
  if (o.iterations > 0 && !where.measured_whole)
    throw config_error(k_key, "needs method.measure \"grid\" (the other measures have no grid edge to park on)");
  return o;
}

}  // namespace ppsynth
