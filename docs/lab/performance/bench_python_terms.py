#!/usr/bin/python3
"""What a loss term written in Python costs per iteration against the same term compiled.

On `lines` at the published settings (256 x 256 grid), the first stage's iterations are timed
with the compiled "gram" loss and with the same Gram loss written in Python (python
registered as "py_gram"), alternating, REPEATS times each; prints the median seconds per
iteration of each and their ratio. Usage (after scripts/install_python.sh, or with
PYTHONPATH=build/python):  /usr/bin/python3 docs/lab/performance/bench_python_terms.py [ITERATIONS] [REPEATS]
"""
import os
import statistics
import sys
import time

import ppsynth

ITERATIONS = int(sys.argv[1]) if len(sys.argv) > 1 else 30
REPEATS = int(sys.argv[2]) if len(sys.argv) > 2 else 3
LINES = "shared:data/exemplars/gabor-paper/lines.txt"


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples"))
import python_terms  # noqa: E402

py_gram = python_terms.gram_loss
ppsynth.register_loss("py_gram", py_gram, defaults={"weight": 0.08, "layers": [0, 1, 2]})


def seconds_per_iteration(losses):
    stamps = []

    def progress(p):
        if p.stage_index == 0:
            stamps.append(time.perf_counter())
        elif len(stamps) >= ITERATIONS:
            raise StopIteration
    try:
        ppsynth.synthesize(LINES, seed=95, progress=progress,
                           overrides={"evaluate": False, "method.max_iterations": ITERATIONS,
                                      "method.losses": losses})
    except StopIteration:
        pass
    steps = [b - a for a, b in zip(stamps[1:], stamps[2:])]  # the first iteration builds the targets
    return statistics.median(steps)


def python_gram_alone(reps=5):
    """The Python Gram's own forward + gradient on the network's layer shapes (channels-last,
    as the features come), without ppsynth: what the function costs in torch."""
    import torch
    shapes = [(1, 120, 256, 256), (1, 120, 128, 128), (1, 120, 64, 64)]
    out = [torch.randn(s).contiguous(memory_format=torch.channels_last).requires_grad_() for s in shapes]
    tgt = [torch.randn(s).contiguous(memory_format=torch.channels_last) for s in shapes]
    times = []
    for _ in range(reps + 1):
        a = time.perf_counter()
        torch.autograd.grad(py_gram(out, tgt, {}), out)
        times.append(time.perf_counter() - a)
    return statistics.median(times[1:])


compiled = ppsynth.resolve_config({"exemplar": LINES})["method"]["losses"]
python = [dict(l, type="py_gram") if l["type"] == "gram" else l for l in compiled]
times = {"compiled": [], "python": []}
for _ in range(REPEATS):
    times["compiled"].append(seconds_per_iteration(compiled))
    times["python"].append(seconds_per_iteration(python))
c, p = statistics.median(times["compiled"]), statistics.median(times["python"])
alone = python_gram_alone()
print(f"lines, 256 x 256 grid, {ppsynth.synthesis._native.threads()} threads, {ITERATIONS} iterations x {REPEATS} runs each")
print(f"  compiled gram      : {c:.4f} s/iteration  (runs: {', '.join(f'{t:.4f}' for t in times['compiled'])})")
print(f"  gram in Python     : {p:.4f} s/iteration  (runs: {', '.join(f'{t:.4f}' for t in times['python'])})")
print(f"  Python / compiled  : {p / c:.3f}  (+{1000 * (p - c):.1f} ms per iteration)")
print(f"  the Python Gram alone in torch (forward + gradient, 3 layers): {1000 * alone:.1f} ms per evaluation;")
print("  compare with `ppsynth bench`'s 'loss gram (forward + backward)' phase for the compiled one")
