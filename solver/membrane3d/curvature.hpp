#pragma once
// Mean and Gaussian curvature and normals at every vertex by the local quadratic fit of
// Garimella and Schwartz, (73)-(80).
//
// Sign convention (fixed once): the normal points OUTWARD and the mean curvature
// kappa = (kappa_1 + kappa_2)/2 is POSITIVE on a sphere (kappa = 1/R, kappa_g = 1/R^2).
// The fitted height z = a x^2 + b xy + c y^2 + d x + e y is measured along the outward
// normal, so a sphere curves to negative z; (79) as printed (and the "bdc" misprint, solver/membrane3d/README.md
// "Conventions") gives the mean curvature with the opposite sign, hence
//   kappa = -(a (1 + e^2) + c (1 + d^2) - b d e) / (1 + d^2 + e^2)^(3/2).
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

struct Curvatures {
  std::vector<double> mean;      // kappa (79), corrected
  std::vector<double> gaussian;  // kappa_g (78)
  std::vector<Vec3> normal;      // improved outward unit normal (80)
  std::vector<Vec3> triangle_normal;  // outward unit normal of each triangle (the fit's start, averaged)
};

// One fit per vertex over its one-ring (5 neighbours: exact solve; 6 or more: least
// squares; both through the 5x5 normal equations of the scaled system, Eigen LDL^T).
// Threads only from level 5 on (more than 8192 vertices): below, the loop takes about a
// millisecond and an OpenMP fork on shared cores costs more than it saves. The local frame (73)-(75) uses the averaged
// triangle normal; `passes` > 1 repeats the fit in the frame of the improved normal (80).
Curvatures fit_curvatures(const Mesh& mesh, int passes = 1);
// The same into `out`, reusing its storage (a member's step allocates nothing).
void fit_curvatures(const Mesh& mesh, Curvatures& out, int passes = 1);

}  // namespace capsule::membrane3d
