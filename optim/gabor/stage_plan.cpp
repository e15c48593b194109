#include "optim/gabor/stage_plan.hpp"

#include <algorithm>

#include "optim/gabor/gabor_pipeline.hpp"

namespace ppsynth {

Vec2 to_output(const StageWindow& w, double u, double v) {
  if (w.torus) return {u, v};
  const Domain& g = w.grid;
  const Domain& m = w.movable;
  return {std::clamp(g.x0 + g.width() * u, m.x0, m.x1), std::clamp(g.y0 + g.height() * v, m.y0, m.y1)};
}

SynthesisPlan class_sigma_plan(const PointSet& exemplar, const GaborSettings& s,
                               const std::vector<std::vector<size_t>>& out_index) {
  SynthesisPlan plan;
  SynthesisPlan relax_after_all;  // method.border_relax.after "all": appended after every class
  const int K = exemplar.num_classes();
  // The neighbor count of a stage whose targets hold `points` exemplar points.
  auto k_for = [&](size_t points) { return s.k_per_stage ? static_cast<int>(std::min<size_t>(s.k, points)) : s.k; };
  for (int st = 0; st < K; ++st) {
    const int cls = s.class_order[st];
    const std::vector<int> active(s.class_order.begin(), s.class_order.begin() + st + 1);
    const size_t active_points = exemplar.subset_classes(active).size();
    std::vector<size_t> frozen;
    for (int j = 0; j < st; ++j) frozen.insert(frozen.end(), out_index[s.class_order[j]].begin(), out_index[s.class_order[j]].end());
    const std::string of_class =
        K > 1 ? "class " + std::to_string(st + 1) + "/" + std::to_string(K) + " (id " + std::to_string(cls) + "), " : std::string();
    for (size_t j = 0; j < s.sigmas.size(); ++j) {
      Stage stage;
      stage.label = of_class + "sigma " + std::to_string(j + 1) + "/" + std::to_string(s.sigmas.size());
      stage.group = st;
      stage.sigma_index = static_cast<int>(j);
      stage.sigma = s.sigmas[j];
      stage.k = k_for(active_points);
      stage.target_classes = active;
      stage.own_class = cls;
      stage.moving = out_index[cls];
      stage.frozen = frozen;
      plan.push_back(stage);
      if (j + 1 == s.sigmas.size() && s.relax_iterations > 0) {  // the finest sigma's settings, the border band only
        stage.label = of_class + "border relax";
        stage.border_relax = true;
        if (!s.relax_after_all || K == 1) {  // one class: after it is after all
          plan.push_back(std::move(stage));
          continue;
        }
        // After every class: a group of its own, beside every other point of every class,
        // measured against the targets of all classes (the last class's stages measure them).
        stage.group = K + st;
        stage.target_classes = s.class_order;
        stage.k = k_for(exemplar.size());
        stage.frozen.clear();
        for (int other : s.class_order)
          if (other != cls) stage.frozen.insert(stage.frozen.end(), out_index[other].begin(), out_index[other].end());
        relax_after_all.push_back(std::move(stage));
      }
    }
  }
  plan.insert(plan.end(), relax_after_all.begin(), relax_after_all.end());
  return plan;
}

}  // namespace ppsynth
