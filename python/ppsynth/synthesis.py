"""Synthesis: an exemplar in, a larger pattern out.

:func:`synthesize` runs in memory and returns a :class:`Result`; :func:`run` and
:func:`resume` write a run directory, exactly as ``ppsynth synthesize`` does. All three run the
library of the command (same config, same seed and thread count: the same points, bit for
bit), release the GIL while they work, and stop on Ctrl-C at the end of the current iteration
after writing a checkpoint, raising KeyboardInterrupt.
"""
from __future__ import annotations

import csv
import json
import numbers
import os
from dataclasses import dataclass, field
from typing import Callable, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _ppsynth as _native
from .evaluation import Evaluation
from .points import PointSet, _as_points

__all__ = ["synthesize", "run", "resume", "resolve_config", "Result", "Stage", "Losses", "Progress"]


@dataclass(frozen=True)
class Progress:
    """What a ``progress`` callable receives at every iteration.

    Attributes
    ----------
    stage : str
        The stage's name, e.g. ``"class 1/2, sigma 3/4"``.
    stage_index : int
        The stage, 0-based over the whole run.
    stage_count : int
        How many stages the run has.
    iteration : int
        The iteration within the stage.
    max_iterations : int
        The stage's cap on iterations (0: unknown).
    loss : float
        The loss at this iteration.
    seconds : float
        Seconds since the stage began.
    """
    stage: str
    stage_index: int
    stage_count: int
    iteration: int
    max_iterations: int
    loss: float
    seconds: float


@dataclass(frozen=True)
class Stage:
    """One stage of a run (a class and a sigma of the Gabor method).

    Attributes
    ----------
    stage : str
        The stage's name, as in :class:`Progress`.
    iterations : int
        Iterations it ran.
    final_loss : float
        Its loss at the end.
    seconds : float
        Its wall time.
    details : dict
        What the method and the stage's kind recorded of it: the class, sigma and number of
        neighbors of a Gabor stage; a border relax's ``parked_over_uniform`` and ``relaxed``;
        under the pattern stopping rule, ``stopping_rule`` (each check's PCF MSE and the
        iteration the stage ended on, -1 for its start).
    """
    stage: str
    iterations: int
    final_loss: float
    seconds: float
    details: dict = field(default_factory=dict)


@dataclass
class Losses:
    """Every iteration's loss, as parallel arrays with one entry per iteration.

    Attributes
    ----------
    stage_index : numpy.ndarray of int64
        The stage of each iteration (0-based).
    stage : list of str
        The stage's name for each iteration.
    iteration : numpy.ndarray of int64
        The iteration within its stage.
    loss : numpy.ndarray of float64
        The loss.
    seconds : numpy.ndarray of float64
        Seconds since the stage began.
    """
    stage_index: np.ndarray
    stage: List[str]
    iteration: np.ndarray
    loss: np.ndarray
    seconds: np.ndarray


@dataclass
class Result:
    """What :func:`synthesize`, :func:`run` and :func:`resume` return.

    Attributes
    ----------
    output : PointSet
        The synthesized pattern, in the unit square, with classes and attributes.
    initialization : PointSet
        The output before optimization.
    exemplar : PointSet
        The exemplar the synthesis read.
    stages : list of Stage
        Each stage that ran.
    losses : Losses
        Every iteration's loss.
    stats : dict
        The rest the method measured: grids, sigmas, phase times, the resolved parts (the
        stages are in ``stages``).
    metrics : Evaluation or None
        ``evaluate(exemplar, output)`` when the config's ``"evaluate"`` is on, else None.
    seconds : float
        Wall time of the synthesis (for a resumed run, of the whole run).
    cpu_seconds : float or None
        CPU time of the synthesis, all threads (for a resumed run, of the whole run): unlike
        ``seconds`` it does not grow when other work shares the cores. None when not known
        (resumed from a checkpoint written before CPU time was kept).
    threads : int
        LibTorch's thread count: the output depends on it in the last bits.
    processor : str
        ``"MODEL (ISA)"``: the output depends on the instruction set too.
    config : dict
        The resolved config.
    resumed : bool
        Whether the synthesis continued from a checkpoint.
    dir : str or None
        The run directory (:func:`run`, :func:`resume`); None for :func:`synthesize`.
    """
    output: PointSet
    initialization: PointSet
    exemplar: PointSet
    stages: List[Stage]
    losses: Losses
    stats: dict
    metrics: Optional[Evaluation]
    seconds: float
    cpu_seconds: Optional[float]
    threads: int
    processor: str
    config: dict
    resumed: bool
    dir: Optional[str] = None


ConfigLike = Union[None, str, os.PathLike, Mapping]
Overrides = Union[None, Mapping[str, object], Sequence[str]]


def _split_overrides(overrides: Overrides):
    """(the command's ``--set`` strings, a dict of key paths to values)."""
    if overrides is None:
        return [], {}
    if isinstance(overrides, Mapping):
        for k in overrides:
            if not isinstance(k, str):
                raise TypeError(f"overrides: the key {k!r} is not a 'key.path' string")
        return [], dict(overrides)
    if isinstance(overrides, str):
        raise TypeError("overrides: expected a dict {'key.path': value} or a list of 'key.path=value' strings")
    return [str(o) for o in overrides], {}


def resolve_config(config: ConfigLike = None, seed: Optional[int] = None, overrides: Overrides = None) -> dict:
    """The config a run uses, merged with every default.

    Parameters
    ----------
    config : None, dict, str or os.PathLike
        None for the paper's defaults, a dict, or a JSON file (with its ``parent`` chain).
    seed : int, optional
        The run's seed, an integer in [0, 2^63).
    overrides : dict or list of str, optional
        ``{"method.max_iterations": 50}`` or ``["method.max_iterations=50"]``: the command's
        ``--set``.

    Returns
    -------
    dict
        The resolved config, as ``ppsynth synthesize`` writes it into config.json.

    Raises
    ------
    ValueError
        An unknown key or an impossible value; the message names the key path.
    TypeError
        A seed that is a float or a string, or a config of another type.
    """
    if config is None:
        c = {}
    elif isinstance(config, (str, os.PathLike)):
        c = _native.load_config(os.fspath(config))
    elif isinstance(config, Mapping):
        c = dict(config)  # only "seed" is set here; the binding copies the rest as it converts it
    else:
        raise TypeError(f"config: expected None, a dict or a file name, not {type(config).__name__}")
    if seed is not None:
        # Strictly an integer (NumPy's too): int() would truncate 5.7 and parse "95".
        if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
            raise TypeError(f"seed: expected an integer in [0, 2^63), not {type(seed).__name__}")
        c["seed"] = int(seed)
    assignments, values = _split_overrides(overrides)
    return _native.resolve_config(c, assignments, values)


def _progress_hook(progress: Optional[Callable[[Progress], object]]):
    if progress is None:
        return None
    if not callable(progress):
        raise TypeError("progress: expected a callable taking a ppsynth.Progress")
    return lambda event: progress(Progress(**event))


def _evaluation_or_none(metrics: Optional[dict]) -> Optional[Evaluation]:
    return None if metrics is None else Evaluation(metrics)


def synthesize(exemplar=None, config: ConfigLike = None, seed: Optional[int] = None, overrides: Overrides = None,
               progress: Optional[Callable[[Progress], object]] = None, checkpoint_dir=None, quick: bool = False,
               initialization=None, threads: int = 0) -> Result:
    """Synthesizes a larger pattern from an exemplar, in memory.

    The same config, seed and thread count give the same output as ``ppsynth synthesize``.

    Parameters
    ----------
    exemplar : PointSet, array_like of shape (N, 2), str or None
        The exemplar, or a point file's name; None takes the config's ``"exemplar"``.
    config, seed, overrides
        As :func:`resolve_config`. None: the paper's method with the published settings,
        seed 95, u = 2 (4 x the exemplar's points).
    progress : callable, optional
        ``progress(p: Progress)``, called at every iteration. An exception it raises stops
        the run (after its checkpoint) and is raised here.
    checkpoint_dir : str or os.PathLike, optional
        Where this synthesis keeps its checkpoint (at every stage and every
        ``checkpoint_seconds``). After an interruption the same call continues from it and
        returns what an uninterrupted run returns; a finished run removes it. A directory
        holding files this synthesis did not write is refused.
    quick : bool
        Tiny grids and few iterations (tests).
    initialization : PointSet or array_like, optional
        An explicit initial output.
    threads : int
        LibTorch's thread count; 0: every core, or ``PPSYNTH_THREADS``.

    Returns
    -------
    Result
        With ``dir`` None.

    Raises
    ------
    ValueError
        Bad input, with the command's message (``FileNotFoundError`` for a missing file).
    KeyboardInterrupt
        Ctrl-C: the run stops at the end of the current iteration, after its checkpoint.
    """
    spec = resolve_config(config, seed, overrides)
    if exemplar is None:
        ex = PointSet._from_native(_native.load_exemplar(spec))
    else:
        ex = _as_points(exemplar, "exemplar")
    init = None if initialization is None else _as_points(initialization, "initialization")._to_native()
    r = _native.synthesize(ex._to_native(), spec, bool(quick), init, _progress_hook(progress),
                           "" if checkpoint_dir is None else os.fspath(checkpoint_dir), int(threads))
    return Result(PointSet._from_native(r["output"]), PointSet._from_native(r["initialization"]), ex,
                  [Stage(**st) for st in r["stages"]], _losses(r["losses"]), r["stats"],
                  _evaluation_or_none(r["metrics"]), r["seconds"], _cpu_or_none(r["cpu_seconds"]), r["threads"],
                  r["processor"], spec, r["resumed"])


def _cpu_or_none(cpu_seconds: float) -> Optional[float]:
    """The native layer's CPU time: 0 means not recorded (a resume from an older checkpoint)."""
    return cpu_seconds if cpu_seconds > 0 else None


def _losses(rows) -> Losses:
    return Losses(np.array([x[0] for x in rows], dtype=np.int64), [x[1] for x in rows],
                  np.array([x[2] for x in rows], dtype=np.int64), np.array([x[3] for x in rows], dtype=np.float64),
                  np.array([x[4] for x in rows], dtype=np.float64))


def _losses_of_run(run_dir: str) -> Losses:
    """The run directory's loss.csv (a method without per-iteration losses has none)."""
    path = os.path.join(run_dir, "loss.csv")
    rows = []
    if os.path.exists(path):
        with open(path, newline="") as f:
            for rec in csv.DictReader(f):
                rows.append((int(rec["stage_index"]), rec["stage"], int(rec["iteration"]), float(rec["loss"]),
                             float(rec["seconds"])))
    return _losses(rows)


def _run_result(r: dict, resumed: bool) -> Result:
    """A run directory's Result: what the native call returned, and its run.json and loss.csv."""
    with open(os.path.join(r["dir"], "run.json")) as f:
        record = json.load(f)
    return Result(PointSet._from_native(r["output"]), PointSet._from_native(r["initialization"]),
                  PointSet._from_native(r["exemplar"]), [Stage(**st) for st in r["stages"]], _losses_of_run(r["dir"]),
                  r["stats"],
                  _evaluation_or_none(r["metrics"]), r["seconds"], _cpu_or_none(r["cpu_seconds"]),
                  int(record.get("threads", 0)),
                  str(record.get("processor", "")), r["config"], resumed, r["dir"])


def run(config: ConfigLike, out_dir, seed: Optional[int] = None, overrides: Overrides = None, quick: bool = False,
        force: bool = False, progress: Optional[Callable[[Progress], object]] = None, threads: int = 0) -> Result:
    """Runs a synthesis into a run directory, as ``ppsynth synthesize CONFIG -o OUT_DIR``.

    The directory gets the command's files: output points, plots, snapshots, loss curve,
    config.json, run.json and metrics.

    Parameters
    ----------
    config, seed, overrides
        As :func:`resolve_config`; the config names its exemplar.
    out_dir : str or os.PathLike
        The run directory: new or empty, or holding a ppsynth run and ``force=True``.
    quick : bool
        Tiny grids and few iterations (tests).
    force : bool
        Replace the run that ``out_dir`` holds (never anything else).
    progress : callable, optional
        As in :func:`synthesize`.
    threads : int
        As in :func:`synthesize`.

    Returns
    -------
    Result
        With ``dir`` the run directory.

    Raises
    ------
    ValueError
        Bad input, or an ``out_dir`` that holds something else.
    KeyboardInterrupt
        Ctrl-C: the run stops with a checkpoint in ``out_dir``; :func:`resume` continues it.
    """
    spec = resolve_config(config, seed, overrides)
    return _run_result(_native.run(spec, os.fspath(out_dir), bool(quick), bool(force),
                                   _progress_hook(progress), int(threads)), False)


def resume(run_dir, progress: Optional[Callable[[Progress], object]] = None, threads: int = 0) -> Result:
    """Continues an interrupted run from its checkpoint, as ``ppsynth synthesize --resume``.

    The outputs equal those of the run never interrupted, given the same thread count as the
    run had (its run.json says which).

    Parameters
    ----------
    run_dir : str or os.PathLike
        The interrupted run's directory.
    progress : callable, optional
        As in :func:`synthesize`; Ctrl-C stops it again with a new checkpoint.
    threads : int
        As in :func:`synthesize`.

    Returns
    -------
    Result
        With ``dir`` the run directory and ``resumed`` True.

    Raises
    ------
    ValueError
        A directory without a checkpoint (finished, or stopped before its first), or one whose
        checkpoint fails its checks.
    """
    return _run_result(_native.resume(os.fspath(run_dir), _progress_hook(progress), int(threads)), True)
