// HDF5 output file of one run: written under "<path>.tmp" and renamed to <path> by commit(), so a killed
// job never leaves a half-written file under the final name. Parallel (MPI-IO, collective) writes of
// distributed arrays; replicated data is written by rank 0. Every call is collective on the communicator.
//
//   suite::H5Output out;
//   PetscCall(out.open(ctx.comm(), "run.h5"));
//   PetscCall(out.writeProvenance(ctx));                       // program, version, options, nranks, ...
//   PetscCall(out.writeAttribute("/", "problem", "sod"));
//   PetscCall(out.writeDistributed("/final/rho", rho_local, {nx}, {xs}, {xm}, "kg/m^3"));
//   PetscCall(out.commit(ctx));                                 // sets wall_seconds, closes, renames
#pragma once

#include <petscsys.h>

#include <cstdint>
#include <string>
#include <vector>

namespace suite {

class RunContext;
using Dims = std::vector<unsigned long long>; // HDF5 dims, slowest-varying first, e.g. (z, y, x)

class H5Output {
public:
  H5Output() = default;
  ~H5Output(); // not committed: closes and removes the temporary file (collective)
  H5Output(const H5Output&) = delete;
  H5Output& operator=(const H5Output&) = delete;

  PetscErrorCode open(MPI_Comm comm, const std::string& path);
  // Root attributes program, version, options, nranks, start_time (wall_seconds is set by commit()).
  PetscErrorCode writeProvenance(const RunContext& ctx);

  // Attributes on an object ("/" or a group/dataset path; groups are created as needed).
  PetscErrorCode writeAttribute(const std::string& object, const std::string& name, const std::string& value);
  PetscErrorCode writeAttribute(const std::string& object, const std::string& name, double value);
  PetscErrorCode writeAttribute(const std::string& object, const std::string& name, long long value);
  PetscErrorCode writeAttribute(const std::string& object, const std::string& name, int value) {
    return writeAttribute(object, name, static_cast<long long>(value));
  }
  PetscErrorCode writeAttribute(const std::string& object, const std::string& name, const char* value) {
    return writeAttribute(object, name, std::string(value));
  }
  PetscErrorCode writeAttribute(const std::string& object, const std::string& name,
                                const std::vector<double>& value);

  // Distributed array: this rank writes the block start..start+count of a global array of shape dims.
  // Ranks with an empty block pass count with a zero entry. units: attribute "units" ("" = dimensionless).
  PetscErrorCode writeDistributed(const std::string& dataset, const double* local, const Dims& dims,
                                  const Dims& start, const Dims& count, const char* units);
  PetscErrorCode writeDistributed(const std::string& dataset, const long long* local, const Dims& dims,
                                  const Dims& start, const Dims& count, const char* units);
  PetscErrorCode writeDistributed(const std::string& dataset, const int* local, const Dims& dims,
                                  const Dims& start, const Dims& count, const char* units);
  // Replicated array (identical on all ranks, or only rank 0's copy matters): written by rank 0.
  PetscErrorCode writeReplicated(const std::string& dataset, const double* data, const Dims& dims,
                                 const char* units);
  PetscErrorCode writeReplicated(const std::string& dataset, const long long* data, const Dims& dims,
                                 const char* units);
  PetscErrorCode writeReplicated(const std::string& dataset, const int* data, const Dims& dims,
                                 const char* units);
  // Replicated list of strings (rank 0's), as fixed-length null-terminated strings of the longest's length
  // (parallel HDF5 writes no variable-length data); h5py reads them as bytes.
  PetscErrorCode writeReplicatedStrings(const std::string& dataset, const std::vector<std::string>& values);
  PetscErrorCode createGroup(const std::string& group);
  // Flushes HDF5 buffers to the temporary file (for long-lived files such as batch results).
  PetscErrorCode flush();

  // Sets wall_seconds (if ctx given), closes the file and renames <path>.tmp -> <path>.
  PetscErrorCode commit(const RunContext* ctx);
  const std::string& path() const { return path_; }
  const std::string& tmpPath() const { return tmp_path_; }
  bool isOpen() const { return file_ >= 0; }

private:
  template <typename T>
  PetscErrorCode writeArray(const std::string& dataset, const T* local, const Dims& dims, const Dims& start,
                            const Dims& count, const char* units, bool replicated);
  PetscErrorCode closeFile();

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  int64_t file_ = -1; // hid_t
  std::string path_, tmp_path_;
};

// Collective: errors (one message, all ranks) if the directory of path does not exist or a file cannot be
// created there. Apps call it at start, before spending time on the run.
PetscErrorCode checkOutputWritable(MPI_Comm comm, const std::string& path, const char* option);

} // namespace suite
