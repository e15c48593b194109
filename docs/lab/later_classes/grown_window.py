#!/usr/bin/python3
"""grown_window.py SRC DST [PAD]: a Point-Synthesis file (x y class ...) written as a ppsynth
points file whose domain is the per-axis min-max unit square (as ppsynth's reader scales it)
grown by PAD on every side; without PAD, by half the points' mean nearest-neighbour distance
(pooled). Prints that distance, pooled and per class. docs/lab/later_classes/README.md,
"Parterre10's lattice and its window"."""
import sys, math
src, dst = sys.argv[1], sys.argv[2]
rows = [l.split() for l in open(src) if l.strip()]
xs = [float(r[0]) for r in rows]; ys = [float(r[1]) for r in rows]; cl = [int(r[2]) for r in rows]
x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
P = [((x - x0) / (x1 - x0), (y - y0) / (y1 - y0)) for x, y in zip(xs, ys)]
def nn(i, pts):
    return min(math.dist(pts[i], q) for j, q in enumerate(pts) if j != i)
d = sum(nn(i, P) for i in range(len(P))) / len(P)
per = {}
for k in sorted(set(cl)):
    Q = [p for p, c in zip(P, cl) if c == k]
    per[k] = sum(nn(i, Q) for i in range(len(Q))) / len(Q)
print("pooled mean NN %.4f; per class %s" % (d, {k: round(v, 4) for k, v in per.items()}), file=sys.stderr)
pad = float(sys.argv[3]) if len(sys.argv) > 3 else d / 2
with open(dst, "w") as f:
    f.write("# ppsynth points\n# %s, window grown by %.6g on each side\n" % (src, pad))
    f.write("# domain %.9g %.9g %.9g %.9g\n# x y class\n" % (-pad, -pad, 1 + pad, 1 + pad))
    for (x, y), c in zip(P, cl):
        f.write("%.9g %.9g %d\n" % (x, y, c))
