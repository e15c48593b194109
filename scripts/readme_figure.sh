#!/usr/bin/env bash
# Makes the README's picture: the paper's `lines` exemplar (20 points) beside a synthesis of
# it (80 points), docs/images/readme_lines.png. Synthesizes configs/runs/lines.json (seed 95)
# with the `fast` preset, which stops each stage once its pattern stops improving, then plots
# the run's exemplar and output side by side. A few minutes on one core.
# Usage: scripts/readme_figure.sh [RUN_DIR] (default runs/readme_lines; an earlier run of this
# script there is replaced, anything else refused). PPSYNTH_BIN overrides the binary.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
run="${1:-$here/runs/readme_lines}"
bin="${PPSYNTH_BIN:-$here/build/ppsynth}"
[ -x "$bin" ] || { echo "readme_figure.sh: $bin not built (run scripts/setup.sh)" >&2; exit 1; }
force=()
[ -e "$run/.ppsynth-run" ] && force=(--force)
"$bin" synthesize "$here/configs/runs/lines.json" --preset fast -o "$run" "${force[@]}"
"$bin" plot "$run/exemplar.txt" --title exemplar --compare "$run/output.txt" --size 320 \
  -o "$here/docs/images/readme_lines.png" --force
echo "wrote $here/docs/images/readme_lines.png from $run"
