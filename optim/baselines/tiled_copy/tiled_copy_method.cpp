// "tiled_copy": the trivial by-example baseline. The exemplar (mapped to the unit square) is
// tiled u x u and the tiling shifted by an offset on the torus: every point keeps its class
// and attributes (radii divided by u). Locally it is the exemplar itself, so it is the floor
// a structure-preserving method can hope for, and it shows what a metric rewards besides
// structure: with the default random offset the copies no longer line up with the
// evaluation's quadrant windows (docs/lab/method_measurements.md, "What the per-class criterion measures").
// An offset of [0, 0] puts one copy in each quadrant (every quadrant metric is then 0).
//
// Rectangle outputs (core/output_shape.hpp): copies of the exemplar in exemplar units (no
// rescaling, radii kept) tiled from the origin of [0, W] x [0, H], shifted by the offset
// (exemplar units; random = uniform within one tile), the partial tiles at the edges cropped.
// Border: a tiling has no synthesis border, so a clean-border canvas would crop to these same points; it tiles the rectangle directly.
// ctx.initialization is ignored (nothing is optimized).
#include <cmath>
#include <random>

#include "core/config/config.hpp"
#include "core/config/params.hpp"
#include "core/error.hpp"
#include "optim/method/method.hpp"

namespace ppsynth {

namespace {

// Its one key, declared once: the offset, null (seeded random) or [x, y] (each in its bound).
struct TiledCopyOptions {
  nlohmann::json offset;
  static const ParamTable<TiledCopyOptions>& params() {
    static const ParamTable<TiledCopyOptions> t("method", {
        param("offset", &TiledCopyOptions::offset, "[-1e6, 1e6]",
              "null: a seeded random shift; or [x, y] (output units: the unit square, or exemplar units on a rectangle)"),
    });
    return t;
  }
};

class TiledCopyMethod : public SynthesisMethod {
 public:
  // The offset's type is checked here: a bound checks only the numbers it holds.
  TiledCopyMethod(const TiledCopyOptions& options, const std::string& key) {
    const nlohmann::json& o = options.offset;
    if (o.is_null()) return;
    if (!o.is_array() || o.size() != 2 || !o[0].is_number() || !o[1].is_number())
      throw config_error(key + ".offset",
                         "expected null (a seeded random offset) or [x, y] (output units: the unit square, or exemplar units on a rectangle)");
    offset_ = {o[0].get<double>(), o[1].get<double>()};
    random_ = false;
  }

  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override {
    validate(exemplar, "exemplar");
    Vec2 off = offset_;
    if (random_) {  // seeded: the same seed gives the same copy
      std::mt19937_64 rng(ctx.seed);
      std::uniform_real_distribution<double> uni(0.0, 1.0);
      off.x = uni(rng);
      off.y = uni(rng);
    }
    if (ctx.output.rectangle) return tile_rectangle(exemplar, ctx, off);
    if (ctx.output.upscale < 1) throw InputError("tiled_copy: upscale must be >= 1");
    const int u = ctx.output.upscale;
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
  // The rectangle [0, W] x [0, H] covered by copies of the exemplar's window E, tile (a, b)
  // at (a w + s.x, b h + s.y) with the shift s = offset reduced modulo the tile (a random
  // offset's unit draws scaled to one tile: shifting by a whole tile changes nothing).
  PointSet tile_rectangle(const PointSet& exemplar, const SynthesisContext& ctx, Vec2 off) const {
    const Domain D = ctx.output.domain(), E = exemplar.domain();
    const double w = E.width(), h = E.height();
    if (!(w > 0 && h > 0)) throw InputError("tiled_copy: the exemplar's domain has no area");
    if (random_) off = {off.x * w, off.y * h};
    const double sx = off.x - w * std::floor(off.x / w), sy = off.y - h * std::floor(off.y / h);
    PointSet tiled = exemplar.tiled_over(D, Vec2{sx, sy});
    ctx.start(tiled.subset({}));  // the start of a copy: nothing placed yet
    return tiled;
  }

  Vec2 offset_{0, 0};
  bool random_ = true;
};

}  // namespace

}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::MethodRegistry, "method", "tiled_copy", ppsynth::TiledCopyOptions::params(),
                        "the exemplar tiled u x u (or over an output rectangle), shifted (offset null = seeded random, or [x, y]): the copy baseline",
                        [](const ppsynth::TiledCopyOptions& o, const std::string& key) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                          return std::make_unique<ppsynth::TiledCopyMethod>(o, key);
                        })
