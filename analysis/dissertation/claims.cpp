#include "analysis/dissertation/claims.hpp"

#include "analysis/dissertation/claims/chapters.hpp"

namespace capsule::analysis {

using namespace claims;

std::vector<ClaimResult> evaluate_claims(const DissertationResults& res) {
  std::vector<ClaimResult> out;
  out.push_back(claim_2_mesh(res));
  out.push_back(claim_2_G(res));
  out.push_back(claim_3_1(res));
  out.push_back(claim_3_1_overshoot(res));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_2_proportional(res, c));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_2_modest(res, c));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_2_constant(res, c));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_2_response_normalized(res, c));
  out.push_back(claim_3_2_cleaner(res));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_3_falls(res, c, "recovery.k_tau_r"));
  out.push_back(claim_3_3_falls(res, "3d", "response.k_tau_s"));
  out.push_back(claim_3_3_slight(res));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_3_no_bending(res, c));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_4_linear(res, c));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_4_small_V(res, c));
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_4_recovery_more(res, c));
  out.push_back(claim_3_5_2d(res));
  out.push_back(claim_3_5_3d(res));
  out.push_back(claim_orders(res, "4.1.1 orders", "two_phase", -1, 1, missed_stop_in(res)));
  out.push_back(claim_4_1_1_fit_quality(res));
  out.push_back(claim_4_1_1_R1(res));
  out.push_back(claim_4_1_1_R2(res));
  out.push_back(claim_4_1_1_R1_weak(res));
  out.push_back(claim_4_1_1_R2_eta(res));
  out.push_back(claim_4_1_1_no_bending(res));
  out.push_back(claim_4_1_2_r2(res));
  out.push_back(claim_orders(res, "4.1.2 orders", "double_exponential", -1, 0, outside_tumbling_ensemble_in(res)));
  out.push_back(claim_4_1_2_Ca(res));
  out.push_back(claim_4_1_2_E_b_V(res));
  out.push_back(claim_4_1_2_eta(res));
  out.push_back(claim_4_1_2_fig38(res));
  out.push_back(claim_4_2_A(res));
  out.push_back(claim_4_2_B(res));
  out.push_back(claim_4_2_C(res));
  out.push_back(claim_5_1_2(res, "ch5_bilinear_ca005", 0.2, "Fig. 55"));
  out.push_back(claim_5_1_2(res, "ch5_bilinear_ca005_eb", 1.0, "Fig. 56"));
  out.push_back(claim_5_2_pairs(res, true));
  out.push_back(claim_5_2_pairs(res, false));
  out.push_back(claim_5_2_mesh(res));
  out.push_back(claim_5_2_gamma(res));
  return out;
}

}  // namespace capsule::analysis
