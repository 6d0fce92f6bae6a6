#pragma once
// The 2D member (Sec. 2.1-2.4): D2Q9 MRT fluid between moving walls, the 2D membrane of
// Sec. 2.4 coupled by the immersed boundary (17)-(21), optional viscosity contrast (15)-(16).
//
// Per lattice step: membrane forces at X(n) -> spread (21) -> fluid step with that force ->
// interpolate u(n) at X(n) (19) -> X(n+1) = X(n) + U dt (20) -> viscosity field (if V != 1).
// The fluid starts in the linear Couette flow u = k (y - H/2) shear_factor(0) (so the capsule
// feels the shear from step 0); walls move at -+ k H/2 shear_factor(kt).
//
// Series columns written every output interval (docs/guide/member-files.md "2D series"):
//   kt              time in units of 1/k
//   D_xy            Taylor deformation (37), chords through the centroid (measures.hpp)
//   theta           major-axis inclination, rad, in (-pi/2, pi/2]
//   L, W            the two chords, units of a
//   area_drift      A / A(0) - 1 of the membrane polygon
//   tension         mean in-plane tension tau (28), length-weighted, units of E_s
//   bending_moment  mean |m| = |E_B (kappa - kappa0)| (32), length-weighted, units of E_s a
//   stretch_min/max extreme segment stretch lambda (29)
//   centroid_x/y    centroid offset from the domain centre, units of a
//   max_speed       largest fluid speed on the lattice (lattice units)
//   shear_on        1 under shear, 0 after the stop;  shear_factor: the wall-speed factor
//   /series/beta    [rows x 1]: phase angle (89) of node 0 (initially at the end of the major
//                   axis), wrapped into (-pi, pi]; tank-treading is clockwise, so beta decreases
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "solver/io/member_file.hpp"
#include "solver/io/state_archive.hpp"
#include "solver/run/run_control.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule {


class Simulation2D {
 public:
  // scene.dim == 2. start_in_shear = false starts the fluid at rest (tests).
  explicit Simulation2D(const Scene& scene, bool start_in_shear = true);
  ~Simulation2D();
  Simulation2D(const Simulation2D&) = delete;
  Simulation2D& operator=(const Simulation2D&) = delete;

  const Units& units() const;
  long steps() const;
  double kt() const;  // steps * k
  // One lattice step with the walls at -+ k H/2 * shear_factor.
  void step(double shear_factor);

  // The measures of docs/guide/member-files.md "2D series" at the current state (one output row), and the tracked phase
  // angle (89) of node 0 wrapped into (-pi, pi]. Call once per output interval (it
  // follows theta and beta continuously between calls).
  std::map<std::string, double> row();
  double beta() const;
  // "" when healthy, else the reason (NaN, stretch or area beyond the bounds below).
  std::string health(const std::map<std::string, double>& row) const;
  // Set when step() met a node that is NaN or beyond a wall (then step() does nothing).
  const std::string& failure() const;
  std::vector<double> shape() const;  // node positions (lattice units), flat n x 2
  // Moves the membrane nodes (the reference shape stays): for tests that start deformed.
  void set_shape(const std::vector<double>& xy);
  // Kinematic viscosity of the fluid node nearest to (x, y) (lattice units).
  double viscosity_at(double x, double y) const;

  // Health bounds (docs/guide/member-files.md "Health checks"): a segment stretched beyond max_stretch or compressed below
  // min_stretch, the enclosed area drifting by more than max_area_drift, or a lattice speed
  // above max_speed (Mach ~ 0.35, where the LBM is no longer a Navier-Stokes solver).
  // The compression bound is not 1/max_stretch: a bending-free Hookean membrane (30) really
  // compresses that far. Fig. 1's member Ca = 0.4, E_b = 0 reaches stretch_min 0.36 / 0.35 /
  // 0.35 at kt = 3 with 70 / 140 / 280 segments (a = 10: resolved, not a zig-zag of the mesh),
  // 0.40 at a = 20, and then tank-treads with stretch_min 0.38-0.58; a bound of 1/3 ended it
  // at kt = 3.1. 0.1 still catches a collapsing segment.
  static constexpr double max_stretch = 3.0;
  static constexpr double min_stretch = 0.1;
  static constexpr double max_area_drift = 0.05;
  static constexpr double max_speed = 0.2;

  // Time split for the benchmark: seconds in membrane + coupling and in the fluid step.
  double seconds_membrane() const;
  double seconds_fluid() const;

  // Restart points (solver/run/checkpoint.hpp): everything a later step() and row() read.
  // restore_state() moves the large fields out of the archive; it throws when the archive does
  // not fit this scene (another lattice, node count or reference shape).
  void save_state(io::StateArchive& archive) const;
  void restore_state(io::StateArchive& archive);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Runs the scene to the end of its protocol, appending rows to `out` (and the solver's
// choices as attributes). Returns "complete" or "unstable at kt = X: reason".
std::string run_simulation2d(const Scene& scene, io::MemberWriter& out, const RunControl& control);
inline std::string run_simulation2d(const Scene& scene, io::MemberWriter& out, bool quiet) {
  RunControl c;
  c.quiet = quiet;
  return run_simulation2d(scene, out, c);
}

}  // namespace capsule
