"""evaluate() returns the numbers of `ppsynth eval --json`, with NumPy curves."""
import json

import numpy as np
import pytest

import ppsynth
from conftest import GABOR, command


def as_lists(node):
    if isinstance(node, dict):
        return {k: as_lists(v) for k, v in node.items()}
    if isinstance(node, list):
        return [as_lists(v) for v in node]
    if isinstance(node, np.ndarray):
        return node.tolist()
    return node


@pytest.mark.parametrize("name", ["poisson_n64c2_disk", "lines"])
def test_evaluate_equals_eval_json(tmp_path, name):
    ex = ppsynth.read(GABOR + f"{name}.txt")
    rng = np.random.default_rng(5)
    n = 4 * len(ex)
    out = ppsynth.PointSet(rng.random((n, 2)), np.repeat(ex.classes, 4), np.repeat(ex.attributes, 4, axis=0),
                           ex.attribute_names, class_labels=ex.class_labels)
    ppsynth.write(out, tmp_path / "out.txt")
    r = ppsynth.evaluate(ex, out, bins=40)
    assert isinstance(r["all"]["pcf"]["output"], np.ndarray) and r["all"]["pcf"]["output"].shape == (40,)
    _, text, _ = command("eval", "--exemplar", GABOR + f"{name}.txt", "--output", tmp_path / "out.txt", "--json",
                         "--bins", 40)
    expected = json.loads(text)
    del expected["exemplar"]["path"], expected["output"]["path"]
    assert as_lists(r) == expected


def test_evaluate_refuses_impossible_options():
    ex = ppsynth.read(GABOR + "lines.txt")
    with pytest.raises(ValueError, match=r"bins \(--bins\) must be in 2..10000"):
        ppsynth.evaluate(ex, ex, bins=1)
    with pytest.raises(ValueError, match="r_max"):
        ppsynth.evaluate(ex, ex, r_max=float("nan"))


def test_evaluate_crops_equals_eval_json_on_a_rectangle(tmp_path):
    # A 4 x 1 strip in exemplar units (as `synthesize --size 4 1` makes): exemplar-sized crops.
    ex = ppsynth.read(GABOR + "lines.txt")
    rng = np.random.default_rng(6)
    out = ppsynth.PointSet(rng.random((80, 2)) * [4.0, 1.0], domain=(0, 0, 4, 1))
    ppsynth.write(out, tmp_path / "strip.txt")
    r = ppsynth.evaluate(ex, out, bins=40, protocol="crops", crops=7, crop_seed=3)
    assert r["protocol"]["name"] == "crops" and r["protocol"]["patches"] == 7
    _, text, _ = command("eval", "--exemplar", GABOR + "lines.txt", "--output", tmp_path / "strip.txt", "--json",
                         "--bins", 40, "--protocol", "crops", "--crops", 7, "--crop-seed", 3)
    expected = json.loads(text)
    del expected["exemplar"]["path"], expected["output"]["path"]
    assert as_lists(r) == expected
    with pytest.raises(ValueError, match="protocol"):
        ppsynth.evaluate(ex, out, protocol="halves")
    # zoom: the crops' scale as the run made the output, as `eval --zoom` takes it; 0 reads it
    # from the densities (20 exemplar points per unit against 100 over 4 units: 0.89).
    dense = ppsynth.PointSet(rng.random((100, 2)) * [4.0, 1.0], domain=(0, 0, 4, 1))
    assert ppsynth.evaluate(ex, dense, bins=40, protocol="crops", zoom=1.0)["protocol"]["zoom"] == 1.0
    assert ppsynth.evaluate(ex, dense, bins=40, protocol="crops")["protocol"]["zoom"] == pytest.approx((80 / 100) ** 0.5)
    with pytest.raises(ValueError, match="zoom"):
        ppsynth.evaluate(ex, dense, protocol="crops", zoom=-1.0)
