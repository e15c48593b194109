#include "optim/gabor/stages/stage_plan.hpp"

#include <algorithm>

#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/gabor/stages/sigma_stage.hpp"

namespace ppsynth {

SynthesisPlan class_sigma_plan(const PointSet& exemplar, const GaborSettings& s,
                               const std::vector<std::vector<size_t>>& out_index) {
  SynthesisPlan plan;
  SynthesisPlan after_all;  // class-end stages after every class's (border_relax.after "all")
  const int K = exemplar.num_classes();
  const auto sigma_stage = std::make_shared<SigmaStage>();
  const auto torus = std::make_shared<TorusGeometry>();
  const auto class_end = class_end_kinds(s);
  // The neighbor count of a stage whose targets hold `points` exemplar points.
  auto k_for = [&](size_t points) { return s.options.k_per_stage ? static_cast<int>(std::min<size_t>(s.k, points)) : s.k; };
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
      stage.kind = sigma_stage;
      stage.geometry = torus;
      plan.push_back(stage);
      if (j + 1 < s.sigmas.size()) continue;
      int own_groups = 0;  // after-all kinds so far: each takes K groups of its own
      for (const auto& kind : class_end) {  // the finest sigma's settings
        if (!kind->acts_on(K)) continue;
        Stage end = stage;
        end.label = of_class + kind->label();
        end.kind = kind;
        if (!kind->after_all_classes() || K == 1) {  // one class: after it is after all
          plan.push_back(std::move(end));
          continue;
        }
        // After every class: a group of its own, beside every other point of every class,
        // measured against the targets of all classes (the last class's stages measure them).
        end.group = K * ++own_groups + st;
        end.target_classes = s.class_order;
        end.k = k_for(exemplar.size());
        end.frozen.clear();
        for (int other : s.class_order)
          if (other != cls) end.frozen.insert(end.frozen.end(), out_index[other].begin(), out_index[other].end());
        after_all.push_back(std::move(end));
      }
    }
  }
  // Kind by kind (their groups), each over the classes in order: every class's relax ends
  // before any class is revisited.
  std::stable_sort(after_all.begin(), after_all.end(), [](const Stage& a, const Stage& b) { return a.group < b.group; });
  plan.insert(plan.end(), after_all.begin(), after_all.end());
  return plan;
}

}  // namespace ppsynth
