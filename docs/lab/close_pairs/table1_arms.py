#!/usr/bin/python3
"""table1_arms.py EXEMPLAR RUN_DIR... : per arm (the run directories' names up to _sSEED), median
(min-max) over its seeds of the output's normalized minimum distance rho (table1's number), its
pairs closer than the exemplar's closest, its PCF MSE and Wasserstein distance, beside the same
for the runs' initializations (init.txt); and the run's seconds. `ppsynth eval` (the scorecard's
close-pairs part) judges both. PPSYNTH_BIN picks the binary."""
import collections, json, os, re, statistics as st, subprocess, sys

BIN = os.environ.get('PPSYNTH_BIN', 'build/ppsynth')
ex = sys.argv[1]


def evaluate(points):
    r = subprocess.run(['nice', BIN, 'eval', '-q', '--exemplar', ex, '--output', points, '--json', '--no-curves'],
                       capture_output=True, text=True, check=True)
    m = json.loads(r.stdout)
    cp = next(x for x in m['scorecard']['close_pairs']['rows'] if x['row'] == 'all')
    return {'rho': cp['output_normalized'], 'below': cp['pairs_below'], 'pcf': m['all']['pcf_mse'],
            'w': m['all']['wasserstein'], 'rho_ex': cp['exemplar_normalized']}


def fmt(v, f='%.3f'):
    return (f + ' (' + f + '-' + f + ')') % (st.median(v), min(v), max(v))


arms = collections.defaultdict(list)
for d in sys.argv[2:]:
    if os.path.exists(os.path.join(d, 'output.txt')):
        arms[re.sub(r'_s\d+$', '', os.path.basename(d.rstrip('/')))].append(d)
print('| arm | seeds | rho | pairs below the exemplar\'s closest | PCF MSE | Wasserstein | rho at init | seconds |')
print('| --- | --- | --- | --- | --- | --- | --- | --- |')
for arm, runs in sorted(arms.items()):
    out = [evaluate(os.path.join(d, 'output.txt')) for d in sorted(runs)]
    ini = [evaluate(os.path.join(d, 'init.txt')) for d in sorted(runs)]
    secs = [json.load(open(os.path.join(d, 'run.json')))['total_seconds'] for d in sorted(runs)]
    print('| %s | %s | %s | %s | %s | %s | %s | %s |' % (
        arm, ' '.join(os.path.basename(d)[-2:] for d in sorted(runs)), fmt([o['rho'] for o in out]),
        fmt([o['below'] for o in out], '%d'), fmt([o['pcf'] for o in out], '%.4f'), fmt([o['w'] for o in out], '%.4f'),
        fmt([o['rho'] for o in ini]), fmt(secs, '%.0f')))
print('exemplar rho: %.3f' % out[0]['rho_ex'])
