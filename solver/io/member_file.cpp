#include "solver/io/member_file.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <cerrno>
#include <cstring>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <system_error>

#include "solver/io/content_hash.hpp"
#include "solver/io/hdf5_dataset.hpp"
#include "solver/io/hdf5_handle.hpp"
#include "solver/io/quantities.hpp"
#include "solver/common/atomic_write.hpp"
#include "solver/io/write_guard.hpp"

namespace capsule::io {
namespace {

using Handle = Hdf5Handle;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

void check(herr_t r, const std::string& path, const std::string& what) {
  if (r < 0) fail(path, what);
}

hid_t string_type() {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return t;
}

void write_string_attr(hid_t obj, const std::string& name, const std::string& value, const std::string& path) {
  Handle type(string_type(), H5Tclose);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) fail(path, "cannot create attribute " + name);
  const char* c = value.c_str();
  check(H5Awrite(attr, type, &c), path, "cannot write attribute " + name);
}

template <class T>
void write_scalar_attr(hid_t obj, const std::string& name, T value, hid_t mem_type, hid_t file_type,
                       const std::string& path) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(obj, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) fail(path, "cannot create attribute " + name);
  check(H5Awrite(attr, mem_type, &value), path, "cannot write attribute " + name);
}

void write_matrix(hid_t group, const std::string& name, const double* data, hsize_t rows, hsize_t cols,
                  const std::string& path) {
  hsize_t dims[2] = {rows, cols};
  Handle set = create_dataset(group, name, H5T_IEEE_F64LE, cols == 0 ? 1 : 2, dims, DatasetFilters::checksum_compressed);
  if (!set.ok()) fail(path, "cannot create dataset " + name);
  if (rows > 0) check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path, "write " + name);
}

// The parts of a member file as the content hash sees them (content_hash.hpp): the writer and
// read_member describe the same file in the same words.
void digest_doubles(ContentDigest& d, const std::string& name, const double* data, std::size_t n,
                    std::uint64_t rows, std::uint64_t cols) {
  Fnv1a64 h;
  h.add(&rows, sizeof rows);
  h.add(&cols, sizeof cols);
  h.add(data, n * sizeof(double));
  const std::uint64_t v = h.value();
  d.add(name, 'f', &v, sizeof v);
}
void digest_attribute(ContentDigest& d, const std::string& name, const nlohmann::json& value) {
  if (value.is_string()) {
    const std::string s = value.get<std::string>();
    d.add(name, 's', s.data(), s.size());
  } else if (value.is_number_integer()) {
    const std::int64_t x = value.get<std::int64_t>();
    d.add(name, 'i', &x, sizeof x);
  } else if (value.is_number()) {
    const double x = value.get<double>();
    d.add(name, 'd', &x, sizeof x);
  }
}

// The attributes `units` and `description` of a quantity (quantities.hpp) on obj, hashed as
// "<part>@units" and "<part>@description".
void describe(hid_t obj, const std::string& part, const Quantity& q, ContentDigest& d, const std::string& path) {
  write_string_attr(obj, "units", q.units, path);
  write_string_attr(obj, "description", q.description, path);
  digest_attribute(d, part + "@units", std::string(q.units));
  digest_attribute(d, part + "@description", std::string(q.description));
}

// Why H5Fopen refused a file: what the system said (a lock held by another process, no
// permission), or that it is not an HDF5 file.
std::string unreadable_file_reason() {
  const int err = errno;
  std::string why = "not a readable HDF5 member file";
  if (err == EWOULDBLOCK || err == EAGAIN) why += " (another process holds it locked: HDF5's file lock)";
  else if (err != 0 && err != ENOENT) why += std::string(" (") + std::strerror(err) + ")";
  return why;
}

// HDF5 prints its own error stack to stderr by default (twenty lines for a missing
// folder); we report errors ourselves, in one line naming the path.
struct QuietHdf5 {
  QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
};

}  // namespace

MemberWriter::MemberWriter(std::string final_path) : final_path_(std::move(final_path)) { static QuietHdf5 quiet; }

void MemberWriter::set_attribute(const std::string& name, const std::string& value) { attributes_[name] = value; }
void MemberWriter::set_attribute(const std::string& name, double value) { attributes_[name] = value; }
void MemberWriter::set_attribute(const std::string& name, long value) { attributes_[name] = value; }
void MemberWriter::set_scene(const nlohmann::json& scene) { attributes_["scene"] = scene.dump(); }

void MemberWriter::append(const std::map<std::string, double>& row, const std::vector<double>& beta) {
  if (rows_ == 0) {
    for (const auto& [k, v] : row) {
      quantity(series_quantities(), k);  // every quantity written has its units: throws when not
      columns_.push_back(k);
    }
  } else if (row.size() != columns_.size()) {
    throw std::logic_error("member row " + std::to_string(rows_) + " has " + std::to_string(row.size()) +
                           " columns, the first had " + std::to_string(columns_.size()));
  }
  for (const auto& c : columns_) {
    auto it = row.find(c);
    if (it == row.end()) throw std::logic_error("member row lacks column " + c);
    series_[c].push_back(it->second);
  }
  if (!beta.empty() || !beta_.empty()) {
    if (!beta_.empty() && beta.size() != beta_.front().size())
      throw std::logic_error("member row: beta width changed");
    beta_.push_back(beta);
  }
  ++rows_;
}

void MemberWriter::set_markers(const std::map<std::string, double>& markers) {
  for (const auto& [name, v] : markers) quantity(marker_quantities(), name);
  markers_ = markers;
}

void MemberWriter::add_shape(double kt, const std::vector<double>& xyz, int dim, const std::vector<int>& triangles) {
  shapes_.push_back({kt, xyz, dim});
  if (!triangles.empty()) triangles_ = triangles;
}

std::vector<double> MemberWriter::shape_times() const {
  std::vector<double> kt;
  for (const auto& s : shapes_) kt.push_back(s.kt);
  return kt;
}

void MemberWriter::write(const std::string& path, const std::string& status, bool with_rows) const {
  ContentDigest digest;
  Handle file = create_checked_file(path);
  if (!file.ok()) fail(path, "cannot create the member file");
  write_string_attr(file, "status", status, path);
  digest_attribute(digest, "@status", std::string(status.c_str()));
  for (const auto& [name, value] : attributes_) {
    if (name == "status" || name == kContentHashAttribute) continue;
    if (auto s = std::get_if<std::string>(&value)) {
      write_string_attr(file, name, *s, path);
      digest_attribute(digest, "@" + name, std::string(s->c_str()));  // HDF5 stores the text up to a NUL
    } else if (auto d = std::get_if<double>(&value)) {
      write_scalar_attr(file, name, *d, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, path);
      digest_attribute(digest, "@" + name, *d);
    } else {
      write_scalar_attr(file, name, std::get<long>(value), H5T_NATIVE_LONG, H5T_STD_I64LE, path);
      digest_attribute(digest, "@" + name, static_cast<std::int64_t>(std::get<long>(value)));
    }
  }
  if (with_rows) {
    Handle series(H5Gcreate2(file, "series", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    for (const auto& c : columns_) {
      write_matrix(series, c, series_.at(c).data(), rows_, 0, path);
      digest_doubles(digest, "series/" + c, series_.at(c).data(), rows_, rows_, 0);
    }
    if (!beta_.empty()) {
      std::vector<double> flat;
      for (const auto& r : beta_) flat.insert(flat.end(), r.begin(), r.end());
      write_matrix(series, "beta", flat.data(), beta_.size(), beta_.front().size(), path);
      digest_doubles(digest, "series/beta", flat.data(), flat.size(), beta_.size(), beta_.front().size());
    }
    // Each series says what it is, and kt is the dimension scale of every series' rows, so
    // h5py, xarray and netCDF readers see the time coordinate (HDF5 dimension scales).
    std::vector<std::string> names = columns_;
    if (!beta_.empty()) names.push_back("beta");
    const bool has_kt = std::find(columns_.begin(), columns_.end(), "kt") != columns_.end();
    Handle kt(has_kt ? H5Dopen2(series, "kt", H5P_DEFAULT) : H5I_INVALID_HID, H5Dclose);
    if (has_kt) check(H5DSset_scale(kt, "kt"), path, "cannot make series/kt a dimension scale");
    for (const auto& c : names) {
      Handle set(H5Dopen2(series, c.c_str(), H5P_DEFAULT), H5Dclose);
      describe(set, "series/" + c, quantity(series_quantities(), c), digest, path);
      if (has_kt && c != "kt") check(H5DSattach_scale(set, kt, 0), path, "cannot attach kt to series/" + c);
    }
  }
  if (with_rows) {
    Handle markers(H5Gcreate2(file, "markers", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    for (const auto& [name, v] : markers_) {
      write_scalar_attr(markers, name, v, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, path);
      digest_attribute(digest, "markers@" + name, v);
    }
    // A marker is an attribute, and attributes carry none of their own: its units and
    // description are the attributes of the same name on /markers/units and /markers/description.
    if (!markers_.empty()) {
      Handle units(H5Gcreate2(markers, "units", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
      Handle descriptions(H5Gcreate2(markers, "description", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
      for (const auto& [name, v] : markers_) {
        const Quantity& q = quantity(marker_quantities(), name);
        write_string_attr(units, name, q.units, path);
        write_string_attr(descriptions, name, q.description, path);
        digest_attribute(digest, "markers/units@" + name, std::string(q.units));
        digest_attribute(digest, "markers/description@" + name, std::string(q.description));
      }
    }
  }
  if (!shapes_.empty()) {
    Handle shapes(H5Gcreate2(file, "shapes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    for (std::size_t i = 0; i < shapes_.size(); ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "%04zu", i);
      const auto& s = shapes_[i];
      write_matrix(shapes, name, s.xyz.data(), s.xyz.size() / s.dim, s.dim, path);
      Handle set(H5Dopen2(shapes, name, H5P_DEFAULT), H5Dclose);
      write_scalar_attr(set, "kt", s.kt, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, path);
      describe(set, std::string("shapes/") + name, quantity(shape_quantities(), "positions"), digest, path);
      digest_doubles(digest, std::string("shapes/") + name, s.xyz.data(), s.xyz.size(), s.xyz.size() / s.dim,
                     static_cast<std::uint64_t>(s.dim));
      digest_attribute(digest, std::string("shapes/") + name + "@kt", s.kt);
    }
    if (!triangles_.empty()) {
      hsize_t dims[2] = {triangles_.size() / 3, 3};
      Handle set = create_dataset(shapes, "triangles", H5T_STD_I32LE, 2, dims, DatasetFilters::checksum_compressed);
      if (!set.ok()) fail(path, "cannot create dataset triangles");
      check(H5Dwrite(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, triangles_.data()), path, "triangles");
      digest.add("shapes/triangles", 'n', triangles_.data(), triangles_.size() * sizeof(int));
      describe(set, "shapes/triangles", quantity(shape_quantities(), "triangles"), digest, path);
    }
  }
  write_string_attr(file, kContentHashAttribute, digest.hex(), path);
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), path, "cannot flush");
}

void MemberWriter::write_then_rename(const std::string& status, const std::string& to) const {
  // The file at `to` is always a whole one (solver/common/atomic_write.hpp).
  require_ownership("write " + to);
  replace_atomically(to, [&](const std::string& tmp) { write(tmp, status); },
                     [&] { require_ownership("rename over " + to); });
}

void MemberWriter::checkpoint() {
  if (!in_memory_) write_then_rename("running", partial_path());
}

void MemberWriter::write_shapes_file(const std::string& path) const {
  replace_atomically(path, [&](const std::string& tmp) { write(tmp, "shapes", /*with_rows=*/false); });
}

void MemberWriter::finish(const std::string& status) {
  write_then_rename(status, partial_path());
  require_ownership("rename " + partial_path() + " to " + final_path_);
  std::filesystem::rename(partial_path(), final_path_);
}

void MemberWriter::save_rows(StateArchive& a) const {
  std::string columns;
  for (const auto& c : columns_) columns += c + "\n";
  a.put_text("member.columns", columns);
  a.put_integer("member.rows", static_cast<std::int64_t>(rows_));
  for (const auto& c : columns_) a.put("member.series." + c, series_.at(c));
  std::vector<double> beta;
  for (const auto& r : beta_) beta.insert(beta.end(), r.begin(), r.end());
  a.put("member.beta", std::move(beta));
  a.put_integer("member.beta_rows", static_cast<std::int64_t>(beta_.size()));
  std::vector<double> kt, xyz;
  std::vector<std::int64_t> dims, sizes;
  for (const auto& s : shapes_) {
    kt.push_back(s.kt);
    dims.push_back(s.dim);
    sizes.push_back(static_cast<std::int64_t>(s.xyz.size()));
    xyz.insert(xyz.end(), s.xyz.begin(), s.xyz.end());
  }
  a.put("member.shapes.kt", std::move(kt));
  a.put("member.shapes.dim", std::move(dims));
  a.put("member.shapes.size", std::move(sizes));
  a.put("member.shapes.xyz", std::move(xyz));
  a.put("member.triangles", std::vector<std::int64_t>(triangles_.begin(), triangles_.end()));
}

void MemberWriter::restore_rows(const StateArchive& a) {
  columns_.clear();
  series_.clear();
  const std::string& columns = a.text("member.columns");
  for (std::size_t start = 0, end; (end = columns.find('\n', start)) != std::string::npos; start = end + 1)
    columns_.push_back(columns.substr(start, end - start));
  rows_ = static_cast<std::size_t>(a.integer("member.rows"));
  for (const auto& c : columns_) {
    series_[c] = a.doubles("member.series." + c);
    if (series_[c].size() != rows_) throw std::runtime_error("restart point: series " + c + " has the wrong length");
  }
  beta_.clear();
  const auto& beta = a.doubles("member.beta");
  const auto beta_rows = static_cast<std::size_t>(a.integer("member.beta_rows"));
  if (beta_rows > 0) {
    if (beta.size() % beta_rows != 0) throw std::runtime_error("restart point: beta is not rectangular");
    const std::size_t w = beta.size() / beta_rows;
    for (std::size_t r = 0; r < beta_rows; ++r) beta_.emplace_back(beta.begin() + r * w, beta.begin() + (r + 1) * w);
  }
  shapes_.clear();
  const auto& kt = a.doubles("member.shapes.kt");
  const auto& dims = a.ints("member.shapes.dim");
  const auto& sizes = a.ints("member.shapes.size");
  const auto& xyz = a.doubles("member.shapes.xyz");
  if (dims.size() != kt.size() || sizes.size() != kt.size()) throw std::runtime_error("restart point: shapes do not match");
  std::size_t at = 0;
  for (std::size_t i = 0; i < kt.size(); ++i) {
    const auto n = static_cast<std::size_t>(sizes[i]);
    if (at + n > xyz.size()) throw std::runtime_error("restart point: shapes are truncated");
    shapes_.push_back({kt[i], std::vector<double>(xyz.begin() + at, xyz.begin() + at + n), static_cast<int>(dims[i])});
    at += n;
  }
  const auto& tri = a.ints("member.triangles");
  triangles_.assign(tri.begin(), tri.end());
}

// ---------------------------------------------------------------- reading

namespace {

struct AttrVisit {
  nlohmann::json* out;
  std::string path;
};

herr_t read_attr(hid_t loc, const char* name, const H5A_info_t*, void* data) {
  auto* v = static_cast<AttrVisit*>(data);
  Handle attr(H5Aopen(loc, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attr), H5Tclose);
  H5T_class_t cls = H5Tget_class(type);
  if (cls == H5T_STRING) {
    std::string value;
    if (H5Tis_variable_str(type) > 0) {
      Handle mem(string_type(), H5Tclose);
      char* c = nullptr;
      if (H5Aread(attr, mem, &c) < 0) return -1;
      value = c ? c : "";
      H5free_memory(c);
    } else {
      std::size_t n = H5Tget_size(type);
      std::string buf(n, '\0');
      if (H5Aread(attr, type, buf.data()) < 0) return -1;
      value = buf.c_str();
    }
    (*v->out)[name] = value;
  } else if (cls == H5T_INTEGER) {
    long x = 0;
    if (H5Aread(attr, H5T_NATIVE_LONG, &x) < 0) return -1;
    (*v->out)[name] = x;
  } else if (cls == H5T_FLOAT) {
    double x = 0;
    if (H5Aread(attr, H5T_NATIVE_DOUBLE, &x) < 0) return -1;
    (*v->out)[name] = x;
  }
  return 0;
}

nlohmann::json read_attributes(hid_t obj, const std::string& path) {
  nlohmann::json out = nlohmann::json::object();
  AttrVisit v{&out, path};
  hsize_t idx = 0;
  if (H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, &idx, read_attr, &v) < 0) fail(path, "cannot read attributes");
  return out;
}

std::vector<double> read_doubles(hid_t set, std::vector<hsize_t>& dims, const std::string& path,
                                 const std::string& name) {
  Handle space(H5Dget_space(set), H5Sclose);
  int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail(path, "dataset " + name + " has no readable extent");
  dims.assign(rank, 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hsize_t n = 1;
  for (auto d : dims) n *= d;
  std::vector<double> out(n);
  read_whole_dataset(set, H5T_NATIVE_DOUBLE, out.data(), path, name);
  return out;
}

// The units and description a series carries, as the writer hashed them (none in files written
// before they existed; the dimension-scale attributes are HDF5's bookkeeping and not hashed).
void digest_description(ContentDigest& d, hid_t set, const std::string& part, const std::string& path) {
  const auto a = read_attributes(set, path);
  for (const char* key : {"units", "description"})
    if (a.contains(key)) digest_attribute(d, part + "@" + key, a[key]);
}

Handle open_dataset(hid_t group, const std::string& name, const std::string& path) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail(path, "cannot open dataset " + name + ": the file is damaged");
  return set;
}

struct NameList {
  std::vector<std::string> names;
};
herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<NameList*>(data)->names.push_back(name);
  return 0;
}
std::vector<std::string> children(hid_t group) {
  NameList list;
  hsize_t idx = 0;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &idx, collect_name, &list);
  return list.names;
}

bool g_accept_legacy = false;

}  // namespace

void accept_files_without_content_hash(bool accept) { g_accept_legacy = accept; }

MemberData read_member(const std::string& path) {
  static QuietHdf5 quiet;
  if (!std::filesystem::exists(path)) fail(path, "no such member file");
  errno = 0;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.ok()) fail(path, unreadable_file_reason());
  MemberData m;
  m.path = path;
  m.attributes = read_attributes(file, path);
  if (!m.attributes.contains("status")) fail(path, "no status attribute: not a member file");
  m.status = m.attributes["status"].get<std::string>();
  ContentDigest digest;
  for (auto it = m.attributes.begin(); it != m.attributes.end(); ++it)
    if (it.key() != kContentHashAttribute) digest_attribute(digest, "@" + it.key(), it.value());
  if (m.attributes.contains("scene") && m.attributes["scene"].is_string()) {
    try {
      m.attributes["scene"] = nlohmann::json::parse(m.attributes["scene"].get<std::string>());
    } catch (const std::exception&) {
      fail(path, "attribute scene is not JSON");
    }
  }
  if (H5Lexists(file, "series", H5P_DEFAULT) > 0) {
    Handle series(H5Gopen2(file, "series", H5P_DEFAULT), H5Gclose);
    for (const auto& name : children(series)) {
      Handle set = open_dataset(series, name, path);
      std::vector<hsize_t> dims;
      auto data = read_doubles(set, dims, path, "series/" + name);
      digest_doubles(digest, "series/" + name, data.data(), data.size(), dims.empty() ? 0 : dims[0],
                     dims.size() == 2 ? dims[1] : 0);
      digest_description(digest, set, "series/" + name, path);
      if (name == "beta" && dims.size() == 2) {
        for (hsize_t r = 0; r < dims[0]; ++r)
          m.beta.emplace_back(data.begin() + r * dims[1], data.begin() + (r + 1) * dims[1]);
      } else {
        m.series[name] = std::move(data);
      }
    }
  }
  if (H5Lexists(file, "markers", H5P_DEFAULT) > 0) {
    Handle markers(H5Gopen2(file, "markers", H5P_DEFAULT), H5Gclose);
    auto a = read_attributes(markers, path);
    for (auto it = a.begin(); it != a.end(); ++it) {
      digest_attribute(digest, "markers@" + it.key(), it.value());
      m.markers[it.key()] = it.value().is_number() ? it.value().get<double>() : std::nan("");
    }
    for (const char* about : {"units", "description"}) {
      if (H5Lexists(markers, about, H5P_DEFAULT) <= 0) continue;  // files written before they existed
      Handle group(H5Gopen2(markers, about, H5P_DEFAULT), H5Gclose);
      auto texts = read_attributes(group, path);
      for (auto it = texts.begin(); it != texts.end(); ++it)
        digest_attribute(digest, std::string("markers/") + about + "@" + it.key(), it.value());
    }
  }
  if (H5Lexists(file, "shapes", H5P_DEFAULT) > 0) {
    Handle shapes(H5Gopen2(file, "shapes", H5P_DEFAULT), H5Gclose);
    for (const auto& name : children(shapes)) {
      Handle set = open_dataset(shapes, name, path);
      if (name == "triangles") {
        Handle space(H5Dget_space(set), H5Sclose);
        hsize_t dims[2] = {0, 0};
        H5Sget_simple_extent_dims(space, dims, nullptr);
        m.triangles.resize(dims[0] * dims[1]);
        read_whole_dataset(set, H5T_NATIVE_INT, m.triangles.data(), path, "shapes/triangles");
        digest.add("shapes/triangles", 'n', m.triangles.data(), m.triangles.size() * sizeof(int));
        digest_description(digest, set, "shapes/triangles", path);
        continue;
      }
      std::vector<hsize_t> dims;
      MemberData::Shape s;
      s.xyz = read_doubles(set, dims, path, "shapes/" + name);
      s.dim = dims.size() == 2 ? static_cast<int>(dims[1]) : 1;
      auto a = read_attributes(set, path);
      s.kt = a.contains("kt") ? a["kt"].get<double>() : std::nan("");
      digest_doubles(digest, "shapes/" + name, s.xyz.data(), s.xyz.size(), dims.empty() ? 0 : dims[0],
                     dims.size() == 2 ? dims[1] : 0);
      if (a.contains("kt")) digest_attribute(digest, "shapes/" + name + "@kt", a["kt"]);
      digest_description(digest, set, "shapes/" + name, path);
      m.shapes.push_back(std::move(s));
    }
  }
  // Files written before the content hash existed have none: read only when asked for.
  if (!m.attributes.contains(kContentHashAttribute) && !g_accept_legacy)
    fail(path, "no content hash, so its content cannot be checked (the hash was removed, or the file predates it); "
               "read it anyway only with --legacy-member-files");
  if (m.attributes.contains(kContentHashAttribute)) {
    const auto& recorded = m.attributes[kContentHashAttribute];
    if (!recorded.is_string() || recorded.get<std::string>() != digest.hex())
      fail(path, std::string("content hash does not match (recorded ") +
                     (recorded.is_string() ? recorded.get<std::string>() : "not a text") + ", the file's content " +
                     digest.hex() + "): the file was changed or damaged after it was written");
  }
  return m;
}

std::string missing_series(const MemberData& member) {
  const auto kt = member.series.find("kt");
  if (kt == member.series.end() || kt->second.empty()) return member.path + ": no series kt";
  if (!member.series.count("D_xy")) return member.path + ": no series D_xy";
  for (const auto& [name, values] : member.series)
    if (values.size() != kt->second.size())
      return member.path + ": series " + name + " has " + std::to_string(values.size()) + " rows, kt has " +
             std::to_string(kt->second.size());
  if (!member.beta.empty() && member.beta.size() != kt->second.size())
    return member.path + ": series beta has " + std::to_string(member.beta.size()) + " rows, kt has " +
           std::to_string(kt->second.size());
  return "";
}

MemberStatus read_member_status(const std::string& path) {
  static QuietHdf5 quiet;
  errno = 0;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.ok()) fail(path, unreadable_file_reason());
  auto a = read_attributes(file, path);
  MemberStatus s;
  if (a.contains("status") && a["status"].is_string()) s.status = a["status"];
  if (a.contains("member_id") && a["member_id"].is_string()) s.member_id = a["member_id"];
  if (a.contains("wall_seconds") && a["wall_seconds"].is_number()) s.wall_seconds = a["wall_seconds"].get<double>();
  if (a.contains("steps") && a["steps"].is_number()) s.steps = a["steps"].get<double>();
  if (a.contains("threads") && a["threads"].is_number()) s.threads = a["threads"].get<long>();
  if (a.contains("code_version") && a["code_version"].is_string()) s.code_version = a["code_version"];
  if (a.contains("physics_version") && a["physics_version"].is_string()) s.physics_version = a["physics_version"];
  if (a.contains("tau") && a["tau"].is_number()) s.tau = a["tau"].get<double>();
  if (a.contains(kContentHashAttribute) && a[kContentHashAttribute].is_string()) s.content_hash = a[kContentHashAttribute];
  if (a.contains("scene") && a["scene"].is_string())
    s.scene = nlohmann::json::parse(a["scene"].get<std::string>(), nullptr, /*allow_exceptions=*/false);
  if (s.scene.is_discarded()) s.scene = nullptr;
  if (H5Lexists(file, "markers", H5P_DEFAULT) > 0) {
    Handle markers(H5Gopen2(file, "markers", H5P_DEFAULT), H5Gclose);
    const auto m = read_attributes(markers, path);
    if (m.contains("t_stop") && m["t_stop"].is_number()) s.t_stop = m["t_stop"].get<double>();
    if (m.contains("t_end") && m["t_end"].is_number()) s.t_end = m["t_end"].get<double>();
  }
  return s;
}

}  // namespace capsule::io
