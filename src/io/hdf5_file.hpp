#pragma once
// The HDF5 C API as rouleau's writers and readers use it: owned handles, failures as
// exceptions that name the file, the object and HDF5's own reason, one dataset writer and
// reader, string attributes on the root group, and files written to PATH.tmp and renamed
// once complete (io/atomic_file.hpp). Host-only: includes no Kokkos header.
#include <hdf5.h>

#include <functional>
#include <string>
#include <vector>

#include "io/provenance.hpp"

namespace rouleau {

// An HDF5 identifier closed by `close` when it goes out of scope.
class Hdf5Handle {
 public:
  Hdf5Handle(hid_t id, herr_t (*close_function)(hid_t)) : id_(id), close_(close_function) {}
  ~Hdf5Handle() {
    if (id_ >= 0) close_(id_);
  }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Hdf5Handle& operator=(Hdf5Handle&&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now and reports HDF5's result (negative on failure), e.g. for a file whose
  // last buffers are written out by H5Fclose.
  herr_t close() {
    const herr_t result = id_ >= 0 ? close_(id_) : 0;
    id_ = -1;
    return result;
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// An open HDF5 file, with the names its errors mention: `who` (e.g.
// "rouleau::XdmfTimeSeries") and the file's path.
struct Hdf5File {
  hid_t id;
  std::string path;
  std::string who;
};

// Throws std::runtime_error "WHO: FILE: OBJECT: ACTION failed: HDF5'S REASON".
[[noreturn]] void throw_hdf5_error(const Hdf5File& file, const std::string& object, const std::string& action);

// Writes `data` (row-major, `dimensions`, in `memory_type`) as the dataset `dataset_path`,
// stored as `file_type`; missing groups on the way are created.
void write_dataset(const Hdf5File& file, const std::string& dataset_path, hid_t memory_type, hid_t file_type,
                   const void* data, const std::vector<hsize_t>& dimensions);
// Writes an n x columns float64 array (a plain n-vector when columns == 1).
void write_double_array(const Hdf5File& file, const std::string& dataset_path, const double* data, std::size_t n,
                        int columns);

// Writes `text` as a one-dimensional dataset of bytes (uint8): text of any length (an
// attribute holds at most 64 KiB).
void write_text_dataset(const Hdf5File& file, const std::string& dataset_path, const std::string& text);

// Writes `value` as a null-terminated UTF-8 string attribute `name` of the root group.
void write_root_string_attribute(const Hdf5File& file, const std::string& name, const std::string& value);

// Creates PATH.tmp, stamps the provenance on its root group, lets `fill` write the
// datasets, closes it, syncs it and renames it to `path`. On failure the .tmp is removed and
// the error rethrown, so `path` is either the complete new file or untouched.
void write_hdf5_file_atomically(const std::string& path, const std::string& who, const Provenance& provenance,
                                const std::function<void(const Hdf5File&)>& fill);

// ---- reading

// Opens `path` read-only; throws std::runtime_error when it is not a readable HDF5 file.
// The handle closes the file.
Hdf5Handle open_hdf5_file(const std::string& path, const std::string& who);

// Whether the file has a link (dataset or group) at `dataset_path` ("/a/b").
bool has_dataset(const Hdf5File& file, const std::string& dataset_path);
// The dataset's dimensions. Throws (naming file and dataset) when it is missing.
std::vector<hsize_t> dataset_dimensions(const Hdf5File& file, const std::string& dataset_path);
// The names of the links (datasets, groups) directly in the group `group_path`, in
// HDF5's name order. Throws when the group is missing.
std::vector<std::string> group_members(const Hdf5File& file, const std::string& group_path);
// The whole dataset converted to double / to int64, row-major. Throws when it is missing.
std::vector<double> read_double_dataset(const Hdf5File& file, const std::string& dataset_path);
std::vector<long long> read_integer_dataset(const Hdf5File& file, const std::string& dataset_path);
// A dataset written by write_text_dataset. Throws when it is missing.
std::string read_text_dataset(const Hdf5File& file, const std::string& dataset_path);
// The string attribute `name` of the root group. Throws when it is missing or not a string.
std::string read_root_string_attribute(const Hdf5File& file, const std::string& name);

}  // namespace rouleau
