#pragma once
// Which patches evaluate() compares with the exemplar (patches.hpp):
//   quadrants : the paper's 4 quadrants of the output (quadrant.hpp); fits a square output
//               holding about 4 times the exemplar's points (the paper's u = 2). Each patch
//               and the exemplar are mapped onto the unit square, so a quadrant must have the
//               exemplar's shape: asked for on an output whose quadrants' aspect ratio is more
//               than 1 % from the exemplar's (a 4 x 1 strip against a square), it is refused
//               (InputError saying what fits) instead of comparing squashed patches.
//   crops     : N random exemplar-sized crops (crops.hpp); fits any output at least as large
//               as the exemplar at its density (rectangles in exemplar units, 10,000 points)
//   auto      : quadrants when the output domain and the exemplar's are square (sides equal
//               to 1e-9) and the output holds 3 to 5 times the exemplar's points, else crops,
//               so every u = 2 result of the paper's protocol stays what it was.
// When crops do not fit, the error says whether quadrants would (the output has the
// exemplar's shape) or that neither does.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

enum class PatchProtocol { Auto, Quadrants, Crops };

// "auto" | "quadrants" | "crops" (InputError naming --protocol and the accepted names).
PatchProtocol parse_patch_protocol(const std::string& name);
const char* patch_protocol_name(PatchProtocol p);

inline constexpr int kDefaultCrops = 20;
inline constexpr int kMaxCrops = 10000;
inline constexpr uint64_t kDefaultCropSeed = 1;

struct ProtocolPlan {
  PatchProtocol requested = PatchProtocol::Auto;
  PatchProtocol used = PatchProtocol::Quadrants;  // never Auto
  std::string reason;            // why `used` (auto's rule in words, or "requested")
  std::vector<Domain> windows;   // on the output domain, one per patch
  double zoom = 1;               // output units per exemplar unit: given, or from the densities
  double patch_width = 0, patch_height = 0;  // output units
  uint64_t seed = 0;             // crops only
};

// Resolves `requested` for this pair and places the windows. InputError when crops do not
// fit the output (crops.hpp), or quadrants were asked for and do not have the exemplar's shape.
// `zoom` > 0: the output's scale as its run made it (crops.hpp); 0: from the densities.
ProtocolPlan plan_protocol(const PointSet& exemplar, const PointSet& output, PatchProtocol requested,
                           int crops = kDefaultCrops, uint64_t seed = kDefaultCropSeed, double zoom = 0);

// evaluate()'s "protocol" object: { "name", "requested", "reason", "patches",
// "crop_size": [w, h] (output units: a quadrant's or a crop's), "zoom" } and for crops
// "seed" and "windows": [[x0, y0, x1, y1], ...] (output coordinates).
nlohmann::json protocol_json(const ProtocolPlan& plan);
// One line for the table: "protocol: crops, 20 crops of 1 x 1 output units (...); auto: ...".
std::string protocol_line(const nlohmann::json& protocol);

}  // namespace ppsynth
