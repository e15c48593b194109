#!/usr/bin/python3
"""file_arms.py EXEMPLAR ARM=FILE ... : per arm, over its files (an output.txt, a cropped
snapshot, a fitted model's draw: any point file in exemplar units), each row's verdict p
(passes at 0.05), sup |L - L_ex| in mean spacings and PCF MSE, median (min-max), then every
file's rows on a line of its own (paired reading by seed). `ppsynth eval --zoom 1`: every file
lies in the exemplar's units, as spatstat_fitted.R's draws and `--size` outputs do.
PPSYNTH_BIN picks the binary."""
import collections, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'real_scale'))
from two_class_arms import evaluate, fmt  # noqa: E402  (one eval reader for the lab's arm tables)

ex = sys.argv[1]


arms = collections.OrderedDict()
for a in sys.argv[2:]:
    arm, path = a.split('=', 1)
    arms.setdefault(arm, []).append(path)
for arm, files in arms.items():
    res = [(f, evaluate(ex, f, zoom=1)) for f in files]
    print('## %s (%d files)' % (arm, len(res)))
    print('| row | p | passes | L | PCF MSE |')
    print('| --- | --- | --- | --- | --- |')
    for row in res[0][1]:
        ps = [r[row].get('p') for _, r in res]
        print('| %s | %s | %d/%d | %s | %s |' % (row, fmt(ps, '%.3f'), sum(p is not None and p >= 0.05 for p in ps), len(ps),
                                              fmt([r[row].get('L') for _, r in res], '%.3f'),
                                              fmt([r[row].get('pcf') for _, r in res], '%.4f')))
    for f, r in res:
        print('  %s: %s' % (f, '; '.join('%s p %.3f L %.3f pcf %.4f' % (k, v.get('p', float('nan')), v.get('L', float('nan')),
                                                                      v.get('pcf', float('nan'))) for k, v in r.items())))
    print()
