// Small internal helpers for the HDF5 wrappers (not part of the public io API).
#pragma once

#include <hdf5.h>
#include <petscsys.h>

#include <string>

namespace suite {
namespace h5 {

// Turns HDF5's own error-stack printing off once (the suite reports its own, clearer errors).
void silence();

template <typename T> hid_t nativeType();
template <> inline hid_t nativeType<double>() {
  return H5T_NATIVE_DOUBLE;
}
template <> inline hid_t nativeType<long long>() {
  return H5T_NATIVE_LLONG;
}
template <> inline hid_t nativeType<int>() {
  return H5T_NATIVE_INT;
}

// Opens an object by path ("/" included); creates the groups of the path when create is true and the object
// does not exist. Returns a negative id when it does not exist and create is false.
hid_t openObject(hid_t file, const std::string& path, bool create);
bool exists(hid_t file, const std::string& path);
// Variable-length UTF-8 string type (caller closes).
hid_t stringType();

} // namespace h5
} // namespace suite
