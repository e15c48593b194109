// "identity": no filter network (Fig. 12b, "Gabor only"): every block's features are the
// maps themselves, so the losses act on the Gabor maps directly (published encode2).
#include "models/feature_net.hpp"

namespace ppsynth {
namespace {
class IdentityNet : public FeatureNet {
 public:
  explicit IdentityNet(int depth) : depth_(depth) {}
  Features forward(const torch::Tensor& maps) override { return Features(depth_, maps); }

 private:
  int depth_;
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::FeatureNetRegistry, "identity", (ppsynth::json{{"depth", 3}}),
                 (ppsynth::json{{"depth", "int [1, 16]"}}),
                 "no filters: the maps themselves at every layer (Fig. 12b)",
                 [](const ppsynth::json& p, const std::string& key, int, uint64_t) -> std::unique_ptr<ppsynth::FeatureNet> {
                   return std::make_unique<ppsynth::IdentityNet>(p["depth"].get<int>());
                 })
