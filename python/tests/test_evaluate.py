"""evaluate() returns the numbers of `ppsynth eval --json` as an object with NumPy curves."""
import copy
import json
import pickle

import numpy as np
import pytest

import ppsynth
from conftest import GABOR, command


@pytest.mark.parametrize("name", ["poisson_n64c2_disk", "lines"])
def test_evaluate_equals_eval_json(tmp_path, name):
    ex = ppsynth.read(GABOR + f"{name}.txt")
    rng = np.random.default_rng(5)
    n = 4 * len(ex)
    out = ppsynth.PointSet(rng.random((n, 2)), np.repeat(ex.classes, 4), np.repeat(ex.attributes, 4, axis=0),
                           ex.attribute_names, class_labels=ex.class_labels)
    ppsynth.write(out, tmp_path / "out.txt")
    r = ppsynth.evaluate(ex, out, bins=40)
    assert isinstance(r, ppsynth.Evaluation)
    assert isinstance(r.all.pcf.output, np.ndarray) and r.all.pcf.output.shape == (40,)
    assert r.all.pcf_mse >= 0 and r.all.exemplar_points == len(ex)
    _, text, _ = command("eval", "--exemplar", GABOR + f"{name}.txt", "--output", tmp_path / "out.txt", "--json",
                         "--bins", 40)
    expected = json.loads(text)
    del expected["exemplar"]["path"], expected["output"]["path"]
    assert r.to_dict() == expected


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
    assert r.protocol.name == "crops" and r.protocol.patches == 7
    assert r.all.per_crop.pcf_mse.shape == (7,)
    _, text, _ = command("eval", "--exemplar", GABOR + "lines.txt", "--output", tmp_path / "strip.txt", "--json",
                         "--bins", 40, "--protocol", "crops", "--crops", 7, "--crop-seed", 3)
    expected = json.loads(text)
    del expected["exemplar"]["path"], expected["output"]["path"]
    assert r.to_dict() == expected
    with pytest.raises(ValueError, match="protocol"):
        ppsynth.evaluate(ex, out, protocol="halves")
    # zoom: the crops' scale as the run made the output, as `eval --zoom` takes it; 0 reads it
    # from the densities (20 exemplar points per unit against 100 over 4 units: 0.89).
    dense = ppsynth.PointSet(rng.random((100, 2)) * [4.0, 1.0], domain=(0, 0, 4, 1))
    assert ppsynth.evaluate(ex, dense, bins=40, protocol="crops", zoom=1.0).protocol.zoom == 1.0
    assert ppsynth.evaluate(ex, dense, bins=40, protocol="crops").protocol.zoom == pytest.approx((80 / 100) ** 0.5)
    with pytest.raises(ValueError, match="zoom"):
        ppsynth.evaluate(ex, dense, protocol="crops", zoom=-1.0)


def test_evaluation_reads_as_attributes_and_gives_its_dict_back():
    ex = ppsynth.read(GABOR + "poisson_n64c2_point.txt")
    rng = np.random.default_rng(7)
    out = ppsynth.PointSet(rng.random((4 * len(ex), 2)), np.repeat(ex.classes, 4), class_labels=ex.class_labels)
    r = ppsynth.evaluate(ex, out, bins=20)
    # Keys that are Python keywords read with a trailing underscore; to_dict keeps the key.
    assert [c.class_ for c in r.classes] == [0, 1]
    row = r.verdict.rows[0]
    assert row.row == "all" and isinstance(row.pass_, bool) and 0 <= row.p <= 1
    assert r.passed == r.verdict.passed  # the verdict's own answer (None: a row it cannot judge)
    assert r.to_dict()["verdict"]["rows"][0]["pass"] == row.pass_
    # Lists of numbers are arrays (undefined values NaN), and come back as lists (None).
    g = r.second_order.rows[0].exemplar.g
    assert isinstance(g, np.ndarray) and np.isnan(g[0])
    assert r.to_dict()["second_order"]["rows"][0]["exemplar"]["g"][0] is None
    assert isinstance(r.exemplar.class_counts, np.ndarray) and r.exemplar.class_counts.dtype == np.int64
    json.dumps(r.to_dict())  # plain Python values only
    assert "pcf_mse" in dir(r.all) and "verdict" in r
    with pytest.raises(AttributeError, match="no 'pcf_mes'.*pcf_mse"):
        r.all.pcf_mes
    with pytest.raises(AttributeError, match="read-only"):
        r.all.pcf_mse = 0.0
    assert pickle.loads(pickle.dumps(r)) == r and copy.deepcopy(r) == r
    assert "Evaluation(all=Record(...)" in repr(r)
