// Problem file readers of the LCP library.
//
// Siconos numerics text format (.dat; Acary & Brogliato 2008, Siconos numerics test data): whitespace-
// separated numbers, dense matrices in column-major order (Siconos' NumericsMatrix storage 0).
//   LCP    "lcp_*.dat":   n, storage type (0 = dense), rows, cols, rows cols, M (n*n), q (n)
//   relay  "relay_*.dat": the same, then lb (n), ub (n)                      -> box LCP
//   MLCP   "*_mlcp.dat":  isStorageType1, isStorageType2, n (equalities), m (complementarities); if type 1:
//          block row starts ending at n+m, one 0/1 "is complementarity" flag per block, then M as above
//          (size n+m) and q; if type 2: A (n x n), B (m x m), C (n x m), D (m x n) row-wise, a, b, with
//          M = [A C; D B], q = [a; b].  Equality rows become free variables (l = -inf, u = +inf).
//   Anything after the last number needed is a comment. Kind: relay if the file name starts with "relay"
//   (or 2n numbers follow q), MLCP if it contains "mlcp".
//
// Suite HDF5 problem format (one problem per file; read collectively with suite::H5Input):
//   /q        float64 (n)             required
//   /M        float64 (n, n)          dense, row-major (M[i][j] = row i, column j), or instead
//   /M_csr/indptr (n+1), /M_csr/indices (nnz), /M_csr/data (nnz)   CSR, 0-based column indices
//   /l, /u    float64 (n)             optional bounds (defaults 0 and +inf; IEEE +-inf allowed)
//   /z_known  float64 (n)             optional known solution
//   root attribute "n_eq" (integer, optional): the first n_eq variables are free (MLCP equality block)
//   root attribute "kind" (string, optional): "lcp", "box" or "mlcp" (informative)
//
// FCLib local frictional-contact problems (FCLib HDF5 files, group /fclib_local: W, q, mu, spacedim; layout in
// reader_fclib.cpp): the frictionless (normal-contact) LCP is extracted, 0 <= r_n _|_ W_nn r_n + q_n >= 0,
// with W_nn the rows and columns of the normal directions (local index spacedim * contact) and q_n likewise;
// the friction coefficients are validated but a Coulomb cone is not an LCP and is not used. Read with the
// suite's HDF5 (not libfclib, which links the serial libhdf5). Global problems (M, H, G) and mixed local
// problems (V, R) are refused with a clear message.
#pragma once

#include "lcp/problem.hpp"

#include <petscsys.h>

#include <string>

namespace suite::lcp {

// Throws std::runtime_error("<file>: <what is wrong>") on a missing, truncated or malformed file.
Problem readSiconos(const std::string& path);
Problem parseSiconos(const std::string& text, const std::string& name);

// FCLib (serial, per rank): throws std::runtime_error("<file>: <what is wrong>"); at most 8192 contacts.
// Normal: the frictionless normal-contact LCP (nc unknowns). BoxFriction: all spacedim * nc unknowns of W
// as a box LCP, tangential bounds +-mu_c * rhat_c with rhat_c the normal forces of the frictionless problem
// (the box-friction model of Lacoursiere 2003; at most 6144 unknowns, dense).
enum class FclibModel { Normal, BoxFriction };
Problem readFclibLocal(const std::string& path, FclibModel model = FclibModel::Normal);
// True when path is an HDF5 file with an /fclib_local or /fclib_global group.
bool isFclibFile(const std::string& path);

// Collective on comm; a malformed file is a PETSc error with a message naming the file.
PetscErrorCode readProblemH5(MPI_Comm comm, const std::string& path, Problem* p);
// Collective; writes p in the format above (dense M).
PetscErrorCode writeProblemH5(MPI_Comm comm, const std::string& path, const Problem& p);

} // namespace suite::lcp
