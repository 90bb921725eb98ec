#pragma once
// Reading HDF5 datasets back in tests, with the HDF5 C API.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <string>
#include <vector>

namespace {

struct Dataset {
  std::vector<hsize_t> dimensions;
  H5T_class_t type_class = H5T_NO_CLASS;
  std::size_t type_size = 0;
  std::vector<double> doubles;        // filled when read as double
  std::vector<long long> integers;    // filled when read as int64
};

// Reads `dataset_path` of `file`, converted to double or to long long; fails the test when absent.
Dataset read_dataset(const std::string& file, const std::string& dataset_path, bool as_integer) {
  Dataset result;
  const hid_t file_id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file_id, 0) << file;
  if (file_id < 0) return result;
  const hid_t dataset = H5Dopen2(file_id, dataset_path.c_str(), H5P_DEFAULT);
  EXPECT_GE(dataset, 0) << file << ":" << dataset_path;
  if (dataset >= 0) {
    const hid_t space = H5Dget_space(dataset);
    result.dimensions.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, result.dimensions.data(), nullptr);
    const hid_t type = H5Dget_type(dataset);
    result.type_class = H5Tget_class(type);
    result.type_size = H5Tget_size(type);
    const std::size_t count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    if (as_integer) {
      result.integers.resize(count);
      EXPECT_GE(H5Dread(dataset, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, result.integers.data()), 0);
    } else {
      result.doubles.resize(count);
      EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, result.doubles.data()), 0);
    }
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(dataset);
  }
  H5Fclose(file_id);
  return result;
}

}  // namespace
