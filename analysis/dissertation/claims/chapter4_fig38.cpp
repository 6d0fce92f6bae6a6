// The claims of the dissertation's Sec. 4.1.2 on Fig. 38's tumbling capsule (Ca 0.4, E_b 0.05,
// V 5, eta 0, stopped at theta = -pi/3): its first recovery time and how its bending moment falls
// in that first phase, each a rule with a stated numeric criterion (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

namespace {

// Fig. 38's member of ch4_2d_tumble (its base member, not the theta = pi/6 stop); null, with
// r.measured saying why, when it is not there or its stop never came.
const DissertationMember* fig38_member(const DissertationResults& res, const DissertationCampaign& c, ClaimResult& r) {
  const DissertationMember* base = nullptr;
  for (const DissertationMember* m : c.in_case(""))
    if (m->case_name != "theta_pi_6" && std::abs(parameter(*m, "Ca") - 0.4) < 1e-9 &&
        std::abs(parameter(*m, "E_b") - 0.05) < 1e-9 && std::abs(parameter(*m, "V") - 5) < 1e-9 &&
        parameter(*m, "eta") == 0.0)
      base = m;
  if (!base) {
    r.measured = "cannot tell (members missing): no member with Ca 0.4, E_b 0.05, V 5, eta 0 in fits.json";
    return nullptr;
  }
  if (const std::string missed = missed_stop(res, *base); !missed.empty()) {
    r.measured = "cannot tell: " + base->slug + ": " + missed;
    return nullptr;
  }
  return base;
}

}  // namespace

// Sec. 4.1.2: Fig. 38's capsule: "the capsule's first recover time, tau_R1 = 0.283".
ClaimResult claim_4_1_2_fig38(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 Fig. 38");
  if (!c) return r;
  const DissertationMember* base = fig38_member(res, *c, r);
  if (!base) return r;
  const ColumnValue v = column_value(base->fits, "double_exponential.k_tau_R1");
  if (!v.parameter) {
    r.measured = "cannot tell: " + base->slug + ": (90) " + v.reason;
    return r;
  }
  std::string text = "(90): k tau_R1 " + short_plus_minus(v.parameter->value, v.parameter->half_width());
  if (const ColumnValue r2 = column_value(base->fits, "double_exponential.k_tau_R2"); r2.parameter)
    text += ", k tau_R2 " + num(r2.parameter->value) + ", R^2 " + num(v.fit->r_squared);
  const ColumnValue f1 = column_value(base->fits, "double_exponential_free.k_tau_R1");
  const ColumnValue f2 = column_value(base->fits, "double_exponential_free.k_tau_R2");
  const ColumnValue w = column_value(base->fits, "double_exponential_free.w_R1");
  if (f1.parameter && f2.parameter && w.parameter)
    text += "; free amplitudes: k tau_R1 " + num(f1.parameter->value) + ", k tau_R2 " + num(f2.parameter->value) +
            ", fast share w_R1 " + num(w.parameter->value);
  set(r, std::abs(v.parameter->value - 0.283) <= 0.2 * 0.283, text);
  return r;
}

// Sec. 4.1.2: "For the tumbling capsule considered in Figure 38, there is a similar sharp initial
// decrease in [tension], which ends near t = 1. ... Further, the bending moment also decreases by
// nearly 50% during this initial phase, before entering a slower decline."
ClaimResult claim_4_1_2_fig38_bending(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 Fig. 38 bending");
  if (!c) return r;
  const DissertationMember* base = fig38_member(res, *c, r);
  if (!base) return r;
  std::string why;
  const auto data = res.member_data(*base, why, true);
  const double t_stop = data ? marker(*data, "t_stop") : k_nan;
  if (!data || !data->series.count("kt") || !data->series.count("bending_moment") || !std::isfinite(t_stop)) {
    r.measured = "cannot tell (members missing): " + (data ? base->slug + ": no bending_moment series or t_stop" : why);
    return r;
  }
  const auto& kt = data->series.at("kt");
  const auto& m = data->series.at("bending_moment");
  if (kt.empty() || kt.back() < t_stop + 1.0) {
    r.measured = "cannot tell (members missing): " + base->slug + ": the recovery ends before kt_stop + 1";
    return r;
  }
  const double m_stop = interpolate_series(kt, m, t_stop), m_1 = interpolate_series(kt, m, t_stop + 1.0);
  const double fall = 1.0 - m_1 / m_stop;
  set(r, fall >= 0.4 && fall <= 0.6,
      base->slug + ": mean |m| " + num(m_stop) + " at the stop (kt " + num(t_stop) + "), " + num(m_1) + " at kt_stop + 1: falls by " +
          num(100 * fall) + " %");
  return r;
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter4_fig38_claims() {
  return {once("4.1.2 Fig. 38", claim_4_1_2_fig38), once("4.1.2 Fig. 38 bending", claim_4_1_2_fig38_bending)};
}

}  // namespace capsule::analysis::claims
