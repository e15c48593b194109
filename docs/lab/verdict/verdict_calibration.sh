#!/usr/bin/env bash
# Calibration and power of eval's verdict (core/metrics/verdict.hpp; docs/lab/verdict/README.md): known
# processes simulated by spatstat (docs/lab/verdict/verdict_simulate.R), judged by `ppsynth eval`.
# Prints, per process and per kind of output, the share of draws whose p < 0.05 in each row:
#   same     an independent realization: the share should be 0.05 (calibration)
#   csr      uniform points of the same count per class (power)
#   ssi      a Poisson-disk pattern of the same count per class (power)
#   relabel  the realization with its labels permuted (power; multitype only)
#
#   docs/lab/verdict/verdict_calibration.sh DIR DRAWS [U=2] [FIRST=1] [EVAL FLAGS...]
#   e.g. docs/lab/verdict/verdict_calibration.sh /tmp/verdict 200 2 201 --verdict-guard 0.1
# Draws FIRST..FIRST+DRAWS-1 (docs/lab/verdict/verdict_simulate.R; another FIRST, fresh draws).
# DIR receives the simulated files (made once: an existing DIR/U<u> is reused, and must hold
# those draws) and
# results_U<u>.tsv (process, draw, output kind, row, p). Needs build/ppsynth and R with
# spatstat (scripts/setup.sh). The outputs are in exemplar units: eval runs with --zoom 1.
set -euo pipefail
cd "$(dirname "$0")/../../.."  # the checkout: this script is in docs/lab/<topic>/
usage="usage: docs/lab/verdict/verdict_calibration.sh DIR DRAWS [U] [FIRST] [EVAL FLAGS...]"
dir=${1:?$usage}
draws=${2:?$usage}
u=${3:-2}
first=${4:-1}
shift $(( $# < 4 ? $# : 4 ))
bin=build/ppsynth
[[ -x $bin ]] || { echo "verdict_calibration: $bin not built (scripts/setup.sh)" >&2; exit 1; }
sim="$dir/U$u"
if [[ ! -d $sim ]]; then
  Rscript docs/lab/verdict/verdict_simulate.R "$sim.tmp" "$draws" "$u" "$first" > /dev/null
  mv "$sim.tmp" "$sim"
fi
results="$dir/results_U$u.tsv"
: > "$results.tmp"
for pdir in "$sim"/*/; do
  process=$(basename "$pdir")
  for d in $(seq "$first" $((first + draws - 1))); do
    draw=$(printf 'd%03d' "$d")
    ex="$pdir${draw}_exemplar.txt"
    [[ -f $ex ]] || { echo "verdict_calibration: no $ex (DIR/U$u was made with other draws)" >&2; exit 1; }
    for kind in same csr ssi relabel; do
      out="$pdir${draw}_$kind.txt"
      [[ -f $out ]] || continue
      "$bin" eval -q --exemplar "$ex" --output "$out" --zoom 1 --json --no-curves --no-second-order "$@" |
        /usr/bin/python3 -c '
import json, sys
r = json.load(sys.stdin)
for row in r["verdict"]["rows"]:
    name = row["row"] if row["row"] == "all" else ("class %d" % row["class"] if row["row"] == "class" else "pair %d-%d" % (row["ci"], row["cj"]))
    print("\t".join([sys.argv[1], sys.argv[2], sys.argv[3], name, "NA" if row["p"] is None else repr(row["p"])]))
' "$process" "$draw" "$kind" >> "$results.tmp"
    done
  done
done
mv "$results.tmp" "$results"
/usr/bin/python3 - "$results" "$u" <<'EOF'
import sys, collections
rows = collections.OrderedDict()
for line in open(sys.argv[1]):
    process, draw, kind, row, p = line.rstrip("\n").split("\t")
    rows.setdefault((process, kind), collections.OrderedDict()).setdefault(row, []).append(p)
print("| process | output (U = %s) | draws | rejected at 5 %% per row (untestable draws) |" % sys.argv[2])
print("|---|---|---|---|")
for (process, kind), per in rows.items():
    cells = []
    for row, ps in per.items():
        tested = [float(p) for p in ps if p != "NA"]
        rate = sum(p < 0.05 for p in tested) / len(tested) if tested else float("nan")
        cells.append("%s %.2f%s" % (row, rate, "" if len(tested) == len(ps) else " (%d)" % (len(ps) - len(tested))))
    print("| %s | %s | %d | %s |" % (process, kind, len(next(iter(per.values()))), ", ".join(cells)))
EOF
