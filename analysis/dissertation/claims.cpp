#include "analysis/dissertation/claims.hpp"

#include "analysis/dissertation/claims/chapters.hpp"

#include <stdexcept>

namespace capsule::analysis {

using namespace claims;

std::vector<ClaimResult> evaluate_claims(const DissertationResults& res) {
  std::vector<ClaimResult> out;
  res.take_campaigns_read();
  // Each row with whether a campaign its rule read ships some point at two levels.
  const auto push = [&](ClaimResult r) {
    for (const std::string& name : res.take_campaigns_read()) r.several_levels = r.several_levels || res.campaign(name).several_levels;
    res.take_campaigns_read();
    out.push_back(std::move(r));
  };
  // A rule judged once, and a rule judged for the circle and the sphere (cases 2d, 3d).
  const auto once = [&](ClaimResult (*rule)(const DissertationResults&)) { push(rule(res)); };
  const auto per_case = [&](ClaimResult (*rule)(const DissertationResults&, const std::string&)) {
    for (const char* c : {"2d", "3d"}) push(rule(res, c));
  };
  once(claim_2_fig7), once(claim_2_mesh), once(claim_2_G);
  once(claim_3_1), once(claim_3_1_overshoot);
  per_case(claim_3_2_proportional), per_case(claim_3_2_modest), per_case(claim_3_2_constant);
  once(claim_3_2_small_Ca);
  per_case(claim_3_2_response_normalized), per_case(claim_3_2_response_slows), once(claim_3_2_cleaner);
  for (const char* c : {"2d", "3d"}) push(claim_3_3_falls(res, c, "recovery.k_tau_r"));
  push(claim_3_3_falls(res, "3d", "response.k_tau_s"));
  once(claim_3_3_slight), per_case(claim_3_3_no_bending), per_case(claim_3_3_stiff), per_case(claim_3_3_deformation);
  per_case(claim_3_4_linear), per_case(claim_3_4_small_V), per_case(claim_3_4_recovery_more), per_case(claim_3_4_deformation);
  once(claim_3_5_2d), once(claim_3_5_3d), once(claim_3_5_small_eta), once(claim_3_5_fig20);
  push(claim_orders(res, "4.1.1 orders", "two_phase", -1, 1, missed_stop_in(res)));
  once(claim_4_1_1_fit_quality), once(claim_4_1_1_worst_fits), once(claim_4_1_1_R1), once(claim_4_1_1_R2), once(claim_4_1_1_R1_weak);
  once(claim_4_1_1_R2_eta), once(claim_4_1_1_dip_rise), once(claim_4_1_1_no_bending), once(claim_4_1_1_phase_angle);
  once(claim_4_1_2_monotone), once(claim_4_1_2_direction), once(claim_4_1_2_r2);
  push(claim_orders(res, "4.1.2 orders", "double_exponential", -1, 0, outside_tumbling_ensemble_in(res)));
  once(claim_4_1_2_Ca), once(claim_4_1_2_E_b_V), once(claim_4_1_2_eta), once(claim_4_1_2_fig38);
  once(claim_4_1_2_fig38_bending);
  once(claim_4_2_A), once(claim_4_2_A_plateau), once(claim_4_2_c0), once(claim_4_2_B), once(claim_4_2_C);
  once(claim_4_2_C_steady), once(claim_4_2_drift);
  once(claim_5_1_1_fit_quality), once(claim_5_1_1_similar), once(claim_5_1_1_ratio_trends);
  once(claim_5_1_1_ratios), once(claim_5_1_1_r2_rows);
  push(claim_5_1_2(res, "ch5_bilinear_ca005", 0.2, "Fig. 55"));
  push(claim_5_1_2(res, "ch5_bilinear_ca005_eb", 1.0, "Fig. 56"));
  once(claim_5_1_3_ratios_differ);
  push(claim_5_2_pairs(res, true));
  push(claim_5_2_pairs(res, false));
  once(claim_5_2_inclination), once(claim_5_2_settled), once(claim_5_2_n), once(claim_5_2_gamma_range), once(claim_5_2_mesh),
      once(claim_5_2_2_initial), once(claim_5_2_gamma), once(claim_5_2_fig66);
  return out;
}

std::vector<ClaimResult> combine_levels(std::vector<ClaimResult> fine, const std::vector<ClaimResult>& coarse) {
  if (fine.size() != coarse.size()) throw std::logic_error("combine_levels: the two levels give different numbers of rows");
  for (std::size_t i = 0; i < fine.size(); ++i) {
    ClaimResult& f = fine[i];
    const ClaimResult& c = coarse[i];
    if (f.key != c.key) throw std::logic_error("combine_levels: row " + std::to_string(i) + " is " + f.key + " and " + c.key);
    if (!f.several_levels) {
      f.levels = Levels::one_level;
      continue;
    }
    f.coarse_measured = std::string(verdict_text(c.verdict)) + ": " + c.measured;
    if (f.verdict == Verdict::cannot_tell) {
      f.levels = Levels::not_judged;
    } else if (c.verdict == f.verdict) {
      f.levels = Levels::converged;
    } else {
      f.levels = Levels::not_converged;
      f.measured = "cannot tell: not converged (finest level " + std::string(verdict_text(f.verdict)) + ", next coarser level " +
                   verdict_text(c.verdict) + "); finest: " + f.measured + "; next coarser: " + c.measured;
      f.verdict = Verdict::cannot_tell;
    }
  }
  return fine;
}

std::vector<ClaimResult> evaluate_claims_at_two_levels(const DissertationResults& finest) {
  return combine_levels(evaluate_claims(finest), evaluate_claims(DissertationResults(finest.results_dir(), 1)));
}

const char* levels_text(Levels l) {
  switch (l) {
    case Levels::one_level: return "one level";
    case Levels::converged: return "converged";
    case Levels::not_converged: return "not converged";
    case Levels::not_judged: return "";
  }
  return "";
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

const char* text_passes_text(TextPasses t) {
  switch (t) {
    case TextPasses::yes: return "yes";
    case TextPasses::no: return "no";
    case TextPasses::no_numbers: return "no numbers";
  }
  return "no numbers";
}

std::vector<std::pair<std::string, TextPasses>> claim_text_passes(const std::vector<ClaimResult>& rows) {
  std::vector<std::pair<std::string, TextPasses>> out;
  for (std::size_t i = 0; i < rows.size();) {
    TextPasses t = TextPasses::no_numbers;
    std::size_t j = i;
    for (; j < rows.size() && rows[j].key == rows[i].key; ++j) {
      if (rows[j].text_passes == TextPasses::no) t = TextPasses::no;
      else if (rows[j].text_passes == TextPasses::yes && t == TextPasses::no_numbers) t = TextPasses::yes;
    }
    out.emplace_back(rows[i].key, t);
    i = j;
  }
  return out;
}

std::string claim_chapter(const ClaimResult& row) { return row.section.substr(0, row.section.find('.')); }

}  // namespace capsule::analysis
