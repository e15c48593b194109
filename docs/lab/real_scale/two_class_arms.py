#!/usr/bin/python3
"""two_class_arms.py EXEMPLAR RUN_DIR... : per arm (the run directories' names up to _sSEED),
median (min-max) over its seeds of each row's verdict p (passes at 0.05), sup L distance (mean
spacings) and own PCF MSE, each class's PCF MSE at its initialization (init.txt) beside its
output's, the run's seconds, and its seconds per iteration by class (run.json's stage records).
`ppsynth eval` judges both, at its default zoom (from the densities). PPSYNTH_BIN picks the binary."""
import collections, json, os, re, statistics as st, subprocess, sys

BIN = os.environ.get('PPSYNTH_BIN', 'build/ppsynth')


def name(r):
    return 'all' if r['row'] == 'all' else ('class %d' % r['class'] if r['row'] == 'class' else 'pair %d-%d' % (r['ci'], r['cj']))


def evaluate(ex, points, zoom=None, scorecard=False):
    """Each row's verdict p, sup L distance (mean spacings) and PCF MSE of `points` against `ex`
    (zoom: output units per exemplar unit; None: eval's, from the densities). With `scorecard`,
    also the scorecard's fidelity per row: 'spreads' (L distance over the sub-window spread,
    None where it cannot judge) and 'within' (within its band)."""
    r = subprocess.run(['nice', BIN, 'eval', '-q', '--exemplar', ex, '--output', points, '--json', '--no-curves']
                       + ([] if scorecard else ['--no-scorecard'])
                       + ([] if zoom is None else ['--zoom', str(zoom)]), capture_output=True, text=True, check=True)
    m = json.loads(r.stdout)
    rows = collections.defaultdict(dict)
    for x in m['verdict']['rows']: rows[name(x)]['p'] = x['p']
    if scorecard:
        for x in m['scorecard']['fidelity']['rows']:
            if x['row'] not in ('all', 'class', 'pair'): continue
            rows[name(x)]['spreads'] = x.get('l', {}).get('spreads')
            rows[name(x)]['within'] = x.get('l', {}).get('within')
    for x in m['second_order']['rows']: rows[name(x)]['L'] = x['l_sup_spacings']
    rows['all']['pcf'] = m['all']['pcf_mse']
    for i, c in enumerate(m['classes']): rows['class %d' % i]['pcf'] = c['pcf_mse']
    for c in m.get('cross', []): rows['pair %d-%d' % (c['ci'], c['cj'])]['pcf'] = c['pcf_mse']
    return rows


def fmt(v, f='%.4f'):
    v = [x for x in v if x is not None]
    return '-' if not v else (f + ' (' + f + '-' + f + ')') % (st.median(v), min(v), max(v))


if __name__ == '__main__':
    ex = sys.argv[1]
    arms = collections.defaultdict(list)
    for d in sys.argv[2:]:
        if not os.path.exists(os.path.join(d, 'output.txt')): continue
        arms[re.sub(r'_s\d+$', '', os.path.basename(d.rstrip('/')))].append(d)
    for arm, runs in arms.items():
        res = []
        for d in sorted(runs):
            out, init = evaluate(ex, os.path.join(d, 'output.txt')), evaluate(ex, os.path.join(d, 'init.txt'))
            run = json.load(open(os.path.join(d, 'run.json')))
            per_class = collections.defaultdict(lambda: [0.0, 0])
            for s in run['method_stats']['stages']:
                per_class[s['class']][0] += s['seconds']; per_class[s['class']][1] += s['iterations']
            res.append((out, init, run['synthesis_seconds'], {k: v[0] / max(1, v[1]) for k, v in per_class.items()},
                        {k: v[1] for k, v in per_class.items()}))
        print('%s: %d seeds (%s)' % (arm, len(res), ' '.join(os.path.basename(d)[-3:] for d in sorted(runs))))
        print('| row | p | passes | L (mean spacings) | PCF MSE | PCF MSE at init | worse than init |')
        print('| --- | --- | --- | --- | --- | --- | --- |')
        for row in res[0][0]:
            ps = [r[0][row].get('p') for r in res]
            worse = sum(r[0][row]['pcf'] > r[1][row]['pcf'] for r in res)
            print('| %s | %s | %d/%d | %s | %s | %s | %d/%d |' % (row, fmt(ps, '%.3f'), sum(p is not None and p >= 0.05 for p in ps), len(ps),
                  fmt([r[0][row].get('L') for r in res], '%.3f'), fmt([r[0][row]['pcf'] for r in res]),
                  fmt([r[1][row]['pcf'] for r in res]), worse, len(res)))
        print('seconds: %s; s/iteration by class: %s; iterations by class: %s' % (
            fmt([r[2] for r in res], '%.0f'),
            ', '.join('%d: %s' % (k, fmt([r[3][k] for r in res], '%.2f')) for k in sorted(res[0][3])),
            ', '.join('%d: %s' % (k, fmt([r[4][k] for r in res], '%d')) for k in sorted(res[0][4]))))
        print()
