#!/usr/bin/env python3
"""Calibration of eval's fidelity lines (core/metrics/fidelity.hpp; docs/explanation/scorecard.md).

  /usr/bin/python3 docs/lab/scorecard/fidelity_calibration.py DIR DRAWS FIRST [PROCESS ...]
  /usr/bin/python3 docs/lab/scorecard/fidelity_calibration.py --summary TABLE ...

Runs in one process on the checkout's Python module (build/python: `cmake --build build
--target ppsynth_python ppsynth_python_files`; needs NumPy): the same evaluate() as `ppsynth
eval`, its scorecard at the defaults (64 sub-windows of half the exemplar's sides, alpha 0.05).
For each spatstat process (strauss hardcore matern thomas lgcp multitype; default all) and draw
d = FIRST..FIRST+DRAWS-1, drawn by docs/lab/verdict/verdict_simulate.R into DIR/sim (link an
earlier DIR/sim to reuse its draws: the exemplar on the unit square, about 100 points), against
the draw's exemplar:
  same   an independent realization of its process on 2 x 2 exemplar windows (zoom 1): the
         null; "within band" should fail at the nominal rate, "copy" never
  csr    uniform points of that count per class: should fail fidelity where it is detectable
  ssi    a Poisson-disk pattern of that count
  tiled  the tiled_copy method's output (seed d, 2 x 2 whole tiles): must be flagged a copy
Writes DIR/fidelity.tsv, one line per pattern and distance: process, kind, draw, row, distance
(l, g, kmm, or "-" for a row without distances), spreads, band, within (True, False, None),
the pattern's novelty share and copy flag, and the row's clustering (fidelity.hpp; tables
without it read as 1); prints per process and kind the share of patterns out of band per row
and distance, of patterns with any row out of band, and flagged a copy, with exact
(Clopper-Pearson) 95 % intervals.
  BAND=C (environment): judge "within" as spreads <= C x clustering^EXPONENT instead of the band
    the table was made at (EXPONENT, environment: default 0.25, fidelity.hpp's; 0: a constant).
  CHOOSE=D (environment, with --summary): first print the 95th percentile over draws up to D of
    the independent realizations' ("same") spreads / clustering^EXPONENT, every process, row and
    distance pooled (how the default band was chosen), then the rates over the draws after D
    only (held out).
"""
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
sys.path.insert(0, os.environ.get("PPSYNTH_PYTHON", os.path.join(ROOT, "build", "python")))  # PPSYNTH_PYTHON: a copy of the module
import ppsynth  # noqa: E402
import numpy as np  # noqa: E402
from scipy.stats import binomtest  # noqa: E402


def clopper_pearson(k, n):
    """Exact (Clopper-Pearson) 95 % interval of a binomial rate k / n; (0, 1) when n is 0."""
    if n == 0:
        return 0.0, 1.0
    ci = binomtest(k, n).proportion_ci(confidence_level=0.95, method="exact")
    return ci.low, ci.high

SPATSTAT = ["strauss", "hardcore", "matern", "thomas", "lgcp", "multitype"]
KINDS = ("same", "csr", "ssi", "tiled")


def cases(dirpath, process, draw):
    """(kind, exemplar, output, zoom) of one draw (zoom 0: from the densities)."""
    sim = os.path.join(dirpath, "sim", process)
    path = os.path.join(sim, "d%03d_exemplar.txt" % draw)
    if not os.path.exists(path):
        subprocess.run(["Rscript", os.path.join(ROOT, "docs/lab/verdict/verdict_simulate.R"), os.path.join(dirpath, "sim"),
                        "1", "2", str(draw), process], check=True, capture_output=True)
    ex = ppsynth.read(path)
    out = [(kind, ex, ppsynth.read(os.path.join(sim, "d%03d_%s.txt" % (draw, kind))), 1.0) for kind in ("same", "csr", "ssi")]
    whole = ppsynth.synthesize(ex, {"method": {"type": "tiled_copy"}}, seed=draw).output
    return out + [("tiled", ex, whole, 0.0)]


def score(exemplar, output, zoom):
    """The scorecard's fidelity rows and novelty of one pattern."""
    e = ppsynth.evaluate(exemplar, output, zoom=zoom, curves=False, verdict=False, second_order=False).to_dict()
    sc = e["scorecard"]
    lines = []
    for row in sc["fidelity"]["rows"]:
        name = row.get("name", row["row"])
        keys = [k for k in ("l", "g", "kmm") if k in row]
        clustering = row.get("clustering", 1.0)
        for k in keys:
            m = row[k]
            lines.append((name, k, m.get("spreads"), m.get("band"), m.get("within"), clustering))
        if not keys:
            lines.append((name, "-", None, None, row.get("within"), clustering))
    return lines, sc["novelty"].get("share"), sc["novelty"].get("copy")



def rate(k, n):
    lo, hi = clopper_pearson(k, n)
    return "%d / %d (%.2f, %.2f-%.2f)" % (k, n, k / n if n else float("nan"), lo, hi)


def median(v):
    v = sorted(v)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])


def summarize(records):
    """records: (process, kind, draw, row, distance, spreads, band, within, share, copy, clustering)."""
    per_pattern = {}
    for p, kind, d, row, dist, spreads, band, within, share, copy, _ in records:
        per_pattern.setdefault((p, kind, d), {"rows": [], "copy": copy})["rows"].append((row, dist, spreads, band, within))
    groups = {}
    for (p, kind, d), v in per_pattern.items():
        groups.setdefault((p, kind), []).append(v)
    print("| process | output | patterns | out of band, per row and distance: count / n (rate, 95 % interval); median spreads, median band "
          "| any row out of band | flagged a copy |")
    print("|---|---|---|---|---|---|")
    pooled = {}
    for (p, kind), pats in sorted(groups.items(), key=lambda x: (SPATSTAT.index(x[0][0]) if x[0][0] in SPATSTAT else 99,
                                                                  KINDS.index(x[0][1]) if x[0][1] in KINDS else 99)):
        cells = []
        keys = []
        for pat in pats:
            for row, dist, *_ in pat["rows"]:
                if (row, dist) not in keys:
                    keys.append((row, dist))
        for row, dist in keys:
            vals = [(s, b, w) for pat in pats for r, di, s, b, w in pat["rows"] if (r, di) == (row, dist)]
            judged = [w for _, _, w in vals if w is not None]
            out = sum(1 for w in judged if not w)
            spreads = [s for s, _, _ in vals if s is not None]
            bands = [b for _, b, _ in vals if b is not None]
            extra = "; %.2f, %.2f" % (median(spreads), median(bands)) if spreads and bands else ""
            cells.append("%s %s: %s%s" % (row, dist, rate(out, len(judged)) if judged else "-", extra))
            if dist != "-":
                t = pooled.setdefault((kind, dist), [0, 0])
                t[0] += out
                t[1] += len(judged)
        anyout = sum(1 for pat in pats if any(w is False for *_, w in pat["rows"]))
        copies = sum(1 for pat in pats if pat["copy"])
        print("| %s | %s | %d | %s | %s | %s |" % (p, kind, len(pats), "<br>".join(cells), rate(anyout, len(pats)),
                                                  rate(copies, len(pats))))
        t = pooled.setdefault((kind, "any row"), [0, 0])
        t[0] += anyout
        t[1] += len(pats)
        t = pooled.setdefault((kind, "copy"), [0, 0])
        t[0] += copies
        t[1] += len(pats)
    print("\npooled over the processes:")
    for (kind, what), (k, n) in sorted(pooled.items()):
        print("  %-6s %-8s out of band / flagged: %s" % (kind, what, rate(k, n)))



def rejudge(records):
    """BAND and CHOOSE applied to the records (see the docstring)."""
    exponent = float(os.environ.get("EXPONENT", "0.25"))
    band = os.environ.get("BAND")
    if band:
        band = float(band)
        records = [r[:6] + (band * r[10] ** exponent, r[7] if r[5] is None else r[5] <= band * r[10] ** exponent) + r[8:]
                   for r in records]
    choose = os.environ.get("CHOOSE")
    if choose:
        d = int(choose)
        same = [r[5] / r[10] ** exponent for r in records if r[1] == "same" and r[2] <= d and r[5] is not None]
        print("independent realizations' spreads / clustering^%g over draws up to %d: %d values, 95th percentile %.3f, "
              "90th %.3f, 99th %.3f\n" % (exponent, d, len(same), np.quantile(same, 0.95), np.quantile(same, 0.9),
                                         np.quantile(same, 0.99)))
        records = [r for r in records if r[2] > d]
    return records


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "--summary":  # tables written before, pooled
        records = []
        for table in sys.argv[2:]:
            for line in open(table):
                p, kind, d, row, dist, s, b, w, share, copy, *clustering = line.rstrip("\n").split("\t")
                f = lambda x: None if x == "None" else float(x)  # noqa: E731
                records.append((p, kind, int(d), row, dist, f(s), f(b), None if w == "None" else w == "True", f(share),
                                copy == "True", float(clustering[0]) if clustering else 1.0))
        summarize(rejudge(records))
        return
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    dirpath, draws, first = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    processes = sys.argv[4:] or SPATSTAT
    bad = [p for p in processes if p not in SPATSTAT]
    if bad:
        sys.exit("fidelity_calibration: unknown process %s; known: %s" % (" ".join(bad), " ".join(SPATSTAT)))
    os.makedirs(dirpath, exist_ok=True)
    table = os.path.join(dirpath, "fidelity.tsv")
    records = []
    with open(table, "w") as f:
        for process in processes:
            for draw in range(first, first + draws):
                for kind, ex, out, zoom in cases(dirpath, process, draw):
                    lines, share, copy = score(ex, out, zoom)
                    for row, dist, s, b, w, clustering in lines:
                        rec = (process, kind, draw, row, dist, s, b, w, share, copy, clustering)
                        f.write("\t".join(str(x) for x in rec) + "\n")
                        records.append(rec)
                f.flush()
    summarize(rejudge(records))


if __name__ == "__main__":
    main()
