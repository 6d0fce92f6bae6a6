// The claims of the dissertation's Chapter 3 on how the times' growth and the deformation itself
// change along a sweep (Secs. 3.2-3.4), each a rule with a stated numeric criterion (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

// Sec. 3.2: "increasing the capillary number leads only to a small increase in k tau_s, with the
// rate of increase declining as Ca rises."
ClaimResult claim_3_2_response_slows(const DissertationResults& res, const std::string& case_name) {
  auto [r, c] = open_claim(res, "3.2 response slows", {{"case", case_name}});
  if (!c) return r;
  const Series s = series(*c, case_name, "Ca", "response.k_tau_s");
  if (!have_points(r, s, 4, "values of Ca with k tau_s")) return r;
  bool rises = true, slows = true;
  std::string slopes;
  double previous = k_nan;
  for (std::size_t i = 1; i < s.points.size(); ++i) {
    const double slope = (s.points[i].y - s.points[i - 1].y) / (s.points[i].x - s.points[i - 1].x);
    rises = rises && slope > 0;
    slows = slows && (std::isnan(previous) || slope < previous);
    previous = slope;
    slopes += (slopes.empty() ? "" : ", ") + num(slope);
  }
  set(r, rises && slows, "slope of k tau_s between successive Ca: " + slopes + "; k tau_s: " + s.listing("Ca") + not_counted(s));
  return r;
}

// Secs. 3.3 and 3.4: D_xy at the stop of each member of a case against x, lower at every step up in x.
ClaimResult deformation_falls(const DissertationResults& res, const std::string& key, const std::string& case_name,
                              const std::string& x) {
  auto [r, c] = open_claim(res, key, {{"case", case_name}});
  if (!c) return r;
  Series s;
  for (const DissertationMember* m : c->in_case(case_name)) {
    std::string why;
    const auto data = res.member_data(*m, why);
    const double xv = parameter(*m, x), D = data ? marker(*data, "D_stop") : k_nan;
    if (!data) s.gaps.push_back(why);
    else if (std::isnan(xv) || std::isnan(D)) s.gaps.push_back(m->slug + ": no " + (std::isnan(xv) ? x : std::string("D_stop")));
    else s.points.push_back({xv, D, m});
  }
  std::sort(s.points.begin(), s.points.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
  if (!have_points(r, s, 3, "values of " + x + " with D_stop")) return r;
  std::string rise;
  for (std::size_t i = 1; i < s.points.size() && rise.empty(); ++i)
    if (!(s.points[i].y < s.points[i - 1].y)) rise = num(s.points[i - 1].x) + " -> " + num(s.points[i].x);
  set(r, rise.empty(),
      std::string(rise.empty() ? "falls at every step" : "does not fall from " + x + " " + rise) + " (first / last " +
          num(s.points.front().y / s.points.back().y) + "); D_xy at the stop: " + s.listing(x) + not_counted(s));
  return r;
}

// Sec. 3.3: "bending stiffness also decreases the time ... in addition to decreasing the extent of the
// capsule deformation, as was clear in Figures 2 and 8".
ClaimResult claim_3_3_deformation(const DissertationResults& res, const std::string& case_name) {
  return deformation_falls(res, "3.3 deformation", case_name, "E_b");
}

// Sec. 3.4: "the steady-state deformation of a capsule with small V is, ceteris paribus, much larger
// than a capsule with a larger V".
ClaimResult claim_3_4_deformation(const DissertationResults& res, const std::string& case_name) {
  return deformation_falls(res, "3.4 deformation", case_name, "V");
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter3_trends_claims() {
  return {per_case("3.2 response slows", claim_3_2_response_slows), per_case("3.3 deformation", claim_3_3_deformation),
          per_case("3.4 deformation", claim_3_4_deformation)};
}

}  // namespace capsule::analysis::claims
