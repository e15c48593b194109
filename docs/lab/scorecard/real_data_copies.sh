#!/usr/bin/env bash
# The scorecard's novelty, periodicity and close-pairs lines on spatstat.data's six real
# exemplars (docs/explanation/scorecard.md): tiled_copy's outputs (must be flagged a copy and
# periodic) and uniform points of the same count on the same 2 x 2 exemplar windows (must not),
# per seed.
#
#   docs/lab/scorecard/real_data_copies.sh DIR "DATA SETS" "SEEDS"
#   e.g. docs/lab/scorecard/real_data_copies.sh /tmp/sc "cells redwood japanesepines swedishpines amacrine longleaf" "95 96 97 98 99"
#
# Prints one line per data set, kind and seed: the novelty share (matched of scored), the copy
# flag, the periodicity ratio and flag, and the all-points close-pairs row (pairs below the
# exemplar's closest, normalized minimum distance of exemplar and output). Exemplars already in
# DIR/exemplars (e.g. copied there) are used as they are; the others are exported.
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
bin=$root/build/ppsynth
usage='usage: docs/lab/scorecard/real_data_copies.sh DIR "DATA SETS" "SEEDS"'
dir=${1:?$usage}
sets=${2:?$usage}
seeds=${3:?$usage}
mkdir -p "$dir/exemplars" "$dir/runs" "$dir/csr"
missing=$(for set in $sets; do [[ -f $dir/exemplars/$set.txt ]] || echo "$set"; done)
# shellcheck disable=SC2086
[[ -z $missing ]] || Rscript "$root/scripts/spatstat_export.R" "$dir/exemplars" $missing > /dev/null

line() {  # DATA SET KIND SEED EXEMPLAR OUTPUT [EVAL FLAGS...]
  local set=$1 kind=$2 seed=$3 ex=$4 out=$5
  shift 5
  "$bin" eval -q --exemplar "$ex" --output "$out" --json --no-curves --no-verdict --no-second-order "$@" |
    /usr/bin/python3 -c '
import json, sys
sc = json.load(sys.stdin)["scorecard"]
n, p, a = sc["novelty"], sc["periodicity"], sc["close_pairs"]["rows"][0]
print("%-14s %-10s %s  novelty %s (%d of %d)  copy %-5s  periodicity %.3g periodic %-5s  pairs below %s  normalized min %.3f / %.3f" % (
    sys.argv[1], sys.argv[2], sys.argv[3], n["share"], n["matched"], n["scored"], n["copy"], p["ratio"], p["periodic"],
    a["pairs_below"], a["exemplar_normalized"] or 0, a["output_normalized"] or 0))' "$set" "$kind" "$seed"
}

for set in $sets; do
  ex="$dir/exemplars/$set.txt"
  for seed in $seeds; do
    run="$dir/runs/${set}_tiled_copy_s$seed"
    [[ -f $run/output.txt ]] || "$bin" synthesize -q -e "$ex" -m tiled_copy --seed "$seed" -o "$run" --force > /dev/null
    line "$set" tiled_copy "$seed" "$ex" "$run/output.txt"
    # Uniform points, as many as the copy, on its 2 x 2 exemplar windows (exemplar units).
    read -r w h n < <(/usr/bin/python3 -c '
import sys
pts = [l for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
dom = [l for l in open(sys.argv[1]) if l.startswith("# domain")][0].split()
print(float(dom[4]) - float(dom[2]), float(dom[5]) - float(dom[3]), len(pts))' "$run/output.txt")
    csr="$dir/csr/${set}_s$seed.txt"
    [[ -f $csr ]] || "$bin" generate uniform -n "$n" --seed "$seed" --domain 0 0 "$w" "$h" -o "$csr" -q > /dev/null
    line "$set" csr "$seed" "$ex" "$csr" --zoom 1
  done
done
