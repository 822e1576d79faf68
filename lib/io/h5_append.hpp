// Single-process HDF5 file for streamed results (batch drivers: one rank owns the file, the others send it
// their results). MPI-free and PETSc-free: every failure throws std::runtime_error with a clear message; the
// caller turns it into a collective error.
//
// Two kinds of 1-D datasets:
//   - preallocated (createFixed): the final size is known (a batch of `count` problems); the file space is
//     allocated and filled at creation, so later writes only overwrite raw data in place and never touch
//     HDF5 metadata. A process killed (even by SIGKILL) between or during writes leaves a structurally
//     valid file; write the data, flush(), then the "done" flags, flush(), and a reader trusts exactly the
//     entries flagged done. lcpbench uses these.
//   - extendable (createExtendable): chunked, unlimited maximum size, grown by append() / writeAt() past the
//     end. Growing changes metadata (chunk index, dataspace), which is only consistent on disk after
//     flush() / close(): use for logs whose size is not known in advance.
// Scattered writes: select(sorted indices) builds one file selection (runs of consecutive indices) reused by
// writeSelected() for every dataset of the same length, one HDF5 write per dataset.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace suite {

class H5AppendFile {
public:
  H5AppendFile() = default;
  ~H5AppendFile(); // closes (no throw)
  H5AppendFile(const H5AppendFile&) = delete;
  H5AppendFile& operator=(const H5AppendFile&) = delete;

  // Creates (truncates) path.
  void create(const std::string& path);
  // Opens an existing file; throws "PATH: not a valid HDF5 file" etc.
  void open(const std::string& path, bool writable);
  void flush();
  void close();
  bool isOpen() const { return file_ >= 0; }
  const std::string& path() const { return path_; }
  // True when path names a readable HDF5 file.
  static bool isHdf5(const std::string& path);

  // T: double, long long, int, unsigned char.
  template <typename T>
  void createFixed(const std::string& name, unsigned long long size, T fill, const char* units = nullptr);
  template <typename T>
  void createExtendable(const std::string& name, unsigned long long chunk, T fill,
                        const char* units = nullptr);
  bool exists(const std::string& name) const;
  // Removes a dataset or group link if present (its space is not reclaimed).
  void remove(const std::string& name);
  unsigned long long size(const std::string& name) const;

  // Contiguous range [offset, offset + count); an extendable dataset grows as needed, a fixed one throws
  // when the range is past its end.
  template <typename T>
  void writeAt(const std::string& name, unsigned long long offset, const T* data, unsigned long long count);
  template <typename T> void append(const std::string& name, const T* data, unsigned long long count);
  template <typename T>
  void read(const std::string& name, unsigned long long offset, T* data, unsigned long long count) const;
  // Scattered writes: indices strictly increasing; data of writeSelected has one value per index.
  void select(const std::vector<unsigned long long>& sorted_indices);
  template <typename T> void writeSelected(const std::string& name, const T* data);

  // Attributes on "/" or on a group / dataset (groups are created as needed).
  void setAttribute(const std::string& object, const std::string& name, const std::string& value);
  void setAttribute(const std::string& object, const std::string& name, double value);
  void setAttribute(const std::string& object, const std::string& name, long long value);
  void setAttribute(const std::string& object, const std::string& name, const std::vector<double>& value);
  // False when the object or attribute does not exist; throws on a type mismatch.
  bool getAttribute(const std::string& object, const std::string& name, std::string* value) const;
  bool getAttribute(const std::string& object, const std::string& name, double* value) const;
  bool getAttribute(const std::string& object, const std::string& name, long long* value) const;
  bool getAttribute(const std::string& object, const std::string& name, std::vector<double>* value) const;

private:
  template <typename T>
  void create(const std::string& name, unsigned long long size, unsigned long long chunk, bool extendable,
              T fill, const char* units);
  void requireOpen() const;

  int64_t file_ = -1; // hid_t
  std::string path_;
  std::vector<unsigned long long> sel_start_, sel_count_; // runs of the current selection
  unsigned long long sel_points_ = 0, sel_end_ = 0;
};

} // namespace suite
