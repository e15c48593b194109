// `ppsynth pptbf CONFIG.json -o image.png`: renders a Point Process Texture Basis Function
// (Guehl et al. 2020; core/procedural/pptbf.hpp) over the unit square as a gray PNG
// (min -> black, max -> white). --grid renders several configs into one titled grid.
// --points writes a point exemplar: --mode process (the PPTBF's own feature points) or
// --mode threshold (dart throwing where pptbf > threshold, threshold = --threshold or the
// --quantile of the image, minimum distance --min-dist or 0.5 sqrt(accepted area / n)).
// Existing files are replaced only with --force, a config never (apps/ppsynth/output_files.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/render/gray_png.hpp"
#include "core/procedural/pptbf.hpp"
#include "core/procedural/pptbf_points.hpp"
#include "core/render/image_grid.hpp"
#include "core/formats/point_io.hpp"

namespace {

using namespace ppsynth;

struct PptbfArgs {
  std::vector<std::string> configs, sets;
  std::string output, points, mode = "process";
  int res = 512, n = 1000, columns = 0;
  long long seed = 0;
  bool has_seed = false, grid = false, force = false;
  double threshold = NAN, quantile = 0.5, min_dist = -1;
  unsigned long long sample_seed = 1;
};

PptbfParams load_params(const std::string& path, const PptbfArgs& a) {
  json cfg = load_config(path);
  for (const auto& s : a.sets) set_override(cfg, s);
  if (a.has_seed) cfg["seed"] = a.seed;
  try {
    return pptbf_params_from_json(cfg);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

void write_point_file(const std::string& path, const PointSet& ps) {
  write_points(path, ps);
}

int run(const PptbfArgs& a) {
  if (a.res < 8 || a.res > 8192) throw InputError("--res must be in 8..8192");
  if (a.configs.size() > 1 && !a.grid) throw InputError("several configs need --grid");
  if (!a.points.empty() && a.grid) throw InputError("--points works with one config, not --grid");
  if (a.has_seed) app::refuse_set_conflicts(a.sets, {{"--seed " + std::to_string(a.seed), "seed"}});
  std::vector<app::NamedPath> inputs;
  for (const auto& c : a.configs) inputs.push_back({"config", c});
  app::check_output_files({{"-o", a.output}, {"--points", a.points}}, inputs, a.force);
  const auto t0 = std::chrono::steady_clock::now();
  if (a.grid) {
    std::vector<GrayImage> images;
    for (const auto& c : a.configs) {
      GrayImage img = render_pptbf(load_params(c, a), a.res, a.res);
      img.title = std::filesystem::path(c).stem().string();
      images.push_back(std::move(img));
    }
    const int cols = a.columns > 0 ? a.columns : std::min<int>(5, static_cast<int>(images.size()));
    plot_image_grid(a.output, images, cols, a.res, true);
  } else {
    const GrayImage img = render_pptbf(load_params(a.configs[0], a), a.res, a.res);
    write_gray_png(a.output, img);
    auto [mn, mx] = std::minmax_element(img.pixels.begin(), img.pixels.end());
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    spdlog::info("wrote {} ({}x{}, values {:.4g}..{:.4g}, {:.2f} s)", a.output, a.res, a.res, *mn, *mx, secs);
  }
  if (!a.points.empty()) {
    const PptbfParams p = load_params(a.configs[0], a);
    PointSet ps;
    if (a.mode == "process") {
      ps = pptbf_process_points(p);
    } else if (a.mode == "threshold") {
      if (a.n <= 0) throw InputError("-n must be positive");
      // accepted-area fraction from a 128^2 render decides the threshold / min distance
      GrayImage probe = render_pptbf(p, 128, 128);
      std::vector<float> v = probe.pixels;
      std::sort(v.begin(), v.end());
      ThresholdSampling s;
      s.n = a.n;
      s.seed = a.sample_seed;
      if (std::isfinite(a.threshold)) {
        s.threshold = a.threshold;
      } else {
        if (!(a.quantile >= 0 && a.quantile < 1)) throw InputError("--quantile must be in [0,1)");
        s.threshold = v[static_cast<size_t>(a.quantile * (v.size() - 1))];
      }
      const double frac = static_cast<double>(v.end() - std::upper_bound(v.begin(), v.end(), static_cast<float>(s.threshold))) / v.size();
      if (frac <= 0) throw InputError("no part of the PPTBF is above the threshold " + std::to_string(s.threshold));
      s.min_dist = a.min_dist >= 0 ? a.min_dist : 0.5 * std::sqrt(frac / a.n);
      ps = pptbf_threshold_points(p, s);
      spdlog::info("threshold {:.4g} (area above {:.2f}), min distance {:.4g}", s.threshold, frac, s.min_dist);
      if (static_cast<int>(ps.size()) < a.n)
        spdlog::warn("only {} of {} points fit (lower --min-dist or the threshold)", ps.size(), a.n);
    } else {
      throw InputError("--mode must be 'process' or 'threshold'");
    }
    write_point_file(a.points, ps);
    spdlog::info("wrote {} ({} points, mode {})", a.points, ps.size(), a.mode);
  }
  return 0;
}

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<PptbfArgs>();
  app.add_option("config", a->configs, "PPTBF config(s) (JSON, keys of PptbfParams)")
      ->required()
      ->expected(1, -1)
      ->check(ppsynth::app::path_text());
  app.add_option("-o,--output", a->output, "output PNG (with --grid: .png/.svg/.pdf grid)")
      ->required()
      ->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace existing output files");
  app.add_option("--res", a->res, "resolution in pixels (square)");
  auto* seed = app.add_option("--seed", a->seed, "override the config's seed");
  app.add_option("--set", a->sets, "override a config key, e.g. --set mixture=3")->expected(1, -1);
  app.add_flag("--grid", a->grid, "render every config into one grid image");
  app.add_option("--columns", a->columns, "grid columns (default min(5, count))");
  app.add_option("--points", a->points, "also write a point exemplar to this file")->check(ppsynth::app::path_text());
  app.add_option("--mode", a->mode, "point exemplar: process | threshold");
  app.add_option("-n", a->n, "threshold mode: number of points");
  app.add_option("--threshold", a->threshold, "threshold mode: accept where pptbf > this value");
  app.add_option("--quantile", a->quantile, "threshold mode: threshold = this quantile of the image (default 0.5)");
  app.add_option("--min-dist", a->min_dist, "threshold mode: minimum point distance (default 0.5 sqrt(area/n))");
  app.add_option("--sample-seed", a->sample_seed, "threshold mode: dart-throwing seed, 0 to 2^63 - 1")
      ->check(ppsynth::app::seed_number());
  return [a, seed]() {
    a->has_seed = seed->count() > 0;
    return run(*a);
  };
}

}  // namespace

PPSYNTH_COMMAND("pptbf", "render a PPTBF (Guehl et al. 2020) and sample point exemplars from it", setup)
