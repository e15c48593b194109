#!/usr/bin/env bash
# Reproduces every figure, table and ablation of the paper (configs/paper/*.json) at full
# settings, one report per config in OUT_DIR/NAME/index.html, and prints the wall time of each
# and the total. Full settings take hours on a CPU; pass --quick for a smoke run (~minutes).
# Usage: scripts/reproduce_all.sh [OUT_DIR] [PPSYNTH_BINARY] [--quick] [--set key=value ...]
# Stops at the first failing config (its previous report is kept; see docs/howto/reproduce_a_figure.md).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-reports}"
bin="${2:-$root/build/ppsynth}"
shift $(( $# >= 2 ? 2 : $# ))
extra=("$@")
if [[ ! -x "$bin" ]]; then
  echo "reproduce_all: no ppsynth binary at $bin (build it, or pass its path as the 2nd argument)" >&2
  exit 2
fi
mkdir -p "$out"
start=$(date +%s)
summary=()
for cfg in "$root"/configs/paper/*.json; do
  name="$(basename "$cfg" .json)"
  t0=$(date +%s)
  echo "=== $name"
  "$bin" reproduce "$cfg" -o "$out/$name" "${extra[@]}"
  t1=$(date +%s)
  summary+=("$(printf '%-26s %6d s' "$name" $((t1 - t0)))")
done
end=$(date +%s)
echo
echo "wall time per config:"
printf '  %s\n' "${summary[@]}"
total=$((end - start))
printf 'TOTAL wall time: %d s (%d min %d s) for %d configs; reports in %s\n' \
  "$total" $((total / 60)) $((total % 60)) "${#summary[@]}" "$out"
