#!/usr/bin/python3
"""file_arms.py EXEMPLAR ARM=FILE ... : per arm, over its files (an output.txt, a cropped
snapshot, a fitted model's draw: any point file in exemplar units), each row's verdict p
(passes at 0.05), sup |L - L_ex| in mean spacings and PCF MSE, median (min-max), then every
file's rows on a line of its own (paired reading by seed). `ppsynth eval --zoom 1`: every file
lies in the exemplar's units, as spatstat_fitted.R's draws and `--size` outputs do; ZOOM=auto
lets eval take the zoom from the densities (outputs in the unit square, e.g. the default 2 x 2
of a gabor-paper exemplar). SCORECARD=1 adds the scorecard's fidelity per row: L in spreads
(median (min-max) over the files where it can judge), how many are within band, and how many
it cannot judge. PPSYNTH_BIN picks the binary."""
import collections, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'real_scale'))
from two_class_arms import evaluate, fmt  # noqa: E402  (one eval reader for the lab's arm tables)

ex = sys.argv[1]
zoom = None if os.environ.get('ZOOM', '1') == 'auto' else float(os.environ.get('ZOOM', '1'))
scorecard = os.environ.get('SCORECARD') == '1'


arms = collections.OrderedDict()
for a in sys.argv[2:]:
    arm, path = a.split('=', 1)
    arms.setdefault(arm, []).append(path)
for arm, files in arms.items():
    res = [(f, evaluate(ex, f, zoom=zoom, scorecard=scorecard)) for f in files]
    print('## %s (%d files)' % (arm, len(res)))
    print('| row | p | passes | L | PCF MSE |' + (' scorecard: L spreads | within band | cannot judge |' if scorecard else ''))
    print('| --- | --- | --- | --- | --- |' + (' --- | --- | --- |' if scorecard else ''))
    for row in res[0][1]:
        ps = [r[row].get('p') for _, r in res]
        line = '| %s | %s | %d/%d | %s | %s |' % (row, fmt(ps, '%.3f'), sum(p is not None and p >= 0.05 for p in ps), len(ps),
                                               fmt([r[row].get('L') for _, r in res], '%.3f'),
                                               fmt([r[row].get('pcf') for _, r in res], '%.4f'))
        if scorecard:
            sp = [r[row].get('spreads') for _, r in res]
            line += ' %s | %d/%d | %d |' % (fmt(sp, '%.2f'), sum(r[row].get('within') is True for _, r in res),
                                           sum(x is not None for x in sp), sum(x is None for x in sp))
        print(line)
    num = lambda v: float('nan') if v is None else v  # a row the verdict cannot judge has p None
    for f, r in res:
        print('  %s: %s' % (f, '; '.join('%s p %.3f L %.3f pcf %.4f' % (k, num(v.get('p')), num(v.get('L')), num(v.get('pcf')))
                                       for k, v in r.items())))
    print()
