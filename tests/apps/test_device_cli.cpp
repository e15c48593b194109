// `--device` on the commands, end to end: run.json's record, the refusals (the key named, exit
// 2, no run directory left), and the whole synthesis through the tensor-operation maps (the
// path a CUDA run takes) agreeing with the CPU kernel's on the CPU. Tagged [device]:
// scripts/gpu_check.sh runs these on the GPU machine too.
#include <catch2/catch.hpp>

#include <torch/cuda.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "core/processor.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using Catch::Contains;
using ppsynth::test::run_ppsynth;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

nlohmann::json runtime_of(const fs::path& run) {
  return nlohmann::json::parse(ppsynth::read_file_text((run / "run.json").string())).at("method_stats").at("runtime");
}

}  // namespace

TEST_CASE("synthesize --device cpu records the device and precision in run.json", "[apps][device]") {
  const auto d = ppsynth::test::scratch_dir("cli_device_cpu");
  const auto r = run_ppsynth("synthesize " + kLines + " --quick -q --device cpu -o " + (d / "a").string());
  REQUIRE(r.status == 0);
  const auto rt = runtime_of(d / "a");
  CHECK(rt.at("device") == "cpu");
  CHECK(rt.at("precision") == "float32");
  CHECK(rt.at("deterministic") == true);
  const auto bf16 = run_ppsynth("synthesize " + kLines + " --quick -q --device cpu --set method.feature_net.precision=bfloat16 -o " +
                                (d / "b").string());
  if (ppsynth::cpu_isa().bf16_unavailable) {  // an AVX-512 CPU under the AVX2 cap: refused, nothing written
    CHECK(bf16.status == 2);
    CHECK_THAT(bf16.output, Contains("method.feature_net.precision"));
    CHECK_FALSE(fs::exists(d / "b"));
    return;
  }
  REQUIRE(bf16.status == 0);
  CHECK(runtime_of(d / "b").at("precision") == "bfloat16");
}

TEST_CASE("--device refuses a bad value, and cuda where there is none, naming the key and writing nothing", "[apps][device]") {
  const auto d = ppsynth::test::scratch_dir("cli_device_bad");
  const auto bad = run_ppsynth("synthesize " + kLines + " --quick -q --device gpu -o " + (d / "x").string());
  CHECK(bad.status == 2);
  CHECK_THAT(bad.output, Contains("runtime.device") && Contains("expected \"cpu\", \"cuda\", \"cuda:N\" or \"auto\""));
  CHECK_FALSE(fs::exists(d / "x"));
  const auto bench = run_ppsynth("bench " + kLines + " --reps 1 --skip-setup --device cuda:x");
  CHECK(bench.status == 2);
  CHECK_THAT(bench.output, Contains("runtime.device"));
  const auto resume = run_ppsynth("synthesize --resume " + (d / "x").string() + " --device cpu");
  CHECK(resume.status == 2);
  CHECK_THAT(resume.output, Contains("--resume takes the run directory alone"));
  if (torch::cuda::is_available()) {
    WARN("part skipped: this process sees a CUDA device, so --device cuda is not refused");
    return;
  }
  const auto cuda = run_ppsynth("synthesize " + kLines + " --quick -q --device cuda -o " + (d / "y").string());
  CHECK(cuda.status == 2);
  CHECK_THAT(cuda.output, Contains("runtime.device") && Contains("asks for a CUDA device"));
  CHECK_FALSE(fs::exists(d / "y"));
  CHECK(run_ppsynth("bench " + kLines + " --reps 1 --skip-setup --device cuda").status == 2);
}

TEST_CASE("A synthesis on the tensor-operation maps equals the CPU kernel's within float rounding", "[apps][device]") {
  const auto d = ppsynth::test::scratch_dir("cli_device_paths");
  const std::string args = "synthesize " + kLines + " --quick -q --device cpu --set evaluate=false -o ";
  REQUIRE(run_ppsynth(args + (d / "kernel").string(), "PPSYNTH_GABOR_MAPS=auto").status == 0);
  REQUIRE(run_ppsynth(args + (d / "ops").string(), "PPSYNTH_GABOR_MAPS=tensor_ops").status == 0);
  CHECK(runtime_of(d / "kernel").at("gabor_maps") == "cpu_kernel");
  CHECK(runtime_of(d / "ops").at("gabor_maps") == "tensor_ops");
  const auto a = ppsynth::read_points((d / "kernel" / "output.txt").string()).positions();
  const auto b = ppsynth::read_points((d / "ops" / "output.txt").string()).positions();
  REQUIRE(a.size() == b.size());
  std::vector<double> diff;
  for (size_t i = 0; i < a.size(); ++i) diff.insert(diff.end(), {std::abs(a[i].x - b[i].x), std::abs(a[i].y - b[i].y)});
  std::sort(diff.begin(), diff.end());
  // Rounding-sized differences of the two paths (equal maps and gradients to float rounding:
  // tests/models/test_gabor_maps_paths.cpp), amplified by 160 Adam steps by an amount that
  // depends on the processor and oneDNN's kernels, not on the maps (medians seen: 6e-8 on an
  // AVX2 EPYC; on AMX Xeons 4.5e-8 and 1.3e-5 natively, 3e-8 and 7.3e-5 with oneDNN capped to
  // AVX2, that last with a largest difference of 1.5e-3 of 160). A wrong map or gradient moves
  // them all by about the rate (0.005): the median's bound is a fifth of it, and the largest
  // difference, noise, is not checked.
  INFO("coordinate differences: median " << diff[diff.size() / 2] << ", largest " << diff.back());
  CHECK(diff[diff.size() / 2] < 1e-3);
  // A value the variable does not take stops the run before anything is kept.
  const auto bad = run_ppsynth(args + (d / "bad").string(), "PPSYNTH_GABOR_MAPS=cuda");
  CHECK(bad.status == 2);
  CHECK_THAT(bad.output, Contains("PPSYNTH_GABOR_MAPS='cuda'"));
  CHECK_FALSE(fs::exists(d / "bad"));
}
