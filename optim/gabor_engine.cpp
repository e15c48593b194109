#include "optim/gabor_engine.hpp"

#include <cmath>
#include <sstream>

#include "models/point_tensor.hpp"
#include "optim/initializer.hpp"

namespace ppsynth {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The output before optimisation: u^2 points per exemplar point of each class, attributes
// tiled from the class's exemplar points (radius divided by u), positions from the
// initialiser or an explicit initialisation.
PointSet initial_output(const PointSet& ex, const SynthesisContext& ctx, const Initializer& init,
                        std::vector<std::vector<size_t>>& index_of_class) {
  const int u = ctx.output.upscale, K = ex.num_classes();
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

std::vector<size_t> concat(const std::vector<size_t>& a, const std::vector<size_t>& b) {
  std::vector<size_t> v = a;
  v.insert(v.end(), b.begin(), b.end());
  return v;
}

}  // namespace

GaborEngine::GaborEngine(const json& params, const PointSet& exemplar, const SynthesisContext& ctx)
    : p_(params), exemplar_(exemplar), ctx_(ctx), jitter_rng_(ctx.seed ^ 0x9e3779b97f4a7c15ull) {
  validate(exemplar, "exemplar");
  s_ = resolve_gabor_settings(p_, exemplar, ctx.output.upscale, ctx.quick);
  pipe_ = std::make_unique<GaborPipeline>(p_, s_, ctx.seed);
  map_terms_ = create_map_terms(p_["map_terms"]);
  for (auto& t : map_terms_) t.term->begin_run(MapTermRun{p_, s_, exemplar, ctx.seed});
  terms_ = create_point_terms(p_["terms"]);
  OptimizerRegistry::instance().entry(p_["optimizer"].value("type", ""), "method.optimizer.type");
  auto init = InitializerRegistry::instance().create(p_["init"], "method.init");
  std::vector<std::vector<size_t>> out_index;
  out_ = initial_output(exemplar, ctx, *init, out_index);
  plan_ = class_sigma_plan(exemplar, s_, out_index);
  stats_ = {{"grid_res", s_.res}, {"output_grid_res", s_.upscale * s_.res}, {"k", s_.k}, {"sigmas", s_.sigmas},
            {"mean_nn_distance", s_.mean_nn_distance},
            {"map_terms", json::object()}, {"terms", json::object()}};
  for (const auto& t : map_terms_) stats_["map_terms"][t.name] = t.weight;
  for (const auto& t : terms_) stats_["terms"][t.name] = t.weight;
}

void GaborEngine::restore(const std::string& bytes) {
  state_ = deserialize_state(bytes, "checkpoint");
  if (state_.positions.size() != out_.size() || state_.stage < 0 || state_.stage > static_cast<int>(plan_.size()) ||
      (state_.moving.defined() && state_.stage < static_cast<int>(plan_.size()) &&
       state_.moving.size(0) != static_cast<int64_t>(plan_[state_.stage].moving.size())))
    throw InputError("the checkpoint does not belong to this synthesis (other exemplar, config or plan)");
  for (size_t i = 0; i < out_.size(); ++i) out_[i] = state_.positions[i];
  std::istringstream rng(state_.rng);
  rng >> jitter_rng_;
  if (!rng) throw InputError("checkpoint: unreadable generator state");
  std::vector<ProgressEvent> earlier;
  for (const auto& r : state_.history) {
    ProgressEvent ev;
    ev.stage = plan_.at(r.stage).label;
    ev.stage_index = r.stage;
    ev.stage_count = static_cast<int>(plan_.size());
    ev.iteration = r.iteration;
    ev.max_iterations = s_.max_iterations;
    ev.loss = r.loss;
    ev.seconds = r.seconds;
    earlier.push_back(ev);
  }
  ctx_.resumed(earlier);
}

PointSet GaborEngine::run() {
  ctx_.start(out_);
  if (ctx_.resume_state) restore(*ctx_.resume_state);
  last_checkpoint_ = Clock::now();
  for (; state_.stage < static_cast<int>(plan_.size());) {
    const Stage& stage = plan_[state_.stage];
    if (stage.group != group_) enter_group(stage);
    enter_stage(stage);
    run_stage(stage);
    finish_stage(stage);
    save_checkpoint();  // every stage boundary, the last one included
  }
  stats_["stages"] = state_.stages;
  stats_["phase_seconds"] = {{"targets", phases_.targets}, {"maps_forward", phases_.maps}, {"net_forward", phases_.net},
                             {"loss_forward", phases_.loss}, {"backward", phases_.backward}, {"optimizer_step", phases_.step}};
  stats_["resolved"] = pipe_->resolved();
  if (ctx_.stats) *ctx_.stats = stats_;
  return out_;
}

void GaborEngine::enter_group(const Stage& stage) {
  group_ = stage.group;
  const bool fresh_net = p_["fresh_net_per_class"].get<bool>();
  if (fresh_net && group_ > 0) pipe_->redraw_network(ctx_.seed + 7919ull * group_);
  const int A = static_cast<int>(s_.attr_cols.size());
  frozen_ = positions_tensor(out_.subset(stage.frozen));
  out_weights_ = A > 0 ? normalized_attributes(out_.subset(concat(stage.frozen, stage.moving)), s_.attr_cols) : torch::Tensor();
  // A group continues one optimisation: its positions come from the checkpoint when resumed
  // inside it, else from the output (wrapped) as the group starts.
  if (!state_.moving.defined()) state_.moving = positions_tensor(out_.subset(stage.moving));
  state_.moving.set_requires_grad(true);
  for (auto& t : terms_) t.term->begin_class(ClassStage{exemplar_, out_, stage.moving, stage.frozen, s_.upscale});
  for (auto& t : map_terms_) t.term->begin_group(stage, out_);
}

void GaborEngine::enter_stage(const Stage& stage) {
  const int A = static_cast<int>(s_.attr_cols.size());
  const auto t0 = Clock::now();
  pipe_->set_neighbours(stage.k);
  const PointSet ex_active = exemplar_.subset_classes(stage.target_classes);
  pipe_->set_targets(positions_tensor(ex_active), A > 0 ? normalized_attributes(ex_active, s_.attr_cols) : torch::Tensor(),
                     stage.sigma);
  for (auto& t : map_terms_) t.term->begin_stage(stage);
  phases_.targets += since(t0);
  optimizer_ = OptimizerRegistry::instance().create(p_["optimizer"], "method.optimizer", state_.moving, stage.sigma_index);
  if (!state_.optimizer.empty()) optimizer_->load_state(state_.optimizer);  // resumed inside the stage
  stage_start_ = Clock::now();
  if (state_.iteration == 0) ctx_.stage_begin(event(stage));
}

ProgressEvent GaborEngine::event(const Stage& stage) const {
  ProgressEvent ev;
  ev.stage = stage.label;
  ev.stage_index = state_.stage;
  ev.stage_count = static_cast<int>(plan_.size());
  ev.iteration = state_.iteration;
  ev.max_iterations = s_.max_iterations;
  ev.seconds = since(stage_start_);
  return ev;
}

torch::Tensor GaborEngine::evaluate(const Stage& stage) {
  const auto ta = Clock::now();
  const auto mv = wrap_unit(state_.moving);
  const auto jitter = pipe_->draw_jitter(jitter_rng_);
  auto pts = frozen_.size(0) > 0 ? torch::cat({frozen_, mv}) : mv;
  auto maps = pipe_->output_maps(pts, out_weights_, stage.sigma, jitter);
  const auto tb = Clock::now();
  auto feats = pipe_->features(maps);
  const auto tc = Clock::now();
  auto l = pipe_->loss(feats);
  for (auto& t : map_terms_) {  // beside the paper's (optim/map_term.hpp); their maps and nets count as loss time
    const auto v = t.term->evaluate(mv, jitter, stage);
    if (v.defined()) l = l + t.weight * v;
  }
  // The paper's loss (+ map terms) at the stage's first evaluation: the unit of the point
  // terms, so one weight serves every scene and sigma (optim/point_term.hpp).
  if (!terms_.empty() && state_.stage_scale < 0) state_.stage_scale = l.item<double>();
  for (auto& t : terms_) l = l + t.weight * state_.stage_scale * t.term->evaluate(mv, frozen_);
  const auto td = Clock::now();
  l.backward();
  phases_.maps += std::chrono::duration<double>(tb - ta).count();
  phases_.net += std::chrono::duration<double>(tc - tb).count();
  phases_.loss += std::chrono::duration<double>(td - tc).count();
  phases_.backward += since(td);
  return l;
}

void GaborEngine::run_stage(const Stage& stage) {
  while (state_.iteration < s_.max_iterations) {
    const int it = state_.iteration;
    const auto ts = Clock::now();
    const double inner_before = phases_.maps + phases_.net + phases_.loss + phases_.backward;
    const double lv = optimizer_->step([&] { return evaluate(stage); });
    phases_.step += since(ts) - (phases_.maps + phases_.net + phases_.loss + phases_.backward - inner_before);
    if (!std::isfinite(lv))
      throw InputError("the loss became " + std::to_string(lv) + " at " + stage.label + ", iteration " + std::to_string(it));
    state_.stage_losses.push_back(lv);
    state_.iteration = it + 1;
    ProgressEvent ev = event(stage);
    ev.iteration = it;
    ev.loss = lv;
    state_.history.push_back({state_.stage, it, lv, ev.seconds});
    ctx_.iteration(ev);
    if (s_.rule.converged(state_.stage_losses, it)) break;
    if (ctx_.stop_requested()) {
      save_checkpoint();
      throw SynthesisInterrupted();
    }
    if (ctx_.save_checkpoint && since(last_checkpoint_) >= ctx_.checkpoint_seconds) save_checkpoint();
  }
}

void GaborEngine::finish_stage(const Stage& stage) {
  {  // the stage's positions, wrapped, into the output (snapshots and later stages see them)
    torch::NoGradGuard ng;
    auto w = wrap_unit(state_.moving).to(torch::kFloat64);
    auto a = w.accessor<double, 2>();
    for (size_t i = 0; i < stage.moving.size(); ++i) out_[stage.moving[i]] = Vec2{a[i][0], a[i][1]};
  }
  ProgressEvent ev = event(stage);
  state_.stages.push_back({{"stage", stage.label}, {"class", stage.own_class}, {"sigma", stage.sigma}, {"k", stage.k},
                           {"iterations", state_.iteration},
                           {"final_loss", state_.stage_losses.empty() ? 0.0 : state_.stage_losses.back()},
                           {"seconds", ev.seconds}});
  ctx_.stage_end(ev, out_);
  // The next stage starts: a fresh optimiser and convergence window; a new group also
  // starts from the wrapped output positions.
  ++state_.stage;
  state_.iteration = 0;
  state_.stage_losses.clear();
  state_.stage_scale = -1;
  state_.optimizer.clear();
  optimizer_.reset();
  if (state_.stage >= static_cast<int>(plan_.size()) || plan_[state_.stage].group != stage.group) state_.moving = torch::Tensor();
}

void GaborEngine::save_checkpoint() {
  last_checkpoint_ = Clock::now();
  if (!ctx_.save_checkpoint) return;
  state_.positions = out_.positions();
  state_.optimizer = optimizer_ ? optimizer_->save_state() : std::string();
  std::ostringstream rng;
  rng << jitter_rng_;
  state_.rng = rng.str();
  ctx_.save_checkpoint(serialize_state(state_));
}

}  // namespace ppsynth
