#pragma once
// Scene values inside their ranges whose combination no one means: a run of more time steps
// than any machine finishes, more output rows than a member file should hold, or a capsule
// inside that relaxes at tau = 1/2 (zero viscosity, (8)) although both V and tau are allowed.
#include <string>

#include "solver/scene/scene.hpp"

namespace capsule {

inline constexpr double max_run_steps = 1e10;   // time steps of shear and recovery together
inline constexpr double max_output_rows = 1e6;  // rows of the member file's series
inline constexpr double min_inside_tau = 0.505; // the smallest tau a scene may give (resolution.tau)

// Throws SceneError naming source, the key and the allowed range for this scene's a, Re and
// tau, when the scene breaks one of the bounds above.
void check_run_bounds(const Scene& scene, const std::string& source);

}  // namespace capsule
