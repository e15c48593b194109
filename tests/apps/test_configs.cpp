// Every config under configs/ runs, through the same functions the commands call, with
// --quick settings (so no config can rot):
//   configs/runs, configs/methods  -> resolve_run_config + run_synthesis (a method-only
//                                     fragment runs on the lines exemplar)
//   configs/paper                  -> load_reproduce_config + run_reproduction (report)
//   configs/pptbf                  -> pptbf_params_from_json + render_pptbf (16 x 16)
//   configs/sweeps                 -> expand_sweep_spec + the first row run as a sweep task
// and no config lives in a folder this test does not know.

#include <catch2/catch.hpp>

#include "core/output_shape.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "experiments/plan/reproduce_config.hpp"
#include "experiments/reproduce/reproduce_runner.hpp"
#include "optim/run/run_config.hpp"
#include "optim/run/run_synthesis.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "experiments/execute/sweep_runs.hpp"
#include "core/config/config.hpp"
#include "core/log.hpp"
#include "core/procedural/pptbf.hpp"
#include "core/procedural/pptbf_params.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using ppsynth::json;

const fs::path kConfigs = fs::path(PPSYNTH_SOURCE_DIR) / "configs";

std::vector<fs::path> json_files(const fs::path& dir) {
  std::vector<fs::path> v;
  for (auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

size_t count_points(const fs::path& f) {
  std::ifstream in(f);
  size_t n = 0;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') ++n;
  return n;
}

struct QuietLogs {
  QuietLogs() { ppsynth::configure_logging(-2); }
  ~QuietLogs() { ppsynth::configure_logging(0); }
};

}  // namespace

TEST_CASE("every config folder is one this test runs", "[apps][configs]") {
  const std::set<std::string> known = {"runs", "methods", "paper", "pptbf", "sweeps"};
  for (auto& e : fs::directory_iterator(kConfigs)) {
    INFO(e.path().string());
    if (e.is_directory()) CHECK(known.count(e.path().filename().string()) == 1);
    else CHECK(e.path().extension() != ".json");  // loose configs at the top would be skipped
  }
  for (auto& d : known) CHECK_FALSE(json_files(kConfigs / d).empty());
}

TEST_CASE("every run config runs with --quick", "[apps][configs]") {
  QuietLogs quiet;
  const fs::path out = ppsynth::test::scratch_dir("configs_runs");
  for (const char* dir : {"runs", "methods"})
    for (auto& f : json_files(kConfigs / dir)) {
      INFO(f.string());
      json c = ppsynth::load_config(f.string());
      // A method-only fragment (configs/methods/pcf2017.json) runs on the lines exemplar.
      if (!c.contains("exemplar")) c["exemplar"] = "shared:data/exemplars/gabor-paper/lines.txt";
      try {
        json r = ppsynth::resolve_run_config(c, {});
        const fs::path run_dir = out / (std::string(dir) + "_" + f.stem().string());
        ppsynth::RunRequest req;
        req.dir = run_dir.string();
        req.quick = true;
        auto o = ppsynth::run_synthesis(r, req);
        const ppsynth::OutputShape shape = ppsynth::resolve_output_shape(r, o.exemplar);
        const double target = shape.expected_points(o.exemplar);
        if (r["method"]["type"] == "roveri2015")  // sampling control (Eq. 3.7) adapts the count
          CHECK(std::abs(double(o.output.size()) - target) <= 0.25 * target);
        else if (shape.rectangle && shape.clean_border)  // the crop of a padded canvas: the density's expectation
          CHECK(std::abs(double(o.output.size()) - target) <= 3 * std::sqrt(target) + 1);
        else
          CHECK(double(o.output.size()) == target);
        CHECK(o.output.domain().x1 == shape.domain().x1);
        CHECK(o.output.domain().y1 == shape.domain().y1);
        // The Gabor method keeps every class; the baselines document that they pool them.
        if (r["method"]["type"] == "gabor") CHECK(o.output.num_classes() == o.exemplar.num_classes());
        CHECK(count_points(run_dir / "output.txt") == o.output.size());
        CHECK(fs::exists(run_dir / "run.json"));
        CHECK(std::isfinite(o.metrics["all"]["pcf_mse"].get<double>()));
      } catch (const std::exception& e) {
        FAIL_CHECK(f.string() << ": " << e.what());
      }
    }
}

TEST_CASE("the paper's choices where the defaults differ are pinned once, in configs/methods/gabor_published.json", "[apps][configs]") {
  // A default that changes (the border relax became one) is then one edit, not one per config.
  const json published = ppsynth::load_config((kConfigs / "methods" / "gabor_published.json").string());
  CHECK(published["method"]["border_relax"]["iterations"] == 0);
  CHECK(published["method"]["map_terms"]["class_own"]["weight"] == 0);  // a later class on the joint maps alone
  CHECK(published["method"]["revisit"]["iterations"] == 0);             // no class moves again once the next begins
  for (auto& f : json_files(kConfigs / "runs")) {
    INFO(f.string());
    std::ifstream in(f);
    const json own = json::parse(in);  // the file itself, without its parent chain
    const bool pins = own.contains("method") && own["method"].contains("border_relax") &&
                      own["method"]["border_relax"].contains("iterations") && own["method"]["border_relax"]["iterations"] == 0;
    CHECK_FALSE(pins);
  }
  const json lines = ppsynth::resolve_run_config(ppsynth::load_config((kConfigs / "runs" / "lines.json").string()), {});
  CHECK(lines["method"]["border_relax"]["iterations"] == 0);  // through the parent
  const json two = ppsynth::resolve_run_config(ppsynth::load_config((kConfigs / "runs" / "poisson_n64c2_point.json").string()), {});
  CHECK(two["method"]["map_terms"]["class_own"]["weight"] == 0);
  CHECK(two["method"]["revisit"]["iterations"] == 0);
}

TEST_CASE("every paper config (configs/paper) reproduces with --quick", "[apps][configs][reproduce]") {
  QuietLogs quiet;
  const fs::path out = ppsynth::test::scratch_dir("configs_paper");
  const auto files = json_files(kConfigs / "paper");
  REQUIRE(files.size() >= 20);  // one config per row of method.md section 7 (and more)
  for (auto& f : files) {
    INFO(f.string());
    try {
      auto c = ppsynth::load_reproduce_config(f.string());
      CHECK(c.name == f.stem().string());
      CHECK_FALSE(c.claim.empty());
      ppsynth::ReproduceOptions o;
      o.quick = true;
      o.out = (out / c.name).string();
      auto r = ppsynth::run_reproduction(c, o);
      CHECK(fs::exists(out / c.name / "index.html"));
      // A metrics table where something was synthesized; none of headers only for maps alone (fig03).
      const bool synthesizes = std::any_of(c.panels.begin(), c.panels.end(), [](const auto& p) { return p.kind == "synthesis"; });
      CHECK(fs::exists(out / c.name / "metrics.csv") == synthesizes);
      CHECK_FALSE(fs::exists(out / (c.name + ".partial")));
      for (auto& t : c.tables) {
        CHECK(fs::exists(out / c.name / (t.name + ".csv")));
        CHECK(fs::exists(out / c.name / (t.name + ".md")));
      }
      REQUIRE(r.panels.size() == c.panels.size());
      for (size_t i = 0; i < r.panels.size(); ++i) {
        INFO("panel " << r.panels[i].name);
        CHECK_FALSE(r.panels[i].images.empty());
        if (c.panels[i].kind != "synthesis") continue;
        CHECK(r.panels[i].columns.size() == c.panels[i].methods.size());
        for (auto& col : r.panels[i].columns) {
          INFO("column " << col.column << " status " << col.status);
          if (col.column == "ours") CHECK(col.status == "ok");
          if (col.status != "ok") continue;
          CHECK(col.output.size() > 0);
          CHECK(std::isfinite(col.metrics["all"]["pcf_mse"].get<double>()));
        }
      }
    } catch (const std::exception& e) {
      FAIL_CHECK(f.string() << ": " << e.what());
    }
  }
}

TEST_CASE("every PPTBF config parses and renders", "[apps][configs]") {
  for (auto& f : json_files(kConfigs / "pptbf")) {
    INFO(f.string());
    try {
      auto p = ppsynth::pptbf_params_from_json(ppsynth::load_config(f.string()));
      auto img = ppsynth::render_pptbf(p, 16, 16);
      CHECK(img.pixels.size() == 256u);
      CHECK(std::all_of(img.pixels.begin(), img.pixels.end(), [](float v) { return std::isfinite(v); }));
    } catch (const std::exception& e) {
      FAIL_CHECK(f.string() << ": " << e.what());
    }
  }
}

TEST_CASE("every sweep spec (configs/sweeps) plans, and its first run runs with --quick", "[apps][configs][sweep]") {
  QuietLogs quiet;
  const auto d = ppsynth::test::scratch_dir("configs_sweeps");
  for (const auto& f : json_files(kConfigs / "sweeps")) {
    INFO(f.string());
    json spec = ppsynth::load_config(f.string());
    spec["quick"] = true;  // what it plans is checked as written; what it runs, on a tiny grid
    const auto m = ppsynth::expand_sweep_spec(spec, f.string(), f.parent_path().string());
    REQUIRE_FALSE(m.rows.empty());
    const std::string dir = (d / f.stem()).string();
    ppsynth::plan_sweep(m, dir);
    CHECK(ppsynth::run_sweep_task(dir, m.rows[0].id, "", nullptr) == ppsynth::RowState::Done);
  }
}
