// Checkpoint/restart: atomic write, validated header, order-independent exact checksums per field.
// The checksum is the wrap-around (mod 2^64) sum over elements of splitmix64(bits(x_i) ^ splitmix64(i)),
// i the global linear index: exact, independent of the rank count, and sensitive to any flipped bit.
#include "io/checkpoint.hpp"

#include "io/h5_input.hpp"
#include "core/version.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace suite {
namespace {

constexpr long long kFormatVersion = 1;

uint64_t splitmix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// Global row-major linear index of each local element of the block start/count in dims.
PetscErrorCode fieldChecksum(MPI_Comm comm, const CheckpointField& f, uint64_t* sum) {
  PetscFunctionBeginUser;
  const size_t r = f.dims.size();
  size_t n = 1;
  for (auto c : f.count) n *= c;
  uint64_t local = 0;
  std::vector<unsigned long long> idx(r, 0);
  for (size_t k = 0; k < n; ++k) {
    uint64_t g = 0;
    for (size_t a = 0; a < r; ++a) g = g * f.dims[a] + (f.start[a] + idx[a]);
    uint64_t bits;
    std::memcpy(&bits, &f.data[k], sizeof bits);
    local += splitmix64(bits ^ splitmix64(g));
    for (size_t a = r; a-- > 0;) { // advance the multi-index, last axis fastest
      if (++idx[a] < f.count[a]) break;
      idx[a] = 0;
    }
  }
  PetscCallMPI(MPI_Allreduce(&local, sum, 1, MPI_UINT64_T, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

std::string gridText(const std::vector<long long>& g) {
  std::ostringstream s;
  for (size_t i = 0; i < g.size(); ++i) s << (i ? " x " : "") << g[i];
  return g.empty() ? "(none)" : s.str();
}

} // namespace

PetscErrorCode writeCheckpoint(MPI_Comm comm, const std::string& path, const CheckpointHeader& h,
                               const std::vector<CheckpointField>& fields) {
  PetscFunctionBeginUser;
  H5Output out;
  PetscCall(out.open(comm, path));
  PetscCall(out.writeAttribute("/checkpoint", "format_version", kFormatVersion));
  PetscCall(out.writeAttribute("/checkpoint", "app", h.app));
  PetscCall(out.writeAttribute("/checkpoint", "scheme", h.scheme));
  PetscCall(out.writeAttribute("/checkpoint", "step", h.step));
  PetscCall(out.writeAttribute("/checkpoint", "time", h.time));
  PetscCall(out.writeAttribute("/checkpoint", "dt", h.dt));
  PetscCall(out.writeAttribute("/checkpoint", "version", versionString()));
  const long long ng = (long long)h.grid.size();
  PetscCall(out.writeReplicated("/checkpoint/grid", h.grid.data(), {(unsigned long long)ng}, ""));
  for (const auto& f : fields) {
    uint64_t sum = 0;
    PetscCall(fieldChecksum(comm, f, &sum));
    const std::string ds = "/fields/" + f.name;
    PetscCall(out.writeDistributed(ds, f.data, f.dims, f.start, f.count, ""));
    PetscCall(out.writeAttribute(ds, "checksum", std::to_string(sum)));
  }
  // Fault injection for the reliability tests: a job killed in the middle of this checkpoint's write.
  if (const char* s = std::getenv("SUITE_FAULT_ABORT_IN_CHECKPOINT"))
    if (std::atoll(s) == h.step) std::abort();
  PetscCall(out.commit(nullptr));
  PetscFunctionReturn(0);
}

namespace {

PetscErrorCode readHeader(MPI_Comm comm, const H5Input& in, CheckpointHeader* h) {
  PetscFunctionBeginUser;
  bool is_ckpt = false;
  PetscCall(in.hasObject("/checkpoint", &is_ckpt));
  PetscCheck(is_ckpt, comm, PETSC_ERR_FILE_UNEXPECTED, "%s is not a checkpoint (no /checkpoint header)",
             in.path().c_str());
  long long version = 0;
  PetscCall(in.readAttribute("/checkpoint", "format_version", &version));
  PetscCheck(version == kFormatVersion, comm, PETSC_ERR_FILE_UNEXPECTED,
             "%s: checkpoint format version %lld, this build reads version %lld", in.path().c_str(), version,
             kFormatVersion);
  PetscCall(in.readAttribute("/checkpoint", "app", &h->app));
  PetscCall(in.readAttribute("/checkpoint", "scheme", &h->scheme));
  PetscCall(in.readAttribute("/checkpoint", "step", &h->step));
  PetscCall(in.readAttribute("/checkpoint", "time", &h->time));
  PetscCall(in.readAttribute("/checkpoint", "dt", &h->dt));
  std::vector<long long> grid;
  Dims dims;
  PetscCall(in.readAll("/checkpoint/grid", &grid, &dims));
  h->grid = grid;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readCheckpointHeader(MPI_Comm comm, const std::string& path, CheckpointHeader* header) {
  PetscFunctionBeginUser;
  H5Input in;
  PetscCall(in.open(comm, path));
  PetscCall(readHeader(comm, in, header));
  PetscFunctionReturn(0);
}

PetscErrorCode readCheckpoint(MPI_Comm comm, const std::string& path, const CheckpointHeader& expected,
                              CheckpointHeader* found, const std::vector<CheckpointField>& fields) {
  PetscFunctionBeginUser;
  H5Input in;
  PetscCall(in.open(comm, path));
  PetscCall(readHeader(comm, in, found));
  const char* p = path.c_str();
  PetscCheck(found->app == expected.app, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: written by app '%s', this is '%s'", p, found->app.c_str(), expected.app.c_str());
  PetscCheck(expected.scheme.empty() || found->scheme == expected.scheme, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: written with scheme '%s', this run uses '%s'", p, found->scheme.c_str(),
             expected.scheme.c_str());
  PetscCheck(found->grid == expected.grid, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: grid %s, this run has grid %s", p, gridText(found->grid).c_str(),
             gridText(expected.grid).c_str());
  PetscCheck(found->time >= 0.0 && found->dt >= 0.0 && found->step >= 0, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: invalid header (step %lld, time %g, dt %g)", p, found->step, found->time,
             found->dt);
  for (const auto& f : fields) {
    const std::string ds = "/fields/" + f.name;
    Dims dims;
    PetscCall(in.datasetDims(ds, &dims));
    PetscCheck(dims == f.dims, comm, PETSC_ERR_ARG_INCOMP,
               "restart %s: field %s has other dimensions than this run", p, f.name.c_str());
    PetscCall(in.readBlock(ds, f.start, f.count, f.data));
    std::string stored;
    PetscCall(in.readAttribute(ds, "checksum", &stored));
    uint64_t sum = 0;
    PetscCall(fieldChecksum(comm, f, &sum));
    PetscCheck(stored == std::to_string(sum), comm, PETSC_ERR_FILE_UNEXPECTED,
               "restart %s: field %s fails its checksum (file corrupted)", p, f.name.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace suite
