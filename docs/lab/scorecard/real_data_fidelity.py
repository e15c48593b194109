#!/usr/bin/env python3
"""eval's fidelity and copy lines on real exemplars (docs/lab/scorecard/README.md, "Fidelity on real data").

  /usr/bin/python3 docs/lab/scorecard/real_data_fidelity.py EXEMPLARS FITTED DRAWS SET ...

Runs in one process on the checkout's Python module (build/python, or PPSYNTH_PYTHON: a copy of
it; needs NumPy). For each SET (EXEMPLARS/SET.txt, a plain point file of scripts/spatstat_export.R)
and draw d = 1..DRAWS, against the exemplar, the scorecard at its defaults of
  fitted  FITTED/SET_dNNN.txt: a realization of spatstat's fitted model on 2 x 2 exemplar windows
          (docs/lab/verdict/spatstat_fitted.R EXEMPLAR FITTED/SET DRAWS 2), zoom 1
  csr     uniform points, 4 x the exemplar's count of each class, on 2 x 2 windows (seed d), zoom 1
  ssi     Poisson-disk points (`ppsynth generate poisson_disk`, each class on its own), the same counts
  tiled   the tiled_copy method's output (seed d, 2 x 2 whole tiles), zoom from the densities
Prints per set and kind: patterns with any row out of band, the median L and g spreads of the
"all points" row, and patterns flagged a copy.
"""
import os
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
sys.path.insert(0, os.environ.get("PPSYNTH_PYTHON", os.path.join(ROOT, "build", "python")))
import ppsynth  # noqa: E402


def like(ex, seed, generator):
    """`generator`'s points ("uniform", "poisson_disk"), 4 x each class's count, each class on its
    own, on the exemplar's window doubled."""
    x0, y0, x1, y1 = ex.domain
    domain = (0, 0, 2 * (x1 - x0), 2 * (y1 - y0))
    counts = 4 * np.bincount(ex.classes, minlength=ex.num_classes)
    parts = [ppsynth.generate(generator, int(n), seed=1000 * seed + k, domain=domain).positions for k, n in enumerate(counts)]
    classes = np.repeat(np.arange(ex.num_classes), counts)
    return ppsynth.PointSet(np.concatenate(parts), classes=classes, domain=domain, class_labels=list(ex.class_labels))


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    exemplars, fitted, draws, sets = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
    print("| data set | output | patterns | any row out of band | all points: median L, g spreads | flagged a copy |")
    print("|---|---|---|---|---|---|")
    for name in sets:
        ex = ppsynth.read(os.path.join(exemplars, name + ".txt"))
        results = {}
        for d in range(1, draws + 1):
            cases = [("csr", like(ex, d, "uniform"), 1.0), ("ssi", like(ex, d, "poisson_disk"), 1.0),
                     ("tiled", ppsynth.synthesize(ex, {"method": {"type": "tiled_copy"}}, seed=d).output, 0.0)]
            path = os.path.join(fitted, "%s_d%03d.txt" % (name, d))
            if os.path.exists(path):
                cases.insert(0, ("fitted", ppsynth.read(path), 1.0))
            for kind, out, zoom in cases:
                e = ppsynth.evaluate(ex, out, zoom=zoom, curves=False, verdict=False, second_order=False).to_dict()
                sc = e["scorecard"]
                rows = sc["fidelity"]["rows"]
                out_of_band = any(r.get("within") is False for r in rows)
                all_row = rows[0]
                spreads = tuple((all_row.get(k) or {}).get("spreads") for k in ("l", "g"))
                results.setdefault(kind, []).append((out_of_band, spreads, bool(sc["novelty"].get("copy"))))
        for kind in ("fitted", "csr", "ssi", "tiled"):
            if kind not in results:
                continue
            r = results[kind]
            med = [np.median([s[i] for _, s, _ in r if s[i] is not None]) for i in (0, 1)]
            print("| %s | %s | %d | %d | %.2f, %.2f | %d |" % (name, kind, len(r), sum(o for o, _, _ in r), med[0], med[1],
                                                            sum(c for _, _, c in r)))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
