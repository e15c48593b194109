"""Synthesize 4x the points of the paper's `lines` exemplar and plot both (README, "Python")."""
import sys
import matplotlib
matplotlib.use("Agg")  # write a file; no display needed
import matplotlib.pyplot as plt
import ppsynth

def report(p):  # called at every iteration
    if p.iteration % 100 == 0:
        print(f"{p.stage}: iteration {p.iteration}, loss {p.loss:.4g}", flush=True)

exemplar = ppsynth.read("shared:data/exemplars/gabor-paper/lines.txt")
result = ppsynth.synthesize(exemplar, seed=95, progress=report, quick="--quick" in sys.argv)
print(f"{len(exemplar)} -> {len(result.output)} points in {result.seconds:.0f} s, "
      f"PCF MSE {result.metrics.all.pcf_mse:.3g}")
fig, axes = plt.subplots(1, 2, figsize=(8, 4))
for ax, ps, title in zip(axes, (exemplar, result.output), ("exemplar", "output")):
    ax.scatter(*ps.positions.T, s=6), ax.set_title(title), ax.set_aspect("equal")
fig.savefig(next((a for a in sys.argv[1:] if not a.startswith("--")), "lines.png"), dpi=120)
