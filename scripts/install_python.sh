#!/usr/bin/env bash
# Installs the Python package `ppsynth` into the virtual environment VENV (default .venv in
# the checkout), made with --system-site-packages when missing so that it sees Debian's NumPy,
# torch and matplotlib: no package index is used, nothing is downloaded.
# Usage: scripts/install_python.sh [VENV]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="${1:-$here/.venv}"
"$here/scripts/setup.sh"  # Debian packages (python3-pybind11, -numpy, -torch, ...) and the build
if [ ! -x "$venv/bin/python" ]; then
  /usr/bin/python3 -m venv --system-site-packages "$venv"  # Debian's interpreter, explicitly
fi
"$venv/bin/python" -m pip install --quiet --no-index --no-build-isolation "$here"
echo "ppsynth installed in $venv: $venv/bin/python -c 'import ppsynth; help(ppsynth)'"
