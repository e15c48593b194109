#!/usr/bin/python3
"""file_arms.py EXEMPLAR ARM=FILE ... : per arm, over its files (an output.txt, a cropped
snapshot, a fitted model's draw: any point file in exemplar units), each row's verdict p
(passes at 0.05), sup |L - L_ex| in mean spacings and PCF MSE, median (min-max), then every
file's rows on a line of its own (paired reading by seed). `ppsynth eval --zoom 1`: every file
lies in the exemplar's units, as spatstat_fitted.R's draws and `--size` outputs do.
PPSYNTH_BIN picks the binary."""
import collections, json, os, statistics as st, subprocess, sys

BIN = os.environ.get('PPSYNTH_BIN', 'build/ppsynth')
ex = sys.argv[1]


def name(r):
    return 'all' if r['row'] == 'all' else ('class %d' % r['class'] if r['row'] == 'class' else 'pair %d-%d' % (r['ci'], r['cj']))


def evaluate(points):
    r = subprocess.run(['nice', BIN, 'eval', '-q', '--exemplar', ex, '--output', points, '--zoom', '1', '--json', '--no-curves',
                        '--no-scorecard'], capture_output=True, text=True, check=True)
    m = json.loads(r.stdout)
    rows = collections.defaultdict(dict)
    for x in m['verdict']['rows']: rows[name(x)]['p'] = x['p']
    for x in m['second_order']['rows']: rows[name(x)]['L'] = x['l_sup_spacings']
    rows['all']['pcf'] = m['all']['pcf_mse']
    for i, c in enumerate(m['classes']): rows['class %d' % i]['pcf'] = c['pcf_mse']
    for c in m.get('cross', []): rows['pair %d-%d' % (c['ci'], c['cj'])]['pcf'] = c['pcf_mse']
    return rows


def fmt(v, f):
    v = [x for x in v if x is not None]
    return '-' if not v else (f + ' (' + f + '-' + f + ')') % (st.median(v), min(v), max(v))


arms = collections.OrderedDict()
for a in sys.argv[2:]:
    arm, path = a.split('=', 1)
    arms.setdefault(arm, []).append(path)
for arm, files in arms.items():
    res = [(f, evaluate(f)) for f in files]
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
