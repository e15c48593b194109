"""Terms written in Python: a point term and a feature loss join the composite loss like
compiled parts, their gradients reach the optimizer (checked against finite differences and
against the compiled Gram loss), and they move the result the way they should."""
import os
import sys

import numpy as np
import pytest

torch = pytest.importorskip("torch")

import ppsynth
from conftest import GABOR, LINES, SOURCE_DIR


sys.path.insert(0, os.path.join(SOURCE_DIR, "docs", "examples"))
import python_terms  # noqa: E402  the example terms of docs/examples

ppsynth.register_point_term("py_repulsion", python_terms.repulsion, defaults={"h": 0.05})
ppsynth.register_loss("py_gram", python_terms.gram_loss, defaults={"weight": 0.08, "layers": [0, 1, 2]})


def closest_pair(points):
    p = points.positions
    d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(-1))
    d[np.diag_indices(len(p))] = np.inf
    return d.min()


def test_point_term_gradient_matches_finite_differences():
    rng = np.random.default_rng(0)
    moving, frozen = rng.random((12, 2)) * 0.2 + 0.4, rng.random((5, 2)) * 0.2 + 0.4
    v, g = ppsynth.point_term_value_and_grad("py_repulsion", moving, frozen, h=0.05)
    assert g.shape == (12, 2) and v > 0
    eps = 1e-6
    fd = np.zeros_like(moving)
    for i in range(12):
        for j in range(2):
            up, down = moving.copy(), moving.copy()
            up[i, j] += eps
            down[i, j] -= eps
            fd[i, j] = (ppsynth.point_term_value_and_grad("py_repulsion", up, frozen, h=0.05)[0]
                        - ppsynth.point_term_value_and_grad("py_repulsion", down, frozen, h=0.05)[0]) / (2 * eps)
    np.testing.assert_allclose(g, fd, rtol=1e-5, atol=1e-7)


def random_layers(seed, shape):
    """Three layers of output and of target features, standard normal."""
    rng = np.random.default_rng(seed)
    return [rng.standard_normal(shape) for _ in range(3)], [rng.standard_normal(shape) for _ in range(3)]


def test_python_gram_equals_the_compiled_gram_value_and_gradient():
    out, tgt = random_layers(1, (1, 4, 6, 6))
    v_py, g_py = ppsynth.loss_value_and_grad("py_gram", out, tgt)
    v_c, g_c = ppsynth.loss_value_and_grad("gram", out, tgt)
    assert v_py == pytest.approx(v_c, rel=1e-12)
    for a, b in zip(g_py, g_c):
        np.testing.assert_allclose(a, b, rtol=1e-10, atol=1e-14)


def test_loss_gradient_matches_finite_differences():
    out, tgt = random_layers(2, (1, 3, 5, 5))
    _, grads = ppsynth.loss_value_and_grad("py_gram", out, tgt)
    eps = 1e-6
    for layer, index in [(0, (0, 0, 0, 0)), (1, (0, 2, 3, 1)), (2, (0, 1, 4, 4)), (2, (0, 0, 2, 2))]:
        up = [o.copy() for o in out]
        down = [o.copy() for o in out]
        up[layer][index] += eps
        down[layer][index] -= eps
        fd = (ppsynth.loss_value_and_grad("py_gram", up, tgt)[0] - ppsynth.loss_value_and_grad("py_gram", down, tgt)[0]) / (2 * eps)
        assert grads[layer][index] == pytest.approx(fd, rel=1e-6, abs=1e-9)


def test_a_repulsion_term_raises_the_closest_pair_distance():
    base = {"evaluate": False}
    plain = ppsynth.synthesize(LINES, seed=5, quick=True, threads=1, overrides=base)
    pushed = ppsynth.synthesize(LINES, seed=5, quick=True, threads=1,
                                overrides={**base, "method.terms": {"py_repulsion": {"weight": 50.0, "h": 0.03}}})
    assert closest_pair(pushed.output) > 1.2 * closest_pair(plain.output)


def torus_gap(a, b):
    d = np.abs(a.positions - b.positions)
    return np.median(np.minimum(d, 1 - d))


def test_a_python_loss_joins_the_synthesis_like_the_compiled_one():
    # The paper's losses with the Gram part written in Python. Its value enters the loss: the
    # first iterations' losses equal the compiled run's. Its gradient reaches the optimizer:
    # the output stays near the compiled run's (Adam's first steps amplify float rounding, so
    # not bit-equal) and far from a run without a Gram part, which a value without a gradient
    # would have reproduced exactly.
    defaults = ppsynth.resolve_config({"exemplar": LINES})["method"]["losses"]
    swapped = [dict(l, type="py_gram") if l["type"] == "gram" else l for l in defaults]
    without = [l for l in defaults if l["type"] != "gram"]
    assert swapped != defaults and len(without) < len(defaults)
    args = dict(seed=5, quick=True, threads=1)
    compiled = ppsynth.synthesize(LINES, overrides={"evaluate": False}, **args)
    python = ppsynth.synthesize(LINES, overrides={"evaluate": False, "method.losses": swapped}, **args)
    none = ppsynth.synthesize(LINES, overrides={"evaluate": False, "method.losses": without}, **args)
    np.testing.assert_allclose(python.losses.loss[:3], compiled.losses.loss[:3], rtol=1e-6)
    assert torus_gap(python.output, compiled.output) < 0.4 * torus_gap(none.output, compiled.output)
    assert torus_gap(python.output, none.output) > 2 * torus_gap(python.output, compiled.output)


def test_registration_rules():
    with pytest.raises(ValueError, match="compiled-in part"):
        ppsynth.register_loss("gram", lambda o, t, p: o[0].sum())
    with pytest.raises(ValueError, match="letters, digits"):
        ppsynth.register_point_term("bad name", lambda m, f, p, s: m.sum())
    # Redefining a Python part is allowed (a notebook cell run twice).
    ppsynth.register_point_term("py_twice", lambda m, f, p, s: m.sum())
    ppsynth.register_point_term("py_twice", lambda m, f, p, s: 2 * m.sum())
    v, _ = ppsynth.point_term_value_and_grad("py_twice", np.full((2, 2), 0.5))
    assert v == pytest.approx(4.0)


def test_a_term_returning_garbage_is_reported():
    ppsynth.register_point_term("py_vector", lambda m, f, p, s: m)
    with pytest.raises(TypeError, match="point term 'py_vector' must return a scalar"):
        ppsynth.point_term_value_and_grad("py_vector", np.full((3, 2), 0.5))
