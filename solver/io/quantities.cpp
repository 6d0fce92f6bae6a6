#include "solver/io/quantities.hpp"

#include <stdexcept>

namespace capsule::io {

const std::vector<Quantity>& series_quantities() {
  static const std::vector<Quantity> table = {
      {"kt", "1/k", "time since the shear started, in units of 1/k (k the shear rate)"},
      {"D_xy", "1", "Taylor deformation (L - W)/(L + W) (37): chords through the centroid in 2D, the inertia-equivalent ellipsoid (38) in 3D"},
      {"D_extent", "1", "(r_max - r_min)/(r_max + r_min) of the section z = z_centroid (the Ramanujan-Pozrikidis measure)"},
      {"theta", "rad", "inclination of the major axis to the flow direction, in (-pi/2, pi/2]"},
      {"L", "a", "major chord through the centroid (2D) or major axis of the ellipse (3D)"},
      {"W", "a", "minor chord through the centroid (2D) or minor axis of the ellipse (3D)"},
      {"area_drift", "1", "A / A(0) - 1 of the membrane polygon"},
      {"volume_drift", "1", "V / V(0) - 1 of the volume the membrane encloses"},
      {"surface_drift", "1", "S / S(0) - 1 of the membrane's surface area"},
      {"tension", "E_s", "mean in-plane tension tau (28), length-weighted"},
      {"bending_moment", "E_s a", "mean |m| = |E_B (kappa - kappa0)| (32), length-weighted"},
      {"stretch_min", "1", "smallest segment stretch lambda (29)"},
      {"stretch_max", "1", "largest segment stretch lambda (29)"},
      {"triangle_quality_min", "1", "smallest triangle quality 4 sqrt(3) A / sum l^2 (1 for an equilateral triangle)"},
      {"inverted_triangles", "1", "number of triangles whose normal turned inward"},
      {"elastic_energy", "E_s a^2", "elastic energy of the membrane"},
      {"centroid_x", "a", "x of the membrane's centroid from the domain centre"},
      {"centroid_y", "a", "y of the membrane's centroid from the domain centre"},
      {"centroid_z", "a", "z of the membrane's centroid from the domain centre"},
      {"max_speed", "lattice", "largest fluid speed on the lattice, in lattice units dx/dt"},
      {"shear_on", "1", "1 under shear, 0 after the shear stopped"},
      {"shear_factor", "1", "wall speed over k H/2 (1 under steady shear)"},
      {"force_on", "1", "stretch protocol: 1 while the beads pull, 0 after the release"},
      {"D_axial", "r_m", "stretch protocol: the cell's largest extent along the pull (x), in units of the membrane's radius r_m = a - marker_inset"},
      {"D_transverse", "r_m", "stretch protocol: the largest distance between two membrane points projected onto the y-z plane (the width across the pull), in units of r_m"},
      {"D_axial_um", "um", "stretch protocol, physical cell: D_axial in micrometres (r_m is the cell's radius_um)"},
      {"D_transverse_um", "um", "stretch protocol, physical cell: D_transverse in micrometres"},
      {"gamma_min", "k", "smallest surface shear rate (101) over the vertices"},
      {"gamma_max", "k", "largest surface shear rate (101) over the vertices"},
      {"beta", "rad", "phase angles of the tracked membrane points, one column each ((89) in 2D, wrapped into (-pi, pi]; (91)-(92) in 3D, continuous modulo pi); which points: root attribute beta_tracked"},
  };
  return table;
}

const std::vector<Quantity>& marker_quantities() {
  static const std::vector<Quantity> table = {
      {"t_max", "1/k", "time of the largest D_xy under shear (NaN = not reached)"},
      {"D_max", "1", "largest D_xy under shear"},
      {"t_stop", "1/k", "time the shear stopped"},
      {"D_stop", "1", "D_xy when the shear stopped"},
      {"t_min", "1/k", "time of the smallest D_xy after the stop"},
      {"D_min", "1", "smallest D_xy after the stop"},
      {"t_end", "1/k", "time the recovery ended"},
      {"D_inf", "1", "D_xy when the recovery ended (the recovered deformation)"},
  };
  return table;
}

const std::vector<Quantity>& shape_quantities() {
  static const std::vector<Quantity> table = {
      {"positions", "lattice", "membrane node positions x, y (and z), one row per node, in lattice units dx from the lattice's origin (the domain centre is at half the grid nx, ny, nz); attribute kt: the time"},
      {"triangles", "1", "the three node indices (from 0) of each triangle of the 3D mesh"},
  };
  return table;
}

const Quantity& quantity(const std::vector<Quantity>& table, const std::string& name) {
  for (const auto& q : table)
    if (name == q.name) return q;
  throw std::logic_error("quantity " + name + " has no row in solver/io/quantities.cpp (units and description)");
}

}  // namespace capsule::io
