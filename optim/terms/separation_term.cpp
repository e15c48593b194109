#include "optim/terms/separation_term.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/neighbors.hpp"
#include "models/point_tensor.hpp"
#include "optim/terms/point_term.hpp"

namespace ppsynth {

std::vector<std::vector<double>> class_pair_min_distance(const PointSet& ps) {
  const int K = ps.num_classes();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> d(K, std::vector<double>(K, inf));
  for (size_t i = 0; i < ps.size(); ++i)
    for (size_t j = i + 1; j < ps.size(); ++j) {
      const int a = ps.cls(i), b = ps.cls(j);
      const double dist = point_distance(ps[i], ps[j]);  // in the square: the exemplar is a crop
      d[a][b] = d[b][a] = std::min(d[a][b], dist);
    }
  for (auto& row : d)
    for (auto& v : row)
      if (v == inf) v = 0;
  return d;
}

SeparationTerm::SeparationTerm(const PointSet& ex, const PointSet& out, const std::vector<size_t>& moving,
                               const std::vector<size_t>& frozen, int upscale, double fraction, torch::Device device,
                               double window_side)
    : periodic_(window_side <= 0) {
  const auto dmin = class_pair_min_distance(ex);
  const auto radius_col = out.attribute_index("radius");
  // Exemplar and output lengths in the positions' units (point_term.hpp's ClassStage).
  const double ex_scale = periodic_ ? 1.0 / upscale : 1.0 / window_side;
  const double out_scale = periodic_ ? 1.0 : 1.0 / window_side;
  auto threshold = [&](size_t i, size_t j) {
    const double spacing = fraction * dmin[out.cls(i)][out.cls(j)] * ex_scale;
    const double contact = radius_col ? (out.attr(i, *radius_col) + out.attr(j, *radius_col)) * out_scale : 0.0;
    return static_cast<float>(std::max(spacing, contact));
  };
  const int64_t n = static_cast<int64_t>(moving.size()), m = static_cast<int64_t>(frozen.size());
  t_moving_ = torch::zeros({n, n});
  t_frozen_ = torch::zeros({n, m});
  auto tm = t_moving_.accessor<float, 2>();
  auto tf = t_frozen_.accessor<float, 2>();
  for (int64_t a = 0; a < n; ++a) {
    for (int64_t b = a + 1; b < n; ++b) tm[a][b] = threshold(moving[a], moving[b]);
    for (int64_t b = 0; b < m; ++b) tf[a][b] = threshold(moving[a], frozen[b]);
  }
  t_moving_ = t_moving_.to(device);
  t_frozen_ = t_frozen_.to(device);
}

namespace {

// Sum over pairs with a threshold of relu(1 - d / t)^2, d on the unit torus or in the plane.
torch::Tensor pair_penalty(const torch::Tensor& a, const torch::Tensor& b, const torch::Tensor& t, bool periodic) {
  if (a.size(0) == 0 || b.size(0) == 0) return torch::zeros({}, a.options());
  auto d = periodic ? torus_distances(a, b) : plane_distances(a, b);
  auto active = t > 0;
  auto v = torch::relu(1 - d / torch::where(active, t, torch::ones_like(t)));
  return (v * active).pow(2).sum();
}

}  // namespace

torch::Tensor SeparationTerm::operator()(const torch::Tensor& moving, const torch::Tensor& frozen) const {
  auto p = pair_penalty(moving, moving, t_moving_, periodic_);
  if (frozen.defined() && frozen.size(0) > 0) p = p + pair_penalty(moving, frozen, t_frozen_, periodic_);
  return p;
}

namespace {

// The registered form: builds the stage's thresholds at each class stage.
struct SeparationOptions {
  double weight = 0;
  double fraction = 0.9;
  static const ParamTable<SeparationOptions>& params() {
    using O = SeparationOptions;
    static const ParamTable<O> t("method.terms.separation", {
        param("weight", &O::weight, "[0, inf)", "the term's weight against the paper's loss at the class's start (0: off)"),
        param("fraction", &O::fraction, "(0, 2]", "the minimum distance as a fraction of the exemplar's closest pair (per class pair, / u)"),
    });
    return t;
  }
};

class SeparationPointTerm : public PointTerm {
 public:
  explicit SeparationPointTerm(const SeparationOptions& o) : fraction_(o.fraction) {}
  void begin_class(const ClassStage& s) override {
    term_ = std::make_unique<SeparationTerm>(s.exemplar, s.output, s.moving, s.frozen, s.upscale, fraction_, s.device,
                                             s.window_side);
  }
  bool in_windows() const override { return true; }
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& frozen) override {
    return (*term_)(moving, frozen);
  }

 private:
  double fraction_;
  std::unique_ptr<SeparationTerm> term_;
};

}  // namespace

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::PointTermRegistry, "point_term", "separation", ppsynth::SeparationOptions::params(),
                        "soft minimum distance: fraction x the exemplar's closest pair per class pair / u (at least r_i + r_j)",
                        [](const ppsynth::SeparationOptions& o, const std::string&) -> std::unique_ptr<ppsynth::PointTerm> {
                          return std::make_unique<ppsynth::SeparationPointTerm>(o);
                        })
