"""Synthesis: an exemplar in, a larger pattern out.

:func:`synthesize` runs in memory and returns a :class:`Result`; :func:`run` and
:func:`resume` write a run directory, exactly as ``ppsynth synthesize`` does. All three run the
library of the command (same config, same seed and thread count: the same points, bit for
bit), release the GIL while they work, and stop on Ctrl-C at the end of the current iteration
after writing a checkpoint, raising KeyboardInterrupt.
"""
from __future__ import annotations

import json
import numbers
import os
from dataclasses import dataclass
from typing import Callable, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _ppsynth as _native
from .evaluation import _arrays
from .points import PointSet, _as_points

__all__ = ["synthesize", "run", "resume", "resolve_config", "Result", "RunResult", "Stage", "Progress"]


@dataclass(frozen=True)
class Progress:
    """What a ``progress`` callable receives at every iteration."""
    stage: str            # e.g. "class 1/2, sigma 3/4"
    stage_index: int      # 0-based over the whole run
    stage_count: int
    iteration: int        # within the stage
    max_iterations: int   # the stage's cap (0: unknown)
    loss: float
    seconds: float        # since the stage began


@dataclass(frozen=True)
class Stage:
    """One stage of a run (a class and sigma of the Gabor method)."""
    stage: str
    iterations: int
    final_loss: float
    seconds: float


@dataclass
class Losses:
    """Every iteration's loss: parallel arrays, one entry per iteration."""
    stage_index: np.ndarray
    stage: List[str]
    iteration: np.ndarray
    loss: np.ndarray
    seconds: np.ndarray


@dataclass
class Result:
    """What :func:`synthesize` returns."""
    output: PointSet              # in the unit square, with classes and attributes
    initialization: PointSet      # the output before optimisation
    stages: List[Stage]
    losses: Losses
    stats: dict                   # all the method measured (grid, sigmas, phase times, ...)
    metrics: Optional[dict]       # evaluate(exemplar, output) when config "evaluate" is on
    seconds: float                # wall time of the synthesis
    threads: int                  # LibTorch's thread count (results depend on it in the last bits)
    processor: str                # "MODEL (ISA)": results depend on the instruction set too
    config: dict                  # the resolved config
    resumed: bool                 # continued from checkpoint_dir


@dataclass
class RunResult:
    """What :func:`run` and :func:`resume` return: the run directory and what is in it."""
    dir: str
    exemplar: PointSet
    initialization: PointSet
    output: PointSet
    stats: dict
    metrics: Optional[dict]
    config: dict
    seconds: float


ConfigLike = Union[None, str, os.PathLike, Mapping]
Overrides = Union[None, Mapping[str, object], Sequence[str]]


def _override_strings(overrides: Overrides) -> List[str]:
    if overrides is None:
        return []
    if isinstance(overrides, Mapping):
        return [f"{k}={v if isinstance(v, str) else json.dumps(v)}" for k, v in overrides.items()]
    if isinstance(overrides, str):
        raise TypeError("overrides: expected a dict {'key.path': value} or a list of 'key.path=value' strings")
    return [str(o) for o in overrides]


def resolve_config(config: ConfigLike = None, seed: Optional[int] = None, overrides: Overrides = None) -> dict:
    """The config a run uses: ``config`` (None for the paper's defaults, a dict, or a JSON file
    with its ``parent`` chain), then ``seed`` and ``overrides`` (``{"method.max_iterations":
    50}`` or ``["method.max_iterations=50"]``, the command's ``--set``), merged with every
    default. Unknown keys and impossible values raise ValueError naming the key path; a seed
    is an integer in [0, 2^63) (ValueError outside it, TypeError for a float or a string)."""
    if config is None:
        c = {}
    elif isinstance(config, (str, os.PathLike)):
        c = json.loads(_native.load_config(os.fspath(config)))
    elif isinstance(config, Mapping):
        c = json.loads(json.dumps(dict(config)))
    else:
        raise TypeError(f"config: expected None, a dict or a file name, not {type(config).__name__}")
    if seed is not None:
        # Strictly an integer (NumPy's too): int() would truncate 5.7 and parse "95".
        if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
            raise TypeError(f"seed: expected an integer in [0, 2^63), not {type(seed).__name__}")
        c["seed"] = int(seed)
    return json.loads(_native.resolve_config(json.dumps(c), _override_strings(overrides)))


def _progress_hook(progress: Optional[Callable[[Progress], object]]):
    if progress is None:
        return None
    if not callable(progress):
        raise TypeError("progress: expected a callable taking a ppsynth.Progress")
    return lambda event: progress(Progress(**event))


def _loads_or_none(text: str):
    v = json.loads(text)
    return None if v is None else _arrays(v)


def synthesize(exemplar=None, config: ConfigLike = None, seed: Optional[int] = None, overrides: Overrides = None,
               progress: Optional[Callable[[Progress], object]] = None, checkpoint_dir=None, quick: bool = False,
               initialization=None, threads: int = 0) -> Result:
    """Synthesises a larger pattern from ``exemplar``, in memory.

    ``exemplar``: a PointSet, an (N, 2) array or a file name; None takes the config's
    ``"exemplar"``. ``config``, ``seed``, ``overrides``: as :func:`resolve_config` (None: the
    paper's method with the published settings, seed 95, u = 2, i.e. 4x the points).
    ``progress(p: Progress)`` is called at every iteration; an exception it raises stops the
    run (after its checkpoint) and is raised here. ``checkpoint_dir``: where the checkpoint of
    this synthesis is kept (every stage and every ``checkpoint_seconds``); after an
    interruption (Ctrl-C raises KeyboardInterrupt at the end of the iteration) the same call
    continues from it and returns what an uninterrupted run returns; a finished run removes
    it. ``quick``: tiny grids and few iterations (tests). ``initialization``: an explicit
    initial output. ``threads``: LibTorch's thread count (0: every core or PPSYNTH_THREADS).

    The same config, seed and thread count give the same output as ``ppsynth synthesize``.
    Bad input raises ValueError (FileNotFoundError for a missing file) with the command's
    message.
    """
    spec = resolve_config(config, seed, overrides)
    if exemplar is None:
        ex = PointSet._from_native(_native.load_exemplar(json.dumps(spec)))
    else:
        ex = _as_points(exemplar, "exemplar")
    init = None if initialization is None else _as_points(initialization, "initialization")._to_native()
    r = _native.synthesize(ex._to_native(), json.dumps(spec), bool(quick), init, _progress_hook(progress),
                           "" if checkpoint_dir is None else os.fspath(checkpoint_dir), int(threads))
    rows = r["losses"]
    losses = Losses(np.array([x[0] for x in rows], dtype=np.int64), [x[1] for x in rows],
                    np.array([x[2] for x in rows], dtype=np.int64), np.array([x[3] for x in rows], dtype=np.float64),
                    np.array([x[4] for x in rows], dtype=np.float64))
    return Result(PointSet._from_native(r["output"]), PointSet._from_native(r["initialization"]),
                  [Stage(**s) for s in r["stages"]], losses, json.loads(r["stats_json"]),
                  _loads_or_none(r["metrics_json"]), r["seconds"], r["threads"], r["processor"], spec, r["resumed"])


def _run_result(r: dict) -> RunResult:
    return RunResult(r["dir"], PointSet._from_native(r["exemplar"]), PointSet._from_native(r["initialization"]),
                     PointSet._from_native(r["output"]), json.loads(r["stats_json"]),
                     _loads_or_none(r["metrics_json"]), json.loads(r["config_json"]), r["seconds"])


def run(config: ConfigLike, out_dir, seed: Optional[int] = None, overrides: Overrides = None, quick: bool = False,
        force: bool = False, progress: Optional[Callable[[Progress], object]] = None, threads: int = 0) -> RunResult:
    """Runs a synthesis into the run directory ``out_dir``, as ``ppsynth synthesize CONFIG -o
    OUT_DIR``: the same files (output points, plots, snapshots, loss curve, config.json,
    run.json, metrics). ``out_dir`` must be new or empty, or hold a ppsynth run and
    ``force=True``. Ctrl-C stops it with a checkpoint in ``out_dir``: :func:`resume` continues.
    """
    spec = resolve_config(config, seed, overrides)
    return _run_result(_native.run(json.dumps(spec), os.fspath(out_dir), bool(quick), bool(force),
                                   _progress_hook(progress), int(threads)))


def resume(run_dir, progress: Optional[Callable[[Progress], object]] = None, threads: int = 0) -> RunResult:
    """Continues the interrupted run in ``run_dir`` from its checkpoint, as ``ppsynth
    synthesize --resume``; the outputs equal those of the run never interrupted (same thread
    count: ``threads`` as the run had, see its run.json). ``progress`` as in
    :func:`synthesize`; Ctrl-C stops it again with a new checkpoint. A directory without a
    checkpoint (finished, or stopped before its first) raises ValueError."""
    return _run_result(_native.resume(os.fspath(run_dir), _progress_hook(progress), int(threads)))
