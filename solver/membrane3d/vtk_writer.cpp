#include "solver/membrane3d/vtk_writer.hpp"

#include "solver/common/atomic_write.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <stdexcept>

namespace capsule::membrane3d {

namespace {

std::string xml_attribute(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// The appended section of a VTK XML file: each array compressed with zlib in blocks of 32 KiB,
// preceded by VTK's compression header (UInt64: number of blocks, block size, size of the last
// block when it is partial, else 0, then each block's compressed size).
class AppendedData {
 public:
  // Adds an array's bytes; returns its offset in the section (the DataArray's "offset").
  std::uint64_t add(const void* data, std::size_t size) {
    const std::uint64_t offset = bytes_.size();
    constexpr std::size_t block = 32768;
    const std::size_t blocks = (size + block - 1) / block;
    std::vector<std::uint64_t> header = {blocks, block, size % block};
    std::string compressed;
    const auto* p = static_cast<const Bytef*>(data);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t n = std::min(block, size - b * block);
      uLongf out_size = compressBound(n);
      std::string out(out_size, '\0');
      if (compress2(reinterpret_cast<Bytef*>(out.data()), &out_size, p + b * block, n, Z_DEFAULT_COMPRESSION) != Z_OK)
        throw std::runtime_error("zlib could not compress a snapshot array");
      header.push_back(out_size);
      compressed.append(out.data(), out_size);
    }
    bytes_.append(reinterpret_cast<const char*>(header.data()), header.size() * sizeof(std::uint64_t));
    bytes_ += compressed;
    return offset;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

void write_array(std::ostream& f, AppendedData& data, const VtkField& field, std::size_t count, const std::string& path) {
  if (field.components < 1 || field.values.size() != count * static_cast<std::size_t>(field.components))
    throw std::invalid_argument("vtp " + path + ": field " + field.name + " has " + std::to_string(field.values.size()) +
                                " values, expected " + std::to_string(count * field.components));
  const std::uint64_t offset = data.add(field.values.data(), field.values.size() * sizeof(double));
  f << "        <DataArray type=\"Float64\" Name=\"" << xml_attribute(field.name) << "\" NumberOfComponents=\""
    << field.components << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
}

void write_indices(std::ostream& f, AppendedData& data, const char* name, const std::vector<std::int64_t>& values) {
  const std::uint64_t offset = data.add(values.data(), values.size() * sizeof(std::int64_t));
  f << "        <DataArray type=\"Int64\" Name=\"" << name << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
}

}  // namespace

void write_vtp(const std::string& path, const Mesh& m, const std::vector<VtkField>& point_fields,
               const std::vector<VtkField>& cell_fields, const VtkFrame& frame) {
  static_assert(std::endian::native == std::endian::little, "the snapshot writer declares LittleEndian");
  replace_atomically(path, [&](const std::string& tmp) {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    AppendedData data;
    f << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\""
      << " compressor=\"vtkZLibDataCompressor\">\n  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << m.vertex_count() << "\" NumberOfPolys=\"" << m.triangle_count() << "\">\n"
      << "      <Points>\n";
    VtkField xyz{"Points", 3, {}};
    for (const auto& p : m.x) {
      const Vec3 q = (p - frame.origin) / frame.length;
      xyz.values.insert(xyz.values.end(), {q.x(), q.y(), q.z()});
    }
    write_array(f, data, xyz, m.x.size(), path);
    f << "      </Points>\n      <Polys>\n";
    std::vector<std::int64_t> connectivity, offsets;
    for (const auto& t : m.triangles) connectivity.insert(connectivity.end(), {t[0], t[1], t[2]});
    for (int t = 0; t < m.triangle_count(); ++t) offsets.push_back(3 * (t + 1));
    write_indices(f, data, "connectivity", connectivity);
    write_indices(f, data, "offsets", offsets);
    f << "      </Polys>\n      <PointData>\n";
    for (const auto& field : point_fields) write_array(f, data, field, m.x.size(), path);
    f << "      </PointData>\n      <CellData>\n";
    for (const auto& field : cell_fields) write_array(f, data, field, m.triangles.size(), path);
    f << "      </CellData>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
    f.write(data.bytes().data(), static_cast<std::streamsize>(data.bytes().size()));
    f << "\n  </AppendedData>\n</VTKFile>\n";
    if (!f) throw std::runtime_error("write failed: " + tmp);
  });
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& snapshots) {
  replace_atomically(path, [&](const std::string& tmp) {
    std::ofstream f(tmp);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f.precision(10);
    f << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
    for (const auto& [kt, file] : snapshots)
      f << "    <DataSet timestep=\"" << kt << "\" group=\"\" part=\"0\" file=\"" << xml_attribute(file) << "\"/>\n";
    f << "  </Collection>\n</VTKFile>\n";
    if (!f) throw std::runtime_error("write failed: " + tmp);
  });
}

}  // namespace capsule::membrane3d
