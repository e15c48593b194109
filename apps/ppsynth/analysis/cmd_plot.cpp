// `ppsynth plot FILE -o out.png|svg|pdf`: scatter plot of a point file (format by extension
// of the output: PNG, SVG or PDF). With --compare OTHER ...: the files side by side, each
// titled with its file name (e.g. exemplar | output), sharing one class legend.
// Classes use the fixed Tableau-10 palette; disks (a "radius" attribute) are drawn at their
// true radius unless --no-disks. An existing image is replaced only with --force, an input
// never (apps/ppsynth/output_files.hpp).
#include <filesystem>
#include <memory>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/render/plot_points.hpp"

namespace {

using namespace ppsynth;

struct PlotArgs {
  std::string input, output, format, size_attr, color_attr, title;
  std::vector<std::string> compare;
  bool no_disks = false, force = false;
  int size_px = 0;  // 0 = 600 for one plot, 400 per panel, more for many points (readable_plot_px)
  int columns = 0;
};

int run(const PlotArgs& a) {
  ReadOptions ro;
  if (!a.format.empty()) ro.format = parse_format(a.format);
  PointStyle st;
  st.size_attribute = a.size_attr;
  st.color_attribute = a.color_attr;
  st.draw_disks = !a.no_disks;
  st.title = a.title;
  if (a.size_px != 0 && (a.size_px < 80 || a.size_px > 8000)) throw InputError("--size must be in 80..8000 px");
  std::vector<app::NamedPath> inputs{{"file", a.input}};
  for (const auto& f : a.compare) inputs.push_back({"--compare", f});
  app::check_output_files({{"-o", a.output}}, inputs, a.force);
  if (a.compare.empty()) {
    const PointSet ps = read_points(a.input, ro);
    plot_points(a.output, ps, st, a.size_px ? a.size_px : readable_plot_px({&ps}, 600));
  } else {
    std::vector<std::pair<std::string, PointSet>> panels;
    panels.emplace_back(a.title.empty() ? std::filesystem::path(a.input).stem().string() : a.title,
                        read_points(a.input, ro));
    for (const auto& f : a.compare) panels.emplace_back(std::filesystem::path(f).stem().string(), read_points(f, ro));
    st.title.clear();
    std::vector<const PointSet*> sets;
    for (const auto& p : panels) sets.push_back(&p.second);
    plot_panels(a.output, panels, st, a.size_px ? a.size_px : readable_plot_px(sets, 400), a.columns);
  }
  spdlog::info("wrote {}", a.output);
  return 0;
}

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<PlotArgs>();
  app.add_option("file", a->input, "point file")->required()->check(ppsynth::app::path_text());
  app.add_option("-o,--output", a->output, "output image: .png, .svg or .pdf")->required()->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace an existing image");
  app.add_option("--format", a->format, "input format (default: detect from the file)");
  app.add_option("--size-attr", a->size_attr, "attribute mapped to marker size");
  app.add_option("--color-attr", a->color_attr, "attribute mapped to a color ramp (instead of class colors)");
  app.add_flag("--no-disks", a->no_disks, "draw points with a radius attribute as plain markers");
  app.add_option("--title", a->title, "plot title (with --compare: title of the first panel)");
  app.add_option("--compare", a->compare, "more point files, drawn side by side")->expected(1, -1);
  app.add_option("--size", a->size_px, "image (or panel) size in px (default 600, panels 400; larger for 10,000+ points so they stay apart)");
  app.add_option("--columns", a->columns, "panels per row with --compare (0 = one row)");
  return [a]() { return run(*a); };
}

}  // namespace

PPSYNTH_COMMAND("plot", "plot a point file (PNG/SVG/PDF), optionally beside others", setup)
