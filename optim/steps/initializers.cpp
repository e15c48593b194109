// Initializers of the output positions (optim/steps/initializer.hpp).
#include <spdlog/spdlog.h>

#include "core/config/defaults_catalog.hpp"
#include "core/generators/best_candidate.hpp"
#include "core/generators/generator.hpp"
#include "core/generators/uniform.hpp"
#include "optim/steps/initializer.hpp"

namespace ppsynth {

void log_initialization(size_t points, const Domain& canvas) {
  spdlog::info("initializing {} points on the canvas [{:g}, {:g}] x [{:g}, {:g}] ({:g} x {:g}, area {:g})", points, canvas.x0,
               canvas.x1, canvas.y0, canvas.y1, canvas.width(), canvas.height(), canvas.area());
}

namespace {

// `d` shrunk by `margin` (a fraction of its width and height) on every side.
Domain inset(const Domain& d, double margin) {
  return Domain{d.x0 + margin * d.width(), d.y0 + margin * d.height(), d.x1 - margin * d.width(), d.y1 - margin * d.height()};
}

// The paper's: toroidal best-candidate Poisson disk, candidates in [0.01, 0.99]^2.
class BestCandidateInit : public Initializer {
 public:
  explicit BestCandidateInit(BestCandidateOptions o) : o_(o) {}
  PointSet initialize(size_t n, int, uint64_t seed, const Domain& d) const override {
    BestCandidateOptions o = o_;
    o.poll = poll_;
    return best_candidate_points(n, seed, d, o);
  }

 private:
  BestCandidateOptions o_;
};

struct UniformInitOptions {
  double margin = 0.01;
  static const ParamTable<UniformInitOptions>& params() {
    static const ParamTable<UniformInitOptions> t(
        "method.init", {param("margin", &UniformInitOptions::margin, "[0, 0.5)", "points kept this fraction of the side away from the border")});
    return t;
  }
};

class UniformInit : public Initializer {
 public:
  explicit UniformInit(double margin) : margin_(margin) {}  // in [0, 0.5): the registry's bound
  PointSet initialize(size_t n, int, uint64_t seed, const Domain& d) const override {
    return uniform_points(n, seed, inset(d, margin_));
  }

 private:
  double margin_;
};

struct GeneratorInitOptions {
  json generator = json{{"type", "jittered_grid"}};
  static const ParamTable<GeneratorInitOptions>& params() {
    static const ParamTable<GeneratorInitOptions> t(
        "method.init", {param("generator", &GeneratorInitOptions::generator, "", "the generator's spec ({\"type\": ..., its keys})")});
    return t;
  }
};

// Any registered point generator ({"generator": {"type": "jittered_grid", ...}}).
class GeneratorInit : public Initializer {
 public:
  explicit GeneratorInit(json spec) : spec_(std::move(spec)) {}
  PointSet initialize(size_t n, int, uint64_t seed, const Domain& d) const override {
    return generate_points(spec_, n, seed, d, "method.init.generator");
  }

 private:
  json spec_;
};

}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::InitializerRegistry, "initializer", "best_candidate", ppsynth::BestCandidateOptions::params(),
                        "toroidal best-candidate Poisson disk in [margin, 1-margin]^2 (the paper's)",
                        [](const ppsynth::BestCandidateOptions& o, const std::string&) -> std::unique_ptr<ppsynth::Initializer> {
                          return std::make_unique<ppsynth::BestCandidateInit>(o);
                        })
PPSYNTH_REGISTER_PARAMS(ppsynth::InitializerRegistry, "initializer", "uniform", ppsynth::UniformInitOptions::params(),
                        "uniform random positions (the supplement: random initialization works too)",
                        [](const ppsynth::UniformInitOptions& o, const std::string&) -> std::unique_ptr<ppsynth::Initializer> {
                          return std::make_unique<ppsynth::UniformInit>(o.margin);
                        })
PPSYNTH_REGISTER_PARAMS(ppsynth::InitializerRegistry, "initializer", "generator", ppsynth::GeneratorInitOptions::params(),
                        "any registered point generator",
                        [](const ppsynth::GeneratorInitOptions& o, const std::string&) -> std::unique_ptr<ppsynth::Initializer> {
                          return std::make_unique<ppsynth::GeneratorInit>(o.generator);
                        })
PPSYNTH_DEFAULTS_KIND("initializer", ppsynth::InitializerRegistry)
