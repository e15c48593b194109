#!/usr/bin/python3
"""rule_replay.py [--window W] [--min-iterations M] [--threshold T] [--give-up K] [--only revisit] RUN_DIR...

Replays the pattern stopping rule on the checks a finished run recorded (run.json,
method_stats.stages[].stopping_rule: each check's PCF MSE, the measure that chose the best, the
iteration the stage ended on) with other settings, and says per stage where that rule would
have stopped and which checked iterate it would have ended on. The same trajectory holds up to
the earlier of the two stops, so a rule that stops no later than the run's is replayed exactly:
if it ends on the same iterate, the stage's points are the same bits and only its iterations
are saved. A rule that would run past the run's stop cannot be replayed ("runs on").
The run's own settings: window 50, min_iterations 30, threshold 0.02 (the fast preset's)."""
import argparse, json, os

ap = argparse.ArgumentParser()
ap.add_argument('runs', nargs='+')
ap.add_argument('--window', type=int, default=50)
ap.add_argument('--min-iterations', type=int, default=30)
ap.add_argument('--threshold', type=float, default=0.02)
ap.add_argument('--give-up', type=int, default=0,
                help='also stop once this many iterations have run with no check better than the start (0: never)')
ap.add_argument('--only', default='', help='only stages whose label holds this text (e.g. revisit)')
a = ap.parse_args()


def stop_index(watched, chosen, every, window, min_it, thr, give_up):
    """The first check index at which the rule stops (check j is iteration j * every - 1; check 0 the start)."""
    recent = max(1, window // every)
    for j in range(1, len(watched)):
        it = j * every - 1
        if give_up and it + 1 >= give_up and min(chosen[1:j + 1]) >= chosen[0]: return j
        seen = watched[:j + 1]
        if it + 1 < min_it or len(seen) <= recent: continue
        before, last = min(seen[:-recent]), min(seen[-recent:])
        if last > (1 - thr) * before: return j
    return None


saved_total = same_total = stages_total = 0
for run in a.runs:
    st = json.load(open(os.path.join(run, 'run.json')))['method_stats']['stages']
    print('##', run)
    for s in st:
        r = s.get('stopping_rule')
        if not r or a.only not in s['stage'] or 'ended_on_iteration' not in r: continue
        every, watched = r['check_every'], r['pcf_mse']
        chosen = r.get('pcf_mse_chosen_by', watched)
        j = stop_index(watched, chosen, every, a.window, a.min_iterations, a.threshold, a.give_up)
        ran = s['iterations']
        if j is None or j * every > ran:
            print('  %-32s ran %3d, ended on %4d: runs on past %d' % (s['stage'], ran, r['ended_on_iteration'], ran))
            continue
        upto = chosen[:j + 1]
        ended = upto.index(min(upto)) * every - 1
        same = ended == r['ended_on_iteration']
        stages_total += 1
        same_total += same
        saved_total += ran - j * every
        print('  %-32s ran %3d, ended on %4d | replayed: stops after %3d, ends on %4d%s' %
              (s['stage'], ran, r['ended_on_iteration'], j * every, ended, '' if same else '  DIFFERS (chosen %.5f against %.5f)' %
               (min(upto), min(chosen))))
print('replayed stages: %d, the same iterate: %d, iterations saved: %d' % (stages_total, same_total, saved_total))
