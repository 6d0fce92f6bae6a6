#include "solver/io/state_archive.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "solver/io/hdf5_dataset.hpp"
#include "solver/io/hdf5_handle.hpp"
#include "solver/common/atomic_write.hpp"
#include "solver/io/write_guard.hpp"

namespace capsule::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

[[noreturn]] void missing(const std::string& name) { throw std::runtime_error("restart point has no " + name); }

// Marks a file as a restart point (read() refuses any other HDF5 file).
constexpr const char* kMagicName = "capsule_restart_point";

template <class T>
void write_array(hid_t file, const std::string& name, const std::vector<T>& v, hid_t mem, hid_t disk,
                 const std::string& path) {
  const hsize_t n = v.size();
  Hdf5Handle set = create_dataset(file, name, disk, 1, &n, DatasetFilters::checksum);
  if (!set.ok()) fail(path, "cannot create " + name);
  if (n > 0 && H5Dwrite(set, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) fail(path, "cannot write " + name);
}

void write_text(hid_t file, const std::string& name, const std::string& text, const std::string& path) {
  // Texts as byte arrays: any content (JSON with line breaks, NUL-free or not) round-trips.
  const hsize_t n = text.size();
  Hdf5Handle set = create_dataset(file, name, H5T_STD_U8LE, 1, &n, DatasetFilters::checksum);
  if (!set.ok()) fail(path, "cannot create " + name);
  if (n > 0 && H5Dwrite(set, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0)
    fail(path, "cannot write " + name);
  Hdf5Handle aspace(H5Screate(H5S_SCALAR), H5Sclose);
  Hdf5Handle attr(H5Acreate2(set, "text", H5T_STD_U8LE, aspace, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const unsigned char one = 1;
  if (!attr.ok() || H5Awrite(attr, H5T_NATIVE_UCHAR, &one) < 0) fail(path, "cannot mark " + name);
}

herr_t collect(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

}  // namespace

const std::vector<double>& StateArchive::doubles(const std::string& name) const {
  auto it = doubles_.find(name);
  if (it == doubles_.end()) missing(name);
  return it->second;
}
const std::vector<std::int64_t>& StateArchive::ints(const std::string& name) const {
  auto it = ints_.find(name);
  if (it == ints_.end()) missing(name);
  return it->second;
}
const std::string& StateArchive::text(const std::string& name) const {
  auto it = texts_.find(name);
  if (it == texts_.end()) missing(name);
  return it->second;
}
double StateArchive::number(const std::string& name) const {
  const auto& v = doubles(name);
  if (v.size() != 1) missing(name + " (one number)");
  return v[0];
}
std::int64_t StateArchive::integer(const std::string& name) const {
  const auto& v = ints(name);
  if (v.size() != 1) missing(name + " (one integer)");
  return v[0];
}
std::vector<double> StateArchive::take_doubles(const std::string& name) {
  auto it = doubles_.find(name);
  if (it == doubles_.end()) missing(name);
  return std::move(it->second);
}

std::size_t StateArchive::payload_bytes() const {
  std::size_t b = 0;
  for (const auto& [k, v] : doubles_) b += 8 * v.size();
  for (const auto& [k, v] : ints_) b += 8 * v.size();
  for (const auto& [k, v] : texts_) b += v.size();
  return b;
}

void StateArchive::write(const std::string& path) const {
  silence_hdf5_errors();
  require_ownership("write " + path);
  const auto still_owner = [&] { require_ownership("rename over " + path); };
  replace_atomically(path, [&](const std::string& tmp) {
    Hdf5Handle file = create_checked_file(tmp);
    if (!file.ok()) fail(tmp, "cannot create the restart point");
    write_array(file, kMagicName, std::vector<std::int64_t>{1}, H5T_NATIVE_INT64, H5T_STD_I64LE, tmp);
    for (const auto& [name, v] : doubles_) write_array(file, name, v, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, tmp);
    for (const auto& [name, v] : ints_) write_array(file, name, v, H5T_NATIVE_INT64, H5T_STD_I64LE, tmp);
    for (const auto& [name, t] : texts_) write_text(file, name, t, tmp);
    if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) fail(tmp, "cannot flush");
  }, still_owner);
}

StateArchive StateArchive::read(const std::string& path) {
  silence_hdf5_errors();
  if (!std::filesystem::exists(path)) fail(path, "no such restart point");
  Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.ok()) fail(path, "not a readable HDF5 file");
  if (H5Lexists(file, kMagicName, H5P_DEFAULT) <= 0) fail(path, "not a capsule restart point");
  std::vector<std::string> names;
  hsize_t idx = 0;
  if (H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, &idx, collect, &names) < 0) fail(path, "cannot list datasets");
  StateArchive a;
  for (const auto& name : names) {
    if (name == kMagicName) continue;
    Hdf5Handle set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok()) fail(path, "cannot open " + name);
    Hdf5Handle type(H5Dget_type(set), H5Tclose);
    Hdf5Handle space(H5Dget_space(set), H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    if (n < 0) fail(path, "bad extent of " + name);
    const bool is_text = H5Aexists(set, "text") > 0;
    // A chunk whose Fletcher32 checksum does not match its bytes fails to read: refused.
    if (is_text) {
      std::string t(static_cast<std::size_t>(n), '\0');
      read_whole_dataset(set, H5T_NATIVE_UCHAR, t.data(), path, name);
      a.texts_[name] = std::move(t);
    } else if (H5Tget_class(type) == H5T_FLOAT) {
      std::vector<double> v(static_cast<std::size_t>(n));
      read_whole_dataset(set, H5T_NATIVE_DOUBLE, v.data(), path, name);
      a.doubles_[name] = std::move(v);
    } else if (H5Tget_class(type) == H5T_INTEGER) {
      std::vector<std::int64_t> v(static_cast<std::size_t>(n));
      read_whole_dataset(set, H5T_NATIVE_INT64, v.data(), path, name);
      a.ints_[name] = std::move(v);
    } else {
      fail(path, "dataset " + name + " has an unexpected type");
    }
  }
  return a;
}

}  // namespace capsule::io
