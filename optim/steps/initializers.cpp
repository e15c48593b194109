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

class UniformInit : public Initializer {
 public:
  explicit UniformInit(double margin) : margin_(margin) {}  // in [0, 0.5): the registry's bound
  PointSet initialize(size_t n, int, uint64_t seed, const Domain& d) const override {
    return uniform_points(n, seed, inset(d, margin_));
  }

 private:
  double margin_;
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

PPSYNTH_REGISTER(ppsynth::InitializerRegistry, "best_candidate", (ppsynth::json{{"m", 10.0}, {"margin", 0.01}}),
                 (ppsynth::json{{"m", "(0, 10000]"}, {"margin", "[0, 0.5)"}}),
                 "toroidal best-candidate Poisson disk in [margin, 1-margin]^2 (the paper's)",
                 [](const ppsynth::json& p, const std::string& key) -> std::unique_ptr<ppsynth::Initializer> {
                   ppsynth::BestCandidateOptions o;
                   o.m = p["m"].get<double>();
                   o.margin = p["margin"].get<double>();
                   return std::make_unique<ppsynth::BestCandidateInit>(o);
                 })
PPSYNTH_REGISTER(ppsynth::InitializerRegistry, "uniform", (ppsynth::json{{"margin", 0.01}}),
                 (ppsynth::json{{"margin", "[0, 0.5)"}}),
                 "uniform random positions (the supplement: random initialization works too)",
                 [](const ppsynth::json& p, const std::string& key) -> std::unique_ptr<ppsynth::Initializer> {
                   return std::make_unique<ppsynth::UniformInit>(p["margin"].get<double>());
                 })
PPSYNTH_REGISTER(ppsynth::InitializerRegistry, "generator", (ppsynth::json{{"generator", {{"type", "jittered_grid"}}}}),
                 ppsynth::json::object(),
                 "any registered point generator",
                 [](const ppsynth::json& p, const std::string& key) -> std::unique_ptr<ppsynth::Initializer> {
                   return std::make_unique<ppsynth::GeneratorInit>(p["generator"]);
                 })
PPSYNTH_DEFAULTS_KIND("initializer", ppsynth::InitializerRegistry)
