#pragma once
// Reading and writing point files: the one entry point for every stage (exemplars in,
// synthesis outputs out, conversions). Four formats, each described in its own header:
//   GaborInt        gabor_int_format.hpp        `CLASS X Y [ATTR..]` integers (Gabor paper)
//   PointSynthesis  point_synthesis_format.hpp  `x y c2 c3 [c4]` pixel units (Tu et al. 2019)
//   Plain           plain_text_format.hpp       `# x y class radius` + rows (this project)
//   Json            json_format.hpp             {"domain", "class_labels", "attributes", "points"}
// Every error caused by the file is an InputError "path:line: what" (file_error).
#include <string>
#include <vector>

#include "core/formats/format_options.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

// Reads a point file ("shared:data/..." names a file of the shared folder, core/paths.hpp).
// Format::Auto detects it (detect_format). The result is validated
// (core/point_set.hpp validate: finite, inside the domain, radii > 0, no empty class) and a
// warning lists coincident points (they are reported, not rejected). Every error names the
// file (and line) and the format it was read as.
PointSet read_points(const std::string& path, const ReadOptions& opts = {});
// read_points with the format the file was read as (opts.format, or the detected one for
// Format::Auto): a caller that needs both reads the file once (a run keeps the exemplar's
// format for its outputs, optim/run/run_spec.hpp).
struct PointFile {
  PointSet points;
  Format format = Format::Auto;
};
PointFile read_point_file(const std::string& path, const ReadOptions& opts = {});
// How many point files this process has read (read_points, read_point_file, detect_format),
// so that a test can show that one synthesis reads its exemplar once.
size_t point_file_reads();

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

// Detection (Format::Auto) decides from the file's structure, before any reader runs, and
// once a format is chosen its reader alone reads the file: a flaw is reported by that reader
// on its own line ("f.txt:3: read as the published integer format (gabor): '65x27' is not an
// integer"), never by another reader, and a damaged file is never read as another format.
// A UTF-8 byte-order mark at the start is skipped. In order:
//   1. extension .json, or first non-blank character '{'            -> Json
//   2. first non-blank line starts with '#'                           -> Plain
//   3. otherwise the first 64 data lines are scored, each line against each format:
//        gabor            integers `CLASS X Y [ATTR..]`, X and Y in 0..10000, CLASS in the
//                         "K id_1..id_K" header of line 1 (K < 1000) or, without one, a
//                         positive multiple of 1000
//        point-synthesis  >= 4 numbers, the third a whole number
//        plain            `x y` or `x y class` in the unit square (class a whole number >= 0)
//      Gabor when at least half its lines fit (its lines with >= 4 fields fit Point-Synthesis
//      too: the more specific format wins), else the format most lines fit; when none fits
//      most lines, the one that fits the most lines, else by the field count of line 1
//      (>= 4: point-synthesis, else plain), marked as a guess.
// Ambiguity: when most lines also fit another format (a Gabor file without a header and with
// attributes fits Point-Synthesis too), or the choice was a guess, a reader's error says so
// and names `--format NAME` to choose. An explicit format is used as given.
// Throws InputError for a missing or empty file or a directory.
struct Detection {
  Format format = Format::Auto;
  std::string reason;            // "20 of the first 20 lines fit", "it starts with '{'", ...
  std::vector<Format> also_fits;  // other formats most of the first lines fit as well
  bool guessed = false;           // no format fits most of the first lines
};
Detection detect_format_details(const std::string& text, const std::string& source);
Format detect_format(const std::string& name);  // a path or "shared:data/...", as read_points
Format detect_format_of_text(const std::string& text, const std::string& source);

}  // namespace ppsynth
