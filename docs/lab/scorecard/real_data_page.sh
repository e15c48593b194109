#!/usr/bin/env bash
# One page over the six real sets (docs/explanation/scorecard.md): per set, cards of spatstat's
# fitted model's draw, tiled_copy's output and ppsynth's outputs where they exist, each with the
# exemplar, the output, the L curves with fidelity's band and eval's scorecard and verdict
# (scripts/gallery.py --pair).
#
#   docs/lab/scorecard/real_data_page.sh PAGE EXEMPLARS FITTED WORK [RUNS...]
#   e.g. docs/lab/scorecard/real_data_page.sh /tmp/real.html /tmp/real/exemplars /tmp/fid/real/fitted /tmp/page \
#          /tmp/s5/real /tmp/l64/runs
#
# FITTED/SET_d001.txt: a draw of spatstat's fitted model (docs/lab/verdict/spatstat_fitted.R);
# WORK/tiled/SET: tiled_copy's run at seed 95 (made when missing); RUNS...: folders whose
# SET_s95/output.txt (or, for amacrine, ama1x_own_s95/output.txt) is a ppsynth run's output.
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
usage='usage: docs/lab/scorecard/real_data_page.sh PAGE EXEMPLARS FITTED WORK [RUNS...]'
page=${1:?$usage}
exemplars=${2:?$usage}
fitted=${3:?$usage}
work=${4:?$usage}
shift 4
bin=${PPSYNTH_BIN:-$root/build/ppsynth}
args=()
for set in cells redwood japanesepines swedishpines longleaf amacrine; do
  ex=$exemplars/$set.txt
  names=("${set}_s95")
  [[ $set == amacrine ]] && names+=(ama1x_own_s95)  # the lead's amacrine runs at 2.56 x 1
  for runs in "$@"; do
    for name in "${names[@]}"; do
      run=$runs/$name
      if [[ -f $run/output.txt ]]; then args+=(--pair "$set: ppsynth, seed 95 ($run)" "$ex" "$run/output.txt"); fi
    done
  done
  [[ -f $fitted/${set}_d001.txt ]] && args+=(--pair "$set: spatstat's fitted model, draw 1" "$ex" "$fitted/${set}_d001.txt")
  [[ -f $work/tiled/$set/output.txt ]] ||
    "$bin" synthesize -q -e "$ex" -m tiled_copy --seed 95 -o "$work/tiled/$set" --force > /dev/null
  args+=(--pair "$set: tiled_copy (the exemplar tiled), seed 95" "$ex" "$work/tiled/$set/output.txt")
done
PPSYNTH_BIN=$bin /usr/bin/python3 "$root/scripts/gallery.py" -o "$page" --force "${args[@]}"
