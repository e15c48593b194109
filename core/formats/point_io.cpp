#include "core/formats/point_io.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/gabor_int_format.hpp"
#include "core/formats/json_format.hpp"
#include "core/formats/plain_text_format.hpp"
#include "core/formats/point_synthesis_format.hpp"
#include "core/formats/text_table.hpp"
#include "core/log.hpp"

namespace ppsynth {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void report_coincident(const PointSet& ps, const std::string& path) {
  const auto pairs = coincident_pairs(ps);
  if (pairs.empty()) return;
  std::ostringstream s;
  const size_t shown = std::min<size_t>(pairs.size(), 20);
  for (size_t i = 0; i < shown; ++i) s << (i ? ", " : "") << pairs[i].first << "=" << pairs[i].second;
  if (shown < pairs.size()) s << ", ...";
  spdlog::warn("{}: {} pair(s) of coincident points (0-based point indices): {}", path, pairs.size(), s.str());
}

}  // namespace

Format detect_format_of_text(const std::string& text, const std::string& source) {
  if (lower_extension(source) == ".json") return Format::Json;
  const auto b = text.find_first_not_of(" \t\r\n\f\v");
  if (b == std::string::npos) throw file_error(source, 0, "empty file: no points");
  if (text[b] == '{') return Format::Json;
  if (text[b] == '#') return Format::Plain;
  if (looks_like_gabor_int(text)) return Format::GaborInt;
  const auto rows = split_rows(text);
  if (!rows.empty() && rows.front().fields.size() >= 4) return Format::PointSynthesis;
  return Format::Plain;
}

Format detect_format(const std::string& path) { return detect_format_of_text(read_file_text(path), path); }

PointSet parse_points(const std::string& text, const std::string& source, const ReadOptions& opts) {
  const Format f = opts.format == Format::Auto ? detect_format_of_text(text, source) : opts.format;
  switch (f) {
    case Format::GaborInt: return parse_gabor_int(text, source, opts);
    case Format::PointSynthesis: return parse_point_synthesis(text, source, opts);
    case Format::Plain: return parse_plain_text(text, source);
    case Format::Json: return parse_json_points(text, source);
    case Format::Auto: break;
  }
  throw InputError("parse_points: unreachable format");
}

PointSet read_points(const std::string& path, const ReadOptions& opts) {
  const std::string text = read_file_text(path);
  PointSet ps = parse_points(text, path, opts);
  validate(ps, path);
  report_coincident(ps, path);
  spdlog::debug("read {}: {} points, {} classes, {} attributes", path, ps.size(), ps.num_classes(),
                ps.num_attributes());
  return ps;
}

std::string format_points(const PointSet& ps, Format format) {
  switch (format) {
    case Format::GaborInt: return print_gabor_int(ps);
    case Format::PointSynthesis: return print_point_synthesis(ps);
    case Format::Json: return print_json_points(ps);
    case Format::Plain:
    case Format::Auto: return print_plain_text(ps);
  }
  return print_plain_text(ps);
}

void write_points(const std::string& path, const PointSet& ps, Format format) {
  if (format == Format::Auto) format = lower_extension(path) == ".json" ? Format::Json : Format::Plain;
  write_text_atomic(path, format_points(ps, format));
}

Format parse_format(const std::string& name) {
  if (name == "auto") return Format::Auto;
  if (name == "gabor" || name == "gabor-int") return Format::GaborInt;
  if (name == "point-synthesis" || name == "ps") return Format::PointSynthesis;
  if (name == "plain" || name == "txt") return Format::Plain;
  if (name == "json") return Format::Json;
  throw InputError("unknown point format '" + name + "' (expected auto, gabor, point-synthesis, plain or json)");
}

std::string format_name(Format format) {
  switch (format) {
    case Format::Auto: return "auto";
    case Format::GaborInt: return "gabor";
    case Format::PointSynthesis: return "point-synthesis";
    case Format::Plain: return "plain";
    case Format::Json: return "json";
  }
  return "auto";
}

AxisScaling parse_axis_scaling(const std::string& name) {
  if (name == "per-axis") return AxisScaling::PerAxisMinMax;
  if (name == "uniform") return AxisScaling::Uniform;
  throw InputError("unknown axis scaling '" + name + "' (expected per-axis or uniform)");
}

std::string axis_scaling_name(AxisScaling scaling) {
  return scaling == AxisScaling::Uniform ? "uniform" : "per-axis";
}

}  // namespace ppsynth
