#!/usr/bin/env bash
# The real-data table's syntheses on a GPU machine of the device tool (docs/lab/verdict/README.md):
# a borrowed GPU runs several seeds side by side a call at a time, where a CPU takes a seed at a
# time (amacrine, two classes on one grid: 2 x 4 sigmas = 8 stages; how long: that page).
#
# Here, beforehand (Debian, R with spatstat; the exemplar is exported, never shipped):
#   scripts/carry_deps.sh                                        # .deps: the headers
#   Rscript scripts/spatstat_export.R .deps/real_data amacrine   # .deps/real_data/amacrine.txt
# There, through the device tool with carry [".deps"]:
#   docs/lab/verdict/gpu_real_data.sh amacrine "95 96 97 98 99" --preset fast --set method.feature_net.precision=float32
# it builds (scripts/gpu_build.sh; a warm machine's build is reused), runs the gabor method on
# every seed side by side into .deps/real_data/runs/SET_gabor_sSEED (the names
# docs/lab/verdict/verdict_real_data.sh reads), continues a run whose directory holds a checkpoint,
# stops what is still running when the budget is spent (SIGTERM: each run keeps its
# checkpoint) and packs every run directory, checkpoints included, into OUT/runs.tgz beside
# OUT/summary.txt. Back here:
#   tar xzf FILES_AT/runs.tgz -C .deps/real_data
# then either call it again (the runs that did not end continue from their checkpoints: the
# carried .deps is what the device machine sees) or, once all have ended, evaluate them:
#   mkdir -p DIR && cp -r .deps/real_data/runs DIR/
#   VERDICT_SYNTHESIZE=no docs/lab/verdict/verdict_real_data.sh DIR amacrine gabor "95 96 97 98 99"
#
# Usage: docs/lab/verdict/gpu_real_data.sh SET "SEEDS" [SYNTHESIZE FLAGS...]   (into $OUT, else gpu_real_data/)
#   GPU_SECONDS  the whole script's budget, the build's included (default 540: the device
#                tool's 600 s a call, less the packing)
#   GPU_DEVICE   cuda (default) or cpu (a dry run of the script at --quick sizes)
#   GPU_BUILD    the build folder (default build-gpu); PPSYNTH_BIN: a built ppsynth instead
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"  # the checkout: this script is in docs/lab/verdict/
usage='usage: docs/lab/verdict/gpu_real_data.sh SET "SEEDS" [SYNTHESIZE FLAGS...]'
set_name=${1:?$usage}
seeds=${2:?$usage}
shift 2
out="${OUT:-$here/gpu_real_data}"
budget="${GPU_SECONDS:-540}"
device="${GPU_DEVICE:-cuda}"
build="${GPU_BUILD:-$here/build-gpu}"
data="$here/.deps/real_data"
exemplar="$data/$set_name.txt"
case "$device" in
  cuda) quick=() ;;
  cpu) quick=(--quick) ;;
  *) echo "gpu_real_data: GPU_DEVICE='$device': expected cuda or cpu" >&2; exit 2 ;;
esac
[ -f "$exemplar" ] || { echo "gpu_real_data: $exemplar: no such file (export it here: Rscript scripts/spatstat_export.R .deps/real_data $set_name)" >&2; exit 2; }
for s in $seeds; do
  [[ $s =~ ^[0-9]+$ ]] || { echo "gpu_real_data: seed '$s': expected a whole number" >&2; exit 2; }
done
mkdir -p "$out" "$data/runs"
summary="$out/summary.txt"
: > "$summary"
t0=$(date +%s)
say() { echo "[gpu_real_data $(( $(date +%s) - t0 )) s] $*" | tee -a "$summary"; }
left() { echo $(( budget - ($(date +%s) - t0) )); }

if [ -n "${PPSYNTH_BIN:-}" ]; then
  bin="$PPSYNTH_BIN"
  say "ppsynth: $bin (PPSYNTH_BIN; no build)"
else
  # shellcheck source=scripts/gpu_build.sh
  . "$here/scripts/gpu_build.sh"
  gpu_describe "$device" 2>&1 | while read -r line; do say "$line"; done || { say "FAILED: the machine"; exit 1; }
  gpu_build "$out" "$build" 2>&1 | while read -r line; do say "$line"; done || { say "FAILED: build"; exit 1; }
  bin="$build/ppsynth"
fi

# Each seed: ended (run.json) -> left as it is; a checkpoint -> continued; else started. The
# cores are shared out among the runs; the device is shared by all.
count=$(wc -w <<< "$seeds")
threads=$(( $(nproc) / count > 0 ? $(nproc) / count : 1 ))
stop_after=$(( $(left) - 15 ))
[ "$stop_after" -gt 30 ] || { say "FAILED: $(left) s left of the budget after the build: nothing run"; exit 1; }
say "$set_name, seeds $seeds on $device, side by side ($threads threads each), stopped after $stop_after s"
for s in $seeds; do
  run="$data/runs/${set_name}_gabor_s$s"
  if [ -f "$run/run.json" ]; then
    say "seed $s: ended before, left as it is"
    continue
  elif [ -f "$run/checkpoint.bin" ]; then
    cmd=(synthesize --resume "$run")
  else
    cmd=(synthesize -e "$exemplar" -m gabor --seed "$s" -o "$run" --device "$device" "${quick[@]}" "$@")
  fi
  # SIGTERM: the run saves its checkpoint and ends; 20 s later, still running, it is killed
  # (its last checkpoint, at most checkpoint_seconds old, stays).
  PPSYNTH_THREADS=$threads timeout -s TERM -k 20 "$stop_after" "$bin" "${cmd[@]}" >> "$run.log" 2>&1 &
done
wait

for s in $seeds; do
  run="$data/runs/${set_name}_gabor_s$s"
  if [ -f "$run/run.json" ]; then
    say "seed $s: ended, $(/usr/bin/env python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print("%.0f s of synthesis, %d stages" % (r["synthesis_seconds"], len(r["method_stats"].get("stages", []))))' "$run/run.json" 2> /dev/null)"
  elif [ -f "$run/checkpoint.bin" ]; then
    say "seed $s: stopped with its checkpoint ($(grep -o 'stage [0-9]*/[0-9]*' "$run.log" | tail -n 1)): call again to continue"
  else
    say "seed $s: FAILED: $(tail -n 2 "$run.log")"
  fi
done
tar czf "$out/runs.tgz" -C "$data" runs
# The device tool returns files of at most 16 MiB: say so before the call's files are lost.
size=$(stat -c %s "$out/runs.tgz")
[ "$size" -lt $((16 * 1024 * 1024)) ] || say "WARNING: runs.tgz is $size bytes, over the 16 MiB a returned file may have: fewer seeds a call"
say "packed $(tar tzf "$out/runs.tgz" | grep -c '/run.json$') ended and $(tar tzf "$out/runs.tgz" | grep -c '/checkpoint.bin$') checkpointed run(s) into $out/runs.tgz ($(du -h "$out/runs.tgz" | cut -f1))"
