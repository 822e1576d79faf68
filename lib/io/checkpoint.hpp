// Checkpoint/restart: state plus a header (format version, app, step, time, dt, grid, scheme), written
// atomically (.tmp + rename) with a checksum per field; the header is validated on load with a clear
// message on any mismatch; fields are stored as global arrays so a restart may use another rank count.
#pragma once

#include "io/h5_output.hpp"

#include <string>
#include <vector>

namespace suite {

struct CheckpointHeader {
  std::string app;    // e.g. "euler"
  std::string scheme; // discretisation tag that must match on restart ("" = not checked)
  long long step = 0;
  double time = 0.0, dt = 0.0;
  std::vector<long long> grid; // global sizes that must match on restart
};

// One distributed field: this rank's block of a global array of shape dims.
struct CheckpointField {
  std::string name;
  Dims dims, start, count;
  double* data; // read into / written from
};

// Fault injection for tests: with SUITE_FAULT_ABORT_IN_CHECKPOINT=STEP in the environment, the write of the
// checkpoint of that step aborts the process after its data, before the rename (a job killed mid-write).
PetscErrorCode writeCheckpoint(MPI_Comm comm, const std::string& path, const CheckpointHeader& header,
                               const std::vector<CheckpointField>& fields);
// Reads the header into *found and checks it against expected (app, scheme, grid); then reads the fields
// (their dims must match) and verifies their checksums. Any problem: one clear error on all ranks.
// Collective: the header of the checkpoint at path (app, scheme tag, grid, step, time) without its fields.
PetscErrorCode readCheckpointHeader(MPI_Comm comm, const std::string& path, CheckpointHeader* header);

PetscErrorCode readCheckpoint(MPI_Comm comm, const std::string& path, const CheckpointHeader& expected,
                              CheckpointHeader* found, const std::vector<CheckpointField>& fields);

} // namespace suite
