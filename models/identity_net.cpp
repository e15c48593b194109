// "identity": no filter network (Fig. 12b, "Gabor only"): every block's features are the
// maps themselves, so the losses act on the Gabor maps directly (published encode2).
#include "core/config/params.hpp"
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

struct IdentityOptions {
  int depth = 3;
  static const ParamTable<IdentityOptions>& params() {
    static const ParamTable<IdentityOptions> t("method.feature_net", {
        param("depth", &IdentityOptions::depth, "int [1, 16]", "feature layers, each the maps themselves"),
    });
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::FeatureNetRegistry, "feature_net", "identity", ppsynth::IdentityOptions::params(),
                        "no filters: the maps themselves at every layer (Fig. 12b)",
                        [](const ppsynth::IdentityOptions& o, const std::string&, int, uint64_t) -> std::unique_ptr<ppsynth::FeatureNet> {
                          return std::make_unique<ppsynth::IdentityNet>(o.depth);
                        })
