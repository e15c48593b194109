#pragma once
// Reading and writing point files: the one entry point for every stage (exemplars in,
// synthesis outputs out, conversions). Four formats, each described in its own header:
//   GaborInt        gabor_int_format.hpp        `CLASS X Y [ATTR..]` integers (Gabor paper)
//   PointSynthesis  point_synthesis_format.hpp  `x y c2 c3 [c4]` pixel units (Tu et al. 2019)
//   Plain           plain_text_format.hpp       `# x y class radius` + rows (this project)
//   Json            json_format.hpp             {"domain", "class_labels", "attributes", "points"}
// Every error caused by the file is an InputError "path:line: what" (file_error).
#include <string>

#include "core/formats/format_options.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

// Reads a point file. Format::Auto detects it (detect_format). The result is validated
// (core/point_set.hpp validate: finite, inside the domain, no empty class) and a warning
// lists coincident points (they are reported, not rejected).
PointSet read_points(const std::string& path, const ReadOptions& opts = {});

// Writes atomically (temp file + rename). Format::Auto: ".json" -> Json, else Plain.
void write_points(const std::string& path, const PointSet& ps, Format format = Format::Auto);

// The text a writer would produce (write_points = this + atomic write). Auto is Plain.
std::string format_points(const PointSet& ps, Format format);
// Parses `text` as if read from `source` (tests, stdin); Auto detects from text + name.
// No validation or coincidence report (read_points adds those).
PointSet parse_points(const std::string& text, const std::string& source, const ReadOptions& opts = {});

// "auto", "gabor", "point-synthesis", "plain", "json" (also "gabor-int", "ps", "txt");
// anything else throws InputError listing the names.
Format parse_format(const std::string& name);
// The canonical name used by parse_format ("gabor", "point-synthesis", ...).
std::string format_name(Format format);
// "per-axis" (PerAxisMinMax) or "uniform"; InputError otherwise.
AxisScaling parse_axis_scaling(const std::string& name);
std::string axis_scaling_name(AxisScaling scaling);

// Detection, first match wins:
//   1. extension .json, or first non-blank character '{'          -> Json
//   2. first non-blank line starts with '#'                         -> Plain
//   3. Gabor shape (looks_like_gabor_int: integers, CLASS multiples
//      of 1000, X/Y in 0..10000, optional "K id..." header)         -> GaborInt
//   4. rows of >= 4 fields                                          -> PointSynthesis
//   5. otherwise (2 or 3 fields, no header)                         -> Plain
// Throws InputError for a missing or empty file.
Format detect_format(const std::string& path);
Format detect_format_of_text(const std::string& text, const std::string& source);

}  // namespace ppsynth
