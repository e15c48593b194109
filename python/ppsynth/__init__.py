"""ppsynth: by-example point-pattern synthesis (Huang et al., EGSR 2022) from Python.

The same library as the ``ppsynth`` command, on NumPy arrays::

    import ppsynth
    exemplar = ppsynth.read("shared:data/exemplars/gabor-paper/lines.txt")
    result = ppsynth.synthesize(exemplar, seed=95)          # 4x the points, the paper's method
    result.output.positions                                  # (N, 2) float64
    ppsynth.evaluate(exemplar, result.output).all.pcf_mse

- points:     :class:`PointSet`, :func:`read`, :func:`write` (every format of the command plus
              .npy / .npz), :func:`generate`
- synthesis:  :func:`synthesize` (in memory), :func:`run` / :func:`resume` (run directories),
              :func:`resolve_config`
- metrics:    :func:`evaluate` -> :class:`Evaluation` (``ppsynth eval --json`` as an object
              with NumPy curves; ``to_dict()`` for the JSON's dict)
- extending:  :func:`register_loss`, :func:`register_point_term` (terms written with torch)

Importing starts no thread and changes no allocator setting; the first synthesis applies
the command's runtime settings (every core, or PPSYNTH_THREADS).
"""
from .points import PointSet, read, write, generate, generators
from .evaluation import evaluate, Evaluation, Record
from .synthesis import synthesize, run, resume, resolve_config, Result, Stage, Losses, Progress
from .terms import register_loss, register_point_term, ClassStage, point_term_value_and_grad, loss_value_and_grad

__all__ = [
    "PointSet", "read", "write", "generate", "generators", "evaluate", "Evaluation", "Record",
    "synthesize", "run", "resume", "resolve_config", "Result", "Stage", "Losses", "Progress",
    "register_loss", "register_point_term", "ClassStage", "point_term_value_and_grad", "loss_value_and_grad",
]
