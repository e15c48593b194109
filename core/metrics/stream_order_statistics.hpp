#pragma once
// Exact order statistics of values too many to hold but cheap to produce again (the pair
// distances of a pattern: about 1000 per point at spatstat's r_max): the k-th smallest values,
// found over passes through the values, each pass narrowing every rank's value range with a
// histogram until the range holds few enough values to sort, or one value. The same answers as
// sorting the values; memory O(bins + held values), not O(count).
#include <cstddef>
#include <vector>

namespace ppsynth {

class StreamOrderStatistics {
 public:
  // 0-based `ranks` among `count` values (NaN-free) that lie in [lo, hi].
  StreamOrderStatistics(const std::vector<size_t>& ranks, size_t count, double lo, double hi);
  ~StreamOrderStatistics();
  StreamOrderStatistics(const StreamOrderStatistics&) = delete;
  StreamOrderStatistics& operator=(const StreamOrderStatistics&) = delete;
  // A pass: see() every value once (the same values each pass, in any order), then end_pass().
  // A handful of passes for any count: 1 when count <= 2^20, usually 2 beyond.
  bool done() const;
  void see(double v);
  void end_pass();
  // result[t] is the ranks[t]-th smallest value (once done()).
  std::vector<double> values() const;

 private:
  struct Search;
  std::vector<Search> s_;
};

}  // namespace ppsynth
