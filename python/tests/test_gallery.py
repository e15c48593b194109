"""scripts/gallery.py: finished runs (or new quick syntheses) on one self-contained page: a card
per run with its picture embedded, written whole, never over an existing page without --force;
a measure not computed shows as such; a page that could not be written is refused before any work."""
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

from conftest import BINARY, LINES, SOURCE_DIR, command

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "gallery.py")


def gallery(*args, bin=BINARY):
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], capture_output=True, text=True,
                          env={**os.environ, "PPSYNTH_BIN": str(bin), "PPSYNTH_THREADS": "1"})


def test_a_card_per_run_with_its_picture_and_measures(tmp_path):
    for seed in (1, 2):
        command("synthesize", "--exemplar", LINES, "--quick", "--seed", seed, "-o", tmp_path / f"run{seed}", "-q")
    page = tmp_path / "g.html"
    p = gallery("-o", page, "--runs", tmp_path / "run2", tmp_path / "run1")
    assert p.returncode == 0, p.stderr
    text = page.read_text()
    assert len(re.findall(r'<img [^>]*src="data:image/png;base64,[A-Za-z0-9+/=]{1000,}"', text)) == 2  # self-contained
    assert text.index("seed 1") < text.index("seed 2")  # sorted by name, then seed
    assert text.count("PCF MSE") == 2 and "gabor, quick settings" in text
    assert text.count("K test, all points") == 2
    assert not [f for f in os.listdir(tmp_path) if f.endswith(".partial")]


def test_it_refuses_what_it_would_lose(tmp_path):
    page = tmp_path / "g.html"
    page.write_text("mine")
    p = gallery("-o", page, "--runs", tmp_path)
    assert p.returncode != 0 and "--force" in p.stderr and page.read_text() == "mine"
    p = gallery("-o", tmp_path / "new.html", "--runs", tmp_path)  # not a run directory
    assert p.returncode != 0 and "not a finished run directory" in p.stderr
    assert not (tmp_path / "new.html").exists()


@pytest.fixture(scope="module")
def one_run(tmp_path_factory):
    run = tmp_path_factory.mktemp("gallery_run") / "run"
    command("synthesize", "--exemplar", LINES, "--quick", "--seed", 1, "-o", run, "-q")
    return run


def test_a_measure_not_computed_shows_as_such(tmp_path, one_run):
    # A large exemplar's Wasserstein is null beside its subsample estimate (was a TypeError).
    run = tmp_path / "run"
    shutil.copytree(one_run, run)
    metrics = json.loads((run / "metrics.json").read_text())
    metrics["all"].update(wasserstein=None, wasserstein_estimate=0.0123, wasserstein_sample=[500, 600], chamfer=None)
    (run / "metrics.json").write_text(json.dumps(metrics))
    page = tmp_path / "g.html"
    p = gallery("-o", page, "--runs", run)
    assert p.returncode == 0, p.stderr
    text = page.read_text()
    assert "&asymp; 0.0123 (estimate, subsamples of 500 and 600 points)" in text
    assert re.search(r"<th>Chamfer</th><td>n/a</td>", text)


def test_a_row_that_fails_without_a_p_shows_as_a_failure(tmp_path, one_run):
    # A class missing from the output fails its row with no p: not "cannot judge".
    run = tmp_path / "run"
    shutil.copytree(one_run, run)
    metrics = json.loads((run / "metrics.json").read_text())
    metrics["verdict"]["rows"] = [
        {"row": "class", "class": 1, "p": None, "pass": False, "outcome": "fail",
         "reason": "the output has no points of class 2000"},
        {"row": "pair", "ci": 0, "cj": 1, "p": None, "pass": None, "outcome": "cannot judge",
         "reason": "too few sub-windows"}]
    (run / "metrics.json").write_text(json.dumps(metrics))
    page = tmp_path / "g.html"
    p = gallery("-o", page, "--runs", run)
    assert p.returncode == 0, p.stderr
    text = page.read_text()
    assert "<b>fails</b>: the output has no points of class 2000" in text
    assert "cannot judge: too few sub-windows" in text
    assert "cannot judge: the output has no points" not in text


def test_the_page_is_checked_before_any_synthesis(tmp_path):
    # A stand-in for ppsynth that leaves a mark when it runs: it must not run at all.
    mark = tmp_path / "ran"
    fake = tmp_path / "fake-ppsynth"
    fake.write_text(f"#!/bin/sh\ntouch {mark}\nexit 1\n")
    fake.chmod(0o755)
    for out, says in ((tmp_path / "nosuchdir" / "x.html", "no directory"), (tmp_path, "is a directory")):
        p = gallery("-o", out, "--force", bin=fake)
        assert p.returncode != 0 and str(out) in p.stderr and says in p.stderr, p.stderr
        assert not mark.exists()  # was: every exemplar synthesized first, then the crash


def test_a_directory_as_the_page_leaves_nothing_behind(tmp_path, one_run):
    p = gallery("-o", tmp_path, "--force", "--runs", one_run)
    assert p.returncode != 0 and "is a directory" in p.stderr
    assert not [f for f in os.listdir(tmp_path.parent) if f.endswith(".partial")]  # was left beside it


def test_a_failed_write_removes_its_partial_file(tmp_path, monkeypatch):
    spec = importlib.util.spec_from_file_location("gallery", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)

    def refuse(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(module.os, "replace", refuse)
    with pytest.raises(OSError):
        module.write_page("<html></html>", str(tmp_path / "g.html"))
    assert os.listdir(tmp_path) == []


def test_a_point_file_gets_a_card_with_its_l_curves_and_band(tmp_path):
    # --pair: an output that is a point file (a fitted model's draw), evaluated against its
    # exemplar: both drawn, L(r) - r of both inside the band's polygon, the scorecard's lines.
    ex, out = tmp_path / "ex.txt", tmp_path / "out.txt"
    command("generate", "poisson_disk", "-n", 200, "--seed", 1, "-o", ex, "-q")
    command("generate", "poisson_disk", "-n", 800, "--seed", 2, "--domain", 0, 0, 2, 2, "-o", out, "-q")
    page = tmp_path / "g.html"
    p = gallery("-o", page, "--pair", "a Poisson disk's draw", ex, out)
    assert p.returncode == 0, p.stderr
    text = page.read_text()
    assert "<figcaption>a Poisson disk&#x27;s draw</figcaption>" in text
    assert text.count("<svg") >= 3  # exemplar, output, the all-points L panel
    assert '<polygon points="' in text and "all points: L " in text and "spreads" in text
    assert re.search(r"fidelity, all points</th><td>L [0-9.]+ \(band [0-9.]+\)", text)
    assert "novelty" in text and "K test, all points" in text
    p = gallery("-o", tmp_path / "h.html", "--pair", "x", ex, tmp_path / "missing.txt")
    assert p.returncode != 0 and "missing.txt" in p.stderr and not (tmp_path / "h.html").exists()


def test_a_mark_column_is_not_a_class(tmp_path):
    # longleaf's plain file: "# x y mark" (a tree's diameter); it was drawn as 70-odd classes.
    spec = importlib.util.spec_from_file_location("gallery", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    marked, classed = tmp_path / "m.txt", tmp_path / "c.txt"
    marked.write_text("# domain 0 0 1 1\n# x y mark\n0.1 0.2 32.9\n0.3 0.4 53.5\n")
    classed.write_text("# domain 0 0 1 1\n# classes 0=off 1=on\n# x y class\n0.1 0.2 1\n0.3 0.4 0\n")
    assert [p[2] for p in module.read_points(str(marked))[1]] == [0, 0]
    _, points, labels = module.read_points(str(classed))
    assert [p[2] for p in points] == [1, 0] and labels == ["off", "on"]
