#!/usr/bin/python3
"""class_spacing.py EXEMPLAR ARM=FILE ... : two tables, per class, median (min-max) over each
arm's files:
- spacing: the output's mean nearest-neighbour distance within the class over the exemplar's,
  both scaled to the same density (1: the exemplar's spacing; below 1: the class is packed
  tighter than in the exemplar; above: spread wider);
- close: the share of the class's output points whose nearest neighbour of the class is
  closer than the exemplar's closest pair of the class (density-scaled; a copy's pairs equal
  it to rounding, hence the 1e-6 margin): a hard core broken. CLOSE=0.9 counts only pairs
  nearer than 0.9 x that pair (the separation term's threshold, method.terms.separation).

Why this and not the class's PCF MSE: lemon_4c_v2's classes hold 3-13 points. A PCF estimated
from 3 points is mostly noise (a tiled copy of the exemplar reads worse than a random start on
some classes), while each point's nearest neighbour of its class is still measured: a class of 3
exemplar points gives 3 distances, its output of 12 points gives 12.

The exemplar is read on the torus (the method learns it periodic, and a tiled copy repeats it
exactly, so a copy reads 1.00). The output is read in its own domain with the border
corrected by minus sampling: a point counts only when its nearest neighbour is closer than the
domain's edge (a point whose neighbour may lie outside the window is left out). The mean, not
the median: a class with near pairs and lone points has two modes, and which points minus
sampling keeps moved a copy's median by 0.61-1.22 but its mean by 0.87-1.04 (lemon, five copies).
`ppsynth convert --to json` reads every format; PPSYNTH_BIN picks the binary."""
import collections, json, math, os, statistics as st, subprocess, sys, tempfile

BIN = os.environ.get('PPSYNTH_BIN', 'build/ppsynth')
CLOSE = float(os.environ.get('CLOSE', '1'))


def read(path):
    """(domain (x0, y0, x1, y1), {class: [(x, y)]}) of a point file in any format ppsynth reads."""
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, 'p.json')
        subprocess.run([BIN, 'convert', '-q', '--to', 'json', path, out], check=True)
        m = json.load(open(out))
    box = tuple(m['domain'])  # x0 y0 x1 y1
    by_class = collections.defaultdict(list)
    for p in m['points']:  # x, y, class, attributes...
        by_class[int(p[2]) if len(p) > 2 else 0].append((p[0], p[1]))
    return box, by_class


def nn_distances(pts, box, torus, minus_sampling=True):
    w, h = box[2] - box[0], box[3] - box[1]
    out = []
    for i, (x, y) in enumerate(pts):
        best = math.inf
        for j, (u, v) in enumerate(pts):
            if i == j: continue
            dx, dy = abs(x - u), abs(y - v)
            if torus: dx, dy = min(dx, w - dx), min(dy, h - dy)
            best = min(best, math.hypot(dx, dy))
        edge = min(x - box[0], box[2] - x, y - box[1], box[3] - y)
        if best < math.inf and (torus or not minus_sampling or best < edge): out.append(best)
    return out


def spacing(box, by_class, torus):
    """{class: (mean nearest-neighbour distance, points per unit area, every point's nearest
    neighbour distance without the border correction: a close pair inside the window is
    measured exactly wherever it lies)}."""
    area = (box[2] - box[0]) * (box[3] - box[1])
    res = {}
    for c, pts in by_class.items():
        d = nn_distances(pts, box, torus)
        res[c] = (st.mean(d) if d else None, len(pts) / area, nn_distances(pts, box, torus, minus_sampling=False))
    return res


def fmt(v):
    v = [x for x in v if x is not None]
    return '-' if not v else '%.2f (%.2f-%.2f)' % (st.median(v), min(v), max(v))


if __name__ == '__main__':
    ex_box, ex_classes = read(sys.argv[1])
    ex = spacing(ex_box, ex_classes, torus=True)
    arms = collections.OrderedDict()
    for a in sys.argv[2:]:
        arm, path = a.split('=', 1)
        arms.setdefault(arm, []).append(path)
    ratios, close = collections.OrderedDict(), collections.OrderedDict()
    for arm, files in arms.items():
        per, share = collections.defaultdict(list), collections.defaultdict(list)
        for f in files:
            box, cl = read(f)
            for c, (d, rho, all_d) in spacing(box, cl, torus=False).items():
                d_ex, rho_ex, all_ex = ex[c]
                # the same process at density rho spaces its points by 1/sqrt(rho): scale to compare
                scale = math.sqrt(rho) / math.sqrt(rho_ex)
                per[c].append(None if d is None or d_ex is None else d * scale / d_ex)
                share[c].append(None if not all_d or not all_ex else
                                sum(x * scale < (CLOSE - 1e-6) * min(all_ex) for x in all_d) / len(all_d))
        ratios[arm], close[arm] = per, share
    classes = sorted(ex)
    for title, table in (('spacing: mean nearest-neighbour distance over the exemplar\'s', ratios),
                         ('close: share of points nearer than %g x the exemplar\'s closest pair of the class' % CLOSE, close)):
        print('%s\n' % title)
        print('| class (exemplar points) | ' + ' | '.join('%s (%d files)' % (a, len(arms[a])) for a in arms) + ' |')
        print('| --- |' + ' --- |' * len(arms))
        for c in classes:
            print('| %d (%d) | %s |' % (c, len(ex_classes[c]), ' | '.join(fmt(table[a][c]) for a in arms)))
        print()
