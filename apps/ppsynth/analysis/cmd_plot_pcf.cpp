// `ppsynth plot-pcf --exemplar E --output O -o pcf.png`: pair correlation functions of an
// exemplar (dashed) and a synthesized output (solid), core/metrics/pcf.hpp, radii in units
// of each set's own r_max so an exemplar and its u^2-times larger output line up.
// One class: one plot. K classes: a grid with the whole pattern and each class's auto-PCF
// (classes matched by class id). An existing image is replaced only with --force, an input
// never (apps/ppsynth/output_files.hpp).
#include <algorithm>
#include <filesystem>
#include <memory>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/metrics/pcf.hpp"
#include "core/render/plot_curves.hpp"

namespace {

using namespace ppsynth;

struct PlotPcfArgs {
  std::string exemplar, output, image, format, title;
  int bins = 100;
  double r_max_factor = 2.5, sigma_factor = 0.25;
  bool periodic = false, force = false;
};

CurvePlot pcf_plot(const std::string& title, const PointSet& ex, const PointSet& out, const PcfOptions& opt) {
  const Curve ge = pcf(ex, opt), go = pcf(out, opt);
  CurvePlot p;
  p.title = title;
  p.xlabel = "r / r_max";
  p.ylabel = "g(r)";
  p.series.push_back({"exemplar (N=" + std::to_string(ex.size()) + ")", ge.r, ge.g, true});
  p.series.push_back({"output (N=" + std::to_string(out.size()) + ")", go.r, go.g, false});
  return p;
}

int run(const PlotPcfArgs& a) {
  if (a.bins < 2 || a.bins > 10000) throw InputError("--bins must be in 2..10000");
  // Radii reach r_max_factor r_max (+ 4 sigma): large factors put every pair within reach.
  if (!(a.r_max_factor > 0) || a.r_max_factor > 100) throw InputError("--r-max-factor must be in (0, 100]");
  if (!(a.sigma_factor > 0) || a.sigma_factor > 10) throw InputError("--sigma-factor must be in (0, 10]");
  app::check_output_files({{"-o", a.image}}, {{"--exemplar", a.exemplar}, {"--output", a.output}}, a.force);
  ReadOptions ro;
  if (!a.format.empty()) ro.format = parse_format(a.format);
  const PointSet ex = read_points(a.exemplar, ro), out = read_points(a.output, ro);
  PcfOptions opt;
  opt.bins = a.bins;
  opt.r_max_factor = a.r_max_factor;
  opt.sigma_factor = a.sigma_factor;
  opt.periodic = a.periodic;
  const std::string title = a.title.empty() ? "PCF: " + std::filesystem::path(a.exemplar).stem().string() + " vs " +
                                                  std::filesystem::path(a.output).stem().string()
                                            : a.title;
  const int k = std::max(ex.num_classes(), out.num_classes());
  if (k <= 1) {
    plot_curves(a.image, pcf_plot(title, ex, out, opt));
  } else {
    if (ex.num_classes() != out.num_classes())
      throw InputError("exemplar has " + std::to_string(ex.num_classes()) + " classes but output has " +
                       std::to_string(out.num_classes()));
    // The grid shows what fits one image (render/plot_curves.hpp); only those PCFs are
    // computed, from one pass over each set (not one per class).
    const int columns = std::min(3, k + 1);
    const CurveGridLayout layout = curve_grid_layout(static_cast<size_t>(k) + 1, columns, 420, 300);
    const int shown_classes = static_cast<int>(std::min<size_t>(k, layout.shown - 1));
    std::vector<std::vector<size_t>> ex_idx(k), out_idx(k);
    for (size_t i = 0; i < ex.size(); ++i) ex_idx[ex.cls(i)].push_back(i);
    for (size_t i = 0; i < out.size(); ++i) out_idx[out.cls(i)].push_back(i);
    std::vector<CurvePlot> plots{pcf_plot(title + " (all classes)", ex, out, opt)};
    for (int c = 0; c < shown_classes; ++c)
      plots.push_back(pcf_plot("class " + std::to_string(ex.class_label(c)), ex.subset(ex_idx[c]), out.subset(out_idx[c]), opt));
    if (shown_classes < k) {
      plots[0].title += " (" + std::to_string(shown_classes) + " of " + std::to_string(k) + " classes shown)";
      spdlog::warn("plot-pcf: {} classes do not fit one image; the first {} are drawn", k, shown_classes);
    }
    plot_curve_grid(a.image, plots, columns, 420, 300);
  }
  spdlog::info("wrote {}", a.image);
  return 0;
}

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<PlotPcfArgs>();
  app.add_option("--exemplar", a->exemplar, "exemplar point file")->required()->check(ppsynth::app::path_text());
  app.add_option("--output", a->output, "synthesized point file")->required()->check(ppsynth::app::path_text());
  app.add_option("-o", a->image, "output image: .png, .svg or .pdf")->required()->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace an existing image");
  app.add_option("--format", a->format, "input format of both files (default: detect)");
  app.add_option("--title", a->title, "plot title");
  app.add_option("--bins", a->bins, "number of radii (default 100)");
  app.add_option("--r-max-factor", a->r_max_factor, "last radius in r_max units (default 2.5)");
  app.add_option("--sigma-factor", a->sigma_factor, "kernel width in r_max units (default 0.25)");
  app.add_flag("--periodic", a->periodic, "torus domain (no edge correction)");
  return [a]() { return run(*a); };
}

}  // namespace

PPSYNTH_COMMAND("plot-pcf", "plot the PCFs of an exemplar and an output", setup)
