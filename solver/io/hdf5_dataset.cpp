#include "solver/io/hdf5_dataset.hpp"

#include <algorithm>
#include <stdexcept>

namespace capsule::io {

namespace {

// About 1 MiB of float64 a chunk: small enough for deflate to stay cheap, large enough that a
// member file's series are one chunk each and a restart point's populations a few hundred.
constexpr hsize_t kChunkElements = hsize_t(1) << 17;
constexpr unsigned kDeflateLevel = 4;  // zlib's middle setting; the size gain is measured in docs/findings

}  // namespace

Hdf5Handle create_checked_file(const std::string& path) {
  Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.ok() || H5Pset_libver_bounds(access, H5F_LIBVER_V110, H5F_LIBVER_LATEST) < 0)
    return Hdf5Handle(-1, H5Fclose);
  return Hdf5Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose);
}

Hdf5Handle create_dataset(hid_t loc, const std::string& name, hid_t file_type, int rank, const hsize_t* dims,
                          DatasetFilters filters) {
  Hdf5Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  if (!space.ok()) return Hdf5Handle(-1, H5Dclose);
  hsize_t elements = 1;
  for (int d = 0; d < rank; ++d) elements *= dims[d];
  Hdf5Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (elements > 0) {
    hsize_t chunk[2] = {dims[0], rank == 2 ? dims[1] : 1};
    const hsize_t row = rank == 2 ? dims[1] : 1;
    chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], kChunkElements / row));
    const bool ok = H5Pset_chunk(properties, rank, chunk) >= 0 &&
                    (filters != DatasetFilters::checksum_compressed ||
                     (H5Pset_shuffle(properties) >= 0 && H5Pset_deflate(properties, kDeflateLevel) >= 0)) &&
                    H5Pset_fletcher32(properties) >= 0;
    if (!ok) return Hdf5Handle(-1, H5Dclose);
  }
  return Hdf5Handle(H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, properties, H5P_DEFAULT), H5Dclose);
}

void read_whole_dataset(hid_t set, hid_t mem_type, void* buffer, const std::string& file, const std::string& name) {
  Hdf5Handle space(H5Dget_space(set), H5Sclose);
  if (H5Sget_simple_extent_npoints(space) == 0) return;
  if (H5Dread(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer) < 0)
    throw std::runtime_error(file + ": dataset " + name +
                             " cannot be read: its checksum does not match its bytes or the file is damaged");
}

}  // namespace capsule::io
