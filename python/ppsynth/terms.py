"""Loss terms written in Python, registered by name beside the compiled ones.

Two kinds, each a function of ``torch.Tensor``\\ s that returns a scalar tensor; its gradient
(``torch.autograd``) flows into the optimizer with the rest of the loss:

- a **loss** on the feature maps of the random-filter network (the paper's losses are of this
  kind): ``fn(output, target, params)``, where ``output`` and ``target`` are lists with one
  ``1 x C x H x W`` tensor per layer in ``params["layers"]`` (indices into the network's
  blocks), for the output and for the exemplar. Switched on in a config by
  ``"method": {"losses": [..., {"type": NAME, "weight": w, "layers": [2]}]}``.
- a **point term** on the moving positions of a class stage: ``fn(moving, frozen, params,
  stage)``, ``moving`` (n, 2) the wrapped positions that move, ``frozen`` (m, 2) the others,
  ``stage`` a :class:`ClassStage` (exemplar, output, indices, u). Switched on by
  ``"method": {"terms": {NAME: {"weight": w}}}``; the synthesizer adds weight x (the paper's
  loss at the stage's first evaluation) x term.

``params`` is the term's config entry merged with its ``defaults``. Registering a name again
redefines it (a notebook cell run twice); compiled-in names cannot be taken. Needs PyTorch
(Debian's python3-torch, the same LibTorch as ppsynth): tensors cross without copies.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional

import numpy as np

from . import _ppsynth as _native
from .points import PointSet

__all__ = ["register_loss", "register_point_term", "ClassStage", "point_term_value_and_grad", "loss_value_and_grad"]


def _torch():
    try:
        import torch
        import torch.utils.dlpack  # noqa: F401
    except ImportError as e:
        raise ImportError("terms written in Python need PyTorch (Debian: apt install python3-torch)") from e
    return torch


@dataclass
class ClassStage:
    """The class stage a point term is evaluated in.

    Attributes
    ----------
    exemplar : PointSet
        The exemplar.
    output : PointSet
        Every point of the output, positions as the stage starts.
    moving : numpy.ndarray of int
        Indices into ``output`` of the points that move (one class).
    frozen : numpy.ndarray of int
        Indices of the frozen ones.
    upscale : int
        u: the output has u^2 times the exemplar's points.
    """
    exemplar: PointSet
    output: PointSet
    moving: np.ndarray
    frozen: np.ndarray
    upscale: int


def _scalar(torch, v, kind: str, name: str):
    if not isinstance(v, torch.Tensor) or v.numel() != 1:
        raise TypeError(f"{kind} '{name}' must return a scalar torch.Tensor, not {type(v).__name__}"
                        + (f" of shape {tuple(v.shape)}" if isinstance(v, torch.Tensor) else ""))
    return v.reshape(())


def _gradients(torch, v, xs):
    if not v.requires_grad:
        return [torch.zeros_like(x) for x in xs]
    gs = torch.autograd.grad(v, xs, allow_unused=True)
    return [torch.zeros_like(x) if g is None else g for g, x in zip(gs, xs)]


def _loss_glue(name: str, fn: Callable):
    torch = _torch()
    from_dlpack, to_dlpack = torch.utils.dlpack.from_dlpack, torch.utils.dlpack.to_dlpack

    def glue(params, output_caps, target_caps):
        with torch.enable_grad():
            xs = [from_dlpack(c).requires_grad_(True) for c in output_caps]
            ts = [from_dlpack(c) for c in target_caps]
            v = _scalar(torch, fn(xs, ts, params), "loss", name)
            gs = _gradients(torch, v, xs)
        return float(v.detach()), [to_dlpack(g) for g in gs]

    return glue


def _point_term_glue(name: str, fn: Callable):
    torch = _torch()
    from_dlpack, to_dlpack = torch.utils.dlpack.from_dlpack, torch.utils.dlpack.to_dlpack
    last = {"native": None, "stage": None}  # the stage of the class being synthesized

    def glue(params, moving_caps, frozen_cap, stage):
        if last["native"] is not stage:
            last["native"] = stage
            last["stage"] = ClassStage(PointSet._from_native(stage["exemplar"]), PointSet._from_native(stage["output"]),
                                       np.asarray(stage["moving"], dtype=np.int64),
                                       np.asarray(stage["frozen"], dtype=np.int64), int(stage["upscale"]))
        with torch.enable_grad():
            x = from_dlpack(moving_caps[0]).requires_grad_(True)
            f = from_dlpack(frozen_cap)
            v = _scalar(torch, fn(x, f, params, last["stage"]), "point term", name)
            gs = _gradients(torch, v, [x])
        return float(v.detach()), [to_dlpack(g) for g in gs]

    return glue


def _register(native_register, make_glue, name: str, fn: Optional[Callable], defaults, description: str):
    def do(f):
        if not callable(f):
            raise TypeError(f"'{name}': expected a callable")
        native_register(name, make_glue(name, f), dict(defaults or {}), description or (f.__doc__ or "").strip())
        return f
    return do if fn is None else do(fn)


def register_loss(name: str, fn: Optional[Callable] = None, *, defaults: Optional[dict] = None, description: str = ""):
    """Registers a feature loss written with torch under a config name.

    Parameters
    ----------
    name : str
        The name a config's ``method.losses[i].type`` uses.
    fn : callable, optional
        ``fn(output, target, params) -> scalar tensor``: ``output`` and ``target`` are lists
        of the chosen layers' features (1 x C x H x W tensors), ``params`` the resolved
        parameters. Omitted: returns a decorator.
    defaults : dict, optional
        Parameters beyond the ones every loss takes, ``weight`` (default 1) and ``layers``
        (default [0, 1, 2]), or new defaults for those.
    description : str
        One line for ``ppsynth config --defaults``.

    Returns
    -------
    callable
        ``fn``, or the decorator.

    Examples
    --------
    Usable as a decorator::

        @ppsynth.register_loss("mean_match", defaults={"layers": [2]})
        def mean_match(output, target, params):
            return sum(((o.mean((2, 3)) - t.mean((2, 3))) ** 2).sum() for o, t in zip(output, target))
    """
    return _register(_native.register_loss, _loss_glue, name, fn, defaults, description)


def register_point_term(name: str, fn: Optional[Callable] = None, *, defaults: Optional[dict] = None,
                        description: str = ""):
    """Registers a point term written with torch under a config name.

    Parameters
    ----------
    name : str
        The name a config's ``method.terms`` uses.
    fn : callable, optional
        ``fn(moving, frozen, params, stage) -> scalar tensor``: ``moving`` (n, 2) and
        ``frozen`` (m, 2) positions, the resolved ``params``, the :class:`ClassStage`.
        Omitted: returns a decorator.
    defaults : dict, optional
        Its parameters; ``weight`` defaults to 0, so the term is off until a config sets it.
    description : str
        As in :func:`register_loss`.

    Returns
    -------
    callable
        As :func:`register_loss` returns.

    Examples
    --------
    ::

        @ppsynth.register_point_term("repulsion", defaults={"h": 0.02})
        def repulsion(moving, frozen, params, stage):
            d2 = torch.cdist(moving, moving).pow(2)
            return torch.exp(-d2 / params["h"] ** 2).triu(1).sum()
    """
    return _register(_native.register_point_term, _point_term_glue, name, fn, defaults, description)


def point_term_value_and_grad(name: str, moving, frozen=None, stage: Optional[ClassStage] = None, **params):
    """A point term's value and gradient, through the path a synthesis takes.

    For checking a term (compiled or Python), e.g. against finite differences.

    Parameters
    ----------
    name : str
        The term's registered name.
    moving : array_like, shape (n, 2)
        The moving points.
    frozen : array_like, shape (m, 2), optional
        The frozen points.
    stage : ClassStage, optional
        Default: one class, whose exemplar is ``moving`` itself, at u = 1.
    **params
        The term's parameters.

    Returns
    -------
    value : float
    gradient : numpy.ndarray, shape (n, 2)
    """
    torch = _torch()
    to_dlpack = torch.utils.dlpack.to_dlpack
    moving = np.ascontiguousarray(moving, dtype=np.float64)
    frozen = np.zeros((0, 2)) if frozen is None else np.ascontiguousarray(frozen, dtype=np.float64)
    if stage is None:
        ps = PointSet(np.concatenate([moving, frozen]))
        stage = ClassStage(ps, ps, np.arange(len(moving)), np.arange(len(moving), len(ps)), 1)
    v, g = _native.point_term_value_and_grad({"type": name, **params}, stage.exemplar._to_native(), stage.output._to_native(),
                                             [int(i) for i in stage.moving], [int(i) for i in stage.frozen],
                                             int(stage.upscale), to_dlpack(torch.from_numpy(moving.copy())),
                                             to_dlpack(torch.from_numpy(frozen.copy())))
    return v, torch.utils.dlpack.from_dlpack(g).numpy().copy()


def loss_value_and_grad(name: str, output, target, **params):
    """A feature loss's value and gradient, through the path a synthesis takes.

    Parameters
    ----------
    name : str
        The loss's registered name (compiled or Python).
    output, target : list of array_like or torch.Tensor
        One 1 x C x H x W array per layer.
    **params
        The loss's parameters.

    Returns
    -------
    value : float
    gradients : list of numpy.ndarray or None
        The gradient for each output layer (None for a layer the loss does not read).
    """
    torch = _torch()
    to_dlpack = torch.utils.dlpack.to_dlpack
    caps = [to_dlpack(torch.as_tensor(np.asarray(o)).contiguous().clone()) for o in output]
    tcaps = [to_dlpack(torch.as_tensor(np.asarray(t)).contiguous().clone()) for t in target]
    v, gs = _native.loss_value_and_grad({"type": name, **params}, caps, tcaps)
    return v, [None if g is None else torch.utils.dlpack.from_dlpack(g).numpy().copy() for g in gs]
