#pragma once
// A `ppsynth` subcommand: one file in apps/ppsynth/analysis (torch-free) or
// apps/ppsynth/synthesis, ending with PPSYNTH_COMMAND(name, description, setup). `setup`
// declares the subcommand's options on its CLI11 App and returns the function to run
// (exit code). InputError thrown while running prints as "ppsynth NAME: message", exit 2.
#include <functional>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

namespace ppsynth::app {

using RunFn = std::function<int()>;
using SetupFn = std::function<RunFn(CLI::App&)>;

struct CommandEntry {
  std::string description;
  SetupFn setup;
};

std::map<std::string, CommandEntry>& commands();
bool register_command(const std::string& name, const std::string& description, SetupFn setup);


}  // namespace ppsynth::app

#define PPSYNTH_COMMAND(NAME, DESC, SETUP) \
  namespace {                              \
  [[maybe_unused]] const bool ppsynth_command_registered = ::ppsynth::app::register_command(NAME, DESC, SETUP); \
  }
