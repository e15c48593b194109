// The second-order summaries (core/metrics/second_order.hpp, mark_correlation.hpp,
// second_order_report.hpp) in bounded memory: the pairs are summed as they are found, the
// mark correlation's bandwidth takes its quartiles from passes over the pairs
// (stream_order_statistics.hpp), and more than 64 classes leave out the class pairs' rows. A
// long computation ends at its caller's stop check (core/poll.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"
#include "core/metrics/mark_correlation.hpp"
#include "core/metrics/overlap.hpp"
#include "core/metrics/second_order.hpp"
#include "core/metrics/second_order_report.hpp"
#include "core/metrics/stream_order_statistics.hpp"
#include "core/poll.hpp"
#include "tests/support/sanitizers.hpp"

using namespace ppsynth;

namespace {

// n points with a "mark" column, all within a disk of radius `spread` at the unit square's
// center: every pair is within spatstat's r_max (n^2 pairs).
PointSet cluster(size_t n, double spread, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointSet ps(Domain{0, 0, 1, 1});
  ps.add_attribute("mark");
  while (ps.size() < n) {
    const double x = 2 * u(rng) - 1, y = 2 * u(rng) - 1;
    if (x * x + y * y <= 1) ps.add({0.5 + spread * x, 0.5 + spread * y}, 0, {0.5 + u(rng)});
  }
  return ps;
}

double virtual_bytes() {  // VmSize of this process
  std::ifstream in("/proc/self/status");
  std::string key;
  double kib = 0;
  while (in >> key) {
    if (key == "VmSize:") {
      in >> kib;
      break;
    }
    std::getline(in, key);
  }
  return kib * 1024.0;
}

// Runs `work` in a child process whose address space may grow by `headroom` bytes only: its
// exit status (0 when `work` returned, 1 when it threw, e.g. std::bad_alloc).
template <class F>
int with_address_space_headroom(double headroom, F work) {
  const pid_t pid = fork();
  if (pid == 0) {
    const auto limit = static_cast<rlim_t>(virtual_bytes() + headroom);
    const rlimit rl{limit, limit};
    setrlimit(RLIMIT_AS, &rl);
    int code = 0;
    try {
      work();
    } catch (...) {
      code = 1;
    }
    _exit(code);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

TEST_CASE("K, L, g and the mark correlation of 9 million pairs fit in 128 MiB more memory", "[metrics][spatstat][memory]") {
  if (test::kAddressSanitizer) {
    WARN("built with AddressSanitizer: it reserves terabytes of address space, no limit to set");
    return;
  }
  // 3000 points in one cluster: 9 million ordered pairs within reach, 216 MB as the pair list
  // the estimators once held (more while it grew).
  const PointSet ps = cluster(3000, 0.02, 7);
  const int status = with_address_space_headroom(128.0 * 1024 * 1024, [&] {
    const SecondOrder s = second_order(ps, nullptr, EdgeCorrection::Translation);
    if (!(s.k.back() > 0)) throw std::runtime_error("no pairs");
    const MarkCorrelation m = mark_correlation(ps, 0, EdgeCorrection::Translation);
    if (!(m.bandwidth > 0)) throw std::runtime_error("no bandwidth");
  });
  CHECK(status == 0);
}

TEST_CASE("stream order statistics equal sorting, over many values, ties and a narrow spread", "[metrics][spatstat]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Beyond the 2^20 values held at once: the histogram passes narrow the range first.
  std::vector<double> v(3'000'000);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = i % 3 == 0 ? 0.25 : i % 3 == 1 ? 1e-9 * u(rng) + 0.5 : u(rng);  // a third tied, a third within 1e-9
  std::vector<double> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  const std::vector<size_t> ranks = {0, 1, 999'999, 1'000'000, 1'500'000, 2'000'000, 2'999'999};
  StreamOrderStatistics s(ranks, v.size(), sorted.front(), sorted.back());
  int passes = 0;
  while (!s.done()) {
    for (double x : v) s.see(x);
    s.end_pass();
    ++passes;
  }
  const std::vector<double> got = s.values();
  for (size_t t = 0; t < ranks.size(); ++t) CHECK(got[t] == sorted[ranks[t]]);
  CHECK(passes <= 4);
  // The bandwidth of few values: R's bw.nrd0(c(0.3, 0.1, 0.4, 0.1, 0.5, 0.9, 0.2)).
  const std::vector<double> few = {0.3, 0.1, 0.4, 0.1, 0.5, 0.9, 0.2};
  const double bw = bandwidth_nrd0([&](const std::function<void(double)>& sink) {
    for (double x : few) sink(x);
  });
  CHECK(bw == Approx(0.13653354225233572).epsilon(1e-14));
}

TEST_CASE("more than 64 classes: no class-pair rows of K, L, g, and the report says so", "[metrics][spatstat]") {
  for (const int K : {kMaxPairClasses, kMaxPairClasses + 1}) {
    PointSet ps(Domain{0, 0, 1, 1});
    std::mt19937_64 rng(K);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 3 * K; ++i) ps.add({u(rng), u(rng)}, i % K);
    const nlohmann::json so = second_order_report(ps, ps, 1.0, false);
    size_t pairs = 0, classes = 0;
    for (const auto& row : so["rows"]) pairs += row["row"] == "pair", classes += row["row"] == "class";
    INFO(K << " classes");
    CHECK(classes == static_cast<size_t>(K));
    if (K <= kMaxPairClasses) {
      CHECK(pairs == static_cast<size_t>(K * (K - 1) / 2));
      CHECK_FALSE(so.contains("pairs_skipped"));
    } else {
      CHECK(pairs == 0);
      CHECK(so["pairs_skipped"].get<std::string>().find("65 classes") != std::string::npos);
      // eval's table says it too.
      EvalOptions opt;
      opt.verdict = false;
      opt.include_curves = false;
      const std::string text = format_evaluation(evaluate(ps, ps, opt));
      CHECK(text.find("class pairs' K, L and g are computed up to 64 classes only") != std::string::npos);
    }
  }
}

TEST_CASE("the second order ends at its caller's stop check", "[metrics][spatstat]") {
  struct Stop {};
  const PointSet ps = cluster(2000, 0.3, 5);
  int calls = 0;
  const PollScope scope([&] {
    if (++calls == 3) throw Stop{};
  });
  CHECK_THROWS_AS(second_order(ps, nullptr, EdgeCorrection::Translation), Stop);
  CHECK(calls == 3);
  calls = 0;
  CHECK_THROWS_AS(mark_correlation(ps, 0, EdgeCorrection::Translation), Stop);
}
