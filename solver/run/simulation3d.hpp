#pragma once
// The 3D member: D3Q19 fluid, triangulated FEM membrane, immersed boundary coupling.
#include <cstddef>
#include <string>

#include "solver/io/member_file.hpp"
#include "solver/run/run_control.hpp"
#include "solver/scene/scene.hpp"

namespace capsule {
// Seconds per lattice step of a 3D member, by part (`capsule bench member3d`): measured over
// `steps` steps of the scene's shear after `warmup_steps`, at the caller's OpenMP thread count.
struct StepSplit3D {
  long steps = 0;
  double total = 0, fluid = 0, coupling = 0, viscosity = 0, elastic = 0, curvature = 0, bending = 0;
  double spreading = 0;  // the part of `coupling` that clears the force field and spreads (21)
  std::size_t vertices = 0;
  double nodes = 0;
  // A refined member (resolution.refine): one step is a coarse step (two fine ones), and its
  // fluid splits into the coarse lattice, the fine sub-steps and the transfers.
  bool refined = false;
  double coarse = 0, fine = 0, transfers = 0;
};
StepSplit3D time_steps3d(const Scene& scene, long warmup_steps, long steps);

// Snapshots (scene output.snapshots): <member>_kt0001.000.vtp beside the member file, and
// <member>.pvd (snapshot_base + ".pvd") collecting them; <member> is the path less ".h5".
std::string snapshot_base(const std::string& member_path);
std::string snapshot_path(const std::string& member_path, double kt);

// Runs the scene to the end of its protocol, appending rows to `out`.
// Returns the final status: "complete" or "unstable at kt = X: reason".
std::string run_simulation3d(const Scene& scene, io::MemberWriter& out, const RunControl& control);
inline std::string run_simulation3d(const Scene& scene, io::MemberWriter& out, bool quiet) {
  RunControl c;
  c.quiet = quiet;
  return run_simulation3d(scene, out, c);
}
}  // namespace capsule
