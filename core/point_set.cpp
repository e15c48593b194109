#include "core/point_set.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace ppsynth {

void PointSet::add(Vec2 p, int cls, const std::vector<double>& attrs) {
  if (attrs.size() != attr_names_.size())
    throw std::invalid_argument("PointSet::add: " + std::to_string(attrs.size()) +
                                " attribute values for " + std::to_string(attr_names_.size()) +
                                " columns");
  pos_.push_back(p);
  cls_.push_back(cls);
  for (size_t a = 0; a < attrs.size(); ++a) attrs_[a].push_back(attrs[a]);
}

int PointSet::add_attribute(const std::string& name, double fill) {
  if (attribute_index(name)) throw std::invalid_argument("duplicate attribute column '" + name + "'");
  attr_names_.push_back(name);
  attrs_.emplace_back(pos_.size(), fill);
  return static_cast<int>(attr_names_.size()) - 1;
}

void PointSet::reserve(size_t n) {
  pos_.reserve(n);
  cls_.reserve(n);
  for (auto& c : attrs_) c.reserve(n);
}

int PointSet::num_classes() const {
  if (cls_.empty()) return static_cast<int>(class_labels_.size());
  int k = *std::max_element(cls_.begin(), cls_.end()) + 1;
  return std::max<int>(k, static_cast<int>(class_labels_.size()));
}

int PointSet::class_label(int k) const {
  if (k >= 0 && k < static_cast<int>(class_labels_.size())) return class_labels_[k];
  return k;
}

std::vector<size_t> PointSet::class_counts() const {
  std::vector<size_t> counts(std::max(num_classes(), 0), 0);
  for (int c : cls_) ++counts[c];
  return counts;
}

std::optional<int> PointSet::attribute_index(const std::string& name) const {
  for (size_t a = 0; a < attr_names_.size(); ++a)
    if (attr_names_[a] == name) return static_cast<int>(a);
  return std::nullopt;
}

std::vector<double> PointSet::attributes_of(size_t i) const {
  std::vector<double> v(attrs_.size());
  for (size_t a = 0; a < attrs_.size(); ++a) v[a] = attrs_[a][i];
  return v;
}

PointSet PointSet::subset(const std::vector<size_t>& indices) const {
  PointSet out(domain_);
  out.class_labels_ = class_labels_;
  for (auto& n : attr_names_) out.add_attribute(n);
  out.reserve(indices.size());
  for (size_t i : indices) out.add(pos_[i], cls_[i], attributes_of(i));
  return out;
}

PointSet PointSet::subset_classes(const std::vector<int>& keep) const {
  std::vector<size_t> idx;
  for (size_t i = 0; i < size(); ++i)
    if (std::find(keep.begin(), keep.end(), cls_[i]) != keep.end()) idx.push_back(i);
  return subset(idx);
}

PointSet PointSet::subset_class(int k) const { return subset_classes({k}); }

PointSet PointSet::mapped_to(const Domain& target) const {
  PointSet out = *this;
  out.domain_ = target;
  const double sx = target.width() / domain_.width(), sy = target.height() / domain_.height();
  for (auto& p : out.pos_) {
    p.x = target.x0 + (p.x - domain_.x0) * sx;
    p.y = target.y0 + (p.y - domain_.y0) * sy;
  }
  return out;
}

PointSet PointSet::crop(const Domain& window) const {
  std::vector<size_t> idx;
  for (size_t i = 0; i < size(); ++i) {
    const auto& p = pos_[i];
    // Half-open windows so a point on a shared edge lands in exactly one quadrant; the
    // domain's far edge is closed.
    const bool in_x = p.x >= window.x0 && (p.x < window.x1 || (window.x1 >= domain_.x1 && p.x <= window.x1));
    const bool in_y = p.y >= window.y0 && (p.y < window.y1 || (window.y1 >= domain_.y1 && p.y <= window.y1));
    if (in_x && in_y) idx.push_back(i);
  }
  PointSet out = subset(idx);
  out.domain_ = window;
  return out;
}

PointSet PointSet::tiled_over(const Domain& d, Vec2 origin) const {
  const double w = domain_.width(), h = domain_.height();
  if (!(w > 0 && h > 0)) throw InputError("tiling: the pattern's domain has no area");
  // One tile more on each side than the cover needs: the crop decides what stays.
  const int a0 = static_cast<int>(std::floor((d.x0 - origin.x) / w)) - 1, a1 = static_cast<int>(std::ceil((d.x1 - origin.x) / w));
  const int b0 = static_cast<int>(std::floor((d.y0 - origin.y) / h)) - 1, b1 = static_cast<int>(std::ceil((d.y1 - origin.y) / h));
  PointSet tiled(d);
  tiled.set_class_labels(class_labels_);
  for (auto& n : attr_names_) tiled.add_attribute(n);
  for (int a = a0; a < a1; ++a)
    for (int b = b0; b < b1; ++b)
      for (size_t i = 0; i < size(); ++i)
        tiled.add(Vec2{pos_[i].x - domain_.x0 + a * w + origin.x, pos_[i].y - domain_.y0 + b * h + origin.y}, cls_[i],
                  attributes_of(i));
  return tiled.crop(d);
}

PointSet PointSet::crop_to_unit(const Domain& window) const { return crop(window).mapped_to(Domain{}); }

std::vector<double> PointSet::flat_xy() const {
  std::vector<double> v;
  v.reserve(2 * size());
  for (auto& p : pos_) {
    v.push_back(p.x);
    v.push_back(p.y);
  }
  return v;
}

std::string attribute_value_problem(const std::string& name, double value) {
  std::ostringstream s;
  if (!std::isfinite(value)) {
    s << "attribute '" << name << "' is not finite";
    return s.str();
  }
  if (name == kRadiusAttribute && !(value > 0)) {
    s << "radius " << value << " is not > 0 (a disk radius must be positive)";
    return s.str();
  }
  return "";
}

void validate(const PointSet& ps, const std::string& source) {
  if (ps.empty()) throw file_error(source, 0, "no points");
  for (size_t i = 0; i < ps.size(); ++i) {
    const auto& p = ps[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw file_error(source, 0, "point " + std::to_string(i) + " has a non-finite coordinate");
    if (!ps.domain().contains(p)) {
      std::ostringstream s;
      s << "point " << i << " (" << p.x << ", " << p.y << ") lies outside the domain ["
        << ps.domain().x0 << "," << ps.domain().x1 << "]x[" << ps.domain().y0 << ","
        << ps.domain().y1 << "]";
      throw file_error(source, 0, s.str());
    }
    for (size_t a = 0; a < ps.num_attributes(); ++a) {
      const std::string problem = attribute_value_problem(ps.attribute_names()[a], ps.attr(i, a));
      if (!problem.empty()) throw file_error(source, 0, "point " + std::to_string(i) + ": " + problem);
    }
  }
  auto counts = ps.class_counts();
  for (size_t k = 0; k < counts.size(); ++k)
    if (counts[k] == 0)
      throw file_error(source, 0, "class " + std::to_string(k) + " (label " +
                                      std::to_string(ps.class_label(static_cast<int>(k))) +
                                      ") has no points");
}

std::vector<std::pair<size_t, size_t>> coincident_pairs(const PointSet& ps, double eps) {
  // Sort by x and sweep: O(N log N) for the usual case of few duplicates.
  std::vector<size_t> order(ps.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return ps[a].x < ps[b].x; });
  std::vector<std::pair<size_t, size_t>> out;
  for (size_t a = 0; a < order.size(); ++a)
    for (size_t b = a + 1; b < order.size() && ps[order[b]].x - ps[order[a]].x <= eps; ++b)
      if (std::abs(ps[order[b]].y - ps[order[a]].y) <= eps)
        out.emplace_back(std::min(order[a], order[b]), std::max(order[a], order[b]));
  return out;
}

}  // namespace ppsynth
