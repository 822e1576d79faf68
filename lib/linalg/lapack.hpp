// Fortran LAPACK prototypes used by lib/linalg (Debian's liblapack / OpenBLAS; no LAPACKE needed).
#pragma once

extern "C" {
// General tridiagonal solve with partial pivoting (overwrites dl, d, du and b).
void dgtsv_(const int* n, const int* nrhs, double* dl, double* d, double* du, double* b, const int* ldb,
            int* info);
// General band solve with partial pivoting; ab holds 2*kl+ku+1 rows (LAPACK band storage).
void dgbsv_(const int* n, const int* kl, const int* ku, const int* nrhs, double* ab, const int* ldab,
            int* ipiv, double* b, const int* ldb, int* info);
// General dense solve with partial pivoting.
void dgesv_(const int* n, const int* nrhs, double* a, const int* lda, int* ipiv, double* b, const int* ldb,
            int* info);
}
