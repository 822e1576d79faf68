// Reading the suite's HDF5 files (checkpoints, problem files, restarts): collective, parallel reads of
// blocks of global arrays, attribute queries with clear errors when something is missing or malformed.
#pragma once

#include "io/h5_output.hpp"

#include <string>
#include <vector>

namespace suite {

class H5Input {
public:
  H5Input() = default;
  ~H5Input();
  H5Input(const H5Input&) = delete;
  H5Input& operator=(const H5Input&) = delete;

  // Errors collectively if the file is missing or not HDF5 (message names the file and the option).
  PetscErrorCode open(MPI_Comm comm, const std::string& path);
  PetscErrorCode close();

  PetscErrorCode hasObject(const std::string& path, bool* exists) const;
  PetscErrorCode hasAttribute(const std::string& object, const std::string& name, bool* exists) const;
  PetscErrorCode readAttribute(const std::string& object, const std::string& name, std::string* value) const;
  PetscErrorCode readAttribute(const std::string& object, const std::string& name, double* value) const;
  PetscErrorCode readAttribute(const std::string& object, const std::string& name, long long* value) const;
  PetscErrorCode readAttribute(const std::string& object, const std::string& name,
                               std::vector<double>* value) const;
  PetscErrorCode datasetDims(const std::string& dataset, Dims* dims) const;
  // The names of the links in group `group` (datasets and groups), in HDF5's name order; an error naming the
  // file when the group does not exist.
  PetscErrorCode groupMembers(const std::string& group, std::vector<std::string>* names) const;
  // Collective: errors when a dataset claims more elements than its stored bytes can hold (a corrupted or
  // hostile header), before anything that size is allocated. Unfiltered data must be stored in full (or be
  // under 1 MiB); filtered (compressed) data may expand at most 1024 times.
  PetscErrorCode checkPlausibleSize(const std::string& dataset, const Dims& dims, size_t element_bytes) const;
  // Reads the block start..start+count of a dataset (converted to double / long long).
  PetscErrorCode readBlock(const std::string& dataset, const Dims& start, const Dims& count,
                           double* local) const;
  PetscErrorCode readBlock(const std::string& dataset, const Dims& start, const Dims& count,
                           long long* local) const;
  // Whole dataset on every rank.
  PetscErrorCode readAll(const std::string& dataset, std::vector<double>* data, Dims* dims) const;
  PetscErrorCode readAll(const std::string& dataset, std::vector<long long>* data, Dims* dims) const;
  const std::string& path() const { return path_; }

private:
  template <typename T>
  PetscErrorCode readBlockT(const std::string& dataset, const Dims& start, const Dims& count, T* local) const;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int64_t file_ = -1;
  bool serial_ = false; // a one-rank communicator: opened without MPI-IO
  std::string path_;
};

} // namespace suite
