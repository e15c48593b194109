// "pcf2017": thesis Chapter 4's PCF-matching synthesis as a SynthesisMethod (stationary
// case): target = the exemplar's PCF (Eq. 4.1 over the exemplar window, radii relative to
// its r_max); output = u^2 M points on the unit torus, descended on Eq. 4.3. Because radii are
// relative to r_max and r_max scales as 1/sqrt(N), the output's PCF in its own r_max units is
// the exemplar's PCF at 1/u size. Classes and attributes are not modelled (single class).
#include <chrono>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "optim/baselines/pcf2017/local_pcf.hpp"
#include "optim/baselines/pcf2017/pcf_synthesizer.hpp"
#include "optim/method.hpp"

namespace ppsynth::pcf2017 {

namespace {

class Pcf2017Method : public SynthesisMethod {
 public:
  explicit Pcf2017Method(const nlohmann::json& p) {
    const std::string kp = "method";
    pcf_.bins = get_int(p, "bins", kp);
    pcf_.r_a = get_number(p, "r_a", kp);
    pcf_.r_b = get_number(p, "r_b", kp);
    pcf_.sigma_factor = get_number(p, "sigma_factor", kp);
    descent_.iterations = get_int(p, "iterations", kp);
    descent_.step = get_number(p, "step", kp);
    descent_.max_step = get_number(p, "max_step", kp);
    descent_.grow = get_number(p, "grow", kp);
    descent_.line_search_halvings = get_int(p, "line_search_halvings", kp);
    quick_iterations_ = get_int(p, "quick_iterations", kp);
    if (pcf_.bins < 2) throw config_error(kp + ".bins", "must be >= 2");
    if (!(pcf_.r_a > 0) || !(pcf_.r_b > pcf_.r_a)) throw config_error(kp + ".r_a", "need 0 < r_a < r_b");
    if (!(pcf_.sigma_factor > 0)) throw config_error(kp + ".sigma_factor", "must be > 0");
    if (descent_.iterations < 0) throw config_error(kp + ".iterations", "must be >= 0");
    if (!(descent_.step > 0)) throw config_error(kp + ".step", "must be > 0");
    if (!(descent_.max_step >= descent_.step)) throw config_error(kp + ".max_step", "must be >= step");
    if (!(descent_.grow >= 1)) throw config_error(kp + ".grow", "must be >= 1");
    if (descent_.line_search_halvings < 0) throw config_error(kp + ".line_search_halvings", "must be >= 0");
    if (quick_iterations_ < 0) throw config_error(kp + ".quick_iterations", "must be >= 0");
  }

  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override {
    validate(exemplar, "exemplar");
    if (exemplar.size() < 2) throw InputError("pcf2017: the exemplar needs at least 2 points");
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
      (*ctx.stats)["iterations"] = int(res.energy.size()) - 1;
      (*ctx.stats)["energy_initial"] = res.energy.front();
      (*ctx.stats)["energy_final"] = res.energy.back();
      (*ctx.stats)["converged"] = res.converged;
      (*ctx.stats)["points"] = n;
      (*ctx.stats)["target_r_max"] = target.r_max;
      (*ctx.stats)["seconds"] = ev.seconds;
    }
    spdlog::debug("pcf2017: E {} -> {} in {} iterations{}", res.energy.front(), res.energy.back(),
                  res.energy.size() - 1, res.converged ? " (converged)" : "");
    return out;
  }

 private:
  PcfParams pcf_;
  DescentOptions descent_;
  int quick_iterations_ = 30;
};

}  // namespace

}  // namespace ppsynth::pcf2017

PPSYNTH_REGISTER(ppsynth::MethodRegistry, "pcf2017",
                 (nlohmann::json{{"iterations", 300},
                                 {"quick_iterations", 30},
                                 {"step", 0.1},
                                 {"max_step", 0.5},
                                 {"grow", 1.2},
                                 {"line_search_halvings", 12},
                                 {"bins", 100},
                                 {"r_a", 0.01},
                                 {"r_b", 2.5},
                                 {"sigma_factor", 0.25}}),
                 (nlohmann::json{{"iterations", "int [0, inf)"},
                                 {"quick_iterations", "int [0, inf)"},
                                 {"step", "(0, inf)"},
                                 {"max_step", "(0, inf)"},
                                 {"grow", "[1, inf)"},
                                 {"line_search_halvings", "int [0, 64]"},
                                 {"bins", "int [2, 100000]"},
                                 {"r_a", "[0, inf)"},
                                 {"r_b", "(0, inf)"},
                                 {"sigma_factor", "(0, inf)"}}),
                 "Roveri et al. 2017 (thesis Ch. 4): gradient descent on the PCF energy (Eq. 4.3), stationary, torus",
                 [](const nlohmann::json& p) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                   return std::make_unique<ppsynth::pcf2017::Pcf2017Method>(p);
                 })
