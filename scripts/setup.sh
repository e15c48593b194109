#!/usr/bin/env bash
# Installs every Debian package ppsynth needs, then configures in Release and builds the
# command, build/ppsynth: all the main job needs, so a first synthesis does not wait for the
# test binary and the Python module (scripts/test.sh builds those, or --all here).
# Usage: scripts/setup.sh [--no-build | --all]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
targets=(--target ppsynth)
case "${1:-}" in
  "" | --no-build) ;;
  --all) targets=() ;;  # every target: the test binary, the library example, the Python module
  *) echo "usage: scripts/setup.sh [--no-build | --all]" >&2; exit 2 ;;
esac
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config
  libtorch-dev            # LibTorch 1.13, CPU
  libopenblas0-pthread    # without it LibTorch's matrix products run on the reference BLAS, far slower
  libnanoflann-dev        # k-NN and radius queries
  nlohmann-json3-dev      # configs, JSON point sets, reports
  libspdlog-dev           # logging
  catch2                  # unit tests (v2)
  libcli11-dev            # command line
  libcairo2-dev           # PNG / SVG / PDF plots
  clang-14 libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes (scripts/fuzz.sh)
  llvm-14                 # llvm-symbolizer: file:line in sanitizer reports
  munge slurmctld slurmd slurm-client  # a single-node SLURM cluster for the sweep tests (scripts/slurm_cluster.sh)
  python3-dev python3-pybind11 pybind11-json-dev python3-numpy  # the Python package (python/)
  python3-torch           # loss terms written in Python (the same LibTorch build as libtorch-dev)
  python3-pytest python3-matplotlib python3-venv python3-pip python3-setuptools python3-wheel  # its tests, example, install
  # R's spatstat: the field's reference for K, L, g and mark correlation (tests/core
  # test_spatstat_*), its real data sets as exemplars (scripts/spatstat_export.R) and the
  # simulated processes that calibrate eval's verdict (docs/lab/verdict/verdict_calibration.sh)
  r-base-core r-cran-spatstat r-cran-spatstat.explore r-cran-spatstat.data r-cran-spatstat.random r-cran-spatstat.model
  r-cran-randomfields     # the Gaussian fields of spatstat's log-Gaussian Cox simulations
)

need=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  echo "[setup] installing: ${need[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}"
fi

if [ "${1:-}" = "--no-build" ]; then exit 0; fi

cd "$here"
# ccache: paths relative to the checkout, so a fresh clone elsewhere (CI) reuses the cache;
# the precompiled header needs the pch sloppiness to be cacheable.
export CCACHE_BASEDIR="$here"
export CCACHE_SLOPPINESS="pch_defines,time_macros,include_file_mtime,include_file_ctime"
export CCACHE_NOHASHDIR=1
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" ${targets[@]+"${targets[@]}"}
