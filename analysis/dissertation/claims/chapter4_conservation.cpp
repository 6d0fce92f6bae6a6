// The claim of the dissertation's Sec. 4.2 on how well the 3D biconcave capsule keeps its surface
// area and volume over its shear and recovery, a rule with a stated numeric criterion
// (claims/support.hpp).
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

// Sec. 4.2.2, case A (after Fig. 47): "both the local surface area of the capsule and the capsule volume are
// nearly conserved, varying less than 2-3% from their undeformed values". The member files
// record the whole surface's drift: a bound the largest local drift is at least. The sentence names
// a cause of case A's incomplete recovery, so case A's members are judged; B and C are shown beside.
ClaimResult claim_4_2_drift(const DissertationResults& res) {
  auto [r, c] = open_claim(res, "4.2 drift");
  if (!c) return r;
  constexpr double bound = 0.03;
  Parts parts;
  std::size_t judged = 0;
  std::string beside;
  for (const DissertationMember* m : c->in_case("")) {
    std::string why;
    const auto data = res.member_data(*m, why, true);  // an unstable member's rows before the end count
    if (!data || !data->series.count("volume_drift") || !data->series.count("surface_drift")) {
      part_missing(parts.why, data ? m->slug + ": no volume_drift / surface_drift series" : why);
      continue;
    }
    const auto largest = [](const std::vector<double>& v) {
      double x = 0.0;
      for (double d : v) x = std::max(x, std::abs(d));
      return x;
    };
    const double volume = largest(data->series.at("volume_drift")), surface = largest(data->series.at("surface_drift"));
    const std::string numbers = m->slug + ": volume " + num(100 * volume) + " %, surface " + num(100 * surface) + " %";
    if (m->case_name.rfind("A", 0) != 0) {  // cases B and C: reported beside, not counted
      append_listed(beside, numbers);
      continue;
    }
    ++judged;
    parts.add(volume <= bound && surface <= bound, numbers);
  }
  if (judged == 0 && parts.why.empty()) part_missing(parts.why, "no member of case A");
  r = parts.finish(r);
  if (!beside.empty()) r.measured += " [beside, not counted: " + beside + "]";
  return r;
}

// This file's claims under their keys in claims.md, each with its rows (claims/registry.hpp).
ClaimList chapter4_conservation_claims() {
  return {once("4.2 drift", claim_4_2_drift)};
}

}  // namespace capsule::analysis::claims
