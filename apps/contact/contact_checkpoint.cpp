// Checkpoint/restart of the contact app (see contact_checkpoint.hpp).
#include "contact_checkpoint.hpp"

#include "io/checkpoint.hpp"
#include "io/h5_input.hpp"

#include <cmath>
#include <stdexcept>

namespace contact_app {

using namespace suite::contact;

std::string checkpointScheme(const std::string& scene, FrictionModel f) {
  return "scene=" + scene + " friction=" + frictionName(f);
}

namespace {

// Replicated array of shape {rows, cols}: rank 0 owns all of it.
suite::CheckpointField field(MPI_Comm comm, const std::string& name, unsigned long long rows,
                             unsigned long long cols, double* data) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const unsigned long long own = rank == 0 ? rows : 0;
  return suite::CheckpointField{name, {rows, cols}, {0, 0}, {own, cols}, data};
}

// Rows of the checkpoint's contact table (checked: a contact checkpoint with a sane table shape).
PetscErrorCode contactRows(MPI_Comm comm, const std::string& path, unsigned long long* rows) {
  suite::H5Input in;
  bool has = false;
  suite::Dims d;
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  PetscCall(in.hasObject("/fields/contacts", &has));
  PetscCheck(has, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: no /fields/contacts (not a contact checkpoint)", path.c_str());
  PetscCall(in.datasetDims("/fields/contacts", &d));
  PetscCheck(d.size() == 2 && d[0] >= 1 && d[1] == 8 && d[0] <= 100000000ULL, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: /fields/contacts has a bad shape", path.c_str());
  *rows = d[0];
  PetscCall(in.close());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode writeContactCheckpoint(MPI_Comm comm, const std::string& path, const std::string& scheme,
                                      long long step, double time, double dt, const std::vector<Body>& bodies,
                                      const Stepper& stepper) {
  PetscFunctionBeginUser;
  const int nb = (int)bodies.size();
  std::vector<double> b(std::max(1, nb * kStateSize)), sleep, contacts;
  for (int i = 0; i < nb; ++i) packState(bodies[i], &b[i * kStateSize]);
  stepper.exportState(nb, &sleep, &contacts);
  const unsigned long long nc = contacts.size() / 8;
  contacts.insert(contacts.begin(), 8, 0.0);
  contacts[0] = (double)nc;
  suite::CheckpointHeader h{"contact", scheme, step, time, dt, {(long long)nb}};
  std::vector<suite::CheckpointField> fields = {field(comm, "bodies", nb, kStateSize, b.data()),
                                                field(comm, "sleep", nb, 2, sleep.data()),
                                                field(comm, "contacts", nc + 1, 8, contacts.data())};
  std::vector<double> rungs; // -friction auto: per contact its rung, then the step count
  if (stepper.options().friction == FrictionModel::Auto) {
    stepper.exportAutoState(&rungs);
    fields.push_back(field(comm, "friction_auto", nc + 1, 1, rungs.data()));
  }
  PetscCall(suite::writeCheckpoint(comm, path, h, fields));
  PetscFunctionReturn(0);
}

PetscErrorCode readContactCheckpoint(MPI_Comm comm, const std::string& path, const std::string& scheme,
                                     double dt, std::vector<Body>* bodies, Stepper* stepper, long long* step,
                                     double* time) {
  PetscFunctionBeginUser;
  const int nb = (int)bodies->size();
  unsigned long long rows = 0;
  PetscCall(contactRows(comm, path, &rows));
  std::vector<double> b(nb * kStateSize), sleep(2 * nb), contacts(rows * 8), rungs(rows);
  suite::CheckpointHeader expected{"contact", scheme, 0, 0.0, dt, {(long long)nb}}, found;
  std::vector<suite::CheckpointField> fields = {field(comm, "bodies", nb, kStateSize, b.data()),
                                                field(comm, "sleep", nb, 2, sleep.data()),
                                                field(comm, "contacts", rows, 8, contacts.data())};
  const bool with_auto = stepper->options().friction == FrictionModel::Auto;
  if (with_auto) fields.push_back(field(comm, "friction_auto", rows, 1, rungs.data()));
  PetscCall(suite::readCheckpoint(comm, path, expected, &found, fields));
  PetscCallMPI(MPI_Bcast(rungs.data(), (int)rungs.size(), MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(b.data(), (int)b.size(), MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(sleep.data(), (int)sleep.size(), MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(contacts.data(), (int)contacts.size(), MPI_DOUBLE, 0, comm));
  PetscCheck(found.dt == dt, comm, PETSC_ERR_ARG_INCOMP, "restart %s: written with -dt %g, this run has %g",
             path.c_str(), found.dt, dt);
  PetscCheck(contacts[0] == (double)(rows - 1), comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: contact count %g does not match the table (%llu rows)", path.c_str(), contacts[0],
             rows - 1);
  bool finite = true;
  for (double v : b) finite = finite && std::isfinite(v);
  PetscCheck(finite, comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: non-finite body state", path.c_str());
  for (int i = 0; i < nb; ++i) unpackState(&b[i * kStateSize], &(*bodies)[i]);
  std::string err;
  try {
    stepper->importState(nb, sleep, std::vector<double>(contacts.begin() + 8, contacts.end()));
    if (with_auto) stepper->importAutoState(rungs);
  } catch (const std::exception& e) {
    err = e.what();
  }
  PetscCheck(err.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: %s", path.c_str(), err.c_str());
  *step = found.step;
  *time = found.time;
  PetscFunctionReturn(0);
}

} // namespace contact_app
