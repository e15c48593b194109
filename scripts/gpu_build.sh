# shellcheck shell=bash
# Sourced by the scripts that run on a GPU machine of the device tool (scripts/gpu_check.sh,
# docs/lab/verdict/gpu_real_data.sh): no Debian packages, no network, a torch wheel, CMake and ninja.
# Defines
#   gpu_python             the python3 that imports torch (its LibTorch is what we build with)
#   gpu_describe DEVICE    lines on the machine: cores, compilers, torch, the GPU (fails on cuda
#                          without nvidia-smi)
#   gpu_build OUT BUILD [TARGET...]
#                          configure and build the targets (default: ppsynth and ppsynth_tests;
#                          ppsynth alone saves about a minute) in BUILD against the
#                          wheel's LibTorch, with the headers carried in .deps/root
#                          (scripts/carry_deps.sh) and without cairo; OUT/configure.log and
#                          OUT/build.log; prints ppsynth's configure lines; non-zero on failure
# and exports PPSYNTH_SHARED=.deps/shared (the exemplars the configs name as shared:data/...).
gpu_here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PPSYNTH_SHARED="$gpu_here/.deps/shared"

gpu_python() {
  local p
  for p in python3 /usr/bin/python3; do
    if command -v "$p" > /dev/null && "$p" -c 'import torch' 2> /dev/null; then echo "$p"; return 0; fi
  done
  echo "no python3 with torch: the build takes the wheel's LibTorch (torch.utils.cmake_prefix_path)" >&2
  return 1
}

gpu_describe() {
  local py
  py="$(gpu_python)" || return 1
  echo "$(uname -m), $(nproc) cores; $(c++ --version | head -1); $(cmake --version | head -1); ninja $(ninja --version 2> /dev/null || echo missing)"
  echo "torch: $("$py" -c 'import torch; print(torch.__version__, "CUDA", torch.version.cuda, "devices", torch.cuda.device_count() if torch.cuda.is_available() else 0)')"
  if command -v nvidia-smi > /dev/null; then
    echo "GPU: $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader | head -1)"
  elif [ "$1" = cuda ]; then
    echo "no nvidia-smi on a run on cuda (the dry run takes cpu)" >&2
    return 1
  fi
}

gpu_build() {
  local out=$1 build=$2 py torch_prefix
  shift 2
  local targets=("$@")
  [ ${#targets[@]} -gt 0 ] || targets=(ppsynth ppsynth_tests)
  py="$(gpu_python)" || return 1
  [ -f "$gpu_here/.deps/root/usr/include/nanoflann.hpp" ] ||
    { echo "no .deps/root: run scripts/carry_deps.sh on a Debian machine and carry .deps" >&2; return 1; }
  torch_prefix="$("$py" -c 'import torch; print(torch.utils.cmake_prefix_path)')"
  local cuda_flags=()
  if command -v nvcc > /dev/null; then
    # A CUDA LibTorch's CMake config enables the CUDA language; Hopper is sm_90.
    cuda_flags=(-DCMAKE_CUDA_COMPILER="$(command -v nvcc)" -DCMAKE_CUDA_ARCHITECTURES=90)
    export TORCH_CUDA_ARCH_LIST="${TORCH_CUDA_ARCH_LIST:-9.0}"
  fi
  echo "configure: LibTorch from $torch_prefix, dependencies from .deps/root, no cairo"
  cmake -S "$gpu_here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$torch_prefix" \
    -DPPSYNTH_DEPS_DIR="$gpu_here/.deps/root" -DPPSYNTH_WITH_CAIRO=OFF -DPPSYNTH_PYTHON=OFF "${cuda_flags[@]}" \
    > "$out/configure.log" 2>&1 || { tail -n 40 "$out/configure.log"; echo "configure failed (configure.log)" >&2; return 1; }
  grep "ppsynth:" "$out/configure.log"
  echo "build: ${targets[*]} ($(nproc) jobs)"
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]}" > "$out/build.log" 2>&1 ||
    { grep -m 20 -A 5 "error" "$out/build.log"; tail -n 20 "$out/build.log"; echo "build failed (build.log)" >&2; return 1; }
  echo "built"
}
