#!/bin/bash
# The runs of docs/lab/later_classes/README.md: amacrine at --size 1.601 1 (2.56 x 1 exemplar
# units, ~470 points), --preset fast, one thread each (two streams ran side by side on 2 cores).
#   docs/lab/later_classes/runs.sh DIR "TAG:SEED ..."   TAG: all | mc | own | half | allown | rev
#   all     the pattern rule judges the points in play pooled (the rule before this page)
#   mc      the rule judges the moving class's own PCF and its cross PCF (rows: moving_class)
#   own     mc + the class_own map term at weight 1
#   half    mc + the class_own map term at weight 0.5
#   allown  all + the class_own map term at weight 1
#   rev     own + method.revisit.iterations 100 (each class moves again after all are placed;
#           before 2026-11-30 it ran 0 iterations on this rectangle output: a bug, mended;
#           the default since the tenth session)
# (each tag sets all three keys, so the tags mean the same whatever the defaults are)
# Then per run: docs/lab/later_classes/stage_rows.py DIR/ama1x_TAG_sSEED EXEMPLAR 2.5635 1
set -euo pipefail
dir=${1:?usage: runs.sh DIR "TAG:SEED ..."}
jobs=${2:?usage: runs.sh DIR "TAG:SEED ..."}
bin=${PPSYNTH_BIN:-build/ppsynth}
ex=${EXEMPLAR:-$dir/exemplars/amacrine.txt}   # Rscript scripts/spatstat_export.R $dir/exemplars amacrine
mkdir -p "$dir"
for job in $jobs; do
  tag=${job%%:*}; s=${job##*:}
  d=$dir/ama1x_${tag}_s$s
  [[ -f $d/output.txt ]] && continue
  case $tag in
    all) extra=(--set method.convergence.rows=all --set method.map_terms.class_own.weight=0 --set method.revisit.iterations=0);;
    mc) extra=(--set method.convergence.rows=moving_class --set method.map_terms.class_own.weight=0 --set method.revisit.iterations=0);;
    own) extra=(--set method.convergence.rows=moving_class --set method.map_terms.class_own.weight=1 --set method.revisit.iterations=0);;
    half) extra=(--set method.convergence.rows=moving_class --set method.map_terms.class_own.weight=0.5 --set method.revisit.iterations=0);;
    allown) extra=(--set method.convergence.rows=all --set method.map_terms.class_own.weight=1 --set method.revisit.iterations=0);;
    rev) extra=(--set method.convergence.rows=moving_class --set method.map_terms.class_own.weight=1 --set method.revisit.iterations=100);;
    *) echo "runs.sh: unknown tag $tag" >&2; exit 2;;
  esac
  PPSYNTH_THREADS=1 "$bin" synthesize -q -e "$ex" --preset fast --seed "$s" -o "$d" --size 1.601 1 --set evaluate=false "${extra[@]}" > "$d.log" 2>&1
done
