// The machine report's JSON with what a processor gives: one floor where no bf16 convolution
// runs (an AVX-512 CPU under the AVX2 cap), both elsewhere, none with --grid 0.
#include <catch2/catch.hpp>

#include "optim/run/machine_report.hpp"

using ppsynth::ConvThroughput;
using ppsynth::MachineReport;

TEST_CASE("the machine report's JSON takes one floor, two or none", "[doctor][machine-report]") {
  MachineReport m;
  m.floor_res = 16;
  m.floors = {ConvThroughput{"float32", 40.0, 0.01}};
  // Was floors[1] read past the end: garbage for bf16_over_float32.
  nlohmann::json j = m.to_json();
  CHECK(j["conv_gflops"] == nlohmann::json{{"float32", 40.0}});
  CHECK_FALSE(j.contains("bf16_over_float32"));
  CHECK(m.text().find("bf16 / float32") == std::string::npos);

  m.floors.push_back(ConvThroughput{"bfloat16 channels-last", 80.0, 0.005});
  j = m.to_json();
  CHECK(j["bf16_over_float32"].get<double>() == 2.0);

  m.floors.clear();
  j = m.to_json();
  CHECK_FALSE(j.contains("conv_gflops"));
  CHECK_FALSE(j.contains("bf16_over_float32"));
}
