#include "core/generators/best_candidate.hpp"

#include <cmath>
#include <random>

#include "core/generators/candidate_cells.hpp"
#include "core/config/params.hpp"
#include "core/generators/generator.hpp"

namespace ppsynth {

PointSet best_candidate_points(size_t n, uint64_t seed, Domain d, const BestCandidateOptions& opt) {
  gen_detail::check_domain(d, "best_candidate");
  if (!(opt.m > 0) || !std::isfinite(opt.m)) throw config_error("best_candidate.m", "must be positive");
  if (!(opt.margin >= 0) || opt.margin >= 0.5)
    throw config_error("best_candidate.margin", "must be in [0, 0.5)");
  const Domain window{d.x0 + opt.margin * d.width(), d.y0 + opt.margin * d.height(),
                      d.x1 - opt.margin * d.width(), d.y1 - opt.margin * d.height()};
  std::mt19937_64 rng(seed);
  PointSet ps(d);
  ps.reserve(n);
  gen_detail::CandidateCells cells(d, window, n);
  for (size_t count = 0; count < n; ++count) {
    if (opt.poll && count % 1024 == 0) opt.poll();
    const size_t candidates = std::max<size_t>(1, static_cast<size_t>(std::ceil(opt.m * static_cast<double>(count))));
    const Vec2 best = count == 0 ? gen_detail::uniform_in(rng, window) : cells.best_of(candidates, rng);
    cells.accept(best);
    ps.add(best);
  }
  return ps;
}

namespace {
struct BestCandidateGen : PointGenerator {
  BestCandidateOptions opt;
  PointSet generate(size_t n, uint64_t seed, const Domain& d) const override {
    return best_candidate_points(n, seed, d, opt);
  }
};
}  // namespace

}  // namespace ppsynth

namespace ppsynth {
const ParamTable<BestCandidateOptions>& BestCandidateOptions::params() {
  using O = BestCandidateOptions;
  static const ParamTable<O> t("generator", {
      param("m", &O::m, "(0, 10000]", "candidates drawn per point placed so far"),
      param("margin", &O::margin, "[0, 0.5)", "candidates kept this fraction of the side away from the border"),
  });
  return t;
}
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::GeneratorRegistry, "generator", "best_candidate", ppsynth::BestCandidateOptions::params(),
                        "Mitchell best-candidate (toroidal distances, m * count candidates; margin 0.01 = "
                        "the published initialization's [0.01, 0.99]^2)",
                        [](const ppsynth::BestCandidateOptions& o, const std::string&) {
                          auto g = std::make_unique<ppsynth::BestCandidateGen>();
                          g->opt = o;
                          return g;
                        })
