// Outputs never replace an input, and never replace an existing file without --force, in every
// command that writes a file (apps/ppsynth/output_files.hpp), through the real binary. The
// defect: `eval --exemplar X --output Y --out X` replaced the exemplar with JSON (exit 0) while
// `spectrum` refused the same without --force.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "core/generators/lattices.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using ppsynth::read_file_text;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
const std::string kPptbf = std::string(PPSYNTH_SOURCE_DIR) + "/configs/pptbf/fig2_base.json";
const std::string kKept = "the user's file\n";

// Point files are read by their content, so they may carry an image's extension: a command
// that writes an image can then be pointed at one.
struct Files {
  fs::path dir;
  std::string ex, out, other;  // a 64-point exemplar, a 256-point u = 2 output, a second point file
};

Files point_files(const std::string& name) {
  Files f;
  f.dir = ppsynth::test::scratch_dir(name);
  f.ex = (f.dir / "ex.png").string();
  f.out = (f.dir / "out.png").string();
  f.other = (f.dir / "other.png").string();
  ppsynth::write_points(f.ex, ppsynth::jittered_grid_points(64, 1));
  ppsynth::write_points(f.out, ppsynth::jittered_grid_points(256, 2));
  ppsynth::write_points(f.other, ppsynth::jittered_grid_points(64, 3));
  return f;
}

const char* const kQuickEval = " --no-verdict --no-second-order --no-curves";

}  // namespace

TEST_CASE("no command writes over one of its inputs, even with --force", "[apps][outputs]") {
  const Files f = point_files("outputs_onto_input");
  fs::copy_file(kPptbf, f.dir / "cfg.png");
  const std::string cfg = (f.dir / "cfg.png").string();
  fs::create_symlink(f.ex, f.dir / "link_to_ex.txt");
  const std::string link = (f.dir / "link_to_ex.txt").string();
  struct Case {
    std::string args, input;  // the input the command is told to write over
  };
  for (const Case& c : {
           Case{"eval --exemplar " + f.ex + " --output " + f.out + " --out " + f.ex + kQuickEval, f.ex},
           Case{"eval --exemplar " + f.ex + " --output " + f.out + " --out " + f.out + kQuickEval, f.out},
           Case{"spectrum " + f.ex + " -o " + (f.dir / "s.png").string() + " --frequencies 8 --json " + f.ex, f.ex},
           Case{"spectrum " + f.ex + " -o " + f.ex + " --frequencies 8", f.ex},
           Case{"plot " + f.ex + " -o " + f.ex, f.ex},
           Case{"plot " + f.ex + " --compare " + f.other + " -o " + f.other, f.other},
           Case{"plot-pcf --exemplar " + f.ex + " --output " + f.out + " -o " + f.out, f.out},
           Case{"convert " + f.ex + " " + f.ex, f.ex},
           Case{"convert " + f.ex + " " + link, f.ex},  // through a link to the input
           Case{"convert " + f.ex + " " + (f.dir / "." / "ex.png").string(), f.ex},
           Case{"pptbf " + cfg + " --res 8 -o " + cfg, cfg},
           Case{"pptbf " + cfg + " --res 8 -o " + (f.dir / "p.png").string() + " --points " + cfg, cfg},
           Case{"analyze " + (f.dir / "points.png").string() + " -o " + f.dir.string(), (f.dir / "points.png").string()},
       }) {
    if (c.args.rfind("analyze", 0) == 0) fs::copy_file(f.ex, f.dir / "points.png", fs::copy_options::overwrite_existing);
    const std::string before = read_file_text(c.input);
    for (const std::string force : {"", " --force"}) {
      const auto r = run_ppsynth(c.args + force);
      INFO(c.args << force << "\n" << r.output);
      CHECK(r.status == 2);
      CHECK_THAT(r.output, Catch::Contains("is the input") && Catch::Contains("Nothing was written"));
      CHECK(read_file_text(c.input) == before);
    }
  }
  // Two outputs of one command naming one file: the second would replace the first.
  const auto twice = run_ppsynth("spectrum " + f.ex + " -o " + (f.dir / "t.png").string() + " --frequencies 8 --json " +
                                 (f.dir / "t.png").string());
  CHECK(twice.status == 2);
  CHECK_THAT(twice.output, Catch::Contains("same file"));
  CHECK_FALSE(fs::exists(f.dir / "t.png"));
}

TEST_CASE("no command replaces an existing file without --force", "[apps][outputs]") {
  const Files f = point_files("outputs_existing");
  const std::string kept = (f.dir / "kept.png").string(), kept_txt = (f.dir / "kept.txt").string();
  fs::create_directories(f.dir / "analysis");
  const std::string analysis = (f.dir / "analysis").string();
  struct Case {
    std::string args, existing;
  };
  for (const Case& c : {
           Case{"eval --exemplar " + f.ex + " --output " + f.out + " --out " + kept_txt + kQuickEval, kept_txt},
           Case{"spectrum " + f.ex + " -o " + kept + " --frequencies 8", kept},
           Case{"spectrum " + f.ex + " -o " + (f.dir / "s.png").string() + " --frequencies 8 --json " + kept_txt, kept_txt},
           Case{"plot " + f.ex + " -o " + kept, kept},
           Case{"plot-pcf --exemplar " + f.ex + " --output " + f.out + " -o " + kept, kept},
           Case{"convert " + f.ex + " " + kept_txt, kept_txt},
           Case{"generate uniform -n 10 -o " + kept_txt, kept_txt},
           Case{"pptbf " + kPptbf + " --res 8 -o " + kept, kept},
           Case{"pptbf " + kPptbf + " --res 8 -o " + (f.dir / "p.png").string() + " --points " + kept_txt, kept_txt},
           Case{"analyze " + f.ex + " -o " + analysis, analysis + "/intensity.png"},
       }) {
    for (const std::string& file : {kept, kept_txt, analysis + "/intensity.png"}) std::ofstream(file) << kKept;
    fs::remove(f.dir / "s.png");
    fs::remove(f.dir / "p.png");
    const auto refused = run_ppsynth(c.args);
    INFO(c.args << "\n" << refused.output);
    CHECK(refused.status == 2);
    CHECK_THAT(refused.output, Catch::Contains(c.existing) && Catch::Contains("--force"));
    CHECK(read_file_text(c.existing) == kKept);
    const auto forced = run_ppsynth(c.args + " --force");
    INFO(forced.output);
    CHECK(forced.status == 0);
    CHECK(read_file_text(c.existing) != kKept);
  }
}

TEST_CASE("--force never empties a directory that holds an input", "[apps][outputs]") {
  const auto d = ppsynth::test::scratch_dir("outputs_inside");
  const std::string run = (d / "run").string();
  const std::string quick = " --quick -q --set method.quick.max_iterations=1";
  REQUIRE(run_ppsynth("synthesize " + kLines + quick + " -o " + run).status == 0);
  const std::string output = read_file_text(run + "/output.txt");
  // The run's own output as the next run's exemplar, into the same directory.
  auto r = run_ppsynth("synthesize -e " + run + "/output.txt" + quick + " -o " + run + " --force");
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("holds the input"));
  CHECK(read_file_text(run + "/output.txt") == output);
  // A reference file kept in an earlier gather's directory.
  const std::string g = (d / "g").string();
  REQUIRE(run_ppsynth("gather " + run + " -o " + g).status == 0);
  std::ofstream(g + "/ref.txt") << read_file_text(run + "/output.txt");
  r = run_ppsynth("gather " + run + " -o " + g + " --force --reference " + g + "/ref.txt");
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Catch::Contains("holds the input") && Catch::Contains("ref.txt"));
  CHECK(fs::exists(g + "/ref.txt"));
}
