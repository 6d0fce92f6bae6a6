#pragma once
// The 3D member: D3Q19 fluid, triangulated FEM membrane, immersed boundary coupling.
#include <string>

#include "solver/io/member_file.hpp"
#include "solver/run/run_control.hpp"
#include "solver/scene/scene.hpp"

namespace capsule {
// Runs the scene to the end of its protocol, appending rows to `out`.
// Returns the final status: "complete" or "unstable at kt = X: reason".
std::string run_simulation3d(const Scene& scene, io::MemberWriter& out, const RunControl& control);
inline std::string run_simulation3d(const Scene& scene, io::MemberWriter& out, bool quiet) {
  RunControl c;
  c.quiet = quiet;
  return run_simulation3d(scene, out, c);
}
}  // namespace capsule
