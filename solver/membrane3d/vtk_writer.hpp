#pragma once
// Snapshots of the membrane for ParaView: VTK XML PolyData files (.vtp) with fields on the
// membrane, and the collection (.pvd) that makes them one time series.
#include <string>
#include <utility>
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// A field on the membrane for a VTK XML file: per vertex (point data) or per triangle (cell
// data), with 1 or 3 components.
struct VtkField {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components x count, interleaved
};

// Where the points are measured from and in what unit: a point x is written as
// (x - origin) / length (the solver writes units of a from the domain centre).
struct VtkFrame {
  Vec3 origin = Vec3::Zero();
  double length = 1.0;
};

// Writes one snapshot as VTK XML PolyData (.vtp): points, triangles, the point fields and the
// cell fields, each array binary and zlib-compressed in the appended section (as ParaView's own
// writer makes them). Written under a temporary name and renamed. Throws on I/O failure or a field of the wrong size.
void write_vtp(const std::string& path, const Mesh& mesh, const std::vector<VtkField>& point_fields,
               const std::vector<VtkField>& cell_fields, const VtkFrame& frame = {});

// Writes a ParaView collection (.pvd): one DataSet per (time, file), the file named relative to
// the collection's folder, so ParaView opens the snapshots as one time series.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& snapshots);

}  // namespace capsule::membrane3d
