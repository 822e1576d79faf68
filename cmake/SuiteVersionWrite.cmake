# Writes the version source (script mode, cmake -P): `git describe --always --dirty --tags` of SRC_DIR appended
# to PROJECT_VERSION, else PROJECT_VERSION alone, into OUT from TEMPLATE. configure_file rewrites OUT only when
# the string changes, so a build recompiles version.cpp only after a commit or a change of the tree's state.
find_program(GIT_EXECUTABLE git)
set(SUITE_VERSION "${PROJECT_VERSION}")
if(GIT_EXECUTABLE AND EXISTS ${SRC_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags
                  WORKING_DIRECTORY ${SRC_DIR} OUTPUT_VARIABLE _describe
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _rc)
  if(_rc EQUAL 0 AND _describe)
    set(SUITE_VERSION "${PROJECT_VERSION}-${_describe}")
  endif()
endif()
configure_file(${TEMPLATE} ${OUT} @ONLY)
