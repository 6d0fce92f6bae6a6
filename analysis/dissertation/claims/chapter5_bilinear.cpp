// The claims of the dissertation's Sec. 5.1.1 on the bilinear models (95)-(96) of Table 2: how well
// they fit, and how their coefficients move with E_b and Ca, each a rule with a stated numeric
// criterion (claims/support.hpp). Table 2's numbers themselves are compared in table2.cpp.
#include "analysis/compare/bilinear_entries.hpp"
#include "analysis/dissertation/table2.hpp"
#include "analysis/dissertation/claims/chapters.hpp"
#include "analysis/dissertation/claims/support.hpp"

namespace capsule::analysis::claims {

namespace {

// Table 2's three ensembles: the base (Ca 0.05, E_b 0), with bending, at the larger Ca.
const char* const k_base = "ch5_bilinear_ca005";
const char* const k_bending = "ch5_bilinear_ca005_eb";
const char* const k_large_Ca = "ch5_bilinear_ca02";
const char* const k_times[] = {"response.k_tau_s", "recovery.k_tau_r"};

// The finest-level bilinear fit of one time in one campaign; null, with why, when the campaign
// was not run or the fit failed.
const FitResult* bilinear_fit(const DissertationResults& res, const std::string& campaign, const std::string& target,
                              std::vector<BilinearEntry>& keep, std::string& why) {
  const DissertationCampaign& c = res.campaign(campaign);
  if (!c.found) {
    why = c.missing;
    return nullptr;
  }
  keep = read_bilinear_entries(campaign, c.fits);
  for (const BilinearEntry& e : keep)
    if (e.target == target) {
      if (e.fit.ok) return &e.fit;
      why = campaign + ": the bilinear fit of " + bare_time(target) + " failed: " + e.fit.reason;
      return nullptr;
    }
  why = campaign + ": no bilinear fit of " + bare_time(target);
  return nullptr;
}

// The coefficients (a, b) and R^2 of one time's fit in each campaign, or why not.
struct Coefficients {
  double a = k_nan, b = k_nan, r_squared = k_nan;
};
bool coefficients(const DissertationResults& res, const std::vector<std::string>& campaigns, const std::string& target,
                  std::map<std::string, Coefficients>& out, std::string& why) {
  for (const auto& campaign : campaigns) {
    std::vector<BilinearEntry> entries;
    const FitResult* f = bilinear_fit(res, campaign, target, entries, why);
    if (!f || !f->parameter("a") || !f->parameter("b")) {
      if (why.empty()) why = campaign + ": the bilinear fit has no a / b";
      return false;
    }
    out[campaign] = {f->parameter("a")->value, f->parameter("b")->value, f->r_squared};
  }
  return true;
}

}  // namespace

// Sec. 5.1.1: "The coefficients a_s and b_s for k tau_s and both ensembles with Ca = 0.05 are
// surprisingly similar, suggesting that their dependence on E_b may be small."
ClaimResult claim_5_1_1_similar(const DissertationResults& res) {
  ClaimResult r = claim("5.1.1 similar");
  std::map<std::string, Coefficients> k;
  std::string why;
  if (!coefficients(res, {k_base, k_bending}, "response.k_tau_s", k, why)) {
    r.measured = "cannot tell: " + why;
    return r;
  }
  const double da = k[k_bending].a / k[k_base].a - 1.0, db = k[k_bending].b / k[k_base].b - 1.0;
  set(r, std::abs(da) <= 0.2 && std::abs(db) <= 0.2,
      "a_s " + num(k[k_base].a) + " -> " + num(k[k_bending].a) + " (" + num(100 * da) + " %), b_s " + num(k[k_base].b) +
          " -> " + num(k[k_bending].b) + " (" + num(100 * db) + " %)");
  return r;
}

// Sec. 5.1.1: "Starting from the base ensemble ... b_s/a_s ~ 2.8, the ratio of response coefficients
// increases to b_s/a_s ~ 3.5 with the both addition of bending stiffness E_b = 0.025 and the higher
// capillary number Ca = 0.2. Conversely, the ratio b_r/a_r ~ 5 ... decreases to ~ 4.6 with ... bending
// stiffness ... and falls to ~ 4.1 at the higher capillary number".
ClaimResult claim_5_1_1_ratio_trends(const DissertationResults& res) {
  ClaimResult r = claim("5.1.1 ratio trends");
  Parts parts;
  for (const char* target : k_times) {
    std::map<std::string, Coefficients> k;
    std::string why;
    if (!coefficients(res, {k_base, k_bending, k_large_Ca}, target, k, why)) {
      part_missing(parts.why, why);
      continue;
    }
    const bool response = std::string(target) == "response.k_tau_s";
    const std::string name = response ? "b_s/a_s" : "b_r/a_r";
    const auto ratio = [&](const char* campaign) { return k[campaign].b / k[campaign].a; };
    for (const char* other : {k_bending, k_large_Ca}) {
      const bool rises = ratio(other) > ratio(k_base);
      parts.add(rises == response, name + " " + num(ratio(k_base)) + " -> " + num(ratio(other)) +
                                       (other == k_bending ? " with E_b 0.025" : " at Ca 0.2"));
    }
  }
  return parts.finish(r);
}

// Sec. 5.1.1: "The model fit very well for k tau_r, with a correlation coefficient R^2 > 0.99 for all
// three cases. The model fit more poorly for k tau_s, with R^2 ~ 0.91 ..., ~ 0.96 ... and ~ 0.95".
ClaimResult claim_5_1_1_fit_quality(const DissertationResults& res) {
  ClaimResult r = claim("5.1.1 fit quality");
  Parts parts;
  std::map<std::string, Coefficients> s, t;
  std::string why;
  if (!coefficients(res, {k_base, k_bending, k_large_Ca}, "response.k_tau_s", s, why) ||
      !coefficients(res, {k_base, k_bending, k_large_Ca}, "recovery.k_tau_r", t, why)) {
    r.measured = "cannot tell: " + why;
    return r;
  }
  for (const char* campaign : {k_base, k_bending, k_large_Ca})
    parts.add(t[campaign].r_squared > 0.99 && s[campaign].r_squared < t[campaign].r_squared,
              std::string(campaign) + ": R^2 k tau_r " + num(t[campaign].r_squared) + ", k tau_s " + num(s[campaign].r_squared));
  return parts.finish(r);
}

// Sec. 5.1.1: "b_s/a_s ~ 2.8 ... increases to b_s/a_s ~ 3.5 ... b_r/a_r ~ 5 ... ~ 4.6 ... ~ 4.1" (the
// ratios the text quotes, each a number the toolkit's b/a and its 95 % interval can hold or not).
ClaimResult claim_5_1_1_ratios(const DissertationResults& res) {
  ClaimResult r = claim("5.1.1 ratios");
  Parts parts;
  for (const auto& row : compare_table2_rows(res)) {
    if (!row.ensemble) continue;
    const bool response = row.reference->target == "k_tau_s";
    const std::string name = std::string(response ? "b_s/a_s" : "b_r/a_r") + " at Ca " + num(row.ensemble->Ca) + ", E_b " +
                             num(row.ensemble->E_b);
    const double quoted = response ? row.ensemble->text_ratio_response : row.ensemble->text_ratio_recovery;
    if (!row.found) {
      part_missing(parts.why, name + ": " + row.why);
      continue;
    }
    const RatioInterval mine = ratio_b_over_a_interval(row.entry.fit);
    if (!mine.ok) {
      part_missing(parts.why, name + ": " + mine.why);
      continue;
    }
    parts.add(std::abs(mine.value - quoted) <= mine.half_width,
              name + ": text ~ " + num(quoted) + ", toolkit " + short_plus_minus(mine.value, mine.half_width));
  }
  return parts.finish(r);
}

// Sec. 5.1.1: "The model fit more poorly for k tau_s, with R^2 ~ 0.91 for Ca = 0.05 and E_b = 0,
// R^2 ~ 0.96 for Ca = 0.05 and E_b = 0.025, and R^2 ~ 0.95 for Ca = 0.2 and E_b = 0" (each row's
// own number, beside 5.1.1 fit quality's ordering of the two times).
ClaimResult claim_5_1_1_r2_rows(const DissertationResults& res) {
  ClaimResult r = claim("5.1.1 R2 rows");
  Parts parts;
  for (const auto& row : compare_table2_rows(res)) {
    if (!row.ensemble || row.reference->target != "k_tau_s") continue;
    const std::string name = "Ca " + num(row.ensemble->Ca) + ", E_b " + num(row.ensemble->E_b);
    if (!row.found || !row.entry.fit.ok) {
      part_missing(parts.why, name + ": " + (row.found ? row.entry.fit.reason : row.why));
      continue;
    }
    const double quoted = std::stod(row.ensemble->text_r2_response), mine = row.entry.fit.r_squared;
    parts.add(std::abs(mine - quoted) <= 0.02, name + ": R^2 of k tau_s " + num(mine) + " against the text's ~ " +
                                                   row.ensemble->text_r2_response);
  }
  return parts.finish(r);
}

// Sec. 5.1.3: "the ratio of the a and b coefficients differs for tau_s and tau_r. As a result, one
// could not accurately simulate both response and recovery phases with the same ratio in one model."
ClaimResult claim_5_1_3_ratios_differ(const DissertationResults& res) {
  ClaimResult r = claim("5.1.3 ratios differ");
  std::map<std::string, std::map<std::string, RatioInterval>> ratios;  // campaign -> target -> b/a
  std::vector<std::string> order;
  Parts parts;
  for (const auto& row : compare_table2_rows(res)) {
    if (!row.ensemble) continue;
    const std::string& campaign = row.ensemble->campaign;
    if (std::find(order.begin(), order.end(), campaign) == order.end()) order.push_back(campaign);
    const std::string name = campaign + " b/a of " + row.reference->target;
    if (!row.found) {
      part_missing(parts.why, name + ": " + row.why);
      continue;
    }
    const RatioInterval mine = ratio_b_over_a_interval(row.entry.fit);
    if (!mine.ok) part_missing(parts.why, name + ": " + mine.why);
    else ratios[campaign][row.reference->target] = mine;
  }
  for (const std::string& campaign : order) {
    const auto& k = ratios[campaign];
    if (!k.count("k_tau_s") || !k.count("k_tau_r")) continue;  // the reason is in parts.why
    const RatioInterval &s = k.at("k_tau_s"), &t = k.at("k_tau_r");
    const double difference = t.value - s.value, half_width = std::hypot(s.half_width, t.half_width);
    parts.add(std::abs(difference) > half_width, campaign + ": b_s/a_s " + short_plus_minus(s.value, s.half_width) + ", b_r/a_r " +
                                                     short_plus_minus(t.value, t.half_width) + ", difference " + num(difference) +
                                                     " (95 % half-width " + num(half_width) + ")");
  }
  return parts.finish(r);
}

}  // namespace capsule::analysis::claims
