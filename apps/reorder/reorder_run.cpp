// reorder: see main.cpp. Ordering time: minimum over -repeat runs of the thread CPU time (core/clocks.hpp).
#include "core/clocks.hpp"
#include "core/log.hpp"
#include "core/option_value.hpp"
#include "core/resource_checks.hpp"
#include "core/run_summary.hpp"
#include "fem/matrix_market.hpp"
#include "fem/ordering.hpp"
#include "io/h5_output.hpp"
#include "reorder_run.hpp"

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

namespace reorder_app {

using namespace suite::fem;

namespace {
struct Options {
  std::string matrix, output, ordering = "all";
  PetscInt repeat = 3;
};

PetscErrorCode readOptions(MPI_Comm comm, Options* o) {
  PetscFunctionBeginUser;
  std::vector<suite::Choice> choices = orderingChoices(); // each with its help line, and "all" of them
  choices.push_back({"all", "every ordering above, in this order"});
  PetscOptionsBegin(comm, "", "reorder options", "");
  PetscCall(suite::optionsString(PetscOptionsObject, "-matrix",
                                 "Matrix Market file (coordinate; symmetric or general)", &o->matrix));
  PetscCall(
      suite::optionsChoice(PetscOptionsObject, "-ordering", "Fill-reducing ordering", choices, &o->ordering));
  PetscCall(suite::optionsString(PetscOptionsObject, "-output", "HDF5 output file", &o->output));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-repeat", "Ordering time = minimum over this many runs",
                              "", o->repeat, &o->repeat, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

// The matrix's memory before it is read: the file text, its entries, the symmetrised matrix, its graph and
// the orderings' workspace are within 10 bytes per byte of the file (measured 6: a 3.6 MB 40^3 Laplacian,
// rcm/amd/metis, 22 MB over the 44 MB of an empty run). A file that cannot be read is left to the reader.
PetscErrorCode checkMatrixMemory(MPI_Comm comm, const std::string& path) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  const std::string what = "-matrix " + path;
  PetscFunctionBeginUser;
  if (!ec) PetscCall(suite::checkMemoryEstimate(comm, 5e7 + 10.0 * (double)bytes, what.c_str()));
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
  const double best = timeOrdering(fn, g, (int)repeat, &p);
  PetscCheck(isPermutation(p, g.n), comm, PETSC_ERR_PLIB, "ordering %s did not return a permutation",
             name.c_str());
  const OrderingMetrics m = computeMetrics(g, p);
  const std::string taken = name == "auto" ? chooseOrdering(g).name : name; // auto: the one it chose
  const std::string label = taken == name ? name : name + " (" + taken + ")";
  PetscCall(suite::logInfo(comm, ctx.quiet(), "%-15s %10lld %12lld %12lld %12.4g %12.4f", label.c_str(),
                           m.bandwidth, m.profile, m.nnz_L, m.flops, 1e3 * best));
  if (!out.isOpen()) PetscFunctionReturn(0); // no -output: the table only
  const std::string grp = "/" + name;
  const std::pair<const char*, long long> counts[] = {
      {"bandwidth", m.bandwidth}, {"profile", m.profile}, {"nnz_L", m.nnz_L}};
  for (const auto& [key, v] : counts) PetscCall(out.writeReplicated(grp + "/" + key, &v, {1}, ""));
  PetscCall(out.writeReplicated(grp + "/flops", &m.flops, {1}, ""));
  PetscCall(out.writeReplicated(grp + "/time", &best, {1}, "s"));
  PetscCall(out.writeReplicated(grp + "/permutation", p.data(), {(unsigned long long)p.size()}, ""));
  PetscCall(out.writeAttribute(grp, "taken", taken));
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
  PetscCall(suite::checkIntOptionRange(comm, "-repeat", 1));
  PetscCheck(o.repeat >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-repeat %d: must be >= 1", (int)o.repeat);
  if (!o.output.empty()) PetscCall(suite::checkOutputWritable(comm, o.output, "output"));
  SymCsc A;
  MatrixMarketInfo info;
  PetscCall(checkMatrixMemory(comm, o.matrix));
  PetscCall(readMatrixMarket(comm, o.matrix, &A, &info));
  const Graph g = graphOfMatrix(A);
  suite::H5Output out;
  const double t0 = suite::wallSeconds();
  if (!o.output.empty()) {
    PetscCall(out.open(comm, o.output));
    PetscCall(out.writeProvenance(ctx));
    PetscCall(out.writeAttribute("/", "status", "completed")); // written only when every ordering ran
    PetscCall(out.writeAttribute("/", "matrix", o.matrix));
    PetscCall(out.writeAttribute("/", "n", (long long)A.n));
    PetscCall(out.writeAttribute("/", "nnz_lower", (long long)A.nnzUpper()));
    PetscCall(out.writeAttribute("/", "profile_definition", kProfileDefinition));
  }
  PetscCall(suite::logInfo(comm, ctx.quiet(),
                           "reorder: %s  n = %d  nnz(lower incl. diagonal) = %lld  (%s %s)", o.matrix.c_str(),
                           A.n, A.nnzUpper(), info.field.c_str(), info.symmetry.c_str()));
  PetscCall(suite::logInfo(comm, ctx.quiet(), "%-15s %10s %12s %12s %12s %12s", "ordering", "bandwidth",
                           "profile", "nnz(L)", "flops", "time [ms]"));
  const std::vector<std::string> names =
      o.ordering == "all" ? orderingNames() : std::vector<std::string>{o.ordering};
  for (const auto& name : names) PetscCall(applyOrdering(ctx, out, g, name, o.repeat));
  std::vector<std::string> written;
  if (out.isOpen()) {
    PetscCall(out.commit(&ctx));
    written.push_back(o.output);
  }
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.3f", suite::wallSeconds() - t0);
  const std::string what = std::to_string(names.size()) + " ordering(s) of " + o.matrix +
                           " (n = " + std::to_string(A.n) + ") in " + secs + " s";
  PetscCall(suite::logRunSummary(ctx, "completed", what, written));
  PetscFunctionReturn(0);
}

} // namespace reorder_app
