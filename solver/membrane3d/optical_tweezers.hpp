#pragma once
// The optical-tweezers load (Mills et al. 2004; simulated by Dao et al. 2003 and Fedosov et al.
// 2010): two opposite patches of the membrane, where the beads are glued, pulled apart along x by
// a total force F each, and the diameters the experiment reads.
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// The vertices under each bead and each one's share of the bead's force. A patch is chosen on the
// start shape (the beads stay glued to the same material points): the vertices nearest the pole,
// the point where the x axis through the centroid leaves the membrane on that side. Each vertex
// carries the share A_i / sum A of the force, A_i its Voronoi area (83) on the start shape: a
// uniform traction over the contact area, whatever the local mesh spacing (a biconcave mesh's
// vertices are far from evenly spread; Fedosov et al. give each vertex an equal share on a
// near-uniform mesh, which this is where the mesh is uniform).
struct PulledPatches {
  std::vector<int> plus, minus;                 // vertices pulled along +x and -x
  std::vector<double> plus_share, minus_share;  // their shares of F (each list sums to 1)
  double plus_area = 0, minus_area = 0;         // the patches' areas on the start shape
};

// The round(fraction x vertices) vertices nearest each pole (at least one), together with any
// vertex as near as the last of them (so that a symmetric mesh gives symmetric patches).
PulledPatches patches_by_fraction(const Mesh& start, double fraction);
// The vertices within contact_diameter / 2 of each pole (distance in space), or the nearest
// vertex and its ties when none is.
PulledPatches patches_by_contact_diameter(const Mesh& start, double contact_diameter);

// Adds +F share_i e_x to the plus patch's vertices and -F share_i e_x to the minus patch's.
void add_pulling_forces(const PulledPatches& patches, double F, std::vector<Vec3>& force);

// The diameters Mills et al. read: axial, the largest extent along x; transverse, the largest
// distance between two vertices projected onto the y-z plane (the cell's width across the pull).
struct StretchDiameters {
  double axial = 0, transverse = 0;
};
StretchDiameters stretch_diameters(const Mesh& mesh);

}  // namespace capsule::membrane3d
