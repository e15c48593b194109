#include "models/random_filter_net.hpp"

#include "models/network_precision.hpp"

namespace ppsynth {

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;
constexpr auto kChannelsLast = at::MemoryFormat::ChannelsLast;

// A convolution with frozen filters: the backward returns the input gradient only. At stride
// 1 that gradient is the convolution of the output gradient with the filters transposed
// (in <-> out) and flipped, which oneDNN runs as fast as a forward convolution; LibTorch's own
// backward is slower (docs/lab/performance/README.md, "Per phase", step 4). Stride 2 keeps
// LibTorch's input-gradient kernel.
class FrozenConvFunction : public torch::autograd::Function<FrozenConvFunction> {
 public:
  static torch::Tensor forward(AutogradContext* ctx, torch::Tensor x, torch::Tensor w, torch::Tensor b,
                               torch::Tensor w_grad, int64_t stride, int64_t pad) {
    ctx->save_for_backward({w, w_grad});
    ctx->saved_data["stride"] = stride;
    ctx->saved_data["pad"] = pad;
    ctx->saved_data["input_sizes"] = x.sizes().vec();
    return torch::conv2d(x, w, b, stride, pad);
  }

  static variable_list backward(AutogradContext* ctx, variable_list grad_out) {
    auto saved = ctx->get_saved_variables();
    const int64_t stride = ctx->saved_data["stride"].toInt(), pad = ctx->saved_data["pad"].toInt();
    auto g = grad_out[0].contiguous(kChannelsLast);
    torch::Tensor gi;
    if (stride == 1) {
      gi = torch::conv2d(g, saved[1], {}, 1, saved[0].size(-1) - 1 - pad);
    } else {
      // Only the input's shape is read; its values are not needed for the input gradient.
      auto shape = torch::empty(ctx->saved_data["input_sizes"].toIntVector(), g.options().memory_format(kChannelsLast));
      gi = std::get<0>(at::convolution_backward(g, shape, saved[0], at::OptionalIntArrayRef(), {stride, stride}, {pad, pad}, {1, 1},
                                                false, {0, 0}, 1, {true, false, false}));
    }
    return {gi, torch::Tensor(), torch::Tensor(), torch::Tensor(), torch::Tensor(), torch::Tensor()};
  }
};

}  // namespace

RandomFilterNet::RandomFilterNet(RandomFilterNetOptions o) : opt_(o) {
  TORCH_CHECK(o.depth >= 1 && o.channels >= 1 && o.kernel_size % 2 == 1, "RandomFilterNet: bad options");
  // Draw every weight from the run's seed, independent of anything drawn before.
  torch::manual_seed(o.seed);
  auto make = [&](int in, int out, int stride) {
    auto conv = torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, o.kernel_size).stride(stride).padding(o.kernel_size / 2));
    torch::NoGradGuard ng;
    torch::nn::init::xavier_uniform_(conv->weight);
    convs_.push_back(register_module("conv" + std::to_string(convs_.size()), conv));
    strides_.push_back(stride);
  };
  make(o.in_channels, o.channels, 1);
  make(o.channels, o.channels, 1);
  block_end_.push_back(1);
  for (int b = 1; b < o.depth; ++b) {
    make(o.channels, o.channels, 2);
    block_end_.push_back(static_cast<int>(convs_.size()) - 1);
  }
  freeze(*this);
  if (o.dtype != torch::kFloat32) this->to(o.dtype);
  // The fast path in float32 and in bfloat16 (oneDNN's channels-last bf16 convolutions, on the
  // CPU's bf16 units where it has them).
  if (o.fast_cpu && (o.dtype == torch::kFloat32 || o.dtype == torch::kBFloat16))
    for (auto& c : convs_) {
      w_cl_.push_back(c->weight.contiguous(kChannelsLast));
      w_grad_cl_.push_back(c->weight.transpose(0, 1).flip({2, 3}).contiguous(kChannelsLast));
    }
}

bool RandomFilterNet::use_fast_path(const torch::Tensor& maps) const {
  return !w_cl_.empty() && maps.scalar_type() == torch::kFloat32 && maps.dim() == 4 && maps.size(0) == 1 &&
         maps.device().is_cpu();
}

torch::Tensor RandomFilterNet::activate(const torch::Tensor& x, bool fast) const {
  torch::Tensor y = x;
  // For one image instance norm is batch norm with batch statistics; LibTorch's batch norm
  // keeps channels-last (its instance norm would copy to NCHW and back at every layer).
  if (opt_.instance_norm && fast)
    y = torch::batch_norm(y, {}, {}, {}, {}, /*training=*/true, 0.1, 1e-5, /*cudnn_enabled=*/false);
  else if (opt_.instance_norm)
    y = torch::instance_norm(y, {}, {}, {}, {}, /*use_input_stats=*/true, 0.1, 1e-5, /*cudnn_enabled=*/false);
  // In place, as the published nn.ReLU(inplace=True): neither the norm nor the conv needs
  // its output for backward, and it saves a full-resolution buffer per layer.
  if (opt_.relu) y = torch::relu_(y);
  return y;
}

nlohmann::json RandomFilterNet::choices() const {
  return {{"precision", opt_.dtype == torch::kBFloat16 ? "bfloat16" : "float32"}, {"precision_reason", opt_.precision_reason}};
}

Features RandomFilterNet::forward(const torch::Tensor& maps) {
  Features out;
  const bool cast = opt_.dtype != maps.scalar_type() && opt_.dtype != torch::kFloat32;
  const bool fast = use_fast_path(maps);
  torch::Tensor x = cast ? maps.to(opt_.dtype) : maps;
  if (fast) x = x.contiguous(kChannelsLast);
  size_t next_block = 0;
  for (size_t i = 0; i < convs_.size(); ++i) {
    auto& c = convs_[i];
    x = fast ? FrozenConvFunction::apply(x, w_cl_[i], c->bias, w_grad_cl_[i], strides_[i], opt_.kernel_size / 2)
             : c->forward(x);
    x = activate(x, fast);
    if (next_block < block_end_.size() && static_cast<int>(i) == block_end_[next_block]) {
      out.push_back(cast ? x.to(maps.scalar_type()) : x);
      ++next_block;
    }
  }
  return out;
}

const ParamTable<RandomFilterNetOptions>& RandomFilterNetOptions::params() {
  using O = RandomFilterNetOptions;
  static const ParamTable<O> t("method.feature_net", {
      param("channels", &O::channels, "int [1, 4096]", "filters per layer"),
      param("kernel_size", &O::kernel_size, "int [1, 63]", "the filters' width (odd)"),
      param("depth", &O::depth, "int [1, 16]", "blocks, each a feature layer (3: the paper's)"),
      param("instance_norm", &O::instance_norm, "", "instance normalization after each convolution"),
      param("relu", &O::relu, "", "ReLU after each convolution"),
      param("precision", &O::precision, "", "the network's arithmetic: \"float32\", \"bfloat16\" or \"auto\" (models/network_precision.hpp)"),
  });
  return t;
}

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::FeatureNetRegistry, "feature_net", "random", ppsynth::RandomFilterNetOptions::params(),
                        "the paper's random-filter network (Glorot-uniform, frozen)",
                        [](ppsynth::RandomFilterNetOptions o, const std::string& key, int in_channels,
                           uint64_t seed) -> std::unique_ptr<ppsynth::FeatureNet> {
                          o.in_channels = in_channels;
                          o.seed = seed;
                          const ppsynth::NetworkPrecision prec = ppsynth::resolve_network_precision(o.precision, key + ".precision");
                          o.dtype = prec.dtype;
                          o.precision_reason = prec.reason;
                          if (o.kernel_size % 2 == 0) throw ppsynth::config_error(key + ".kernel_size", "must be odd");
                          return std::make_unique<ppsynth::RandomFilterNet>(o);
                        })
