#pragma once
// Every claim of the dissertation comparison, one function each, defined in chapter2.cpp ...
// chapter5.cpp and the files beside them; evaluate_claims (claims.cpp) calls them in the order of the text.
#include <string>

#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

ClaimResult claim_2_mesh(const DissertationResults& res);
ClaimResult claim_2_G(const DissertationResults& res);
ClaimResult claim_2_fig7(const DissertationResults& res);
ClaimResult claim_3_1(const DissertationResults& res);
ClaimResult claim_3_1_overshoot(const DissertationResults& res);
ClaimResult claim_3_2_proportional(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_2_constant(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_2_modest(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_2_response_normalized(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_2_cleaner(const DissertationResults& res);
ClaimResult claim_3_2_response_slows(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_3_deformation(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_4_deformation(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_2_small_Ca(const DissertationResults& res);
ClaimResult claim_3_3_no_bending(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_3_stiff(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_4_recovery_more(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_3_falls(const DissertationResults& res, const std::string& case_name, const std::string& column);
ClaimResult claim_3_3_slight(const DissertationResults& res);
ClaimResult claim_3_4_linear(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_4_small_V(const DissertationResults& res, const std::string& case_name);
ClaimResult claim_3_5_2d(const DissertationResults& res);
ClaimResult claim_3_5_3d(const DissertationResults& res);
ClaimResult claim_3_5_small_eta(const DissertationResults& res);
ClaimResult claim_3_5_fig20(const DissertationResults& res);
ClaimResult claim_orders(const DissertationResults& res, const std::string& key, const std::string& fit, int o1, int o2,
                         const Skip& skip);
ClaimResult claim_4_1_1_fit_quality(const DissertationResults& res);
ClaimResult claim_4_1_1_R1(const DissertationResults& res);
ClaimResult claim_4_1_1_R2(const DissertationResults& res);
ClaimResult claim_4_1_1_R1_weak(const DissertationResults& res);
ClaimResult claim_4_1_1_R2_eta(const DissertationResults& res);
ClaimResult claim_4_1_2_Ca(const DissertationResults& res);
ClaimResult claim_4_1_2_E_b_V(const DissertationResults& res);
ClaimResult claim_4_1_2_eta(const DissertationResults& res);
ClaimResult claim_4_1_1_no_bending(const DissertationResults& res);
ClaimResult claim_4_1_1_dip_rise(const DissertationResults& res);
ClaimResult claim_4_1_1_worst_fits(const DissertationResults& res);
ClaimResult claim_4_1_2_direction(const DissertationResults& res);
ClaimResult claim_4_1_2_r2(const DissertationResults& res);
ClaimResult claim_4_1_2_fig38(const DissertationResults& res);
ClaimResult claim_4_1_2_fig38_bending(const DissertationResults& res);
ClaimResult claim_4_1_1_phase_angle(const DissertationResults& res);
ClaimResult claim_4_1_2_monotone(const DissertationResults& res);
ClaimResult claim_4_2_A_plateau(const DissertationResults& res);
ClaimResult claim_4_2_c0(const DissertationResults& res);
ClaimResult claim_4_2_C_steady(const DissertationResults& res);
ClaimResult claim_4_2_A(const DissertationResults& res);
ClaimResult claim_4_2_B(const DissertationResults& res);
ClaimResult claim_4_2_C(const DissertationResults& res);
ClaimResult claim_4_2_drift(const DissertationResults& res);
ClaimResult claim_5_1_1_fit_quality(const DissertationResults& res);
ClaimResult claim_5_1_1_similar(const DissertationResults& res);
ClaimResult claim_5_1_1_ratio_trends(const DissertationResults& res);
ClaimResult claim_5_1_1_ratios(const DissertationResults& res);
ClaimResult claim_5_1_1_r2_rows(const DissertationResults& res);
ClaimResult claim_5_1_3_ratios_differ(const DissertationResults& res);
ClaimResult claim_5_1_2(const DissertationResults& res, const std::string& campaign, double V_base, const std::string& figure);
ClaimResult claim_5_2_pairs(const DissertationResults& res, bool initial);
ClaimResult claim_5_2_n(const DissertationResults& res);
ClaimResult claim_5_2_inclination(const DissertationResults& res);
ClaimResult claim_5_2_gamma_range(const DissertationResults& res);
ClaimResult claim_5_2_mesh(const DissertationResults& res);
ClaimResult claim_5_2_gamma(const DissertationResults& res);
ClaimResult claim_5_2_fig66(const DissertationResults& res);
ClaimResult claim_5_2_settled(const DissertationResults& res);
ClaimResult claim_5_2_2_initial(const DissertationResults& res);

}  // namespace capsule::analysis::claims
