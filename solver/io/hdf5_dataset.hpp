#pragma once
// Datasets that can tell when they are damaged. Every dataset the toolkit writes is chunked
// with HDF5's Fletcher32 checksum filter, so reading a chunk whose bytes changed on disk
// fails instead of returning other numbers; member files add the shuffle and deflate
// filters (h5py, h5dump and any HDF5 1.10 reader decode them unchanged). Files written before
// the filters existed (contiguous, unfiltered) are read as before.
#include <hdf5.h>

#include <string>

#include "solver/io/hdf5_handle.hpp"

namespace capsule::io {

// Creates (truncates) an HDF5 file in the 1.10 file format or later: its superblock and object
// headers carry checksums of their own (the metadata as well as the data can tell damage), and a
// dataset of one chunk needs no B-tree (a small member file would otherwise grow 2.6x from the
// chunking: 51 against 19.6 KB for a 21-row 2D member; 17 KB this way). HDF5 1.10 or later reads
// it (Debian 12's h5py, h5dump). Returns an invalid handle on failure.
Hdf5Handle create_checked_file(const std::string& path);

enum class DatasetFilters {
  checksum,             // Fletcher32 only: restart points (large, rewritten often; speed matters)
  checksum_compressed,  // shuffle + deflate + Fletcher32: member files (kept, shipped)
};

// Creates dataset `name` under loc with the given file type and extent (rank 1 or 2). An empty
// extent is stored contiguous (HDF5 does not chunk it). Returns an invalid handle on failure.
Hdf5Handle create_dataset(hid_t loc, const std::string& name, hid_t file_type, int rank, const hsize_t* dims,
                          DatasetFilters filters);

// Reads the whole dataset into buffer as mem_type. Throws std::runtime_error naming file and
// dataset when HDF5 refuses, as it does when a chunk's checksum does not match its bytes.
void read_whole_dataset(hid_t set, hid_t mem_type, void* buffer, const std::string& file, const std::string& name);

}  // namespace capsule::io
