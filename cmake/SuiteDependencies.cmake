# Finds every dependency of the suite; a missing one stops cmake with one line naming the Debian package.
include(FindPkgConfig)

function(suite_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "Missing dependency: ${what}. Install the Debian package '${package}' "
                        "(or run scripts/install-deps).")
  endif()
endfunction()

find_package(PkgConfig QUIET)
suite_require(PKG_CONFIG_FOUND "pkg-config" "pkg-config")

pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc>=3.18)
suite_require(PETSC_FOUND "PETSc >= 3.18 (pkg-config PETSc)" "petsc-dev")

find_package(MPI QUIET COMPONENTS C CXX)
suite_require(MPI_FOUND "MPI (C and C++)" "libopenmpi-dev")

set(HDF5_PREFER_PARALLEL TRUE)
find_package(HDF5 QUIET COMPONENTS C HL)
suite_require(HDF5_FOUND "HDF5 with the high-level library" "libhdf5-openmpi-dev")
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "Missing dependency: the HDF5 found (${HDF5_INCLUDE_DIRS}) is serial; "
                      "install the Debian package 'libhdf5-openmpi-dev'.")
endif()

find_package(Eigen3 3.3 QUIET NO_MODULE)
suite_require(Eigen3_FOUND "Eigen3" "libeigen3-dev")

find_path(FFTW_INCLUDE_DIR fftw3.h)
find_library(FFTW_LIBRARY fftw3)
find_library(FFTW_MPI_LIBRARY fftw3_mpi)
suite_require(FFTW_INCLUDE_DIR "FFTW3 headers" "libfftw3-dev")
suite_require(FFTW_LIBRARY "FFTW3 library" "libfftw3-dev")
suite_require(FFTW_MPI_LIBRARY "FFTW3 MPI library" "libfftw3-mpi-dev")

find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
suite_require(SUITESPARSE_INCLUDE_DIR "SuiteSparse headers (cholmod.h)" "libsuitesparse-dev")
set(SUITESPARSE_LIBRARIES)
foreach(lib cholmod umfpack amd camd colamd ccolamd suitesparseconfig)
  find_library(SUITESPARSE_${lib}_LIBRARY ${lib})
  suite_require(SUITESPARSE_${lib}_LIBRARY "SuiteSparse ${lib} library" "libsuitesparse-dev")
  list(APPEND SUITESPARSE_LIBRARIES ${SUITESPARSE_${lib}_LIBRARY})
endforeach()

# The OpenMP runtime CHOLMOD is built with (Debian's libcholmod links libgomp): fem/solver_cholmod.cpp switches
# CHOLMOD's OpenMP loops off or on (-cholmod_openmp); no suite source is compiled with OpenMP.
find_package(OpenMP QUIET COMPONENTS CXX)
suite_require(OpenMP_CXX_FOUND "the OpenMP runtime of the compiler (libgomp)" "build-essential")

# libyaml: the options file check (lib/core/options_file_check) parses YAML run decks itself, to report the line.
find_path(YAML_INCLUDE_DIR yaml.h)
find_library(YAML_LIBRARY yaml)
suite_require(YAML_INCLUDE_DIR "libyaml headers (yaml.h)" "libyaml-dev")
suite_require(YAML_LIBRARY "libyaml library" "libyaml-dev")

# muParser: the Euler app's formula initial states and boundary states (lib/core/expression).
find_path(MUPARSER_INCLUDE_DIR muParser.h)
find_library(MUPARSER_LIBRARY muparser)
suite_require(MUPARSER_INCLUDE_DIR "muParser headers (muParser.h)" "libmuparser-dev")
suite_require(MUPARSER_LIBRARY "muParser library" "libmuparser-dev")

# tinyxml2: the contact app's MJCF model files (lib/contact/mjcf).
find_path(TINYXML2_INCLUDE_DIR tinyxml2.h)
find_library(TINYXML2_LIBRARY tinyxml2)
suite_require(TINYXML2_INCLUDE_DIR "tinyxml2 headers (tinyxml2.h)" "libtinyxml2-dev")
suite_require(TINYXML2_LIBRARY "tinyxml2 library" "libtinyxml2-dev")

find_path(METIS_INCLUDE_DIR metis.h)
find_library(METIS_LIBRARY metis)
suite_require(METIS_INCLUDE_DIR "METIS headers" "libmetis-dev")
suite_require(METIS_LIBRARY "METIS library" "libmetis-dev")

# Optimised BLAS/LAPACK: Debian's alternatives select OpenBLAS when libopenblas-dev is installed.
find_library(OPENBLAS_LIBRARY openblas)
suite_require(OPENBLAS_LIBRARY "OpenBLAS" "libopenblas-dev")
