// `ppsynth info FILE [--format F] [--scaling S] [--json]`: what a point file holds: its
// format, point count, domain, classes (label and count), attributes (name, min, max),
// coincident points, and the spacing statistics of core/metrics/nearest_neighbor.hpp:
// mean nearest-neighbor distance d (domain units, periodic when the domain is) and the
// relative radius rho (dimensionless; 1 = hexagonal packing), per file and per class.
#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/ppsynth/command.hpp"
#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/metrics/nearest_neighbor.hpp"

namespace {

using namespace ppsynth;
using nlohmann::json;

struct InfoArgs {
  std::string input, format = "auto", scaling = "per-axis";
  std::vector<std::string> attribute_names;
  bool as_json = false;
};

// Spacing statistics, null when there are fewer than 2 points.
json spacing(const PointSet& ps) {
  json j;
  if (ps.size() < 2) {
    j["mean_nn_distance"] = nullptr;
    j["relative_radius"] = nullptr;
  } else {
    j["mean_nn_distance"] = mean_nn_distance(ps, ps.domain().periodic);
    j["relative_radius"] = relative_radius(ps);
  }
  return j;
}

json collect(const InfoArgs& a) {
  ReadOptions ro;
  ro.format = parse_format(a.format);
  ro.scaling = parse_axis_scaling(a.scaling);
  ro.attribute_names = a.attribute_names;
  const Format fmt = ro.format == Format::Auto ? detect_format(a.input) : ro.format;
  const PointSet ps = read_points(a.input, ro);

  json j;
  j["file"] = shown_text(a.input);  // any file name can be written as JSON
  j["format"] = format_name(fmt);
  if (fmt == Format::PointSynthesis) j["scaling"] = axis_scaling_name(ro.scaling);
  j["points"] = ps.size();
  const Domain& d = ps.domain();
  j["domain"] = {d.x0, d.y0, d.x1, d.y1};
  j["periodic"] = d.periodic;
  json spc = spacing(ps);
  j["mean_nn_distance"] = spc["mean_nn_distance"];
  j["relative_radius"] = spc["relative_radius"];

  json classes = json::array();
  const auto counts = ps.class_counts();
  for (int k = 0; k < ps.num_classes(); ++k) {
    json c{{"class", k}, {"label", ps.class_label(k)}, {"count", counts[k]}};
    if (ps.num_classes() > 1) {
      json s = spacing(ps.subset_class(k));
      c["mean_nn_distance"] = s["mean_nn_distance"];
      c["relative_radius"] = s["relative_radius"];
    }
    classes.push_back(c);
  }
  j["classes"] = classes;

  json attrs = json::array();
  for (size_t at = 0; at < ps.num_attributes(); ++at) {
    const auto& col = ps.attribute_column(at);
    const auto [lo, hi] = std::minmax_element(col.begin(), col.end());
    attrs.push_back({{"name", ps.attribute_names()[at]}, {"min", *lo}, {"max", *hi}});
  }
  j["attributes"] = attrs;

  json pairs = json::array();
  for (const auto& [p, q] : coincident_pairs(ps)) pairs.push_back({p, q});
  j["coincident_pairs"] = pairs;
  return j;
}

std::string num(const json& v) {
  if (v.is_null()) return "n/a (fewer than 2 points)";
  std::ostringstream s;
  s.precision(6);
  s << v.get<double>();
  return s.str();
}

void print_text(const json& j) {
  std::cout << "file:        " << j["file"].get<std::string>() << "\n";
  std::cout << "format:      " << j["format"].get<std::string>();
  if (j.contains("scaling")) std::cout << " (scaling " << j["scaling"].get<std::string>() << ")";
  std::cout << "\npoints:      " << j["points"].get<size_t>() << "\n";
  const auto& d = j["domain"];
  std::cout << "domain:      [" << d[0].get<double>() << ", " << d[2].get<double>() << "] x [" << d[1].get<double>()
            << ", " << d[3].get<double>() << "]" << (j["periodic"].get<bool>() ? " periodic" : "") << "\n";
  std::cout << "mean NN distance d: " << num(j["mean_nn_distance"]) << "\n";
  std::cout << "relative radius:    " << num(j["relative_radius"]) << "\n";
  std::cout << "classes:     " << j["classes"].size() << "\n";
  for (const auto& c : j["classes"]) {
    std::cout << "  class " << c["class"].get<int>() << " (label " << c["label"].get<int>()
              << "): " << c["count"].get<size_t>() << " points";
    if (c.contains("mean_nn_distance"))
      std::cout << ", d " << num(c["mean_nn_distance"]) << ", rho " << num(c["relative_radius"]);
    std::cout << "\n";
  }
  std::cout << "attributes:  " << j["attributes"].size() << "\n";
  for (const auto& at : j["attributes"])
    std::cout << "  " << at["name"].get<std::string>() << ": min " << at["min"].get<double>() << ", max "
              << at["max"].get<double>() << "\n";
  const auto& pairs = j["coincident_pairs"];
  std::cout << "coincident point pairs: " << pairs.size();
  for (size_t i = 0; i < pairs.size() && i < 20; ++i)
    std::cout << (i ? ", " : " (") << pairs[i][0].get<size_t>() << "=" << pairs[i][1].get<size_t>();
  if (!pairs.empty()) std::cout << (pairs.size() > 20 ? ", ...)" : ")");
  std::cout << "\n";
}

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<InfoArgs>();
  app.add_option("file", a->input, "point file (gabor, point-synthesis, plain or json)")->required();
  app.add_option("--format", a->format, "input format: auto, gabor, point-synthesis, plain, json")
      ->capture_default_str();
  app.add_option("--scaling", a->scaling, "point-synthesis rescaling to the unit square: per-axis or uniform")
      ->capture_default_str();
  app.add_option("--attribute-names", a->attribute_names,
                 "names of the attribute columns (gabor, point-synthesis), overriding the format's rule")
      ->delimiter(',');
  app.add_flag("--json", a->as_json, "print the summary as JSON");
  app.footer(
      "Mean NN distance d is in domain units (toroidal if the domain is periodic); the relative\n"
      "radius is (d_min/2)/r_max with r_max = sqrt(A/(2 sqrt(3) N)), 1 for a hexagonal lattice.\n"
      "Per-class values are listed for multi-class files. Coincident points are listed as\n"
      "0-based point index pairs.\n");
  return [a]() {
    const json j = collect(*a);
    if (a->as_json) std::cout << j.dump(2) << "\n";
    else print_text(j);
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("info", "summarize a point file: counts, classes, attributes, domain, spacing", setup)
