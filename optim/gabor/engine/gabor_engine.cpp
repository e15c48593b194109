#include "optim/gabor/engine/gabor_engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "core/checkpoint_file.hpp"
#include "core/process_cpu.hpp"
#include "models/device_capabilities.hpp"
#include "models/gabor_feature_maps.hpp"
#include "models/network_precision.hpp"
#include "models/point_tensor.hpp"
#include "optim/steps/initializer.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/stages/random_tiles.hpp"

namespace ppsynth {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// A canvas's start in blocks of about the paper's output (2 x 2 exemplar units), each
// initialized on its own with its share of the points: the paper's best-candidate start
// grows faster than its point count (m * i candidates for the i-th point, each a nearest
// search), while blocks keep it linear in the area. Only the start: block edges vanish in
// the synthesis.
PointSet initialize_in_blocks(const Initializer& init, size_t n, int cls, uint64_t seed, const Domain& canvas,
                              const SynthesisContext& ctx) {
  const int bx = std::max(1, static_cast<int>(std::lround(canvas.width() / 2))),
            by = std::max(1, static_cast<int>(std::lround(canvas.height() / 2)));
  PointSet all(canvas);
  size_t placed = 0;
  for (int j = 0; j < by; ++j)
    for (int i = 0; i < bx; ++i) {
      const int b = j * bx + i;  // equal blocks: the cumulative share, rounded, sums to n
      const size_t upto = static_cast<size_t>(std::llround(static_cast<double>(n) * (b + 1) / (bx * by)));
      const Domain d{canvas.x0 + canvas.width() * i / bx, canvas.y0 + canvas.height() * j / by,
                     canvas.x0 + canvas.width() * (i + 1) / bx, canvas.y0 + canvas.height() * (j + 1) / by};
      if (upto == placed) continue;
      ctx.poll();
      const PointSet part = init.initialize(upto - placed, cls, seed + 7777777ull * b, d);
      for (size_t k = 0; k < part.size(); ++k) all.add(part[k]);
      placed = upto;
    }
  return all;
}

// The output before optimization: per class, u^2 points per exemplar point (the paper's
// unit square) or the density's count over the canvas (rectangles); attributes tiled from
// the class's exemplar points (radius divided by u on the unit square); positions from the
// initializer or an explicit initialization.
PointSet initial_output(const PointSet& ex, const SynthesisContext& ctx, const Initializer& init,
                        std::vector<std::vector<size_t>>& index_of_class) {
  const OutputShape& shape = ctx.output;
  const int u = shape.upscale, K = ex.num_classes();
  const Domain canvas = shape.canvas(), area = shape.moving_area();
  PointSet out(canvas);
  out.set_class_labels(ex.class_labels());
  for (auto& n : ex.attribute_names()) out.add_attribute(n);
  const auto radius_col = ex.attribute_index("radius");
  const auto counts = shape.class_counts(ex, area);
  index_of_class.assign(K, {});
  if (!ctx.initialization) {
    const auto ex_counts = ex.class_counts();
    size_t total = 0;
    for (int c = 0; c < K; ++c) total += shape.rectangle ? counts[c] : ex_counts[c] * static_cast<size_t>(u * u);
    log_initialization(total, shape.rectangle ? area : canvas);
  }
  for (int c = 0; c < K; ++c) {
    PointSet ex_c = ex.subset_class(c);
    if (ex_c.empty()) continue;
    const size_t n = shape.rectangle ? counts[c] : ex_c.size() * static_cast<size_t>(u * u);
    PointSet start;
    if (ctx.initialization) {
      start = ctx.initialization->subset_class(c);
      if (start.size() != n)
        throw InputError("the initialization has " + std::to_string(start.size()) + " points of class " +
                         std::to_string(c) + "; the synthesis needs " + std::to_string(n));
      check_initialization_inside(start, area, "gabor (class " + std::to_string(c) + ")", "the synthesis domain");
    } else if (!shape.rectangle) {
      start = init.initialize(n, c, ctx.seed + 1000003ull * (c + 1), canvas);
    } else {
      start = initialize_in_blocks(init, n, c, ctx.seed + 1000003ull * (c + 1), area, ctx);
    }
    for (size_t i = 0; i < n; ++i) {
      auto attrs = ex_c.attributes_of(i % ex_c.size());
      if (radius_col && !shape.rectangle) attrs[*radius_col] /= u;
      index_of_class[c].push_back(out.size());
      out.add(start[i], c, attrs);
    }
  }
  return out;
}

// "border": "context": the pad around the rectangle holds copies of the exemplar, tiled from
// the rectangle's corner, appended after the points to synthesize. They never move (final
// from the start): the rectangle's points meet a pattern of the exemplar's own statistics
// at the rectangle's edge instead of an empty border to fill, and the count is exact (a
// cropped padded canvas loses some of its points to its border). Measured, it helps
// only exemplars like lines; on poisson, Tree1 and lemon it is worse than the crop
// (docs/lab/large_outputs.md, "Context borders"), which is why "clean" stays the default.
// The tiles are centered on the rectangle's corner (shifted by half a tile): a pad narrower
// than half the exemplar then shows the exemplar's inside, not the seam of two copies, where
// an exemplar whose points keep off its own border (lines) leaves an empty strip that the
// rectangle's points would move to fill.
void add_exemplar_pad(PointSet& out, const PointSet& ex, const OutputShape& shape) {
  const Domain inner = shape.domain(), E = ex.domain();
  const PointSet tiles = ex.tiled_over(shape.canvas(), Vec2{inner.x0 + 0.5 * E.width(), inner.y0 + 0.5 * E.height()});
  for (size_t i = 0; i < tiles.size(); ++i)
    if (!inner.contains(tiles[i])) out.add(tiles[i], tiles.cls(i), tiles.attributes_of(i));
}

std::vector<size_t> concat(const std::vector<size_t>& a, const std::vector<size_t>& b) {
  std::vector<size_t> v = a;
  v.insert(v.end(), b.begin(), b.end());
  return v;
}

}  // namespace

GaborEngine::GaborEngine(const GaborParams& params, const PointSet& exemplar, const SynthesisContext& ctx)
    : exemplar_(exemplar), shape_(ctx.output), ctx_(ctx), device_(ctx.device),
      jitter_rng_(ctx.seed ^ 0x9e3779b97f4a7c15ull) {
  validate(exemplar, "exemplar");
  s_ = resolve_gabor_settings(params, exemplar, shape_, ctx.quick);
  const GaborOptions& o = s_.options;
  pipe_ = std::make_unique<GaborPipeline>(s_, ctx.seed, device_);
  map_terms_ = create_map_terms(o.map_terms);
  for (auto& t : map_terms_) t.term->begin_run(MapTermRun{s_, exemplar, ctx.seed, device_});
  terms_ = create_point_terms(o.terms);
  rule_ = StoppingRuleRegistry::instance().create(o.convergence, "method.convergence");
  OptimizerRegistry::instance().entry(o.optimizer.value("type", ""), "method.optimizer.type");
  auto init = InitializerRegistry::instance().create(o.init, "method.init");
  init->set_poll([&ctx] { ctx.poll(); });
  std::vector<std::vector<size_t>> out_index;
  out_ = initial_output(exemplar, ctx, *init, out_index);
  pad_begin_ = out_.size();
  if (shape_.exemplar_pad) add_exemplar_pad(out_, exemplar, shape_);
  if (!shape_.rectangle) {
    plan_ = class_sigma_plan(exemplar, s_, out_index);
  } else {
    layout_ = window_layout(shape_.canvas(), shape_.moving_area(), s_.window, s_.window_margin, 3 * s_.sigmas.front());
    plan_ = window_plan(exemplar, s_, layout_);
    state_.final_points.assign(out_.size(), 0);
    std::fill(state_.final_points.begin() + static_cast<std::ptrdiff_t>(pad_begin_), state_.final_points.end(), 1);
  }
  for (const Stage& stage : plan_)
    if (std::find(kinds_.begin(), kinds_.end(), stage.kind) == kinds_.end()) kinds_.push_back(stage.kind);
  stats_.grid_res = s_.res;
  stats_.output_grid_res = s_.out_res;
  stats_.output_grid_rows = s_.out_rows;
  stats_.grid_res_per_sigma = s_.sigma_res;
  stats_.output_grid_res_per_sigma = s_.sigma_out_res;
  stats_.output_grid_rows_per_sigma = s_.sigma_out_rows;
  stats_.k = s_.k;
  stats_.sigmas = s_.sigmas;
  stats_.mean_nn_distance = s_.mean_nn_distance;
  stats_.runtime = runtime_record();
  if (shape_.rectangle) {
    const Domain c = shape_.canvas();
    stats_.rectangle = GaborRectangle{
        {shape_.describe(), {c.x0, c.y0, c.x1, c.y1}, out_.size()},
        out_.size() - pad_begin_,
        {layout_.nx, layout_.ny, layout_.size.width, layout_.size.height, layout_.margin, s_.out_res, s_.out_rows}};
  }
  for (const auto& t : map_terms_) stats_.map_terms[t.name] = t.weight;
  for (const auto& t : terms_) stats_.terms[t.name] = t.weight;
  for (const auto& kind : kinds_) kind->describe(stats_.kinds);
}

void GaborEngine::restore(const std::string& bytes) {
  const std::string& source = ctx_.resume_source;
  state_ = deserialize_state(bytes, source);
  if (!ctx_.checkpoint_key.is_null())
    if (const std::string differs = checkpoint_key_difference(ctx_.checkpoint_key, state_.key); !differs.empty())
      throw checkpoint_error(source, "made for another synthesis: " + differs);
  check_restored(source);
  for (size_t i = 0; i < out_.size(); ++i) out_[i] = state_.positions[i];
  // The time and phases of the processes before this one (0 in checkpoints without them).
  const json& ph = state_.phase_seconds;
  seconds_before_ = ph.value("wall", 0.0);
  cpu_before_ = ph.contains("cpu") ? ph["cpu"].get<double>() : -1;  // a checkpoint from before it was kept: unknown
  phases_ = GaborPhaseSeconds{ph.value("targets", 0.0),      ph.value("maps_forward", 0.0), ph.value("net_forward", 0.0),
                              ph.value("loss_forward", 0.0), ph.value("backward", 0.0),     ph.value("optimizer_step", 0.0)};
  std::istringstream rng(state_.rng);
  rng >> jitter_rng_;
  if (!rng) throw checkpoint_error(source, "an unreadable generator state");
  std::vector<ProgressEvent> earlier;
  for (const auto& r : state_.history) {
    ProgressEvent ev;
    ev.stage = plan_[r.stage].label;
    ev.stage_index = r.stage;
    ev.stage_count = static_cast<int>(plan_.size());
    ev.iteration = r.iteration;
    ev.max_iterations = iteration_cap(plan_[r.stage]);
    ev.loss = r.loss;
    ev.seconds = r.seconds;
    ev.window = plan_[r.stage].geometry->index();
    ev.windows = plan_[r.stage].geometry->count();
    earlier.push_back(ev);
  }
  ctx_.resumed(earlier);
}

void GaborEngine::check_restored(const std::string& source) const {
  auto refuse = [&](const std::string& what) {
    return checkpoint_error(source, what + " (a damaged checkpoint, or one of another synthesis)");
  };
  const SynthesisState& s = state_;
  const size_t n = out_.size();
  const int stages = static_cast<int>(plan_.size());
  if (s.positions.size() != n)
    throw refuse("it holds " + std::to_string(s.positions.size()) + " points; this synthesis has " + std::to_string(n));
  const Domain area = shape_.canvas();
  const double slack = 1e-6 * std::max(area.width(), area.height());  // float positions mapped back
  for (size_t i = 0; i < n; ++i)
    if (!area.contains(s.positions[i], slack)) throw refuse("point " + std::to_string(i) + " lies outside the synthesis domain");
  if (s.stage > stages) throw refuse("stage " + std::to_string(s.stage) + " of a plan of " + std::to_string(stages));
  if (s.stages.size() != static_cast<size_t>(s.stage))
    throw refuse(std::to_string(s.stages.size()) + " finished stages recorded at stage " + std::to_string(s.stage));
  const int cap = s.stage < stages ? iteration_cap(plan_[s.stage]) : 0;
  if (s.iteration > cap) throw refuse("iteration " + std::to_string(s.iteration) + " of a stage of " + std::to_string(cap));
  if (s.stage_losses.size() != static_cast<size_t>(s.iteration))
    throw refuse(std::to_string(s.stage_losses.size()) + " losses recorded at iteration " + std::to_string(s.iteration));
  if (!(s.stage_scale == -1 || s.stage_scale >= 0)) throw refuse("a negative loss scale");
  for (const auto& r : s.history)
    if (r.stage > s.stage || r.stage >= stages || r.iteration >= iteration_cap(plan_[r.stage]))
      throw refuse("a loss recorded at stage " + std::to_string(r.stage) + ", iteration " + std::to_string(r.iteration));
  // Each finished stage's record is its stage's: the engine's fields, then its kind's (the
  // checkpoint's reader keeps them as they are).
  for (size_t i = 0; i < s.stages.size(); ++i) {
    const json& d = s.stages[i].details;
    const std::string which = "stage record " + std::to_string(i) + ": ";
    for (const char* k : {"class", "k"})
      if (!d.contains(k) || !d[k].is_number_integer()) throw refuse(which + "'" + k + "' is not a whole number");
    if (!d.contains("sigma") || !d["sigma"].is_number()) throw refuse(which + "'sigma' is not a number");
    if (const std::string problem = plan_[i].kind->record_problem(d); !problem.empty()) throw refuse(which + problem);
  }
  if (s.final_points.size() != (shape_.rectangle ? n : 0)) throw refuse("final flags for another number of points");
  for (uint8_t f : s.final_points)
    if (f > 1) throw refuse("a final flag that is neither 0 nor 1");
  if (!s.moving.defined()) {
    if (s.stage_best.defined() || !s.optimizer.empty()) throw refuse("an optimizer state or best iterate without positions");
    return;
  }
  if (s.stage >= stages) throw refuse("moving positions after the last stage");
  const Stage& stage = plan_[s.stage];
  if (s.moving.size(0) != static_cast<int64_t>(s.group_moving.size()))
    throw refuse(std::to_string(s.moving.size(0)) + " moving positions for " + std::to_string(s.group_moving.size()) + " moving points");
  if (s.stage_best.defined() && s.stage_best.sizes() != s.moving.sizes()) throw refuse("a best iterate of another shape");
  // The group's points: indices into the output, each once, of the stage's classes (its own
  // class moves); the paper's plan names them itself.
  std::vector<char> seen(n, 0);
  auto check_points = [&](const std::vector<int64_t>& idx, bool moving) {
    for (int64_t i : idx) {
      if (i < 0 || static_cast<size_t>(i) >= n) throw refuse("point index " + std::to_string(i) + " of " + std::to_string(n));
      if (seen[i]++) throw refuse("point " + std::to_string(i) + " twice in its group");
      const int c = out_.cls(static_cast<size_t>(i));
      const bool ok = moving && stage.own_class >= 0 ? c == stage.own_class
                             : std::find(stage.target_classes.begin(), stage.target_classes.end(), c) != stage.target_classes.end();
      if (!ok) throw refuse("point " + std::to_string(i) + " (class " + std::to_string(c) + ") is not of " + stage.label);
    }
  };
  check_points(s.group_moving, true);
  check_points(s.group_frozen, false);
  if (const std::string problem = stage.geometry->restored_points_problem(stage, s.group_moving, s.group_frozen); !problem.empty())
    throw refuse(problem);
}

PointSet GaborEngine::synthesized() const {
  std::vector<size_t> idx(pad_begin_);
  std::iota(idx.begin(), idx.end(), size_t{0});
  PointSet p = out_.subset(idx);
  p.set_domain(shape_.moving_area());
  return p;
}

GaborRuntime GaborEngine::runtime_record() const {
  const bool cuda = device_.is_cuda();
  // "auto" as the device resolves it (models/network_precision.hpp)
  const std::string net = resolve_network_precision(s_.feature_net.value("precision", "float32"), "method.feature_net.precision").name;
  GaborRuntime r;
  r.device = device_.str();
  // the network's arithmetic: bfloat16 as the net asks, else float32, on TF32 tensor cores where runtime.tf32 applies
  r.precision = net != "float32" ? net : (cuda && ctx_.tf32 ? "tf32" : "float32");
  r.deterministic = cuda ? ctx_.deterministic : true;
  // what the device decided and why (optim/run/runtime.hpp's decide_device_settings)
  if (cuda) r.choices = json::parse(synthesis_device().choices);
  const std::string rasterizer = s_.options.rasterizer.value("type", "");
  if (rasterizer == "gabor" || rasterizer == "spatial")
    r.gabor_maps = gabor_maps_path_name(gabor_maps_path(GaborMapsPath::automatic, device_));
  return r;
}

PointSet GaborEngine::run() {
  run_start_ = Clock::now();
  cpu_at_start_ = process_cpu_seconds();
  // The start as `--init` takes it back: a frozen exemplar pad is not part of it.
  ctx_.start(shape_.exemplar_pad ? synthesized() : out_);
  if (ctx_.resume_state) restore(*ctx_.resume_state);
  last_checkpoint_ = Clock::now();
  for (; state_.stage < static_cast<int>(plan_.size());) {
    ctx_.poll();  // a stop between stages (a window's set-up, its empty stages) goes back to the last checkpoint
    const Stage& stage = plan_[state_.stage];
    if (stage.group != group_) enter_group(stage);
    if (moving_idx_.empty()) {  // a window without points of this class left to move
      stage_start_ = Clock::now();
      finish_stage(stage);
      continue;
    }
    enter_stage(stage);
    run_stage(stage);
    finish_stage(stage);
    save_checkpoint();  // every stage boundary, the last one included
  }
  stats_.phase_seconds = phases_;
  const json resolved = pipe_->resolved();
  stats_.resolved = GaborResolved{resolved["rasterizer"], resolved["feature_net"], resolved["losses"]};
  if (ctx_.stats) *ctx_.stats = to_json(stats_);
  if (ctx_.stages) *ctx_.stages = StagesReport{state_.stages, seconds_before_, cpu_before_};
  if (!shape_.rectangle) return out_;
  // "context": the synthesized points, all inside the rectangle (the pad is the exemplar's).
  // "clean": the canvas's border band (the pad) holds the points that parked on its border.
  PointSet out = shape_.exemplar_pad ? synthesized() : out_.crop(shape_.domain());
  out.set_domain(shape_.domain());
  return out;
}

void GaborEngine::enter_group(const Stage& stage) {
  group_ = stage.group;
  geometry_ = stage.geometry;
  const int K = exemplar_.num_classes(), class_step = group_ % K;  // window plans: a multiple of K groups per window
  if (s_.options.fresh_net_per_class && group_ > 0)
    pipe_->redraw_network(class_network_seed(ctx_.seed, class_step));
  // A group continues one optimization: its points and positions come from the checkpoint
  // when resumed inside it, else from the plan (or the window's choice) and the output.
  const bool fresh = !state_.moving.defined();
  if (fresh)
    geometry_->choose_points(stage, out_, state_.final_points, [this] { ctx_.poll(); }, state_.group_moving,
                             state_.group_frozen);
  moving_idx_.assign(state_.group_moving.begin(), state_.group_moving.end());
  frozen_idx_.assign(state_.group_frozen.begin(), state_.group_frozen.end());
  // The group's tensors go to the device once, here (and back at the stage's end).
  frozen_ = geometry_->to_local(out_.subset(frozen_idx_)).to(device_);
  out_weights_ = s_.attr_cols.empty() ? torch::Tensor()
                                      : map_weights(concat(frozen_idx_, moving_idx_), stage.target_classes).to(device_);
  // Fresh: from the output; resumed: the checkpoint's (read on the CPU).
  state_.moving = (fresh ? geometry_->to_local(out_.subset(moving_idx_)) : state_.moving).to(device_);
  if (state_.stage_best.defined()) state_.stage_best = state_.stage_best.to(device_);
  state_.moving.set_requires_grad(true);
  measured_.clear();
  if (s_.statistics_in_output) measured_ = geometry_->part_inside(shape_.domain());
  const ClassStage class_stage{exemplar_, out_, moving_idx_, frozen_idx_, s_.upscale, device_,
                               geometry_->periodic() ? 0.0 : geometry_->grid().width()};
  for (auto& t : terms_) t.term->begin_class(class_stage);
  for (auto& kind : kinds_)
    for (auto& t : kind->terms()) t.term->begin_class(class_stage);
  for (auto& t : map_terms_) t.term->begin_group(MapTermGroup{stage, out_, moving_idx_, frozen_idx_, frozen_, measured_});
}

torch::Tensor GaborEngine::map_weights(const std::vector<size_t>& rows, const std::vector<int>& classes) const {
  // Each column divided by its maximum over every output point of the stage's classes (the
  // paper's plan: exactly `rows`; a window sees only part of them, the scale stays global).
  std::vector<char> in_play(exemplar_.num_classes(), 0);
  for (int c : classes) in_play[c] = 1;
  const int64_t n = static_cast<int64_t>(rows.size()), A = static_cast<int64_t>(s_.attr_cols.size());
  auto w = torch::ones({n, A}, torch::kFloat64);
  auto acc = w.accessor<double, 2>();
  for (int64_t a = 0; a < A; ++a) {
    const auto& col = out_.attribute_column(s_.attr_cols[a]);
    double mx = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < out_.size(); ++i)
      if (in_play[out_.cls(i)]) mx = std::max(mx, col[i]);
    if (!(mx > 0)) continue;
    for (int64_t r = 0; r < n; ++r) acc[r][a] = col[rows[r]] / mx;
  }
  return w.to(torch::kFloat32);
}

void GaborEngine::enter_stage(const Stage& stage) {
  const int A = static_cast<int>(s_.attr_cols.size());
  const auto t0 = Clock::now();
  pipe_->set_neighbors(stage.k);
  pipe_->set_grid(stage.sigma_index);
  const PointSet ex_active = exemplar_.subset_classes(stage.target_classes);
  pipe_->set_targets(positions_tensor(ex_active), A > 0 ? normalized_attributes(ex_active, s_.attr_cols) : torch::Tensor(),
                     stage.sigma);
  rule_->begin_stage(ex_active, stage.own_class);
  for (auto& t : map_terms_) t.term->begin_stage(stage);
  phases_.targets += since(t0);
  start_ = stage.kind->start(StageStartView{stage, s_, out_, moving_idx_, state_.stages});
  if (start_.moving_mask.defined()) start_.moving_mask = start_.moving_mask.to(device_);
  optimizer_ = OptimizerRegistry::instance().create(stage.kind->optimizer(s_.options.optimizer, s_), "method.optimizer",
                                                    state_.moving, stage.sigma_index);
  if (!state_.optimizer.empty()) optimizer_->load_state(state_.optimizer, ctx_.resume_source);  // resumed inside the stage
  stage_start_ = Clock::now();
  // Resumed inside the stage: its clock goes on from the last iteration recorded before.
  if (state_.iteration > 0 && !state_.history.empty() && state_.history.back().stage == state_.stage)
    stage_start_ -= std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(state_.history.back().seconds));
  if (state_.iteration == 0) {
    ProgressEvent begin = event(stage);
    begin.note = start_.note;  // why the stage moves what it moves, where the user watches
    ctx_.stage_begin(begin);
  }
}

int GaborEngine::iteration_cap(const Stage& stage) const { return stage.kind->iteration_cap(s_); }

ProgressEvent GaborEngine::event(const Stage& stage) const {
  ProgressEvent ev;
  ev.stage = stage.label;
  ev.stage_index = state_.stage;
  ev.stage_count = static_cast<int>(plan_.size());
  ev.iteration = state_.iteration;
  ev.max_iterations = iteration_cap(stage);
  ev.seconds = since(stage_start_);
  ev.window = stage.geometry->index();
  ev.windows = stage.geometry->count();
  ev.window_grid = stage.geometry->grid();
  const size_t next = static_cast<size_t>(state_.stage) + 1;
  ev.window_ends = ev.windows <= 1 || next >= plan_.size() || plan_[next].geometry->index() != ev.window;
  return ev;
}

torch::Tensor GaborEngine::measure(const torch::Tensor& points, const torch::Tensor& weights, const torch::Tensor& jitter,
                                   const Stage& stage, bool tile) {
  const auto ta = Clock::now();
  auto maps = tile ? pipe_->tile_maps(points, weights, stage.sigma, jitter) : pipe_->output_maps(points, weights, stage.sigma, jitter);
  const auto tb = Clock::now();
  auto feats = measured_part(pipe_->features(maps), measured_);
  const auto tc = Clock::now();
  auto l = pipe_->loss(feats);
  phases_.maps_forward += std::chrono::duration<double>(tb - ta).count();
  phases_.net_forward += std::chrono::duration<double>(tc - tb).count();
  phases_.loss_forward += since(tc);
  return l;
}

torch::Tensor GaborEngine::evaluate(const Stage& stage) {
  const torch::Tensor& mask = start_.moving_mask;
  const auto mv = geometry_->confine(mask.defined() ? torch::where(mask, state_.moving, state_.moving.detach()) : state_.moving);
  auto pts = frozen_.size(0) > 0 ? torch::cat({frozen_, mv}) : mv;
  torch::Tensor l, jitter;
  if (s_.measure_tiles()) {  // the mean over the tiles of the cut (optim/gabor/stages/random_tiles.hpp)
    const int u = s_.upscale;
    const auto tiles = cut_into_tiles(pts, u, tile_offset(ctx_.seed, state_.stage, state_.iteration, u));
    for (const auto& t : tiles) {
      const auto w = out_weights_.defined() ? out_weights_.index_select(0, t.rows) : torch::Tensor();
      const auto v = measure(t.local, w, pipe_->draw_jitter(jitter_rng_, true), stage, true) / static_cast<double>(u * u);
      l = l.defined() ? l + v : v;
    }
  } else {
    if (s_.options.measure == GaborOptions::Measure::rolled || stage.kind->rolls_grid())
      pts = roll_torus(pts, tile_offset(ctx_.seed, state_.stage, state_.iteration, 1));
    jitter = pipe_->draw_jitter(jitter_rng_);
    l = measure(pts, out_weights_, jitter, stage, false);
  }
  const auto tc = Clock::now();
  // Beside the paper's (optim/gabor/stages/map_term.hpp); their maps and nets count as loss
  // time. Their maps are the unrolled grid's: a stage that rolls the grid (the border relax)
  // leaves them out.
  if (!stage.kind->rolls_grid())
    for (auto& t : map_terms_) {
      const auto v = t.term->evaluate(mv, jitter, stage);
      if (v.defined()) l = l + t.weight * v;
    }
  // The paper's loss (+ map terms) at the stage's first evaluation: the unit of the point
  // terms, so one weight serves every scene and sigma (optim/terms/point_term.hpp).
  auto& own_terms = stage.kind->terms();  // the stage kind's, beside the run's
  if ((!terms_.empty() || !own_terms.empty()) && state_.stage_scale < 0) state_.stage_scale = l.item<double>();
  for (auto& t : terms_) l = l + t.weight * state_.stage_scale * t.term->evaluate(mv, frozen_);
  for (auto& t : own_terms) l = l + t.weight * state_.stage_scale * t.term->evaluate(mv, frozen_);
  const auto td = Clock::now();
  l.backward();
  phases_.loss_forward += std::chrono::duration<double>(td - tc).count();
  phases_.backward += since(td);
  return l;
}

void GaborEngine::run_stage(const Stage& stage) {
  // The rule's verdict on the points as they are after iteration `it`; a new best is kept
  // (optim/steps/stopping_rule.hpp). True: the stage has converged.
  auto judge = [&](int it) {
    const StopVerdict v =
        rule_->judge(StageView{state_.stage_losses, it, [this] { return points_in_play(); }, geometry_->periodic(),
                               geometry_->periodic() ? 1.0 / s_.upscale : 1.0},
                     state_.stage_watch);
    if (v.best) state_.stage_best = state_.moving.detach().clone();
    return v.stop;
  };
  // A kind that is not judged (the border relax: its pattern is the finished stage's, judged
  // already) runs its fixed count.
  const bool judged = stage.kind->judged();
  // A stage whose kind moves no point (a relax whose class does not park, or none near the
  // edge) ends at once: its iterations would leave every point where it is.
  if (start_.moving_mask.defined() && !start_.moving_mask.any().item<bool>()) return;
  if (judged && state_.iteration == 0) judge(-1);  // the stage's start, a candidate to end on (a stop there is ignored)
  while (state_.iteration < iteration_cap(stage)) {
    const int it = state_.iteration;
    const auto ts = Clock::now();
    const double inner_before = phases_.maps_forward + phases_.net_forward + phases_.loss_forward + phases_.backward;
    const double lv = optimizer_->step([&] { return evaluate(stage); });
    phases_.optimizer_step += since(ts) - (phases_.maps_forward + phases_.net_forward + phases_.loss_forward + phases_.backward - inner_before);
    if (!std::isfinite(lv))
      throw InputError("the loss became " + std::to_string(lv) + " at " + stage.label + ", iteration " + std::to_string(it));
    state_.stage_losses.push_back(lv);
    state_.iteration = it + 1;
    ProgressEvent ev = event(stage);
    ev.iteration = it;
    ev.loss = lv;
    state_.history.push_back({state_.stage, it, lv, ev.seconds});
    ctx_.iteration(ev);
    if (judged && judge(it)) break;
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
    // A rule that keeps the stage's best iterate: the stage ends there (the group's next
    // stage starts from it too, as `moving` is the tensor it goes on with).
    if (state_.stage_best.defined()) state_.moving.copy_(state_.stage_best);
    auto w = geometry_->confine(state_.moving).to(torch::kCPU, torch::kFloat64);
    auto a = w.accessor<double, 2>();
    for (size_t i = 0; i < moving_idx_.size(); ++i) out_[moving_idx_[i]] = geometry_->to_output(a[i][0], a[i][1]);
  }
  ProgressEvent ev = event(stage);
  StageRecord record{stage.label, state_.iteration, state_.stage_losses.empty() ? 0.0 : state_.stage_losses.back(), ev.seconds,
                     {{"class", stage.own_class}, {"sigma", stage.sigma}, {"k", stage.k}}};
  record.details.update(start_.record);  // what the kind decided (the relax: its share, relaxed or not)
  if (stage.kind->judged()) {              // what the stopping rule saw (a stage that ran, judged)
    nlohmann::json seen = rule_->summary(state_.stage_watch);
    if (!seen.empty() && state_.iteration > 0) record.details["stopping_rule"] = std::move(seen);
  }
  state_.stages.push_back(std::move(record));
  ctx_.stage_end(ev, out_);
  // The next stage starts: a fresh optimizer and convergence window; a new group also
  // starts from the wrapped output positions.
  ++state_.stage;
  state_.iteration = 0;
  state_.stage_losses.clear();
  state_.stage_watch.clear();
  state_.stage_best = torch::Tensor();
  state_.stage_scale = -1;
  state_.optimizer.clear();
  optimizer_.reset();
  start_ = StageStart();
  const bool last = state_.stage >= static_cast<int>(plan_.size());
  if (last || plan_[state_.stage].group != stage.group) state_.moving = torch::Tensor();
  if (last || plan_[state_.stage].geometry != stage.geometry) geometry_->stages_done(out_, state_.final_points);
  if (ev.window_ends) geometry_->window_done();
}

PointSet GaborEngine::points_in_play() const {
  torch::NoGradGuard ng;
  const auto mv = geometry_->confine(state_.moving);
  const auto local = (frozen_.size(0) > 0 ? torch::cat({frozen_, mv}) : mv).to(torch::kCPU, torch::kFloat64);
  std::vector<int> classes;
  classes.reserve(frozen_idx_.size() + moving_idx_.size());
  for (const auto i : frozen_idx_) classes.push_back(out_.cls(static_cast<size_t>(i)));
  for (const auto i : moving_idx_) classes.push_back(out_.cls(static_cast<size_t>(i)));
  if (static_cast<int64_t>(classes.size()) != local.size(0))
    throw std::logic_error("points in play: " + std::to_string(local.size(0)) + " positions, " + std::to_string(classes.size()) + " classes");
  return geometry_->pattern(local, frozen_.size(0), classes, shape_.moving_area());
}

void GaborEngine::save_checkpoint() {
  last_checkpoint_ = Clock::now();
  if (!ctx_.save_checkpoint) return;
  state_.positions = out_.positions();
  state_.optimizer = optimizer_ ? optimizer_->save_state() : OptimizerState();
  state_.key = ctx_.checkpoint_key.is_null() ? json::object() : ctx_.checkpoint_key;
  std::ostringstream rng;
  rng << jitter_rng_;
  state_.rng = rng.str();
  // Wall time so far over every process of the run: a resumed run reports its whole time.
  state_.phase_seconds = to_json(phases_);
  state_.phase_seconds["wall"] = seconds_before_ + since(run_start_);
  if (cpu_before_ >= 0) state_.phase_seconds["cpu"] = cpu_before_ + process_cpu_seconds() - cpu_at_start_;
  ctx_.save_checkpoint(serialize_state(state_));
}

}  // namespace ppsynth
