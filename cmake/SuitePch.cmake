# Precompiled headers (SUITE_PCH, default ON with GCC): the system headers that nearly every translation unit
# parses (standard library, PETSc, MPI, HDF5, Eigen; GoogleTest for the test executables) are compiled once
# per build instead of once per file. Parsing them is ~1.5-2 s of the ~2-10 s a file takes (ASan+UBSan -O1 and
# Release -O3 alike); the whole build's CPU time is in docs/reliability.md ("Sanitizers").
# - One PCH for the `suite` library, reused (REUSE_FROM) by every executable compiled with the same options
#   (apps, tests/mpi drivers, fuzz replays, benchmarks); GCC takes a PCH into a file that defines more -D
#   macros than the PCH was built with (LCPCOMPARE_*), not fewer. The GoogleTest executables get one PCH with
#   gtest.h added per set of options and definitions (the unit tests with SUITE_DATA_DIR, the MPI tests
#   without), and so does a target with other compile options (e.g. -fsanitize=fuzzer). A PCH that does not
#   fit is not an error: GCC parses the headers instead and -Winvalid-pch (added by CMake) says why.
# - PETSc only up to petscsys.h: petscvec.h's typedef Vec would clash with the suite's own Vec (lcp/problem.hpp)
#   in files that use both names unqualified; the other PETSc headers are included by few files.
# - petscsys.h comes first: it defines OMPI_SKIP_MPICXX, so <mpi.h> does not pull in Open MPI's deprecated C++
#   bindings (their inline code cost ~1.5 s of code generation in every file that included <mpi.h> first).
# - Every file still includes what it uses: the PCH is a build-time cache, and SUITE_PCH=OFF (the default with
#   clang, e.g. scripts/fuzz's build) must compile the same sources.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(_suite_pch_default ON)
else()
  set(_suite_pch_default OFF)
endif()
option(SUITE_PCH "Precompiled headers for the standard library, PETSc, MPI, HDF5, Eigen, GoogleTest" ${_suite_pch_default})

set(SUITE_PCH_HEADERS
    <petscsys.h> <mpi.h> <hdf5.h> <Eigen/Dense>
    <algorithm> <array> <cmath> <cstdint> <cstdio> <cstdlib> <cstring> <fstream> <functional> <iostream>
    <limits> <map> <memory> <numeric> <random> <sstream> <stdexcept> <string> <utility> <vector>)

function(_suite_pch_collect dir out)
  get_property(_targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(_subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(_sub ${_subdirs})
    _suite_pch_collect(${_sub} _more)
    list(APPEND _targets ${_more})
  endforeach()
  set(${out} ${_targets} PARENT_SCOPE)
endfunction()

# Call once at the end of the top-level CMakeLists.txt, after every target exists.
function(suite_precompile_headers)
  if(NOT SUITE_PCH OR NOT TARGET suite)
    return()
  endif()
  set(_cxx_headers "")
  foreach(_h ${SUITE_PCH_HEADERS})
    list(APPEND _cxx_headers "$<$<COMPILE_LANGUAGE:CXX>:${_h}>")
  endforeach()
  target_precompile_headers(suite PRIVATE ${_cxx_headers})
  get_target_property(_suite_opts suite COMPILE_OPTIONS)
  get_target_property(_suite_defs suite COMPILE_DEFINITIONS)
  _suite_pch_collect(${CMAKE_SOURCE_DIR} _all)
  foreach(_t ${_all})
    get_target_property(_type ${_t} TYPE)
    if(_t STREQUAL "suite" OR NOT _type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY)$")
      continue()
    endif()
    get_target_property(_opts ${_t} COMPILE_OPTIONS)
    get_target_property(_defs ${_t} COMPILE_DEFINITIONS)
    get_target_property(_libs ${_t} LINK_LIBRARIES)
    set(_headers ${_cxx_headers})
    if("GTest::gtest" IN_LIST _libs OR "GTest::GTest" IN_LIST _libs)
      list(APPEND _headers "$<$<COMPILE_LANGUAGE:CXX>:<gtest/gtest.h>>")
      set(_key "gtest;${_opts};${_defs}")
    elseif("${_opts}" STREQUAL "${_suite_opts}" AND (CMAKE_CXX_COMPILER_ID STREQUAL "GNU" OR "${_defs}" STREQUAL "${_suite_defs}"))
      # GCC takes a PCH into a file that defines more macros (unused by the headers), not fewer.
      set_target_properties(${_t} PROPERTIES PRECOMPILE_HEADERS_REUSE_FROM suite)
      continue()
    else()
      set(_key "plain;${_opts};${_defs}")
    endif()
    # Targets with the same options and definitions share one PCH (GoogleTest's: the unit tests, the MPI tests).
    string(MD5 _key "${_key}")
    if(DEFINED _suite_pch_${_key})
      set_target_properties(${_t} PROPERTIES PRECOMPILE_HEADERS_REUSE_FROM ${_suite_pch_${_key}})
    else()
      target_precompile_headers(${_t} PRIVATE ${_headers})
      set(_suite_pch_${_key} ${_t})
    endif()
  endforeach()
endfunction()
