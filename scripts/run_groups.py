"""Helpers shared by the scripts that read finished runs (time_quality.py, protocols.py):
the ppsynth binary, a run's group label as `ppsynth gather` shows it, quartiles, and writing
a file atomically without replacing one the user did not name with --force."""
import functools
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BIN = os.environ.get("PPSYNTH_BIN", os.path.join(HERE, "..", "build", "ppsynth"))


def fail(message):
    sys.exit(f"{os.path.basename(sys.argv[0])}: {message}")


def ppsynth(*args):
    r = subprocess.run([BIN, *args], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"ppsynth {' '.join(args)} failed:\n{r.stderr}")
    return r.stdout


@functools.lru_cache(maxsize=None)
def sweep_group_labels(sweep):
    """{run dir relative to the sweep: group label} from a sweep's manifest.json (read once per
    sweep); empty for a directory that is not a sweep."""
    manifest = os.path.join(sweep, "manifest.json")
    if not os.path.exists(manifest):
        return {}
    with open(manifest) as f:
        rows = json.load(f).get("rows", [])
    return {row["dir"]: row["group_label"] for row in rows if row.get("dir") and row.get("group_label")}


def label(run_dir, config):
    """The configuration a run belongs to, seeds pooled: a sweep's run takes its group's label
    from the sweep's manifest.json (as `ppsynth gather` shows it: name, preset and grid point);
    another run its config's name and preset."""
    sweep = os.path.dirname(os.path.dirname(os.path.abspath(run_dir)))
    group = sweep_group_labels(sweep).get(os.path.relpath(os.path.abspath(run_dir), sweep))
    if group:
        return group
    text = config.get("name") or "run"
    if config.get("preset"):
        text += f" (preset {config['preset']})"
    return text


def quartiles(v):
    if len(v) == 1:
        return v[0], v[0], v[0]
    q = statistics.quantiles(v, n=4, method="inclusive")
    return q[0], statistics.median(v), q[2]


def write_atomic(path, force, write):
    if os.path.exists(path) and not force:
        fail(f"{path} exists; pass --force to replace it")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(path)), suffix=os.path.splitext(path)[1])
    os.close(fd)
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
