# Version string for provenance: `git describe` at configure time, else the project version.
find_package(Git QUIET)
set(SUITE_VERSION "${PROJECT_VERSION}")
if(GIT_FOUND AND EXISTS ${CMAKE_SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags
                  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR} OUTPUT_VARIABLE _describe
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _rc)
  if(_rc EQUAL 0 AND _describe)
    set(SUITE_VERSION "${PROJECT_VERSION}-${_describe}")
  endif()
endif()
message(STATUS "Suite version: ${SUITE_VERSION}")
configure_file(${CMAKE_SOURCE_DIR}/cmake/version.cpp.in ${CMAKE_BINARY_DIR}/generated/version.cpp @ONLY)
