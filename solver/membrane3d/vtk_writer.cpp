#include "solver/membrane3d/vtk_writer.hpp"

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

void write_array(std::ostream& f, const VtkField& field, std::size_t count, const std::string& path) {
  if (field.components < 1 || field.values.size() != count * static_cast<std::size_t>(field.components))
    throw std::invalid_argument("vtp " + path + ": field " + field.name + " has " + std::to_string(field.values.size()) +
                                " values, expected " + std::to_string(count * field.components));
  f << "        <DataArray type=\"Float64\" Name=\"" << xml_attribute(field.name) << "\" NumberOfComponents=\"" << field.components
    << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < field.values.size(); ++i) f << (i % 9 == 0 ? "          " : " ") << field.values[i]
                                                          << (i % 9 == 8 || i + 1 == field.values.size() ? "\n" : "");
  f << "        </DataArray>\n";
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path);
  }
}

}  // namespace

void write_vtp(const std::string& path, const Mesh& m, const std::vector<VtkField>& point_fields,
               const std::vector<VtkField>& cell_fields) {
  const std::string tmp = path + ".tmp";
  try {
    std::ofstream f(tmp);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f.precision(10);
    f << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << m.vertex_count() << "\" NumberOfPolys=\"" << m.triangle_count() << "\">\n"
      << "      <Points>\n";
    VtkField xyz{"Points", 3, {}};
    for (const auto& p : m.x) xyz.values.insert(xyz.values.end(), {p.x(), p.y(), p.z()});
    write_array(f, xyz, m.x.size(), path);
    f << "      </Points>\n      <Polys>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : m.triangles) f << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    f << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (int t = 0; t < m.triangle_count(); ++t) f << "          " << 3 * (t + 1) << '\n';
    f << "        </DataArray>\n      </Polys>\n      <PointData>\n";
    for (const auto& field : point_fields) write_array(f, field, m.x.size(), path);
    f << "      </PointData>\n      <CellData>\n";
    for (const auto& field : cell_fields) write_array(f, field, m.triangles.size(), path);
    f << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
    if (!f) throw std::runtime_error("write failed: " + tmp);
  } catch (...) {
    std::remove(tmp.c_str());  // nothing half-written stays behind
    throw;
  }
  rename_into_place(tmp, path);
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& snapshots) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f.precision(10);
    f << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
    for (const auto& [kt, file] : snapshots)
      f << "    <DataSet timestep=\"" << kt << "\" group=\"\" part=\"0\" file=\"" << xml_attribute(file) << "\"/>\n";
    f << "  </Collection>\n</VTKFile>\n";
    if (!f) {
      std::remove(tmp.c_str());
      throw std::runtime_error("write failed: " + tmp);
    }
  }
  rename_into_place(tmp, path);
}

}  // namespace capsule::membrane3d
