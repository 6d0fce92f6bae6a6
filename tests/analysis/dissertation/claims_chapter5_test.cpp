// The Sec. 5.1.1 claims on Table 2's bilinear fits (the keys 5.1.1 fit quality, 5.1.1 similar and
// 5.1.1 ratio trends of analysis/dissertation/claims.md), on synthetic fits.json files with known
// coefficients: each agrees on fits that satisfy its rule, differs on fits that contradict it, and
// cannot tell when an ensemble is missing.
#include <catch2/catch.hpp>

#include "analysis/dissertation/claims.hpp"
#include "tests/analysis/dissertation_fixtures.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;

namespace {

// One ensemble's two bilinear fits: k tau_s = a_s eta + b_s V + c, k tau_r = a_r eta + b_r V + c.
void write_ensemble(const TempDir& tmp, const std::string& campaign, double Ca, double E_b, double a_s, double b_s,
                    double r2_s, double a_r, double b_r, double r2_r) {
  const auto fit = [](double a, double b, double r2) {
    return known_fit("bilinear (95)-(96)", {{"a", {a, 0.1 * a}}, {"b", {b, 0.1 * b}}, {"c", {0.4, 0.05}}}, r2, 15);
  };
  write_fits(tmp.path, campaign, nlohmann::json::array(),
             nlohmann::json::array({bilinear_json("response.k_tau_s", Ca, E_b, fit(a_s, b_s, r2_s)),
                                    bilinear_json("recovery.k_tau_r", Ca, E_b, fit(a_r, b_r, r2_r))}));
}

std::vector<ClaimResult> judge(const TempDir& tmp) { return evaluate_claims(DissertationResults(tmp.path.string())); }

}  // namespace

TEST_CASE("Sec. 5.1.1 claims: bilinear fit quality, similar a_s and b_s, and the trends of b/a", "[analysis][dissertation]") {
  TempDir tmp("dissertation_claims_bilinear");
  SECTION("Table 2's own coefficients agree with all three") {
    // The text's Table 2: b_s/a_s 2.8 -> 3.5 -> 3.5, b_r/a_r 5 -> 4.6 -> 4.1; R^2 0.91 / 0.96 / 0.95 against > 0.99.
    write_ensemble(tmp, "ch5_bilinear_ca005", 0.05, 0.0, 0.0208, 0.0590, 0.91, 0.0534, 0.2711, 0.995);
    write_ensemble(tmp, "ch5_bilinear_ca005_eb", 0.05, 0.025, 0.0190, 0.0665, 0.96, 0.0500, 0.2300, 0.996);
    write_ensemble(tmp, "ch5_bilinear_ca02", 0.2, 0.0, 0.0500, 0.1750, 0.95, 0.1500, 0.6150, 0.993);
    const auto claims = judge(tmp);
    const auto& q = find_claim(claims, "5.1.1", "fits k tau_r very well");
    INFO(q.measured);
    CHECK(q.verdict == Verdict::agrees);
    const auto& s = find_claim(claims, "5.1.1", "surprisingly similar");
    INFO(s.measured);
    CHECK(s.verdict == Verdict::agrees);  // a_s -8.7 %, b_s +12.7 %
    const auto& t = find_claim(claims, "5.1.1", "b_s/a_s rises");
    INFO(t.measured);
    CHECK(t.verdict == Verdict::agrees);
    CHECK(t.measured.find("b_s/a_s 2.84 -> 3.5 at Ca 0.2") != std::string::npos);
    // Each quoted ratio lies inside b/a's interval (10 % half-widths on a and b: about 14 % on b/a).
    const auto& q6 = find_claim(claims, "5.1.1", "b_s/a_s ~ 2.8, 3.5, 3.5");
    INFO(q6.measured);
    CHECK(q6.verdict == Verdict::agrees);
  }
  SECTION("a poor k tau_r fit, a_s halved with bending, and b_s/a_s falling at Ca 0.2 differ") {
    write_ensemble(tmp, "ch5_bilinear_ca005", 0.05, 0.0, 0.0208, 0.0590, 0.91, 0.0534, 0.2711, 0.98);
    write_ensemble(tmp, "ch5_bilinear_ca005_eb", 0.05, 0.025, 0.0104, 0.0665, 0.96, 0.0500, 0.2300, 0.996);
    write_ensemble(tmp, "ch5_bilinear_ca02", 0.2, 0.0, 0.1000, 0.1500, 0.95, 0.1500, 0.6150, 0.993);
    const auto claims = judge(tmp);
    CHECK(find_claim(claims, "5.1.1", "fits k tau_r very well").verdict == Verdict::differs);
    CHECK(find_claim(claims, "5.1.1", "surprisingly similar").verdict == Verdict::differs);
    CHECK(find_claim(claims, "5.1.1", "b_s/a_s rises").verdict == Verdict::differs);
    CHECK(find_claim(claims, "5.1.1", "b_s/a_s ~ 2.8, 3.5, 3.5").verdict == Verdict::differs);  // 6.4 +- 0.9 against 3.5
  }
  SECTION("the Ca = 0.2 ensemble not run: the two claims that need it cannot tell") {
    write_ensemble(tmp, "ch5_bilinear_ca005", 0.05, 0.0, 0.0208, 0.0590, 0.91, 0.0534, 0.2711, 0.995);
    write_ensemble(tmp, "ch5_bilinear_ca005_eb", 0.05, 0.025, 0.0190, 0.0665, 0.96, 0.0500, 0.2300, 0.996);
    const auto claims = judge(tmp);
    CHECK(find_claim(claims, "5.1.1", "fits k tau_r very well").verdict == Verdict::cannot_tell);
    CHECK(find_claim(claims, "5.1.1", "b_s/a_s rises").verdict == Verdict::cannot_tell);
    CHECK(find_claim(claims, "5.1.1", "surprisingly similar").verdict == Verdict::agrees);
    CHECK(find_claim(claims, "5.1.1", "b_s/a_s ~ 2.8, 3.5, 3.5").verdict == Verdict::cannot_tell);
  }
}

TEST_CASE("Sec. 5.1.1-5.1.3 claims: each row's R^2 of k tau_s, and b/a different for the two times", "[analysis][dissertation]") {
  TempDir tmp("dissertation_claims_bilinear_rows");
  // b_s/a_s = 3 and b_r/a_r = 5 (each +- 14 %: 10 % half-widths on a and b) unless given.
  const auto write = [&](double r2_base, double ratio_r_large_Ca, bool large_Ca = true) {
    write_ensemble(tmp, "ch5_bilinear_ca005", 0.05, 0.0, 0.02, 0.06, r2_base, 0.05, 0.25, 0.995);
    write_ensemble(tmp, "ch5_bilinear_ca005_eb", 0.05, 0.025, 0.02, 0.06, 0.95, 0.03, 0.15, 0.996);
    if (large_Ca) write_ensemble(tmp, "ch5_bilinear_ca02", 0.2, 0.0, 0.05, 0.15, 0.96, 0.2, 0.2 * ratio_r_large_Ca, 0.993);
    return judge(tmp);
  };
  SECTION("R^2 0.92 / 0.95 / 0.96 and ratios 3 against 5: agrees") {
    const auto claims = write(0.92, 5.0);
    const auto& rows = find_claim(claims, "5.1.1", "R^2 ~ 0.91");
    INFO(rows.measured);
    CHECK(rows.verdict == Verdict::agrees);
    CHECK(rows.measured.find("Ca 0.05, E_b 0: R^2 of k tau_s 0.92 against ~ 0.91") != std::string::npos);
    const auto& d = find_claim(claims, "5.1.3", "differs for tau_s and tau_r");
    INFO(d.measured);
    CHECK(d.verdict == Verdict::agrees);
  }
  SECTION("R^2 0.8 for the base, and b_r/a_r = 3.2 beside b_s/a_s = 3 at Ca 0.2: differs") {
    const auto claims = write(0.8, 3.2);
    CHECK(find_claim(claims, "5.1.1", "R^2 ~ 0.91").verdict == Verdict::differs);
    const auto& d = find_claim(claims, "5.1.3", "differs for tau_s and tau_r");
    INFO(d.measured);
    CHECK(d.verdict == Verdict::differs);
  }
  SECTION("the Ca = 0.2 ensemble not run cannot tell") {
    const auto claims = write(0.92, 5.0, false);
    CHECK(find_claim(claims, "5.1.1", "R^2 ~ 0.91").verdict == Verdict::cannot_tell);
    CHECK(find_claim(claims, "5.1.3", "differs for tau_s and tau_r").verdict == Verdict::cannot_tell);
  }
}
