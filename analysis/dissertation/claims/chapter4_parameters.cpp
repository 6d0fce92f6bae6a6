// The claims of the dissertation's Chapter 4 on how the two recovery times of the biconcave capsule
// depend on the parameters (Figs. 25-28 tank-treading, Figs. 33-36 tumbling) and on how well
// (87)-(88) fit, each a rule with a stated numeric criterion (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

namespace {

// Both recovery times of one case against x, covering the same first and last x with at least
// n values each, and how much each rises over the sweep (last / first - 1).
struct TwoTimes {
  Series r1, r2;
  double rise1 = k_nan, rise2 = k_nan;
  std::string span(const std::string& x) const { return x + " " + num(r1.points.front().x) + "-" + num(r1.points.back().x); }
};
std::optional<TwoTimes> two_times(Parts& parts, const DissertationCampaign& c, const std::string& case_name,
                                  const std::string& x, const std::string& fit, std::size_t n, const Skip& skip,
                                  const Keep& keep = {}) {
  TwoTimes t{series(c, case_name, x, fit + ".k_tau_R1", keep, skip), series(c, case_name, x, fit + ".k_tau_R2", keep, skip)};
  if (!parts.enough(t.r1, n, case_name, x, fit + ".k_tau_R1") || !parts.enough(t.r2, n, case_name, x, fit + ".k_tau_R2"))
    return std::nullopt;
  if (t.r1.points.front().x != t.r2.points.front().x || t.r1.points.back().x != t.r2.points.back().x) {
    part_missing(parts.why, "case " + case_name + ": the two times span other values of " + x);
    return std::nullopt;
  }
  t.rise1 = t.r1.points.back().y / t.r1.points.front().y - 1.0;
  t.rise2 = t.r2.points.back().y / t.r2.points.front().y - 1.0;
  return t;
}

const char* k_tt_fit = "two_phase";
const char* k_tumble_fit = "double_exponential";

}  // namespace

// Sec. 4.1.1: "The fitted results had a coefficients of correlation R^2 > 0.95 and the majority of
// cases were in excess of 0.98."
ClaimResult claim_4_1_1_fit_quality(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.1 fit quality");
  if (!c) return r;
  Parts parts;
  for (const char* fit : {"two_phase_R1", "two_phase_R2"}) {
    std::size_t n = 0, above_098 = 0;
    double lowest = 1.0;
    std::vector<std::string> below, seen;
    for (const char* case_name : {"Ca", "E_b", "V", "eta"})
      for (const DissertationMember* m : c->in_case(case_name)) {
        if (std::find(seen.begin(), seen.end(), m->slug) != seen.end()) continue;  // the base member is in every case
        seen.push_back(m->slug);
        const auto it = m->fits.find(fit);
        if (it == m->fits.end() || !it->second.ok) continue;
        ++n;
        const double r2 = it->second.r_squared;
        lowest = std::min(lowest, r2);
        above_098 += r2 > 0.98;
        if (!(r2 > 0.95)) below.push_back(m->slug + " " + num(r2));
      }
    const std::string phase = fit == std::string("two_phase_R1") ? "(87)" : "(88)";
    if (n < 5) {
      part_missing(parts.why, phase + ": " + std::to_string(n) + " fits, need 5");
      continue;
    }
    parts.add(below.empty() && 2 * above_098 > n,
              phase + ": " + std::to_string(n) + " fits, lowest R^2 " + num(lowest) + ", " + std::to_string(above_098) +
                  " above 0.98" + (below.empty() ? "" : ", at or below 0.95: " + first_gaps(below)));
  }
  return parts.finish(r);
}

// Sec. 4.1.1: "During the first phase, however, the recovery time k tau_R1 decreased only slightly for
// larger bending stiffness"; "a much weaker linear relationship between V and the initial recovery
// time k tau_R1" (than k tau_R2's, "almost directly proportional with V").
ClaimResult claim_4_1_1_R1_weak(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.1 R1 weak");
  if (!c) return r;
  Parts parts;
  const auto positive_E_b = [](const DissertationMember& m) { return parameter(m, "E_b") > 0.0; };
  if (const auto e = two_times(parts, *c, "E_b", "E_b", k_tt_fit, 3, missed_stop_in(res), positive_E_b))
    parts.add(e->rise1 <= 0.02 && e->rise1 > -0.3, "E_b: k tau_R1 falls by " + num(-100 * e->rise1) + " % (" + e->r1.listing("E_b") + ")");
  if (const auto v = two_times(parts, *c, "V", "V", k_tt_fit, 3, missed_stop_in(res)))
    parts.add(v->rise1 <= 0.5 * v->rise2,
              v->span("V") + ": k tau_R1 rises " + num(100 * v->rise1) + " %, k tau_R2 " + num(100 * v->rise2) + " %");
  return parts.finish(r);
}

// Sec. 4.1.1: "the latter recovery time k tau_R2 was clearly independent of the membrane viscosity ratio".
ClaimResult claim_4_1_1_R2_eta(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.1 R2 eta");
  if (!c) return r;
  const Series s = series(*c, "eta", "eta", std::string(k_tt_fit) + ".k_tau_R2", {}, missed_stop_in(res));
  if (!have_points(r, s, 3, "values of eta with k tau_R2")) return r;
  const double spread = relative_spread(s.ys());
  set(r, spread <= 0.1, "spread " + num(spread) + "; k tau_R2: " + s.listing("eta") + not_counted(s));
  return r;
}

// Sec. 4.1.2: "both recovery times were almost directly proportional to Ca".
ClaimResult claim_4_1_2_Ca(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 Ca");
  if (!c) return r;
  Parts parts;
  for (const char* t : {"k_tau_R1", "k_tau_R2"})
    exponent_part(parts, *c, "Ca", "Ca", std::string(k_tumble_fit) + "." + t, 0.7, 1.3, outside_tumbling_ensemble_in(res));
  return parts.finish(r);
}

// Sec. 4.1.2: "bending stiffness and the fluid viscosity ratio had fairly negligible impacts on
// k tau_R1, but k tau_R2 varied directly with V and inversely with E_b".
ClaimResult claim_4_1_2_E_b_V(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 E_b and V");
  if (!c) return r;
  Parts parts;
  const Skip skip = outside_tumbling_ensemble_in(res);
  const std::string R1 = std::string(k_tumble_fit) + ".k_tau_R1", R2 = std::string(k_tumble_fit) + ".k_tau_R2";
  for (const char* x : {"E_b", "V"}) {
    const Series s = series(*c, x, x, R1, {}, skip);
    if (!parts.enough(s, 3, x, x, R1)) continue;
    const double spread = relative_spread(s.ys());
    parts.add(spread <= 0.3, std::string(x) + ": k tau_R1 spread " + num(spread) + " (" + s.listing(x) + ")" + not_counted(s));
  }
  exponent_part(parts, *c, "E_b", "E_b", R2, -1.3, -0.7, skip);
  const Series v = series(*c, "V", "V", R2, {}, skip);
  if (parts.enough(v, 3, "V", "V", R2)) {
    const LineFit f = fit_line(v.xs(), v.ys());
    parts.add(f.ok && f.slope > 0, "V: k tau_R2 slope " + num(f.slope) + " (" + v.listing("V") + ")" + not_counted(v));
  }
  return parts.finish(r);
}

// Sec. 4.1.2: "for the membrane viscosity ratio, both recovery times increased modestly with eta for
// the tumbling capsule, though k tau_R1 still had a higher dependence on eta".
ClaimResult claim_4_1_2_eta(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 eta");
  if (!c) return r;
  Parts parts;
  const auto e = two_times(parts, *c, "eta", "eta", k_tumble_fit, 3, outside_tumbling_ensemble_in(res));
  if (!e) return parts.finish(r);
  const LineFit f1 = fit_line(e->r1.xs(), e->r1.ys()), f2 = fit_line(e->r2.xs(), e->r2.ys());
  parts.add(f1.ok && f2.ok && f1.slope > 0 && f2.slope > 0 && e->rise1 > e->rise2,
            "slopes k tau_R1 " + num(f1.slope) + ", k tau_R2 " + num(f2.slope) + "; rise over " + e->span("eta") +
                ": k tau_R1 " + num(100 * e->rise1) + " %, k tau_R2 " + num(100 * e->rise2) + " %");
  return parts.finish(r);
}

// Sec. 4.1.1 (Fig. 30): "If phase angle beta is small, then the capsule will recover its shape more
// quickly than for a larger phase angle" (0.11 against the ensemble's 0.49 rad).
ClaimResult claim_4_1_1_phase_angle(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.1 phase angle");
  if (!c) return r;
  const std::string column = std::string(k_tt_fit) + ".k_tau_R2";
  const auto same_point = [](const DissertationMember& m) {
    return parameter(m, "Ca") == 0.067 && parameter(m, "E_b") == 0.0014 && parameter(m, "V") == 1.0 && parameter(m, "eta") == 0.0;
  };
  const Series small = series(*c, "beta_0.11", "Ca", column, same_point, missed_stop_in(res));
  const Series base = series(*c, "Ca", "Ca", column, same_point, missed_stop_in(res));
  if (!have_points(r, small, 1, "beta 0.11 members with k tau_R2") || !have_points(r, base, 1, "base members with k tau_R2"))
    return r;
  const double k_small = small.points.front().y, k_base = base.points.front().y;
  set(r, k_small < k_base, "k tau_R2 " + num(k_small) + " at beta 0.11 against " + num(k_base) + " at 0.49");
  return r;
}

// Sec. 4.1.2 (Fig. 31): "After shear flow is stopped ... the Taylor deformation parameter essentially
// increased or decreased monotonically from D_stop to its initial value".
ClaimResult claim_4_1_2_monotone(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.1.2 monotone");
  if (!c) return r;
  Parts parts;
  const std::size_t n = judge_curves(res, *c, "", parts, false, outside_tumbling_ensemble_in(res),
                                     [&](const DissertationMember& m, const Curve& curve) {
    const auto& D = curve.D;
    const std::size_t i0 = curve.stop_row;
    // The largest step back against the recovery's overall direction, from the furthest point reached.
    const double direction = D.back() >= D[i0] ? 1.0 : -1.0;
    double furthest = D[i0], back = 0.0;
    for (std::size_t i = i0; i < D.size(); ++i) {
      furthest = direction > 0 ? std::max(furthest, D[i]) : std::min(furthest, D[i]);
      back = std::max(back, direction * (furthest - D[i]));
    }
    parts.add(back <= 0.02, m.slug + " " + (direction > 0 ? "rises" : "falls") + " " + num(D[i0]) + " -> " + num(D.back()) +
                                ", largest step back " + num(back));
  });
  if (n < 3) part_missing(parts.why, std::to_string(n) + " ensemble members with a recovery, need 3");
  return parts.finish(r);
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter4_parameters_claims() {
  return {once("4.1.1 fit quality", claim_4_1_1_fit_quality),
          once("4.1.1 R1 weak", claim_4_1_1_R1_weak),
          once("4.1.1 R2 eta", claim_4_1_1_R2_eta),
          once("4.1.2 Ca", claim_4_1_2_Ca),
          once("4.1.2 E_b and V", claim_4_1_2_E_b_V),
          once("4.1.2 eta", claim_4_1_2_eta),
          once("4.1.1 phase angle", claim_4_1_1_phase_angle),
          once("4.1.2 monotone", claim_4_1_2_monotone)};
}

}  // namespace capsule::analysis::claims
