// `ppsynth spectrum FILE -o OUT.png|svg|pdf [--frequencies F] [--step S] [--json OUT.json]
// [--force]`: the 2-D power spectrum (periodogram) of a point file as a log-scale heat map
// (core/metrics/periodogram.hpp, core/render/plot_spectrum.hpp): seams and repetition show as
// isolated peaks off the radial ring. Prints the peak ratio (strongest frequency over the
// median of its ring) and writes it, with where it is, to --json.
// Outputs are written atomically; an existing file is replaced only with --force, the input
// never (apps/ppsynth/output_files.hpp; a device or FIFO, e.g. /dev/stdout, is written through).
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/atomic_file.hpp"
#include "core/config/json_text.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/log.hpp"
#include "core/metrics/periodogram.hpp"
#include "core/render/image_file.hpp"
#include "core/render/plot_spectrum.hpp"

namespace {

using namespace ppsynth;

struct SpectrumArgs {
  std::string input, image, json_file, format, title;
  int frequencies = 128;
  double step = 0;
  int size_px = 560;
  bool force = false;
};

int run(const SpectrumArgs& a) {
  if (a.size_px < 64 || a.size_px > 4096) throw InputError("--size must be in 64..4096 px");
  render::image_kind_for(a.image);  // a bad extension fails before the work
  app::check_output_files({{"-o", a.image}, {"--json", a.json_file}}, {{"file", a.input}}, a.force);
  ReadOptions ro;
  if (!a.format.empty()) ro.format = parse_format(a.format);
  const PointSet ps = read_points(a.input, ro);
  PeriodogramOptions po;
  po.frequencies = a.frequencies;
  po.step = a.step;
  const Periodogram p = periodogram(ps, po);
  const SpectrumPeak peak = spectrum_peak(p);
  const std::string title =
      a.title.empty() ? shown_text(std::filesystem::path(a.input).stem().string()).get<std::string>() + " (N = " + std::to_string(ps.size()) + ")"
                      : a.title;
  plot_spectrum(a.image, p, title, a.size_px);
  const Domain& d = ps.domain();
  const nlohmann::json j = {{"input", shown_text(a.input)},  // any file name can be written as JSON
                            {"points", ps.size()},
                            {"domain", {d.x0, d.y0, d.x1, d.y1}},
                            {"frequencies", p.F},
                            {"step", p.step},
                            {"max_frequency", p.F * p.step},
                            {"unit", "cycles per coordinate unit"},
                            {"peak_ratio", peak.ratio},
                            {"peak", {{"fx", peak.fx}, {"fy", peak.fy}, {"power", peak.power}, {"ring", peak.ring},
                                      {"ring_median", peak.ring_median}}},
                            {"image", shown_text(a.image)}};
  if (!a.json_file.empty()) write_text_atomic(a.json_file, j.dump(2) + "\n");
  std::cout << "peak ratio " << peak.ratio << " at f = (" << peak.fx << ", " << peak.fy << ") cycles per unit (power "
            << peak.power << ", ring median " << peak.ring_median << "); grid step " << p.step << ", up to "
            << p.F * p.step << " cycles per unit\n";
  spdlog::info("wrote {}", a.image);
  return 0;
}

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<SpectrumArgs>();
  app.add_option("file", a->input, "point file")->required()->check(ppsynth::app::path_text());
  app.add_option("-o,--output", a->image, "heat map image: .png, .svg or .pdf")->required()->check(ppsynth::app::path_text());
  app.add_option("--frequencies", a->frequencies, "grid half size F: (2F+1)^2 frequencies, 1..1024 (cost O(N F^2))")
      ->capture_default_str();
  app.add_option("--step", a->step,
                 "frequency step in cycles per coordinate unit (default 0 = 1 / the domain's longer side)");
  app.add_option("--json", a->json_file, "also write the peak ratio and the grid as JSON (atomically)")
      ->check(ppsynth::app::path_text());
  app.add_option("--format", a->format, "input format (default: detect from the file)");
  app.add_option("--title", a->title, "plot title (default: file name and point count)");
  app.add_option("--size", a->size_px, "heat map side in px, 64..4096")->capture_default_str();
  app.add_flag("--force", a->force, "replace existing output files");
  return [a]() { return run(*a); };
}

}  // namespace

PPSYNTH_COMMAND("spectrum", "2-D power spectrum of a point file as a heat map (seams, repetition) with its peak ratio",
                setup)
