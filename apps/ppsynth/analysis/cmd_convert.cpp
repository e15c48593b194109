// `ppsynth convert IN OUT [--from F] [--to F] [--scaling S] [--force]`: rewrites a point file in
// another format (core/formats/point_io.hpp). The input is fully read and validated before
// anything is written, and the output is written atomically: bad input leaves no file. An
// existing OUT is replaced only with --force, IN never (apps/ppsynth/output_files.hpp).
#include <memory>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"

namespace {

using namespace ppsynth;

struct ConvertArgs {
  std::string input, output, from = "auto", to = "auto", scaling = "per-axis";
  std::vector<std::string> attribute_names;
  bool force = false;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<ConvertArgs>();
  app.add_option("input", a->input, "point file to read")->required()->check(ppsynth::app::path_text());
  app.add_option("output", a->output, "point file to write")->required()->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace an existing output file");
  app.add_option("--from,--format", a->from, "input format: auto (detect), gabor, point-synthesis, plain, json")
      ->capture_default_str();
  app.add_option("--to", a->to,
                 "output format: auto (.json -> json, else plain), gabor, point-synthesis, plain, json")
      ->capture_default_str();
  app.add_option("--scaling", a->scaling, "point-synthesis input rescaling: per-axis or uniform")
      ->capture_default_str();
  app.add_option("--attribute-names", a->attribute_names,
                 "names of the input's attribute columns (gabor, point-synthesis)")
      ->delimiter(',');
  app.footer(
      "Writing gabor maps the domain onto the unit square and rounds coordinates and attributes\n"
      "to 1e-4 (the format's integer scale). Plain and json keep every double exactly.\n");
  return [a]() {
    ReadOptions ro;
    ro.format = parse_format(a->from);
    ro.scaling = parse_axis_scaling(a->scaling);
    ro.attribute_names = a->attribute_names;
    const Format to = parse_format(a->to);
    app::check_output_files({{"output", a->output}}, {{"input", a->input}}, a->force);
    const PointSet ps = read_points(a->input, ro);
    write_points(a->output, ps, to);
    spdlog::info("wrote {} ({} points, {} classes, {} attributes)", a->output, ps.size(), ps.num_classes(),
                 ps.num_attributes());
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("convert", "convert a point file between the gabor, point-synthesis, plain and json formats", setup)
