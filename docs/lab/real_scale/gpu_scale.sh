#!/usr/bin/env bash
# Issue 61's numbers on a GPU machine of the device tool (docs/lab/real_scale/README.md, "On a
# GPU"), in the order that only a GPU can give them:
#   1. amacrine (spatstat's, carried in .deps/real_data/amacrine.txt) at --preset fast, seed 95
#      alone on the card: the whole run's time;
#   2. scripts/bench_scaling.sh on the card: lines and poisson_n64c2_point at --preset fast, 4 to
#      1024 copies, square outputs, then 2:1 ones while the budget lasts (a run cut short is
#      redone by the next call: finished runs are read, not rerun);
#   3. amacrine seeds 96-99 side by side, while the budget lasts (a seed that does not end is
#      dropped: its checkpoint stays on the machine for a next call on it while warm).
# Here, beforehand: scripts/carry_deps.sh (.deps: headers, the two exemplars, amacrine.txt).
# There, through the device tool, carry [".deps"]:  docs/lab/real_scale/gpu_scale.sh
# Into $OUT: summary.txt, configure.log, build.log and results.tgz (every ended run's run.json,
# config.json, loss.csv, output.txt and log; scaling.tsv). Back here:
#   mkdir -p DIR && tar xzf FILES_AT/results.tgz -C DIR
#   PPSYNTH_BIN=build/ppsynth scripts/bench_scaling.sh DIR/scale --presets fast --shapes "square wide"   # the table
#   GPU_SECONDS  the whole script's budget, the build included (default 560)
#   GPU_BUILD    the build folder (default build-gpu: a warm machine's build is reused)
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
out="${OUT:-$here/gpu_scale}"
budget="${GPU_SECONDS:-560}"
build="${GPU_BUILD:-$here/build-gpu}"
# Under the build folder, which a warm machine keeps between calls (not under .deps: a call's
# carry replaces .deps there, and a second call then redid every run of the first).
work="$build/gpu_scale"
mkdir -p "$out" "$work/amacrine" "$work/scale"
summary="$out/summary.txt"
: > "$summary"
t0=$(date +%s)
say() { echo "[gpu_scale $(( $(date +%s) - t0 )) s] $*" | tee -a "$summary"; }
left() { echo $(( budget - ($(date +%s) - t0) )); }
run_seconds() {  # RUN_DIR: "<synthesis s> s synthesis, <stages> stages, peak <MiB> MiB host"
  "$py" -c 'import json,sys; r=json.load(open(sys.argv[1])); m=r["method_stats"]
print("%.1f s synthesis, %d stages, grid %dx%d, peak %.0f MiB host" % (r["synthesis_seconds"], len(m.get("stages", [])), m["output_grid_res"], m["output_grid_rows"], r["peak_rss_mib"]))' "$1/run.json"
}

# shellcheck source=scripts/gpu_build.sh
. "$here/scripts/gpu_build.sh"
py="$(gpu_python)" || { say "FAILED: no python3 with torch"; exit 1; }
gpu_describe cuda 2>&1 | while read -r line; do say "$line"; done || { say "FAILED: the machine"; exit 1; }
gpu_build "$out" "$build" ppsynth 2>&1 | while read -r line; do say "$line"; done || { say "FAILED: build"; exit 1; }
bin="$build/ppsynth"
PPSYNTH_THREADS=$(nproc)
export PPSYNTH_THREADS

# 1. amacrine, seed 95 alone on the card.
ama="$work/amacrine/amacrine_gabor_s95"
if [ ! -f "$ama/run.json" ]; then
  limit=$(( $(left) - 150 < 300 ? $(left) - 150 : 300 ))
  [ "$limit" -gt 30 ] || { say "FAILED: $(left) s left after the build"; exit 1; }
  say "amacrine --preset fast, seed 95 alone on the card (at most $limit s)"
  rm -rf "$ama"
  timeout -s TERM -k 10 "$limit" "$bin" synthesize -e "$here/.deps/real_data/amacrine.txt" -m gabor --seed 95 \
    -o "$ama" --device cuda --preset fast --set evaluate=false -q > "$ama.log" 2>&1
fi
if [ -f "$ama/run.json" ]; then say "amacrine seed 95: $(run_seconds "$ama")"; else say "amacrine seed 95: did not end: $(tail -n 2 "$ama.log")"; fi

# 2. the scaling curve on the card, square then 2:1.
for shape in square wide; do
  l=$(left)
  [ "$l" -gt 60 ] || { say "scaling $shape: not run ($l s left)"; continue; }
  say "scaling curve, $shape outputs (at most $(( l - 40 )) s)"
  PPSYNTH_BIN="$bin" PPSYNTH_PYTHON="$py" timeout -s TERM -k 10 $(( l - 40 )) "$here/scripts/bench_scaling.sh" "$work/scale" \
    --presets fast --shapes "$shape" --copies "4 16 64 256 1024" -- --device cuda > "$work/scale/$shape.out" 2>&1
  say "scaling $shape: exit $?; $(find "$work/scale/runs" -name run.json | wc -l) runs ended so far"
done

# 3. amacrine seeds 96-99 side by side, while the budget lasts.
l=$(( $(left) - 25 ))
if [ "$l" -gt 90 ]; then
  say "amacrine seeds 96-99 side by side (at most $l s)"
  for s in 96 97 98 99; do
    run="$work/amacrine/amacrine_gabor_s$s"
    [ -f "$run/run.json" ] && continue
    if [ -f "$run/checkpoint.bin" ]; then cmd=(synthesize --resume "$run"); else
      cmd=(synthesize -e "$here/.deps/real_data/amacrine.txt" -m gabor --seed "$s" -o "$run" --device cuda --preset fast --set evaluate=false -q); fi
    PPSYNTH_THREADS=4 timeout -s TERM -k 10 "$l" "$bin" "${cmd[@]}" >> "$run.log" 2>&1 &
  done
  wait
  for s in 96 97 98 99; do
    run="$work/amacrine/amacrine_gabor_s$s"
    if [ -f "$run/run.json" ]; then say "amacrine seed $s: $(run_seconds "$run")"; else say "amacrine seed $s: did not end"; fi
  done
else
  say "amacrine seeds 96-99: not run ($l s left)"
fi

# Pack what ended (no checkpoints: they stay on the machine).
(cd "$work" && find amacrine scale \( -name run.json -o -name config.json -o -name loss.csv -o -name output.txt \
  -o -name '*.log' -o -name '*.out' -o -name scaling.tsv \) -print0 | tar czf "$out/results.tgz" --null -T -)
say "packed $(tar tzf "$out/results.tgz" | grep -c '/run.json$') ended run(s) into results.tgz ($(du -h "$out/results.tgz" | cut -f1))"
cat "$work/scale/wide.out" "$work/scale/square.out" 2> /dev/null | grep -A 30 "^finest s" | head -n 30
