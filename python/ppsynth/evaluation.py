"""The evaluation suite of ``ppsynth eval``: an output against its exemplar."""
from __future__ import annotations

import keyword
import math
from typing import Any, Dict, Optional

import numpy as np

from . import _ppsynth as _native
from .points import PointSet, _as_points

__all__ = ["evaluate", "Evaluation", "Record"]


def _is_number(v) -> bool:
    return v is None or (isinstance(v, (int, float)) and not isinstance(v, bool))


def _numeric_array(values: list):
    """A list of numbers (None for an undefined value) or of such lists as one array, else None."""
    if not values:
        return None
    if all(_is_number(v) for v in values):
        if all(isinstance(v, int) for v in values):
            return np.asarray(values, dtype=np.int64)
        return np.asarray([math.nan if v is None else v for v in values], dtype=np.float64)
    if all(isinstance(v, list) for v in values):
        rows = [_numeric_array(v) for v in values]
        if all(r is not None and r.shape == rows[0].shape for r in rows):
            return np.stack(rows)
    return None


def _attribute(key: str) -> str:
    """The attribute for a JSON key: a Python keyword gets a trailing underscore (``class_``)."""
    return key + "_" if keyword.iskeyword(key) else key


def _wrap(v):
    if isinstance(v, dict):
        return Record(v)
    if isinstance(v, list):
        a = _numeric_array(v)
        return a if a is not None else [_wrap(x) for x in v]
    return v


def _unwrap(v):
    if isinstance(v, Record):
        return v.to_dict()
    if isinstance(v, np.ndarray):
        if v.dtype.kind == "f":
            return [_unwrap(x) for x in v] if v.ndim > 1 else [None if math.isnan(x) else float(x) for x in v]
        return v.tolist()
    if isinstance(v, list):
        return [_unwrap(x) for x in v]
    return v


class Record:
    """A read-only node of a result: its keys as attributes, its lists of numbers as NumPy arrays.

    A key that is a Python keyword is read with a trailing underscore (``row.pass_``,
    ``measures.class_``); ``to_dict()`` gives the plain nested dict back, with the original keys
    and lists (an undefined value, NaN in an array, as None), as ``ppsynth eval --json`` prints it.
    """

    __slots__ = ("_keys", "_values")

    def __init__(self, data: Dict[str, Any]):
        object.__setattr__(self, "_keys", list(data.keys()))
        object.__setattr__(self, "_values", {_attribute(k): _wrap(v) for k, v in data.items()})

    def __getattr__(self, name: str):
        if name.startswith("__") or name in Record.__slots__:  # copy, pickle: before __init__
            raise AttributeError(name)
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no '{name}' (it has: {', '.join(self._values)})") from None

    def __setattr__(self, name, value):
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __dir__(self):
        return list(self._values)

    def __contains__(self, name: str) -> bool:
        return _attribute(name) in self._values

    def __reduce__(self):
        return (type(self), (self.to_dict(),))

    def __eq__(self, other) -> bool:
        return isinstance(other, Record) and self.to_dict() == other.to_dict()

    def __repr__(self) -> str:
        def short(v):
            if isinstance(v, np.ndarray):
                return f"array{v.shape}"
            if isinstance(v, Record):
                return f"{type(v).__name__}(...)"
            if isinstance(v, list):
                return f"[{len(v)} items]"
            return repr(v)
        return f"{type(self).__name__}(" + ", ".join(f"{k}={short(v)}" for k, v in self._values.items()) + ")"

    def to_dict(self) -> Dict[str, Any]:
        """The plain nested dict (lists, numbers, strings), ready for ``json.dump``."""
        return {k: _unwrap(self._values[_attribute(k)]) for k in self._keys}


class Evaluation(Record):
    """What :func:`evaluate` returns: ``ppsynth eval --json`` as an object.

    Every key of that JSON is an attribute, nested objects are :class:`Record`\\ s and lists of
    numbers are NumPy arrays; ``to_dict()`` gives the JSON's dict back.

    Attributes
    ----------
    all : Record
        All classes together: ``pcf_mse``, ``wasserstein``, ``chamfer``,
        ``wasserstein_method``, ``exemplar_points`` and ``pcf`` (arrays ``r`` in r_max
        units, ``exemplar`` and ``output``); with the crops protocol also ``per_crop`` and
        the ``*_quartiles``.
    classes : list of Record
        The same per class, with ``class_`` (its index) and ``label``.
    cross : list of Record
        The cross-PCF of every class pair ``ci``, ``cj``: ``pcf_mse``, ``pcf``.
    exemplar, output : Record
        Each pattern's ``count``, ``class_counts``, closest pair ``d_min``, mean
        nearest-neighbor distance ``mean_nn``, ``relative_radius`` and
        ``border_fraction`` (share of points within 1 % of the shorter side of the border)
        beside ``border_fraction_uniform`` (uniform points' share).
    second_order : Record
        K, L and g of both patterns with spatstat's edge correction (``rows``: ``r``,
        ``exemplar.k`` ..., ``l_sup``), and the mark correlation of marked patterns; over 64
        classes no class-pair rows, and ``pairs_skipped`` says so. Absent with
        ``second_order=False``.
    verdict : Record
        The studentized permutation test of equal K-functions over sub-windows
        (docs/explanation/verdict.md): ``rows``, each with ``row`` (``"all"``, ``"class"``, ``"pair"``),
        ``p`` and ``pass_``; ``passed`` (True, False, or None when a row cannot be judged);
        ``alpha``, ``test``. Absent with ``verdict=False``.
    passed : bool or None
        The verdict's ``passed``: None when it cannot judge a row or was left out.
    protocol : Record
        Quadrants or crops, and why (``name``, ``reason``, ``zoom``, ``windows``).
    options : Record
        The PCF's settings.
    overlap : Record
        Disk patterns only: the overlap of the output's disks.
    spectrum : Record
        With ``spectrum=True``: the radially averaged power spectra and their peak ratios.
    """

    __slots__ = ()

    @property
    def passed(self) -> Optional[bool]:
        """The verdict's own answer (its ``passed``): True when every row passed, False when a
        row failed, None when the verdict cannot judge a row (a row that cannot be judged is
        never counted as a pass) or was left out (``verdict=False``)."""
        return self.verdict.passed if "verdict" in self else None


def evaluate(exemplar, output, bins: int = 100, r_max: float = 0.0, periodic_pcf: bool = False,
             curves: bool = True, spectrum: bool = False,
             wasserstein_exact_limit: int = _native.WASSERSTEIN_EXACT_PAIRS,
             protocol: str = "auto", crops: int = 20, crop_seed: int = 1, zoom: float = 0.0,
             second_order: bool = True, verdict: bool = True,
             verdict_split: int = _native.VERDICT_DEFAULTS["split"],
             verdict_guard: float = _native.VERDICT_DEFAULTS["guard"],
             verdict_permutations: int = _native.VERDICT_DEFAULTS["permutations"],
             verdict_seed: int = _native.VERDICT_DEFAULTS["seed"],
             verdict_alpha: float = _native.VERDICT_DEFAULTS["alpha"]) -> Evaluation:
    """Metrics of an output against its exemplar: the numbers of ``ppsynth eval --json``.

    Parameters
    ----------
    exemplar, output : PointSet, array_like of shape (N, 2), or str
        The two patterns (or point files' names).
    bins : int
        PCF bins, 2..10000.
    r_max : float
        The PCF's range; 0 derives it from the exemplar's count.
    periodic_pcf : bool
        Measure the PCF on the torus.
    curves : bool
        Keep the PCF curves (``pcf``) in the result.
    spectrum : bool
        Add the 2-D power spectrum's summary (``spectrum``).
    wasserstein_exact_limit : int
        Pairs per region up to which the Wasserstein distance is the exact assignment.
    protocol : str
        ``"quadrants"`` (the paper's: the output's four quadrants against the exemplar),
        ``"crops"`` (``crops`` random exemplar-sized crops placed from ``crop_seed``, for
        outputs of other sizes and shapes; rows then carry ``per_crop`` values and
        ``pcf_mse_quartiles``), or ``"auto"`` (quadrants for a square output holding 3-5
        times the exemplar's points, else crops; ``protocol.name`` in the result says which).
    crops, crop_seed : int
        How many crops, and their seed.
    zoom : float
        Output units per exemplar unit, the crops' scale; 0 reads it from the two densities.
    second_order : bool
        Add spatstat's K, L, g and the mark correlations (``second_order``; ``eval
        --no-second-order`` is False).
    verdict : bool
        Add the verdict (``verdict``, ``passed``; ``eval --no-verdict`` is False).
    verdict_split, verdict_guard, verdict_permutations, verdict_seed, verdict_alpha
        The verdict's options, as ``eval --verdict-split`` ... take them: the exemplar in
        split x split sub-windows, the share of a sub-window cell left out between them, the
        random reassignments, their seed, and the p-value a row passes from.

    Returns
    -------
    Evaluation
        E.g. ``e.all.pcf_mse``, ``e.classes[1].wasserstein``, ``e.all.pcf.output`` (an
        array), ``e.verdict.rows[0].p``, ``e.passed``; ``e.to_dict()`` is the JSON's dict.

    Raises
    ------
    ValueError
        Bad input or an impossible option, naming it.
    KeyboardInterrupt
        Ctrl-C while it works (it stops within a fraction of a second).
    """
    for name, seed in (("crop_seed", crop_seed), ("verdict_seed", verdict_seed)):
        if not 0 <= int(seed) < 2 ** 63:  # the C++ side takes unsigned 64-bit seeds; a negative one would wrap
            raise ValueError(f"{name} must be in 0..2^63-1, got {seed}")
    ex = _as_points(exemplar, "exemplar")
    out = _as_points(output, "output")
    return Evaluation(_native.evaluate(ex._to_native(), out._to_native(), int(bins), float(r_max), bool(periodic_pcf),
                                       bool(curves), bool(spectrum), int(wasserstein_exact_limit), str(protocol),
                                       int(crops), int(crop_seed), float(zoom), bool(second_order), bool(verdict),
                                       int(verdict_split), float(verdict_guard), int(verdict_permutations),
                                       int(verdict_seed), float(verdict_alpha)))
