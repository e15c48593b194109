#pragma once
// OutputShape: what a synthesis produces (the run config's "upscale" and "output" keys).
//
//   the paper's (no "output"):  the unit square holding u^2 times the exemplar's points;
//                               the pattern is the exemplar's zoomed out by u ("upscale").
//                               A rectangular exemplar (sides not equal) gets the rectangle
//                               [0, u W] x [0, u H] in exemplar units instead, as if "size"
//                               said so: the square would squeeze its pattern to the square's
//                               aspect.
//   {"size": [a, b]}:           a times the exemplar's width by b times its height (exemplar
//                               sides, so the same at any coordinate units): the rectangle
//                               [0, a W] x [0, b H] in exemplar units; points keep the
//                               exemplar's spacing; each class keeps its density.
//   {"points": N}:              a square of the area that holds N points at the exemplar's
//                               density (the exemplar's shape when it is not square: W/H kept).
//
// "border" (rectangles only): "clean" synthesizes on a canvas padded by "pad" exemplar units
// on every side and keeps the crop (the points that park on a synthesis border are cut off;
// counts are then the density's expectation, not exact); "context" pads the same way but
// fills the pad with the exemplar's own points, tiled and frozen, and moves only the
// rectangle's points (the Gabor method; exact counts: nothing parks, nothing is cut off);
// "published" synthesizes on the rectangle itself and keeps the method's border behavior.
// "pad": null or "auto" = 2 mean nearest-neighbor distances of the exemplar, or a length in
// exemplar units (docs/lab/large_outputs.md).
//
// Torch-free: every method (optim/method/method.hpp) gets one in its SynthesisContext.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

struct OutputShape {
  int upscale = 2;             // the paper's u (used when !rectangle)
  bool rectangle = false;      // true: "size" or "points" given, or a rectangular exemplar (exemplar units)
  bool from_upscale = false;   // the rectangle is u x u copies of a rectangular exemplar (no "output" given)
  double width = 0, height = 0;  // the output rectangle's size (exemplar units; rectangle only)
  bool clean_border = true;    // rectangle only: synthesize padded, keep the crop
  bool exemplar_pad = false;   // "context": the pad holds the tiled exemplar, frozen
  double pad = 0;              // resolved pad (exemplar units; 0 when !clean_border)

  // The domain of the output: the unit square, or [0, W] x [0, H].
  Domain domain() const;
  // The domain actually synthesized: domain() grown by `pad` on every side (rectangles with
  // clean borders), else domain().
  Domain canvas() const;
  // Where the synthesis moves points: the rectangle ("context": the pad is frozen), else canvas().
  Domain moving_area() const;
  // Methods without a frozen pad call this: "context" is then an error naming output.border.
  void require_no_exemplar_pad(const std::string& method) const;
  double exemplar_width = 1;    // the exemplar's domain width (exemplar units), for zoom()

  // Output units per exemplar unit: the paper's unit square holds u x u exemplars, so an
  // exemplar of width W is 1 / u of the square's side: 1 / (u W); rectangles are in exemplar
  // units: 1.
  double zoom() const { return rectangle ? 1.0 : 1.0 / (upscale * exemplar_width); }
  // Points of each exemplar class over `d` (an area in output units) at the exemplar's
  // density, rounded; at least 1 for a class of the exemplar.
  std::vector<size_t> class_counts(const PointSet& exemplar, const Domain& d) const;
  // What the output will hold: u^2 x |exemplar| exactly, or the rectangle's expectation.
  double expected_points(const PointSet& exemplar) const;
  // The config's shape in words ("u = 2 (unit square)", "4 x 1 exemplar units, clean border").
  std::string describe() const;
};

// Sides equal to 1e-9 of the longer.
bool is_square(const Domain& d);

template <class T>
class ParamTable;

// The run config's "output" block: its keys declared once (output_shape.cpp's table), read by
// resolve_output_shape.
struct OutputOptions {
  nlohmann::json size;    // null, or [a, b] in exemplar sides
  nlohmann::json points;  // null, or N
  std::string border = "clean";
  nlohmann::json pad;     // null or "auto", or a length in exemplar units
  static const ParamTable<OutputOptions>& params();
};

// The run config's defaults for "output": OutputOptions{} written out.
nlohmann::json output_defaults();
// From a resolved run config (its "upscale" and "output"); errors name the key.
// `exemplar` resolves "points" and the automatic pad.
OutputShape resolve_output_shape(const nlohmann::json& run_config, const PointSet& exemplar);
// How many times this process has called resolve_output_shape, so that a test can show that
// one synthesis resolves its shape once (optim/run/run_spec.hpp).
size_t output_shape_resolutions();

}  // namespace ppsynth
