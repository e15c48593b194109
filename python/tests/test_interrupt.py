"""Ctrl-C stops a synthesis at the end of an iteration after its checkpoint and raises
KeyboardInterrupt; the same call continues from the checkpoint and returns what an
uninterrupted run returns."""
import os
import signal
import threading

import numpy as np
import pytest

import ppsynth
from conftest import GABOR

EXEMPLAR = GABOR + "poisson_n64c2_point.txt"  # two classes: several stages


def ctrl_c_at(n):
    """A progress callable that, at its n-th call, has SIGINT sent to this process from
    another thread while the synthesis runs in C++ (as a terminal's Ctrl-C would)."""
    calls = []

    def progress(p):
        calls.append(p)
        if len(calls) == n:
            threading.Thread(target=os.kill, args=(os.getpid(), signal.SIGINT)).start()
    return progress, calls


def test_keyboard_interrupt_then_resume_equals_uninterrupted(tmp_path):
    whole = ppsynth.synthesize(EXEMPLAR, seed=5, quick=True, threads=1, overrides={"evaluate": False})
    total = len(whole.losses.loss)
    progress, calls = ctrl_c_at(total // 2)
    with pytest.raises(KeyboardInterrupt):
        ppsynth.synthesize(EXEMPLAR, seed=5, quick=True, threads=1, overrides={"evaluate": False},
                           checkpoint_dir=tmp_path / "ck", progress=progress)
    assert total // 2 <= len(calls) < total  # stopped within an iteration or two of the signal
    assert sorted(os.listdir(tmp_path / "ck")) == [".ppsynth-run", "checkpoint.bin"]
    # Another synthesis is not resumed from it: the message says what differs.
    with pytest.raises(ValueError, match=r"made for another synthesis: seed 6 \(the checkpoint's: 5\)"):
        ppsynth.synthesize(EXEMPLAR, seed=6, quick=True, threads=1, overrides={"evaluate": False},
                           checkpoint_dir=tmp_path / "ck")
    again = ppsynth.synthesize(EXEMPLAR, seed=5, quick=True, threads=1, overrides={"evaluate": False},
                               checkpoint_dir=tmp_path / "ck")
    assert again.resumed
    # The CPU time spent before the interrupt was kept in the checkpoint and added.
    assert again.cpu_seconds is not None and again.cpu_seconds > 0
    np.testing.assert_array_equal(again.output.positions, whole.output.positions)
    np.testing.assert_array_equal(again.losses.loss, whole.losses.loss)
    assert not (tmp_path / "ck").exists()  # a finished synthesis removes its checkpoint (and the folder it made)


def test_an_exception_in_progress_stops_the_run_and_is_raised(tmp_path):
    class Enough(Exception):
        pass

    def progress(p):
        if p.iteration == 2:
            raise Enough("stop here")
    with pytest.raises(Enough, match="stop here"):
        ppsynth.synthesize(EXEMPLAR, seed=5, quick=True, threads=1, progress=progress, checkpoint_dir=tmp_path / "ck")
    assert (tmp_path / "ck" / "checkpoint.bin").exists()


def test_run_directory_interrupted_then_resumed(tmp_path):
    ppsynth.run({"exemplar": EXEMPLAR, "seed": 5}, tmp_path / "whole", quick=True, threads=1)
    progress, _ = ctrl_c_at(10)
    with pytest.raises(KeyboardInterrupt):
        ppsynth.run({"exemplar": EXEMPLAR, "seed": 5}, tmp_path / "cut", quick=True, threads=1, progress=progress)
    assert (tmp_path / "cut" / "checkpoint.bin").exists()
    r = ppsynth.resume(tmp_path / "cut", threads=1)
    assert (tmp_path / "cut" / "output.txt").read_bytes() == (tmp_path / "whole" / "output.txt").read_bytes()
    assert not (tmp_path / "cut" / "checkpoint.bin").exists()
    assert r.dir == str(tmp_path / "cut")
    assert r.resumed and r.cpu_seconds is not None and r.cpu_seconds > 0
