// HDF5 output of one run: temporary name + rename, provenance, attributes, parallel datasets.
#include "io/h5_output.hpp"

#include "core/option_text.hpp"
#include "core/run_context.hpp"
#include "core/version.hpp"
#include "io/h5_util.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace suite {

H5Output::~H5Output() {
  if (file_ < 0) return;
  // Error path (never committed): abandon the partial file quietly. Truncating it first frees the space a
  // full disk needs for the closing metadata flush; a close that fails would leave HDF5 an open file that
  // it then tries to close again inside MPI_Finalize, which crashed (HDF5 1.10, Open MPI).
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  if (rank_ == 0 && truncate(tmp_path_.c_str(), 0) != 0) { /* nothing more to do */
  }
  MPI_Barrier(comm_);
  H5Fclose((hid_t)file_);
  file_ = -1;
  if (rank_ == 0) std::remove(tmp_path_.c_str());
}

PetscErrorCode H5Output::closeFile() {
  PetscFunctionBeginUser;
  if (file_ >= 0) {
    herr_t st = H5Fclose((hid_t)file_);
    file_ = -1;
    PetscCheck(st >= 0, comm_, PETSC_ERR_FILE_WRITE, "closing HDF5 file %s failed (disk full?)",
               tmp_path_.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::open(MPI_Comm comm, const std::string& path) {
  PetscFunctionBeginUser;
  PetscCheck(file_ < 0, comm, PETSC_ERR_ORDER, "H5Output already open on %s", path_.c_str());
  h5::silence();
  comm_ = comm;
  MPI_Comm_rank(comm, &rank_);
  path_ = path;
  tmp_path_ = path + ".tmp";
  PetscCall(checkOutputWritable(comm, path, "output"));
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL);
  hid_t f = H5Fcreate(tmp_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  PetscCheck(f >= 0, comm, PETSC_ERR_FILE_OPEN, "cannot create HDF5 file %s", tmp_path_.c_str());
  file_ = f;
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::writeProvenance(const RunContext& ctx) {
  PetscFunctionBeginUser;
  PetscCall(writeAttribute("/", "program", ctx.program()));
  PetscCall(writeAttribute("/", "version", versionString()));
  PetscCall(writeAttribute("/", "options", ctx.optionsText()));
  PetscCall(writeAttribute("/", "nranks", ctx.size()));
  PetscCall(writeAttribute("/", "start_time", ctx.startTimeIso()));
  PetscFunctionReturn(0);
}

namespace {
// Writes one attribute (identical data on every rank: HDF5 metadata writes are collective).
PetscErrorCode putAttribute(MPI_Comm comm, hid_t file, const std::string& object, const std::string& name,
                            hid_t type, hid_t space, const void* buf) {
  PetscFunctionBeginUser;
  hid_t obj = h5::openObject(file, object, true);
  PetscCheck(obj >= 0, comm, PETSC_ERR_FILE_WRITE, "cannot open or create HDF5 object %s", object.c_str());
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  hid_t attr = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = attr >= 0 ? H5Awrite(attr, type, buf) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Oclose(obj);
  PetscCheck(st >= 0, comm, PETSC_ERR_FILE_WRITE, "cannot write attribute %s on %s", name.c_str(),
             object.c_str());
  PetscFunctionReturn(0);
}

// A dataset created with its intermediate groups, replacing one of the same name.
hid_t createDataset(hid_t file, const std::string& dataset, hid_t type, hid_t fspace) {
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  if (h5::exists(file, dataset)) H5Ldelete(file, dataset.c_str(), H5P_DEFAULT);
  hid_t dset = H5Dcreate2(file, dataset.c_str(), type, fspace, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  return dset;
}

// The collective write of a created dataset (dset < 0: its creation failed), its handles closed, and one
// error for the whole job when any rank failed.
PetscErrorCode writeCollectively(MPI_Comm comm, hid_t dset, hid_t type, hid_t mspace, hid_t fspace,
                                 const void* data, const std::string& dataset, const std::string& file) {
  PetscFunctionBeginUser;
  hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
  H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE);
  herr_t st = dset >= 0 ? H5Dwrite(dset, type, mspace, fspace, dxpl, data) : -1;
  H5Pclose(dxpl);
  H5Sclose(mspace);
  H5Sclose(fspace);
  if (dset >= 0) H5Dclose(dset);
  int ok = st >= 0, all_ok = 0;
  PetscCallMPI(MPI_Allreduce(&ok, &all_ok, 1, MPI_INT, MPI_LAND, comm));
  PetscCheck(all_ok, comm, PETSC_ERR_FILE_WRITE, "writing dataset %s to %s failed (disk full?)",
             dataset.c_str(), file.c_str());
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode H5Output::writeAttribute(const std::string& object, const std::string& name,
                                        const std::string& value) {
  PetscFunctionBeginUser;
  hid_t type = h5::stringType();
  hid_t space = H5Screate(H5S_SCALAR);
  const char* p = value.c_str();
  PetscErrorCode ierr = putAttribute(comm_, (hid_t)file_, object, name, type, space, &p);
  H5Sclose(space);
  H5Tclose(type);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::writeAttribute(const std::string& object, const std::string& name, double value) {
  PetscFunctionBeginUser;
  hid_t space = H5Screate(H5S_SCALAR);
  PetscErrorCode ierr = putAttribute(comm_, (hid_t)file_, object, name, H5T_NATIVE_DOUBLE, space, &value);
  H5Sclose(space);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::writeAttribute(const std::string& object, const std::string& name, long long value) {
  PetscFunctionBeginUser;
  hid_t space = H5Screate(H5S_SCALAR);
  PetscErrorCode ierr = putAttribute(comm_, (hid_t)file_, object, name, H5T_NATIVE_LLONG, space, &value);
  H5Sclose(space);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::writeAttribute(const std::string& object, const std::string& name,
                                        const std::vector<double>& value) {
  PetscFunctionBeginUser;
  hsize_t n = value.size();
  hid_t space = H5Screate_simple(1, &n, nullptr);
  PetscErrorCode ierr =
      putAttribute(comm_, (hid_t)file_, object, name, H5T_NATIVE_DOUBLE, space, value.data());
  H5Sclose(space);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::createGroup(const std::string& group) {
  PetscFunctionBeginUser;
  hid_t g = h5::openObject((hid_t)file_, group, true);
  PetscCheck(g >= 0, comm_, PETSC_ERR_FILE_WRITE, "cannot create HDF5 group %s", group.c_str());
  H5Oclose(g);
  PetscFunctionReturn(0);
}

template <typename T>
PetscErrorCode H5Output::writeArray(const std::string& dataset, const T* local, const Dims& dims,
                                    const Dims& start, const Dims& count, const char* units,
                                    bool replicated) {
  PetscFunctionBeginUser;
  PetscCheck(file_ >= 0, comm_, PETSC_ERR_ORDER, "H5Output not open (writing %s)", dataset.c_str());
  const int rank = (int)dims.size();
  PetscCheck(rank >= 1 && start.size() == dims.size() && count.size() == dims.size(), comm_,
             PETSC_ERR_ARG_SIZ, "dataset %s: dims/start/count ranks differ", dataset.c_str());
  std::vector<hsize_t> d(dims.begin(), dims.end()), s(start.begin(), start.end()),
      c(count.begin(), count.end());
  bool empty = replicated ? rank_ != 0 : false;
  for (hsize_t ci : c) empty = empty || ci == 0;

  hid_t fspace = H5Screate_simple(rank, d.data(), nullptr);
  hid_t dset = createDataset((hid_t)file_, dataset, h5::nativeType<T>(), fspace);
  hid_t mspace;
  if (empty) {
    hsize_t one = 1;
    mspace = H5Screate_simple(1, &one, nullptr);
    H5Sselect_none(mspace);
    H5Sselect_none(fspace);
  } else {
    mspace = H5Screate_simple(rank, c.data(), nullptr);
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, s.data(), nullptr, c.data(), nullptr);
  }
  PetscCall(writeCollectively(comm_, dset, h5::nativeType<T>(), mspace, fspace, local, dataset, tmp_path_));
  PetscCall(writeAttribute(dataset, "units", units ? units : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::writeDistributed(const std::string& ds, const double* local, const Dims& dims,
                                          const Dims& start, const Dims& count, const char* units) {
  return writeArray(ds, local, dims, start, count, units, false);
}
PetscErrorCode H5Output::writeDistributed(const std::string& ds, const long long* local, const Dims& dims,
                                          const Dims& start, const Dims& count, const char* units) {
  return writeArray(ds, local, dims, start, count, units, false);
}
PetscErrorCode H5Output::writeDistributed(const std::string& ds, const int* local, const Dims& dims,
                                          const Dims& start, const Dims& count, const char* units) {
  return writeArray(ds, local, dims, start, count, units, false);
}
PetscErrorCode H5Output::writeReplicated(const std::string& ds, const double* data, const Dims& dims,
                                         const char* units) {
  return writeArray(ds, data, dims, Dims(dims.size(), 0), dims, units, true);
}
PetscErrorCode H5Output::writeReplicated(const std::string& ds, const long long* data, const Dims& dims,
                                         const char* units) {
  return writeArray(ds, data, dims, Dims(dims.size(), 0), dims, units, true);
}
PetscErrorCode H5Output::writeReplicated(const std::string& ds, const int* data, const Dims& dims,
                                         const char* units) {
  return writeArray(ds, data, dims, Dims(dims.size(), 0), dims, units, true);
}

PetscErrorCode H5Output::writeReplicatedStrings(const std::string& dataset,
                                                const std::vector<std::string>& values) {
  PetscFunctionBeginUser;
  PetscCheck(file_ >= 0, comm_, PETSC_ERR_ORDER, "H5Output not open (writing %s)", dataset.c_str());
  size_t width = 1;
  for (const std::string& v : values) width = std::max(width, v.size() + 1);
  std::vector<char> buf(std::max<size_t>(1, values.size()) * width, '\0');
  for (size_t i = 0; i < values.size(); ++i) values[i].copy(buf.data() + i * width, values[i].size());
  hsize_t n = values.size();
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, width);
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  hid_t fspace = H5Screate_simple(1, &n, nullptr);
  hid_t dset = createDataset((hid_t)file_, dataset, type, fspace);
  hsize_t one = 1;
  hid_t mspace = rank_ == 0 && n > 0 ? H5Screate_simple(1, &n, nullptr) : H5Screate_simple(1, &one, nullptr);
  if (rank_ != 0 || n == 0) {
    H5Sselect_none(mspace);
    H5Sselect_none(fspace);
  }
  const PetscErrorCode ierr =
      writeCollectively(comm_, dset, type, mspace, fspace, buf.data(), dataset, tmp_path_);
  H5Tclose(type);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::flush() {
  PetscFunctionBeginUser;
  PetscCheck(H5Fflush((hid_t)file_, H5F_SCOPE_GLOBAL) >= 0, comm_, PETSC_ERR_FILE_WRITE, "flushing %s failed",
             tmp_path_.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode H5Output::commit(const RunContext* ctx) {
  PetscFunctionBeginUser;
  if (ctx) {
    double wall = ctx->wallSeconds();
    PetscCallMPI(MPI_Bcast(&wall, 1, MPI_DOUBLE, 0, comm_));
    PetscCall(writeAttribute("/", "wall_seconds", wall));
  }
  PetscCall(closeFile());
  PetscCallMPI(MPI_Barrier(comm_));
  int err = 0;
  if (rank_ == 0) {
    int fd = ::open(tmp_path_.c_str(), O_RDONLY);
    if (fd >= 0) {
      if (fsync(fd) != 0) err = errno;
      ::close(fd);
    }
    if (!err && std::rename(tmp_path_.c_str(), path_.c_str()) != 0) err = errno;
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm_));
  PetscCheck(err == 0, comm_, PETSC_ERR_FILE_WRITE, "cannot finish output %s: %s", path_.c_str(),
             std::strerror(err));
  PetscFunctionReturn(0);
}

PetscErrorCode checkOutputWritable(MPI_Comm comm, const std::string& path, const char* option) {
  PetscFunctionBeginUser;
  char msg[512] = {0};
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) {
    const std::string::size_type slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    struct stat st {};
    struct statvfs vfs {};
    const std::string probe = path + ".tmp.probe";
    // a path in a message: whole up to 160 characters, else abbreviated saying so (core/option_text.hpp), so
    // that the message fits its buffer and is never cut without a word
    const std::string p = shownValue(path), d = shownValue(dir);
    if (path.empty() || path.back() == '/')
      std::snprintf(msg, sizeof msg, "-%s '%s': not a file name", option, p.c_str());
    else if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
      std::snprintf(msg, sizeof msg, "-%s %s: directory '%s' does not exist", option, p.c_str(), d.c_str());
    else if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
      std::snprintf(msg, sizeof msg, "-%s %s: is a directory", option, p.c_str());
    // a device, FIFO or socket (-output /dev/null): the rename of the finished file would replace it
    else if (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
      std::snprintf(msg, sizeof msg,
                    "-%s %s: exists and is not a regular file (the finished file would replace it)", option,
                    p.c_str());
    else if (statvfs(dir.c_str(), &vfs) == 0 && (double)vfs.f_bavail * vfs.f_frsize < 1 << 20)
      std::snprintf(msg, sizeof msg, "-%s %s: less than 1 MiB free in '%s' (disk full?)", option, p.c_str(),
                    d.c_str());
    else {
      FILE* f = std::fopen(probe.c_str(), "w");
      if (!f)
        std::snprintf(msg, sizeof msg, "-%s %s: cannot create files in '%s': %s", option, p.c_str(),
                      d.c_str(), std::strerror(errno));
      else {
        std::fclose(f);
        std::remove(probe.c_str());
      }
    }
  }
  PetscCallMPI(MPI_Bcast(msg, sizeof msg, MPI_CHAR, 0, comm));
  PetscCheck(msg[0] == 0, comm, PETSC_ERR_FILE_OPEN, "output not writable: %s", msg);
  PetscFunctionReturn(0);
}

} // namespace suite
