# The header-only dependencies from unpacked Debian packages (PPSYNTH_DEPS_DIR, filled by
# scripts/carry_deps.sh), for a machine that cannot install packages: the targets that
# find_package gives on a Debian machine, as interface targets on <dir>/usr/include.
# spdlog is used header-only here, on fmt header-only (Debian's spdlog is built against the
# external fmt, which its tweakme.h names, so FMT_HEADER_ONLY is all that differs).
set(_ppsynth_inc "${PPSYNTH_DEPS_DIR}/usr/include")
foreach(header nlohmann/json.hpp nanoflann.hpp CLI/CLI.hpp catch2/catch.hpp spdlog/spdlog.h fmt/format.h)
  if(NOT EXISTS "${_ppsynth_inc}/${header}")
    message(FATAL_ERROR "PPSYNTH_DEPS_DIR=${PPSYNTH_DEPS_DIR}: no ${header} under usr/include "
                        "(scripts/carry_deps.sh unpacks the packages there)")
  endif()
endforeach()
foreach(target nlohmann_json::nlohmann_json nanoflann::nanoflann CLI11::CLI11 Catch2::Catch2 spdlog::spdlog)
  add_library(${target} INTERFACE IMPORTED)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_ppsynth_inc}")
endforeach()
set_target_properties(spdlog::spdlog PROPERTIES INTERFACE_COMPILE_DEFINITIONS "SPDLOG_FMT_EXTERNAL;FMT_HEADER_ONLY")
message(STATUS "ppsynth: header-only dependencies from ${PPSYNTH_DEPS_DIR}")
