#include "core/metrics/stream_order_statistics.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace ppsynth {

namespace {
constexpr size_t kBins = 4096;
// A range holding at most this many values is sorted (8 MiB of doubles).
constexpr size_t kMaxHeld = size_t{1} << 20;
}  // namespace

// What one rank knows: its value lies in [lo, hi], and `below` values of this pass are < lo.
struct StreamOrderStatistics::Search {
  size_t rank = 0;
  double lo = 0, hi = 0;
  size_t below = 0;
  bool collect = false, done = false;
  double value = 0;
  std::vector<size_t> count;
  std::vector<double> bin_min, bin_max;
  std::vector<double> held;

  // Monotone in v, so the values of [bin_min[b], bin_max[b]] all fall in bin b.
  size_t bin(double v) const {
    if (!(hi > lo)) return 0;
    return std::min(kBins - 1, static_cast<size_t>((v - lo) / (hi - lo) * static_cast<double>(kBins)));
  }
  void start() {
    below = 0;
    held.clear();
    if (!collect) {
      count.assign(kBins, 0);
      bin_min.assign(kBins, std::numeric_limits<double>::infinity());
      bin_max.assign(kBins, -std::numeric_limits<double>::infinity());
    }
  }
  void see(double v) {
    if (v < lo) {
      ++below;
    } else if (v <= hi) {
      if (collect) {
        held.push_back(v);
      } else {
        const size_t b = bin(v);
        ++count[b];
        bin_min[b] = std::min(bin_min[b], v);
        bin_max[b] = std::max(bin_max[b], v);
      }
    }
  }
  void end() {
    const size_t k = rank - below;  // the rank within [lo, hi]
    if (collect) {
      std::nth_element(held.begin(), held.begin() + static_cast<std::ptrdiff_t>(k), held.end());
      value = held[k];
      done = true;
      held = {};
      return;
    }
    size_t seen = 0, b = 0;
    while (b + 1 < kBins && seen + count[b] <= k) seen += count[b++];
    if (bin_min[b] == bin_max[b]) {
      value = bin_min[b];
      done = true;
    } else {
      lo = bin_min[b];
      hi = bin_max[b];
      collect = count[b] <= kMaxHeld;
    }
    count = {};
    bin_min = {};
    bin_max = {};
  }
};

StreamOrderStatistics::StreamOrderStatistics(const std::vector<size_t>& ranks, size_t count, double lo, double hi) {
  s_.resize(ranks.size());
  for (size_t t = 0; t < ranks.size(); ++t) {
    if (ranks[t] >= count)
      throw InputError("StreamOrderStatistics: rank " + std::to_string(ranks[t]) + " of " + std::to_string(count) + " values");
    s_[t].rank = ranks[t];
    s_[t].lo = lo;
    s_[t].hi = hi;
    s_[t].collect = count <= kMaxHeld;
    s_[t].start();
  }
}

StreamOrderStatistics::~StreamOrderStatistics() = default;

bool StreamOrderStatistics::done() const {
  return std::all_of(s_.begin(), s_.end(), [](const Search& x) { return x.done; });
}

void StreamOrderStatistics::see(double v) {
  for (auto& x : s_)
    if (!x.done) x.see(v);
}

void StreamOrderStatistics::end_pass() {
  for (auto& x : s_)
    if (!x.done) {
      x.end();
      if (!x.done) x.start();
    }
}

std::vector<double> StreamOrderStatistics::values() const {
  std::vector<double> out;
  for (const auto& x : s_) out.push_back(x.value);
  return out;
}

}  // namespace ppsynth
