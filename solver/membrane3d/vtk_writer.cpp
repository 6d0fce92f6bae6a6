#include "solver/membrane3d/vtk_writer.hpp"

#include <fstream>
#include <stdexcept>

namespace capsule::membrane3d {

void write_vtk_polydata(const std::string& path, const Mesh& m, const std::string& title,
                        const std::map<std::string, std::vector<double>>& scalars) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  f << "# vtk DataFile Version 3.0\n" << title.substr(0, 255) << "\nASCII\nDATASET POLYDATA\n";
  f << "POINTS " << m.vertex_count() << " double\n";
  for (const auto& p : m.x) f << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  f << "POLYGONS " << m.triangle_count() << ' ' << 4 * m.triangle_count() << '\n';
  for (const auto& t : m.triangles) f << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  if (!scalars.empty()) f << "POINT_DATA " << m.vertex_count() << '\n';
  for (const auto& [name, values] : scalars) {
    if (static_cast<int>(values.size()) != m.vertex_count()) throw std::invalid_argument("vtk: field size " + name);
    f << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
    for (double v : values) f << v << '\n';
  }
  if (!f) throw std::runtime_error("write failed: " + path);
}

}  // namespace capsule::membrane3d
