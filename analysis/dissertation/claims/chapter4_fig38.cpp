// The claims of the dissertation's Sec. 4.1.2 on the tension and bending moment during recovery: Fig. 37's
// tank-treading capsule (Ca 0.067, E_b 0.0014, V 1, eta 12) and Fig. 38's tumbling capsule (Ca 0.4,
// E_b 0.05, V 5, eta 0, stopped at theta = -pi/3): its first recovery time and how its tension and
// bending moment fall in that first phase, each a rule with a stated numeric criterion (claims/support.hpp).
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

// A recorded series of a member (tension, bending_moment) at the stop, at the end of the first phase
// of the recovery (kt `phase_end`) and at the end; nullopt with why.
struct ThreePoints {
  double stop = k_nan, phase = k_nan, end = k_nan, t_stop = k_nan, t_phase = k_nan, t_end = k_nan;
};
std::optional<ThreePoints> three_points(const DissertationResults& res, const DissertationMember& m, const std::string& name,
                                        const std::string& phase_marker, double after_stop, std::string& why) {
  const auto data = res.member_data(m, why, true);
  if (!data) return std::nullopt;
  ThreePoints p;
  p.t_stop = marker(*data, "t_stop");
  p.t_phase = phase_marker.empty() ? p.t_stop + after_stop : marker(*data, phase_marker);
  if (!data->series.count("kt") || !data->series.count(name) || !std::isfinite(p.t_stop) || !std::isfinite(p.t_phase) ||
      data->series.at("kt").empty() || data->series.at("kt").back() <= p.t_phase) {
    why = m.slug + ": no " + name + " series, no t_stop" + (phase_marker.empty() ? "" : " / " + phase_marker) + " or no rows after it";
    return std::nullopt;
  }
  const auto& kt = data->series.at("kt");
  const auto& y = data->series.at(name);
  p.stop = interpolate_series(kt, y, p.t_stop);
  p.phase = interpolate_series(kt, y, p.t_phase);
  p.end = y.back();
  p.t_end = kt.back();
  return p;
}

// Fig. 37's member of ch4_2d_tt (case eta, eta 12); null, with r.measured saying why.
const DissertationMember* fig37_member(const DissertationCampaign& c, ClaimResult& r) {
  for (const DissertationMember* m : c.in_case("eta"))
    if (parameter(*m, "eta") == 12.0) return m;
  r.measured = "cannot tell (members missing): no case eta member at eta 12 (Fig. 37's capsule)";
  return nullptr;
}

// |tension| falls to at most half its value at the stop by the end of the first phase, and on
// through the second (the sharp decline, then the slow dissipation of the rest).
ClaimResult judge_tension_fall(ClaimResult r, const DissertationResults& res, const DissertationMember& m, const std::string& phase_marker,
                               double after_stop, const std::string& phase_name) {
  std::string why;
  const auto p = three_points(res, m, "tension", phase_marker, after_stop, why);
  if (!p) {
    r.measured = "cannot tell (members missing): " + why;
    return r;
  }
  const double a = std::abs(p->stop), b = std::abs(p->phase), e = std::abs(p->end);
  set(r, b <= 0.5 * a && e < b,
      m.slug + ": |tension| " + num(a) + " at the stop (kt " + num(p->t_stop) + "), " + num(b) + " at " + phase_name + " (kt " +
          num(p->t_phase) + "), " + num(e) + " at the end (kt " + num(p->t_end) + ")");
  return r;
}

}  // namespace

// Sec. 4.1.2 (Fig. 37): "for a tank-treading capsule, one may observe that during the initial phase of
// recovery -- when D_xy is decreasing -- tension tau decreases very rapidly. Indeed, the time periods in
// which D_xy decreases and tau sharply declines end nearly simultaneously. ... The remaining tension,
// however, is dissipated very slowly during the second phase of recovery."
ClaimResult claim_4_1_2_fig37_tension(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 Fig. 37 tension");
  if (!c) return r;
  const DissertationMember* m = fig37_member(*c, r);
  if (!m) return r;
  return judge_tension_fall(r, res, *m, "t_min", 0.0, "the minimum of D_xy");
}

// Sec. 4.1.2 (Fig. 37): "In contrast, bending moment m decreases at a modest rate through both recovery
// phases. As a result, the dependence on bending stiffness is seen primarily in the longer, latter
// recovery phase."
ClaimResult claim_4_1_2_fig37_bending(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 Fig. 37 bending");
  if (!c) return r;
  const DissertationMember* m = fig37_member(*c, r);
  if (!m) return r;
  std::string why;
  const auto p = three_points(res, *m, "bending_moment", "t_min", 0.0, why);
  if (!p) {
    r.measured = "cannot tell (members missing): " + why;
    return r;
  }
  const double share = (p->stop - p->phase) / (p->stop - p->end);
  set(r, p->phase < p->stop && p->end < p->phase && share < 0.5,
      m->slug + ": mean |m| " + num(p->stop) + " at the stop (kt " + num(p->t_stop) + "), " + num(p->phase) + " at the minimum of D_xy (kt " +
          num(p->t_phase) + "), " + num(p->end) + " at the end (kt " + num(p->t_end) + "): " + num(100 * share) + " % of its fall in the first phase");
  return r;
}

// Sec. 4.1.2 (Fig. 38): "For the tumbling capsule considered in Figure 38, there is a similar sharp initial
// decrease in k tau, which ends near t = 1. ... As with the tank-treading capsule, it is followed by a much
// slower decline in tension."
ClaimResult claim_4_1_2_fig38_tension(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 Fig. 38 tension");
  if (!c) return r;
  const DissertationMember* base = fig38_member(res, *c, r);
  if (!base) return r;
  return judge_tension_fall(r, res, *base, "", 1.0, "kt_stop + 1");
}

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
  return {once("4.1.2 Fig. 37 tension", claim_4_1_2_fig37_tension), once("4.1.2 Fig. 37 bending", claim_4_1_2_fig37_bending),
          once("4.1.2 Fig. 38", claim_4_1_2_fig38), once("4.1.2 Fig. 38 tension", claim_4_1_2_fig38_tension),
          once("4.1.2 Fig. 38 bending", claim_4_1_2_fig38_bending)};
}

}  // namespace capsule::analysis::claims
