"""scripts/gallery.py: finished runs (or new quick syntheses) on one self-contained page: a card
per run with its picture embedded, written whole, never over an existing page without --force."""
import os
import re
import subprocess
import sys

from conftest import BINARY, LINES, SOURCE_DIR, command

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "gallery.py")


def gallery(*args):
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], capture_output=True, text=True,
                          env={**os.environ, "PPSYNTH_BIN": BINARY, "PPSYNTH_THREADS": "1"})


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
