"""Synthesis from Python runs the command's library: the same config and seed give the same
files as `ppsynth synthesize`, in memory and as a run directory."""
import filecmp
import json
import os

import numpy as np
import pytest

import ppsynth
from conftest import GABOR, LINES, command

# A tiny multi-class disk run: every stage kind, a few seconds.
CONFIG = {"name": "tiny", "exemplar": GABOR + "poisson_n64c2_disk.txt", "seed": 7}


def files_of(d):
    out = []
    for root, _, names in os.walk(d):
        out += [os.path.relpath(os.path.join(root, n), d) for n in names]
    return sorted(out)


def test_run_equals_the_command_file_for_file(tmp_path):
    (tmp_path / "tiny.json").write_text(json.dumps(CONFIG))
    command("synthesize", tmp_path / "tiny.json", "--quick", "-o", tmp_path / "cmd")
    r = ppsynth.run(tmp_path / "tiny.json", tmp_path / "py", quick=True, threads=1)
    assert r.dir == str(tmp_path / "py")
    # One result type: a run directory's Result says what synthesize()'s says.
    assert isinstance(r, ppsynth.Result) and not r.resumed and r.threads == 1
    assert r.stages and len(r.losses.loss) == sum(s.iterations for s in r.stages)
    assert len(r.exemplar) > 0 and len(r.output) == 4 * len(r.exemplar)
    assert r.processor == json.loads((tmp_path / "py" / "run.json").read_text())["processor"]
    names = files_of(tmp_path / "cmd")
    assert names == files_of(tmp_path / "py")
    # Wall times (run.json, the loss CSV's last column) and the writer's pid and clock in the
    # run marker differ; every other byte is equal.
    timed = {"run.json", "loss.csv", ".ppsynth-run"}
    differ = [n for n in names if n not in timed and not filecmp.cmp(tmp_path / "cmd" / n, tmp_path / "py" / n, shallow=False)]
    assert differ == []

    def untimed_csv(d):
        return [line.rsplit(",", 1)[0] for line in (d / "loss.csv").read_text().splitlines()]
    assert untimed_csv(tmp_path / "cmd") == untimed_csv(tmp_path / "py")

    def untimed_marker(d):
        m = json.loads((d / ".ppsynth-run").read_text())
        return {k: v for k, v in m.items() if k not in ("pid", "updated")}
    assert untimed_marker(tmp_path / "cmd") == untimed_marker(tmp_path / "py")
    run_py = json.loads((tmp_path / "py" / "run.json").read_text())
    run_cmd = json.loads((tmp_path / "cmd" / "run.json").read_text())
    assert run_py["seed"] == run_cmd["seed"] == 7 and run_py["threads"] == run_cmd["threads"] == 1
    assert run_py["processor"] == run_cmd["processor"] != ""
    # The CPU time is run.json's, and recorded (a quick run still spends some).
    assert r.cpu_seconds is not None and r.cpu_seconds == run_py["cpu_seconds"] > 0
    assert r.metrics.all.pcf_mse == json.loads((tmp_path / "cmd" / "metrics.json").read_text())["all"]["pcf_mse"]


def test_synthesize_in_memory_equals_the_command(tmp_path):
    command("synthesize", "--exemplar", LINES, "--seed", 11, "--quick", "-o", tmp_path / "cmd")
    r = ppsynth.synthesize(LINES, seed=11, quick=True, threads=1)
    ppsynth.write(r.output, tmp_path / "py_output.txt")
    assert (tmp_path / "py_output.txt").read_bytes() == (tmp_path / "cmd" / "output.txt").read_bytes()
    assert r.output.positions.shape == (80, 2) and r.output.positions.dtype == np.float64
    assert [s.iterations for s in r.stages] and all(s.iterations > 0 for s in r.stages)
    assert len(r.losses.loss) == sum(s.iterations for s in r.stages)
    assert np.all(np.isfinite(r.losses.loss))
    assert r.metrics.all.pcf.r.shape == (100,)
    assert r.config["seed"] == 11 and r.threads == 1 and not r.resumed
    assert r.cpu_seconds is not None and r.cpu_seconds > 0
    record = json.loads((tmp_path / "cmd" / "run.json").read_text())
    assert r.processor == record["processor"]
    # The stages, typed, with what run.json shows of each beside the four fields.
    shown = record["method_stats"]["stages"]
    assert [s.iterations for s in r.stages] == [st["iterations"] for st in shown]
    assert [s.details["sigma"] for s in r.stages] == [st["sigma"] for st in shown]
    assert "stages" not in r.stats


def test_same_seed_same_points_and_progress_is_reported():
    events = []
    a = ppsynth.synthesize(LINES, seed=3, quick=True, threads=1, progress=events.append,
                           overrides={"evaluate": False})
    b = ppsynth.synthesize(ppsynth.read(LINES), seed=3, quick=True, threads=1, overrides=["evaluate=false"])
    np.testing.assert_array_equal(a.output.positions, b.output.positions)
    assert a.metrics is None
    assert len(events) == len(a.losses.loss) and isinstance(events[0], ppsynth.Progress)
    # The last event is the last iterating stage's (the border relax runs none where nothing parks).
    assert events[-1].stage_count == len(a.stages)
    assert events[-1].stage_index == max(i for i, s in enumerate(a.stages) if s.iterations > 0)
    c = ppsynth.synthesize(LINES, seed=4, quick=True, threads=1, overrides={"evaluate": False})
    assert not np.array_equal(a.output.positions, c.output.positions)


def test_config_errors_carry_the_key_path(tmp_path):
    with pytest.raises(ValueError, match="config key 'method.no_such_key'"):
        ppsynth.synthesize(LINES, overrides={"method.no_such_key": 1}, quick=True)
    with pytest.raises(ValueError, match="upscale"):
        ppsynth.synthesize(LINES, overrides={"upscale": 0}, quick=True)
    with pytest.raises(FileNotFoundError, match="no such file"):
        ppsynth.synthesize(tmp_path / "nope.txt", quick=True)
    with pytest.raises(FileNotFoundError):
        ppsynth.synthesize(config=tmp_path / "nope.json", quick=True)
    bad = ppsynth.PointSet(np.array([[0.5, 0.5], [0.5, np.inf]]))
    with pytest.raises(ValueError, match="exemplar: point 1 has a non-finite coordinate"):
        ppsynth.synthesize(bad, quick=True)
    code, _, err = command("synthesize", "--exemplar", LINES, "--quick", "--set", "method.no_such_key=1",
                           "-o", tmp_path / "x", check=False)
    assert code != 0 and "config key 'method.no_such_key'" in err
    assert not (tmp_path / "x").exists()


def test_configs_cross_as_python_values_and_their_flaws_name_the_key():
    # A dict override is a value, not --set text: the string "123" stays a string.
    c = ppsynth.resolve_config(overrides={"description": "123", "method.max_iterations": np.int64(7)})
    assert c["description"] == "123" and c["method"]["max_iterations"] == 7
    with pytest.raises(ValueError, match=r"overrides\['upscale'\]: nan is not a finite number"):
        ppsynth.resolve_config(overrides={"upscale": float("nan")})
    with pytest.raises(ValueError, match=r"config\.method\.sigmas\[1\]: inf is not a finite number"):
        ppsynth.resolve_config({"method": {"type": "gabor", "sigmas": [1.0, float("inf")]}})
    with pytest.raises(ValueError, match=r"config\.description: a set has no JSON form"):
        ppsynth.resolve_config({"description": {1, 2}})
    with pytest.raises(ValueError, match=r"config\.seed: .* is beyond the range of a 64-bit integer"):
        ppsynth.resolve_config({"seed": 2 ** 70})
    loop = {}
    loop["a"] = loop
    with pytest.raises(ValueError, match="nested deeper than 200 levels"):
        ppsynth.resolve_config({"method": loop})
    with pytest.raises(ValueError, match=r"config: the key 1 is not a string"):
        ppsynth.resolve_config({1: 2})


def test_run_refuses_a_foreign_directory(tmp_path):
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep")
    with pytest.raises(ValueError):
        ppsynth.run({"exemplar": LINES}, tmp_path / "mine", quick=True)
    with pytest.raises(ValueError):
        ppsynth.run({"exemplar": LINES}, tmp_path / "mine", quick=True, force=True)
    assert os.listdir(tmp_path / "mine") == ["notes.txt"]


def test_synthesis_releases_the_gil():
    # Another Python thread keeps running while the synthesis works in C++.
    import threading
    import time
    ticks, stop = [], threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)
    t = threading.Thread(target=tick)
    t.start()
    start = time.perf_counter()
    ppsynth.synthesize(GABOR + "poisson_n64c2_point.txt", quick=True, threads=1, overrides={"evaluate": False})
    took = time.perf_counter() - start
    stop.set()
    t.join()
    during = [x for x in ticks if start <= x <= start + took]
    assert took > 0.05 and len(during) > 0.3 * took / 0.0015, (took, len(during))
