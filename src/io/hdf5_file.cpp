#include "io/hdf5_file.hpp"

#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace rouleau {

namespace {

// The innermost message of HDF5's error stack (where the failure was detected), then clears it.
std::string hdf5_error_detail() {
  std::string detail;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* error, void* client) -> herr_t {
        *static_cast<std::string*>(client) =
            std::string(error->func_name ? error->func_name : "?") + ": " + (error->desc ? error->desc : "");
        return 0;
      },
      &detail);
  H5Eclear2(H5E_DEFAULT);
  return detail.empty() ? "no detail from HDF5" : detail;
}

// HDF5 reports failures by return values only: no printing of its error stack.
void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

Hdf5Handle open_dataset(const Hdf5File& file, const std::string& dataset_path) {
  if (!has_dataset(file, dataset_path))
    throw std::runtime_error(file.who + ": " + file.path + ": " + dataset_path + ": no such dataset");
  Hdf5Handle dataset(H5Dopen2(file.id, dataset_path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) throw_hdf5_error(file, dataset_path, "H5Dopen2");
  return dataset;
}

// The dataspace of an open dataset.
Hdf5Handle dataset_space(const Hdf5File& file, const std::string& dataset_path, const Hdf5Handle& dataset) {
  Hdf5Handle space(H5Dget_space(dataset.get()), H5Sclose);
  if (!space.valid()) throw_hdf5_error(file, dataset_path, "H5Dget_space");
  return space;
}

template <class T>
std::vector<T> read_whole_dataset(const Hdf5File& file, const std::string& dataset_path, hid_t memory_type) {
  Hdf5Handle dataset = open_dataset(file, dataset_path);
  const Hdf5Handle space = dataset_space(file, dataset_path, dataset);
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) throw_hdf5_error(file, dataset_path, "H5Sget_simple_extent_npoints");
  std::vector<T> values(static_cast<std::size_t>(count));
  if (count > 0 && H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw_hdf5_error(file, dataset_path, "H5Dread");
  return values;
}

}  // namespace

void throw_hdf5_error(const Hdf5File& file, const std::string& object, const std::string& action) {
  throw std::runtime_error(file.who + ": " + file.path + ": " + object + ": " + action +
                           " failed: " + hdf5_error_detail());
}

void write_dataset(const Hdf5File& file, const std::string& dataset_path, hid_t memory_type, hid_t file_type,
                   const void* data, const std::vector<hsize_t>& dimensions) {
  Hdf5Handle space(H5Screate_simple(static_cast<int>(dimensions.size()), dimensions.data(), nullptr), H5Sclose);
  if (!space.valid()) throw_hdf5_error(file, dataset_path, "H5Screate_simple");
  Hdf5Handle link_properties(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  if (!link_properties.valid() || H5Pset_create_intermediate_group(link_properties.get(), 1) < 0)
    throw_hdf5_error(file, dataset_path, "H5Pset_create_intermediate_group");
  Hdf5Handle dataset(H5Dcreate2(file.id, dataset_path.c_str(), file_type, space.get(), link_properties.get(),
                                H5P_DEFAULT, H5P_DEFAULT),
                     H5Dclose);
  if (!dataset.valid()) throw_hdf5_error(file, dataset_path, "H5Dcreate2");
  if (H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throw_hdf5_error(file, dataset_path, "H5Dwrite");
}

void write_double_array(const Hdf5File& file, const std::string& dataset_path, const double* data, std::size_t n,
                        int columns) {
  std::vector<hsize_t> dimensions{static_cast<hsize_t>(n)};
  if (columns != 1) dimensions.push_back(static_cast<hsize_t>(columns));
  write_dataset(file, dataset_path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, data, dimensions);
}

void write_text_dataset(const Hdf5File& file, const std::string& dataset_path, const std::string& text) {
  write_dataset(file, dataset_path, H5T_NATIVE_UCHAR, H5T_STD_U8LE, text.data(), {static_cast<hsize_t>(text.size())});
}

void write_root_string_attribute(const Hdf5File& file, const std::string& name, const std::string& value) {
  const std::string object = "/ attribute " + name;
  Hdf5Handle string_type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!string_type.valid() || H5Tset_size(string_type.get(), value.size() + 1) < 0 ||
      H5Tset_strpad(string_type.get(), H5T_STR_NULLTERM) < 0 || H5Tset_cset(string_type.get(), H5T_CSET_UTF8) < 0)
    throw_hdf5_error(file, object, "string type");
  Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.valid()) throw_hdf5_error(file, object, "H5Screate");
  Hdf5Handle attribute(H5Acreate2(file.id, name.c_str(), string_type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                       H5Aclose);
  if (!attribute.valid()) throw_hdf5_error(file, object, "H5Acreate2");
  if (H5Awrite(attribute.get(), string_type.get(), value.c_str()) < 0) throw_hdf5_error(file, object, "H5Awrite");
}

void write_hdf5_file_atomically(const std::string& path, const std::string& who, const Provenance& provenance,
                                const std::function<void(const Hdf5File&)>& fill) {
  silence_hdf5_errors();
  const std::string temporary = temporary_path_for(path);
  try {
    Hdf5Handle handle(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    const Hdf5File file{handle.get(), temporary, who};
    if (!handle.valid()) throw_hdf5_error(file, "/", "H5Fcreate");
    for (const auto& [key, value] : provenance.attributes) write_root_string_attribute(file, key, value);
    fill(file);
    if (handle.close() < 0) throw_hdf5_error(file, "/", "H5Fclose");
    commit_temporary_file(temporary, path);
  } catch (...) {
    std::error_code ignored;
    if (!std::filesystem::is_directory(temporary, ignored)) std::filesystem::remove(temporary, ignored);
    throw;
  }
}

Hdf5Handle open_hdf5_file(const std::string& path, const std::string& who) {
  silence_hdf5_errors();
  Hdf5Handle handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!handle.valid()) throw_hdf5_error(Hdf5File{-1, path, who}, "/", "H5Fopen");
  return handle;
}

bool has_dataset(const Hdf5File& file, const std::string& dataset_path) {
  // H5Lexists needs every group on the way to exist: check each prefix in turn.
  if (dataset_path.empty() || dataset_path[0] != '/') return false;
  for (std::size_t slash = dataset_path.find('/', 1);; slash = dataset_path.find('/', slash + 1)) {
    const std::string prefix = dataset_path.substr(0, slash);
    if (H5Lexists(file.id, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) return true;
  }
}

std::vector<hsize_t> dataset_dimensions(const Hdf5File& file, const std::string& dataset_path) {
  Hdf5Handle dataset = open_dataset(file, dataset_path);
  const Hdf5Handle space = dataset_space(file, dataset_path, dataset);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) throw_hdf5_error(file, dataset_path, "H5Sget_simple_extent_ndims");
  std::vector<hsize_t> dimensions(static_cast<std::size_t>(rank));
  if (H5Sget_simple_extent_dims(space.get(), dimensions.data(), nullptr) < 0)
    throw_hdf5_error(file, dataset_path, "H5Sget_simple_extent_dims");
  return dimensions;
}

std::vector<std::string> group_members(const Hdf5File& file, const std::string& group_path) {
  if (group_path != "/" && !has_dataset(file, group_path))
    throw std::runtime_error(file.who + ": " + file.path + ": " + group_path + ": no such group");
  Hdf5Handle group(H5Gopen2(file.id, group_path.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throw_hdf5_error(file, group_path, "H5Gopen2");
  H5G_info_t info;
  if (H5Gget_info(group.get(), &info) < 0) throw_hdf5_error(file, group_path, "H5Gget_info");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length < 0) throw_hdf5_error(file, group_path, "H5Lget_name_by_idx");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    if (H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT) < 0)
      throw_hdf5_error(file, group_path, "H5Lget_name_by_idx");
    name.resize(static_cast<std::size_t>(length));
    names.push_back(name);
  }
  return names;
}

std::vector<double> read_double_dataset(const Hdf5File& file, const std::string& dataset_path) {
  return read_whole_dataset<double>(file, dataset_path, H5T_NATIVE_DOUBLE);
}

std::vector<long long> read_integer_dataset(const Hdf5File& file, const std::string& dataset_path) {
  return read_whole_dataset<long long>(file, dataset_path, H5T_NATIVE_LLONG);
}

std::string read_text_dataset(const Hdf5File& file, const std::string& dataset_path) {
  const std::vector<unsigned char> bytes = read_whole_dataset<unsigned char>(file, dataset_path, H5T_NATIVE_UCHAR);
  return std::string(bytes.begin(), bytes.end());
}

std::string read_root_string_attribute(const Hdf5File& file, const std::string& name) {
  const std::string object = "/ attribute " + name;
  if (H5Aexists(file.id, name.c_str()) <= 0)
    throw std::runtime_error(file.who + ": " + file.path + ": " + object + ": missing");
  Hdf5Handle attribute(H5Aopen(file.id, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) throw_hdf5_error(file, object, "H5Aopen");
  Hdf5Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0)
    throw std::runtime_error(file.who + ": " + file.path + ": " + object + ": not a fixed-length string");
  const std::size_t size = H5Tget_size(type.get());
  std::string value(size, '\0');
  // Read in the stored string type itself (its size, padding and character set).
  if (H5Aread(attribute.get(), type.get(), value.data()) < 0) throw_hdf5_error(file, object, "H5Aread");
  value.resize(value.find('\0') == std::string::npos ? size : value.find('\0'));
  return value;
}

}  // namespace rouleau
