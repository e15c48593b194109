#!/usr/bin/env bash
# The real-data table of docs/lab/verdict/README.md: spatstat.data's patterns as exemplars
# (scripts/spatstat_export.R), each judged against
#   fitted      realizations of a model spatstat fits to it (docs/lab/verdict/spatstat_fitted.R)
#   METHOD      ppsynth's outputs of each method given (gabor, tiled_copy, roveri2015, pcf2017)
# by `ppsynth eval` (its verdict, the L-function's distance and the PCF MSE the project
# reports), one row per data set, kind and seed in DIR/results.tsv:
#   data set, kind, seed, pcf_mse (all), then per row ("all", "class k", "pair i-j") the
#   verdict's p ("ROW=p") and sup |L_out - L_ex| in mean spacings ("L:ROW=value").
#
#   docs/lab/verdict/verdict_real_data.sh DIR "DATA SETS" "METHODS" "SEEDS" [GABOR FLAGS...]
# GABOR FLAGS go to the gabor method's syntheses (the baselines run with their defaults).
#   e.g. docs/lab/verdict/verdict_real_data.sh /tmp/real "cells redwood" "gabor tiled_copy" "95 96" \
#          --preset fast --set method.feature_net.precision=float32
# Runs one synthesis at a time with PPSYNTH_THREADS=1 under nice (the machine is shared);
# a run directory that already holds a finished run is evaluated again, not rerun. With
# VERDICT_SYNTHESIZE=no nothing is synthesized: runs made elsewhere (a GPU machine:
# docs/lab/verdict/gpu_real_data.sh) are evaluated, and a missing one is named and left out. The
# fitted model's draws are numbered by the seeds too. Each synthesis's wall time is in
# DIR/runs/<data set>_<method>_s<seed>/run.json. Prints the table of docs/lab/verdict/README.md from
# results.tsv (every line there, earlier calls' included).
set -euo pipefail
cd "$(dirname "$0")/../../.."  # the checkout: this script is in docs/lab/<topic>/
usage='usage: docs/lab/verdict/verdict_real_data.sh DIR "DATA SETS" "METHODS" "SEEDS" [GABOR FLAGS...]'
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
  # A row of the verdict is its p, FAIL (failed without a p: a class missing from the output
  # or extra in it) or NA (cannot judge); an output eval refuses is one line saying so, and
  # the batch goes on.
  local json
  if ! json=$("$bin" eval -q --exemplar "$ex" --output "$out" --json --no-curves "$@" 2> "$out.eval.log"); then
    echo "verdict_real_data: $set $kind seed $seed: eval failed (see $out.eval.log); recorded as a failure" >&2
    printf '%s\t%s\t%s\tNA\tall=FAIL\n' "$set" "$kind" "$seed"
    return 0
  fi
  printf '%s' "$json" | /usr/bin/python3 -c '
import json, sys
r = json.load(sys.stdin)
def name(row):
    if row["row"] == "all":
        return "all"
    if row["row"] == "class":
        return "class %d" % row["class"]
    return "pair %d-%d" % (row["ci"], row["cj"])
def p(row):
    if row["p"] is not None:
        return "%.4f" % row["p"]
    return "FAIL" if row.get("outcome") == "fail" or row.get("pass") is False else "NA"
pcf = r["all"]["pcf_mse"]
cells = sys.argv[1:4] + ["NA" if pcf is None else "%.6g" % pcf]
for row in r["verdict"]["rows"]:
    cells.append("%s=%s" % (name(row), p(row)))
for row in r["second_order"]["rows"]:
    v = row.get("l_sup_spacings")
    cells.append("L:%s=%s" % (name(row), "NA" if v is None else "%.4f" % v))
print("\t".join(cells))
' "$set" "$kind" "$seed" || {
    echo "verdict_real_data: $set $kind seed $seed: eval's JSON not read; recorded as a failure" >&2
    printf '%s\t%s\t%s\tNA\tall=FAIL\n' "$set" "$kind" "$seed"
  }
}

results="$dir/results.tsv"
touch "$results"
for set in $sets; do
  ex="$dir/exemplars/$set.txt"
  # The fitted model's draws (seeds as draw numbers), in exemplar units: eval with --zoom 1.
  for seed in $seeds; do
    if [[ ! -f $dir/fitted/${set}_d$(printf '%03d' "$seed").txt ]]; then
      Rscript docs/lab/verdict/spatstat_fitted.R "$ex" "$dir/fitted/$set" "$seed:$seed" 2 >> "$dir/fitted/$set.log" 2>&1
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
def number(v):
    try:
        return float(v)
    except ValueError:
        return None
rows = collections.OrderedDict()
for line in open(sys.argv[1]):
    f = line.rstrip("\n").split("\t")
    s, kind, seed, pcf = f[:4]
    cells = dict(x.split("=") for x in f[4:])
    ps = {k: v for k, v in cells.items() if not k.startswith("L:")}
    ls = {k[2:]: number(v) for k, v in cells.items() if k.startswith("L:")}
    rows.setdefault((s, kind), collections.OrderedDict())[seed] = (seed, number(pcf), ps, ls)  # a rerun's line replaces
rows = collections.OrderedDict((k, sorted(v.values(), key=lambda r: int(r[0]))) for k, v in rows.items())  # seeds in order
print("| data set | output | seeds | pass rate at 5 % per row | median sup L distance per row (mean spacings) | median PCF MSE (all) |")
print("|---|---|---|---|---|---|")
for (s, kind), runs in rows.items():
    names = []
    for r in runs:
        names += [n for n in r[2] if n not in names]
    pr, ml = [], []
    for n in names:
        # A run without the row, or whose row is FAIL (no p), fails it; NA cannot judge: apart.
        vals = [r[2].get(n, "FAIL") for r in runs]
        passed = sum(number(v) is not None and number(v) >= 0.05 for v in vals)
        cannot = sum(v == "NA" for v in vals)
        pr.append("%s %d/%d%s" % (n, passed, len(vals), ", %d cannot judge" % cannot if cannot else ""))
        lv = [r[3][n] for r in runs if r[3].get(n) is not None]
        ml.append("%s %.3f" % (n, statistics.median(lv)) if lv else n + " -")
    pcfs = [r[1] for r in runs if r[1] is not None]
    print("| %s | %s | %s | %s | %s | %s |" % (s, kind, ",".join(r[0] for r in runs), ", ".join(pr), ", ".join(ml),
                                               "%.4f" % statistics.median(pcfs) if pcfs else "-"))
EOF
