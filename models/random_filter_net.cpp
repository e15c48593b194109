#include "models/random_filter_net.hpp"

namespace ppsynth {

RandomFilterNet::RandomFilterNet(RandomFilterNetOptions o) : opt_(o) {
  TORCH_CHECK(o.depth >= 1 && o.channels >= 1 && o.kernel_size % 2 == 1, "RandomFilterNet: bad options");
  // Draw every weight from the run's seed, independent of anything drawn before.
  torch::manual_seed(o.seed);
  auto make = [&](int in, int out, int stride) {
    auto conv = torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, o.kernel_size).stride(stride).padding(o.kernel_size / 2));
    torch::NoGradGuard ng;
    torch::nn::init::xavier_uniform_(conv->weight);
    convs_.push_back(register_module("conv" + std::to_string(convs_.size()), conv));
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
}

torch::Tensor RandomFilterNet::activate(const torch::Tensor& x) const {
  torch::Tensor y = x;
  if (opt_.instance_norm)
    y = torch::instance_norm(y, {}, {}, {}, {}, /*use_input_stats=*/true, 0.1, 1e-5, /*cudnn_enabled=*/false);
  // In place, as the published nn.ReLU(inplace=True): neither the norm nor the conv needs
  // its output for backward, and it saves a full-resolution buffer per layer.
  if (opt_.relu) y = torch::relu_(y);
  return y;
}

Features RandomFilterNet::forward(const torch::Tensor& maps) {
  Features out;
  const bool cast = opt_.dtype != maps.scalar_type() && opt_.dtype != torch::kFloat32;
  torch::Tensor x = cast ? maps.to(opt_.dtype) : maps;
  size_t next_block = 0;
  for (size_t i = 0; i < convs_.size(); ++i) {
    x = activate(convs_[i]->forward(x));
    if (next_block < block_end_.size() && static_cast<int>(i) == block_end_[next_block]) {
      out.push_back(cast ? x.to(maps.scalar_type()) : x);
      ++next_block;
    }
  }
  return out;
}

}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::FeatureNetRegistry, "random",
                 (ppsynth::json{{"channels", 120}, {"kernel_size", 7}, {"depth", 3},
                                {"instance_norm", true}, {"relu", true}, {"precision", "float32"}}),
                 "the paper's random-filter network (Glorot-uniform, frozen)",
                 [](const ppsynth::json& p, int in_channels, uint64_t seed) -> std::unique_ptr<ppsynth::FeatureNet> {
                   ppsynth::RandomFilterNetOptions o;
                   o.in_channels = in_channels;
                   o.channels = ppsynth::get_int(p, "channels", "feature_net");
                   o.kernel_size = ppsynth::get_int(p, "kernel_size", "feature_net");
                   o.depth = ppsynth::get_int(p, "depth", "feature_net");
                   o.instance_norm = p["instance_norm"];
                   o.relu = p["relu"];
                   o.seed = seed;
                   const std::string prec = p["precision"].get<std::string>();
                   if (prec == "bfloat16") o.dtype = torch::kBFloat16;
                   else if (prec != "float32")
                     throw ppsynth::config_error("feature_net.precision", "expected \"float32\" or \"bfloat16\", got \"" + prec + "\"");
                   if (o.channels < 1) throw ppsynth::config_error("feature_net.channels", "must be >= 1");
                   if (o.kernel_size < 1 || o.kernel_size % 2 == 0)
                     throw ppsynth::config_error("feature_net.kernel_size", "must be odd and >= 1");
                   if (o.depth < 1) throw ppsynth::config_error("feature_net.depth", "must be >= 1");
                   return std::make_unique<ppsynth::RandomFilterNet>(o);
                 })
