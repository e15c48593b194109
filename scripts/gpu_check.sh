#!/usr/bin/env bash
# The device check (docs/lab/performance/README.md, "The device check"). On a machine with a CUDA GPU, a torch
# wheel, CMake and ninja, and no network (the device tool's: 16 cores, H100 or H200), it
#   1. builds ppsynth against the wheel's LibTorch, with the header-only dependencies carried
#      in .deps (scripts/carry_deps.sh) and without cairo (no figures);
#   2. runs the device tests (ppsynth_tests "[device]": the tensor-operation Gabor maps against
#      the CPU kernel, on the CPU and on CUDA; --device and run.json; a CUDA synthesis twice);
#   3. checks that the same config and seed give the same bits twice on the device;
#   4. benches `lines` on the device (ppsynth bench: per phase, per iteration) in float32, TF32,
#      float32 with cuDNN autotuning (runtime.deterministic=false) and a bfloat16 network;
#   5. runs `lines` at its default settings: seed 95 alone (the whole run's time), then seeds
#      96-99 side by side while the time budget lasts (quality over seeds);
#   6. prints a summary against the targets: <= 25 ms per iteration, <= 30 s per run, PCF MSE,
#      Wasserstein and Chamfer within 1.1 x the CPU default's medians over seeds 95-99.
# It fits in 8 minutes there: GPU_CHECK_SECONDS (default 460) bounds the whole script, so
# the runs of step 5 take what the build and steps 2-4 leave (a run that would not end in
# time is not started, one still running then is stopped; the summary says which ended). On a machine
# without CUDA, GPU_CHECK_DEVICE=cpu runs every step on the CPU at --quick sizes (a dry run of
# the script, its build and its tests; docs/lab/performance/README.md says how it was run).
#
# Usage: scripts/gpu_check.sh [OUT_DIR]   (OUT_DIR: $OUT if set, else gpu_check/)
#   GPU_CHECK_DEVICE   cuda (default) or cpu
#   GPU_CHECK_SECONDS  the time budget of the whole script (default 460)
#   GPU_CHECK_BUILD    the build folder (default build-gpu)
# Into OUT_DIR (six files; the device tool returns at most eight): summary.txt, configure.log,
# build.log, device_tests.log, benches.json (the three benches' --json), runs.json.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-${OUT:-$here/gpu_check}}"
device="${GPU_CHECK_DEVICE:-cuda}"
budget="${GPU_CHECK_SECONDS:-460}"
build="${GPU_CHECK_BUILD:-$here/build-gpu}"
work="$build/gpu_check_runs"  # run directories (many files): the summary copies what matters
mkdir -p "$out"
summary="$out/summary.txt"
: > "$summary"
t0=$(date +%s)
say() { echo "[gpu_check $(( $(date +%s) - t0 )) s] $*" | tee -a "$summary"; }
fail() { say "FAILED: $*"; exit 1; }

case "$device" in
  cuda) quick=""; reps=10 ;;
  cpu) quick="--quick"; reps=1 ;;  # the dry run: every step, at sizes a CPU gets through
  *) echo "gpu_check: GPU_CHECK_DEVICE='$device': expected cuda or cpu" >&2; exit 2 ;;
esac

# --- 0. the machine, 1. build (scripts/gpu_build.sh) ------------------------------------------
# shellcheck source=scripts/gpu_build.sh
. "$here/scripts/gpu_build.sh"
py="$(gpu_python)" || fail "no python3 with torch"
# (set -o pipefail: a pipeline fails when its first command does)
gpu_describe "$device" 2>&1 | while read -r line; do say "$line"; done || fail "the machine"
gpu_build "$out" "$build" 2>&1 | while read -r line; do say "$line"; done || fail "build"
left() {  # seconds of the budget left, at least 1
  local l=$(( budget - ($(date +%s) - t0) ))
  echo $(( l > 1 ? l : 1 ))
}

# --- 2. device tests ---------------------------------------------------------------------
"$build/ppsynth_tests" "[device]" > "$out/device_tests.log" 2>&1
tests_rc=$?
grep -E "^skipped|test cases|assertions" "$out/device_tests.log" | tee -a "$summary"
[ $tests_rc -eq 0 ] || say "device tests FAILED (device_tests.log)"

ppsynth() { "$build/ppsynth" "$@"; }
lines="$here/configs/runs/lines.json"
rm -rf "$work"
mkdir -p "$work"

# --- 3. same config, same seed: the same bits ------------------------------------------------
for r in a b; do
  ppsynth synthesize "$lines" --quick -q --device "$device" --set evaluate=false -o "$work/same_$r" > /dev/null ||
    fail "synthesize --quick on $device"
done
if cmp -s "$work/same_a/output.txt" "$work/same_b/output.txt"; then
  say "determinism: the same output twice (--quick, $device)"
else
  say "determinism FAILED: two --quick runs on $device differ"
fi

# --- 4. bench ------------------------------------------------------------------------------
bench_sizes=()
[ "$device" = cpu ] && bench_sizes=(--set method.grid.res=24 --set method.feature_net.channels=8)
# float32 (the default: IEEE float32, cuDNN's deterministic algorithms), TF32, float32 with
# cuDNN autotuning (runtime.deterministic=false: faster algorithms, bits may vary), and the
# network in bfloat16 (what "auto" picks on a CPU with bf16 units; measured here for the GPU).
for variant in float32 tf32 float32_autotune bfloat16; do
  settings=(--set runtime.tf32=false --set runtime.deterministic=true)
  [ "$variant" = tf32 ] && settings=(--set runtime.tf32=true --set runtime.deterministic=true)
  [ "$variant" = float32_autotune ] && settings=(--set runtime.tf32=false --set runtime.deterministic=false)
  [ "$variant" = bfloat16 ] && settings+=(--set method.feature_net.precision=bfloat16)
  ppsynth bench "$lines" --device "$device" --reps "$reps" --skip-setup "${settings[@]}" "${bench_sizes[@]}" \
    --json "$work/bench_$variant.json" > "$work/bench_$variant.txt" 2>&1 || { cat "$work/bench_$variant.txt"; fail "bench ($variant)"; }
  say "bench, $variant:"
  grep -E "^ppsynth bench|ONE|Gabor|network|loss|neighbor" "$work/bench_$variant.txt" | tee -a "$summary"
done

# --- 5. whole runs -------------------------------------------------------------------------
run_seed() {  # seed, timeout in seconds
  timeout "$2" "$build/ppsynth" synthesize "$lines" $quick -q --device "$device" --seed "$1" -o "$work/lines_s$1" \
    > "$work/lines_s$1.log" 2>&1
}
say "lines, seed 95, default settings on $device"
s95=$(date +%s)
run_seed 95 "$(left)" || say "seed 95 did not finish (rc $?; its log: $(tail -n 3 "$work/lines_s95.log"))"
took=$(( $(date +%s) - s95 ))
say "seed 95: $took s"
if [ "$(left)" -gt $(( took + 20 )) ]; then
  say "seeds 96-99 side by side (at most $(left) s)"
  stop_at=$(( $(left) > 20 ? $(left) - 10 : $(left) ))
  for seed in 96 97 98 99; do PPSYNTH_THREADS=4 run_seed "$seed" "$stop_at" & done
  wait
else
  say "seeds 96-99 skipped: $(left) s left of the budget"
fi

# --- 6. summary ----------------------------------------------------------------------------
"$py" - "$work" "$out" "$device" << 'EOF' | tee -a "$summary"
import json, os, statistics, sys
work, out, device = sys.argv[1:4]
# The CPU default's medians over seeds 95-99 (docs/lab/fast_preset.md, "Each knob on `lines`").
cpu = {"pcf_mse": 0.0266, "wasserstein": 0.108, "chamfer": 0.192}
runs = []
for seed in range(95, 100):
    d = os.path.join(work, f"lines_s{seed}")
    try:
        run = json.load(open(os.path.join(d, "run.json")))
        metrics = json.load(open(os.path.join(d, "metrics.json")))["all"]
    except (OSError, ValueError, KeyError):
        continue
    stats = run["method_stats"]
    iterations = sum(s["iterations"] for s in stats["stages"])
    runs.append({"seed": seed, "seconds": run["synthesis_seconds"], "total_seconds": run["total_seconds"],
                 "iterations": iterations, "ms_per_iteration": 1e3 * run["synthesis_seconds"] / max(1, iterations),
                 "runtime": stats.get("runtime"), **{k: metrics[k] for k in cpu}})
json.dump(runs, open(os.path.join(out, "runs.json"), "w"), indent=2)
for r in runs:
    print(f"seed {r['seed']}: {r['seconds']:.1f} s synthesis ({r['total_seconds']:.1f} s with evaluation), "
          f"{r['iterations']} iterations, {r['ms_per_iteration']:.1f} ms/iteration; PCF MSE {r['pcf_mse']:.4f}, "
          f"Wasserstein {r['wasserstein']:.3f}, Chamfer {r['chamfer']:.3f}; {r['runtime']}")
benches = {}
for variant in ("float32", "tf32", "float32_autotune", "bfloat16"):
    try:
        b = benches[variant] = json.load(open(os.path.join(work, f"bench_{variant}.json")))
        print(f"bench {variant} on {b['device']}: iteration {1e3 * b['iteration_median_s']:.1f} ms (forward + backward), "
              f"run iteration {1e3 * b['run_iteration_median_s']:.1f} ms (+ step + checkpoint) [target <= 25 ms]")
    except (OSError, ValueError, KeyError):
        print(f"bench {variant}: no result")
json.dump(benches, open(os.path.join(out, "benches.json"), "w"), indent=2)
if runs:
    first = runs[0]
    print(f"whole run (seed {first['seed']}): {first['seconds']:.1f} s [target <= 30 s]")
    for k, ref in cpu.items():
        m = statistics.median(r[k] for r in runs)
        print(f"{k}: median {m:.4f} over {len(runs)} seed(s) = {m / ref:.2f} x the CPU default's {ref} [target <= 1.1 x]")
else:
    print("no finished run")
if device == "cpu":
    print("(dry run on the CPU at --quick sizes: the numbers say nothing of a GPU)")
EOF
say "done; files in $out"
[ $tests_rc -eq 0 ] || exit 1
