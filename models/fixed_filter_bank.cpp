#include "models/fixed_filter_bank.hpp"

#include <cmath>

#include "core/config/params.hpp"

namespace ppsynth {

namespace {

torch::Tensor centered(const std::vector<std::vector<double>>& small, int K) {
  // Embeds an odd n x n kernel at the center of a K x K one.
  const int n = static_cast<int>(small.size()), off = (K - n) / 2;
  auto t = torch::zeros({K, K}, torch::kFloat64);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) t[r + off][c + off] = small[r][c];
  return t;
}

std::vector<torch::Tensor> gaussians(int K) {
  std::vector<torch::Tensor> out;
  for (double s : {0.5, 1.0, 1.5, 2.0}) {
    auto ax = torch::arange(K, torch::kFloat64) - (K / 2);
    auto g1 = torch::exp(-ax * ax / (2 * s * s));
    auto g = torch::outer(g1, g1);
    out.push_back(g / g.sum());
  }
  return out;
}

std::vector<torch::Tensor> sobels(int K) {
  return {centered({{-1, 0, 1}, {-2, 0, 2}, {-1, 0, 1}}, K), centered({{-1, -2, -1}, {0, 0, 0}, {1, 2, 1}}, K),
          centered({{0, 1, 2}, {-1, 0, 1}, {-2, -1, 0}}, K), centered({{-2, -1, 0}, {-1, 0, 1}, {0, 1, 2}}, K)};
}

std::vector<torch::Tensor> derivatives(int K) {
  return {centered({{0, 0, 0}, {1, -2, 1}, {0, 0, 0}}, K), centered({{0, 1, 0}, {0, -2, 0}, {0, 1, 0}}, K),
          centered({{0.25, 0, -0.25}, {0, 0, 0}, {-0.25, 0, 0.25}}, K), centered({{0, 1, 0}, {1, -4, 1}, {0, 1, 0}}, K)};
}

class FixedBankNet : public FeatureNet {
 public:
  FixedBankNet(torch::Tensor bank, int in_channels, int depth, bool instance_norm, bool relu)
      : C_(in_channels), depth_(depth), in_(instance_norm), relu_(relu) {
    // Depthwise weights: each input channel convolved with each of the B filters.
    bank_ = register_buffer("bank", bank.to(torch::kFloat32).repeat({in_channels, 1, 1, 1}));
  }
  Features forward(const torch::Tensor& maps) override {
    Features out;
    const int64_t pad = bank_.size(-1) / 2;
    auto w = bank_.to(maps.scalar_type());
    for (int l = 0; l < depth_; ++l) {
      auto y = torch::conv2d(maps, w, {}, /*stride=*/int64_t(1) << l, pad, 1, C_);
      if (in_) y = torch::instance_norm(y, {}, {}, {}, {}, true, 0.1, 1e-5, false);
      if (relu_) y = torch::relu(y);
      out.push_back(y);
    }
    return out;
  }

 private:
  int C_, depth_;
  bool in_, relu_;
  torch::Tensor bank_;
};

struct FixedBankOptions {
  std::string bank = "all";
  int kernel_size = 7;
  int depth = 3;
  bool instance_norm = true;
  bool relu = true;
  static const ParamTable<FixedBankOptions>& params() {
    using O = FixedBankOptions;
    static const ParamTable<O> t("method.feature_net", {
        param("bank", &O::bank, "", "the filters: \"gaussian\", \"sobel\", \"derivative\" or \"all\""),
        param("kernel_size", &O::kernel_size, "int [1, 63]", "the filters' width (odd, >= 3)"),
        param("depth", &O::depth, "int [1, 16]", "blocks, each a feature layer"),
        param("instance_norm", &O::instance_norm, "", "instance normalization after each convolution"),
        param("relu", &O::relu, "", "ReLU after each convolution"),
    });
    return t;
  }
};

}  // namespace

torch::Tensor filter_bank(const std::string& name, int K, const std::string& key_path) {
  if (K < 3 || K % 2 == 0) throw config_error(key_path + ".kernel_size", "must be odd and >= 3");
  std::vector<torch::Tensor> f;
  auto append = [&](std::vector<torch::Tensor> v) { f.insert(f.end(), v.begin(), v.end()); };
  if (name == "gaussian" || name == "all") append(gaussians(K));
  if (name == "sobel" || name == "all") append(sobels(K));
  if (name == "derivative" || name == "all") append(derivatives(K));
  if (f.empty()) throw config_error(key_path + ".bank", "unknown bank '" + name + "' (gaussian, sobel, derivative, all)");
  return torch::stack(f).unsqueeze(1);
}

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::FeatureNetRegistry, "feature_net", "fixed_bank", ppsynth::FixedBankOptions::params(),
                        "fixed filter banks (Fig. 10): gaussian | sobel | derivative | all",
                        [](const ppsynth::FixedBankOptions& o, const std::string& key, int in_channels,
                           uint64_t) -> std::unique_ptr<ppsynth::FeatureNet> {
                          auto bank = ppsynth::filter_bank(o.bank, o.kernel_size, key);
                          return std::make_unique<ppsynth::FixedBankNet>(bank, in_channels, o.depth, o.instance_norm, o.relu);
                        })
