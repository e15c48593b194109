// "sliced_wasserstein" (Heitz et al. 2021; Fig. 14 ablation): per layer, project every pixel's
// feature vector on C random unit directions, sort, and compare the sorted output
// projections with the exemplar's by MSE. The exemplar has u^2 times fewer pixels: its
// sorted values are repeated u^2 times (the published repeat_interleave) when the counts
// match exactly, else resampled as quantiles by linear interpolation. Directions are drawn
// once from the seed (the published code redraws them every 10 iterations for its "slice"
// variant; fixed directions keep runs deterministic and the loss comparable over time).
#include "losses/loss.hpp"

namespace ppsynth {
namespace {

class SlicedWassersteinLoss : public FeatureLoss {
 public:
  explicit SlicedWassersteinLoss(std::vector<int> layers) : layers_(std::move(layers)) {}

  void set_target(const Features& ex, const LossContext& ctx) override {
    dirs_.clear();
    targets_.clear();
    auto gen = at::detail::createCPUGenerator(ctx.seed);
    for (int l : layers_) {
      const auto& F = layer_of(ex, l, "sliced_wasserstein");
      const int64_t C = F.size(1);
      // Drawn on the CPU from the seed (the same directions on every device), moved once per stage.
      auto d = at::normal(0.0, 1.0, {C, C}, gen).to(F.device(), F.scalar_type());
      d = d / d.norm(2, 1, true);
      dirs_.push_back(d);
      targets_.push_back(project_sorted(F.detach(), d).detach());
    }
    upscale_ = ctx.upscale;
  }

  torch::Tensor forward(const Features& out) override {
    torch::Tensor loss;
    for (size_t i = 0; i < layers_.size(); ++i) {
      auto s = project_sorted(layer_of(out, layers_[i], "sliced_wasserstein"), dirs_[i]);
      auto t = match_length(targets_[i], s.size(1));
      auto d = (s - t).pow(2).mean();
      loss = loss.defined() ? loss + d : d;
    }
    return loss;
  }

 private:
  static torch::Tensor project_sorted(const torch::Tensor& F, const torch::Tensor& dirs) {
    auto f = F.reshape({F.size(1), -1});  // C x P
    return std::get<0>(torch::sort(torch::mm(dirs, f), 1));
  }
  torch::Tensor match_length(const torch::Tensor& t, int64_t n) const {
    const int64_t m = t.size(1);
    if (m == n) return t;
    if (n % m == 0) return t.repeat_interleave(n / m, 1);
    // Quantile resampling: position j of n maps to (j + 0.5) * m / n - 0.5 in the target.
    auto pos = ((torch::arange(n, t.options()) + 0.5) * (double(m) / n) - 0.5).clamp(0, m - 1);
    auto lo = pos.floor().to(torch::kLong), hi = (lo + 1).clamp_max(m - 1);
    auto w = pos - lo.to(pos.scalar_type());
    return t.index_select(1, lo) * (1 - w) + t.index_select(1, hi) * w;
  }
  std::vector<int> layers_;
  std::vector<torch::Tensor> dirs_, targets_;
  int upscale_ = 2;
};

}  // namespace
}  // namespace ppsynth

namespace ppsynth {
namespace {
struct SlicedWassersteinOptions {
  std::vector<int> layers{0, 1, 2};
  double weight = 1.0;
  static const ParamTable<SlicedWassersteinOptions>& params() {
    using O = SlicedWassersteinOptions;
    static const ParamTable<O> t("loss", layer_loss_params<O>());
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::LossRegistry, "loss", "sliced_wasserstein", ppsynth::SlicedWassersteinOptions::params(),
                        "sliced Wasserstein loss on per-pixel features (Heitz et al. 2021; Fig. 14)",
                        [](const ppsynth::SlicedWassersteinOptions& o, const std::string& key) -> std::unique_ptr<ppsynth::FeatureLoss> {
                          return std::make_unique<ppsynth::SlicedWassersteinLoss>(ppsynth::given_layers(o.layers, key));
                        })
