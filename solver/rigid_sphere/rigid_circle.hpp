#pragma once
// A rigid circle of immersed-boundary markers in the 2D lattice shear flow: the exact Stokes
// problems that measure the 2D smeared membrane's hydrodynamic radius (the 2D twin of
// rigid_shell.hpp; no membrane mechanics).
//
// The circle's markers (equally spaced at radius r, as the 2D capsule's nodes) sit centred in
// the capsule's channel (walls at y = 0 and y = H moving at -+ k H / 2, periodic in x). Each
// marker is tied to an anchor that turns rigidly about the centre at Omega = spin k:
//   F_c = kappa (A_c(t) - X_c),   X_c += U(X_c) each step   ((19)-(21), as the capsule's nodes);
// once steady every marker moves with its anchor and the force does not depend on kappa. Per
// unit length, for a circular cylinder of radius a in u = k y x (vorticity -k, strain rate k/2):
//   torque    T_z = sum_c ((X_c - c) x F_c)_z          exact, unbounded: 4 pi mu a^2 (Omega + k/2)
//   stresslet S_xy = -sum_c (x_c F_c,y + y_c F_c,x) / 2   exact, unbounded: 4 pi mu a^2 (k/2)
// (the stresslet from the exact disturbance psi' = E sin(2 theta) (a^4 / (2 r^2) - a^2) of a
// cylinder in the strain E, whose far field is that of a force dipole 4 pi mu a^2 E). Both go as
// a^2, so the ratio to the unbounded value is (a_h / a)^2 times the channel's own correction.
#include <iosfwd>
#include <string>
#include <vector>

#include "solver/rigid_sphere/rigid_shell.hpp"

namespace capsule::rigid_sphere {

struct RigidCircleOptions {
  double a = 10;                 // the circle's radius: the exact values use it (lattice units)
  double marker_radius = 0;      // radius of the markers (0: a)
  int segments = 140;            // markers on the circle (the 2D capsule's default)
  double domain[2] = {16, 12};   // channel in units of a, as the 2D capsule's
  double Re = 0.05;              // k a^2 / nu
  double tau = 1.0;              // relaxation time (the 2D rule's default)
  double spin = 0;               // anchor rotation rate, in units of k
  double kt = 4;                 // run until this kt
  double gain = 0.05;            // kappa, force per unit marker lag (lattice units)
  ib::Delta delta = ib::Delta::peskin4;
  lbm::Precision precision = lbm::Precision::double_precision;
  double every = 0.25;           // series interval in kt
  // > 0: the fluid refined by a factor 2 in a block around the circle, this many coarse cells
  // wider on each side; a, the domain and tau are then the fine lattice's (the channel's fine
  // node counts must be even), the markers step on the fine lattice (tethered_markers.hpp).
  int refine_margin = 0;
};

// Throws std::invalid_argument naming the option and its allowed range.
void validate(const RigidCircleOptions& o);

// Runs the circle from the undisturbed Couette flow; a row every options.every kt and at the end.
// The rows' torque and stresslet are in units of 2 pi mu a^2 k (torque_exact = 1 + 2 spin).
RigidShellResult run_rigid_circle(const RigidCircleOptions& o);

}  // namespace capsule::rigid_sphere
