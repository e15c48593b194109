#!/usr/bin/env bash
# Renders the five mixture models of the PPTBF supplement's Fig. 2 (configs/pptbf/fig2_*)
# into OUT_DIR: one PNG per model for both rows of the figure (winfeatcorrel 0 and 1), and
# the two rows as grids. Usage: scripts/pptbf_fig2.sh [OUT_DIR] [PPSYNTH_BINARY] [RES]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-fig2_pptbf}"
bin="${2:-$root/build/ppsynth}"
res="${3:-512}"
mkdir -p "$out"
configs=("$root"/configs/pptbf/fig2_mixture*.json)
for c in "${configs[@]}"; do
  name="$(basename "$c" .json)"
  "$bin" pptbf "$c" --res "$res" -o "$out/${name}_correl0.png" --force
  "$bin" pptbf "$c" --res "$res" --set winfeatcorrel=1 -o "$out/${name}_correl1.png" --force
done
"$bin" pptbf "${configs[@]}" --grid --res 256 -o "$out/fig2_row1_correl0.png" --force
"$bin" pptbf "${configs[@]}" --grid --res 256 --set winfeatcorrel=1 -o "$out/fig2_row2_correl1.png" --force
echo "wrote $out"
