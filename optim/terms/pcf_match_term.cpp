#include "optim/terms/pcf_match_term.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/metrics/pcf.hpp"
#include "models/point_tensor.hpp"
#include "optim/terms/point_term.hpp"

namespace ppsynth {

PcfMatchTerm::PcfMatchTerm(const PointSet& ex, const PointSet& out, const std::vector<size_t>& moving,
                           const std::vector<size_t>& frozen, int upscale, bool cross, torch::Device device) {
  if (moving.empty()) return;
  const int cls = out.cls(moving.front());
  for (size_t i : moving)
    if (out.cls(i) != cls) throw InputError("pcf_match: the moving points must be of one class");
  const double u2 = static_cast<double>(upscale) * upscale;
  const PcfOptions opt;  // the evaluation's estimator: same radii and kernel in r_max units
  const PointSet ex_a = ex.subset_class(cls);

  // g_ex sampled at the radii that fit in half the unit torus, in output units.
  auto add_curve = [&](const ppsynth::Curve& g, size_t ex_count, torch::Tensor rows) {
    const double r_max_out = pcf_unit(static_cast<size_t>(std::llround(ex_count * u2)), 1.0);
    std::vector<float> r, t;
    for (size_t b = 0; b < g.r.size(); ++b) {
      const double rb = g.r[b] * r_max_out;
      if (rb > 0.5) break;
      r.push_back(static_cast<float>(rb));
      t.push_back(static_cast<float>(g.g[b]));
    }
    if (r.empty()) return;
    Curve c;
    c.frozen_rows = rows.defined() ? rows.to(device) : rows;
    c.radii = torch::tensor(r).to(device);
    c.target = torch::tensor(t).to(device);
    c.sigma = opt.sigma_factor * r_max_out;
    curves_.push_back(std::move(c));
  };

  if (ex_a.size() >= 2 && moving.size() >= 2) add_curve(pcf(ex_a, opt), ex_a.size(), torch::Tensor());
  if (!cross) return;
  // One cross curve per frozen class (rows of the frozen tensor holding that class).
  std::vector<std::vector<int64_t>> rows_of(out.num_classes());
  for (size_t r = 0; r < frozen.size(); ++r) rows_of[out.cls(frozen[r])].push_back(static_cast<int64_t>(r));
  for (int b = 0; b < static_cast<int>(rows_of.size()); ++b) {
    if (rows_of[b].empty()) continue;
    const PointSet ex_b = ex.subset_class(b);
    if (ex_b.empty() || ex_a.empty()) continue;
    add_curve(cross_pcf(ex_a, ex_b, opt), ex_a.size() + ex_b.size(), torch::tensor(rows_of[b]));
  }
}

namespace {

// g(r_b) for the pairs of a (n x 2) and b (m x 2) on the unit torus; `same`: a == b, i != j.
torch::Tensor torus_pcf(const torch::Tensor& a, const torch::Tensor& b, bool same, const torch::Tensor& radii,
                        double sigma) {
  auto d = torus_distances(a, b);  // n x m
  const int64_t n = a.size(0), m = b.size(0);
  double pairs = static_cast<double>(n) * m;
  if (same) {  // each unordered pair once, counted twice (ordered pairs as in the estimator)
    auto iu = torch::triu_indices(n, n, 1, d.options().dtype(torch::kLong));  // made where d is
    d = d.index({iu[0], iu[1]});
    pairs = static_cast<double>(n) * (n - 1) / 2.0;
  } else {
    d = d.reshape({-1});
  }
  auto t = radii.unsqueeze(0) - d.unsqueeze(1);  // pairs x bins
  auto k = torch::exp(-(t * t) / (sigma * sigma)) / (std::sqrt(M_PI) * sigma);
  return k.sum(0) / (pairs * 2.0 * M_PI * radii);
}

}  // namespace

torch::Tensor PcfMatchTerm::operator()(const torch::Tensor& moving, const torch::Tensor& frozen) const {
  auto total = torch::zeros({}, moving.options().requires_grad(false));
  for (const auto& c : curves_) {
    torch::Tensor g;
    if (!c.frozen_rows.defined()) {
      g = torus_pcf(moving, moving, true, c.radii, c.sigma);
    } else {
      g = torus_pcf(moving, frozen.index_select(0, c.frozen_rows), false, c.radii, c.sigma);
    }
    total = total + (g - c.target).pow(2).mean();
  }
  return total;
}

namespace {

// The registered form: divided by its value at the class's first evaluation, so at a
// class's start it weighs `weight` x the paper's loss whatever the scene's PCF scale, and it
// fades as the class's PCF approaches the exemplar's.
struct PcfMatchOptions {
  double weight = 0;
  bool cross = true;
  static const ParamTable<PcfMatchOptions>& params() {
    using O = PcfMatchOptions;
    static const ParamTable<O> t("method.terms.pcf_match", {
        param("weight", &O::weight, "[0, inf)", "the term's weight against the paper's loss at the class's start (0: off)"),
        param("cross", &O::cross, "", "the cross PCFs to the frozen classes too"),
    });
    return t;
  }
};

class PcfMatchPointTerm : public PointTerm {
 public:
  explicit PcfMatchPointTerm(const PcfMatchOptions& o) : cross_(o.cross) {}
  void begin_class(const ClassStage& s) override {
    term_ = std::make_unique<PcfMatchTerm>(s.exemplar, s.output, s.moving, s.frozen, s.upscale, cross_, s.device);
    start_ = -1;
  }
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& frozen) override {
    auto v = (*term_)(moving, frozen);
    if (start_ < 0) start_ = std::max(v.item<double>(), 1e-3);
    return v / start_;
  }

 private:
  bool cross_ = true;
  std::unique_ptr<PcfMatchTerm> term_;
  double start_ = -1;
};

}  // namespace

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::PointTermRegistry, "point_term", "pcf_match", ppsynth::PcfMatchOptions::params(),
                        "the moving class's PCF (and cross-PCFs to the frozen classes) on the output torus vs the exemplar's",
                        [](const ppsynth::PcfMatchOptions& o, const std::string&) -> std::unique_ptr<ppsynth::PointTerm> {
                          return std::make_unique<ppsynth::PcfMatchPointTerm>(o);
                        })
