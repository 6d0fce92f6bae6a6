#pragma once
// Damage a file as a failing disk or a stray write would, for the tests of the checksums:
// flip one bit inside the stored bytes of one dataset (its first chunk, or its contiguous
// data), located through HDF5 itself, then written with plain file I/O.
#include <hdf5.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace capsule::testing {

inline void flip_bit_in_dataset(const std::string& file, const std::string& dataset) {
  haddr_t address = HADDR_UNDEF;
  hsize_t size = 0;
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) throw std::runtime_error("flip_bit_in_dataset: cannot open " + file);
    const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    if (d < 0) {
      H5Fclose(f);
      throw std::runtime_error("flip_bit_in_dataset: no dataset " + dataset + " in " + file);
    }
    const hid_t dcpl = H5Dget_create_plist(d);
    if (H5Pget_layout(dcpl) == H5D_CHUNKED) {
      const hid_t space = H5Dget_space(d);
      unsigned mask = 0;
      hsize_t offset[2] = {0, 0};
      H5Dget_chunk_info(d, space, 0, offset, &mask, &address, &size);
      H5Sclose(space);
    } else {
      address = H5Dget_offset(d);
      size = H5Dget_storage_size(d);
    }
    H5Pclose(dcpl);
    H5Dclose(d);
    H5Fclose(f);
  }
  if (address == HADDR_UNDEF || size == 0) throw std::runtime_error("flip_bit_in_dataset: " + dataset + " has no stored bytes");
  std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
  io.seekg(static_cast<std::streamoff>(address + size / 2));
  char byte = 0;
  io.read(&byte, 1);
  byte = static_cast<char>(byte ^ 0x10);
  io.seekp(static_cast<std::streamoff>(address + size / 2));
  io.write(&byte, 1);
}

}  // namespace capsule::testing
