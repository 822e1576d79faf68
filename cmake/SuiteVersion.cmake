# Version string for provenance (every output file's `version` attribute): `git describe` of the source tree,
# else the project version. Written at configure time (so that the file exists) and again by the target
# suite_version at every build (cmake/SuiteVersionWrite.cmake; the file changes only when the string does): a
# configure-time string alone goes stale with incremental builds (outputs of a later commit would carry the hash
# of the tree last configured).
set(SUITE_VERSION_CPP ${CMAKE_BINARY_DIR}/generated/version.cpp)
set(_suite_version_args -DSRC_DIR=${CMAKE_SOURCE_DIR} -DOUT=${SUITE_VERSION_CPP}
                        -DPROJECT_VERSION=${PROJECT_VERSION} -DTEMPLATE=${CMAKE_SOURCE_DIR}/cmake/version.cpp.in)
execute_process(COMMAND ${CMAKE_COMMAND} ${_suite_version_args} -P ${CMAKE_SOURCE_DIR}/cmake/SuiteVersionWrite.cmake)
file(STRINGS ${SUITE_VERSION_CPP} _suite_version_line REGEX "return")
string(REGEX REPLACE ".*return \"([^\"]*)\".*" "\\1" _suite_version "${_suite_version_line}")
message(STATUS "Suite version: ${_suite_version}")
add_custom_target(suite_version
                  COMMAND ${CMAKE_COMMAND} ${_suite_version_args} -P ${CMAKE_SOURCE_DIR}/cmake/SuiteVersionWrite.cmake
                  BYPRODUCTS ${SUITE_VERSION_CPP} VERBATIM)
