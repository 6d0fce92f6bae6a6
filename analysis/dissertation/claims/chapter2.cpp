// The claims of the dissertation's Chapter 2 (validation: mesh and G independence), each a rule with a stated numeric
// criterion (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
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

// Sec. 2.5.5: "due to the excellent agreement with Ramanujan and Pozrikidis for these parameters in
// Figure 7" (neo-Hookean sphere, V = 1). The report's "published" section: each member's D_xy against
// the digitised curve over the curve's points within the shear.
ClaimResult claim_2_fig7(const DissertationResults& res) {
  constexpr double bound = 0.02;  // the bound "4.2 A plateau" takes for "~" in D_xy
  auto [r, c] = open_claim(res, "2 Fig. 7", {{"bound", num(bound)}});
  if (!c) return r;
  Parts parts;
  std::size_t judged = 0;
  for (const auto& e : c->fits.value("published", nlohmann::json::array())) {
    const std::string curve = e.value("curve", ""), member = e.value("member", "");
    if (e.contains("reason") || !e.contains("max_abs_D_xy") || !e["max_abs_D_xy"].is_number()) {
      part_missing(parts.why, member + " against " + curve + ": " + e.value("reason", std::string("no max_abs_D_xy")));
      continue;
    }
    ++judged;
    const double worst = e["max_abs_D_xy"].get<double>();
    parts.add(worst <= bound, member + ": max |D_xy - curve| " + num(worst) + " over " + std::to_string(e.value("points", 0)) + " points");
  }
  if (judged == 0 && parts.why.empty()) part_missing(parts.why, "its report has no \"published\" section");
  return parts.finish(r);
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter2_claims() {
  return {once("2 Fig. 7", claim_2_fig7), once("2 mesh", claim_2_mesh), once("2 G", claim_2_G)};
}

}  // namespace capsule::analysis::claims
