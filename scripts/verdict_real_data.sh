#!/usr/bin/env bash
# The real-data table of docs/verdict.md: spatstat.data's patterns as exemplars
# (scripts/spatstat_export.R), each judged against
#   fitted      realizations of a model spatstat fits to it (scripts/spatstat_fitted.R)
#   METHOD      ppsynth's outputs of each method given (gabor, tiled_copy, roveri2015, pcf2017)
# by `ppsynth eval` (its verdict, the L-function's distance and the PCF MSE the project
# reports), one row per data set, kind and seed in DIR/results.tsv:
#   data set, kind, seed, pcf_mse (all), then per row ("all", "class k", "pair i-j") the
#   verdict's p ("ROW=p") and sup |L_out - L_ex| in mean spacings ("L:ROW=value").
#
#   scripts/verdict_real_data.sh DIR "DATA SETS" "METHODS" "SEEDS" [GABOR FLAGS...]
# GABOR FLAGS go to the gabor method's syntheses (the baselines run with their defaults).
#   e.g. scripts/verdict_real_data.sh /tmp/real "cells redwood" "gabor tiled_copy" "95 96" \
#          --preset fast --set method.feature_net.precision=float32
# Runs one synthesis at a time with PPSYNTH_THREADS=1 under nice (the machine is shared);
# a run directory that already holds a finished run is evaluated again, not rerun. With
# VERDICT_SYNTHESIZE=no nothing is synthesized: runs made elsewhere (a GPU machine:
# scripts/gpu_real_data.sh) are evaluated, and a missing one is named and left out. The
# fitted model's draws are numbered by the seeds too. Each synthesis's wall time is in
# DIR/runs/<data set>_<method>_s<seed>/run.json. Prints the table of docs/verdict.md from
# results.tsv (every line there, earlier calls' included).
set -euo pipefail
cd "$(dirname "$0")/.."
usage='usage: scripts/verdict_real_data.sh DIR "DATA SETS" "METHODS" "SEEDS" [GABOR FLAGS...]'
dir=${1:?$usage}
sets=${2:?$usage}
methods=${3:?$usage}
seeds=${4:?$usage}
shift 4
bin=build/ppsynth
[[ -x $bin ]] || { echo "verdict_real_data: $bin not built (scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$dir/exemplars" "$dir/fitted" "$dir/runs"
# shellcheck disable=SC2086
Rscript scripts/spatstat_export.R "$dir/exemplars" $sets > /dev/null

row() {  # DATA SET KIND SEED EXEMPLAR OUTPUT [EVAL FLAGS...] -> a line of results.tsv
  local set=$1 kind=$2 seed=$3 ex=$4 out=$5
  shift 5
  "$bin" eval -q --exemplar "$ex" --output "$out" --json --no-curves "$@" | /usr/bin/python3 -c '
import json, sys
r = json.load(sys.stdin)
def name(row):
    return row["row"] if row["row"] == "all" else ("class %d" % row["class"] if row["row"] == "class" else "pair %d-%d" % (row["ci"], row["cj"]))
cells = sys.argv[1:4] + ["%.6g" % r["all"]["pcf_mse"]]
for row in r["verdict"]["rows"]:
    cells.append("%s=%s" % (name(row), "NA" if row["p"] is None else "%.4f" % row["p"]))
for row in r["second_order"]["rows"]:
    cells.append("L:%s=%.4f" % (name(row), row["l_sup_spacings"]))
print("\t".join(cells))
' "$set" "$kind" "$seed"
}

results="$dir/results.tsv"
touch "$results"
for set in $sets; do
  ex="$dir/exemplars/$set.txt"
  # The fitted model's draws (seeds as draw numbers), in exemplar units: eval with --zoom 1.
  for seed in $seeds; do
    if [[ ! -f $dir/fitted/${set}_d$(printf '%03d' "$seed").txt ]]; then
      Rscript scripts/spatstat_fitted.R "$ex" "$dir/fitted/$set" "$seed:$seed" 2 >> "$dir/fitted/$set.log" 2>&1
    fi
    row "$set" fitted "$seed" "$ex" "$dir/fitted/${set}_d$(printf '%03d' "$seed").txt" --zoom 1 >> "$results"
  done
  for method in $methods; do
    for seed in $seeds; do
      run="$dir/runs/${set}_${method}_s$seed"
      flags=()
      [[ $method == gabor ]] && flags=("$@")
      if [[ ! -f $run/run.json && ${VERDICT_SYNTHESIZE:-yes} == no ]]; then
        echo "verdict_real_data: $set $method seed $seed: no finished run in $run (VERDICT_SYNTHESIZE=no); left out" >&2
        continue
      elif [[ ! -f $run/run.json ]]; then
        PPSYNTH_THREADS=1 nice -n 10 "$bin" synthesize -q -e "$ex" -m "$method" --seed "$seed" -o "$run" --force "${flags[@]}" \
          > "$run.log" 2>&1 || { echo "verdict_real_data: $set $method seed $seed failed (see $run.log)" >&2; continue; }
      fi
      row "$set" "$method" "$seed" "$ex" "$run/output.txt" >> "$results"
    done
  done
done
echo "results: $results"
# Per data set and kind: the pass rate (p >= 0.05) of each row, the median of sup |L_out - L_ex|
# in mean spacings per row (smaller is closer), the median PCF MSE.
/usr/bin/python3 - "$results" <<'EOF'
import sys, collections, statistics
rows = collections.OrderedDict()
for line in open(sys.argv[1]):
    f = line.rstrip("\n").split("\t")
    s, kind, seed, pcf = f[:4]
    cells = dict(x.split("=") for x in f[4:])
    ps = {k: v for k, v in cells.items() if not k.startswith("L:")}
    ls = {k[2:]: float(v) for k, v in cells.items() if k.startswith("L:")}
    rows.setdefault((s, kind), collections.OrderedDict())[seed] = (seed, float(pcf), ps, ls)  # a rerun's line replaces
rows = collections.OrderedDict((k, sorted(v.values(), key=lambda r: int(r[0]))) for k, v in rows.items())  # seeds in order
print("| data set | output | seeds | pass rate at 5 % per row | median sup L distance per row (mean spacings) | median PCF MSE (all) |")
print("|---|---|---|---|---|---|")
for (s, kind), runs in rows.items():
    names = list(runs[0][2].keys())
    pr, ml = [], []
    for n in names:
        vals = [float(r[2][n]) for r in runs if r[2].get(n, "NA") != "NA"]
        pr.append("%s %d/%d" % (n, sum(v >= 0.05 for v in vals), len(vals)))
        lv = [r[3][n] for r in runs if n in r[3]]
        ml.append("%s %.3f" % (n, statistics.median(lv)) if lv else n + " -")
    print("| %s | %s | %s | %s | %s | %.4f |" % (s, kind, ",".join(r[0] for r in runs), ", ".join(pr), ", ".join(ml), statistics.median(r[1] for r in runs)))
EOF
