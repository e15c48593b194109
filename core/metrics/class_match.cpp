#include "core/metrics/class_match.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace ppsynth {

namespace {

std::string labels_text(const nlohmann::json& labels) {
  std::string s;
  for (const auto& l : labels) s += (s.empty() ? "" : ", ") + std::to_string(l.get<int>());
  return s;
}

}  // namespace

ClassMatch match_classes(const PointSet& exemplar, const PointSet& output) {
  ClassMatch m;
  const int K = std::max(exemplar.num_classes(), 1);
  m.exemplar_classes = K;
  const std::vector<size_t> ex_counts = exemplar.class_counts(), out_counts = output.class_counts();
  const int K_out = static_cast<int>(out_counts.size());
  std::vector<int> labels(static_cast<size_t>(K));
  for (int k = 0; k < K; ++k) labels[static_cast<size_t>(k)] = exemplar.class_label(k);

  // Output class id -> matched id (-1: a class without points, dropped).
  std::vector<int> to(static_cast<size_t>(K_out), -1);
  auto with_points = [&](int c) { return out_counts[static_cast<size_t>(c)] > 0; };
  const int ex_with_points = static_cast<int>(std::count_if(ex_counts.begin(), ex_counts.end(), [](size_t n) { return n > 0; }));
  std::vector<int> out_with_points;
  for (int c = 0; c < K_out; ++c)
    if (with_points(c)) out_with_points.push_back(c);
  if (K == 1 && ex_with_points == 1 && out_with_points.size() == 1) {
    to[static_cast<size_t>(out_with_points[0])] = 0;
    if (output.class_label(out_with_points[0]) != labels[0]) m.by = "the only class of each";
  } else {
    // A file without class labels numbers its classes 0, 1, ...: those numbers are all there
    // is to match.
    const bool by_label = !exemplar.class_labels().empty() && !output.class_labels().empty();
    if (!by_label)
      m.by = exemplar.class_labels().empty() ? "index (the exemplar names no class labels)"
                                             : "index (the output names no class labels)";
    std::map<int, int> extra_ids;  // label -> output class id, ascending label
    for (int c : out_with_points) {
      const auto it = by_label ? std::find(labels.begin(), labels.end(), output.class_label(c))
                               : (c < K ? labels.begin() + c : labels.end());
      if (it != labels.end()) to[static_cast<size_t>(c)] = static_cast<int>(it - labels.begin());
      else extra_ids.emplace(output.class_label(c), c);
    }
    for (const auto& [label, c] : extra_ids) {
      to[static_cast<size_t>(c)] = static_cast<int>(labels.size());
      m.extra.push_back(static_cast<int>(labels.size()));
      labels.push_back(label);
    }
  }
  std::vector<size_t> matched_counts(labels.size(), 0);
  for (int c = 0; c < K_out; ++c)
    if (to[static_cast<size_t>(c)] >= 0) matched_counts[static_cast<size_t>(to[static_cast<size_t>(c)])] += out_counts[static_cast<size_t>(c)];
  for (int k = 0; k < K; ++k)
    if (k < static_cast<int>(ex_counts.size()) && ex_counts[static_cast<size_t>(k)] > 0 && matched_counts[static_cast<size_t>(k)] == 0)
      m.missing.push_back(k);

  m.output = output;
  for (size_t i = 0; i < m.output.size(); ++i) m.output.set_cls(i, to[static_cast<size_t>(output.cls(i))]);
  m.output.set_class_labels(labels);
  return m;
}

nlohmann::json class_match_json(const ClassMatch& m) {
  nlohmann::json missing = nlohmann::json::array(), extra = nlohmann::json::array();
  for (int k : m.missing) missing.push_back(m.output.class_label(k));
  for (int k : m.extra) extra.push_back(m.output.class_label(k));
  return {{"by", m.by}, {"missing", missing}, {"extra", extra}};
}

std::string class_match_warning(const nlohmann::json& match) {
  std::string s;
  if (!match.value("missing", nlohmann::json::array()).empty())
    s += "the output has no point of class " + labels_text(match["missing"]);
  if (!match.value("extra", nlohmann::json::array()).empty())
    s += std::string(s.empty() ? "" : "; ") + "the exemplar has no class " + labels_text(match["extra"]) +
         " of the output";
  return s.empty() ? s : "classes: " + s + " (matched by " + match.value("by", std::string("label")) + "; their rows fail)";
}

}  // namespace ppsynth
