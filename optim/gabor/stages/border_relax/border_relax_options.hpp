#pragma once
// method.border_relax, typed: the block as the user writes it (BorderRelaxOptions, each key
// declared once in its table, border_relax_options.cpp), and what the relax stage runs with
// (BorderRelaxSettings: "auto" decided, the band in output units, --quick's cap). The relax
// stage (border_relax_stage.hpp) registers with the table as its block method.border_relax,
// and resolves the block read through it.
#include <optional>

#include "core/config/params.hpp"

namespace ppsynth {

struct BorderRelaxOptions {
  std::optional<int> iterations;  // none ("auto"): 60 where there is a fixed grid edge, else 0
  double band = 1.0;              // mean nearest-neighbor spacings of the output from the grid's edge
  std::optional<double> lr;       // Adam's rate; none: the finest sigma's
  double separation = 1.0;        // the separation term's weight in the relax stages (0: off)
  double parked = 1.5;            // relax a class whose edge share exceeds parked x uniform's (0: always)
  bool after_all = true;          // "all": after every class's sigma stages; "class": after its own

  static const ParamTable<BorderRelaxOptions>& params();
};

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

// The relax as it runs; zeros: no relax.
struct BorderRelaxSettings {
  int iterations = 0;       // 0: no relax stage (the paper's border)
  double band = 0;          // output units
  double lr = 0;            // Adam's rate; 0: the finest sigma's
  double parked = 0;
  double separation = 0;
  bool after_all = false;

  // From the method's border_relax block, read; errors name method.border_relax.
  static BorderRelaxSettings resolve(const BorderRelaxOptions& block, const BorderRelaxContext& where);
};

}  // namespace ppsynth
