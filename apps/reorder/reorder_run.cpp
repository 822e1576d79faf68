// reorder: see main.cpp. Ordering time: minimum over -repeat runs of the thread CPU time (fem/cpu_timer.hpp).
#include "reorder_run.hpp"

#include "core/log.hpp"
#include "core/named_choice.hpp"
#include "fem/cpu_timer.hpp"
#include "fem/matrix_market.hpp"
#include "fem/ordering.hpp"
#include "io/h5_output.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace reorder_app {

using namespace suite::fem;

namespace {
struct Options {
  std::string matrix, output, ordering = "all";
  PetscInt repeat = 3;
};

PetscErrorCode readOptions(MPI_Comm comm, Options* o) {
  char matrix[PETSC_MAX_PATH_LEN] = "", output[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  // The registered orderings (lib/fem/ordering.cpp), each with its help line, and "all" of them.
  std::vector<suite::Choice> choices = orderingChoices();
  choices.push_back({"all", "every ordering above, in this order"});
  PetscOptionsBegin(comm, "", "reorder options", "");
  PetscCall(PetscOptionsString("-matrix", "Matrix Market file (coordinate; symmetric or general)", "", matrix,
                               matrix, sizeof matrix, nullptr));
  PetscCall(
      suite::optionsChoice(PetscOptionsObject, "-ordering", "Fill-reducing ordering", choices, &o->ordering));
  PetscCall(PetscOptionsString("-output", "HDF5 output file", "", output, output, sizeof output, nullptr));
  PetscCall(PetscOptionsInt("-repeat", "Ordering time = minimum over this many runs", "", o->repeat,
                            &o->repeat, nullptr));
  PetscOptionsEnd();
  o->matrix = matrix, o->output = output;
  PetscFunctionReturn(0);
}

PetscErrorCode writeMatrixInfo(const suite::RunContext& ctx, suite::H5Output& out, const Options& o,
                               const SymCsc& A, const MatrixMarketInfo& info) {
  MPI_Comm comm = ctx.comm();
  PetscFunctionBeginUser;
  PetscCall(out.writeAttribute("/", "matrix", o.matrix));
  PetscCall(out.writeAttribute("/", "n", (long long)A.n));
  PetscCall(out.writeAttribute("/", "nnz_lower", (long long)A.nnzUpper()));
  PetscCall(out.writeAttribute(
      "/", "profile_definition",
      "sum_i (i - f_i), f_i = first nonzero column of row i of the permuted lower triangle "
      "(diagonal excluded)"));
  PetscCall(suite::logInfo(comm, ctx.quiet(),
                           "reorder: %s  n = %d  nnz(lower incl. diagonal) = %lld  (%s %s)", o.matrix.c_str(),
                           A.n, A.nnzUpper(), info.field.c_str(), info.symmetry.c_str()));
  PetscCall(suite::logInfo(comm, ctx.quiet(), "%-8s %10s %12s %12s %12s %12s", "ordering", "bandwidth",
                           "profile", "nnz(L)", "flops", "time [ms]"));
  PetscFunctionReturn(0);
}

// One ordering: timed -repeat times, checked, one table line and the HDF5 group /<name>.
PetscErrorCode applyOrdering(const suite::RunContext& ctx, suite::H5Output& out, const Graph& g,
                             const std::string& name, PetscInt repeat) {
  MPI_Comm comm = ctx.comm();
  OrderingFn fn;
  PetscFunctionBeginUser;
  PetscCall(findOrdering(comm, name, &fn));
  std::vector<int> p;
  double best = 1e300;
  for (PetscInt r = 0; r < repeat; ++r) {
    const double t0 = threadCpuSeconds();
    p = fn(g);
    best = std::min(best, threadCpuSeconds() - t0);
  }
  PetscCheck(isPermutation(p, g.n), comm, PETSC_ERR_PLIB, "ordering %s did not return a permutation",
             name.c_str());
  const OrderingMetrics m = computeMetrics(g, p);
  PetscCall(suite::logInfo(comm, ctx.quiet(), "%-8s %10lld %12lld %12lld %12.4g %12.4f", name.c_str(),
                           m.bandwidth, m.profile, m.nnz_L, m.flops, 1e3 * best));
  const std::string grp = "/" + name;
  const long long b = m.bandwidth, pr = m.profile, nz = m.nnz_L;
  PetscCall(out.writeReplicated(grp + "/bandwidth", &b, {1}, ""));
  PetscCall(out.writeReplicated(grp + "/profile", &pr, {1}, ""));
  PetscCall(out.writeReplicated(grp + "/nnz_L", &nz, {1}, ""));
  PetscCall(out.writeReplicated(grp + "/flops", &m.flops, {1}, ""));
  PetscCall(out.writeReplicated(grp + "/time", &best, {1}, "s"));
  PetscCall(out.writeReplicated(grp + "/permutation", p.data(), {(unsigned long long)p.size()}, ""));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode runReorder(const suite::RunContext& ctx) {
  MPI_Comm comm = ctx.comm();
  Options o;
  PetscFunctionBeginUser;
  PetscCall(readOptions(comm, &o));
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) PetscFunctionReturn(0);
  PetscCheck(!o.matrix.empty(), comm, PETSC_ERR_ARG_WRONG, "-matrix FILE.mtx is required");
  PetscCheck(!o.output.empty(), comm, PETSC_ERR_ARG_WRONG, "-output FILE.h5 is required");
  PetscCheck(o.repeat >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-repeat %d: must be >= 1", (int)o.repeat);
  PetscCall(suite::checkOutputWritable(comm, o.output, "output"));
  SymCsc A;
  MatrixMarketInfo info;
  PetscCall(readMatrixMarket(comm, o.matrix, &A, &info));
  const Graph g = graphOfMatrix(A);
  suite::H5Output out;
  PetscCall(out.open(comm, o.output));
  PetscCall(out.writeProvenance(ctx));
  PetscCall(writeMatrixInfo(ctx, out, o, A, info));
  const std::vector<std::string> names =
      o.ordering == "all" ? orderingNames() : std::vector<std::string>{o.ordering};
  for (const auto& name : names) PetscCall(applyOrdering(ctx, out, g, name, o.repeat));
  PetscCall(out.commit(&ctx));
  PetscFunctionReturn(0);
}

} // namespace reorder_app
