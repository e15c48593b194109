#pragma once
// The knobs of point-file reading, shared by core/formats/point_io.hpp (the public API) and
// the per-format readers. Include point_io.hpp, not this file, from outside core/formats.
#include <string>
#include <vector>

namespace ppsynth {

// The supported point-file formats (see the per-format headers in core/formats/):
//   GaborInt        the Gabor paper's integer files (gabor_int_format.hpp)
//   PointSynthesis  Tu et al.'s `x y c2 c3 [c4]` exemplars (point_synthesis_format.hpp)
//   Plain           this project's `# x y class attrs...` text (plain_text_format.hpp)
//   Json            this project's JSON (json_format.hpp)
// Auto means: detect from the content (read) / from the extension (write).
enum class Format { Auto, GaborInt, PointSynthesis, Plain, Json };

// How Point-Synthesis pixel coordinates are brought to the unit square:
//   PerAxisMinMax  x and y each min-max rescaled to [0,1] (as published; the aspect changes)
//   Uniform        one scale for both axes (aspect kept): the longer side spans [0,1], the
//                  domain is [0, w/s] x [0, h/s] with s = max(w, h).
enum class AxisScaling { PerAxisMinMax, Uniform };

struct ReadOptions {
  Format format = Format::Auto;
  AxisScaling scaling = AxisScaling::PerAxisMinMax;
  // Overrides the attribute-column names a format would choose by its rule (Gabor: see
  // gabor_attribute_names; Point-Synthesis: "c3", "c4"). Must match the column count.
  // Ignored by Plain and Json (their files name their columns).
  std::vector<std::string> attribute_names;
};

}  // namespace ppsynth
