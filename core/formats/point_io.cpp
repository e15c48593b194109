#include "core/formats/point_io.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
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
#include "core/paths.hpp"

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

// --- structural detection ---------------------------------------------------------------

// Data lines looked at: enough to see the structure, few enough to stay cheap on 10^6 points.
constexpr size_t kSampleRows = 64;

struct Field {
  bool is_int = false, is_real = false;
  long long i = 0;
  double d = 0;
};

Field classify(const std::string& f) {
  Field r;
  const char* b = f.data();
  const char* e = b + f.size();
  if (b != e && *b == '+') ++b;
  {
    auto [p, ec] = std::from_chars(b, e, r.i);
    r.is_int = ec == std::errc() && p == e;
  }
  auto [p, ec] = std::from_chars(b, e, r.d);
  r.is_real = ec == std::errc() && p == e && std::isfinite(r.d);
  if (r.is_int) r.is_real = true, r.d = static_cast<double>(r.i);
  return r;
}

std::vector<Field> classify_row(const TextRow& row) {
  std::vector<Field> v;
  v.reserve(row.fields.size());
  for (const auto& f : row.fields) v.push_back(classify(f));
  return v;
}

bool all_int(const std::vector<Field>& v) {
  return std::all_of(v.begin(), v.end(), [](const Field& f) { return f.is_int; });
}
bool all_real(const std::vector<Field>& v) {
  return std::all_of(v.begin(), v.end(), [](const Field& f) { return f.is_real; });
}

// "K id_1 ... id_K" with K < 1000 (a CLASS is >= 1000): the Gabor header.
bool gabor_header(const std::vector<Field>& v) {
  return v.size() >= 2 && all_int(v) && v[0].i >= 1 && v[0].i < 1000 &&
         v[0].i == static_cast<long long>(v.size()) - 1;
}

// `CLASS X Y [ATTR..]`: integers, CLASS in the header (or, without one, a positive multiple
// of 1000), X and Y in 0..10000.
bool gabor_row(const std::vector<Field>& v, const std::vector<long long>* header_ids) {
  if (v.size() < 3 || !all_int(v)) return false;
  const long long c = v[0].i;
  const bool class_ok = header_ids ? std::find(header_ids->begin(), header_ids->end(), c) != header_ids->end()
                                   : c > 0 && c % 1000 == 0;
  return class_ok && v[1].i >= 0 && v[1].i <= 10000 && v[2].i >= 0 && v[2].i <= 10000;
}

// `x y c2 c3 [c4..]`: numbers, c2 a whole number.
bool point_synthesis_row(const std::vector<Field>& v) {
  return v.size() >= 4 && all_real(v) && v[2].d == std::floor(v[2].d);
}

// Plain text without a header: `x y` or `x y class` in the unit square.
bool plain_row(const std::vector<Field>& v) {
  if ((v.size() != 2 && v.size() != 3) || !all_real(v)) return false;
  if (v[0].d < 0 || v[0].d > 1 || v[1].d < 0 || v[1].d > 1) return false;
  return v.size() == 2 || (v[2].is_int && v[2].i >= 0);
}

std::string describe(Format f) {
  switch (f) {
    case Format::GaborInt: return "the published integer format (gabor)";
    case Format::PointSynthesis: return "the Point-Synthesis format (point-synthesis)";
    case Format::Plain: return "plain text (plain)";
    case Format::Json: return "JSON (json)";
    case Format::Auto: break;
  }
  return "auto";
}

// "read as <format>[, <why>]" + what the reader said + how to choose another format.
// `message` is the reader's "source:line: what" (or "source: what").
InputError decorated(const std::string& message, const std::string& source, const Detection* d, Format f) {
  std::string where = source, what = message;
  if (message.compare(0, source.size() + 1, source + ":") == 0) {
    what = message.substr(source.size() + 1);
    size_t k = 0;
    while (k < what.size() && std::isdigit(static_cast<unsigned char>(what[k]))) ++k;
    if (k > 0 && what.compare(k, 2, ": ") == 0) {
      where += ":" + what.substr(0, k);
      what = what.substr(k + 2);
    } else if (!what.empty() && what[0] == ' ') {
      what.erase(0, 1);
    }
  }
  std::string out = where + ": read as " + describe(f);
  if (d && d->guessed) out += ", a guess (" + d->reason + ")";
  out += ": " + what;
  if (d && !d->also_fits.empty()) {
    std::string names, flags;
    for (size_t i = 0; i < d->also_fits.size(); ++i) {
      const std::string name = format_name(d->also_fits[i]);
      names += (i ? " and " : "") + describe(d->also_fits[i]);
      flags += (i ? " or " : "") + std::string("--format ") + name + " (in a run config: \"format\": \"" + name + "\")";
    }
    out += "; its first lines also fit " + names + ": if the file is in that format, pass " + flags;
  } else if (d && d->guessed) {
    out += "; if the file is in another format, pass --format NAME (gabor, point-synthesis, plain or json; in a "
           "run config: \"format\")";
  }
  return InputError(out);
}

// Parses with the format `f` (detected as `d`, or given when d is null), the reader's
// errors decorated with the format; validates when asked.
PointSet parse_as(const std::string& text, const std::string& source, const ReadOptions& opts, Format f,
                  const Detection* d, bool validate_too) {
  try {
    PointSet ps;
    switch (f) {
      case Format::GaborInt: ps = parse_gabor_int(text, source, opts); break;
      case Format::PointSynthesis: ps = parse_point_synthesis(text, source, opts); break;
      case Format::Plain: ps = parse_plain_text(text, source); break;
      case Format::Json: ps = parse_json_points(text, source); break;
      case Format::Auto: throw std::logic_error("parse_as: no format");
    }
    if (validate_too) validate(ps, source);
    return ps;
  } catch (const InputError& e) {
    throw decorated(e.what(), source, d, f);
  }
}

// Sets `read_as` (when given) to the format the text was parsed as.
PointSet parse_text(std::string text, const std::string& source, const ReadOptions& opts, bool validate_too,
                    Format* read_as = nullptr) {
  strip_utf8_bom(text);
  if (opts.format != Format::Auto) {
    if (read_as) *read_as = opts.format;
    return parse_as(text, source, opts, opts.format, nullptr, validate_too);
  }
  const Detection d = detect_format_details(text, source);
  spdlog::debug("{}: detected {} ({})", source, format_name(d.format), d.reason);
  if (read_as) *read_as = d.format;
  return parse_as(text, source, opts, d.format, &d, validate_too);
}

std::atomic<size_t> g_point_file_reads{0};

// The text of a point file, counted (point_file_reads).
std::string read_point_file_text(const std::string& path) {
  ++g_point_file_reads;
  return read_file_text(path);
}

}  // namespace

Detection detect_format_details(const std::string& text, const std::string& source) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) return detect_format_details(text.substr(3), source);
  Detection d;
  const auto b = text.find_first_not_of(" \t\r\n\f\v");
  if (lower_extension(source) == ".json") {
    d.format = Format::Json;
    d.reason = "by its .json extension";
    return d;
  }
  if (b == std::string::npos) throw file_error(source, 0, "empty file: no points");
  if (text[b] == '{') {
    d.format = Format::Json;
    d.reason = "it starts with '{'";
    return d;
  }
  if (text[b] == '#') {
    d.format = Format::Plain;
    d.reason = "it starts with a '#' comment";
    return d;
  }

  // Count how many of the first data lines fit each line-oriented format.
  const std::vector<TextRow> rows = split_rows(text, kSampleRows + 1);
  std::vector<std::vector<Field>> v;
  for (const auto& r : rows) v.push_back(classify_row(r));
  const bool header = gabor_header(v[0]);
  std::vector<long long> ids;
  if (header)
    for (size_t i = 1; i < v[0].size(); ++i) ids.push_back(v[0][i].i);
  const size_t n = std::min(v.size(), kSampleRows), g0 = header ? 1 : 0, ng = std::min(v.size() - g0, kSampleRows);
  size_t g = 0, s = 0, p = 0;
  for (size_t r = g0; r < g0 + ng; ++r) g += gabor_row(v[r], header ? &ids : nullptr);
  for (size_t r = 0; r < n; ++r) s += point_synthesis_row(v[r]), p += plain_row(v[r]);

  // Most lines fitting decides; Gabor first (its lines are Point-Synthesis lines too when
  // they have >= 4 fields), then Point-Synthesis, then plain (2-3 fields: disjoint).
  const bool g_most = g > 0 && 2 * g >= ng, s_most = 2 * s > n, p_most = 2 * p > n;
  auto count = [&](size_t k, size_t of) { return std::to_string(k) + " of the first " + std::to_string(of) + " lines fit"; };
  if (g_most) {
    d.format = Format::GaborInt;
    d.reason = count(g, ng) + (header ? ", after a 'K id...' header" : "");
    if (s_most && !header) d.also_fits.push_back(Format::PointSynthesis);
  } else if (s_most) {
    d.format = Format::PointSynthesis;
    d.reason = count(s, n);
  } else if (p_most) {
    d.format = Format::Plain;
    d.reason = count(p, n);
  } else {
    // No format fits most lines: the one that fits the most, else by the field count of the
    // first line (as a '# x y ...' header would have said).
    d.guessed = true;
    if (g > 0 && g >= s && g >= p) d.format = Format::GaborInt, d.reason = count(g, ng);
    else if (s > 0 && s >= p) d.format = Format::PointSynthesis, d.reason = count(s, n);
    else if (p > 0) d.format = Format::Plain, d.reason = count(p, n);
    else {
      d.format = header ? Format::GaborInt : rows[0].fields.size() >= 4 ? Format::PointSynthesis : Format::Plain;
      d.reason = "no line fits a known format; chosen by the field count of line " + std::to_string(rows[0].line);
    }
  }
  return d;
}

Format detect_format_of_text(const std::string& text, const std::string& source) {
  return detect_format_details(text, source).format;
}

// Takes a name as read_points does ("shared:data/...").
Format detect_format(const std::string& name) {
  const std::string path = resolve_data_path(name);
  return detect_format_of_text(read_point_file_text(path), path);
}

PointSet parse_points(const std::string& text, const std::string& source, const ReadOptions& opts) {
  return parse_text(text, source, opts, /*validate_too=*/false);
}

PointFile read_point_file(const std::string& name, const ReadOptions& opts) {
  const std::string path = resolve_data_path(name);  // "shared:data/..." wherever a file is read
  PointFile f;
  f.points = parse_text(read_point_file_text(path), path, opts, /*validate_too=*/true, &f.format);
  report_coincident(f.points, path);
  spdlog::debug("read {}: {} points, {} classes, {} attributes", path, f.points.size(), f.points.num_classes(),
                f.points.num_attributes());
  return f;
}

PointSet read_points(const std::string& name, const ReadOptions& opts) { return read_point_file(name, opts).points; }

size_t point_file_reads() { return g_point_file_reads.load(); }

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
