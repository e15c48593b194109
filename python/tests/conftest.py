"""Shared fixtures of the Python tests (run by CTest as `python_tests`; by hand:
PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests)."""
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("PPSYNTH_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
BINARY = os.environ.get("PPSYNTH_BINARY", os.path.join(SOURCE_DIR, "build", "ppsynth"))
GABOR = "shared:data/exemplars/gabor-paper/"
LINES = GABOR + "lines.txt"


def command(*args, cwd=None, check=True):
    """Runs the ppsynth command; returns (exit code, stdout, stderr)."""
    p = subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True,
                       env={**os.environ, "PPSYNTH_THREADS": "1"})
    if check and p.returncode != 0:
        raise AssertionError(f"ppsynth {' '.join(map(str, args))} exited {p.returncode}:\n{p.stderr}")
    return p.returncode, p.stdout, p.stderr


@pytest.fixture
def ppsynth_command():
    return command
