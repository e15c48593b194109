#pragma once
// PointSet: the data every stage exchanges. N positions in a rectangular domain, a class id
// per point (0..K-1, dense), and named attribute columns (radius, scale, depth, ...).
// Classes keep the labels they had in their file (`class_labels`) so writers can restore them.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ppsynth {

struct Vec2 {
  double x = 0, y = 0;
};

// Axis-aligned rectangle [x0,x1] x [y0,y1]; `periodic` marks a torus (no edge effects).
struct Domain {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  bool periodic = false;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  double area() const { return width() * height(); }
  bool contains(const Vec2& p, double tol = 1e-9) const {
    return p.x >= x0 - tol && p.x <= x1 + tol && p.y >= y0 - tol && p.y <= y1 + tol;
  }
};

class PointSet {
 public:
  PointSet() = default;
  explicit PointSet(Domain domain) : domain_(domain) {}

  // --- building -------------------------------------------------------------------
  // Adds a point; `attrs` must have one value per attribute column (or be empty when
  // there are no columns).
  void add(Vec2 p, int cls = 0, const std::vector<double>& attrs = {});
  // Declares an attribute column (filled with `fill` for existing points); returns its index.
  int add_attribute(const std::string& name, double fill = 0.0);
  void set_class_labels(std::vector<int> labels) { class_labels_ = std::move(labels); }
  void set_domain(Domain d) { domain_ = d; }
  void reserve(size_t n);

  // --- reading --------------------------------------------------------------------
  size_t size() const { return pos_.size(); }
  bool empty() const { return pos_.empty(); }
  const Domain& domain() const { return domain_; }
  const std::vector<Vec2>& positions() const { return pos_; }
  std::vector<Vec2>& positions() { return pos_; }
  const Vec2& operator[](size_t i) const { return pos_[i]; }
  Vec2& operator[](size_t i) { return pos_[i]; }
  int cls(size_t i) const { return cls_[i]; }
  const std::vector<int>& classes() const { return cls_; }
  void set_cls(size_t i, int c) { cls_[i] = c; }

  // Number of classes K = 1 + max class id (at least 1 when non-empty; 0 when empty).
  int num_classes() const;
  // File label of class k (e.g. 1000 for class 0 in the Gabor format); k when unknown.
  int class_label(int k) const;
  const std::vector<int>& class_labels() const { return class_labels_; }
  // Number of points of each class.
  std::vector<size_t> class_counts() const;

  size_t num_attributes() const { return attr_names_.size(); }
  const std::vector<std::string>& attribute_names() const { return attr_names_; }
  std::optional<int> attribute_index(const std::string& name) const;
  double attr(size_t i, size_t a) const { return attrs_[a][i]; }
  void set_attr(size_t i, size_t a, double v) { attrs_[a][i] = v; }
  const std::vector<double>& attribute_column(size_t a) const { return attrs_[a]; }
  std::vector<double> attributes_of(size_t i) const;

  // --- views ----------------------------------------------------------------------
  // Points of one class (class ids kept), or of the classes in `keep`.
  PointSet subset_class(int k) const;
  PointSet subset_classes(const std::vector<int>& keep) const;
  PointSet subset(const std::vector<size_t>& indices) const;
  // Affine map of the domain onto `target` (positions follow; attributes untouched).
  PointSet mapped_to(const Domain& target) const;
  // Points inside a sub-rectangle (half-open, but closed on the domain's own far edges, so
  // a point on a shared edge lands in exactly one window), coordinates kept, domain `window`.
  PointSet crop(const Domain& window) const;
  // Copies of this set's window tiled over `d` (tile (a, b) shifted by (a w, b h) from
  // `origin`, coordinates relative to the domain's corner), cropped to `d`; classes and
  // attributes kept. The tiled-copy baseline, and the frozen pad of "border": "context".
  PointSet tiled_over(const Domain& d, Vec2 origin) const;
  // crop(window) mapped onto the unit square (the quadrant protocol).
  PointSet crop_to_unit(const Domain& window) const;
  // Flat x0,y0,x1,y1,... (for tensors and metrics).
  std::vector<double> flat_xy() const;

 private:
  Domain domain_;
  std::vector<Vec2> pos_;
  std::vector<int> cls_;
  std::vector<int> class_labels_;
  std::vector<std::string> attr_names_;
  std::vector<std::vector<double>> attrs_;  // column-major: attrs_[a][i]
};

// The attribute column that holds disk radii (domain units): a point set with it is a disk
// pattern (plots draw disks, metrics count overlaps).
inline constexpr const char* kRadiusAttribute = "radius";

// Why `value` cannot be a value of the attribute column `name`, or "" when it can: every
// attribute value is finite, and a radius (kRadiusAttribute) is > 0. Readers call it for
// each value so that their error names the file line; validate() calls it for every point.
std::string attribute_value_problem(const std::string& name, double value);

// Checks what synthesis needs: finite coordinates inside the domain, attribute values that
// attribute_value_problem accepts, at least one point per class id in 0..K-1. Throws
// InputError naming `source` and the first offending point.
void validate(const PointSet& ps, const std::string& source);

// Pairs of coincident points (distance below `eps`), reported by readers.
std::vector<std::pair<size_t, size_t>> coincident_pairs(const PointSet& ps, double eps = 1e-12);

}  // namespace ppsynth
