"""What the package writes and reads is what it can prove: checkpoint_dir writes only files of
its own in a folder of its own, `write` refuses what `read` refuses, bad files and bad terms
raise the documented errors naming the file or the term, seeds are integers in [0, 2^63), and
Ctrl-C stops even a long initialization within a second."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import ppsynth
from conftest import GABOR, LINES

EXEMPLAR = GABOR + "poisson_n64c2_point.txt"
QUICK = dict(seed=5, quick=True, threads=1, overrides={"evaluate": False, "method.quick.max_iterations": 2})


def test_checkpoint_dir_never_touches_what_ppsynth_did_not_write(tmp_path):
    # The defect: the user's own checkpoint.json was overwritten, then deleted at the end.
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "checkpoint.json").write_text("the user's notes\n")
    with pytest.raises(ValueError, match="checkpoint_dir .*mine.*not a ppsynth checkpoint directory"):
        ppsynth.synthesize(EXEMPLAR, checkpoint_dir=mine, **QUICK)
    assert (mine / "checkpoint.json").read_text() == "the user's notes\n"
    assert sorted(os.listdir(mine)) == ["checkpoint.json"]
    # The defect: checkpoint_dir="/" wrote to / and removed from it.
    for folder in ("/", ".", ".."):
        with pytest.raises(ValueError, match="checkpoint_dir"):
            ppsynth.synthesize(EXEMPLAR, checkpoint_dir=folder, **QUICK)
    # A file where the folder should be.
    (tmp_path / "file").write_text("x")
    with pytest.raises(ValueError):
        ppsynth.synthesize(EXEMPLAR, checkpoint_dir=tmp_path / "file", **QUICK)
    assert (tmp_path / "file").read_text() == "x"


def test_checkpoint_dir_an_empty_folder_is_used_and_left_empty(tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    r = ppsynth.synthesize(EXEMPLAR, checkpoint_dir=empty, **QUICK)
    assert not r.resumed
    assert empty.is_dir() and os.listdir(empty) == []  # the user's folder stays; ppsynth's files go
    made = tmp_path / "made" / "here"
    ppsynth.synthesize(EXEMPLAR, checkpoint_dir=made, **QUICK)
    assert not made.exists()  # the folder ppsynth made goes too


@pytest.mark.parametrize("ext", [".txt", ".json", ".npz", ".npy"])
def test_write_refuses_what_read_refuses(tmp_path, ext):
    good = ppsynth.PointSet(np.array([[0.25, 0.5], [0.75, 0.5]]), np.array([0, 1]), np.array([[0.02], [0.03]]), ["radius"])
    ppsynth.write(good, tmp_path / ("good" + ext))
    assert len(ppsynth.read(tmp_path / ("good" + ext))) == 2
    bad = {
        "nan": ppsynth.PointSet(np.array([[np.nan, 0.5]])),
        "inf": ppsynth.PointSet(np.array([[0.5, np.inf]])),
        "none": ppsynth.PointSet(np.array([[None, 0.5]], dtype=object)),
        "outside": ppsynth.PointSet(np.array([[1.5, 0.5]])),
        "negative radius": ppsynth.PointSet(np.array([[0.5, 0.5]]), attributes=np.array([[-0.1]]), attribute_names=["radius"]),
        "nan radius": ppsynth.PointSet(np.array([[0.5, 0.5]]), attributes=np.array([[np.nan]]), attribute_names=["radius"]),
        "class gap": ppsynth.PointSet(np.array([[0.5, 0.5], [0.2, 0.2]]), np.array([0, 2])),
        "empty": ppsynth.PointSet(np.zeros((0, 2))),
    }
    for what, ps in bad.items():
        path = tmp_path / (what.replace(" ", "_") + ext)
        with pytest.raises(ValueError):
            ppsynth.write(ps, path)
        assert not path.exists(), what
        assert not [f for f in os.listdir(tmp_path) if ".tmp-" in f]


@pytest.mark.parametrize("ext", [".npz", ".npy"])
def test_a_garbage_numpy_file_is_a_value_error_naming_it(tmp_path, ext):
    # The defect: BadZipFile (and EOFError for a truncated .npy), without the path.
    for name, data in (("garbage", b"this is not numpy"), ("zip", b"PK\x03\x04" + b"\x00" * 40), ("empty", b"")):
        path = tmp_path / (name + ext)
        path.write_bytes(data)
        with pytest.raises(ValueError, match=str(path)):
            ppsynth.read(path)


def test_a_non_finite_gradient_names_its_term():
    torch = pytest.importorskip("torch")

    @ppsynth.register_point_term("py_nan_gradient")
    def nan_gradient(moving, frozen, params, stage):
        return torch.sqrt((moving - moving.detach()).abs()).sum()  # 0, with the gradient 0 * inf
    with pytest.raises(ValueError, match="point term 'py_nan_gradient'.*gradient 0.*not finite"):
        ppsynth.point_term_value_and_grad("py_nan_gradient", np.random.default_rng(0).random((4, 2)))


def test_seeds_are_integers_in_0_to_2_63():
    assert ppsynth.resolve_config(seed=2**63 - 1)["seed"] == 2**63 - 1
    for seed in (-5, 2**63, 2**64 + 5):
        with pytest.raises(ValueError, match="seed"):
            ppsynth.resolve_config(seed=seed)
    for seed in ("95", 5.5, True):
        with pytest.raises(TypeError, match="seed"):
            ppsynth.resolve_config(seed=seed)
    assert ppsynth.resolve_config(seed=np.int64(7))["seed"] == 7


def test_ctrl_c_stops_a_long_initialization_within_a_second(tmp_path):
    # A large output: seconds of initialization and window set-up before the first iteration.
    # The defect: Python's Ctrl-C (both of them) went unseen until an iteration ended.
    threading.Timer(1.0, os.kill, args=(os.getpid(), signal.SIGINT)).start()
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        ppsynth.synthesize(LINES, seed=5, threads=1, checkpoint_dir=tmp_path / "ck",
                           overrides={"evaluate": False, "output.size": [120, 120], "method.max_iterations": 1})
    assert time.monotonic() - t0 < 10  # the 1 s timer and the stop, with room: catches a hang


def test_resume_of_a_damaged_checkpoint_is_a_value_error(tmp_path):
    # The defect: one flipped byte in checkpoint.bin made ppsynth.resume kill the interpreter (SIGSEGV).
    calls = []

    def stop_at_third(p):
        calls.append(p)
        if len(calls) == 3:
            raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        ppsynth.run({"exemplar": EXEMPLAR, "seed": 5}, tmp_path / "run", quick=True, threads=1, progress=stop_at_third)
    ck = tmp_path / "run" / "checkpoint.bin"
    data = bytearray(ck.read_bytes())
    for at in (len(data) // 3, len(data) // 2, len(data) - 20):
        bad = bytearray(data)
        bad[at] ^= 0x20
        ck.write_bytes(bytes(bad))
        with pytest.raises(ValueError, match="checkpoint.bin"):
            ppsynth.resume(tmp_path / "run", threads=1)
    ck.write_bytes(bytes(data))
    ppsynth.resume(tmp_path / "run", threads=1)
