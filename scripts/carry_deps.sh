#!/usr/bin/env bash
# Prepares what a machine that cannot install packages needs to build and check ppsynth (a
# GPU machine of the device tool: no network there; docs/explanation/performance.md, "On a GPU"):
#   .deps/debs/    the header-only Debian packages ppsynth builds with, as .deb files
#                  (apt-get download: nanoflann, nlohmann-json, CLI11, Catch2, spdlog, fmt)
#   .deps/root/    their headers, unpacked (usr/include): cmake -DPPSYNTH_DEPS_DIR=$PWD/.deps/root
#   .deps/shared/  the exemplars scripts/gpu_check.sh and scripts/bench_scaling.sh synthesize
#                  (PPSYNTH_SHARED there)
#   .deps/real_data/amacrine.txt  spatstat's amacrine, scripts/gpu_check.sh's --preset fast
#                  target, when not there already: copied from CARRY_REAL_DATA/amacrine.txt
#                  when set, else exported by scripts/spatstat_export.R (R with spatstat)
# (the rest of .deps/real_data/, docs/lab/verdict/gpu_real_data.sh's exemplars and runs, is
# left as it is.)
# .deps/ is ignored by git; the device tool takes it along when its `carry` names it.
# Usage: scripts/carry_deps.sh   (on a Debian machine with ../shared beside the checkout)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$here/.deps"
shared="${PPSYNTH_SHARED:-$here/../shared}"
packages=(libnanoflann-dev nlohmann-json3-dev libcli11-dev catch2 libspdlog-dev libfmt-dev)
exemplars=(data/exemplars/gabor-paper/lines.txt data/exemplars/gabor-paper/poisson_n64c2_point.txt)

# Its own folders only, rebuilt from scratch: .deps/real_data (docs/lab/verdict/gpu_real_data.sh's
# exemplars and runs) is the user's and stays.
rm -rf "$out/debs" "$out/root" "$out/shared"
mkdir -p "$out/debs" "$out/root" "$out/shared"
(cd "$out/debs" && apt-get download -q "${packages[@]}")
for deb in "$out"/debs/*.deb; do dpkg-deb -x "$deb" "$out/root"; done
# Only the headers travel: documentation and CMake files of packages whose libraries stay here.
find "$out/root" -mindepth 1 -maxdepth 1 ! -name usr -exec rm -rf {} +
find "$out/root/usr" -mindepth 1 -maxdepth 1 ! -name include -exec rm -rf {} +
for e in "${exemplars[@]}"; do
  [ -f "$shared/$e" ] || { echo "carry_deps: $shared/$e: no such file (set PPSYNTH_SHARED)" >&2; exit 2; }
  mkdir -p "$out/shared/$(dirname "$e")"
  cp "$shared/$e" "$out/shared/$e"
done
if [ ! -f "$out/real_data/amacrine.txt" ]; then
  mkdir -p "$out/real_data"
  if [ -n "${CARRY_REAL_DATA:-}" ]; then
    cp "$CARRY_REAL_DATA/amacrine.txt" "$out/real_data/amacrine.txt"
  elif command -v Rscript > /dev/null; then
    Rscript "$here/scripts/spatstat_export.R" "$out/real_data" amacrine
  else
    echo "carry_deps: no amacrine for scripts/gpu_check.sh: set CARRY_REAL_DATA to a folder with amacrine.txt, or install R with spatstat" >&2
  fi
fi
echo "carry_deps: $(ls "$out/debs" | wc -l) packages unpacked into $out/root ($(du -sh "$out" | cut -f1) in all):"
(cd "$out/debs" && ls -1)
