#include "core/procedural/pptbf_points.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

#include "core/error.hpp"
#include "core/procedural/pptbf.hpp"

namespace ppsynth {

PointSet pptbf_process_points(const PptbfParams& params) {
  PptbfParams undeformed = params;
  undeformed.ampli[0] = 0;
  PptbfEvaluator ev(undeformed);
  pptbf_impl::Rect box{{1e300, 1e300}, {-1e300, -1e300}};
  for (Vec2 c : {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}, Vec2{1, 1}}) {
    const Vec2 m = ev.to_model(c);
    box.lo = {std::min(box.lo.x, m.x), std::min(box.lo.y, m.y)};
    box.hi = {std::max(box.hi.x, m.x), std::max(box.hi.y, m.y)};
  }
  std::vector<pptbf_impl::FeaturePoint> pts;
  ev.point_process().points_in_box(box, pts);
  PointSet out(Domain{0, 0, 1, 1, false});
  for (const auto& fp : pts) {
    const Vec2 q = ev.model_to_image(fp.p);
    if (q.x >= 0 && q.x < 1 && q.y >= 0 && q.y < 1) out.add(q);
  }
  return out;
}

PointSet pptbf_threshold_points(const PptbfParams& params, const ThresholdSampling& s) {
  if (s.n <= 0) throw InputError("threshold sampling: n must be positive");
  if (!(s.min_dist >= 0) || !std::isfinite(s.threshold)) throw InputError("threshold sampling: bad min_dist or threshold");
  PptbfEvaluator ev(params);
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const long long attempts = s.max_attempts > 0 ? s.max_attempts : 500LL * s.n;
  // uniform grid of cell size min_dist for the distance test
  const double cell = s.min_dist > 0 ? s.min_dist : 1.0;
  const int gn = std::max(1, static_cast<int>(std::floor(1.0 / cell)));
  std::unordered_map<long long, std::vector<Vec2>> grid;
  auto gkey = [&](int i, int j) { return static_cast<long long>(i) * 1000003LL + j; };
  PointSet out(Domain{0, 0, 1, 1, false});
  for (long long a = 0; a < attempts && static_cast<int>(out.size()) < s.n; ++a) {
    const Vec2 q{U(rng), U(rng)};
    const int gi = std::min(gn - 1, static_cast<int>(q.x * gn)), gj = std::min(gn - 1, static_cast<int>(q.y * gn));
    bool ok = true;
    if (s.min_dist > 0) {
      for (int di = -1; di <= 1 && ok; ++di)
        for (int dj = -1; dj <= 1 && ok; ++dj) {
          auto it = grid.find(gkey(gi + di, gj + dj));
          if (it == grid.end()) continue;
          for (const Vec2& o : it->second)
            if (std::hypot(o.x - q.x, o.y - q.y) < s.min_dist) { ok = false; break; }
        }
    }
    if (!ok || !(ev(q.x, q.y) > s.threshold)) continue;
    out.add(q);
    grid[gkey(gi, gj)].push_back(q);
  }
  return out;
}

double pptbf_quantile(const PptbfParams& params, double q, int res) {
  if (!(q >= 0 && q <= 1)) throw InputError("quantile must be in [0,1]");
  GrayImage img = render_pptbf(params, res, res);
  std::vector<float> v = img.pixels;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

}  // namespace ppsynth
