// "roveri2015": thesis Chapter 3 (Roveri et al. 2015, "Example Based Repetitive Structure
// Synthesis") as a SynthesisMethod, for 2-D point patterns with classes and attributes.
//
// Expansion by S = u^2: the output is synthesized on a domain u times wider and taller than
// the exemplar's, in exemplar units (so the exemplar's structures keep their size there),
// initialized by random patch copy (patch_init.hpp) or ctx.initialization, optimized by
// Algorithm 1 (solver.hpp), and finally mapped onto the unit square (structures at 1/u size).
// Lengths scale with d_nn, the exemplar's mean nearest-neighbor distance: sigma =
// sigma_factor d_nn, delta_0 = window_factor d_nn (params.hpp).
// Rectangle outputs (core/output_shape.hpp): the same synthesis with the rectangle as the
// output domain, in exemplar units and never mapped (its expected count is the exemplar's
// density times the area); ctx.initialization is then in exemplar units on the canvas.
// Border: synthesized on output.canvas(), the crop to output.domain() kept when output.clean_border and pad > 0.
// Snapshots (start, stage ends) show what is synthesized: the unit square, or the canvas.
// Progress: one ProgressEvent stage per scale ("scale s/N, delta=..."), one iteration event
// per local-global round (loss = T of Eq. 3.6), a stage_end with the current output.
#include <chrono>
#include <cmath>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "optim/baselines/roveri2015/functional.hpp"
#include "optim/baselines/roveri2015/params.hpp"
#include "optim/baselines/roveri2015/roveri2015_options.hpp"
#include "optim/baselines/roveri2015/roveri2015_stats.hpp"
#include "optim/baselines/roveri2015/patch_init.hpp"
#include "optim/baselines/roveri2015/solver.hpp"
#include "optim/baselines/roveri2015/synthesis_state.hpp"
#include "optim/method/method.hpp"

namespace ppsynth::roveri2015 {

namespace {

class Roveri2015Method : public SynthesisMethod {
 public:
  // o: the method's block read through its table.
  explicit Roveri2015Method(const Roveri2015Options& o) {
    p_ = o.roveri;
    quick_scales_ = o.quick_scales;
  }

  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override {
    validate(exemplar, "exemplar");
    if (exemplar.size() < 3) throw InputError("roveri2015: the exemplar needs at least 3 points");
    const OutputShape& shape = ctx.output;
    const bool rect = shape.rectangle;
    shape.require_no_exemplar_pad("roveri2015");
    if (!rect && shape.upscale < 1) throw InputError("roveri2015: upscale must be >= 1");
    const auto t_start = std::chrono::steady_clock::now();
    const Domain E = exemplar.domain();
    const double u = shape.upscale;
    // The paper's: u times the exemplar's window; a rectangle: its canvas (already in exemplar units).
    const Domain canvas = shape.canvas();
    const Domain out_domain = rect ? Domain{canvas.x0, canvas.y0, canvas.x1, canvas.y1, p_.periodic_output}
                                   : Domain{E.x0, E.y0, E.x0 + u * E.width(), E.y0 + u * E.height(), p_.periodic_output};
    const bool crop = rect && shape.clean_border && shape.pad > 0;
    const Domain unit{0, 0, 1, 1, p_.periodic_output};

    const double d_nn = mean_nn_distance(exemplar, false);
    if (!(d_nn > 0)) throw InputError("roveri2015: the exemplar's points all coincide");
    const double sigma = p_.sigma_factor * d_nn;
    const double delta0 = p_.window_factor * d_nn;
    KernelParams probe;
    probe.delta = delta0;
    probe.window = p_.window;
    probe.window_cutoff = p_.window_cutoff;
    if (p_.periodic_output && probe.radius() >= 0.5 * std::min(out_domain.width(), out_domain.height()))
      throw InputError("roveri2015: the window radius (" + std::to_string(probe.radius()) +
                       ") must be below half the periodic output domain; lower window_factor");

    RoveriParams p = p_;
    if (ctx.quick) {
      p.min_window_ratio = std::pow(p.scale_factor, quick_scales_ - 1) * (1 - 1e-9);
      p.local_global_iterations = 1;
      p.sampling_control_iterations = 1;
      p.merge_iterations = std::min(p.merge_iterations, 10);
    }

    PointSet init = ctx.initialization ? (rect ? initialization_on(*ctx.initialization, out_domain)
                                                : ctx.initialization->mapped_to(out_domain))
                                       : random_patch_copy(exemplar, out_domain,
                                                           p.patch_size * std::min(E.width(), E.height()), ctx.seed);
    ctx.start(rect ? init : init.mapped_to(unit));
    const ChannelEncoder enc(exemplar, p.attribute_weight);
    if (init.num_attributes() != exemplar.num_attributes())
      throw InputError("roveri2015: the initialization has " + std::to_string(init.num_attributes()) +
                       " attribute columns, the exemplar " + std::to_string(exemplar.num_attributes()));
    SynthesisState st(encode_points(exemplar, enc), E, encode_points(init, enc), out_domain, p.periodic_output);

    // What observers see and what is returned before the crop: the unit square or the canvas.
    const auto to_unit = [&](const SynthesisState& s) {
      PointSet ps = decode_points(s.out, enc, exemplar, out_domain);
      return rect ? ps : ps.mapped_to(unit);
    };
    ProgressEvent ev;
    auto t_stage = std::chrono::steady_clock::now();
    const auto since = [](std::chrono::steady_clock::time_point t) {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    SolverCallbacks cb;
    cb.scale_begin = [&](int s, int n, double delta) {
      ev = ProgressEvent{};
      ev.stage = "scale " + std::to_string(s + 1) + "/" + std::to_string(n) + ", delta " + std::to_string(delta / d_nn) + " d_nn";
      ev.stage_index = s;
      ev.stage_count = n;
      ev.max_iterations = p.local_global_iterations * p.sampling_control_iterations;
      t_stage = std::chrono::steady_clock::now();
      ctx.stage_begin(ev);
    };
    cb.iteration = [&](int, int it, int, double T) {
      ev.iteration = it;
      ev.loss = T;
      ev.seconds = since(t_stage);
      ctx.iteration(ev);
    };
    Roveri2015Stats stats;
    cb.scale_end = [&](int, const SynthesisState& s, const ScaleReport& r) {
      ev.loss = r.energy_end;
      ev.seconds = since(t_stage);
      ctx.stage_end(ev, to_unit(s));
      stats.scales.push_back(r);
      spdlog::debug("roveri2015: delta {:.4f}: T {:.4g} -> {:.4g}, {} points (+{} -{}), {:.2f} s", r.delta,
                    r.energy_start, r.energy_end, r.points, r.added, r.removed, r.seconds);
    };
    solve(st, enc, p, sigma, delta0, ctx.seed ^ 0x9e3779b97f4a7c15ULL, cb);
    PointSet out = to_unit(st);
    if (crop) out = out.crop(shape.domain());
    if (ctx.stats) {
      stats.d_nn = d_nn;
      stats.sigma = sigma;
      stats.delta0 = delta0;
      stats.quadrature_points = st.quad.size();
      stats.initial_points = init.size();
      stats.points = out.size();
      if (rect) {
        stats.target_points = shape.expected_points(exemplar);
        stats.rectangle = RectangleStats{shape.describe(), {canvas.x0, canvas.y0, canvas.x1, canvas.y1}, st.out.size()};
      } else {
        stats.target_points = static_cast<double>(size_t(u * u) * exemplar.size());
      }
      stats.seconds = since(t_start);
      *ctx.stats = to_json(stats);
    }
    return out;
  }

 private:
  // An explicit initialization of a rectangle output: its points in exemplar units, inside
  // the canvas (its file's own domain may be anything, so positions are not mapped).
  static PointSet initialization_on(const PointSet& init, const Domain& canvas) {
    check_initialization_inside(init, canvas, "roveri2015", "the synthesis canvas (the output rectangle in exemplar units, plus the clean border's pad)");
    PointSet on = init;
    on.set_domain(canvas);
    return on;
  }

  RoveriParams p_;
  int quick_scales_ = 0;
};

}  // namespace

}  // namespace ppsynth::roveri2015

PPSYNTH_REGISTER_PARAMS(ppsynth::MethodRegistry, "method", "roveri2015", ppsynth::roveri2015::Roveri2015Options::params(),
                        "Roveri et al. 2015 (thesis Ch. 3): functional neighborhood matching, multi-scale local-global "
                        "solver with sampling control, random-patch-copy init",
                        [](const ppsynth::roveri2015::Roveri2015Options& o, const std::string&) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                          return std::make_unique<ppsynth::roveri2015::Roveri2015Method>(o);
                        })
