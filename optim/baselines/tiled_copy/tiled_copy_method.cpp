// "tiled_copy": the trivial by-example baseline. The exemplar (mapped to the unit square) is
// tiled u x u and the tiling shifted by an offset on the torus: every point keeps its class
// and attributes (radii divided by u). Locally it is the exemplar itself, so it is the floor
// a structure-preserving method can hope for, and it shows what a metric rewards besides
// structure: with the default random offset the copies no longer line up with the
// evaluation's quadrant windows (docs/method.md, "What the per-class criterion measures").
// An offset of [0, 0] puts one copy in each quadrant (every quadrant metric is then 0).
#include <random>

#include "core/config/config.hpp"
#include "core/error.hpp"
#include "optim/method.hpp"

namespace ppsynth {

namespace {

class TiledCopyMethod : public SynthesisMethod {
 public:
  explicit TiledCopyMethod(const nlohmann::json& p) {
    const auto& o = p.at("offset");
    if (o.is_null()) return;
    if (!o.is_array() || o.size() != 2 || !o[0].is_number() || !o[1].is_number())
      throw config_error("method.offset", "expected null (a seeded random offset) or [x, y] (unit-square units)");
    offset_ = {o[0].get<double>(), o[1].get<double>()};
    random_ = false;
  }

  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override {
    validate(exemplar, "exemplar");
    if (ctx.output.upscale < 1) throw InputError("tiled_copy: upscale must be >= 1");
    const int u = ctx.output.upscale;
    Vec2 off = offset_;
    if (random_) {  // seeded: the same seed gives the same copy
      std::mt19937_64 rng(ctx.seed);
      std::uniform_real_distribution<double> uni(0.0, 1.0);
      off.x = uni(rng);
      off.y = uni(rng);
    }
    const PointSet unit = exemplar.mapped_to(Domain{});
    PointSet out(Domain{});
    out.set_class_labels(unit.class_labels());
    for (auto& n : unit.attribute_names()) out.add_attribute(n);
    const auto radius_col = unit.attribute_index("radius");
    ctx.start(out);
    auto wrap = [](double v) { return v - std::floor(v); };
    for (int a = 0; a < u; ++a)
      for (int b = 0; b < u; ++b)
        for (size_t i = 0; i < unit.size(); ++i) {
          auto attrs = unit.attributes_of(i);
          if (radius_col) attrs[*radius_col] /= u;
          out.add(Vec2{wrap((unit[i].x + a) / u + off.x), wrap((unit[i].y + b) / u + off.y)}, unit.cls(i), attrs);
        }
    return out;
  }

 private:
  Vec2 offset_{0, 0};
  bool random_ = true;
};

}  // namespace

}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::MethodRegistry, "tiled_copy", (nlohmann::json{{"offset", nullptr}}),
                 (nlohmann::json{{"offset", "[-1e6, 1e6]"}}),
                 "the exemplar tiled u x u, shifted on the torus (offset null = seeded random, or [x, y]): the copy baseline",
                 [](const nlohmann::json& p) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                   return std::make_unique<ppsynth::TiledCopyMethod>(p);
                 })
