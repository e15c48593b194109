"""The evaluation suite of ``ppsynth eval``: an output against its exemplar."""
from __future__ import annotations

import json

import numpy as np

from . import _ppsynth as _native
from .points import PointSet, _as_points

__all__ = ["evaluate"]


def _arrays(node):
    """Lists of numbers under "pcf" and "spectrum" become NumPy arrays."""
    if isinstance(node, dict):
        out = {}
        for k, v in node.items():
            if k in ("pcf", "spectrum") and isinstance(v, dict):
                out[k] = {kk: np.asarray(vv, dtype=np.float64) if isinstance(vv, list) else vv for kk, vv in v.items()}
            else:
                out[k] = _arrays(v)
        return out
    if isinstance(node, list):
        return [_arrays(v) for v in node]
    return node


def evaluate(exemplar, output, bins: int = 100, r_max: float = 0.0, periodic_pcf: bool = False,
             curves: bool = True, spectrum: bool = False,
             wasserstein_exact_limit: int = _native.WASSERSTEIN_EXACT_PAIRS,
             protocol: str = "auto", crops: int = 20, crop_seed: int = 1, zoom: float = 0.0) -> dict:
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
        Keep the PCF curves (``"pcf"``) in the result.
    spectrum : bool
        Add the 2-D power spectrum's summary (``"spectrum"``).
    wasserstein_exact_limit : int
        Pairs per region up to which the Wasserstein distance is the exact assignment.
    protocol : str
        ``"quadrants"`` (the paper's: the output's four quadrants against the exemplar),
        ``"crops"`` (``crops`` random exemplar-sized crops placed from ``crop_seed``, for
        outputs of other sizes and shapes; rows then carry ``per_crop`` values and
        ``pcf_mse_quartiles``), or ``"auto"`` (quadrants for a square output holding 3-5
        times the exemplar's points, else crops; ``"protocol"`` in the result says which).
    crops, crop_seed : int
        How many crops, and their seed.
    zoom : float
        Output units per exemplar unit, the crops' scale; 0 reads it from the two densities.

    Returns
    -------
    dict
        - ``"all"``: all classes together: ``pcf_mse``, ``wasserstein``, ``chamfer`` and
          ``pcf`` with NumPy arrays ``r`` (in r_max units), ``exemplar`` and ``output``;
        - ``"classes"``: the same per class; ``"cross"``: the cross-PCF of every class pair;
        - ``"exemplar"``, ``"output"``: counts, closest pair ``d_min``, mean
          nearest-neighbour distance, ``border_fraction`` (share of points within 1 % of the
          shorter side of the border) and ``border_fraction_uniform`` (uniform points' share);
        - ``"second_order"``: the K, L, G and F summaries with their spatstat corrections;
        - ``"verdict"``: a studentized permutation test of equal K-functions over
          sub-windows (docs/verdict.md);
        - ``"overlap"`` (disk patterns), ``"spectrum"`` (``spectrum=True``), ``"options"``.

    Raises
    ------
    ValueError
        Bad input or an impossible option, naming it.
    """
    ex = _as_points(exemplar, "exemplar")
    out = _as_points(output, "output")
    text = _native.evaluate_json(ex._to_native(), out._to_native(), int(bins), float(r_max), bool(periodic_pcf),
                                 bool(curves), bool(spectrum), int(wasserstein_exact_limit), str(protocol), int(crops),
                                 int(crop_seed), float(zoom))
    return _arrays(json.loads(text))
