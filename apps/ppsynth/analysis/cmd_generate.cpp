// `ppsynth generate TYPE -n N --seed S -o FILE [--set key=value ...] [--force]`: one point set
// from a registered generator (core/generators/generator.hpp; `ppsynth config --kind generator`
// lists the types and their parameters), written with write_points (format by extension); an
// existing FILE is replaced only with --force (apps/ppsynth/output_files.hpp).
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "apps/ppsynth/option_checks.hpp"
#include "apps/ppsynth/output_files.hpp"
#include "core/config/config.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/generators/generator.hpp"

namespace {

struct Args {
  std::string type, output, format = "auto";
  long long n = 256;
  uint64_t seed = 1;
  std::vector<std::string> sets;
  std::vector<double> domain;
  bool periodic = false, force = false;
};

ppsynth::app::RunFn setup(CLI::App& app) {
  auto a = std::make_shared<Args>();
  app.add_option("type", a->type, "generator type (uniform, poisson_disk, best_candidate, jittered_grid, ...)")
      ->required();
  app.add_option("-n,--count", a->n, "number of points")->required();
  app.add_option("--seed", a->seed, "random seed, 0 to 2^63 - 1")->check(ppsynth::app::seed_number());
  app.add_option("-o,--output", a->output, "output point file (.json or plain text)")
      ->required()
      ->check(ppsynth::app::path_text());
  app.add_flag("--force", a->force, "replace an existing output file");
  app.add_option("--set", a->sets, "generator parameter override key=value (repeatable)");
  app.add_option("--domain", a->domain, "domain x0 y0 x1 y1 (default: unit square)")->expected(4);
  app.add_flag("--periodic", a->periodic, "treat the domain as a torus (generators that can use it)");
  app.add_option("--format", a->format, "output format: auto, plain, json, gabor, point-synthesis");
  return [a]() {
    if (a->n < 0) throw ppsynth::InputError("-n must be >= 0");
    ppsynth::app::check_output_files({{"-o", a->output}}, {}, a->force);
    nlohmann::json spec = {{"type", a->type}};
    for (const auto& s : a->sets) ppsynth::set_override(spec, s);
    ppsynth::Domain d;
    if (!a->domain.empty()) d = {a->domain[0], a->domain[1], a->domain[2], a->domain[3]};
    if (!(d.width() > 0) || !(d.height() > 0)) throw ppsynth::InputError("--domain: need x1 > x0 and y1 > y0");
    d.periodic = a->periodic;
    ppsynth::PointSet ps = ppsynth::generate_points(spec, static_cast<size_t>(a->n), a->seed, d, "generator");
    ppsynth::write_points(a->output, ps, ppsynth::parse_format(a->format));
    std::cerr << "wrote " << ps.size() << " points (" << a->type << ", seed " << a->seed << ") to " << a->output
              << "\n";
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("generate", "write a point set from a classic point process (uniform, ccvt, ...)", setup)
