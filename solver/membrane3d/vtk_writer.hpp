#pragma once
// Legacy-VTK (ASCII) polydata snapshots of the membrane for ParaView.
#include <map>
#include <string>
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// Writes points, triangles and optional per-vertex scalar fields. Throws on I/O failure.
void write_vtk_polydata(const std::string& path, const Mesh& mesh, const std::string& title,
                        const std::map<std::string, std::vector<double>>& point_scalars = {});

}  // namespace capsule::membrane3d
