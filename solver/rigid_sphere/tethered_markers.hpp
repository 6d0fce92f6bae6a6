#pragma once
// The step loop the rigid shell (3D) and the rigid circle (2D) share: markers tied to anchors
// that turn rigidly about z through the centre of the capsule's channel at Omega, in the lattice
// shear flow between walls moving at -+ k H / 2 (periodic in x, and in z in 3D):
//   F_c = kappa (A_c(t) - X_c),   X_c += U(X_c) each step   ((19)-(21), as the capsule's markers),
// with the torque T_z = sum_c ((X_c - c) x F_c)_z and the stresslet S_xy = -sum_c (x_c F_c,y +
// y_c F_c,x) / 2 of the force on the fluid, in the units the caller gives (rigid_shell.hpp,
// rigid_circle.hpp: the exact values and their derivations).
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/ib/delta.hpp"
#include "solver/lbm/precision.hpp"

#include "solver/rigid_sphere/rigid_shell.hpp"

namespace capsule::rigid_sphere {

struct TetheredMarkers {
  int dim = 3;                      // 2: D2Q9, the markers' z ignored; 3: D3Q19
  std::array<int, 3> grid{0, 0, 1}; // lattice nodes (nz = 1 in 2D)
  double nu = 0;                    // the fluid's kinematic viscosity (lattice units)
  double k = 0;                     // the walls' shear rate
  double Omega = 0;                 // the anchors' rotation rate about z
  std::vector<double> anchors;      // dim coordinates per marker at t = 0, absolute; the markers start there
  double gain = 0.01;               // kappa, force per unit marker lag
  double kt = 4;                    // run until this kt
  double every = 0.25;              // series interval in kt
  double torque_unit = 1;           // the row's torque is T_z / torque_unit
  double stresslet_unit = 1;        // and its stresslet S_xy / stresslet_unit
  double length = 1;                // a: leakage and slip in units of k a, lag in units of a
  double inside = 0;                // leakage is read at the nodes closer than this to the centre
  ib::Delta delta = ib::Delta::peskin4;
  lbm::Precision precision = lbm::Precision::double_precision;
  std::string name = "rigid shell"; // for the error when the fluid blows up
  // > 0: the fluid refined by a factor 2 in a block around the anchors, this many coarse cells
  // wider on each side (solver/lbm/refinement/); the setup above is the fine lattice's (grid,
  // anchors, nu, k per fine step), the markers step on the fine lattice; leakage is not read.
  int refine_margin = 0;
};

// The options both rigid bodies share (RigidShellOptions, RigidCircleOptions), checked with the
// same ranges; throws std::invalid_argument naming the body, the option and its allowed range.
template <class Options>
void validate_tethered_options(const Options& o, const std::string& body) {
  const auto require = [&](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(body + ": " + what);
  };
  const double r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  require(r_m >= 0.5 * o.a && r_m <= 1.5 * o.a, "marker_radius must be in [a/2, 3a/2], got " + std::to_string(o.marker_radius));
  require(o.Re > 0 && o.Re <= 1, "Re must be in (0, 1], got " + std::to_string(o.Re));
  require(o.tau > 0.5 && o.tau <= 5, "tau must be in (0.5, 5], got " + std::to_string(o.tau));
  require(std::abs(o.spin) <= 2, "spin must be in [-2, 2] (units of k), got " + std::to_string(o.spin));
  require(o.kt > 0 && o.kt <= 100, "kt must be in (0, 100], got " + std::to_string(o.kt));
  require(o.gain > 0 && o.gain <= 1, "gain must be in (0, 1], got " + std::to_string(o.gain));
  require(o.every > 0 && o.every <= o.kt, "every must be in (0, kt], got " + std::to_string(o.every));
}

// The setup both bodies derive alike from their options: the fluid from tau and Re ((8), rho = 1,
// so mu = nu; Re = k a^2 / nu), the anchors' spin, the run's length, and the measures' scales
// (leakage read deeper than the delta's reach, 2, plus half a node inside the markers). The
// grid, the anchors and the exact units are each body's own.
template <class Options>
TetheredMarkers tethered_markers_from(const Options& o, int dim, const std::string& body) {
  TetheredMarkers s;
  s.dim = dim;
  s.nu = (o.tau - 0.5) / 3.0;
  s.k = o.Re * s.nu / (o.a * o.a);
  s.Omega = o.spin * s.k;
  s.length = o.a;
  s.inside = (o.marker_radius > 0 ? o.marker_radius : o.a) - 2.5;
  s.gain = o.gain;
  s.kt = o.kt;
  s.every = o.every;
  s.delta = o.delta;
  s.precision = o.precision;
  s.name = body;
  return s;
}

// Runs from the undisturbed Couette flow; a row every setup.every kt and at the end. Fills the
// result's series, steps and seconds (grid and torque_exact are the caller's).
void run_tethered_markers(const TetheredMarkers& setup, RigidShellResult& result);

}  // namespace capsule::rigid_sphere
