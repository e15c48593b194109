# LibTorch: Debian's 1.13 (CPU) from the system, or any other that CMAKE_PREFIX_PATH finds,
# such as a pip wheel's with CUDA:
#   cmake -DCMAKE_PREFIX_PATH="$(python3 -c 'import torch; print(torch.utils.cmake_prefix_path)')" ...
# (a CUDA LibTorch's config enables CMake's CUDA language, so nvcc must be on PATH or CUDACXX).
# Included from CMakeLists.txt before any target: the version decides the C++ standard.
find_package(Torch REQUIRED)
if(TARGET torch_cuda)
  set(PPSYNTH_TORCH_CUDA yes)
else()
  set(PPSYNTH_TORCH_CUDA no)
endif()
message(STATUS "ppsynth: LibTorch ${Torch_VERSION} in ${Torch_DIR}; CUDA: ${PPSYNTH_TORCH_CUDA}")

# LibTorch 2.12 and later refuse to compile below C++20; 1.13 to 2.11 take C++17.
if(Torch_VERSION VERSION_GREATER_EQUAL 2.12)
  set(CMAKE_CXX_STANDARD 20)
endif()

# The C++ ABI LibTorch was built with: the torch libraries get TORCH_CXX_FLAGS, and every other
# object must agree, since core passes std::string and containers to them. Debian's and
# recent wheels' use the compiler's default (the C++11 ABI); older wheels the pre-C++11 one.
if(TORCH_CXX_FLAGS MATCHES "_GLIBCXX_USE_CXX11_ABI=0")
  add_compile_definitions(_GLIBCXX_USE_CXX11_ABI=0)
endif()
