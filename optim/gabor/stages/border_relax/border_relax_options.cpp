#include "optim/gabor/stages/border_relax/border_relax_options.hpp"

#include <algorithm>

#include "core/config/config.hpp"
#include "core/config/param_bounds.hpp"
#include "core/error.hpp"

namespace ppsynth {

namespace {
// "auto" on the u x u square: the count the clean-border criterion was measured with
// (docs/lab/large_outputs.md).
constexpr int k_auto_iterations = 60;
constexpr const char* k_key = "method.border_relax";
}  // namespace

nlohmann::json BorderRelaxOptions::defaults() {
  // Not in the paper: after each class's sigma stages on the u x u torus, `iterations` more
  // at the finest sigma that move only that class's points within `band` mean
  // nearest-neighbor spacings (of the output) of the grid's edge, the rest frozen, with the
  // grid rolled by a random offset every iteration as "rolled" does: the points the
  // published grid parked on its edge go back into the pattern around them (Adam at `lr`,
  // null: the finest sigma's rate). 0 iterations: the paper's border. `separation`: the
  // weight of the separation point term (optim/terms/separation_term.hpp) in the relax stages
  // only, beside any method.terms: across the rolled seam the Gabor losses pull a class's
  // close pairs into one point (lemon_4c_v2's class 0: docs/lab/large_outputs.md), and the
  // term keeps the exemplar's spacing while the sigma stages stay the paper's. 0: off.
  // `parked`: a class is relaxed only when more of its points lie within 1 % of the
  // grid's edge (the border band) than `parked` x what uniform points put there
  // (1.5: the bound; 0: every class), or when an earlier class was relaxed (its
  // pairs with that class across the seam were never measured). Where no class parks
  // there is no pile to take apart, and a relax would only spread the band (it keeps the
  // band's count): poisson_n64c2_point at the full settings parks nowhere and came out
  // thinner at the seam (docs/lab/large_outputs.md). `after`: "all" puts the relaxes after
  // every class's sigma stages, which then are the paper's bit for bit as on a one-class
  // exemplar: class by class in class order, its band moving, every other point of every
  // class frozen, against the targets of all classes. "class" puts each class's relax
  // right after its own sigma stages, so the later classes are synthesized beside the
  // relaxed ones: lemon_4c_v2 scored worse so (docs/lab/large_outputs.md). One class: the same.
  // `iterations` null or "auto" (the default: the clean border, the published one
  // kept as an option): 60 on the u x u square measured as one grid (map terms sit its stages
  // out: their maps are the unrolled grid's), 0 where
  // there is no fixed grid edge to relax (rectangles take output.border instead; "tiles"
  // and "rolled" move the edge). 0: the paper's border, as the shipped configs/runs set it
  // to reproduce the paper (configs/paper runs them).
  return {{"iterations", nullptr}, {"band", 1.0}, {"lr", nullptr}, {"separation", 1.0}, {"parked", 1.5}, {"after", "all"}};
}

nlohmann::json BorderRelaxOptions::bounds() {
  // `iterations` is bounded in resolve(): a bound here would refuse "auto".
  return {{"band", "(0, inf)"}, {"separation", "[0, inf)"}, {"parked", "[0, 1000]"}};
}

BorderRelaxOptions BorderRelaxOptions::resolve(const nlohmann::json& r, const BorderRelaxContext& where) {
  BorderRelaxOptions o;
  const nlohmann::json& iterations = r["iterations"];
  const bool relax_auto = iterations.is_null() || iterations == "auto";
  if (!relax_auto) check_bounds(r, nlohmann::json{{"iterations", "int [0, 1000000000]"}}, k_key);
  const bool has_grid_edge = !where.rectangle && where.measured_whole;
  o.iterations = relax_auto ? (has_grid_edge ? k_auto_iterations : 0) : get_int(r, "iterations", k_key);
  if (where.quick) o.iterations = std::min(o.iterations, where.max_iterations);
  o.band = get_number(r, "band", k_key) * where.mean_nn_distance / where.upscale;
  o.parked = get_number(r, "parked", k_key);
  o.separation = get_number(r, "separation", k_key);
  const nlohmann::json& after = r["after"];
  if (after != "class" && after != "all")
    throw config_error("method.border_relax.after", "expected \"class\" (after each class's sigma stages) or \"all\" "
                                                    "(after every class's), not " + after.dump());
  o.after_all = after == "all";
  const nlohmann::json& lr = r["lr"];
  if (!lr.is_null() && !(lr.is_number() && lr.get<double>() > 0))
    throw config_error("method.border_relax.lr", "expected null (the finest sigma's rate) or a number > 0");
  o.lr = lr.is_null() ? 0.0 : lr.get<double>();
  if (o.iterations > 0 && where.rectangle)
    throw config_error(k_key, "relaxes the border of the paper's u x u square; a rectangle output "
                              "(output.size or output.points) takes output.border instead");
  if (o.iterations > 0 && !where.measured_whole)
    throw config_error(k_key, "needs method.measure \"grid\" (the other measures have no grid edge to park on)");
  return o;
}

}  // namespace ppsynth
