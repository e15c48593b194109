// `ppsynth analyze FILE -o OUTDIR`: thesis Chapter 4's analysis of a point pattern.
// Writes, atomically, into OUTDIR:
//   points.png       the pattern
//   intensity.png    kernel intensity map lambda(x) + the dictionary weight maps w_l
//                    (sampled at the query grid)
//   local_pcfs.png   local PCFs (Eq. 4.1) at the query grid positions, whole-pattern PCF dashed
//   dictionary.png   PCA mean and first components; basis PCFs (Eq. 4.2)
//   analysis.json    every number behind the plots
// An existing file of these names is replaced only with --force, the input never
// (apps/ppsynth/output_files.hpp); other files in OUTDIR are left alone.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/formats/point_io.hpp"
#include "core/render/image_grid.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_points.hpp"
#include "optim/baselines/pcf2017/local_intensity.hpp"
#include "optim/baselines/pcf2017/local_pcf.hpp"
#include "optim/baselines/pcf2017/pcf_dictionary.hpp"

namespace {

using namespace ppsynth;
using namespace ppsynth::pcf2017;

struct AnalyzeArgs {
  std::string input, outdir, format = "auto";
  int map_size = 64;            // intensity map resolution (pixels per side)
  int queries = 4;              // local PCFs on a queries x queries grid
  double sigma_rmax = 3.0;      // intensity kernel width, units of r_max
  double neighborhood = 0;     // expected points per local window (0 = auto)
  bool periodic = false, force = false;
};

// What analyze writes into OUTDIR.
const char* const kOutputFiles[] = {"points.png", "intensity.png", "local_pcfs.png", "dictionary.png", "analysis.json"};

GrayImage to_image(const std::vector<double>& v, int w, int h, const std::string& title) {
  GrayImage img;
  img.width = w;
  img.height = h;
  img.title = title;
  img.pixels.resize(size_t(w) * h);
  for (int j = 0; j < h; ++j)  // maps have row 0 at y0 (bottom); images at the top
    for (int i = 0; i < w; ++i) img.pixels[size_t(h - 1 - j) * w + i] = float(v[size_t(j) * w + i]);
  return img;
}

int run(const AnalyzeArgs& a) {
  if (a.map_size < 2 || a.map_size > 2048) throw InputError("--map-size must be in 2..2048");
  if (a.queries < 1 || a.queries > 16) throw InputError("--queries must be in 1..16");
  if (!(a.sigma_rmax > 0)) throw InputError("--sigma-rmax must be > 0");
  std::vector<app::NamedPath> outputs;
  for (const char* name : kOutputFiles) outputs.push_back({"-o", (std::filesystem::path(a.outdir) / name).string()});
  app::check_output_files(outputs, {{"file", a.input}}, a.force);
  ReadOptions ro;
  ro.format = parse_format(a.format);
  PointSet ps = read_points(a.input, ro);
  validate(ps, a.input);
  if (ps.size() < 4) throw InputError(a.input + ": analysis needs at least 4 points");
  if (a.periodic) {
    Domain d = ps.domain();
    d.periodic = true;
    ps.set_domain(d);
  }
  std::filesystem::create_directories(a.outdir);
  const std::string out = a.outdir + "/";
  const Domain& d = ps.domain();
  const double n = double(ps.size());

  IntensityOptions iopt;
  iopt.sigma_rmax = a.sigma_rmax;
  const std::vector<double> imap = intensity_map(ps, a.map_size, a.map_size, iopt);

  LocalPcfOptions lopt;
  lopt.intensity = iopt;
  lopt.neighborhood_points = a.neighborhood > 0 ? a.neighborhood : std::clamp(n / 4.0, 8.0, 60.0);
  std::vector<Vec2> queries;
  for (int j = 0; j < a.queries; ++j)
    for (int i = 0; i < a.queries; ++i)
      queries.push_back({d.x0 + (i + 0.5) * d.width() / a.queries, d.y0 + (j + 0.5) * d.height() / a.queries});
  const std::vector<PcfCurve> local = local_pcfs(ps, queries, lopt);
  const PcfCurve whole = pattern_pcf(ps, lopt.pcf, d.periodic);

  Matrix samples;
  for (const PcfCurve& c : local) samples.push_back(c.g);
  const PcfDictionary dict = build_dictionary(samples);

  // --- plots ---
  plot_points(out + "points.png", ps);
  std::vector<GrayImage> maps{to_image(imap, a.map_size, a.map_size, "intensity")};
  for (size_t l = 0; l < dict.basis.size(); ++l) {
    std::vector<double> w;
    for (const auto& row : dict.weights) w.push_back(row[l]);
    maps.push_back(to_image(w, a.queries, a.queries, "weight PCF " + std::to_string(l + 1)));
  }
  plot_image_grid(out + "intensity.png", maps, int(maps.size()), 200, true, ColorMap::Viridis);

  std::vector<CurvePlot> grid;
  for (size_t q = 0; q < local.size(); ++q) {
    CurvePlot p;
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.3g, %.3g)", queries[q].x, queries[q].y);
    p.title = buf;
    p.xlabel = "r / r_max";
    p.ylabel = "g";
    p.series.push_back({"local", local[q].rel, local[q].g, false});
    p.series.push_back({"whole", whole.rel, whole.g, true});
    grid.push_back(std::move(p));
  }
  plot_curve_grid(out + "local_pcfs.png", grid, a.queries);

  CurvePlot pca_plot;
  pca_plot.title = "PCF dictionary: PCA mean and components";
  pca_plot.xlabel = "r / r_max";
  pca_plot.series.push_back({"mean", whole.rel, dict.pca.mean, false});
  for (size_t c = 0; c < dict.pca.components.size() && c < 3; ++c)
    pca_plot.series.push_back({"component " + std::to_string(c + 1), whole.rel, dict.pca.components[c], false});
  CurvePlot basis_plot;
  basis_plot.title = "basis PCFs (Eq. 4.2)";
  basis_plot.xlabel = "r / r_max";
  basis_plot.ylabel = "g";
  for (size_t l = 0; l < dict.basis.size(); ++l)
    basis_plot.series.push_back({"PCF " + std::to_string(l + 1) + " (query " + std::to_string(dict.basis_index[l]) + ")",
                                 whole.rel, dict.basis[l], false});
  plot_curve_grid(out + "dictionary.png", {pca_plot, basis_plot}, 2, 480, 320);

  // --- numbers ---
  nlohmann::json j;
  j["input"] = a.input;
  j["points"] = ps.size();
  j["domain"] = {d.x0, d.y0, d.x1, d.y1};
  j["periodic"] = d.periodic;
  j["r_max"] = rmax_for(n, d.area());
  j["pcf_params"] = {{"bins", lopt.pcf.bins}, {"r_a", lopt.pcf.r_a}, {"r_b", lopt.pcf.r_b},
                     {"sigma_factor", lopt.pcf.sigma_factor}, {"units", "r / r_max"}};
  j["intensity"] = {{"sigma", intensity_sigma(ps, iopt)}, {"width", a.map_size}, {"height", a.map_size},
                    {"row0", "y0 (bottom)"}, {"values", imap}};
  j["relative_radii"] = whole.rel;
  j["whole_pcf"] = whole.g;
  j["neighborhood_points"] = lopt.neighborhood_points;
  nlohmann::json lj = nlohmann::json::array();
  for (size_t q = 0; q < local.size(); ++q)
    lj.push_back({{"position", {queries[q].x, queries[q].y}}, {"r_max", local[q].r_max}, {"g", local[q].g},
                  {"weights", dict.weights[q]}, {"residual", dict.residual[q]}});
  j["local"] = lj;
  j["pca"] = {{"mean", dict.pca.mean}, {"components", dict.pca.components}, {"variances", dict.pca.variances},
              {"total_variance", dict.pca.total_variance}};
  j["basis_index"] = dict.basis_index;
  j["basis"] = dict.basis;
  write_text_atomic(out + "analysis.json", j.dump(1) + "\n");
  spdlog::info("analyze: {} points, {} local PCFs, {} PCA components, {} basis PCFs -> {}", ps.size(),
               local.size(), dict.pca.components.size(), dict.basis.size(), a.outdir);
  return 0;
}

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<AnalyzeArgs>();
  app.add_option("file", a->input, "point pattern file")->required()->check(ppsynth::app::path_text());
  app.add_option("-o,--out", a->outdir, "output folder")->required()->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace the files of an earlier analysis in the folder");
  app.add_option("--format", a->format, "input format: auto (detect), gabor, point-synthesis, plain, json")
      ->capture_default_str();
  app.add_option("--map-size", a->map_size, "intensity map resolution (pixels per side)");
  app.add_option("--queries", a->queries, "local PCFs on a Q x Q grid of positions");
  app.add_option("--sigma-rmax", a->sigma_rmax, "intensity kernel width in units of r_max");
  app.add_option("--neighborhood", a->neighborhood, "expected points per local window (0 = N/4 in 8..60)");
  app.add_flag("--periodic", a->periodic, "treat the domain as a torus");
  return [a]() { return run(*a); };
}

}  // namespace

PPSYNTH_COMMAND("analyze", "thesis Ch. 4 analysis: intensity map, local PCFs, PCF dictionary", setup)
