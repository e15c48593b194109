#include "core/formats/plain_text_format.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "core/formats/text_table.hpp"

namespace ppsynth {

namespace {

// Column roles decided by the header (or by the column count when there is none).
struct Columns {
  std::vector<std::string> names;  // all columns, "x" "y" first
  long line = 0;                   // where they were declared (0 = implied)
  std::optional<size_t> class_col;
};

Columns columns_from_header(const std::vector<std::string>& tokens, const std::string& source, long line) {
  Columns c;
  c.names = tokens;
  c.line = line;
  for (size_t i = 2; i < tokens.size(); ++i) {
    if (tokens[i] == "x" || tokens[i] == "y") throw file_error(source, line, "column '" + tokens[i] + "' repeated");
    // The writer cannot write such a name back (a fuzz finding: "# x y dep#h" read, not written).
    if (tokens[i].find('#') != std::string::npos)
      throw file_error(source, line, "column name '" + tokens[i] + "' contains '#'");
    for (size_t j = 2; j < i; ++j)
      if (tokens[j] == tokens[i]) throw file_error(source, line, "column '" + tokens[i] + "' repeated");
    if (tokens[i] == "class") c.class_col = i;
  }
  return c;
}

}  // namespace

PointSet parse_plain_text(const std::string& text, const std::string& source) {
  const std::vector<TextRow> rows = split_rows(text);
  Domain domain{};
  std::vector<int> labels;
  bool have_labels = false;
  std::optional<Columns> cols;
  PointSet ps;
  bool started = false;  // first point seen

  for (const TextRow& row : rows) {
    const long line = row.line;
    if (row.is_comment()) {
      std::istringstream s(row.text.substr(1));
      std::vector<std::string> tok;
      for (std::string t; s >> t;) tok.push_back(t);
      if (tok.empty()) continue;
      if (tok[0] == "domain") {
        if (started) throw file_error(source, line, "'# domain' must precede the first point");
        if (tok.size() != 5 && !(tok.size() == 6 && tok[5] == "periodic"))
          throw file_error(source, line, "expected '# domain x0 y0 x1 y1 [periodic]'");
        domain.x0 = parse_real_field(tok[1], source, line);
        domain.y0 = parse_real_field(tok[2], source, line);
        domain.x1 = parse_real_field(tok[3], source, line);
        domain.y1 = parse_real_field(tok[4], source, line);
        domain.periodic = tok.size() == 6;
        if (!(domain.x1 > domain.x0) || !(domain.y1 > domain.y0))
          throw file_error(source, line, "domain must have x1 > x0 and y1 > y0");
        if (!std::isfinite(domain.width()) || !std::isfinite(domain.height()))
          throw file_error(source, line, "domain width or height is beyond the range of a double");
      } else if (tok[0] == "class_labels") {
        if (started) throw file_error(source, line, "'# class_labels' must precede the first point");
        if (tok.size() < 2) throw file_error(source, line, "'# class_labels' lists no label");
        labels.clear();
        for (size_t i = 1; i < tok.size(); ++i) {
          const int l = checked_int(parse_integer_field(tok[i], source, line), "class label", source, line);
          if (std::find(labels.begin(), labels.end(), l) != labels.end())
            throw file_error(source, line, "class label " + tok[i] + " repeated");
          labels.push_back(l);
        }
        have_labels = true;
      } else if (tok.size() >= 2 && tok[0] == "x" && tok[1] == "y") {
        if (started) throw file_error(source, line, "the column header must precede the first point");
        // A parenthesized remark ends the names: "# x y  (Poisson-disk initialization ...)",
        // as in the published code's reference files.
        auto remark = std::find_if(tok.begin(), tok.end(), [](const std::string& t) { return !t.empty() && t[0] == '('; });
        tok.erase(remark, tok.end());
        cols = columns_from_header(tok, source, line);
      }
      continue;
    }

    if (!started) {
      started = true;
      if (!cols) {
        const size_t n = row.fields.size();
        if (n == 2) cols = columns_from_header({"x", "y"}, source, 0);
        else if (n == 3) cols = columns_from_header({"x", "y", "class"}, source, 0);
        else
          throw file_error(source, line, std::to_string(n) +
                                             " columns but no '# x y ...' header naming them (only 'x y' and "
                                             "'x y class' need none)");
      }
      ps.set_domain(domain);
      for (size_t i = 2; i < cols->names.size(); ++i)
        if (!cols->class_col || i != *cols->class_col) ps.add_attribute(cols->names[i]);
      if (have_labels) ps.set_class_labels(labels);
    }

    const size_t ncol = cols->names.size();
    if (row.fields.size() != ncol) {
      const std::string as = cols->line > 0 ? "the header on line " + std::to_string(cols->line)
                                            : "line " + std::to_string(rows.front().line);
      throw file_error(source, line, "expected " + std::to_string(ncol) + " columns (as " + as + "), found " +
                                         std::to_string(row.fields.size()));
    }
    Vec2 p{0, 0};
    int cls = 0;
    std::vector<double> attrs;
    attrs.reserve(ncol);
    for (size_t i = 0; i < ncol; ++i) {
      const std::string& f = row.fields[i];
      if (i == 0) p.x = parse_real_field(f, source, line);
      else if (i == 1) p.y = parse_real_field(f, source, line);
      else if (cols->class_col && i == *cols->class_col) {
        const long long c = parse_integer_field(f, source, line);
        if (c < 0) throw file_error(source, line, "class id " + f + " is negative");
        if (have_labels && c >= static_cast<long long>(labels.size()))
          throw file_error(source, line, "class id " + f + " is outside the " + std::to_string(labels.size()) +
                                             " class_labels of the header");
        if (c > 1000000) throw file_error(source, line, "class id " + f + " is implausibly large");
        cls = static_cast<int>(c);
      } else {
        attrs.push_back(parse_real_field(f, source, line));
        const std::string problem = attribute_value_problem(cols->names[i], attrs.back());
        if (!problem.empty()) throw file_error(source, line, problem);
      }
    }
    if (!domain.contains(p, 0.0)) {
      std::ostringstream s;
      s << "point (" << row.fields[0] << ", " << row.fields[1] << ") lies outside the domain [" << domain.x0 << ","
        << domain.x1 << "]x[" << domain.y0 << "," << domain.y1 << "]";
      throw file_error(source, line, s.str());
    }
    ps.add(p, cls, attrs);
  }
  if (!started) throw file_error(source, 0, "empty file: no points");
  return ps;
}

std::string print_plain_text(const PointSet& ps) {
  std::ostringstream out;
  const Domain& d = ps.domain();
  out << "# ppsynth points\n";
  out << "# domain " << format_real(d.x0) << ' ' << format_real(d.y0) << ' ' << format_real(d.x1) << ' '
      << format_real(d.y1) << (d.periodic ? " periodic" : "") << '\n';
  const bool with_class = ps.num_classes() > 1 || !ps.class_labels().empty();
  if (!ps.class_labels().empty()) {
    out << "# class_labels";
    for (int k = 0; k < ps.num_classes(); ++k) out << ' ' << ps.class_label(k);
    out << '\n';
  }
  out << "# x y" << (with_class ? " class" : "");
  for (const auto& n : ps.attribute_names()) {
    if (n.empty() || n == "x" || n == "y" || n == "class" ||
        n.find_first_of(" \t\r\n#") != std::string::npos)
      throw InputError("plain text writer: attribute name '" + n +
                       "' cannot be a column name (empty, x, y, class, or contains blanks or '#')");
    out << ' ' << n;
  }
  out << '\n';
  for (size_t i = 0; i < ps.size(); ++i) {
    out << format_real(ps[i].x) << ' ' << format_real(ps[i].y);
    if (with_class) out << ' ' << ps.cls(i);
    for (size_t a = 0; a < ps.num_attributes(); ++a) out << ' ' << format_real(ps.attr(i, a));
    out << '\n';
  }
  return out.str();
}

}  // namespace ppsynth
