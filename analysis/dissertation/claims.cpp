#include "analysis/dissertation/claims.hpp"

#include "analysis/dissertation/claims/chapters.hpp"

namespace capsule::analysis {

using namespace claims;

std::vector<ClaimResult> evaluate_claims(const DissertationResults& res) {
  std::vector<ClaimResult> out;
  // A rule judged once, and a rule judged for the circle and the sphere (cases 2d, 3d).
  const auto once = [&](ClaimResult (*rule)(const DissertationResults&)) { out.push_back(rule(res)); };
  const auto per_case = [&](ClaimResult (*rule)(const DissertationResults&, const std::string&)) {
    for (const char* c : {"2d", "3d"}) out.push_back(rule(res, c));
  };
  once(claim_2_mesh), once(claim_2_G);
  once(claim_3_1), once(claim_3_1_overshoot);
  per_case(claim_3_2_proportional), per_case(claim_3_2_modest), per_case(claim_3_2_constant);
  once(claim_3_2_small_Ca);
  per_case(claim_3_2_response_normalized), once(claim_3_2_cleaner);
  for (const char* c : {"2d", "3d"}) out.push_back(claim_3_3_falls(res, c, "recovery.k_tau_r"));
  out.push_back(claim_3_3_falls(res, "3d", "response.k_tau_s"));
  once(claim_3_3_slight), per_case(claim_3_3_no_bending), per_case(claim_3_3_stiff);
  per_case(claim_3_4_linear), per_case(claim_3_4_small_V), per_case(claim_3_4_recovery_more);
  once(claim_3_5_2d), once(claim_3_5_3d), once(claim_3_5_fig20);
  out.push_back(claim_orders(res, "4.1.1 orders", "two_phase", -1, 1, missed_stop_in(res)));
  once(claim_4_1_1_fit_quality), once(claim_4_1_1_R1), once(claim_4_1_1_R2), once(claim_4_1_1_R1_weak);
  once(claim_4_1_1_R2_eta), once(claim_4_1_1_no_bending), once(claim_4_1_1_phase_angle);
  once(claim_4_1_2_monotone), once(claim_4_1_2_r2);
  out.push_back(claim_orders(res, "4.1.2 orders", "double_exponential", -1, 0, outside_tumbling_ensemble_in(res)));
  once(claim_4_1_2_Ca), once(claim_4_1_2_E_b_V), once(claim_4_1_2_eta), once(claim_4_1_2_fig38);
  once(claim_4_1_2_fig38_bending);
  once(claim_4_2_A), once(claim_4_2_A_plateau), once(claim_4_2_c0), once(claim_4_2_B), once(claim_4_2_C);
  once(claim_4_2_C_steady), once(claim_4_2_drift);
  once(claim_5_1_1_fit_quality), once(claim_5_1_1_similar), once(claim_5_1_1_ratio_trends);
  once(claim_5_1_1_ratios), once(claim_5_1_1_r2_rows);
  out.push_back(claim_5_1_2(res, "ch5_bilinear_ca005", 0.2, "Fig. 55"));
  out.push_back(claim_5_1_2(res, "ch5_bilinear_ca005_eb", 1.0, "Fig. 56"));
  once(claim_5_1_3_ratios_differ);
  out.push_back(claim_5_2_pairs(res, true));
  out.push_back(claim_5_2_pairs(res, false));
  once(claim_5_2_inclination), once(claim_5_2_n), once(claim_5_2_gamma_range), once(claim_5_2_mesh), once(claim_5_2_gamma),
      once(claim_5_2_fig66);
  return out;
}

std::vector<std::pair<std::string, ClaimVerdict>> claim_verdicts(const std::vector<ClaimResult>& rows) {
  std::vector<std::pair<std::string, ClaimVerdict>> out;
  for (std::size_t i = 0; i < rows.size();) {
    std::size_t agree = 0, differ = 0, open = 0, j = i;
    for (; j < rows.size() && rows[j].key == rows[i].key; ++j)
      ++(rows[j].verdict == Verdict::agrees ? agree : rows[j].verdict == Verdict::differs ? differ : open);
    const std::size_t n = j - i;
    out.emplace_back(rows[i].key, agree == n    ? ClaimVerdict::agrees
                                  : differ == n ? ClaimVerdict::differs
                                  : open == n   ? ClaimVerdict::cannot_tell
                                                : ClaimVerdict::in_part);
    i = j;
  }
  return out;
}

const char* claim_verdict_text(ClaimVerdict v) {
  switch (v) {
    case ClaimVerdict::agrees: return "agrees";
    case ClaimVerdict::differs: return "differs";
    case ClaimVerdict::in_part: return "in part";
    case ClaimVerdict::cannot_tell: return "cannot tell";
  }
  return "cannot tell";
}

std::string claim_chapter(const ClaimResult& row) { return row.section.substr(0, row.section.find('.')); }

}  // namespace capsule::analysis
