"""Point sets through NumPy: every format of the command plus .npy / .npz round-trips, the
text a Python write produces equals the command's conversion, bad files raise the command's
errors."""
import os
import subprocess
import sys

import numpy as np
import pytest

import ppsynth
from conftest import GABOR, command

EXEMPLARS = [GABOR + n for n in ("lines.txt", "poisson_n64c2_point.txt", "poisson_n64c2_disk.txt", "lemon_4c_v2.txt")] + \
            ["shared:data/exemplars/point-synthesis/" + n for n in ("Cattles.txt", "Fluid1.txt")]
FORMATS = [("gabor", ".txt"), ("point-synthesis", ".txt"), ("plain", ".txt"), ("json", ".json"),
           (None, ".npy"), (None, ".npz")]


def same_points(a, b, tol=0.0):
    assert len(a) == len(b)
    np.testing.assert_allclose(a.positions, b.positions, rtol=0, atol=tol)
    np.testing.assert_array_equal(a.classes, b.classes)
    np.testing.assert_allclose(a.attributes, b.attributes, rtol=0, atol=tol)


@pytest.mark.parametrize("exemplar", EXEMPLARS)
@pytest.mark.parametrize("fmt,ext", FORMATS)
def test_round_trip_of_every_format(tmp_path, exemplar, fmt, ext):
    ps = ppsynth.read(exemplar)
    assert ps.positions.dtype == np.float64 and ps.positions.shape == (len(ps), 2)
    assert ps.classes.dtype == np.int64
    path = tmp_path / f"points{ext}"
    ppsynth.write(ps, path, format=fmt)
    back = ppsynth.read(path, format=fmt, attribute_names=ps.attribute_names if fmt in ("gabor", "point-synthesis") or ext == ".npy" else None)
    if fmt == "point-synthesis" and "c3" not in ps.attribute_names and not ps.attribute_names:
        back = ppsynth.PointSet(back.positions, back.classes)  # the writer adds a constant c3 (published layout)
    if fmt == "point-synthesis":  # pixel units: the reader rescales each axis onto [0, 1], as published
        lo, hi = ps.positions.min(0), ps.positions.max(0)
        ps = ppsynth.PointSet((ps.positions - lo) / (hi - lo), ps.classes, ps.attributes, ps.attribute_names)
    # The Gabor format stores 1e-4 integers.
    same_points(ps, back, tol=1e-4 if fmt == "gabor" else 1e-12 if fmt == "point-synthesis" else 0.0)
    if ext in (".json", ".npz") or fmt == "plain":
        assert back.attribute_names == ps.attribute_names
        assert back.domain == ps.domain


@pytest.mark.parametrize("fmt,ext", [("plain", ".txt"), ("json", ".json"), ("gabor", ".txt"), ("point-synthesis", ".txt")])
def test_python_write_equals_the_command_conversion(tmp_path, fmt, ext):
    src = GABOR + "poisson_n64c2_disk.txt"
    ppsynth.write(ppsynth.read(src), tmp_path / f"py{ext}", format=fmt)
    command("convert", src, tmp_path / f"cmd{ext}", "--to", fmt)
    assert (tmp_path / f"py{ext}").read_bytes() == (tmp_path / f"cmd{ext}").read_bytes()


def test_published_npz_initialization_reads_as_positions(tmp_path):
    # The published code writes np.savez(path, x=p) with p (N, 2) in the unit square.
    p = np.random.default_rng(3).random((50, 2))
    np.savez(tmp_path / "init_lines_c0_x2.npz", x=p)
    ps = ppsynth.read(tmp_path / "init_lines_c0_x2.npz")
    np.testing.assert_array_equal(ps.positions, p)
    assert ps.num_classes == 1 and ps.attribute_names == []
    # and what we write, the published code reads the same way
    ppsynth.write(ps, tmp_path / "ours.npz")
    np.testing.assert_array_equal(np.load(tmp_path / "ours.npz")["x"], p)


def test_write_never_replaces_an_existing_file_unless_told(tmp_path):
    ps = ppsynth.PointSet(np.array([[0.25, 0.5]]))
    target = tmp_path / "mine.txt"
    target.write_text("precious\n")
    for name in ("mine.txt",):
        with pytest.raises(FileExistsError, match="overwrite=True"):
            ppsynth.write(ps, tmp_path / name)
    assert target.read_text() == "precious\n"
    ppsynth.write(ps, target, overwrite=True)
    assert ppsynth.read(target).positions.tolist() == [[0.25, 0.5]]
    npz = tmp_path / "a.npz"
    npz.write_bytes(b"x")
    with pytest.raises(FileExistsError):
        ppsynth.write(ps, npz)
    assert npz.read_bytes() == b"x"
    assert sorted(os.listdir(tmp_path)) == ["a.npz", "mine.txt"]  # no temporary left behind


def test_generate_equals_the_command(tmp_path):
    ps = ppsynth.generate("poisson_disk", 64, seed=7)
    command("generate", "poisson_disk", "-n", 64, "--seed", 7, "-o", tmp_path / "cmd.txt")
    same_points(ps, ppsynth.read(tmp_path / "cmd.txt"))
    assert "poisson_disk" in ppsynth.generators()


def test_bad_files_raise_the_commands_errors(tmp_path):
    missing = tmp_path / "missing.txt"
    with pytest.raises(FileNotFoundError, match="missing.txt: no such file"):
        ppsynth.read(missing)
    with pytest.raises(FileNotFoundError, match="no such file"):
        ppsynth.read(tmp_path / "missing.npz")
    bad = tmp_path / "bad.txt"
    bad.write_text("# x y class\n0.1 0.2 0\n0.3 zebra 0\n")
    with pytest.raises(ValueError) as e:
        ppsynth.read(bad)
    code, _, err = command("info", bad, check=False)
    assert code != 0 and str(e.value) in err, (str(e.value), err)
    assert f"{bad}:3:" in str(e.value)
    outside = tmp_path / "outside.npy"
    np.save(outside, np.array([[0.5, 0.5], [1.5, 0.5]]))
    with pytest.raises(ValueError, match=r"outside.npy: point 1 .* outside the domain"):
        ppsynth.read(outside)
    nan = tmp_path / "nan.npz"
    np.savez(nan, x=np.array([[0.5, np.nan]]))
    with pytest.raises(ValueError, match="non-finite"):
        ppsynth.read(nan)
    with pytest.raises(ValueError, match=r"positions: expected an \(N, 2\) array"):
        ppsynth.PointSet(np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"class 0 \(label 0\) has no points"):
        ppsynth.PointSet(np.array([[0.5, 0.5]]), classes=[1]).validate()


@pytest.mark.parametrize("label", [1e20, 2 ** 31, -2 ** 63 - 1])
def test_a_class_label_past_32_bits_is_refused_by_name(tmp_path, label):
    # Was "Unable to cast Python instance to C++ type" for labels past 64 bits.
    ps = ppsynth.PointSet(np.array([[0.5, 0.5]]), class_labels=[label])
    with pytest.raises(ValueError, match=r"class_labels: -?\d+ is out of range \(a class label is a 32-bit integer, "
                                         r"-2147483648\.\.2147483647\)"):
        ppsynth.write(ps, tmp_path / "x.txt")
    assert not (tmp_path / "x.txt").exists()


@pytest.mark.parametrize("name", ["p.npy", "p.npz", "p.txt"])
def test_reading_a_fifo_or_a_directory_stops_at_once(tmp_path, name):
    # In a child process with a time limit: a FIFO blocked np.load (and the point readers) forever.
    fifo = tmp_path / name
    os.mkfifo(fifo)
    folder = tmp_path / ("d" + name)
    folder.mkdir()
    script = ("import sys, ppsynth\n"
              "for f in sys.argv[1:]:\n"
              "    try:\n"
              "        ppsynth.read(f)\n"
              "    except ValueError as e:\n"
              "        print(e)\n")
    p = subprocess.run([sys.executable, "-c", script, str(fifo), str(folder)], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    assert f"{fifo}: is a FIFO (named pipe), not a regular file" in p.stdout
    assert f"{folder}: is a directory" in p.stdout
