// A paper item's rule (configs/paper/*.json "rule"): the schema refuses what it does not know,
// naming the key path; every paper config states one and it leaves the runs' configs as they
// were; the verdict follows from the numbers by the rule (synthetic numbers: a rule that should
// fail fails); the numbers over seeds come from a sweep (generated exemplars too, --reuse per
// seed); the page over the reports.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/formats/text_table.hpp"
#include "core/log.hpp"
#include "core/paths.hpp"
#include "core/processor.hpp"
#include "core/run_directory.hpp"
#include "experiments/plan/reproduce_config.hpp"
#include "experiments/plan/sweep_plan.hpp"
#include "experiments/report/reproduce_page.hpp"
#include "experiments/report/reproduce_verdict.hpp"
#include "experiments/report/verdict_html.hpp"
#include "experiments/reproduce/reproduce_runner.hpp"
#include "optim/run/presets.hpp"
#include "optim/run/run_config.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace ppsynth;

const std::string kLines = "shared:data/exemplars/gabor-paper/lines.txt";
const std::string kLinesRef = "shared:data/reference/lines/output.txt";

json config_with_rule(json rule) {
  return json{{"name", "t"},
              {"claim", "c"},
              {"methods", {"ours", "init", "pcf2017"}},
              {"panels", {{{"name", "a"}, {"reference", kLinesRef}, {"run", {{"exemplar", kLines}, {"method", {{"type", "gabor"}}}}}}}},
              {"rule", rule}};
}

json better_rule() {
  return json{{"statement", "ours beats pcf2017"},
              {"checks", {{{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}}}}};
}

std::string error_of(const json& j) {
  try {
    parse_reproduce_config(j, "", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Five seeds of one group and metric.
std::map<uint64_t, double> five(double a, double b, double c, double d, double e) {
  return {{95, a}, {96, b}, {97, c}, {98, d}, {99, e}};
}

ReproduceRule rule_of(const json& rule) { return parse_reproduce_config(config_with_rule(rule), "", ".").rule; }

}  // namespace

TEST_CASE("a diagnosis block: three strings, unknown keys and other types refused by key path", "[reproduce_rules]") {
  json c = config_with_rule(better_rule());
  c["diagnosis"] = {{"text", "why"}, {"published_code", "0.0155"}, {"see", "docs/lab/x/README.md"}};
  CHECK(parse_reproduce_config(c, "", ".").diagnosis["published_code"] == "0.0155");
  c["diagnosis"]["seee"] = "typo";
  CHECK_THAT(error_of(c), Catch::Contains("diagnosis.seee"));
  c["diagnosis"].erase("seee");
  c["diagnosis"]["text"] = 3;
  CHECK_THAT(error_of(c), Catch::Contains("diagnosis.text"));
  CHECK(parse_reproduce_config(config_with_rule(better_rule()), "", ".").diagnosis["text"] == "");  // none written
}

TEST_CASE("a rule block is checked: unknown keys and bad values name the key path", "[reproduce_rules]") {
  CHECK(error_of(config_with_rule(better_rule())).empty());
  json r = better_rule();
  r["checks"][0]["thn"] = {"a/pcf2017"};
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].thn"));
  r = better_rule();
  r["verdict"] = "reproduced";
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.verdict"));
  r = better_rule();
  r["checks"][0]["tolerance"] = 0.1;  // a key of another type of check
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].tolerance"));
  r = better_rule();
  r["checks"][0]["group"] = "b/ours";
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].group") && Catch::Contains("no synthesis panel 'b'"));
  r = better_rule();
  r["checks"][0]["than"] = {"a/roveri2015"};
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].than[0]") && Catch::Contains("no column 'roveri2015'"));
  r = better_rule();
  r["checks"][0]["metric"] = "all/pcf";
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].metric"));
  r = better_rule();
  r["checks"][0]["type"] = "best";
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].type"));
  r = better_rule();
  r["checks"][0]["min_share"] = 1.5;
  CHECK_THAT(error_of(config_with_rule(r)), Catch::Contains("rule.checks[0].min_share"));
  CHECK_THAT(error_of(config_with_rule({{"statement", "s"}, {"kind", "pictures"}, {"checks", better_rule()["checks"]}})),
             Catch::Contains("rule.checks"));
  CHECK_THAT(error_of(config_with_rule({{"statement", "s"}})), Catch::Contains("rule.checks"));
  CHECK_THAT(error_of(config_with_rule({{"kind", "pictures"}})), Catch::Contains("rule.statement"));
  CHECK_THAT(error_of(config_with_rule({{"statement", "s"},
                                        {"checks", {{{"type", "threshold"}, {"metric", "all/overlap_pairs"}, {"group", "a/ours"},
                                                     {"op", "=="}, {"value", 0}}}}})),
             Catch::Contains("rule.checks[0].op"));
  // "init" and "reference" are groups of a panel with ours / a published output.
  r = better_rule();
  r["checks"][0]["than"] = {"a/init", "a/reference"};
  CHECK(error_of(config_with_rule(r)).empty());
}

TEST_CASE("every paper config states a rule, and the rule is not part of any run", "[reproduce_rules]") {
  size_t n = 0;
  for (const auto& f : list_reproduce_configs(paper_config_dir())) {
    INFO(f);
    const ReproduceConfig c = load_reproduce_config(f);
    CHECK(!c.rule.kind.empty());
    CHECK(!c.rule.statement.empty());
    // The same config without its rule starts the same runs (so --reuse and sweep ids match).
    json raw = c.raw;
    raw.erase("rule");
    const ReproduceConfig bare = parse_reproduce_config(raw, f, fs::path(f).parent_path().string());
    CHECK(bare.rule.kind.empty());
    for (size_t i = 0; i < c.panels.size(); ++i)
      for (const auto& col : c.panels[i].methods) {
        if (col == "init" || col == "reference" || !method_available(col)) continue;
        CHECK(column_run_config(c, c.panels[i], col, {}) == column_run_config(bare, bare.panels[i], col, {}));
      }
    ++n;
  }
  CHECK(n >= 21);
}

TEST_CASE("verdicts follow from the numbers by the rule", "[reproduce_rules]") {
  ItemNumbers n;
  n.per_seed["a/ours"]["all/pcf_mse"] = five(0.010, 0.011, 0.009, 0.012, 0.010);
  n.per_seed["a/pcf2017"]["all/pcf_mse"] = five(0.020, 0.021, 0.019, 0.022, 0.020);
  n.per_seed["a/init"]["all/pcf_mse"] = five(0.011, 0.009, 0.008, 0.013, 0.009);  // ours wins 2 of 5, median 0.009 < 0.010
  n.fixed["a/reference"]["all/pcf_mse"] = 0.0105;
  n.per_seed["a/ours"]["all/relative_radius"] = five(0.50, 0.52, 0.51, 0.53, 0.513);
  n.per_seed["a/pcf2017"]["all/relative_radius"] = five(0.40, 0.41, 0.42, 0.43, 0.44);
  n.per_seed["a/ours"]["all/overlap_pairs"] = five(2, 3, 0, 5, 1);
  n.exemplar["a"]["all/relative_radius"] = 0.761;
  n.exemplar["a"]["all/overlap_pairs"] = 0;

  auto check = [&](const json& c) {
    const ItemVerdict v = judge_item(rule_of({{"statement", "s"}, {"checks", {c}}}), n);
    REQUIRE(v.checks.size() == 1);
    INFO(v.checks[0].numbers);
    return v.checks[0].state;
  };
  const json better = {{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}};
  CHECK(check(better) == "pass");
  json b = better;
  b["than"] = {"a/init"};
  CHECK(check(b) == "fail");  // worse median, and 2 of 5 seeds
  b["than"] = {"a/pcf2017", "a/init"};
  CHECK(check(b) == "fail");  // must beat each
  b["than"] = {"a/reference"};
  CHECK(check(b) == "fail");  // a value drawn once: every seed against it, 4 of 5 needed, 3 win
  b["min_share"] = 0.6;
  CHECK(check(b) == "pass");
  json swapped = {{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/pcf2017"}, {"than", {"a/ours"}}};
  CHECK(check(swapped) == "fail");
  swapped["higher_is_better"] = true;
  CHECK(check(swapped) == "pass");

  // Table 1: the exemplar's rho 0.761, ours 0.513: not within 10 %; but closer than pcf2017's.
  const json within = {{"type", "within"}, {"metric", "all/relative_radius"}, {"group", "a/ours"}, {"target", "exemplar"}, {"tolerance", 0.1}};
  CHECK(check(within) == "fail");
  json w = within;
  w["tolerance"] = 0.35;
  CHECK(check(w) == "pass");
  CHECK(check({{"type", "better"}, {"metric", "all/relative_radius"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}, {"toward", "exemplar"}}) ==
        "pass");
  CHECK(check({{"type", "better"}, {"metric", "all/relative_radius"}, {"group", "a/pcf2017"}, {"than", {"a/ours"}}, {"toward", "exemplar"}}) ==
        "fail");

  // Overlaps: more than the exemplar's 0 in 4 of 5 seeds meets 80 %, not 100 %.
  json t = {{"type", "threshold"}, {"metric", "all/overlap_pairs"}, {"group", "a/ours"}, {"op", ">"}, {"value", "exemplar"}};
  CHECK(check(t) == "pass");
  t["min_share"] = 1.0;
  CHECK(check(t) == "fail");

  // Against the published output: 0.010 <= 1.25 x 0.0105, not <= 0.9 x.
  json nw = {{"type", "not_worse"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"target", "a/reference"}, {"tolerance", 0.25}};
  CHECK(check(nw) == "pass");
  nw["target"] = 0.009;
  nw["tolerance"] = 0.0;
  CHECK(check(nw) == "fail");

  // A group no run made: no data, and the item is incomplete.
  CHECK(check({{"type", "better"}, {"metric", "all/wasserstein"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}}) == "no data");

  auto item = [&](const json& checks) { return judge_item(rule_of({{"statement", "s"}, {"checks", checks}}), n).verdict; };
  CHECK(item({better, within}) == "partly");
  t["min_share"] = 0.8;
  CHECK(item({better, t}) == "reproduced");
  CHECK(item(json::array({within})) == "not reproduced");
  CHECK(item({better, {{"type", "better"}, {"metric", "all/chamfer"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}}}) == "incomplete");
  CHECK(item({{{"type", "better"}, {"metric", "all/chamfer"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}}}) == "not run");
  CHECK(judge_item(rule_of({{"statement", "s"}, {"kind", "pictures"}}), n).verdict == "pictures");
  CHECK(judge_item(ReproduceRule{}, n).verdict == "no rule");

  // The decided numbers are in the check's text.
  const ItemVerdict v = judge_item(rule_of({{"statement", "s"}, {"checks", {within}}}), n);
  CHECK_THAT(v.checks[0].numbers, Catch::Contains("0.513") && Catch::Contains("0.761") && Catch::Contains("32.6 %"));
}

TEST_CASE("a check between groups made under different preset variants says it is not like for like", "[reproduce_rules]") {
  ItemNumbers n;
  n.per_seed["a/ours"]["all/pcf_mse"] = five(0.010, 0.011, 0.009, 0.012, 0.010);
  n.per_seed["a/pcf2017"]["all/pcf_mse"] = five(0.020, 0.021, 0.019, 0.022, 0.020);
  n.per_seed["a/reference"]["all/pcf_mse"] = five(0.020, 0.021, 0.019, 0.022, 0.020);
  for (uint64_t seed = 95; seed <= 99; ++seed) {
    n.made_under["a/ours"][seed] = "every processor";  // reused from a machine with bf16 units
    n.made_under["a/pcf2017"][seed] = "without bf16 units";
    n.made_under["a/reference"][seed] = "every processor";
  }
  n.made_under["a/ours"][99] = "without bf16 units";
  auto only = [&](const json& c) {
    const ItemVerdict v = judge_item(rule_of({{"statement", "s"}, {"checks", {c}}}), n);
    REQUIRE(v.checks.size() == 1);
    return v.checks[0];
  };
  const CheckResult mixed = only({{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}});
  CHECK(mixed.state == "pass");  // the rule's state stands; the check says what it compared
  CHECK(mixed.mixed_variants == "a/ours: every processor (4), without bf16 units (1); a/pcf2017: without bf16 units (5)");
  const json within = {{"type", "within"}, {"metric", "all/pcf_mse"}, {"group", "a/pcf2017"}, {"target", "a/ours"}, {"tolerance", 2.0}};
  CHECK(only(within).mixed_variants == "a/pcf2017: without bf16 units (5); a/ours: every processor (4), without bf16 units (1)");
  CHECK(verdict_json(judge_item(rule_of({{"statement", "s"}, {"checks", {within}}}), n))["checks"][0].contains("mixed_variants"));
  CHECK_THAT(check_numbers_text(verdict_json(judge_item(rule_of({{"statement", "s"}, {"checks", {within}}}), n))["checks"][0]),
             Catch::Contains("Not like for like") && Catch::Contains("a/pcf2017: without bf16 units (5)"));

  // The same variants on both sides, or a side without a preset: nothing to say.
  n.made_under["a/ours"][99] = "every processor";
  CHECK(only({{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"than", {"a/reference"}}}).mixed_variants.empty());
  n.made_under.erase("a/pcf2017");
  const CheckResult unrecorded = only({{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"than", {"a/pcf2017"}}});
  CHECK(unrecorded.mixed_variants.empty());
  CHECK_FALSE(verdict_json(judge_item(rule_of({{"statement", "s"}, {"checks", {within}}}), n))["checks"][0].contains("mixed_variants"));
}

TEST_CASE("over seeds: each seed's runs, their initializations, a generated exemplar, --reuse per seed", "[reproduce_rules]") {
  // Through the command: a sweep's tasks run in processes of their own.
  const fs::path d = ppsynth::test::scratch_dir("reproduce_rules_seeds");
  // A generated exemplar panel (Table 1's kind) with ours and its initialization.
  json fig = {{"name", "gen"},
              {"methods", {"ours", "init"}},
              {"panels",
               {{{"name", "a"},
                 {"exemplar_generator", {{"generator", {{"type", "ccvt"}, {"points_per_site", 64}}}, {"n", 24}, {"seed", 3}}},
                 {"run", {{"seed", 3}, {"method", {{"type", "gabor"}}}}}}}},  // the panel shows seed 3's runs
              {"rule",
               {{"statement", "ours beats its start"},
                {"checks", {{{"type", "better"}, {"metric", "all/pcf_mse"}, {"group", "a/ours"}, {"than", {"a/init"}}, {"min_share", 0.5}}}}}},
              {"diagnosis", {{"text", "a diagnosis written after the runs"}}}};
  const std::string file = (d / "gen.json").string();
  std::ofstream(file) << fig.dump(2);
  const std::string base = "reproduce " + file + " --quick --seeds 3-4 --preset fast";
  auto r = ppsynth::test::run_ppsynth(base + " -o " + (d / "report").string() + " --sweep " + (d / "sweep").string(), "PPSYNTH_THREADS=1");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const json report = json::parse(read_file_text((d / "report" / "report.json").string()));
  const json& groups = report["numbers"]["groups"];
  CHECK(groups["a/ours"]["all/pcf_mse"]["seeds"] == json{3, 4});
  CHECK(groups["a/init"]["all/pcf_mse"]["seeds"] == json{3, 4});  // each seed's initialization
  CHECK(groups["a/ours"]["run/iterations"]["min"].get<double>() > 0);
  // Each seed's CPU time, beside its wall time: what a timing rule judges a loaded sweep by.
  CHECK(groups["a/ours"]["run/cpu_seconds"]["seeds"] == json{3, 4});
  CHECK(groups["a/ours"]["run/cpu_seconds"]["min"].get<double>() > 0);
  REQUIRE(report["verdict"]["checks"].size() == 1);
  CHECK(report["verdict"]["checks"][0]["numbers"].get<std::string>().find("wins") != std::string::npos);
  // Each seed's preset variant, from its run.json: what a check's like-for-like note reads.
  const std::string variant = cpu_isa().native_bf16 ? kPresetEveryProcessor : kPresetWithoutBf16Units;
  CHECK(report["numbers"]["made_under"]["a/ours"] == json{{"3", variant}, {"4", variant}});
  CHECK_FALSE(report["verdict"]["checks"][0].contains("mixed_variants"));  // ours and its own start
  // The report's panel is the sweep's seed-3 run (one generated exemplar file for both), not a third run.
  CHECK(report["panels"][0]["columns"][0]["source"].get<std::string>().find("reused from") != std::string::npos);
  // The page's header names every seed and the one its pictures show (it said "seed(s) 3").
  CHECK(read_file_text((d / "report" / "index.html").string()).find("3-4 (the pictures: seed 3)") != std::string::npos);
  CHECK(read_file_text((d / "report" / "index.html").string()).find("a diagnosis written after the runs") != std::string::npos);
  CHECK(read_file_text((d / "report" / "index.html").string()).find("2 runs in the sweep took") != std::string::npos);
  CHECK(report["diagnosis"]["text"] == "a diagnosis written after the runs");

  // Another sweep of the same runs takes them from the first, seed by seed, without running any.
  r = ppsynth::test::run_ppsynth(base + " -o " + (d / "report2").string() + " --sweep " + (d / "sweep2").string() + " --reuse " +
                                     (d / "sweep" / "runs").string() + " --plan-only",
                                 "PPSYNTH_THREADS=1");
  REQUIRE(r.status == 0);
  const SweepManifest m = load_sweep((d / "sweep2").string());
  REQUIRE(m.rows.size() == 2);
  for (const auto& row : m.rows) CHECK(run_dir_state((d / "sweep2" / row.dir).string()) == RunDirState::Complete);
}

TEST_CASE("the page puts every report's verdict beside the claim, and replaces only its own page", "[reproduce_rules]") {
  const fs::path d = ppsynth::test::scratch_dir("reproduce_rules_page");
  CHECK_THROWS_AS(write_reproduce_page(d.string()), InputError);  // no report
  auto report = [&](const std::string& name, const std::string& kind, const std::string& verdict) {
    fs::create_directories(d / name);
    json r = {{"name", name}, {"title", name + " title"}, {"claim", "claim of " + name}, {"paper_ref", "Fig. x"}, {"kind", kind},
              {"quick", true}, {"seeds", "95-96"}, {"figure", ""},
              {"rule", {{"checks", {{{"metric", "all/wasserstein"}}}}}},
              {"verdict", {{"verdict", verdict}, {"statement", "rule of " + name},
                           {"checks", {{{"check", "a/ours lower"}, {"state", "pass"}, {"numbers", "a/ours median 0.01"}}}}}},
              {"numbers", {{"groups", {{"a/ours", {{"all/pcf_mse", {{"n", 2}, {"median", 0.01}, {"min", 0.009}, {"max", 0.011}}}}},
                                       {"a/reference", {{"all/pcf_mse", {{"fixed", true}, {"n", 1}, {"median", 0.02}, {"min", 0.02}, {"max", 0.02}}}}}}},
                           {"exemplar", json::object()}}},
              {"panels", json::array()}};
    std::ofstream(d / name / "report.json") << r.dump();
  };
  report("table1", "table", "not reproduced");
  report("fig10", "figure", "partly");
  report("fig03", "figure", "pictures");
  report("fig08", "figure", "not run");  // a report whose checks all lack numbers: still linked to its section
  {  // table1's config wrote a diagnosis after its runs; fig10's has none (older reports lack the key)
    json r = json::parse(read_file_text((d / "table1" / "report.json").string()));
    r["diagnosis"] = {{"text", "coincident pairs at the finest sigma"}, {"published_code", "not run: 2 h a run"}, {"see", "docs/lab/close_pairs/README.md"}};
    // its two seeds' runs made on machines of both kinds; fig10's on one without bf16 units
    r["numbers"]["made_under"] = {{"a/ours", {{"95", "without bf16 units"}, {"96", "every processor"}}}};
    std::ofstream(d / "table1" / "report.json") << r.dump();
    json f = json::parse(read_file_text((d / "fig10" / "report.json").string()));
    f["numbers"]["made_under"] = {{"a/ours", {{"95", "without bf16 units"}, {"96", "without bf16 units"}}}};
    // fig10 ran at the fast preset, but its panel a kept the config's own settings
    f["overrides"] = {"preset=fast"};
    f["presets_set_aside"] = json::array({{{"panel", "a"}, {"preset", "fast"}, {"why", "its stopping rule keeps the start"}}});
    std::ofstream(d / "fig10" / "report.json") << f.dump();
  }
  CHECK(write_reproduce_page(d.string()) == 4);
  const std::string html = read_file_text((d / "index.html").string());
  CHECK_THAT(html, Catch::Contains("coincident pairs at the finest sigma") && Catch::Contains("not run: 2 h a run") &&
                       Catch::Contains("docs/lab/close_pairs/README.md"));
  CHECK(html.find("What we know") > html.find("table1: table1 title"));  // under table1 only
  CHECK_THAT(html, Catch::Contains("the configs&#39; own") || Catch::Contains("the configs' own"));  // no --set in table1's report
  CHECK_THAT(read_file_text((d / "index.md").string()),
             Catch::Contains("settings: preset=fast; panel a at the config's own settings (the fast preset is not equivalent there)"));
  CHECK_THAT(read_file_text((d / "index.md").string()), Catch::Contains("- **The published code on this item.** not run: 2 h a run"));
  CHECK_THAT(html, Catch::Contains("claim of table1") && Catch::Contains("not reproduced") && Catch::Contains("rule of fig10") &&
                       Catch::Contains("0.01 [0.009 - 0.011] (2)") && Catch::Contains("0.02 (drawn once)"));
  CHECK(html.find("fig03: fig03 title") < html.find("fig10: fig10 title"));    // figures in number order
  CHECK(html.find("fig10: fig10 title") < html.find("table1: table1 title"));  // then tables
  CHECK_THAT(read_file_text((d / "index.md").string()), Catch::Contains("**Verdict by rule: partly**"));
  // Which network each item rests on (kept runs come from machines with and without bf16 units).
  CHECK_THAT(read_file_text((d / "index.md").string()),
             Catch::Contains("the runs made under the preset variants every processor (1), without bf16 units (3), counted per item") &&
                 Catch::Contains("made under: every processor (1), without bf16 units (1))") &&
                 Catch::Contains("made under: without bf16 units (2))") && Catch::Contains("made under: no preset recorded)"));
  // The paper's items without a report here are rows "not run", in the paper's order, with their
  // claims from configs/paper: the page says what is left.
  const size_t papers = list_reproduce_configs(paper_config_dir()).size();
  const std::string md = read_file_text((d / "index.md").string());
  CHECK_THAT(md, Catch::Contains(std::to_string(papers) + " items; ") && Catch::Contains("not run: " + std::to_string(papers - 3)));
  CHECK(html.find("href=\"#fig08\"") != std::string::npos);
  const json fig05 = json::parse(read_file_text(find_reproduce_config("fig05")));
  CHECK_THAT(md, Catch::Contains("| fig05 | " + fig05["paper_ref"].get<std::string>() + " | " + fig05["claim"].get<std::string>() +
                                 " | not run | - | - |"));
  CHECK(md.find("| fig05 |") > md.find("| fig03 |"));
  CHECK(md.find("| fig05 |") < md.find("| fig10 |"));
  CHECK(md.find("## fig05") == std::string::npos);  // no section without a report
  CHECK(read_file_text((d / "index.html").string()).find("href=\"#fig05\"") == std::string::npos);
  CHECK(write_reproduce_page(d.string()) == 4);  // its own page is replaced
  std::ofstream(d / "index.html") << "<html>someone's page</html>";
  CHECK_THROWS_WITH(write_reproduce_page(d.string()), Catch::Contains("not replaced"));
  CHECK(read_file_text((d / "index.html").string()) == "<html>someone's page</html>");
}

TEST_CASE("the rules table of docs/howto/reproduce_a_figure.md is the configs' (ppsynth reproduce --rules)", "[reproduce_rules]") {
  const std::string doc = read_file_text(source_root() + "/docs/howto/reproduce_a_figure.md");
  const std::string begin = "<!-- rules:begin -->\n", end = "<!-- rules:end -->";
  const size_t a = doc.find(begin), b = doc.find(end);
  REQUIRE(a != std::string::npos);
  REQUIRE(b != std::string::npos);
  CHECK(doc.substr(a + begin.size(), b - a - begin.size()) == rules_markdown(list_reproduce_configs(paper_config_dir())));
}
