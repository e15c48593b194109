// gather reports the verdict per row as a pass rate over the runs ("2/5 (40 %), 1 cannot
// judge"), the runs that cannot judge counted apart and never as passes, and a row that fails
// without a p (a class missing from the output) counted as a failure, not left out.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "experiments/execute/sweep_runs.hpp"
#include "experiments/gather/gather.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace ppsynth;
using nlohmann::json;

namespace {

json row(const std::string& kind, const std::string& outcome, json p) {
  json r = {{"row", kind}, {"outcome", outcome}, {"p", p}, {"units", {4, 16}}};
  if (kind == "class") {
    r["class"] = 1;
    r["label"] = 1;
  }
  r["pass"] = outcome == "pass" ? json(true) : outcome == "fail" ? json(false) : json(nullptr);
  if (p.is_null()) r["reason"] = "made up by the test";
  return r;
}

}  // namespace

TEST_CASE("gather reports each verdict row's pass rate, cannot-judge runs apart", "[sweep][verdict_honest]") {
  const auto d = test::scratch_dir("gather_pass_rate");
  const std::string dir = (d / "sw").string();
  const json spec = {{"name", "rate"},
                     {"runs", {std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json"}},
                     {"seeds", {"1-5"}},
                     {"quick", true},
                     {"set", {"method.quick.max_iterations=1", "method.quick.res=16", "snapshots=false"}}};
  plan_sweep(expand_sweep_spec(spec, "spec", ""), dir);
  const SweepManifest m = load_sweep(dir);
  REQUIRE(m.rows.size() == 5);
  // Each run's verdict replaced by one the test chooses: "all" passes twice, fails twice and
  // cannot judge once; "class 1" fails once without a p (missing from the output).
  const std::vector<json> all = {row("all", "pass", 0.4), row("all", "pass", 0.2), row("all", "fail", 0.01),
                                 row("all", "cannot judge", nullptr), row("all", "fail", 0.002)};
  for (size_t i = 0; i < m.rows.size(); ++i) {
    REQUIRE(run_sweep_task(dir, m.rows[i].id, "", nullptr) == RowState::Done);
    const fs::path file = fs::path(dir) / m.rows[i].dir / "metrics.json";
    json metrics = json::parse(std::ifstream(file));
    metrics["verdict"]["rows"] = {all[i], i == 0 ? row("class", "fail", nullptr) : row("class", "pass", 0.5)};
    std::ofstream(file) << metrics.dump();
  }
  const GatherResult g = gather_runs({dir}, GatherOptions{});
  auto summary = [&](const std::string& scope, const std::string& metric) -> const MetricSummary* {
    for (const auto& s : g.summaries)
      if (s.scope == scope && s.metric == metric) return &s;
    return nullptr;
  };
  const MetricSummary* a = summary("all", "verdict_pass");
  REQUIRE(a);
  REQUIRE(a->rate);
  CHECK(a->rate->passed == 2);
  CHECK(a->rate->failed == 2);
  CHECK(a->rate->cannot_judge == 1);
  CHECK(a->rate->text() == "2/5 (40 %), 1 cannot judge");
  CHECK_FALSE(summary("all", "verdict_cannot_judge"));  // folded into the rate
  const MetricSummary* c = summary("class 1", "verdict_pass");
  REQUIRE(c);
  REQUIRE(c->rate);
  CHECK(c->rate->text() == "4/5 (80 %)");

  const std::string table = format_gather(g);
  CHECK(table.find("pass 2/5 (40 %), 1 cannot judge") != std::string::npos);
  write_gather(g, (d / "g").string(), false);
  std::ifstream csv(d / "g" / "gather.csv");
  const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  CHECK(text.find("pass rate") != std::string::npos);
  CHECK(text.find("2/5 (40 %), 1 cannot judge") != std::string::npos);
  const json out = json::parse(std::ifstream(d / "g" / "gather.json"));
  bool found = false;
  for (const auto& s : out["summaries"])
    if (s["scope"] == "all" && s["metric"] == "verdict_pass") {
      found = true;
      CHECK(s["pass_rate"]["cannot_judge"] == 1);
      CHECK(s["pass_rate"]["share"] == Approx(0.4));
      CHECK(s["n"] == 5);
    }
  CHECK(found);
}
