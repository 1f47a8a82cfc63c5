# Precompiled headers. Eigen, the C++ library and GoogleTest are most of what a translation unit parses: about two
# thirds of a unit test's compile time, a third of a solver file's. One header set per kind of target is formed once
# (by poro_core for the libraries and executables, by unit_core for the tests) and reused by every other target of
# that kind: GCC takes it where the flags and the definitions it was formed with are the same (-Winvalid-pch warns
# where not). Code generation is unchanged: only the parsing is saved.
# -DPOROSPH_PCH=OFF builds without them, which shows a file that uses a header it does not include.
option(POROSPH_PCH "Precompile the headers most files include (Eigen, the C++ library, GoogleTest)" ON)

set(POROSPH_PCH_HEADERS <Eigen/Core> <Eigen/Geometry> <algorithm> <array> <cmath> <cstdint> <filesystem> <limits>
    <map> <optional> <sstream> <string> <vector>)

# poro_precompile(<target> library|test): the target uses its kind's precompiled headers.
function(poro_precompile target kind)
  if(NOT POROSPH_PCH)
    return()
  endif()
  if(kind STREQUAL "library")
    set(owner poro_core)
    set(headers ${POROSPH_PCH_HEADERS})
  elseif(kind STREQUAL "test")
    set(owner unit_core)
    set(headers ${POROSPH_PCH_HEADERS} <gtest/gtest.h>)
  else()
    message(FATAL_ERROR "poro_precompile: kind is library or test, not '${kind}'")
  endif()
  if(target STREQUAL owner)
    target_precompile_headers(${target} PRIVATE ${headers})
  else()
    target_precompile_headers(${target} REUSE_FROM ${owner})
  endif()
endfunction()
