#include "core/formats/gabor_int_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/log.hpp"

namespace ppsynth {

namespace {

// A first row "K id_1 ... id_K" (K+1 fields, K >= 1) is a header.
bool is_header(const std::vector<long long>& v) {
  return v.size() >= 2 && v[0] >= 1 && v[0] == static_cast<long long>(v.size()) - 1;
}

bool parse_int_quiet(const std::string& s, long long& v) {
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

std::vector<std::string> gabor_attribute_names(const std::string& source, size_t count) {
  const std::string stem = std::filesystem::path(source).stem().string();
  if (count == 1 && stem.find("disk") != std::string::npos) return {"radius"};
  if (count == 2) return {"scale", "depth"};
  std::vector<std::string> names;
  for (size_t a = 0; a < count; ++a) names.push_back("attr" + std::to_string(a));
  return names;
}

PointSet parse_gabor_int(const std::string& text, const std::string& source, const ReadOptions& opts) {
  std::vector<TextRow> rows = split_rows(text);
  if (rows.empty()) throw file_error(source, 0, "empty file: no points");

  std::vector<std::vector<long long>> values(rows.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (const auto& f : rows[r].fields) values[r].push_back(parse_integer_field(f, source, rows[r].line));

  std::vector<int> labels;
  size_t first = 0;
  const bool header = is_header(values[0]);
  if (header) {
    for (size_t i = 1; i < values[0].size(); ++i) {
      const int id = checked_int(values[0][i], "class id", source, rows[0].line);
      if (std::find(labels.begin(), labels.end(), id) != labels.end())
        throw file_error(source, rows[0].line, "class id " + std::to_string(id) + " repeated in the header");
      labels.push_back(id);
    }
    first = 1;
  }
  if (first >= rows.size()) throw file_error(source, rows[0].line, "header but no points");

  const size_t ncol = values[first].size();
  const long first_line = rows[first].line;
  if (ncol < 3)
    throw file_error(source, first_line, "expected 'CLASS X Y [ATTR...]', found " + std::to_string(ncol) + " field(s)");
  for (size_t r = first; r < rows.size(); ++r)
    if (values[r].size() != ncol)
      throw file_error(source, rows[r].line, "expected " + std::to_string(ncol) + " fields (as on line " +
                                                 std::to_string(first_line) + "), found " +
                                                 std::to_string(values[r].size()));

  // CLASS values beyond 32 bits would be truncated into another label.
  for (size_t r = first; r < rows.size(); ++r) (void)checked_int(values[r][0], "class id", source, rows[r].line);
  if (!header) {  // labels = the distinct CLASS values, ascending
    for (size_t r = first; r < rows.size(); ++r) labels.push_back(static_cast<int>(values[r][0]));
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  }

  const size_t nattr = ncol - 3;
  std::vector<std::string> names = opts.attribute_names.empty() ? gabor_attribute_names(source, nattr)
                                                                 : opts.attribute_names;
  if (names.size() != nattr)
    throw file_error(source, first_line, std::to_string(names.size()) + " attribute name(s) given for " +
                                             std::to_string(nattr) + " attribute column(s)");

  PointSet ps = point_set_with_attributes(Domain{}, names, source, 0);  // a name twice: ReadOptions'
  ps.set_class_labels(labels);
  ps.reserve(rows.size() - first);
  std::vector<double> attrs(nattr);
  for (size_t r = first; r < rows.size(); ++r) {
    const auto& v = values[r];
    auto it = std::find(labels.begin(), labels.end(), v[0]);
    if (it == labels.end()) {
      std::ostringstream s;
      s << "class id " << v[0] << " is not in the header (";
      for (size_t k = 0; k < labels.size(); ++k) s << (k ? " " : "") << labels[k];
      s << ")";
      throw file_error(source, rows[r].line, s.str());
    }
    const Vec2 p{v[1] / kGaborIntScale, v[2] / kGaborIntScale};
    if (!ps.domain().contains(p, 0.0))
      throw file_error(source, rows[r].line, "point (" + std::to_string(v[1]) + ", " + std::to_string(v[2]) +
                                                 ") lies outside the unit square (0..10000)");
    for (size_t a = 0; a < nattr; ++a) {
      attrs[a] = v[3 + a] / kGaborIntScale;
      const std::string problem = attribute_value_problem(names[a], attrs[a]);
      if (!problem.empty()) throw file_error(source, rows[r].line, "column " + std::to_string(4 + a) + ": " + problem);
    }
    ps.add(p, static_cast<int>(it - labels.begin()), attrs);
  }
  return ps;
}

std::string print_gabor_int(const PointSet& ps_in) {
  const Domain unit{};
  const Domain& d = ps_in.domain();
  const bool is_unit = d.x0 == 0 && d.y0 == 0 && d.x1 == 1 && d.y1 == 1;
  if (!is_unit)
    spdlog::debug("gabor writer: mapping domain [{},{}]x[{},{}] onto the unit square", d.x0, d.x1, d.y0, d.y1);
  const PointSet ps = is_unit ? ps_in : ps_in.mapped_to(unit);
  const int K = std::max(ps.num_classes(), 1);

  std::vector<int> labels = ps.class_labels();
  bool usable = static_cast<int>(labels.size()) == K;
  for (size_t k = 0; usable && k < labels.size(); ++k) {
    usable = labels[k] > 0;
    for (size_t j = 0; usable && j < k; ++j) usable = labels[j] != labels[k];
  }
  if (!usable) {
    labels.resize(K);
    for (int k = 0; k < K; ++k) labels[k] = 1000 * (k + 1);
  }

  auto to_int = [](double v) { return std::llround(v * kGaborIntScale); };
  std::ostringstream out;
  // A single-class file has no header, unless its rows would read as one (is_header, the
  // reader's rule: label 2 with no attribute, 3 with one).
  std::vector<long long> first_row(3 + ps.num_attributes(), 0);
  first_row[0] = labels[0];
  if (K > 1 || is_header(first_row)) {
    out << K;
    for (int l : labels) out << ' ' << l;
    out << '\n';
  }
  for (size_t i = 0; i < ps.size(); ++i) {
    out << labels[ps.cls(i)] << ' ' << to_int(ps[i].x) << ' ' << to_int(ps[i].y);
    for (size_t a = 0; a < ps.num_attributes(); ++a) out << ' ' << to_int(ps.attr(i, a));
    out << '\n';
  }
  return out.str();
}

bool looks_like_gabor_int(const std::string& text) {
  const std::vector<TextRow> rows = split_rows(text);
  if (rows.empty()) return false;
  std::vector<std::vector<long long>> values(rows.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (const auto& f : rows[r].fields) {
      long long v;
      if (!parse_int_quiet(f, v)) return false;
      values[r].push_back(v);
    }
  const size_t first = is_header(values[0]) && values[0][0] < 1000 ? 1 : 0;
  if (first >= rows.size()) return false;
  const size_t ncol = values[first].size();
  if (ncol < 3) return false;
  for (size_t r = first; r < rows.size(); ++r) {
    const auto& v = values[r];
    if (v.size() != ncol || v[0] <= 0 || v[0] % 1000 != 0) return false;
    if (v[1] < 0 || v[1] > 10000 || v[2] < 0 || v[2] > 10000) return false;
  }
  return true;
}

}  // namespace ppsynth
