#pragma once
// method.border_relax, typed: each parameter declared once, here, with its default, its range
// and what --quick does to it. The relax stage (border_relax_stage.hpp) registers with
// defaults() and bounds() as its block method.border_relax, and resolves it.
#include <nlohmann/json.hpp>

namespace ppsynth {

// What the rest of the settings say about where a relax can run: "auto" relaxes where there is
// a fixed grid edge to park on, and a count is refused where there is none.
struct BorderRelaxContext {
  bool rectangle = false;       // a rectangle output (it takes output.border instead)
  bool measured_whole = true;   // method.measure "grid" ("tiles" and "rolled" move the edge)
  bool quick = false;           // --quick caps the count at the sigma stages' max_iterations
  int max_iterations = 0;
  double mean_nn_distance = 0;  // the exemplar's: `band`'s unit on the output of upscale u is this / u
  int upscale = 1;
};

struct BorderRelaxOptions {
  int iterations = 0;       // 0: no relax stage (the paper's border); "auto" resolves to 60 or 0
  double band = 0;          // output units (the block's `band` is in mean nn distances)
  double lr = 0;            // Adam's rate; 0 (null): the finest sigma's
  double parked = 0;        // relax a class whose edge share exceeds parked x uniform's (0: always)
  double separation = 0;    // the separation term's weight in the relax stages
  bool after_all = false;   // "all": after every class's sigma stages; "class": after its own

  static nlohmann::json defaults();
  static nlohmann::json bounds();
  // From the method's border_relax block (defaults merged, bounds checked by the method's
  // registry); errors name method.border_relax.<key>.
  static BorderRelaxOptions resolve(const nlohmann::json& block, const BorderRelaxContext& where);
};

}  // namespace ppsynth
