// The claims of the dissertation's Secs. 5.2.1-5.2.2 on the shape of the power-law capsule's D_xy
// over time: a settled ellipsoid in shear, the same initial deformation as Kelvin-Voigt in
// oscillatory shear; each a rule with a stated numeric criterion (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/claims/support.hpp"
#include "analysis/dissertation/document_links.hpp"

namespace capsule::analysis::claims {

namespace {

// The largest D_xy of a member between kt from and to, and when.
struct Peak {
  double D = -std::numeric_limits<double>::infinity(), kt = k_nan;
};
Peak peak_between(const io::MemberData& d, double from, double to) {
  Peak p;
  const auto& kt = d.series.at("kt");
  const auto& D = d.series.at("D_xy");
  for (std::size_t i = 0; i < kt.size() && i < D.size(); ++i)
    if (kt[i] >= from - 1e-9 && kt[i] < to - 1e-9 && D[i] > p.D) p.D = D[i], p.kt = kt[i];
  return p;
}

// One member of each case of ch5_oscillatory (the finest level), or why not.
std::vector<ShearMember> oscillatory_members(const DissertationResults& res, const DissertationCampaign& c, std::string& why) {
  std::vector<ShearMember> out;
  for (const char* name : {"kv", "powerlaw_n1", "powerlaw_n064"}) {
    auto ms = shear_members(res, c, name, why);
    if (ms.empty()) part_missing(why, std::string("no case ") + name + " member with a member file");
    else out.push_back(std::move(ms.front()));
  }
  return out;
}

}  // namespace

// Sec. 5.2.1: "The spherical capsule is deformed to an (eventually) stable ellipsoidal shape,
// described by an approximately constant D_xy."
ClaimResult claim_5_2_settled(const DissertationResults& res) {
  constexpr double bound = 0.01;  // the bound "4.2 C steady" takes for a D_xy without swing
  auto [r, c] = open_claim(res, "5.2.1 settled", {{"bound", num(bound)}});
  if (!c) return r;
  std::string why;
  const auto ms = shear_members(res, *c, "n", why);
  if (ms.size() < 3) {
    r.measured = "cannot tell (members missing): " + std::to_string(ms.size()) + " members of case n, need 3" +
                 (why.empty() ? std::string("") : " (" + why + ")");
    return r;
  }
  Parts parts;
  for (const auto& m : ms) {
    const auto& kt = m.data->series.at("kt");
    const auto& D = m.data->series.at("D_xy");
    const double t_stop = std::isfinite(marker(*m.data, "t_stop")) ? marker(*m.data, "t_stop") : kt.back();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < kt.size() && i < D.size(); ++i)
      if (kt[i] >= 0.75 * t_stop && kt[i] <= t_stop) lo = std::min(lo, D[i]), hi = std::max(hi, D[i]);
    parts.add(hi - lo <= bound, "n " + num(scene_value(*m.data, "/power_law/n")) + ": D_xy " + num(lo) + " to " + num(hi) +
                                    " over kt " + num(0.75 * t_stop) + "-" + num(t_stop));
  }
  return parts.finish(r);
}

// Sec. 5.2.2: "Once again, the initial deformation measured by the Taylor deformation parameter agrees
// very well for all three capsules."
ClaimResult claim_5_2_2_initial(const DissertationResults& res) {
  constexpr double bound = 0.1;  // the bound "5.2.1 initial" takes for "nearly identical"
  auto [r, c] = open_claim(res, "5.2.2 initial", {{"bound", num(bound)}});
  if (!c) return r;
  std::string why;
  const auto ms = oscillatory_members(res, *c, why);
  if (ms.size() < 3) {
    r.measured = "cannot tell (members missing): " + why;
    return r;
  }
  std::vector<double> first;
  std::string text;
  for (const auto& m : ms) {
    const double T = scene_value(*m.data, "/protocol/shear/oscillatory_period_kt");
    first.push_back(peak_between(*m.data, 0.0, T).D);
    append_listed(text, m.member->case_name + " " + num(first.back()));
  }
  const double spread = relative_spread(first);
  set(r, spread <= bound, "peak D_xy in the first period: " + text + "; spread " + num(spread));
  return r;
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter5_shapes_claims() {
  return {once("5.2.1 settled", claim_5_2_settled), once("5.2.2 initial", claim_5_2_2_initial)};
}

}  // namespace capsule::analysis::claims
