// `ppsynth reproduce`: the figure-config schema (errors name the key path), method columns
// (ours / init / reference / registry methods / pending), --set routing, the report's files
// and numbers (checked against an independent evaluate()), generated exemplars, atomicity.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "experiments/report/report_tables.hpp"
#include "experiments/plan/reproduce_config.hpp"
#include "experiments/reproduce/reproduce_runner.hpp"
#include "optim/baselines/pcf2017/pcf2017_stats.hpp"
#include "optim/baselines/roveri2015/roveri2015_stats.hpp"
#include "optim/run/run_synthesis.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "core/log.hpp"
#include "core/processor.hpp"
#include "core/metrics/evaluation.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using ppsynth::InputError;
using json = nlohmann::json;
using namespace ppsynth;

const std::string kLines = "shared:data/exemplars/gabor-paper/lines.txt";
const std::string kLinesRef = "shared:data/reference/lines/output.txt";

json lines_panel(const std::string& name) {
  return json{{"name", name}, {"run", {{"exemplar", kLines}, {"method", {{"type", "gabor"}}}}}};
}

json minimal(json panels = json::array({lines_panel("a")})) {
  return json{{"name", "t"}, {"claim", "a claim"}, {"panels", panels}};
}

ReproduceConfig parse(const json& j) { return parse_reproduce_config(j, "", "."); }

// The message of the InputError parse(j) throws ("" if none).
std::string error_of(const json& j) {
  try {
    parse(j);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct QuietLogs {
  QuietLogs() { ppsynth::configure_logging(-2); }
  ~QuietLogs() { ppsynth::configure_logging(0); }
};

const ColumnResult& column(const PanelResult& p, const std::string& name) {
  for (auto& c : p.columns)
    if (c.column == name) return c;
  throw std::runtime_error("no column " + name);
}

}  // namespace

TEST_CASE("figure configs: unknown keys and bad values are errors naming the key path", "[apps][reproduce]") {
  CHECK_NOTHROW(parse(minimal()));
  json j = minimal();
  j["panles"] = 1;
  CHECK_THAT(error_of(j), Catch::Contains("panles") && Catch::Contains("unknown key"));
  j = minimal();
  j["panels"][0]["color"] = "red";
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].color"));
  j = minimal();
  j["panels"][0]["methods"] = {"ours", "magic"};
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].methods[1]") && Catch::Contains("magic"));
  j = minimal();
  j["panels"][0]["methods"] = {"init"};
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].methods") && Catch::Contains("ours"));
  j = minimal();
  j["panels"][0]["methods"] = {"ours", "reference"};
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].reference"));
  j = minimal(json::array({lines_panel("a"), lines_panel("a")}));
  CHECK_THAT(error_of(j), Catch::Contains("panels[1].name") && Catch::Contains("duplicate"));
  j = minimal();
  j["panels"][0]["run"]["method"]["c3"] = 1;
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].run") && Catch::Contains("c3"));
  j = minimal();
  j["panels"][0]["run"]["exemplar"] = "shared:data/exemplars/none_such.txt";
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].run") && Catch::Contains("none_such"));
  j = minimal();
  j["tables"] = {{{"type", "table9"}}};
  CHECK_THAT(error_of(j), Catch::Contains("tables[0].type"));
  j = minimal();
  j["panels"][0]["name"] = "a b/c";
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].name"));
  j = minimal();
  j["panels"][0]["exemplar_generator"] = {{"generator", {{"type", "uniform"}}}, {"n", 16}};
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].run.exemplar"));  // both a file and a generator
  j = minimal();
  j["panels"][0]["run"].erase("exemplar");
  j["panels"][0]["exemplar_generator"] = {{"generator", {{"type", "uniform"}, {"wobble", 2}}}, {"n", 16}};
  CHECK_THAT(error_of(j), Catch::Contains("exemplar_generator.generator.wobble"));
  j = minimal();
  j["panels"][0]["kind"] = "gabor_maps";
  j["panels"][0]["maps"] = {{"sigma", -1}};
  CHECK_THAT(error_of(j), Catch::Contains("panels[0].maps.sigma"));
  // A file's errors name the file.
  const fs::path d = ppsynth::test::scratch_dir("reproduce_badfile");
  std::ofstream(d / "bad.json") << minimal().dump().substr(0, 20);
  CHECK_THROWS_WITH(load_reproduce_config((d / "bad.json").string()), Catch::Contains("bad.json"));
  j = minimal();
  j["nme"] = "x";
  std::ofstream(d / "unknown.json") << j.dump();
  CHECK_THROWS_WITH(load_reproduce_config((d / "unknown.json").string()), Catch::Contains("unknown.json") && Catch::Contains("nme"));
}

TEST_CASE("method columns: registry names, pending methods, parameters and --set routing", "[apps][reproduce]") {
  json j = minimal();
  j["methods"] = {"ours", "pcf2017", "not_yet_written"};
  CHECK_THAT(error_of(j), Catch::Contains("not_yet_written"));
  j["pending_methods"] = {"not_yet_written"};
  j["method_params"] = {{"pcf2017", {{"iterations", 7}}}};
  auto c = parse(j);
  REQUIRE(c.panels[0].methods == std::vector<std::string>{"ours", "pcf2017", "not_yet_written"});
  CHECK_FALSE(method_available("not_yet_written"));
  CHECK(method_available("pcf2017"));

  const std::vector<std::string> sets = {"seed=7", "method.max_iterations=3", "preset=fast"};
  json ours = column_run_config(c, c.panels[0], "ours", sets);
  json pcf = column_run_config(c, c.panels[0], "pcf2017", sets);
  CHECK(ours["seed"] == 7);
  CHECK(pcf["seed"] == 7);
  CHECK(ours["method"]["type"] == "gabor");
  CHECK(ours["method"]["max_iterations"] == 3);
  CHECK(pcf["method"] == json({{"type", "pcf2017"}, {"iterations", 7}}));  // method.* keys are ours only
  CHECK(ours["preset"] == "fast");  // a preset sets the gabor method's keys: ours only (reproduce --preset)
  CHECK_FALSE(pcf.contains("preset"));
  CHECK(ours["exemplar"] == pcf["exemplar"]);

  // A bad parameter of a baseline is caught before anything runs.
  j["method_params"] = {{"pcf2017", {{"iteratons", 7}}}};
  CHECK_THAT(error_of(j), Catch::Contains("column 'pcf2017'") && Catch::Contains("iteratons"));
}

TEST_CASE("a panel where a preset is not equivalent keeps the config's own settings under it", "[apps][reproduce]") {
  json a = lines_panel("a");
  a["presets_not_equivalent"] = {{"fast", "its stopping rule keeps the initialization here"}};
  const auto c = parse(minimal(json::array({a, lines_panel("b")})));
  const std::vector<std::string> sets = {"seed=7", "preset=fast", "method.max_iterations=3"};
  const json ours_a = column_run_config(c, c.panels[0], "ours", sets);
  CHECK_FALSE(ours_a.contains("preset"));               // set aside on the panel that says so
  CHECK(ours_a["seed"] == 7);                           // every other override still applies
  CHECK(ours_a["method"]["max_iterations"] == 3);
  CHECK(column_run_config(c, c.panels[1], "ours", sets)["preset"] == "fast");  // not on the others
  CHECK(presets_set_aside(c, sets) ==
        json::array({{{"panel", "a"}, {"preset", "fast"}, {"why", "its stopping rule keeps the initialization here"}}}));
  CHECK(presets_set_aside(c, {"seed=7"}).empty());      // no preset asked: nothing set aside

  // Only a known preset, and only with its reason.
  a["presets_not_equivalent"] = {{"fastest", "why"}};
  CHECK_THAT(error_of(minimal(json::array({a}))), Catch::Contains("panels[0].presets_not_equivalent.fastest") && Catch::Contains("not a preset"));
  a["presets_not_equivalent"] = {{"fast", ""}};
  CHECK_THAT(error_of(minimal(json::array({a}))), Catch::Contains("panels[0].presets_not_equivalent.fast") && Catch::Contains("reason"));
  a["presets_not_equivalent"] = json::array({"fast"});
  CHECK_THAT(error_of(minimal(json::array({a}))), Catch::Contains("panels[0].presets_not_equivalent"));
}

TEST_CASE("a reproduction writes a report whose numbers match an independent evaluation", "[apps][reproduce]") {
  QuietLogs quiet;
  const fs::path d = ppsynth::test::scratch_dir("reproduce_report");
  json panel = lines_panel("lines");
  panel["reference"] = kLinesRef;
  panel["stages"] = true;
  panel["paper"] = {{"pcf_mse", {{"ours", 0.39}, {"MWT11", 0.63}}}};
  json j = minimal(json::array({panel}));
  j["methods"] = {"ours", "init", "reference", "pcf2017", "later_method"};
  j["pending_methods"] = {"later_method"};
  j["tables"] = {{{"type", "comparison"}, {"name", "cmp"}},
                 {{"type", "relative_radius"}, {"paper", {{"exemplar", 0.73}}}},
                 {{"type", "runtime"}}};
  auto c = parse(j);
  ReproduceOptions o;
  o.quick = true;
  o.out = (d / "rep").string();
  auto r = run_reproduction(c, o);
  REQUIRE(r.panels.size() == 1);
  const PanelResult& p = r.panels[0];
  REQUIRE(p.columns.size() == 5);
  CHECK(column(p, "ours").status == "ok");
  CHECK(column(p, "pcf2017").status == "ok");
  CHECK(column(p, "later_method").status == "pending");
  CHECK(column(p, "ours").output.size() == 4 * p.exemplar.size());

  // reference and init columns: the same numbers as evaluate() on the files themselves.
  const auto ref = ppsynth::read_points(kLinesRef);
  CHECK(column(p, "reference").metrics["all"]["pcf_mse"].get<double>() ==
        Approx(ppsynth::evaluate(p.exemplar, ref)["all"]["pcf_mse"].get<double>()));
  const auto init = ppsynth::read_points((d / "rep/panels/lines/ours/init.txt").string());
  CHECK(column(p, "init").metrics["all"]["chamfer"].get<double>() ==
        Approx(ppsynth::evaluate(p.exemplar, init)["all"]["chamfer"].get<double>()).epsilon(1e-6));
  CHECK(column(p, "init").metrics["all"]["pcf_mse"] != column(p, "ours").metrics["all"]["pcf_mse"]);

  // Files: the report, its tables (CSV + Markdown), the overview, the run directories.
  for (auto f : {"index.html", "report.json", "figure.png", "metrics.csv", "metrics.md", "cmp.csv", "cmp.md",
                 "relative_radius.csv", "runtime.csv", "panels/lines/side_by_side.png", "panels/lines/pcf_compare.png",
                 "panels/lines/ours/output.txt", "panels/lines/pcf2017/output.txt", "panels/lines/ours/snapshots/stage01.png"})
    CHECK(fs::exists(d / "rep" / f));
  CHECK_FALSE(fs::exists(d / "rep.partial"));
  const std::string html = ppsynth::read_file_text(d / "rep/index.html");
  CHECK(html.find("a claim") != std::string::npos);
  CHECK(html.find("data:image/png;base64,") != std::string::npos);
  CHECK(html.find("later_method: not available") != std::string::npos);
  CHECK(html.find("src=\"panels/") == std::string::npos);  // self-contained: no file links

  // metrics.csv: a header and one row per column; the comparison table keeps paper-only columns.
  std::ifstream mcsv(d / "rep/metrics.csv");
  int lines = 0;
  for (std::string l; std::getline(mcsv, l);) ++lines;
  CHECK(lines == 1 + 5);
  const std::string cmp = ppsynth::read_file_text(d / "rep/cmp.csv");
  CHECK(cmp.find("PCF MSE MWT11") != std::string::npos);
  CHECK(cmp.find("lines (paper)") != std::string::npos);
  const std::string rr = ppsynth::read_file_text(d / "rep/relative_radius.csv");
  CHECK(rr.find("0.7300") != std::string::npos);
  const std::string rt = ppsynth::read_file_text(d / "rep/runtime.csv");
  CHECK(rt.find("s per iteration (ours)") != std::string::npos);
  CHECK(rt.find("processor (ours)") != std::string::npos);
  CHECK(rt.find(ppsynth::processor_kind()) != std::string::npos);  // the run's, from its run.json

  json rep = json::parse(ppsynth::read_file_text(d / "rep/report.json"));
  CHECK(rep["quick"] == true);
  CHECK(rep["presets_set_aside"] == json::array());  // no preset asked, none set aside
  CHECK(rep["panels"][0]["columns"].size() == 5);
  CHECK(rep["panels"][0]["columns"][0]["metrics"]["all"]["pcf_mse"] == column(p, "ours").metrics["all"]["pcf_mse"]);
  CHECK(rep["panels"][0]["columns"][0]["processor"] == ppsynth::processor_kind());

  // Same config and seed: byte-identical outputs.
  o.out = (d / "rep2").string();
  run_reproduction(c, o);
  CHECK(ppsynth::read_file_text(d / "rep/panels/lines/ours/output.txt") == ppsynth::read_file_text(d / "rep2/panels/lines/ours/output.txt"));
  CHECK(ppsynth::read_file_text(d / "rep/panels/lines/pcf2017/output.txt") == ppsynth::read_file_text(d / "rep2/panels/lines/pcf2017/output.txt"));

  // --reuse: a finished run with the same resolved config is copied, not re-run; a run whose
  // config differs (another seed) is not taken, and a full run never stands in for a quick one.
  fs::create_directories(d / "pool");
  fs::copy(d / "rep/panels/lines/ours", d / "pool/lines_a", fs::copy_options::recursive);
  {
    std::ofstream marker(d / "pool/lines_a/reused_marker");
  }
  json other = json::parse(ppsynth::read_file_text(d / "rep/panels/lines/ours/config.json"));
  other["seed"] = 7;
  CHECK_FALSE(same_synthesis(other, json::parse(ppsynth::read_file_text(d / "pool/lines_a/config.json"))));
  o.out = (d / "rep3").string();
  o.reuse = {(d / "pool").string()};
  auto r3 = run_reproduction(c, o);
  CHECK(fs::exists(d / "rep3/panels/lines/ours/reused_marker"));
  CHECK(column(r3.panels[0], "ours").source.find("reused from") != std::string::npos);
  CHECK(column(r3.panels[0], "ours").metrics["all"]["pcf_mse"] == column(p, "ours").metrics["all"]["pcf_mse"]);
  CHECK_FALSE(fs::exists(d / "rep3/panels/lines/pcf2017/reused_marker"));
  CHECK(find_matching_run(json::parse(ppsynth::read_file_text(d / "pool/lines_a/config.json")), false, o.reuse).empty());
  // A rule that reads the runs' CPU time (table3) takes no run made before it was recorded
  // (run.json cpu_seconds 0); any other rule still does.
  const json lines_config = json::parse(ppsynth::read_file_text(d / "pool/lines_a/config.json"));
  ReuseRule needs_cpu;
  needs_cpu.needs_cpu_seconds = true;
  CHECK(ppsynth::read_run_record((d / "pool/lines_a/run.json").string()).cpu_seconds > 0);
  CHECK_FALSE(find_matching_run(lines_config, true, {(d / "pool").string()}, needs_cpu).empty());
  fs::create_directories(d / "pool_old");
  fs::copy(d / "pool/lines_a", d / "pool_old/lines_b", fs::copy_options::recursive);
  json old_record = json::parse(ppsynth::read_file_text(d / "pool_old/lines_b/run.json"));
  old_record["cpu_seconds"] = 0;
  ppsynth::write_text_atomic((d / "pool_old/lines_b/run.json").string(), old_record.dump(2) + "\n");
  CHECK_FALSE(find_matching_run(lines_config, true, {(d / "pool_old").string()}, ReuseRule{}).empty());
  CHECK(find_matching_run(lines_config, true, {(d / "pool_old").string()}, needs_cpu).empty());
  o.reuse = {};
}

TEST_CASE("generated exemplars and Gabor map panels", "[apps][reproduce]") {
  QuietLogs quiet;
  const fs::path d = ppsynth::test::scratch_dir("reproduce_generated");
  json gen = {{"name", "g"}, {"run", {{"method", {{"type", "gabor"}}}}},
              {"exemplar_generator", {{"generator", {{"type", "jittered_grid"}}}, {"n", 25}, {"seed", 3}}}};
  json maps = {{"name", "m"}, {"kind", "gabor_maps"}, {"run", {{"exemplar", kLines}}},
               {"maps", {{"sigma", 0.05}, {"sigmas", {0.02, 0.05, 0.1}}, {"quick_res", 16}}}};
  auto c = parse(minimal(json::array({gen, maps})));
  ReproduceOptions o;
  o.quick = true;
  o.out = (d / "rep").string();
  auto r = run_reproduction(c, o);
  CHECK(r.panels[0].exemplar.size() == 25);
  auto written = ppsynth::read_points((d / "rep/panels/g/exemplar.txt").string());
  CHECK(written.size() == 25);
  // The run's config.json names the exemplar where it is now, not in the ".partial" folder.
  const std::string cfg = ppsynth::read_file_text(d / "rep/panels/g/ours/config.json");
  CHECK(cfg.find(".partial") == std::string::npos);
  CHECK(json::parse(cfg)["exemplar"] == fs::absolute(d / "rep/panels/g/exemplar.txt").string());
  CHECK(r.panels[1].columns.empty());
  CHECK(r.panels[1].images.size() == 3);
  for (auto f : {"gabor_exemplar.png", "gabor_frequencies.png", "gabor_sigmas.png"})
    CHECK(fs::file_size(d / "rep/panels/m" / f) > 1000);

  // Another report generates the same exemplar in its own folder: --reuse matches the first
  // report's run by the exemplar's points, not its file name; another generator seed does not.
  auto c1 = parse(minimal(json::array({gen})));
  o.reuse = {(d / "rep/panels/g").string()};
  o.out = (d / "rep_same").string();
  auto same = run_reproduction(c1, o);
  CHECK(same.panels[0].columns[0].source.find("reused from") != std::string::npos);
  CHECK(ppsynth::read_file_text(d / "rep_same/panels/g/ours/output.txt") == ppsynth::read_file_text(d / "rep/panels/g/ours/output.txt"));
  json gen2 = gen;
  gen2["exemplar_generator"]["seed"] = 4;
  o.out = (d / "rep_other").string();
  auto other = run_reproduction(parse(minimal(json::array({gen2}))), o);
  CHECK(other.panels[0].columns[0].source.find("reused from") == std::string::npos);
  // The reused run reads its exemplar from its own copy, even after the source report is gone.
  fs::remove_all(d / "rep/panels/g/exemplar.txt");
  auto loaded = load_run((d / "rep_same/panels/g/ours").string());
  CHECK(loaded.exemplar.size() == 25);
}

TEST_CASE("a failing reproduction writes nothing and keeps the previous report", "[apps][reproduce]") {
  QuietLogs quiet;
  const fs::path d = ppsynth::test::scratch_dir("reproduce_failing");
  std::ofstream(d / "bad.txt") << "0.1 0.2\n0.3 nan\n";
  json panel = {{"name", "p"}, {"run", {{"exemplar", (d / "bad.txt").string()}}}};
  auto c = parse(minimal(json::array({panel})));  // the file exists: it fails when read
  fs::create_directories(d / "rep");
  std::ofstream(d / "rep/index.html") << "previous";
  ReproduceOptions o;
  o.quick = true;
  o.out = (d / "rep").string();
  CHECK_THROWS_AS(run_reproduction(c, o), InputError);
  CHECK(ppsynth::read_file_text(d / "rep/index.html") == "previous");
  CHECK_FALSE(fs::exists(d / "rep.partial"));
  // A bad --set is refused before anything is written.
  auto good = parse(minimal());
  o.out = (d / "rep_set").string();
  o.overrides = {"method.c3=1"};
  CHECK_THROWS_WITH(run_reproduction(good, o), Catch::Contains("panels[0]") && Catch::Contains("c3"));
  CHECK_FALSE(fs::exists(d / "rep_set"));
  CHECK_FALSE(fs::exists(d / "rep_set.partial"));
}

TEST_CASE("--panels runs only the named panels and says which were left out", "[apps][reproduce]") {
  QuietLogs quiet;
  const fs::path d = ppsynth::test::scratch_dir("reproduce_panels");
  auto c = parse(minimal(json::array({lines_panel("a"), lines_panel("b")})));
  ReproduceOptions o;
  o.quick = true;
  o.out = (d / "rep").string();
  o.panels = {"b"};
  auto r = run_reproduction(c, o);
  REQUIRE(r.panels.size() == 1);
  CHECK(r.panels[0].name == "b");
  CHECK_FALSE(fs::exists(d / "rep/panels/a"));
  CHECK(ppsynth::read_file_text(d / "rep/index.html").find("panel(s) a not run") != std::string::npos);
  o.panels = {"z"};
  o.out = (d / "rep_bad").string();
  CHECK_THROWS_WITH(run_reproduction(c, o), Catch::Contains("'z'") && Catch::Contains("a, b"));
  CHECK_FALSE(fs::exists(d / "rep_bad"));
}

TEST_CASE("report cells and config lookup", "[apps][reproduce]") {
  CHECK(format_cell(json(0.123456)) == "0.1235");
  CHECK(format_cell(json(3)) == "3");
  CHECK(format_cell(json(nullptr)) == "n/a");
  CHECK(format_cell(json("0.66, 0.65")) == "0.66, 0.65");
  CHECK_THROWS_WITH(find_reproduce_config("fig99"), Catch::Contains("fig99") && Catch::Contains("fig05"));
  CHECK(fs::path(find_reproduce_config("fig05")).filename() == "fig05.json");
}

TEST_CASE("a run's iterations, from its stages or its method's typed stats", "[apps][reproduce][method_stats]") {
  const auto run_of = [](const char* method, json stats) {
    RunOutcome o;
    o.dir = "runs/x";
    o.config = resolve_run_config(json{{"exemplar", "x.txt"}, {"method", {{"type", method}}}}, {});
    o.stats = std::move(stats);
    return o;
  };
  RunOutcome staged = run_of("gabor", json::object());
  staged.stages = {StageRecord{"a", 4}, StageRecord{"b", 3}};
  CHECK(total_iterations(staged) == 7);
  pcf2017::Pcf2017Stats pcf;
  pcf.descent = pcf2017::Pcf2017Descent{30, 2.0, 0.1, false, 0.2};
  CHECK(total_iterations(run_of("pcf2017", to_json(pcf))) == 30);
  // A rectangle: every class's descent (a class too small for a PCF has none).
  pcf.descent.reset();
  pcf.rectangle = RectangleStats{"3 x 1 exemplar units, clean border", {0, 0, 3, 1}, 50};
  pcf.classes = {{0, {0, 0, 3, 1}, 40, pcf2017::Pcf2017Descent{30, 2.0, 0.1, false, 0.2}},
                 {1, {0, 0, 3, 1}, 2, std::nullopt},
                 {2, {0, 0, 3, 2}, 8, pcf2017::Pcf2017Descent{12, 1.0, 0.5, true, 0.4}}};
  CHECK(total_iterations(run_of("pcf2017", to_json(pcf))) == 42);
  roveri2015::Roveri2015Stats rov;
  rov.scales = {{0.3, 2, 1, 78, 0, 0, 5, 0.5}, {0.2, 1, 0.5, 78, 0, 0, 2, 0.5}};
  CHECK(total_iterations(run_of("roveri2015", to_json(rov))) == 7);
  CHECK(total_iterations(run_of("tiled_copy", nullptr)) == 0);
  json bad = to_json(rov);
  bad["scales"][1]["merge_iterations"] = "two";
  CHECK_THROWS_MATCHES(total_iterations(run_of("roveri2015", bad)), InputError,
                       Catch::Matchers::Message("runs/x/run.json: method_stats: 'scales[1].merge_iterations' is not an integer"));
}
