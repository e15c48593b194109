#include "optim/gabor_synthesizer.hpp"

#include <chrono>
#include <cmath>

#include "models/point_tensor.hpp"
#include "optim/initializer.hpp"
#include "optim/point_term.hpp"
#include "optim/position_optimizer.hpp"

namespace ppsynth {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The output before optimisation: u^2 points per exemplar point of each class, attributes
// tiled from the class's exemplar points (radius divided by u), positions from the
// initialiser or an explicit initialisation.
PointSet initial_output(const PointSet& ex, const SynthesisContext& ctx, const Initializer& init,
                        std::vector<std::vector<size_t>>& index_of_class) {
  const int u = ctx.upscale, K = ex.num_classes();
  PointSet out(Domain{});
  out.set_class_labels(ex.class_labels());
  for (auto& n : ex.attribute_names()) out.add_attribute(n);
  const auto radius_col = ex.attribute_index("radius");
  index_of_class.assign(K, {});
  for (int c = 0; c < K; ++c) {
    PointSet ex_c = ex.subset_class(c);
    const size_t n = ex_c.size() * static_cast<size_t>(u * u);
    PointSet start;
    if (ctx.initialization) {
      start = ctx.initialization->subset_class(c);
      if (start.size() != n)
        throw InputError("the initialisation has " + std::to_string(start.size()) + " points of class " +
                         std::to_string(c) + "; the synthesis needs " + std::to_string(n));
    } else {
      start = init.initialize(n, c, ctx.seed + 1000003ull * (c + 1));
    }
    for (size_t i = 0; i < n; ++i) {
      auto attrs = ex_c.attributes_of(i % ex_c.size());
      if (radius_col) attrs[*radius_col] /= u;
      index_of_class[c].push_back(out.size());
      out.add(start[i], c, attrs);
    }
  }
  return out;
}

}  // namespace

PointSet GaborSynthesizer::synthesize(const PointSet& exemplar, const SynthesisContext& ctx) {
  validate(exemplar, "exemplar");
  const GaborSettings s = resolve_gabor_settings(p_, exemplar, ctx.upscale, ctx.quick);
  GaborPipeline pipe(p_, s, ctx.seed);
  // The per-class term (s.class_own_weight, not in the paper) needs rasters with the class's
  // own k and targets of the class alone: a second pipeline. Its network is drawn from the
  // same seed as `pipe`'s, so both terms see the same random filters.
  std::unique_ptr<GaborPipeline> own;
  if (s.class_own_weight > 0 && exemplar.num_classes() > 1) own = std::make_unique<GaborPipeline>(p_, s, ctx.seed);
  auto init = InitializerRegistry::instance().create(p_["init"], "method.init");
  auto terms = create_point_terms(p_["terms"]);
  OptimizerRegistry::instance().entry(p_["optimizer"].value("type", ""), "method.optimizer.type");
  const bool fresh_net = p_["fresh_net_per_class"].get<bool>();
  const int K = exemplar.num_classes();
  const int A = static_cast<int>(s.attr_cols.size());

  std::vector<std::vector<size_t>> out_index;
  PointSet out = initial_output(exemplar, ctx, *init, out_index);
  ctx.start(out);

  json stats = {{"grid_res", s.res}, {"output_grid_res", s.upscale * s.res}, {"k", s.k}, {"sigmas", s.sigmas},
                {"mean_nn_distance", s.mean_nn_distance}, {"stages", json::array()},
                {"class_own_weight", s.class_own_weight}, {"terms", json::object()}};
  for (const auto& t : terms) stats["terms"][t.name] = t.weight;
  double t_targets = 0, t_maps = 0, t_net = 0, t_loss = 0, t_backward = 0, t_step = 0;
  std::mt19937_64 jitter_rng(ctx.seed ^ 0x9e3779b97f4a7c15ull);
  const int total_stages = K * static_cast<int>(s.sigmas.size());
  int stage_index = 0;

  for (int st = 0; st < K; ++st) {
    const int cls = s.class_order[st];
    const std::vector<int> active(s.class_order.begin(), s.class_order.begin() + st + 1);
    if (fresh_net && st > 0) pipe.redraw_network(ctx.seed + 7919ull * st);
    const bool own_term = own && st > 0;
    const PointSet ex_active = exemplar.subset_classes(active);
    const int k_stage = s.k_per_stage ? static_cast<int>(std::min<size_t>(s.k, ex_active.size())) : s.k;
    pipe.set_neighbours(k_stage);
    const auto ex_pts = positions_tensor(ex_active);
    const auto ex_w = A > 0 ? normalized_attributes(ex_active, s.attr_cols) : torch::Tensor();

    // Frozen: the earlier classes' output points; moving: this class's. Weights follow the
    // order [frozen..., moving...] and are normalised over that active set.
    std::vector<size_t> frozen_idx;
    for (int j = 0; j < st; ++j) frozen_idx.insert(frozen_idx.end(), out_index[s.class_order[j]].begin(), out_index[s.class_order[j]].end());
    const std::vector<size_t>& moving_idx = out_index[cls];
    std::vector<size_t> active_idx = frozen_idx;
    active_idx.insert(active_idx.end(), moving_idx.begin(), moving_idx.end());
    const auto frozen = positions_tensor(out.subset(frozen_idx));
    const auto out_w = A > 0 ? normalized_attributes(out.subset(active_idx), s.attr_cols) : torch::Tensor();
    auto moving = positions_tensor(out.subset(moving_idx)).set_requires_grad(true);
    for (auto& t : terms) t.term->begin_class(ClassStage{exemplar, out, moving_idx, frozen_idx, s.upscale});
    torch::Tensor own_ex_pts, own_ex_w, own_out_w;
    if (own_term) {
      if (fresh_net) own->redraw_network(ctx.seed + 7919ull * st);
      const PointSet ex_own = exemplar.subset_class(cls);
      own->set_neighbours(s.k_per_stage ? static_cast<int>(std::min<size_t>(s.k, ex_own.size())) : s.k);
      own_ex_pts = positions_tensor(ex_own);
      own_ex_w = A > 0 ? normalized_attributes(ex_own, s.attr_cols) : torch::Tensor();
      own_out_w = A > 0 ? normalized_attributes(out.subset(moving_idx), s.attr_cols) : torch::Tensor();
    }

    for (size_t j = 0; j < s.sigmas.size(); ++j, ++stage_index) {
      const double sigma = s.sigmas[j];
      auto t0 = Clock::now();
      pipe.set_targets(ex_pts, ex_w, sigma);
      if (own_term) own->set_targets(own_ex_pts, own_ex_w, sigma);
      t_targets += since(t0);
      auto optimizer = OptimizerRegistry::instance().create(p_["optimizer"], "method.optimizer", moving, static_cast<int>(j));

      ProgressEvent ev;
      ev.stage = (K > 1 ? "class " + std::to_string(st + 1) + "/" + std::to_string(K) + " (id " + std::to_string(cls) + "), " : std::string()) +
                 "sigma " + std::to_string(j + 1) + "/" + std::to_string(s.sigmas.size());
      ev.stage_index = stage_index;
      ev.stage_count = total_stages;
      ev.max_iterations = s.max_iterations;
      ctx.stage_begin(ev);
      std::vector<double> losses;
      // The paper's loss (+ own term) at the stage's first evaluation: the unit of the
      // point terms, so one weight serves every scene and sigma (optim/point_term.hpp).
      double stage_scale = -1;
      const auto stage_start = Clock::now();
      auto closure = [&]() {
        auto ta = Clock::now();
        const auto mv = wrap_unit(moving);
        const auto jitter = pipe.draw_jitter(jitter_rng);
        auto pts = frozen.size(0) > 0 ? torch::cat({frozen, mv}) : mv;
        auto maps = pipe.output_maps(pts, out_w, sigma, jitter);
        torch::Tensor own_maps;
        if (own_term) own_maps = own->output_maps(mv, own_out_w, sigma, jitter);
        auto tb = Clock::now();
        auto feats = pipe.features(maps);
        Features own_feats;
        if (own_term) own_feats = own->features(own_maps);
        auto tc = Clock::now();
        auto l = pipe.loss(feats);
        if (own_term) l = l + s.class_own_weight * own->loss(own_feats);
        if (!terms.empty() && stage_scale < 0) stage_scale = l.item<double>();
        for (auto& t : terms) l = l + t.weight * stage_scale * t.term->evaluate(mv, frozen);
        auto td = Clock::now();
        l.backward();
        t_maps += std::chrono::duration<double>(tb - ta).count();
        t_net += std::chrono::duration<double>(tc - tb).count();
        t_loss += std::chrono::duration<double>(td - tc).count();
        t_backward += since(td);
        return l;
      };
      int it = 0;
      for (; it < s.max_iterations; ++it) {
        const auto ts = Clock::now();
        const double inner_before = t_maps + t_net + t_loss + t_backward;
        const double lv = optimizer->step(closure);
        t_step += since(ts) - (t_maps + t_net + t_loss + t_backward - inner_before);
        if (!std::isfinite(lv))
          throw InputError("the loss became " + std::to_string(lv) + " at " + ev.stage + ", iteration " + std::to_string(it));
        losses.push_back(lv);
        ev.iteration = it;
        ev.loss = lv;
        ev.seconds = since(stage_start);
        ctx.iteration(ev);
        if (s.rule.converged(losses, it)) {
          ++it;
          break;
        }
      }
      {  // the stage's positions, wrapped, into the output (snapshots and later stages see them)
        torch::NoGradGuard ng;
        auto w = wrap_unit(moving).to(torch::kFloat64);
        auto a = w.accessor<double, 2>();
        for (size_t i = 0; i < moving_idx.size(); ++i) out[moving_idx[i]] = Vec2{a[i][0], a[i][1]};
      }
      ev.iteration = it;
      ev.seconds = since(stage_start);
      stats["stages"].push_back({{"stage", ev.stage}, {"class", cls}, {"sigma", sigma}, {"k", k_stage}, {"iterations", it},
                                 {"final_loss", losses.empty() ? 0.0 : losses.back()}, {"seconds", ev.seconds}});
      ctx.stage_end(ev, out);
    }
  }
  stats["phase_seconds"] = {{"targets", t_targets}, {"maps_forward", t_maps}, {"net_forward", t_net},
                            {"loss_forward", t_loss}, {"backward", t_backward}, {"optimizer_step", t_step}};
  stats["resolved"] = pipe.resolved();
  if (ctx.stats) *ctx.stats = stats;
  return out;
}

}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::MethodRegistry, "gabor", ppsynth::gabor_defaults(),
                 "Huang et al. 2022: Gabor maps + random filters + Gram/correlation losses",
                 [](const ppsynth::json& p) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                   return std::make_unique<ppsynth::GaborSynthesizer>(p);
                 })
