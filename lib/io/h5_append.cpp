// Single-process HDF5 file for streamed results; see h5_append.hpp.
#include "io/h5_append.hpp"

#include "io/h5_util.hpp"

#include <hdf5.h>

#include <fstream>
#include <stdexcept>

namespace suite {

namespace {

template <typename T> hid_t memType();
template <> hid_t memType<double>() {
  return H5T_NATIVE_DOUBLE;
}
template <> hid_t memType<long long>() {
  return H5T_NATIVE_LLONG;
}
template <> hid_t memType<int>() {
  return H5T_NATIVE_INT;
}
template <> hid_t memType<unsigned char>() {
  return H5T_NATIVE_UCHAR;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

// RAII for one hid_t with its close function.
struct Id {
  hid_t id;
  herr_t (*closer)(hid_t);
  Id(hid_t i, herr_t (*c)(hid_t)) : id(i), closer(c) {}
  ~Id() {
    if (id >= 0) closer(id);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id; }
};

std::string parentOf(const std::string& name) {
  const auto pos = name.rfind('/');
  if (pos == std::string::npos || pos == 0) return "/";
  return name.substr(0, pos);
}

} // namespace

H5AppendFile::~H5AppendFile() {
  try {
    close();
  } catch (...) {
  }
}

bool H5AppendFile::isHdf5(const std::string& path) {
  h5::silence();
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  return H5Fis_hdf5(path.c_str()) > 0;
}

void H5AppendFile::create(const std::string& path) {
  h5::silence();
  close();
  path_ = path;
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) fail(path, "cannot create HDF5 file (directory missing or not writable?)");
}

void H5AppendFile::open(const std::string& path, bool writable) {
  h5::silence();
  close();
  path_ = path;
  {
    std::ifstream f(path, std::ios::binary);
    if (!f) fail(path, "cannot open file");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0) fail(path, "not a valid HDF5 file");
  file_ = H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) fail(path, writable ? "cannot open HDF5 file for writing" : "cannot open HDF5 file");
}

void H5AppendFile::requireOpen() const {
  if (file_ < 0) throw std::runtime_error("H5AppendFile: no file open");
}

void H5AppendFile::flush() {
  requireOpen();
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) fail(path_, "flush failed (disk full?)");
}

void H5AppendFile::close() {
  if (file_ < 0) return;
  const herr_t st = H5Fclose(file_);
  file_ = -1;
  if (st < 0) fail(path_, "close failed (disk full?)");
}

bool H5AppendFile::exists(const std::string& name) const {
  requireOpen();
  return h5::exists(file_, name);
}

void H5AppendFile::remove(const std::string& name) {
  requireOpen();
  if (h5::exists(file_, name) && H5Ldelete(file_, name.c_str(), H5P_DEFAULT) < 0)
    fail(path_, "cannot remove " + name);
}

template <typename T>
void H5AppendFile::create(const std::string& name, unsigned long long size, unsigned long long chunk,
                          bool extendable, T fill, const char* units) {
  requireOpen();
  if (h5::exists(file_, name)) fail(path_, "dataset " + name + " exists already");
  {
    Id g(h5::openObject(file_, parentOf(name), true), H5Oclose);
    if (g < 0) fail(path_, "cannot create group " + parentOf(name));
  }
  hsize_t dims[1] = {size}, maxdims[1] = {extendable ? H5S_UNLIMITED : size};
  Id space(H5Screate_simple(1, dims, maxdims), H5Sclose);
  Id dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_fill_value(dcpl, memType<T>(), &fill);
  if (extendable) {
    hsize_t c[1] = {chunk > 0 ? chunk : 4096};
    H5Pset_chunk(dcpl, 1, c);
  } else {
    // Contiguous, allocated and filled now: later writes never change metadata (see the header).
    H5Pset_layout(dcpl, H5D_CONTIGUOUS);
    H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY);
    H5Pset_fill_time(dcpl, H5D_FILL_TIME_ALLOC);
  }
  Id d(H5Dcreate2(file_, name.c_str(), memType<T>(), space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
  if (d < 0) fail(path_, "cannot create dataset " + name + " (disk full?)");
  if (units) {
    Id st(h5::stringType(), H5Tclose);
    Id sc(H5Screate(H5S_SCALAR), H5Sclose);
    Id a(H5Acreate2(d, "units", st, sc, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    const char* v = units;
    if (a < 0 || H5Awrite(a, st, &v) < 0) fail(path_, "cannot write attribute units of " + name);
  }
}

template <typename T>
void H5AppendFile::createFixed(const std::string& name, unsigned long long size, T fill, const char* units) {
  create<T>(name, size, 0, false, fill, units);
}

template <typename T>
void H5AppendFile::createExtendable(const std::string& name, unsigned long long chunk, T fill,
                                    const char* units) {
  create<T>(name, 0, chunk, true, fill, units);
}

unsigned long long H5AppendFile::size(const std::string& name) const {
  requireOpen();
  if (!h5::exists(file_, name)) fail(path_, "missing dataset " + name);
  Id d(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (d < 0) fail(path_, "cannot open dataset " + name);
  Id s(H5Dget_space(d), H5Sclose);
  if (H5Sget_simple_extent_ndims(s) != 1) fail(path_, "dataset " + name + " is not one-dimensional");
  hsize_t dims[1] = {0};
  H5Sget_simple_extent_dims(s, dims, nullptr);
  return dims[0];
}

template <typename T>
void H5AppendFile::writeAt(const std::string& name, unsigned long long offset, const T* data,
                           unsigned long long count) {
  requireOpen();
  if (count == 0) return;
  Id d(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (d < 0) fail(path_, "missing dataset " + name);
  hsize_t dims[1] = {0}, maxdims[1] = {0};
  {
    Id s(H5Dget_space(d), H5Sclose);
    if (H5Sget_simple_extent_ndims(s) != 1) fail(path_, "dataset " + name + " is not one-dimensional");
    H5Sget_simple_extent_dims(s, dims, maxdims);
  }
  if (offset + count > dims[0]) {
    if (maxdims[0] != H5S_UNLIMITED)
      fail(path_, "write of [" + std::to_string(offset) + ", " + std::to_string(offset + count) +
                      ") past the end of " + name + " (size " + std::to_string(dims[0]) + ")");
    hsize_t nd[1] = {offset + count};
    if (H5Dset_extent(d, nd) < 0) fail(path_, "cannot extend dataset " + name);
  }
  Id fs(H5Dget_space(d), H5Sclose);
  hsize_t st[1] = {offset}, ct[1] = {count};
  H5Sselect_hyperslab(fs, H5S_SELECT_SET, st, nullptr, ct, nullptr);
  Id ms(H5Screate_simple(1, ct, nullptr), H5Sclose);
  if (H5Dwrite(d, memType<T>(), ms, fs, H5P_DEFAULT, data) < 0)
    fail(path_, "cannot write dataset " + name + " (disk full?)");
}

template <typename T>
void H5AppendFile::append(const std::string& name, const T* data, unsigned long long count) {
  writeAt<T>(name, size(name), data, count);
}

template <typename T>
void H5AppendFile::read(const std::string& name, unsigned long long offset, T* data,
                        unsigned long long count) const {
  requireOpen();
  if (count == 0) return;
  const unsigned long long n = size(name);
  if (offset + count > n)
    fail(path_, "read of [" + std::to_string(offset) + ", " + std::to_string(offset + count) +
                    ") past the end of " + name + " (size " + std::to_string(n) + ")");
  Id d(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
  Id fs(H5Dget_space(d), H5Sclose);
  hsize_t st[1] = {offset}, ct[1] = {count};
  H5Sselect_hyperslab(fs, H5S_SELECT_SET, st, nullptr, ct, nullptr);
  Id ms(H5Screate_simple(1, ct, nullptr), H5Sclose);
  if (H5Dread(d, memType<T>(), ms, fs, H5P_DEFAULT, data) < 0) fail(path_, "cannot read dataset " + name);
}

void H5AppendFile::select(const std::vector<unsigned long long>& idx) {
  sel_start_.clear();
  sel_count_.clear();
  sel_points_ = idx.size();
  sel_end_ = 0;
  for (size_t i = 0; i < idx.size(); ++i) {
    if (i > 0 && idx[i] <= idx[i - 1])
      throw std::runtime_error("H5AppendFile::select: indices not increasing");
    if (!sel_start_.empty() && sel_start_.back() + sel_count_.back() == idx[i])
      ++sel_count_.back();
    else {
      sel_start_.push_back(idx[i]);
      sel_count_.push_back(1);
    }
  }
  if (!idx.empty()) sel_end_ = idx.back() + 1;
}

template <typename T> void H5AppendFile::writeSelected(const std::string& name, const T* data) {
  requireOpen();
  if (sel_points_ == 0) return;
  Id d(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (d < 0) fail(path_, "missing dataset " + name);
  Id fs(H5Dget_space(d), H5Sclose);
  hsize_t dims[1] = {0};
  H5Sget_simple_extent_dims(fs, dims, nullptr);
  if (sel_end_ > dims[0]) fail(path_, "selected index past the end of " + name);
  H5Sselect_none(fs);
  for (size_t r = 0; r < sel_start_.size(); ++r) {
    hsize_t st[1] = {sel_start_[r]}, ct[1] = {sel_count_[r]};
    H5Sselect_hyperslab(fs, H5S_SELECT_OR, st, nullptr, ct, nullptr);
  }
  hsize_t np[1] = {sel_points_};
  Id ms(H5Screate_simple(1, np, nullptr), H5Sclose);
  if (H5Dwrite(d, memType<T>(), ms, fs, H5P_DEFAULT, data) < 0)
    fail(path_, "cannot write dataset " + name + " (disk full?)");
}

// ---- attributes ----
namespace {
void putAttr(hid_t file, const std::string& path, const std::string& object, const std::string& name,
             hid_t type, hid_t space, const void* buf) {
  Id obj(h5::openObject(file, object, true), H5Oclose);
  if (obj < 0) fail(path, "cannot open or create " + object);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Id a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (a < 0 || H5Awrite(a, type, buf) < 0) fail(path, "cannot write attribute " + name + " on " + object);
}

// Opens attribute name of object; -1 when absent.
hid_t openAttr(hid_t file, const std::string& object, const std::string& name) {
  if (!h5::exists(file, object)) return -1;
  Id obj(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (obj < 0 || H5Aexists(obj, name.c_str()) <= 0) return -1;
  return H5Aopen(obj, name.c_str(), H5P_DEFAULT);
}
} // namespace

void H5AppendFile::setAttribute(const std::string& object, const std::string& name,
                                const std::string& value) {
  requireOpen();
  Id t(h5::stringType(), H5Tclose);
  Id s(H5Screate(H5S_SCALAR), H5Sclose);
  const char* v = value.c_str();
  putAttr(file_, path_, object, name, t, s, &v);
}

void H5AppendFile::setAttribute(const std::string& object, const std::string& name, double value) {
  requireOpen();
  Id s(H5Screate(H5S_SCALAR), H5Sclose);
  putAttr(file_, path_, object, name, H5T_NATIVE_DOUBLE, s, &value);
}

void H5AppendFile::setAttribute(const std::string& object, const std::string& name, long long value) {
  requireOpen();
  Id s(H5Screate(H5S_SCALAR), H5Sclose);
  putAttr(file_, path_, object, name, H5T_NATIVE_LLONG, s, &value);
}

void H5AppendFile::setAttribute(const std::string& object, const std::string& name,
                                const std::vector<double>& value) {
  requireOpen();
  hsize_t n[1] = {value.size()};
  Id s(value.empty() ? H5Screate(H5S_NULL) : H5Screate_simple(1, n, nullptr), H5Sclose);
  putAttr(file_, path_, object, name, H5T_NATIVE_DOUBLE, s, value.data());
}

bool H5AppendFile::getAttribute(const std::string& object, const std::string& name,
                                std::string* value) const {
  requireOpen();
  Id a(openAttr(file_, object, name), H5Aclose);
  if (a < 0) return false;
  Id ft(H5Aget_type(a), H5Tclose);
  if (H5Tget_class(ft) != H5T_STRING) fail(path_, "attribute " + name + " of " + object + " is not a string");
  if (H5Tis_variable_str(ft) > 0) {
    Id mt(h5::stringType(), H5Tclose);
    char* v = nullptr;
    if (H5Aread(a, mt, &v) < 0) fail(path_, "cannot read attribute " + name);
    *value = v ? v : "";
    Id s(H5Aget_space(a), H5Sclose);
    H5Dvlen_reclaim(mt, s, H5P_DEFAULT, &v);
  } else {
    const size_t n = H5Tget_size(ft);
    std::string buf(n, '\0');
    if (H5Aread(a, ft, buf.data()) < 0) fail(path_, "cannot read attribute " + name);
    *value = buf.c_str();
  }
  return true;
}

bool H5AppendFile::getAttribute(const std::string& object, const std::string& name, double* value) const {
  requireOpen();
  Id a(openAttr(file_, object, name), H5Aclose);
  if (a < 0) return false;
  Id ft(H5Aget_type(a), H5Tclose);
  Id s(H5Aget_space(a), H5Sclose);
  if (H5Tget_class(ft) == H5T_STRING || H5Sget_simple_extent_npoints(s) != 1)
    fail(path_, "attribute " + name + " of " + object + " is not a number");
  if (H5Aread(a, H5T_NATIVE_DOUBLE, value) < 0) fail(path_, "cannot read attribute " + name);
  return true;
}

bool H5AppendFile::getAttribute(const std::string& object, const std::string& name, long long* value) const {
  requireOpen();
  Id a(openAttr(file_, object, name), H5Aclose);
  if (a < 0) return false;
  Id ft(H5Aget_type(a), H5Tclose);
  Id s(H5Aget_space(a), H5Sclose);
  if (H5Tget_class(ft) != H5T_INTEGER || H5Sget_simple_extent_npoints(s) != 1)
    fail(path_, "attribute " + name + " of " + object + " is not an integer");
  if (H5Aread(a, H5T_NATIVE_LLONG, value) < 0) fail(path_, "cannot read attribute " + name);
  return true;
}

bool H5AppendFile::getAttribute(const std::string& object, const std::string& name,
                                std::vector<double>* value) const {
  requireOpen();
  Id a(openAttr(file_, object, name), H5Aclose);
  if (a < 0) return false;
  Id ft(H5Aget_type(a), H5Tclose);
  Id s(H5Aget_space(a), H5Sclose);
  if (H5Tget_class(ft) == H5T_STRING) fail(path_, "attribute " + name + " of " + object + " is not numeric");
  const hssize_t n = H5Sget_select_npoints(s);
  value->assign(n > 0 ? static_cast<size_t>(n) : 0, 0.0);
  if (n > 0 && H5Aread(a, H5T_NATIVE_DOUBLE, value->data()) < 0) fail(path_, "cannot read attribute " + name);
  return true;
}

#define SUITE_H5APPEND_INSTANTIATE(T)                                                                        \
  template void H5AppendFile::createFixed<T>(const std::string&, unsigned long long, T, const char*);        \
  template void H5AppendFile::createExtendable<T>(const std::string&, unsigned long long, T, const char*);   \
  template void H5AppendFile::writeAt<T>(const std::string&, unsigned long long, const T*,                   \
                                         unsigned long long);                                                \
  template void H5AppendFile::append<T>(const std::string&, const T*, unsigned long long);                   \
  template void H5AppendFile::read<T>(const std::string&, unsigned long long, T*, unsigned long long) const; \
  template void H5AppendFile::writeSelected<T>(const std::string&, const T*);
SUITE_H5APPEND_INSTANTIATE(double)
SUITE_H5APPEND_INSTANTIATE(long long)
SUITE_H5APPEND_INSTANTIATE(int)
SUITE_H5APPEND_INSTANTIATE(unsigned char)
#undef SUITE_H5APPEND_INSTANTIATE

} // namespace suite
