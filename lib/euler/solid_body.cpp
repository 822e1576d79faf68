// Solid obstacles from a formula or a mask file (see solid_body.hpp).
#include "euler/solid_body.hpp"

#include "core/error_handler.hpp"
#include "core/expression.hpp"
#include "core/option_value.hpp"
#include "io/h5_input.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

namespace suite::euler {

PetscErrorCode readSolidOptions(MPI_Comm comm, ProblemND* pr) {
  std::string formula, mask, group = "/";
  PetscBool has_formula = PETSC_FALSE, has_mask = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Solid obstacle options", "");
  PetscCall(suite::optionsString(PetscOptionsObject, "-solid",
                                 "Solid obstacle: cells whose centre has formula(x[, y[, z]]) > 0 are solid",
                                 &formula, &has_formula));
  PetscCall(suite::optionsString(
      PetscOptionsObject, "-solid_mask",
      "Solid obstacle from an HDF5 file: dataset mask on the grid, non-zero = solid", &mask, &has_mask));
  if (has_mask)
    PetscCall(suite::optionsString(PetscOptionsObject, "-solid_mask_group",
                                   "Group of -solid_mask holding the dataset mask (/final: a run's output)",
                                   &group, nullptr));
  PetscOptionsEnd();
  PetscCheck(!(has_formula && has_mask), comm, PETSC_ERR_ARG_WRONG,
             "-solid and -solid_mask: give one obstacle");
  PetscCheck(!(has_formula || has_mask) || !pr->hasSolid(), comm, PETSC_ERR_ARG_WRONG,
             "-problem %s has its obstacle built in: -solid and -solid_mask are refused", pr->name.c_str());
  if (has_formula) {
    std::vector<std::string> vars = {"x", "y", "z"};
    vars.resize(pr->dim);
    std::shared_ptr<const suite::Expression> e;
    PetscCall(suite::Expression::create(comm, "-solid", formula, vars, {}, &e));
    pr->solid = [e](const double* x) { return (*e)(x); };
  }
  if (has_mask) {
    PetscCheck(!mask.empty(), comm, PETSC_ERR_ARG_WRONG, "-solid_mask needs a file name");
    suite::H5Input in;
    suite::Dims dims;
    PetscCall(in.open(comm, mask));
    const std::string ds = (group == "/" ? std::string("/") : group + "/") + "mask";
    PetscCall(in.datasetDims(ds, &dims));
    PetscCheck((int)dims.size() == pr->dim, comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: dataset %s has %d dimensions; a %dD grid's mask has %d", mask.c_str(), ds.c_str(),
               (int)dims.size(), pr->dim, pr->dim);
    pr->solid_mask_file = mask;
    pr->solid_mask_group = group;
  }
  PetscFunctionReturn(0);
}

namespace {
std::string cellName(int dim, PetscInt i, PetscInt j, PetscInt k) {
  char buf[96];
  if (dim == 1) std::snprintf(buf, sizeof buf, "cell i = %d", (int)i);
  if (dim == 2) std::snprintf(buf, sizeof buf, "cell (i, j) = (%d, %d)", (int)i, (int)j);
  if (dim == 3) std::snprintf(buf, sizeof buf, "cell (i, j, k) = (%d, %d, %d)", (int)i, (int)j, (int)k);
  return buf;
}

PetscErrorCode maskFromFile(MPI_Comm comm, const ProblemND& pr, const PetscInt n[3], const PetscInt s[3],
                            const PetscInt m[3], std::vector<char>* solid) {
  suite::H5Input in;
  suite::Dims dims, start, count;
  PetscFunctionBeginUser;
  const std::string ds = (pr.solid_mask_group == "/" ? std::string("/") : pr.solid_mask_group + "/") + "mask";
  PetscCall(in.open(comm, pr.solid_mask_file));
  PetscCall(in.datasetDims(ds, &dims));
  for (int d = pr.dim - 1; d >= 0; --d) {
    PetscCheck(dims[pr.dim - 1 - d] == (unsigned long long)n[d], comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: dataset %s has %llu cells along %c, the grid %d", pr.solid_mask_file.c_str(), ds.c_str(),
               dims[pr.dim - 1 - d], 'x' + d, (int)n[d]);
    start.push_back((unsigned long long)s[d]);
    count.push_back((unsigned long long)m[d]);
  }
  std::vector<double> v((size_t)m[0] * m[1] * m[2]);
  PetscCall(in.readBlock(ds, start, count, v.data()));
  std::string bad;
  for (size_t c = 0; c < v.size(); ++c) {
    if (!std::isfinite(v[c]) && bad.empty())
      bad = pr.solid_mask_file + ": dataset " + ds + " is not finite at " +
            cellName(pr.dim, s[0] + (PetscInt)(c % m[0]), s[1] + (PetscInt)((c / m[0]) % m[1]),
                     s[2] + (PetscInt)(c / ((size_t)m[0] * m[1])));
    (*solid)[c] = v[c] != 0.0;
  }
  PetscCall(suite::agreeOnFailure(comm, &bad));
  PetscCheck(bad.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "%s", bad.c_str());
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode solidCells(MPI_Comm comm, const ProblemND& pr, const PetscInt n[3], const PetscInt s[3],
                          const PetscInt m[3], std::vector<char>* solid) {
  PetscFunctionBeginUser;
  solid->assign((size_t)m[0] * m[1] * m[2], 0);
  if (!pr.solid_mask_file.empty()) {
    PetscCall(maskFromFile(comm, pr, n, s, m, solid));
  } else if (pr.solid) {
    std::string bad;
    size_t c = 0;
    for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + m[0]; ++i, ++c) {
          const PetscInt idx[3] = {i, j, k};
          double x[3];
          for (int d = 0; d < 3; ++d)
            x[d] = d < pr.dim ? pr.lo[d] + (idx[d] + 0.5) * ((pr.hi[d] - pr.lo[d]) / n[d]) : 0.0;
          const double v = pr.solid(x);
          if (!std::isfinite(v) && bad.empty())
            bad = "the solid formula (-solid) is not finite (" + std::to_string(v) + ") at " +
                  cellName(pr.dim, i, j, k);
          (*solid)[c] = v > 0.0;
        }
    PetscCall(suite::agreeOnFailure(comm, &bad));
    PetscCheck(bad.empty(), comm, PETSC_ERR_ARG_WRONG, "%s", bad.c_str());
  }
  long long fluid = 0;
  for (char v : *solid) fluid += !v;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &fluid, 1, MPI_LONG_LONG, MPI_SUM, comm));
  PetscCheck(fluid > 0, comm, PETSC_ERR_ARG_WRONG, "The solid obstacle covers every cell: no fluid is left");
  PetscFunctionReturn(0);
}

} // namespace suite::euler
