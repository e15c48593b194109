"""evaluate() takes the switches of `ppsynth eval` (the second order, the verdict and its
options), answers the verdict's own `passed`, and stops on Ctrl-C."""
import json
import os
import resource
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import ppsynth
from conftest import GABOR, command


def test_evaluate_takes_the_switches_of_eval(tmp_path):
    ex = ppsynth.read(GABOR + "poisson_n64c2_point.txt")
    rng = np.random.default_rng(8)
    out = ppsynth.PointSet(rng.random((4 * len(ex), 2)), np.repeat(ex.classes, 4), class_labels=ex.class_labels)
    ppsynth.write(out, tmp_path / "out.txt")
    bare = ppsynth.evaluate(ex, out, bins=20, second_order=False, verdict=False)
    assert "second_order" not in bare and "verdict" not in bare
    assert bare.passed is None  # nothing judged
    r = ppsynth.evaluate(ex, out, bins=20, second_order=False, verdict_split=3, verdict_guard=0.2,
                         verdict_permutations=99, verdict_seed=4, verdict_alpha=0.1)
    assert "second_order" not in r and r.verdict.split == 3 and r.verdict.permutations == 99
    _, text, _ = command("eval", "--exemplar", GABOR + "poisson_n64c2_point.txt", "--output", tmp_path / "out.txt",
                         "--json", "--bins", 20, "--no-second-order", "--verdict-split", 3, "--verdict-guard", 0.2,
                         "--verdict-permutations", 99, "--verdict-seed", 4, "--verdict-alpha", 0.1)
    expected = json.loads(text)
    del expected["exemplar"]["path"], expected["output"]["path"]
    assert r.to_dict() == expected
    with pytest.raises(ValueError, match="verdict-split"):
        ppsynth.evaluate(ex, out, verdict_split=0)
    for key, value in (("verdict_seed", -1), ("crop_seed", -3), ("verdict_seed", 2 ** 64)):
        with pytest.raises(ValueError, match=key):  # was a TypeError from the binding
            ppsynth.evaluate(ex, out, bins=20, second_order=False, **{key: value})


def test_passed_is_the_verdicts_own_answer():
    # A row that cannot be judged is never a pass: the verdict says None, whatever the rows say.
    def ev(passed, rows):
        return ppsynth.Evaluation({"verdict": {"passed": passed, "rows": rows}})
    assert ev(None, [{"row": "all", "pass": True}, {"row": "class", "pass": None}]).passed is None
    assert ev(False, [{"row": "all", "pass": False}, {"row": "class", "pass": None}]).passed is False
    assert ev(True, [{"row": "all", "pass": True}]).passed is True
    assert ppsynth.Evaluation({"all": {}}).passed is None


SCRIPT = textwrap.dedent("""
    import sys, time
    import numpy as np
    import ppsynth
    rng = np.random.default_rng(1)
    ex = ppsynth.PointSet(rng.random((60000, 2)))
    out = ppsynth.PointSet(rng.random((240000, 2)))
    print("evaluating", flush=True)
    t0 = time.monotonic()
    try:
        ppsynth.evaluate(ex, out, curves=False)
    except KeyboardInterrupt:
        print(f"KeyboardInterrupt after {time.monotonic() - t0:.2f} s", flush=True)
        sys.exit(7)
    print("finished", flush=True)
""")


def _cpu_seconds(pid):
    # The process's user + system time so far (/proc/PID/stat fields 14 and 15, in clock ticks).
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


@pytest.mark.parametrize("delay", [0.5, 4.0])
def test_ctrl_c_stops_evaluate_within_a_second(delay):
    # A minute of work (60,000 against 240,000 points); SIGINT at two moments of it. What is
    # bounded is the CPU time the child spends after the signal, not the wall time: on a
    # loaded machine (2 cores, load 5) the wall time to exit reached 8 s while the child
    # itself worked well under a second.
    children_before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.Popen([sys.executable, "-c", SCRIPT], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         env={**os.environ, "PPSYNTH_THREADS": "1"})
    try:
        assert p.stdout.readline().strip() == "evaluating"
        time.sleep(delay)
        at_signal = _cpu_seconds(p.pid)
        p.send_signal(signal.SIGINT)
        stdout, stderr = p.communicate(timeout=60)
    finally:
        p.kill()
        p.wait()
    children_after = resource.getrusage(resource.RUSAGE_CHILDREN)
    total = (children_after.ru_utime + children_after.ru_stime) - (children_before.ru_utime + children_before.ru_stime)
    assert p.returncode == 7, stderr
    assert "KeyboardInterrupt after" in stdout
    print(f"CPU after the signal: {total - at_signal:.2f} s (child total {total:.2f} s)")
    assert total - at_signal < 2.0  # a second of its own work to answer, and the interpreter's exit
