// "pcf2017": thesis Chapter 4's PCF-matching synthesis as a SynthesisMethod (stationary
// case): target = the exemplar's PCF (Eq. 4.1 over the exemplar window, radii relative to
// its r_max); output = u^2 M points on the unit torus, descended on Eq. 4.3. Because radii are
// relative to r_max and r_max scales as 1/sqrt(N), the output's PCF in its own r_max units is
// the exemplar's PCF at 1/u size. On this path classes and attributes are not modeled (single class).
//
// Rectangle outputs (core/output_shape.hpp): the canvas, in exemplar units, made a torus;
// each class is synthesized on its own against its own PCF (cross-class structure is not
// modeled) with output.class_counts(exemplar, canvas) points, so every class keeps its
// density, and takes its exemplar points' attributes in turn (i-th point: point i mod M_c).
// A class whose PCF reaches beyond half a side of a thin canvas descends on a torus grown past
// the canvas's far edges and is cut to the canvas (its count is then the density's expectation, not exact).
// A class with fewer than 2 exemplar or output points has no PCF: its points stay uniform.
// ctx.initialization is then in exemplar units on the canvas with exactly those per-class counts.
// Border: synthesized on output.canvas(), the crop to output.domain() kept when output.clean_border and pad > 0.
#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "optim/baselines/pcf2017/local_pcf.hpp"
#include "optim/baselines/pcf2017/pcf2017_options.hpp"
#include "optim/baselines/pcf2017/pcf2017_stats.hpp"
#include "optim/baselines/pcf2017/pcf_synthesizer.hpp"
#include "optim/method/method.hpp"

namespace ppsynth::pcf2017 {

namespace {

class Pcf2017Method : public SynthesisMethod {
 public:
  // o: the method's block read through its table; the checks between two keys made (check).
  explicit Pcf2017Method(const Pcf2017Options& o) {
    pcf_ = o.pcf;
    descent_ = o.descent;
    quick_iterations_ = o.quick_iterations;
  }

  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override {
    validate(exemplar, "exemplar");
    if (exemplar.size() < 2) throw InputError("pcf2017: the exemplar needs at least 2 points");
    if (ctx.output.rectangle) return synthesize_rectangle(exemplar, ctx);
    if (ctx.output.upscale < 1) throw InputError("pcf2017: upscale must be >= 1");
    if (exemplar.num_classes() > 1 || exemplar.num_attributes() > 0)
      spdlog::warn("pcf2017: classes and attributes are ignored (single-class PCF synthesis)");
    const size_t n = size_t(ctx.output.upscale) * size_t(ctx.output.upscale) * exemplar.size();
    const PcfCurve target = pattern_pcf(exemplar, pcf_, exemplar.domain().periodic);

    const Domain torus{0, 0, 1, 1, true};
    std::vector<Vec2> init;
    if (ctx.initialization) {
      if (ctx.initialization->size() != n)
        throw InputError("pcf2017: the initialization has " + std::to_string(ctx.initialization->size()) +
                         " points, expected u^2 M = " + std::to_string(n));
      init = ctx.initialization->mapped_to(torus).positions();
    } else {
      init = uniform_points(n, torus, ctx.seed);
    }
    DescentOptions opt = descent_;
    if (ctx.quick) opt.iterations = std::min(opt.iterations, quick_iterations_);

    {
      PointSet start(torus);
      for (const Vec2& p : init) start.add(p, 0);
      ctx.start(start);
    }
    ProgressEvent ev;
    ev.stage = "pcf2017 gradient descent";
    ev.max_iterations = opt.iterations;
    const auto t0 = std::chrono::steady_clock::now();
    ctx.stage_begin(ev);
    const DescentResult res = synthesize_stationary(target.g, std::move(init), torus, pcf_, opt, [&](int it, double E) {
      ev.iteration = it + 1;
      ev.loss = E;
      ev.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ctx.iteration(ev);
    });
    PointSet out(torus);
    out.reserve(n);
    for (const Vec2& p : res.points) out.add(p, 0);
    ev.loss = res.energy.back();
    ev.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ctx.stage_end(ev, out);
    if (ctx.stats) {
      Pcf2017Stats stats;
      stats.points = n;
      stats.seconds = ev.seconds;
      stats.descent = Pcf2017Descent{int(res.energy.size()) - 1, res.energy.front(), res.energy.back(), res.converged, target.r_max};
      *ctx.stats = to_json(stats);
    }
    spdlog::debug("pcf2017: E {} -> {} in {} iterations{}", res.energy.front(), res.energy.back(),
                  res.energy.size() - 1, res.converged ? " (converged)" : "");
    return out;
  }

 private:
  PointSet synthesize_rectangle(const PointSet& exemplar, const SynthesisContext& ctx) const {
    const OutputShape& shape = ctx.output;
    shape.require_no_exemplar_pad("pcf2017");
    const Domain c = shape.canvas();
    const Domain torus{c.x0, c.y0, c.x1, c.y1, true};
    const int K = exemplar.num_classes();

    // Per class: its exemplar points, the torus it descends on (grown: larger than the
    // canvas) and its positions there.
    std::vector<PointSet> ex_class(K);
    std::vector<Domain> on(K, torus);
    std::vector<char> grown(K, 0);
    for (int k = 0; k < K; ++k) {
      ex_class[k] = exemplar.subset_class(k);
      if (ex_class[k].empty()) continue;
      on[k] = class_torus(exemplar, shape, k, torus);
      grown[k] = on[k].x1 != torus.x1 || on[k].y1 != torus.y1;
      if (ctx.initialization && grown[k])
        throw InputError("pcf2017: class " + std::to_string(k) + "'s PCF reaches beyond half the canvas side, so it is synthesized on a " +
                         std::to_string(on[k].width()) + " x " + std::to_string(on[k].height()) +
                         " torus larger than the canvas, which an initialization cannot fill; give a larger output.size or no initialization");
    }
    if (ctx.initialization) check_initialization(*ctx.initialization, shape.class_counts(exemplar, torus), torus);
    std::vector<std::vector<Vec2>> pos(K);
    for (int k = 0; k < K; ++k) {
      if (ex_class[k].empty()) continue;
      // Seeded per class (class 0 with the run's seed, as the paper's path), so classes start independent.
      pos[k] = ctx.initialization ? ctx.initialization->subset_class(k).positions()
                                  : uniform_points(shape.class_counts(exemplar, on[k])[k], on[k], ctx.seed + 1000003ull * k);
    }
    // The canvas as observers and the result see it: each class's points inside the canvas,
    // the i-th point of class k with the attributes of the class's exemplar point i mod M_k.
    const auto assemble = [&] {
      PointSet ps(torus);
      ps.set_class_labels(exemplar.class_labels());
      for (auto& name : exemplar.attribute_names()) ps.add_attribute(name);
      for (int k = 0; k < K; ++k)
        for (size_t i = 0; i < pos[k].size(); ++i)
          if (!grown[k] || (pos[k][i].x < torus.x1 && pos[k][i].y < torus.y1))  // a larger torus extends past the far edges only
            ps.add(pos[k][i], k, ex_class[k].attributes_of(i % ex_class[k].size()));
      return ps;
    };
    ctx.start(assemble());

    DescentOptions opt = descent_;
    if (ctx.quick) opt.iterations = std::min(opt.iterations, quick_iterations_);
    const auto t_run = std::chrono::steady_clock::now();
    std::vector<Pcf2017Class> per_class;
    for (int k = 0; k < K; ++k) {
      ProgressEvent ev;
      ev.stage = K > 1 ? "class " + std::to_string(k + 1) + "/" + std::to_string(K) + ", pcf2017 gradient descent"
                       : "pcf2017 gradient descent";
      ev.stage_index = k;
      ev.stage_count = K;
      const size_t n = pos[k].size();
      const bool has_pcf = ex_class[k].size() >= 2 && n >= 2;
      ev.max_iterations = has_pcf ? opt.iterations : 0;
      const auto t0 = std::chrono::steady_clock::now();
      const auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
      ctx.stage_begin(ev);
      Pcf2017Class cs{k, {on[k].x0, on[k].y0, on[k].x1, on[k].y1}, n, std::nullopt};
      if (has_pcf) {
        const PcfCurve target = pattern_pcf(ex_class[k], pcf_, exemplar.domain().periodic);
        DescentResult res = synthesize_stationary(target.g, pos[k], on[k], pcf_, opt, [&](int it, double E) {
          ev.iteration = it + 1;
          ev.loss = E;
          ev.seconds = since();
          ctx.iteration(ev);
        });
        pos[k] = std::move(res.points);
        ev.loss = res.energy.back();
        cs.descent = Pcf2017Descent{int(res.energy.size()) - 1, res.energy.front(), res.energy.back(), res.converged, target.r_max};
      } else if (!ex_class[k].empty()) {
        spdlog::warn("pcf2017: class {} has {} exemplar and {} output points, too few for a PCF; its points stay uniform",
                     k, ex_class[k].size(), n);
      }
      ev.seconds = since();
      ctx.stage_end(ev, assemble());
      per_class.push_back(cs);
    }
    const PointSet on_canvas = assemble();
    const bool crop = shape.clean_border && shape.pad > 0;
    PointSet out = crop ? on_canvas.crop(shape.domain()) : on_canvas;
    if (ctx.stats) {
      Pcf2017Stats stats;
      stats.points = out.size();
      stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_run).count();
      stats.rectangle = RectangleStats{shape.describe(), {c.x0, c.y0, c.x1, c.y1}, on_canvas.size()};
      stats.classes = std::move(per_class);
      *ctx.stats = to_json(stats);
    }
    return out;
  }

  // The torus class k descends on: the canvas, or (its PCF reaching beyond half a side of a
  // thin canvas, which PcfEnergy refuses) the canvas extended past its far edges until both
  // sides are twice the reach; the canvas is then cut out of it. The reach follows the
  // rounded count, so it is re-measured after each growth (few rounds: the density is fixed).
  Domain class_torus(const PointSet& exemplar, const OutputShape& shape, int k, const Domain& canvas) const {
    Domain t = canvas;
    for (int round = 0; round < 32; ++round) {
      const size_t n = shape.class_counts(exemplar, t)[k];
      if (n < 2) return t;  // no PCF to match: the class stays uniform on the canvas
      const double reach = (pcf_.r_b + pcf_.kernel_cutoff * pcf_.sigma_factor) * rmax_for(double(n), t.area());
      if (reach <= 0.5 * std::min(t.width(), t.height())) return t;
      const double side = 2.0 * reach * 1.01;  // 1 % over, so the rounding of the next count rarely needs another round
      t.x1 = t.x0 + std::max(t.width(), side);
      t.y1 = t.y0 + std::max(t.height(), side);
    }
    throw InputError("pcf2017: no torus found for class " + std::to_string(k) + " (its PCF reach does not settle)");
  }
  // An explicit initialization of a rectangle output: exemplar units, inside the canvas,
  // the density's count of every class (its file's own domain is not used).
  static void check_initialization(const PointSet& init, const std::vector<size_t>& counts, const Domain& canvas) {
    size_t total = 0;
    for (size_t n : counts) total += n;
    const std::string where = "the synthesis canvas [" + std::to_string(canvas.x0) + ", " + std::to_string(canvas.x1) +
                              "] x [" + std::to_string(canvas.y0) + ", " + std::to_string(canvas.y1) + "]";
    const auto have = init.class_counts();
    for (size_t k = 0; k < std::max(have.size(), counts.size()); ++k) {
      const size_t h = k < have.size() ? have[k] : 0, want = k < counts.size() ? counts[k] : 0;
      if (h != want)
        throw InputError("pcf2017: the initialization has " + std::to_string(h) + " points of class " + std::to_string(k) +
                         "; the synthesis needs " + std::to_string(want) + " (" + std::to_string(total) +
                         " in all: the exemplar's density of each class over " + where + ")");
    }
    check_initialization_inside(init, canvas, "pcf2017", "the synthesis canvas (the output rectangle in exemplar units, plus the clean border's pad)");
  }

  PcfParams pcf_;
  DescentOptions descent_;
  int quick_iterations_ = 0;
};

}  // namespace

}  // namespace ppsynth::pcf2017

PPSYNTH_REGISTER_PARAMS(ppsynth::MethodRegistry, "method", "pcf2017", ppsynth::pcf2017::Pcf2017Options::params(),
                        "Roveri et al. 2017 (thesis Ch. 4): gradient descent on the PCF energy (Eq. 4.3), stationary, torus",
                        [](const ppsynth::pcf2017::Pcf2017Options& o, const std::string& key) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                          o.check(key);
                          return std::make_unique<ppsynth::pcf2017::Pcf2017Method>(o);
                        })
