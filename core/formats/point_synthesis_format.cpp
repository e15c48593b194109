#include "core/formats/point_synthesis_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "core/formats/text_table.hpp"

namespace ppsynth {

PointSet parse_point_synthesis(const std::string& text, const std::string& source, const ReadOptions& opts) {
  const std::vector<TextRow> rows = split_rows(text);
  if (rows.empty()) throw file_error(source, 0, "empty file: no points");
  const size_t ncol = rows[0].fields.size();
  if (ncol < 3)
    throw file_error(source, rows[0].line,
                     "expected 'x y c2 [c3 ...]', found " + std::to_string(ncol) + " field(s)");

  std::vector<Vec2> pos(rows.size());
  std::vector<long long> cat(rows.size());
  std::vector<std::vector<double>> attrs(rows.size(), std::vector<double>(ncol - 3));
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& f = rows[r].fields;
    const long line = rows[r].line;
    if (rows[r].is_comment()) throw file_error(source, line, "comments are not part of the Point-Synthesis format");
    if (f.size() != ncol)
      throw file_error(source, line, "expected " + std::to_string(ncol) + " fields (as on line " +
                                         std::to_string(rows[0].line) + "), found " + std::to_string(f.size()));
    pos[r] = {parse_real_field(f[0], source, line), parse_real_field(f[1], source, line)};
    cat[r] = checked_int(parse_integral_real_field(f[2], source, line), "category id", source, line);
    for (size_t a = 3; a < ncol; ++a) attrs[r][a - 3] = parse_real_field(f[a], source, line);
  }

  // Bounding box and the map onto the unit square.
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& p : pos) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const double w = x1 - x0, h = y1 - y0;
  if (!(w > 0) || !(h > 0))
    throw file_error(source, 0, "all points share one x or one y value; cannot rescale to the unit square");
  if (!std::isfinite(w) || !std::isfinite(h))
    throw file_error(source, 0, "the points' extent is beyond the range of a double; cannot rescale to the unit square");
  double sx = w, sy = h;
  Domain domain{};
  if (opts.scaling == AxisScaling::Uniform) {
    sx = sy = std::max(w, h);
    domain.x1 = w / sx;
    domain.y1 = h / sy;
    // A short side below one ulp of the long side (1e-18 against 1e308 even rounds to 0) is a
    // line at double precision, not a domain: the points could not be told apart across it.
    if (std::min(domain.x1, domain.y1) < std::numeric_limits<double>::epsilon())
      throw file_error(source, 0,
                       "the points' extent is " + format_real(w) + " by " + format_real(h) +
                           ": an aspect ratio beyond 1/DBL_EPSILON cannot be scaled uniformly "
                           "(read with per-axis scaling, or rescale the file)");
  }

  // Classes: a constant column is one class; else distinct values ascending -> 0..K-1.
  std::vector<long long> distinct = cat;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<int> labels;
  for (long long v : distinct) labels.push_back(static_cast<int>(v));

  std::vector<std::string> names = opts.attribute_names;
  if (names.empty())
    for (size_t a = 3; a < ncol; ++a) names.push_back("c" + std::to_string(a));
  if (names.size() != ncol - 3)
    throw file_error(source, rows[0].line, std::to_string(names.size()) + " attribute name(s) given for " +
                                               std::to_string(ncol - 3) + " attribute column(s)");

  for (size_t r = 0; r < rows.size(); ++r)  // a "radius" column (named by ReadOptions) must be > 0
    for (size_t a = 0; a < names.size(); ++a) {
      const std::string problem = attribute_value_problem(names[a], attrs[r][a]);
      if (!problem.empty()) throw file_error(source, rows[r].line, problem);
    }

  PointSet ps = point_set_with_attributes(domain, names, source, 0);  // a name twice: ReadOptions'
  ps.set_class_labels(labels);
  ps.reserve(rows.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    // Extremes land exactly on 0 and the far edge (no rounding outside the domain).
    Vec2 p{(pos[r].x - x0) / sx, (pos[r].y - y0) / sy};
    if (pos[r].x == x1) p.x = domain.x1;
    if (pos[r].y == y1) p.y = domain.y1;
    const int k = static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), cat[r]) - distinct.begin());
    ps.add(p, k, attrs[r]);
  }
  return ps;
}

std::string print_point_synthesis(const PointSet& ps) {
  std::ostringstream out;
  for (size_t i = 0; i < ps.size(); ++i) {
    out << format_real(ps[i].x) << ' ' << format_real(ps[i].y) << ' ' << ps.class_label(ps.cls(i));
    if (ps.num_attributes() == 0) out << " 1";
    for (size_t a = 0; a < ps.num_attributes(); ++a) out << ' ' << format_real(ps.attr(i, a));
    out << '\n';
  }
  return out.str();
}

}  // namespace ppsynth
