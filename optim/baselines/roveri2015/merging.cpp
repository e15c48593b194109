#include "optim/baselines/roveri2015/merging.hpp"

#include <algorithm>
#include <cmath>

#include "optim/baselines/roveri2015/energy.hpp"

namespace ppsynth::roveri2015 {

namespace {

void merge_positions(SynthesisState& st, const MergeOptions& opt, MergeResult& res) {
  const size_t n = st.out.size();
  std::vector<Vec2> g;
  double E = output_energy(st, &g);
  res.energy_before = E;
  double gmax = 0;
  for (const Vec2& v : g) gmax = std::max(gmax, std::hypot(v.x, v.y));
  if (!(gmax > 0) || n == 0) {
    res.energy = E;
    return;
  }
  double eta = opt.step * st.kp.sigma / gmax;
  const std::vector<Vec2> start = st.out.x;
  for (int it = 0; it < opt.iterations; ++it) {
    const std::vector<Vec2> old = st.out.x;
    bool accepted = false;
    double moved = 0;
    for (int tries = 0; tries < 20; ++tries) {
      moved = 0;
      for (size_t i = 0; i < n; ++i) {
        const Vec2 p = st.confine({old[i].x - eta * g[i].x, old[i].y - eta * g[i].y});
        moved += std::hypot(p.x - old[i].x, p.y - old[i].y);
        st.out.x[i] = p;
      }
      st.rebuild_output_index();
      std::vector<Vec2> gn;
      const double En = output_energy(st, &gn);
      if (En < E) {
        E = En;
        g.swap(gn);
        eta *= 1.2;
        accepted = true;
        break;
      }
      eta *= 0.5;
    }
    if (!accepted) {
      st.out.x = old;
      st.rebuild_output_index();
      break;
    }
    ++res.iterations;
    if (moved / double(n) < opt.tolerance * st.kp.sigma) break;
  }
  res.energy = E;
}

void merge_attributes(SynthesisState& st, const ChannelEncoder& enc, const MergeOptions& opt, MergeResult& res) {
  if (enc.channels() <= 1 || opt.attribute_iterations <= 0 || st.out.size() == 0) return;
  const std::vector<double> start = st.out.a;
  std::vector<int> cls0(st.out.size());
  for (size_t i = 0; i < st.out.size(); ++i) cls0[i] = enc.decode_class(st.out.attr(i));
  const double E0 = res.energy;
  std::vector<double> g;
  double E = output_energy(st, nullptr, &g);
  double gmax = 0;
  for (double v : g) gmax = std::max(gmax, std::abs(v));
  if (!(gmax > 0)) return;
  double eta = 0.25 / gmax;  // largest first change: a quarter of a one-hot unit
  for (int it = 0; it < opt.attribute_iterations; ++it) {
    const std::vector<double> old = st.out.a;
    bool accepted = false;
    for (int tries = 0; tries < 20 && !accepted; ++tries) {
      for (size_t t = 0; t < old.size(); ++t) st.out.a[t] = old[t] - eta * g[t];
      std::vector<double> gn;
      const double En = output_energy(st, nullptr, &gn);
      if (En < E) {
        E = En;
        g.swap(gn);
        eta *= 1.2;
        accepted = true;
      } else {
        eta *= 0.5;
      }
    }
    if (!accepted) {
      st.out.a = old;
      break;
    }
  }
  for (size_t i = 0; i < st.out.size(); ++i) enc.snap(st.out.attr(i));
  const double Es = output_energy(st);
  if (Es < E0) {
    res.energy = Es;
    for (size_t i = 0; i < st.out.size(); ++i) res.class_changes += enc.decode_class(st.out.attr(i)) != cls0[i];
  } else {
    st.out.a = start;
  }
}

}  // namespace

MergeResult merge(SynthesisState& st, const ChannelEncoder& enc, const MergeOptions& opt) {
  MergeResult res;
  merge_positions(st, opt, res);
  merge_attributes(st, enc, opt, res);
  return res;
}

}  // namespace ppsynth::roveri2015
