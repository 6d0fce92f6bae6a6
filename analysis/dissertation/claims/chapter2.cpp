// The claims of the dissertation's Chapter 2 (validation: mesh and G independence), each a rule with a stated numeric
// criterion (claims/support.hpp).
#include "analysis/dissertation/claims/chapters.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

// Sec. 2 (Fig. 10): "The convergence of the viscoelastic algorithm is considered ... for
// increasingly fine meshes and is seen to converge nicely."
ClaimResult claim_2_mesh(const DissertationResults& res) {
  return judge_spread(res, {"2 mesh", "mesh", "/resolution/mesh_level", "level", 0.02, 3});
}

// Sec. 2 (Fig. 12): "the difference between the deformation for G = 10 and G = 25 is almost
// indiscernible".
ClaimResult claim_2_G(const DissertationResults& res) {
  return judge_spread(res, {"2 G", "G", "/G", "G", 0.02, 3});
}

}  // namespace capsule::analysis::claims
