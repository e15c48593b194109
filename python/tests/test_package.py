"""The package as a user meets it: importing has no side effects, it works without torch
(except Python terms), help() is useful, and the README's example runs."""
import os
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def python(code, **env):
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env={**os.environ, **env})
    assert p.returncode == 0, p.stderr
    return p.stdout


def test_import_starts_no_thread_and_loads_no_torch():
    # NumPy's OpenBLAS starts its thread pool when NumPy loads: count from there.
    out = python("import re, sys, numpy\n"
                 "def threads(): return int(re.search(r'Threads:\\s+(\\d+)', open('/proc/self/status').read()).group(1))\n"
                 "before = threads()\n"
                 "import ppsynth\n"
                 "print(before, threads(), 'torch' in sys.modules)")
    before, after, torch_loaded = out.split()
    assert after == before and torch_loaded == "False"


def test_works_without_torch(tmp_path):
    out = python("import sys; sys.modules['torch'] = None\n"
                 "import ppsynth\n"
                 "ex = ppsynth.read('shared:data/exemplars/gabor-paper/lines.txt')\n"
                 "r = ppsynth.synthesize(ex, quick=True, threads=1)\n"
                 "print(len(r.output), ppsynth.evaluate(ex, r.output).all.pcf_mse >= 0)\n"
                 "try:\n"
                 "    ppsynth.register_loss('x', lambda o, t, p: o[0].sum())\n"
                 "except ImportError as e:\n"
                 "    print('ImportError', e)\n")
    lines = out.splitlines()
    assert lines[0] == "80 True"
    assert lines[1].startswith("ImportError") and "python3-torch" in lines[1]


def test_help_documents_the_api():
    import ppsynth
    for f in (ppsynth.synthesize, ppsynth.read, ppsynth.write, ppsynth.evaluate, ppsynth.register_loss,
              ppsynth.register_point_term, ppsynth.run, ppsynth.resume, ppsynth.generate):
        assert f.__doc__ and len(f.__doc__) > 200, f.__name__
    assert "checkpoint_dir" in ppsynth.synthesize.__doc__ and "KeyboardInterrupt" in ppsynth.synthesize.__doc__
    # numpydoc: help() shows each parameter, what comes back and each field.
    import re
    for f in (ppsynth.synthesize, ppsynth.run, ppsynth.resume, ppsynth.resolve_config, ppsynth.read, ppsynth.write,
              ppsynth.generate, ppsynth.evaluate, ppsynth.register_loss, ppsynth.register_point_term,
              ppsynth.point_term_value_and_grad, ppsynth.loss_value_and_grad):
        assert re.search(r"\n\s*Parameters\n\s*----------\n", f.__doc__), f.__name__
    for f in (ppsynth.synthesize, ppsynth.run, ppsynth.resume, ppsynth.read, ppsynth.generate, ppsynth.evaluate):
        assert re.search(r"\n\s*Returns\n\s*-------\n", f.__doc__), f.__name__
    for c in (ppsynth.Result, ppsynth.Stage, ppsynth.Losses, ppsynth.Progress, ppsynth.PointSet, ppsynth.ClassStage):
        assert re.search(r"\n\s*Attributes\n\s*----------\n", c.__doc__), c.__name__
        for name in c.__dataclass_fields__:
            assert re.search(rf"\n\s*{name} : ", c.__doc__), f"{c.__name__}.{name}"


def test_readme_example_runs(tmp_path):
    pytest.importorskip("matplotlib")
    script = os.path.join(SOURCE_DIR, "docs", "examples", "python_quickstart.py")
    p = subprocess.run([sys.executable, script, str(tmp_path / "lines.png"), "--quick"], capture_output=True, text=True,
                       env={**os.environ, "PPSYNTH_THREADS": "1"}, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert "20 -> 80 points" in p.stdout
    assert (tmp_path / "lines.png").stat().st_size > 10000
    # The README shows this script.
    readme = open(os.path.join(SOURCE_DIR, "README.md")).read()
    body = open(script).read()
    assert body.split('"""', 2)[2].strip() in readme


def test_install_from_the_root_into_a_virtual_environment(tmp_path):
    # `pip install .` from the checkout's root, as scripts/install_python.sh runs it: a venv
    # that sees Debian's packages, pip without an index, the existing build reused. From a
    # copy of what the root's pyproject.toml needs, so the checkout stays clean.
    import shutil
    from conftest import BINARY
    root = tmp_path / "checkout"
    (root / "python").mkdir(parents=True)
    for f in ("pyproject.toml", "setup.py", "MANIFEST.in", "README.md"):
        shutil.copy2(os.path.join(SOURCE_DIR, f), root / f)
    shutil.copy2(os.path.join(SOURCE_DIR, "python", "README.md"), root / "python" / "README.md")
    shutil.copytree(os.path.join(SOURCE_DIR, "python", "ppsynth"), root / "python" / "ppsynth",
                    ignore=shutil.ignore_patterns("__pycache__"))
    subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(tmp_path / "venv")], check=True)
    env = {**os.environ, "PPSYNTH_BUILD_DIR": os.path.dirname(BINARY), "PPSYNTH_THREADS": "1"}
    env.pop("PYTHONPATH", None)  # the venv's own copy, not the build tree's
    python = str(tmp_path / "venv" / "bin" / "python")
    p = subprocess.run([python, "-m", "pip", "install", "--quiet", "--no-index", "--no-build-isolation", "."],
                       capture_output=True, text=True, env=env, cwd=root)
    assert p.returncode == 0, p.stderr
    p = subprocess.run([python, "-c", "import ppsynth; print(ppsynth.__file__); print(len(ppsynth.generate('uniform', 10)))"],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    where, n = p.stdout.split()
    assert where.startswith(str(tmp_path / "venv")) and n == "10"
    # The README's example runs from the installed package.
    pytest.importorskip("matplotlib")
    p = subprocess.run([python, os.path.join(SOURCE_DIR, "docs", "examples", "python_quickstart.py"), str(tmp_path / "lines.png"), "--quick"],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "lines.png").stat().st_size > 10000


def test_the_source_distribution_holds_every_source_folder():
    # The sdist is the whole CMake project (MANIFEST.in): a folder of C++ sources it leaves out
    # (experiments/ was, when it was made) builds here from the checkout and fails from the sdist.
    manifest = open(os.path.join(SOURCE_DIR, "MANIFEST.in")).read().split("\n")
    grafted = {line.split()[1] for line in manifest if line.startswith("graft ")}
    skip = {"python", "docs", "tests"}  # python/src is grafted on its own; docs and tests are not built into the module
    for entry in sorted(os.listdir(SOURCE_DIR)):
        path = os.path.join(SOURCE_DIR, entry)
        if entry.startswith(".") or entry.startswith("build") or entry in skip or not os.path.isdir(path):
            continue
        has_sources = any(f.endswith((".cpp", ".hpp")) for _, _, files in os.walk(path) for f in files)
        if has_sources:
            assert entry in grafted, f"MANIFEST.in does not graft {entry}/"
