#pragma once
// A rigid spherical shell of immersed-boundary markers in the lattice shear flow: the exact
// Stokes problems that measure the smeared membrane's hydrodynamic radius (Sec. 2.3's coupling,
// no membrane mechanics).
//
// The shell is the capsule's own icosphere at marker radius r_m, centred in the capsule's box
// (walls at y = 0 and y = H moving at -+ k H / 2, periodic in x and z). Each marker is tied
// to an anchor that turns rigidly about z through the centre at Omega = spin k:
//   F_c = kappa (A_c(t) - X_c),   X_c += U(X_c) each step   ((19)-(21), as the capsule's markers);
// kappa is an integral gain in velocity, so once steady every marker moves exactly with its
// anchor (the interpolated velocity equals the rigid motion) and the force does not depend on
// kappa. The force the shell exerts on the fluid gives, at the centre c,
//   torque    T_z = sum_c ((X_c - c) x F_c)_z          exact, unbounded: 8 pi mu a^3 (Omega + k/2)
//   stresslet S_xy = -sum_c (x_c F_c,y + y_c F_c,x) / 2   exact, unbounded: (10/3) pi mu a^3 k
// (Batchelor 1970; a sphere in u = k y x, vorticity -k, strain rate k/2). spin = 0 is the sphere
// held fixed (both measures), spin = -1/2 the freely rotating one (torque zero).
// Their ratios to the unbounded values are (a_h / a)^3 times the box's own correction, so the
// hydrodynamic radius a_h follows once the box correction is known (a larger box, same a).
#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "solver/ib/delta.hpp"
#include "solver/lbm/precision.hpp"

namespace capsule::rigid_sphere {

struct RigidShellOptions {
  double a = 5;                            // the sphere's radius: the exact values use it (lattice units)
  double marker_radius = 0;                // radius of the markers (0: a)
  int level = 3;                           // icosphere level (3: 642, 4: 2562 markers)
  std::array<double, 3> domain{10, 10, 8};  // box in units of a, as the 3D capsule's
  double Re = 0.05;                        // k a^2 / nu
  double tau = 1.5;                        // relaxation time (the 3D rule for V = 1)
  double spin = 0;                         // anchor rotation rate about z, in units of k
  double kt = 4;                           // run until this kt
  double gain = 0.01;                      // kappa, force per unit marker lag (lattice units)
  ib::Delta delta = ib::Delta::peskin4;
  lbm::Precision precision = lbm::Precision::double_precision;
  double every = 0.25;                     // series interval in kt
  // > 0: the fluid refined by a factor 2 in a block around the shell, this many coarse cells
  // wider on each side (solver/lbm/refinement/); a and the lattice are then the fine ones.
  int refine_margin = 0;
};

struct RigidShellRow {
  double kt = 0;
  double torque = 0;     // T_z / (4 pi mu a^3 k)
  double stresslet = 0;  // S_xy / ((10/3) pi mu a^3 k)
  double leakage = 0;    // max |u - Omega x r| / (k a) at the nodes deeper than 2.5 inside the markers
  double lag = 0;        // max |A_c - X_c| / a
  double slip = 0;       // max |U(X_c) - Omega x r_c| / (k a): the markers' velocity against the rigid motion
  double slip_rms = 0;   // its root mean square over the markers
};

struct RigidShellResult {
  std::vector<RigidShellRow> series;
  double torque_exact = 0;     // 1 + 2 spin: the unbounded torque in units of 4 pi mu a^3 k
  int grid[3] = {0, 0, 0};
  long steps = 0;
  double seconds = 0;
};

// Throws std::invalid_argument naming the option and its allowed range.
void validate(const RigidShellOptions& o);

// Runs the shell from the undisturbed Couette flow; a row every options.every kt and at the end.
RigidShellResult run_rigid_shell(const RigidShellOptions& o);

// The result as CSV: header and one row per series entry.
void write_series_csv(const RigidShellResult& r, std::ostream& out);

}  // namespace capsule::rigid_sphere
