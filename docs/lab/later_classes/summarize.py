#!/usr/bin/python3
"""summarize.py RUNS_DIR EXEMPLAR W H TAG...: per tag, over its seeds (RUNS_DIR/ama1x_TAG_sSEED),
the output's rows: PCF MSE, the verdict's p (passes at 0.05) and sup |L - L_ex| in mean spacings
(`ppsynth eval --zoom 1`; a run without output.txt is read from its last snapshot, cropped);
and each run's class-1 stages' seconds per iteration."""
import json, subprocess, sys, os, glob, statistics as st
d, ex, W, H = sys.argv[1:5]
def name(r):
    return 'all' if r['row'] == 'all' else ('class %d' % r['class'] if r['row'] == 'class' else 'pair %d-%d' % (r['ci'], r['cj']))
def one(run):
    out = os.path.join(run, 'output.txt')
    if not os.path.exists(out):
        snaps = sorted(glob.glob(os.path.join(run, 'snapshots', 'stage*.txt')))
        if len(snaps) < 8: return None
        out = os.path.join(run, 'salvaged_output.txt')
        subprocess.run(['python3', os.path.join(os.path.dirname(__file__), 'salvage.py'), snaps[-1], out, W, H], check=True)
    r = subprocess.run(['nice', os.environ.get('PPSYNTH_BIN', 'build/ppsynth'), 'eval', '-q', '--exemplar', ex, '--output', out, '--zoom', '1', '--json', '--no-curves', '--no-scorecard'],
                       capture_output=True, text=True, check=True)
    m = json.loads(r.stdout)
    rows = {}
    for x in m['verdict']['rows']: rows.setdefault(name(x), {})['p'] = x['p']
    for x in m['second_order']['rows']: rows.setdefault(name(x), {})['L'] = x['l_sup_spacings']
    rows['all']['pcf'] = m['all']['pcf_mse']
    for i, c in enumerate(m['classes']): rows['class %d' % i]['pcf'] = c['pcf_mse']
    for c in m.get('cross', []): rows['pair %d-%d' % (c['ci'], c['cj'])]['pcf'] = c['pcf_mse']
    spi = None
    if os.path.exists(os.path.join(run, 'run.json')):
        st_ = json.load(open(os.path.join(run, 'run.json')))['method_stats']['stages']
        c1 = [s for s in st_ if s['class'] == 1]
        spi = sum(s['seconds'] for s in c1) / max(1, sum(s['iterations'] for s in c1))
    return rows, spi
def fmt(v, f='%.4f'):
    v = [x for x in v if x is not None]
    return '-' if not v else (f + ' (' + f + '-' + f + ')') % (st.median(v), min(v), max(v))
for tag in sys.argv[5:]:
    runs = sorted(glob.glob(os.path.join(d, 'ama1x_%s_s*' % tag)))
    res = [(os.path.basename(r)[-3:], one(r)) for r in runs if os.path.isdir(r)]
    res = [(s, x) for s, x in res if x]
    print('%s: seeds %s' % (tag, ' '.join(s for s, _ in res)))
    for row in ['all', 'class 0', 'class 1', 'pair 0-1']:
        ps = [x[0][row]['p'] for _, x in res]
        print('  %-8s PCF MSE %s  p %s  passes %d/%d  L %s' % (row, fmt([x[0][row]['pcf'] for _, x in res]), fmt(ps, '%.3f'),
              sum(p is not None and p >= 0.05 for p in ps), len(ps), fmt([x[0][row]['L'] for _, x in res], '%.3f')))
    print('  class-1 stages s/iteration (1 thread, loaded): %s' % fmt([x[1] for _, x in res], '%.2f'))
