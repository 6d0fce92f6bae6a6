#pragma once
// Every claim of the dissertation comparison, one function each, defined in chapter2.cpp ...
// chapter5.cpp; evaluate_claims (claims.cpp) calls them in the order of the text.
#include <string>

#include "analysis/thesis/claims.hpp"

namespace capsule::analysis::claims {

ClaimResult claim_2_mesh(const ThesisResults& res);
ClaimResult claim_2_G(const ThesisResults& res);
ClaimResult claim_3_1(const ThesisResults& res);
ClaimResult claim_3_2_proportional(const ThesisResults& res, const std::string& case_name);
ClaimResult claim_3_2_constant(const ThesisResults& res, const std::string& case_name);
ClaimResult claim_3_3_falls(const ThesisResults& res, const std::string& case_name, const std::string& column);
ClaimResult claim_3_3_slight(const ThesisResults& res);
ClaimResult claim_3_4_linear(const ThesisResults& res, const std::string& case_name);
ClaimResult claim_3_4_small_V(const ThesisResults& res, const std::string& case_name);
ClaimResult claim_3_5_2d(const ThesisResults& res);
ClaimResult claim_3_5_3d(const ThesisResults& res);
ClaimResult claim_orders(const ThesisResults& res, const std::string& section, const std::string& statement,
                         const std::string& campaign, const std::string& fit, int o1, int o2);
ClaimResult claim_4_1_1_R1(const ThesisResults& res);
ClaimResult claim_4_1_1_R2(const ThesisResults& res);
ClaimResult claim_4_1_1_no_bending(const ThesisResults& res);
ClaimResult claim_4_1_2_r2(const ThesisResults& res);
ClaimResult claim_4_1_2_fig38(const ThesisResults& res);
ClaimResult claim_4_2_A(const ThesisResults& res);
ClaimResult claim_4_2_B(const ThesisResults& res);
ClaimResult claim_4_2_C(const ThesisResults& res);
ClaimResult claim_5_1_2(const ThesisResults& res, const std::string& campaign, double V_base, const std::string& figure);
ClaimResult claim_5_2_pairs(const ThesisResults& res, bool initial);
ClaimResult claim_5_2_mesh(const ThesisResults& res);
ClaimResult claim_5_2_gamma(const ThesisResults& res);

}  // namespace capsule::analysis::claims
