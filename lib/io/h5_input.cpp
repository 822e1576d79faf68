// Reading the suite's HDF5 files: attributes and blocks of global arrays, with clear collective errors.
#include "io/h5_input.hpp"

#include "io/h5_util.hpp"

#include <hdf5.h>

#include <algorithm>
#include <unistd.h>

namespace suite {

H5Input::~H5Input() {
  if (file_ >= 0) H5Fclose((hid_t)file_);
}

PetscErrorCode H5Input::close() {
  PetscFunctionBeginUser;
  if (file_ >= 0) H5Fclose((hid_t)file_);
  file_ = -1;
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::open(MPI_Comm comm, const std::string& path) {
  PetscFunctionBeginUser;
  h5::silence();
  comm_ = comm;
  path_ = path;
  int rank = 0, state = 0; // 0 ok, 1 missing, 2 not HDF5
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) {
    if (access(path.c_str(), R_OK) != 0)
      state = 1;
    else if (H5Fis_hdf5(path.c_str()) <= 0)
      state = 2;
  }
  PetscCallMPI(MPI_Bcast(&state, 1, MPI_INT, 0, comm));
  PetscCheck(state != 1, comm, PETSC_ERR_FILE_OPEN, "cannot read file %s (missing or no permission)",
             path.c_str());
  PetscCheck(state != 2, comm, PETSC_ERR_FILE_UNEXPECTED,
             "%s is not a valid HDF5 file (truncated or corrupted?)", path.c_str());
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  int size = 1;
  MPI_Comm_size(comm, &size);
  serial_ = size == 1;
  if (!serial_) H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL); // one rank: HDF5's POSIX driver, no MPI-IO layer
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl);
  H5Pclose(fapl);
  PetscCheck(f >= 0, comm, PETSC_ERR_FILE_UNEXPECTED, "cannot open HDF5 file %s (truncated or corrupted?)",
             path.c_str());
  file_ = f;
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::hasObject(const std::string& p, bool* e) const {
  PetscFunctionBeginUser;
  *e = h5::exists((hid_t)file_, p);
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::hasAttribute(const std::string& object, const std::string& name, bool* e) const {
  PetscFunctionBeginUser;
  *e = false;
  hid_t obj = h5::openObject((hid_t)file_, object, false);
  if (obj >= 0) {
    *e = H5Aexists(obj, name.c_str()) > 0;
    H5Oclose(obj);
  }
  PetscFunctionReturn(0);
}

namespace {
// Opens attribute object:name or fails collectively with a message naming file, object and attribute.
PetscErrorCode openAttr(MPI_Comm comm, hid_t file, const std::string& path, const std::string& object,
                        const std::string& name, hid_t* attr) {
  PetscFunctionBeginUser;
  hid_t obj = h5::openObject(file, object, false);
  PetscCheck(obj >= 0, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: missing object %s", path.c_str(),
             object.c_str());
  *attr = H5Aexists(obj, name.c_str()) > 0 ? H5Aopen(obj, name.c_str(), H5P_DEFAULT) : -1;
  H5Oclose(obj);
  PetscCheck(*attr >= 0, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: missing attribute '%s' on %s", path.c_str(),
             name.c_str(), object.c_str());
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode H5Input::readAttribute(const std::string& object, const std::string& name,
                                      std::string* value) const {
  PetscFunctionBeginUser;
  hid_t attr;
  PetscCall(openAttr(comm_, (hid_t)file_, path_, object, name, &attr));
  hid_t ftype = H5Aget_type(attr);
  bool is_string = H5Tget_class(ftype) == H5T_STRING;
  herr_t st = -1;
  if (is_string && H5Tis_variable_str(ftype) > 0) {
    hid_t mtype = h5::stringType();
    char* buf = nullptr;
    st = H5Aread(attr, mtype, &buf);
    if (st >= 0 && buf) *value = buf;
    if (buf) H5free_memory(buf);
    H5Tclose(mtype);
  } else if (is_string) {
    size_t n = H5Tget_size(ftype);
    std::string buf(n, '\0');
    hid_t mtype = H5Tcopy(H5T_C_S1);
    H5Tset_size(mtype, n);
    st = H5Aread(attr, mtype, &buf[0]);
    H5Tclose(mtype);
    *value = buf.c_str();
  }
  H5Tclose(ftype);
  H5Aclose(attr);
  PetscCheck(is_string && st >= 0, comm_, PETSC_ERR_FILE_UNEXPECTED,
             "%s: attribute '%s' on %s is not a string", path_.c_str(), name.c_str(), object.c_str());
  PetscFunctionReturn(0);
}

template <typename T>
static PetscErrorCode readNumericAttr(MPI_Comm comm, hid_t file, const std::string& path,
                                      const std::string& object, const std::string& name,
                                      std::vector<T>* out) {
  PetscFunctionBeginUser;
  hid_t attr;
  PetscCall(openAttr(comm, file, path, object, name, &attr));
  hid_t ftype = H5Aget_type(attr);
  H5T_class_t cls = H5Tget_class(ftype);
  hid_t space = H5Aget_space(attr);
  hssize_t n = H5Sget_simple_extent_npoints(space);
  out->assign(n > 0 ? (size_t)n : 0, T());
  herr_t st = -1;
  if ((cls == H5T_FLOAT || cls == H5T_INTEGER) && n > 0) st = H5Aread(attr, h5::nativeType<T>(), out->data());
  H5Sclose(space);
  H5Tclose(ftype);
  H5Aclose(attr);
  PetscCheck(st >= 0, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: attribute '%s' on %s is not numeric",
             path.c_str(), name.c_str(), object.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::readAttribute(const std::string& object, const std::string& name,
                                      double* value) const {
  PetscFunctionBeginUser;
  std::vector<double> v;
  PetscCall(readNumericAttr(comm_, (hid_t)file_, path_, object, name, &v));
  PetscCheck(v.size() == 1, comm_, PETSC_ERR_FILE_UNEXPECTED, "%s: attribute '%s' on %s is not a scalar",
             path_.c_str(), name.c_str(), object.c_str());
  *value = v[0];
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::readAttribute(const std::string& object, const std::string& name,
                                      long long* value) const {
  PetscFunctionBeginUser;
  std::vector<long long> v;
  PetscCall(readNumericAttr(comm_, (hid_t)file_, path_, object, name, &v));
  PetscCheck(v.size() == 1, comm_, PETSC_ERR_FILE_UNEXPECTED, "%s: attribute '%s' on %s is not a scalar",
             path_.c_str(), name.c_str(), object.c_str());
  *value = v[0];
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::readAttribute(const std::string& object, const std::string& name,
                                      std::vector<double>* value) const {
  return readNumericAttr(comm_, (hid_t)file_, path_, object, name, value);
}

PetscErrorCode H5Input::groupMembers(const std::string& group, std::vector<std::string>* names) const {
  PetscFunctionBeginUser;
  names->clear();
  hid_t g = h5::openObject((hid_t)file_, group, false);
  const bool is_group = g >= 0 && H5Iget_type(g) == H5I_GROUP;
  if (is_group) {
    H5G_info_t gi;
    if (H5Gget_info(g, &gi) >= 0)
      for (hsize_t i = 0; i < gi.nlinks; ++i) {
        const ssize_t len =
            H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
        if (len < 0) continue;
        std::string name((size_t)len + 1, '\0');
        H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
        name.resize((size_t)len);
        names->push_back(name);
      }
  }
  if (g >= 0) H5Oclose(g);
  PetscCheck(is_group, comm_, PETSC_ERR_FILE_UNEXPECTED, "%s: no group %s", path_.c_str(), group.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::datasetDims(const std::string& dataset, Dims* dims) const {
  PetscFunctionBeginUser;
  hid_t d = h5::exists((hid_t)file_, dataset) ? H5Dopen2((hid_t)file_, dataset.c_str(), H5P_DEFAULT) : -1;
  PetscCheck(d >= 0, comm_, PETSC_ERR_FILE_UNEXPECTED, "%s: missing dataset %s", path_.c_str(),
             dataset.c_str());
  hid_t space = H5Dget_space(d);
  int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> h(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space, h.data(), nullptr);
  dims->assign(h.begin(), h.end());
  H5Sclose(space);
  H5Dclose(d);
  PetscFunctionReturn(0);
}

template <typename T>
PetscErrorCode H5Input::readBlockT(const std::string& dataset, const Dims& start, const Dims& count,
                                   T* local) const {
  PetscFunctionBeginUser;
  Dims dims;
  PetscCall(datasetDims(dataset, &dims));
  bool fits = dims.size() == start.size() && dims.size() == count.size();
  bool empty = false;
  for (size_t i = 0; fits && i < dims.size(); ++i) {
    fits = start[i] + count[i] <= dims[i];
    empty = empty || count[i] == 0;
  }
  int lfits = fits, gfits = 0;
  PetscCallMPI(MPI_Allreduce(&lfits, &gfits, 1, MPI_INT, MPI_LAND, comm_));
  PetscCheck(gfits, comm_, PETSC_ERR_FILE_UNEXPECTED, "%s: dataset %s is smaller than the block requested",
             path_.c_str(), dataset.c_str());
  hid_t d = H5Dopen2((hid_t)file_, dataset.c_str(), H5P_DEFAULT);
  hid_t fspace = H5Dget_space(d);
  std::vector<hsize_t> s(start.begin(), start.end()), c(count.begin(), count.end());
  hid_t mspace;
  if (empty || dims.empty()) {
    hsize_t one = 1;
    mspace = H5Screate_simple(1, &one, nullptr);
    H5Sselect_none(mspace);
    if (!dims.empty()) H5Sselect_none(fspace);
  } else {
    mspace = H5Screate_simple((int)c.size(), c.data(), nullptr);
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, s.data(), nullptr, c.data(), nullptr);
  }
  hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
  if (!serial_) H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE);
  herr_t st = H5Dread(d, h5::nativeType<T>(), mspace, fspace, dxpl, local);
  H5Pclose(dxpl);
  H5Sclose(mspace);
  H5Sclose(fspace);
  H5Dclose(d);
  int ok = st >= 0, all = 0;
  PetscCallMPI(MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_LAND, comm_));
  PetscCheck(all, comm_, PETSC_ERR_FILE_READ, "%s: reading dataset %s failed (truncated or corrupted file?)",
             path_.c_str(), dataset.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::readBlock(const std::string& ds, const Dims& start, const Dims& count,
                                  double* local) const {
  return readBlockT(ds, start, count, local);
}
PetscErrorCode H5Input::readBlock(const std::string& ds, const Dims& start, const Dims& count,
                                  long long* local) const {
  return readBlockT(ds, start, count, local);
}

PetscErrorCode H5Input::checkPlausibleSize(const std::string& dataset, const Dims& dims,
                                           size_t element_bytes) const {
  PetscFunctionBeginUser;
  long double need = (long double)element_bytes;
  for (auto d : dims) need *= (long double)d;
  hid_t d = H5Dopen2((hid_t)file_, dataset.c_str(), H5P_DEFAULT);
  PetscCheck(d >= 0, comm_, PETSC_ERR_FILE_UNEXPECTED, "%s: missing dataset %s", path_.c_str(),
             dataset.c_str());
  const long double stored = (long double)H5Dget_storage_size(d);
  hid_t dcpl = H5Dget_create_plist(d);
  const int filters = dcpl >= 0 ? H5Pget_nfilters(dcpl) : 0;
  if (dcpl >= 0) H5Pclose(dcpl);
  H5Dclose(d);
  const long double limit = filters > 0 ? 1024.0L * stored + 1048576.0L : std::max(stored, 1048576.0L);
  PetscCheck(
      need <= limit, comm_, PETSC_ERR_FILE_UNEXPECTED,
      "%s: dataset %s claims %.3Lg bytes but the file stores %.3Lg for it (corrupted or truncated file)",
      path_.c_str(), dataset.c_str(), need, stored);
  PetscFunctionReturn(0);
}

template <typename T>
static PetscErrorCode readAllT(const H5Input& in, const std::string& ds, std::vector<T>* data, Dims* dims) {
  PetscFunctionBeginUser;
  PetscCall(in.datasetDims(ds, dims));
  PetscCall(in.checkPlausibleSize(ds, *dims, sizeof(T)));
  size_t n = 1;
  for (auto d : *dims) n *= d;
  data->assign(n, T());
  PetscCall(in.readBlock(ds, Dims(dims->size(), 0), *dims, n ? data->data() : nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode H5Input::readAll(const std::string& ds, std::vector<double>* data, Dims* dims) const {
  return readAllT(*this, ds, data, dims);
}
PetscErrorCode H5Input::readAll(const std::string& ds, std::vector<long long>* data, Dims* dims) const {
  return readAllT(*this, ds, data, dims);
}

} // namespace suite
