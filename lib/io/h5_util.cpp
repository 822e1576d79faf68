// Small internal helpers for the HDF5 wrappers.
#include "io/h5_util.hpp"

namespace suite {
namespace h5 {

void silence() {
  static bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

bool exists(hid_t file, const std::string& path) {
  if (path == "/" || path.empty()) return true;
  // Check every prefix: H5Lexists fails on a path whose intermediate group is missing.
  std::string::size_type pos = 1;
  while (true) {
    pos = path.find('/', pos);
    std::string prefix = path.substr(0, pos);
    if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) return true;
    ++pos;
  }
}

hid_t openObject(hid_t file, const std::string& path, bool create) {
  const std::string p = path.empty() ? "/" : path;
  if (exists(file, p)) return H5Oopen(file, p.c_str(), H5P_DEFAULT);
  if (!create) return -1;
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hid_t g = H5Gcreate2(file, p.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  return g;
}

hid_t stringType() {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return t;
}

} // namespace h5
} // namespace suite
