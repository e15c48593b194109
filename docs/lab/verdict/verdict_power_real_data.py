#!/usr/bin/python3
"""The verdict's power on real exemplars: how often patterns that are NOT the exemplar's
process are told apart from it, per data set (docs/lab/verdict/README.md, "Real data").

    docs/lab/verdict/verdict_power_real_data.py EXEMPLAR_DIR "SETS" DRAWS [--copies K] [-o TSV]
    e.g. docs/lab/verdict/verdict_power_real_data.py /tmp/real/exemplars "cells redwood amacrine" 20

EXEMPLAR_DIR holds the exported data sets (scripts/spatstat_export.R). For each data set and
draw, three kinds of output of K x K the exemplar's window (default 2, the size ppsynth
synthesizes by default) and K^2 x its points per class, in exemplar units (judged with zoom 1,
as eval judges ppsynth's outputs); a larger K shows how the power grows with the output:
    csr      uniform points (complete spatial randomness), each class its count;
    ssi      a Poisson-disk pattern of all the points (dart throwing at 0.65 of the densest
             packing's radius), labels drawn without replacement from the class counts;
    relabel  the exemplar itself, 2 x 2 copies, with its labels permuted (multitype only):
             the positions are right, only the pairing of the types is lost.
    (the relabelled copies are K x K copies)
Prints per data set and kind the share of draws that fail (p < 0.05) in each verdict row: a
share near 0.05 means the verdict cannot tell that kind from the exemplar on this data set.
Writes every p to TSV (default EXEMPLAR_DIR/../power_K<K>.tsv): data set, kind, draw, row, p.
"""
import argparse
import collections
import os
import sys

import numpy as np

import ppsynth


def row_name(r):
    if r.row == "class":
        return f"class {r.class_}"
    return f"pair {r.ci}-{r.cj}" if r.row == "pair" else r.row


def outputs(ex, draw, copies):
    """(kind, PointSet) for one draw: K x K the exemplar's window, K^2 x its points per class."""
    x0, y0, x1, y1 = ex.domain
    w, h = x1 - x0, y1 - y0
    window = (0.0, 0.0, copies * w, copies * h)
    rng = np.random.default_rng(1000 + draw)
    labels = ex.class_labels
    k = int(ex.classes.max()) + 1
    counts = [copies ** 2 * int(np.sum(ex.classes == c)) for c in range(k)]
    classes = np.repeat(np.arange(k), counts)
    # csr: each class its own uniform points
    csr = ppsynth.PointSet(rng.random((len(classes), 2)) * [copies * w, copies * h], classes, domain=window,
                           class_labels=labels)
    yield "csr", csr
    ssi = ppsynth.generate("poisson_disk", len(classes), seed=draw, domain=window)
    if len(ssi) == len(classes):
        yield "ssi", ppsynth.PointSet(ssi.positions, rng.permutation(classes), domain=window, class_labels=labels)
    if k > 1:
        tiles = [ex.positions - [x0, y0] + [i * w, j * h] for i in range(copies) for j in range(copies)]
        pos = np.concatenate(tiles)
        yield "relabel", ppsynth.PointSet(pos, rng.permutation(np.tile(ex.classes, copies ** 2)), domain=window,
                                          class_labels=labels)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exemplars")
    ap.add_argument("sets")
    ap.add_argument("draws", type=int)
    ap.add_argument("--copies", type=int, default=2, help="the output is K x K exemplar windows (default 2)")
    ap.add_argument("-o", "--out")
    a = ap.parse_args()
    if a.draws < 1:
        sys.exit("verdict_power_real_data: DRAWS must be >= 1")
    if not 1 <= a.copies <= 16:
        sys.exit("verdict_power_real_data: --copies must be in 1..16")
    out = a.out or os.path.join(os.path.dirname(os.path.abspath(a.exemplars)), f"power_K{a.copies}.tsv")
    rows = []
    for s in a.sets.split():
        ex = ppsynth.read(os.path.join(a.exemplars, s + ".txt"))
        for d in range(1, a.draws + 1):
            for kind, ps in outputs(ex, d, a.copies):
                e = ppsynth.evaluate(ex, ps, zoom=1.0, curves=False)
                for r in e.verdict.rows:
                    rows.append((s, kind, d, row_name(r), r.p))
        print(f"[{s}] done", file=sys.stderr, flush=True)
    with open(out + ".partial", "w") as f:
        for r in rows:
            f.write("\t".join(map(str, r[:4])) + "\t" + ("NA" if r[4] is None else f"{r[4]:.4f}") + "\n")
    os.replace(out + ".partial", out)
    table = collections.OrderedDict()
    for s, kind, d, row, p in rows:
        if p is not None:
            table.setdefault((s, kind), collections.OrderedDict()).setdefault(row, []).append(p < 0.05)
    print(f"| data set | output ({a.copies} x {a.copies} windows) | draws | share failing at 5 % per row |")
    print("|---|---|---|---|")
    for (s, kind), per_row in table.items():
        n = max(len(v) for v in per_row.values())
        cells = ", ".join(f"{row} {np.mean(v):.2f}" for row, v in per_row.items())
        print(f"| {s} | {kind} | {n} | {cells} |")
    print(f"p values: {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
