#include "core/formats/json_format.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/text_table.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;

// Line of each element of the top-level array `key` (a light scan over the already
// validated JSON text: strings skipped, depth tracked), so errors can name a line.
std::vector<long> element_lines(const std::string& text, const std::string& key) {
  std::vector<long> lines;
  int depth = 0;
  long line = 1;
  std::string last_string;
  bool in_target = false, expect_element = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') { ++line; continue; }
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    if (in_target && depth == 2 && expect_element && c != ']') {
      lines.push_back(line);
      expect_element = false;
    }
    if (c == '"') {
      std::string s;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
        else s += text[i];
      }
      if (depth == 1) last_string = s;
      continue;
    }
    if (c == '[' || c == '{') {
      ++depth;
      if (depth == 2 && c == '[' && last_string == key) in_target = expect_element = true;
    } else if (c == ']' || c == '}') {
      if (depth == 2 && in_target) return lines;
      --depth;
    } else if (c == ',' && in_target && depth == 2) {
      expect_element = true;
    } else if (c == ',' && depth == 1) {
      last_string.clear();
    }
  }
  return lines;
}

// Line of the top-level key `key` (0 when it cannot be found), for errors about its value.
long key_line(const std::string& text, const std::string& key) {
  int depth = 0;
  long line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
    } else if (c == '"') {
      const long at = line;
      std::string s;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\n') ++line;
        if (text[i] == '\\') ++i;
        else s += text[i];
      }
      if (depth == 1 && s == key) {
        const auto next = text.find_first_not_of(" \t\r\n", i + 1);
        if (next != std::string::npos && text[next] == ':') return at;
      }
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return 0;
}

double number_at(const json& v, const std::string& what, const std::string& source, long line) {
  if (!v.is_number()) throw file_error(source, line, what + " is not a number");
  return v.get<double>();
}

}  // namespace

PointSet parse_json_points(const std::string& text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw file_error(source, 0, "empty file: no points");
  // Byte-order mark, nesting depth, numbers beyond double ("1e400"; fuzz finding) and syntax
  // errors, each with its line.
  const json doc = parse_json_text(text, source, /*allow_comments=*/false);
  if (!doc.is_object()) throw file_error(source, 1, "expected a JSON object with a \"points\" array");
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "format" && it.key() != "domain" && it.key() != "periodic" && it.key() != "class_labels" &&
        it.key() != "attributes" && it.key() != "points")
      throw file_error(source, key_line(text, it.key()), "unknown key \"" + it.key() + "\"");

  Domain domain{};
  if (doc.contains("domain")) {
    const json& d = doc["domain"];
    const long dl = key_line(text, "domain");
    if (!d.is_array() || d.size() != 4) throw file_error(source, dl, "\"domain\" must be [x0, y0, x1, y1]");
    domain.x0 = number_at(d[0], "domain[0]", source, dl);
    domain.y0 = number_at(d[1], "domain[1]", source, dl);
    domain.x1 = number_at(d[2], "domain[2]", source, dl);
    domain.y1 = number_at(d[3], "domain[3]", source, dl);
    if (!(domain.x1 > domain.x0) || !(domain.y1 > domain.y0))
      throw file_error(source, dl, "\"domain\" must have x1 > x0 and y1 > y0");
    if (!std::isfinite(domain.width()) || !std::isfinite(domain.height()))
      throw file_error(source, dl, "\"domain\" width or height is beyond the range of a double");
  }
  if (doc.contains("periodic")) {
    if (!doc["periodic"].is_boolean()) throw file_error(source, key_line(text, "periodic"), "\"periodic\" must be true or false");
    domain.periodic = doc["periodic"].get<bool>();
  }
  std::vector<int> labels;
  const bool have_labels = doc.contains("class_labels");
  if (have_labels) {
    const json& l = doc["class_labels"];
    if (!l.is_array() || l.empty()) throw file_error(source, key_line(text, "class_labels"), "\"class_labels\" must be a non-empty array of integers");
    const std::vector<long> label_lines = element_lines(text, "class_labels");
    for (size_t i = 0; i < l.size(); ++i) {
      const json& v = l[i];
      const long line = i < label_lines.size() ? label_lines[i] : 0;
      if (!v.is_number_integer()) throw file_error(source, line, "\"class_labels\" must hold integers");
      // Beyond 32 bits a label was truncated into another one.
      if (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(LLONG_MAX))
        throw file_error(source, line, "class label " + v.dump() + " is out of range");
      const int x = checked_int(v.get<long long>(), "class label", source, line);
      if (std::find(labels.begin(), labels.end(), x) != labels.end())
        throw file_error(source, line, "class label " + std::to_string(x) + " repeated");
      labels.push_back(x);
    }
  }
  std::vector<std::string> names;
  if (doc.contains("attributes")) {
    const json& a = doc["attributes"];
    if (!a.is_array()) throw file_error(source, key_line(text, "attributes"), "\"attributes\" must be an array of names");
    for (const json& v : a) {
      if (!v.is_string()) throw file_error(source, key_line(text, "attributes"), "\"attributes\" must hold strings");
      names.push_back(v.get<std::string>());
    }
  }
  if (!doc.contains("points") || !doc["points"].is_array())
    throw file_error(source, key_line(text, "points"), "missing \"points\" array");
  const json& pts = doc["points"];
  if (pts.empty()) throw file_error(source, key_line(text, "points"), "\"points\" is empty: no points");

  const std::vector<long> lines = element_lines(text, "points");
  PointSet ps = point_set_with_attributes(domain, names, source, key_line(text, "attributes"));
  if (have_labels) ps.set_class_labels(labels);
  ps.reserve(pts.size());
  const size_t ncol = 3 + names.size();
  std::vector<double> attrs(names.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    const long line = i < lines.size() ? lines[i] : 0;
    const std::string where = "points[" + std::to_string(i) + "]";
    const json& p = pts[i];
    if (!p.is_array() || p.size() != ncol)
      throw file_error(source, line, where + " must be [x, y, class" + (names.empty() ? "" : ", attributes...") +
                                         "] with " + std::to_string(ncol) + " numbers");
    const Vec2 xy{number_at(p[0], where + " x", source, line), number_at(p[1], where + " y", source, line)};
    // An unsigned beyond int64 would wrap to a negative long long: "non-negative" still holds.
    if (!p[2].is_number_integer() || p[2].get<long long>() < 0)
      throw file_error(source, line, where + " class must be a non-negative integer");
    const long long c = p[2].get<long long>();
    if (have_labels && c >= static_cast<long long>(labels.size()))
      throw file_error(source, line, where + " class " + std::to_string(c) + " is outside the " +
                                         std::to_string(labels.size()) + " class_labels");
    if (c > 1000000) throw file_error(source, line, where + " class id is implausibly large");
    for (size_t a = 0; a < names.size(); ++a) {
      attrs[a] = number_at(p[3 + a], where + " attribute '" + names[a] + "'", source, line);
      const std::string problem = attribute_value_problem(names[a], attrs[a]);
      if (!problem.empty()) throw file_error(source, line, where + ": " + problem);
    }
    if (!domain.contains(xy, 0.0)) {
      std::ostringstream s;
      s << where << " (" << xy.x << ", " << xy.y << ") lies outside the domain";
      throw file_error(source, line, s.str());
    }
    ps.add(xy, static_cast<int>(c), attrs);
  }
  return ps;
}

std::string print_json_points(const PointSet& ps) {
  const Domain& d = ps.domain();
  std::ostringstream out;
  out << "{\n  \"format\": \"ppsynth-points\",\n";
  out << "  \"domain\": " << json({d.x0, d.y0, d.x1, d.y1}).dump() << ",\n";
  out << "  \"periodic\": " << (d.periodic ? "true" : "false") << ",\n";
  if (!ps.class_labels().empty()) {
    json l = json::array();
    for (int k = 0; k < ps.num_classes(); ++k) l.push_back(ps.class_label(k));
    out << "  \"class_labels\": " << l.dump() << ",\n";
  }
  out << "  \"attributes\": " << json(ps.attribute_names()).dump() << ",\n";
  out << "  \"points\": [";
  for (size_t i = 0; i < ps.size(); ++i) {
    json p = json::array({ps[i].x, ps[i].y, ps.cls(i)});
    for (size_t a = 0; a < ps.num_attributes(); ++a) p.push_back(ps.attr(i, a));
    out << (i ? ",\n    " : "\n    ") << p.dump();
  }
  out << "\n  ]\n}\n";
  return out.str();
}

}  // namespace ppsynth
