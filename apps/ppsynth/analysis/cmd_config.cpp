// `ppsynth config --defaults`: every default of every registered part, as JSON.
#include <iostream>

#include "apps/ppsynth/command.hpp"
#include "core/config/defaults_catalog.hpp"

namespace {

ppsynth::app::RunFn setup(CLI::App& app) {
  auto defaults = std::make_shared<bool>(false);
  auto kind = std::make_shared<std::string>();
  app.add_flag("--defaults", *defaults, "print every default value of every registered part");
  app.add_option("--kind", *kind, "only this kind (e.g. loss, rasterizer, method)");
  return [=]() {
    auto cat = ppsynth::defaults_catalog();
    if (!kind->empty()) {
      if (!cat.contains(*kind)) throw ppsynth::InputError("unknown kind '" + *kind + "'");
      cat = cat[*kind];
    }
    std::cout << cat.dump(2) << "\n";
    return 0;
  };
}

}  // namespace

PPSYNTH_COMMAND("config", "print the defaults of every configurable part", setup)
