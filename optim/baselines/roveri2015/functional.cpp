#include "optim/baselines/roveri2015/functional.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth::roveri2015 {

ChannelEncoder::ChannelEncoder(const PointSet& exemplar, double attribute_weight)
    : classes_(std::max(1, exemplar.num_classes())), weight_(attribute_weight) {
  const size_t n = exemplar.size();
  for (size_t c = 0; c < exemplar.num_attributes(); ++c) {
    const auto& col = exemplar.attribute_column(c);
    double m = 0, v = 0;
    for (double x : col) m += x;
    m /= std::max<size_t>(1, n);
    for (double x : col) v += (x - m) * (x - m);
    const double s = n > 1 ? std::sqrt(v / double(n)) : 0.0;
    mean_.push_back(m);
    std_.push_back(s);
    if (s > 1e-12 * std::max(1.0, std::abs(m)) && attribute_weight > 0) active_.push_back(c);
  }
}

void ChannelEncoder::encode(int cls, const double* attrs, double* out) const {
  for (int k = 0; k < classes_; ++k) out[k] = (k == cls) ? 1.0 : 0.0;
  for (size_t j = 0; j < active_.size(); ++j) {
    const size_t c = active_[j];
    out[classes_ + int(j)] = weight_ * (attrs[c] - mean_[c]) / std_[c];
  }
}

int ChannelEncoder::decode_class(const double* ch) const {
  return int(std::max_element(ch, ch + classes_) - ch);
}

void ChannelEncoder::decode_attributes(const double* ch, double* attrs) const {
  for (size_t c = 0; c < mean_.size(); ++c) attrs[c] = mean_[c];
  for (size_t j = 0; j < active_.size(); ++j) {
    const size_t c = active_[j];
    attrs[c] = mean_[c] + std_[c] * ch[classes_ + int(j)] / weight_;
  }
}

void ChannelEncoder::snap(double* ch) const {
  const int k = decode_class(ch);
  for (int c = 0; c < classes_; ++c) ch[c] = (c == k) ? 1.0 : 0.0;
}

FunctionalSet encode_points(const PointSet& ps, const ChannelEncoder& enc) {
  FunctionalSet fs;
  fs.D = enc.channels();
  std::vector<double> ch(size_t(fs.D));
  for (size_t i = 0; i < ps.size(); ++i) {
    const std::vector<double> raw = ps.attributes_of(i);
    enc.encode(ps.cls(i), raw.empty() ? nullptr : raw.data(), ch.data());
    fs.add(ps[i], ch.data());
  }
  return fs;
}

PointSet decode_points(const FunctionalSet& fs, const ChannelEncoder& enc, const PointSet& exemplar,
                       const Domain& domain) {
  PointSet out(domain);
  for (const std::string& name : exemplar.attribute_names()) out.add_attribute(name);
  out.set_class_labels(exemplar.class_labels());
  out.reserve(fs.size());
  std::vector<double> raw(enc.raw_attributes());
  for (size_t i = 0; i < fs.size(); ++i) {
    enc.decode_attributes(fs.attr(i), raw.data());
    out.add(fs.x[i], enc.decode_class(fs.attr(i)), raw);
  }
  return out;
}

double gaussian(Vec2 x, double sigma) { return std::exp(-(x.x * x.x + x.y * x.y) / (sigma * sigma)); }

void evaluate_function(const FunctionalSet& fs, double sigma, Vec2 y, double* out) {
  for (int d = 0; d < fs.D; ++d) out[d] = 0;
  for (size_t i = 0; i < fs.size(); ++i) {
    const double g = gaussian({y.x - fs.x[i].x, y.y - fs.x[i].y}, sigma);
    const double* a = fs.attr(i);
    for (int d = 0; d < fs.D; ++d) out[d] += a[d] * g;
  }
}

}  // namespace ppsynth::roveri2015
