// "gram": L = sum over layers of sum_{t1,t2} (G_out - G_exemplar)^2, G = F F^T / (C H W)
// (paper §3.1; the published code's normalization). Captures local structure.
#include "losses/gram_loss.hpp"

namespace ppsynth {

namespace {

// G = s m^T m for a pixels x channels matrix m (s m m^T for channels x pixels). Its gradient
// is one matrix product, 2 s m (dG + dG^T)/2 -- autograd's mm backward spends two (one per
// operand), and the Gram's cost is mostly those products (docs/lab/performance/README.md,
// "Per phase", step 5).
class GramFunction : public torch::autograd::Function<GramFunction> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* ctx, torch::Tensor m, bool pixels_by_channels,
                               double scale) {
    ctx->save_for_backward({m});
    ctx->saved_data["pixels_by_channels"] = pixels_by_channels;
    ctx->saved_data["scale"] = scale;
    return (pixels_by_channels ? torch::mm(m.t(), m) : torch::mm(m, m.t())) * scale;
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad) {
    auto m = ctx->get_saved_variables()[0];
    const double scale = ctx->saved_data["scale"].toDouble();
    auto sym = (grad[0] + grad[0].t()) * scale;
    auto gm = ctx->saved_data["pixels_by_channels"].toBool() ? torch::mm(m, sym) : torch::mm(sym, m);
    return {gm, torch::Tensor(), torch::Tensor()};
  }
};

}  // namespace

torch::Tensor gram_matrix(const torch::Tensor& F) {
  const double scale = 1.0 / static_cast<double>(F.numel());
  // Channels-last features (the network's fast path) are a pixels x channels matrix as they
  // lie in memory: use that view instead of copying to channels x pixels.
  if (F.dim() == 4 && F.size(0) == 1 && !F.is_contiguous() && F.is_contiguous(at::MemoryFormat::ChannelsLast))
    return GramFunction::apply(F.permute({0, 2, 3, 1}).reshape({-1, F.size(1)}), true, scale);
  return GramFunction::apply(F.reshape({F.size(1), -1}), false, scale);
}

GramLoss::GramLoss(std::vector<int> layers) : layers_(std::move(layers)) {}

void GramLoss::set_target(const Features& ex, const LossContext&) {
  targets_.clear();
  for (int l : layers_) targets_.push_back(gram_matrix(layer_of(ex, l, "gram")).detach());
}

torch::Tensor GramLoss::forward(const Features& out) {
  torch::Tensor loss;
  for (size_t i = 0; i < layers_.size(); ++i) {
    auto d = (gram_matrix(layer_of(out, layers_[i], "gram")) - targets_[i]).pow(2).sum();
    loss = loss.defined() ? loss + d : d;
  }
  return loss;
}

}  // namespace ppsynth

namespace ppsynth {
namespace {
struct GramOptions {
  std::vector<int> layers{0, 1, 2};
  double weight = 0.08;
  static const ParamTable<GramOptions>& params() {
    using O = GramOptions;
    static const ParamTable<O> t("loss", layer_loss_params<O>());
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::LossRegistry, "loss", "gram", ppsynth::GramOptions::params(),
                        "Gram-matrix loss over the listed layers (local structure)",
                        [](const ppsynth::GramOptions& o, const std::string& key) -> std::unique_ptr<ppsynth::FeatureLoss> {
                          return std::make_unique<ppsynth::GramLoss>(ppsynth::given_layers(o.layers, key));
                        })
