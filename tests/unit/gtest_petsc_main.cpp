// GoogleTest main for the unit tests: PETSc (and MPI) initialised around the whole run, so tests may use
// PETSc objects; exits non-zero on any failure on any rank.
#include <gtest/gtest.h>
#include <petscsys.h>

#include "core/sanitizer_defaults.hpp"

int main(int argc, char** argv) {
  suite::keepSanitizerDefaults();
  ::testing::InitGoogleTest(&argc, argv);
  PetscErrorCode ierr = PetscInitialize(&argc, &argv, nullptr, nullptr);
  if (ierr) return 1;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank != 0) ::testing::GTEST_FLAG(output) = "";
  int failed = RUN_ALL_TESTS();
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscFinalize();
  return any ? 1 : 0;
}
