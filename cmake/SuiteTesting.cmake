# Test helpers shared by every tests/ folder.
#   suite_add_mpi_test(NAME n NP p COMMAND exe args... [LABELS l...])
#       runs `mpiexec -n p --oversubscribe exe args...` (run-as-root variables set).
#   suite_add_failure_test(NAME n NP p EXPECT "regex" COMMAND exe args... [LABELS l...])
#       passes when the command exits non-zero AND the regex matches exactly one line of its output
#       (one clear message, not one per rank) AND it finishes before the timeout (no hang). Label bad_input.
#   suite_add_output_test(NAME n NP p EXPECT "regex"... [REJECT "regex"...] COMMAND exe args... [LABELS l...])
#       passes when the command exits 0 AND every EXPECT regex is found in its output AND no REJECT regex is
#       (Python regexes over the whole output, `.` spanning lines; tests/expect_output.py).
#   suite_add_python_test(NAME n SCRIPT file.py [ARGS ...] [LABELS ...])
find_program(MPIEXEC_EXECUTABLE NAMES mpiexec mpirun REQUIRED)
set(SUITE_MPIEXEC ${MPIEXEC_EXECUTABLE} --oversubscribe)
# Every test runs its ranks on this one machine: Open MPI's shared-memory transport only (pml ob1, btl
# self,vader; its default start probes the network: ~0.25 s of waiting per start, also of a 1-rank run), and a
# job whose rank exits non-zero is ended at once (odls_base_sigkill_timeout 0; the default waits 1 s twice before
# it kills what is left: 2 s of every refused run, also of `mpiexec -n 2 sh -c 'exit 1'`; the message is printed
# before any rank exits, the ranks passing MPI_Finalize together, so nothing is lost). The tests that signal
# mpiexec set Open MPI's default back. Measured on the 2-core machine, label bad_input: 305 s -> 50 s of wall
# time at the same CPU time. hwloc skips its PCI scan (HWLOC_COMPONENTS=-pci: a sixth of a singleton start's CPU
# time reading PCI configuration space, used only to place network cards). Daemon-less singletons
# (ess_singleton_isolated) are not set here: they share one job id, so two tests running at once would share, and
# the first to finish would remove, the session directory that MPI-IO maps files in; the hostile-values test,
# which gains most from them, gives each of its runs a session directory of its own (tests/hostile).
set(SUITE_TEST_ENV "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
list(APPEND SUITE_TEST_ENV "OMPI_MCA_pml=ob1;OMPI_MCA_btl=self,vader;OMPI_MCA_odls_base_sigkill_timeout=0")
list(APPEND SUITE_TEST_ENV "HWLOC_COMPONENTS=-pci")
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(SUITE_PYTHON ${Python3_EXECUTABLE} CACHE FILEPATH "Python for test drivers")
set(SUITE_DATA_DIR ${CMAKE_SOURCE_DIR}/../shared/data CACHE PATH "Reference data (Harwell-Boeing, Siconos)")

function(suite_add_mpi_test)
  cmake_parse_arguments(T "" "NAME;NP;TIMEOUT" "COMMAND;LABELS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  add_test(NAME ${T_NAME} COMMAND ${SUITE_MPIEXEC} -n ${T_NP} ${T_COMMAND}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${T_NAME} PROPERTIES ENVIRONMENT "${SUITE_TEST_ENV}" TIMEOUT ${T_TIMEOUT}
                       LABELS "${T_LABELS}" PROCESSORS ${T_NP})
endfunction()

function(suite_add_failure_test)
  cmake_parse_arguments(T "" "NAME;NP;EXPECT;TIMEOUT" "COMMAND;LABELS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 60)
  endif()
  add_test(NAME ${T_NAME}
           COMMAND ${SUITE_PYTHON} ${CMAKE_SOURCE_DIR}/tests/expect_failure.py --expect "${T_EXPECT}"
                   --timeout ${T_TIMEOUT} -- ${SUITE_MPIEXEC} -n ${T_NP} ${T_COMMAND}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  # Label bad_input: scripts/test-asan runs a bad-input check that exists at 1 and 2 ranks (..._np1 beside
  # ..._np2) at 2 ranks only, where the same checking code runs on each rank.
  set_tests_properties(${T_NAME} PROPERTIES ENVIRONMENT "${SUITE_TEST_ENV}" TIMEOUT ${T_TIMEOUT}
                       LABELS "${T_LABELS};bad_input" PROCESSORS ${T_NP})
endfunction()

function(suite_add_output_test)
  cmake_parse_arguments(T "" "NAME;NP;TIMEOUT" "EXPECT;REJECT;COMMAND;LABELS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 60)
  endif()
  set(_patterns)
  foreach(_rx IN LISTS T_EXPECT)
    list(APPEND _patterns "--expect=${_rx}")
  endforeach()
  foreach(_rx IN LISTS T_REJECT)
    list(APPEND _patterns "--reject=${_rx}")
  endforeach()
  add_test(NAME ${T_NAME}
           COMMAND ${SUITE_PYTHON} ${CMAKE_SOURCE_DIR}/tests/expect_output.py ${_patterns} --timeout ${T_TIMEOUT}
                   -- ${SUITE_MPIEXEC} -n ${T_NP} ${T_COMMAND}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${T_NAME} PROPERTIES ENVIRONMENT "${SUITE_TEST_ENV}" TIMEOUT ${T_TIMEOUT}
                       LABELS "${T_LABELS}" PROCESSORS ${T_NP})
endfunction()

function(suite_add_python_test)
  cmake_parse_arguments(T "" "NAME;SCRIPT;TIMEOUT" "ARGS;LABELS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  add_test(NAME ${T_NAME} COMMAND ${SUITE_PYTHON} ${T_SCRIPT} ${T_ARGS}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${T_NAME} PROPERTIES
                       ENVIRONMENT "${SUITE_TEST_ENV};SUITE_BIN=${CMAKE_BINARY_DIR}/bin;SUITE_SOURCE=${CMAKE_SOURCE_DIR};SUITE_DATA=${SUITE_DATA_DIR};PYTHONPATH=${CMAKE_SOURCE_DIR}"
                       TIMEOUT ${T_TIMEOUT} LABELS "${T_LABELS}")
endfunction()

# One GoogleTest executable per folder tests/unit/<area>/ (custom main with PETSc initialised), every test case
# registered with ctest (label unit).
function(suite_add_unit_area area)
  file(GLOB _srcs CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/unit/${area}/*.cpp)
  if(NOT _srcs)
    return()
  endif()
  add_executable(unit_${area} ${_srcs} ${CMAKE_SOURCE_DIR}/tests/unit/gtest_petsc_main.cpp)
  target_link_libraries(unit_${area} PRIVATE suite GTest::gtest)
  target_compile_definitions(unit_${area} PRIVATE SUITE_DATA_DIR="${SUITE_DATA_DIR}")
  gtest_discover_tests(unit_${area} DISCOVERY_TIMEOUT 60)
  # gtest_discover_tests writes a list-valued PROPERTIES entry as separate arguments (CMake 3.25: only the first
  # label or variable would stick): the cases' labels and environment come from a file ctest reads after the
  # discovery's, over the list of discovered cases (unit_<area>_TESTS).
  set(_props ${CMAKE_CURRENT_BINARY_DIR}/unit_${area}_properties.cmake)
  file(GENERATE OUTPUT ${_props} CONTENT "if(unit_${area}_TESTS)
  set_tests_properties(\${unit_${area}_TESTS} PROPERTIES LABELS unit ENVIRONMENT \"${SUITE_TEST_ENV}\")
endif()
")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${_props})
endfunction()
