// THESIS.md's convergence policy (every claim judged at the two finest levels of its campaigns'
// resolution ladders) on a synthetic two-level ladder, and the column "the text passes its rule":
// the rules re-read from the text (5.1.1 similar, 5.1.3 ratios differ) on the text's own Table 2 and
// on numbers that fail them.
#include <catch2/catch.hpp>

#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/claims/bilinear_rules.hpp"
#include "tests/analysis/dissertation_fixtures.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;

namespace {

const std::vector<double> k_ca{0.05, 0.1, 0.2, 0.4};

// ch3_ca, case 2d, on a resolution.a ladder: k tau_r = fine(Ca) at a = 7 and coarse(Ca) at a = 5.
void write_ladder(const TempDir& tmp, double (*fine)(double), double (*coarse)(double), bool ladder = true) {
  nlohmann::json members = nlohmann::json::array();
  for (double ca : k_ca)
    for (const double a : {7.0, 5.0}) {
      if (!ladder && a == 5.0) continue;
      const double k_tau_r = a == 7.0 ? fine(ca) : coarse(ca);
      members.push_back(member_json("2d-Ca" + std::to_string(ca) + "-a" + std::to_string(int(a)), "2d",
                                    {{"Ca", ca}, {"E_b", 0.05}, {"V", 1.0}, {"eta", 0.0}, {"resolution.a", a}},
                                    {{"recovery", known_fit("recovery (86)", {{"k_tau_r", {k_tau_r, 0.01}}})}}));
    }
  const nlohmann::json analysis{{"fits", {"recovery"}},
                                {"ladder", {{{"key", "resolution.a"}, {"quantities", {"recovery.k_tau_r"}}}}}};
  write_fits(tmp.path, "ch3_ca", members, nlohmann::json::array(), ladder ? analysis : nlohmann::json());
}

double proportional(double ca) { return 10.0 * ca; }
double flat(double) { return 0.5; }

const ClaimResult& proportional_2d(const std::vector<ClaimResult>& rows) {
  return find_claim(rows, "3.2", "almost directly proportional to Ca (2d)");
}

}  // namespace

TEST_CASE("Convergence policy: a claim holds only where the two finest levels of the ladder give the same verdict", "[analysis][dissertation]") {
  TempDir tmp("dissertation_claims_levels");
  SECTION("the next coarser level is what level 1 reads") {
    write_ladder(tmp, proportional, flat);
    for (const DissertationMember* m : DissertationResults(tmp.path.string(), 1).campaign("ch3_ca").in_case("2d"))
      CHECK(m->parameters.at("resolution.a") == 5.0);
    for (const DissertationMember* m : DissertationResults(tmp.path.string()).campaign("ch3_ca").in_case("2d"))
      CHECK(m->parameters.at("resolution.a") == 7.0);
    CHECK(DissertationResults(tmp.path.string()).campaign("ch3_ca").several_levels);
  }
  SECTION("both levels agree: agrees, converged") {
    write_ladder(tmp, proportional, proportional);
    const auto rows = evaluate_claims_at_two_levels(DissertationResults(tmp.path.string()));
    const auto& r = proportional_2d(rows);
    INFO(r.measured);
    CHECK(r.verdict == Verdict::agrees);
    CHECK(r.levels == Levels::converged);
    CHECK(r.coarse_measured.rfind("agrees: p = 1", 0) == 0);
  }
  SECTION("both levels differ: differs, converged") {
    write_ladder(tmp, flat, flat);
    const auto rows = evaluate_claims_at_two_levels(DissertationResults(tmp.path.string()));
    const auto& r = proportional_2d(rows);
    CHECK(r.verdict == Verdict::differs);
    CHECK(r.levels == Levels::converged);
  }
  SECTION("the levels disagree: cannot tell, not converged, with both levels' numbers") {
    write_ladder(tmp, proportional, flat);
    const auto rows = evaluate_claims_at_two_levels(DissertationResults(tmp.path.string()));
    const auto& r = proportional_2d(rows);
    INFO(r.measured);
    CHECK(r.verdict == Verdict::cannot_tell);
    CHECK(r.levels == Levels::not_converged);
    CHECK(r.measured.find("not converged (finest level agrees, next coarser level differs)") != std::string::npos);
    CHECK(r.measured.find("finest: p = 1") != std::string::npos);
    CHECK(r.measured.find("next coarser: p = 0") != std::string::npos);
  }
  SECTION("a campaign shipped at one level keeps its verdict and says so") {
    write_ladder(tmp, proportional, flat, false);
    const auto rows = evaluate_claims_at_two_levels(DissertationResults(tmp.path.string()));
    const auto& r = proportional_2d(rows);
    CHECK(r.verdict == Verdict::agrees);
    CHECK(r.levels == Levels::one_level);
    CHECK(r.coarse_measured.empty());
  }
  SECTION("rows that do not match are an error") {
    ClaimResult a, b;
    a.key = "x", b.key = "y";
    CHECK_THROWS_AS(combine_levels({a}, {b}), std::logic_error);
    CHECK_THROWS_AS(combine_levels({a}, {}), std::logic_error);
  }
}

TEST_CASE("Convergence policy: level 1 reads each target's next coarser bilinear fit", "[analysis][dissertation]") {
  DissertationCampaign c;
  const auto entry = [](const std::string& target, double a) {
    return nlohmann::json{{"case", ""}, {"target", target}, {"level", {{"key", "resolution.a"}, {"value", a}}}};
  };
  c.fits["bilinear"] = nlohmann::json::array({entry("response.k_tau_s", 7), entry("recovery.k_tau_r", 7),
                                              entry("response.k_tau_s", 5), entry("recovery.k_tau_r", 5)});
  DissertationCampaign finest = c;
  judge_bilinear_at_level(finest, 0);
  CHECK(finest.fits["bilinear"].size() == 4);
  CHECK(finest.several_levels);
  judge_bilinear_at_level(c, 1);
  REQUIRE(c.fits["bilinear"].size() == 2);
  for (const auto& e : c.fits["bilinear"]) CHECK(e["level"]["value"] == 5);
}

TEST_CASE("The text passes its rule: the re-read Table 2 rules on the text's numbers and on numbers that fail them", "[analysis][dissertation]") {
  using namespace capsule::analysis::claims;
  // Table 2: a_s 0.0208 +- 0.0039 (E_b 0) against 0.0157 +- 0.0039 (E_b 0.025): -24.5 %, inside the intervals.
  CHECK(similar_coefficient("a_s", {0.0208, 0.0039}, {0.0157, 0.0039}).holds);
  CHECK(similar_coefficient("b_s", {0.0590, 0.0149}, {0.0550, 0.0158}).holds);
  // The same change with intervals a quarter as wide is resolved: not similar.
  const RuleOutcome resolved = similar_coefficient("a_s", {0.0208, 0.001}, {0.0157, 0.001});
  CHECK_FALSE(resolved.holds);
  CHECK(resolved.numbers == "a_s 0.0208 ± 0.001 -> 0.0157 ± 0.001 (difference -0.0051, 95 % half-width 0.00141)");
  // The text's point ratios differ by more than 10 % of the larger (3.5 against 4.1: 0.6 > 0.41); 3.9 against 4.1 does not.
  CHECK(ratios_differ("Ca 0.2", 3.5, 4.1).holds);
  CHECK_FALSE(ratios_differ("Ca 0.2", 3.9, 4.1).holds);

  TempDir tmp("dissertation_claims_text_passes");
  const auto rows = evaluate_claims(DissertationResults(tmp.path.string()));  // no campaign: the text's numbers alone
  CHECK(find_claim(rows, "5.1.1", "surprisingly similar").text_passes == TextPasses::yes);
  CHECK(find_claim(rows, "5.1.3", "differs for tau_s and tau_r").text_passes == TextPasses::yes);
  CHECK(find_claim(rows, "5.1.1", "b_s/a_s ~ 2.8, 3.5, 3.5").text_passes == TextPasses::yes);
  CHECK(find_claim(rows, "5.1.1", "b_s/a_s rises").text_passes == TextPasses::yes);
  CHECK(find_claim(rows, "5.2.2", "factor 6-8").text_passes == TextPasses::yes);
  CHECK(find_claim(rows, "3.2", "proportional to Ca (2d)").text_passes == TextPasses::no_numbers);
  const auto& ratios = find_claim(rows, "5.1.3", "differs for tau_s and tau_r");
  CHECK(ratios.text_numbers.find("ch5_bilinear_ca02: b_s/a_s 3.51, b_r/a_r 4.15") != std::string::npos);
  // No rule fails the text's own numbers.
  for (const auto& [key, t] : claim_text_passes(rows)) {
    INFO(key);
    CHECK(t != TextPasses::no);
  }
}

TEST_CASE("The text passes its rule: one answer per claim from its rows", "[analysis][dissertation]") {
  std::vector<ClaimResult> rows(5);
  rows[0].key = rows[1].key = "a";
  rows[0].text_passes = TextPasses::yes, rows[1].text_passes = TextPasses::no;
  rows[2].key = "b", rows[2].text_passes = TextPasses::yes;
  rows[3].key = rows[4].key = "c";
  const auto t = claim_text_passes(rows);
  REQUIRE(t.size() == 3);
  CHECK(t[0].second == TextPasses::no);
  CHECK(t[1].second == TextPasses::yes);
  CHECK(t[2].second == TextPasses::no_numbers);
  CHECK(std::string(text_passes_text(TextPasses::no_numbers)) == "no numbers");
}
