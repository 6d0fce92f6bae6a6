// How much of a claim's gap a known cause closes: (with the cause - toolkit) / (text - toolkit),
// from the placeholders of deviations.md's Gap: lines filled from a campaign's fits, and on the
// shipped results every linked cause graded.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/rules.hpp"
#include "tests/analysis/dissertation_fixtures.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;
namespace fs = std::filesystem;

namespace {

CauseGrade graded(double toolkit, double with_cause, double text) {
  CauseGrade g;
  g.cause = 12;
  g.gap.claim = "3.1 R2", g.gap.quantity = "R^2", g.gap.text = text, g.gap.text_words = "\"> 0.99\"", g.gap.source = "probe p";
  g.measured = true, g.toolkit = toolkit, g.with_cause = with_cause, g.fraction = gap_fraction(toolkit, with_cause, text);
  return g;
}

}  // namespace

TEST_CASE("Cause grades: the share of the gap closed, its sign and its words", "[analysis][dissertation]") {
  CHECK(gap_fraction(0.9, 0.95, 1.0) == Approx(0.5));
  CHECK(gap_fraction(2.0, 1.5, 1.0) == Approx(0.5));   // from above the text as from below
  CHECK(gap_fraction(2.0, 2.5, 1.0) == Approx(-0.5));  // away from the text: negative
  CHECK(std::isnan(gap_fraction(1.0, 1.2, 1.0)));      // no gap
  CHECK(closes_text(graded(0.9, 0.95, 1.0)) == "closes 50 % of the gap");
  CHECK(closes_text(graded(2.0, 2.5, 1.0)) == "widens the gap (-50 %)");
  CHECK(closes_text(graded(2.0, 0.5, 1.0)) == "closes 150 % of the gap (past the text)");
  CHECK(closes_text(graded(1.0, 0.5, 1.0)) == "no gap to close");
  CHECK(closes_text(graded(0.9, 0.904, 1.0)) == "closes only 4 % of the gap");
  CHECK_FALSE(explains(graded(0.9, 0.904, 1.0)));  // under k_explains_share: the claim stays unexplained
  CHECK(explains(graded(0.9, 0.92, 1.0)));
  CHECK(closes_percent(graded(0.9, 0.95, 1.0)) == "50 %");
  CHECK(explains(graded(0.9, 0.95, 1.0)));
  CHECK_FALSE(explains(graded(2.0, 2.5, 1.0)));
  CHECK_FALSE(explains(graded(1.0, 0.5, 1.0)));
  CauseGrade missing = graded(0.9, 0.95, 1.0);
  missing.measured = false, missing.why = "campaign p not run";
  CHECK_FALSE(explains(missing));
  CHECK(closes_percent(missing) == "not measured");
  CHECK(grade_sentence(missing).find("(campaign p not run)") != std::string::npos);
  CHECK(grade_sentence(graded(0.9, 0.95, 0.99)) ==
        "closes 56 % of the gap in R^2: 0.9 -> 0.95 with the cause, the text 0.99 (\"> 0.99\"); probe p");
}

TEST_CASE("Cause grades: a Gap: side is one placeholder or two divided, filled from the fits", "[analysis][dissertation]") {
  TempDir tmp("dissertation_cause_grades");
  nlohmann::json members = nlohmann::json::array();
  for (const double Re : {0.05, 0.025})
    members.push_back(member_json("Re" + short_number(Re), "", {{"Re", Re}},
                                  {{"recovery", known_fit("recovery (86)", {{"k_tau_r", {10 * Re + 0.5, 0.01}}}, 0.97)},
                                   {"response", known_fit("response (85)", {{"k_tau_s", {0.5, 0.01}}}, 0.99)}}));
  write_fits(tmp.path, "probe", members);
  const DissertationResults results(tmp.path.string());
  const double toolkit = gap_side_value(results, "{fit probe/Re0.05/recovery.k_tau_r} / {fit probe/Re0.05/response.k_tau_s}");
  const double with_cause = gap_side_value(results, "{fit probe/Re0.025/recovery.k_tau_r} / {fit probe/Re0.025/response.k_tau_s}");
  CHECK(toolkit == Approx(2.0));     // 1.0 / 0.5
  CHECK(with_cause == Approx(1.5));  // 0.75 / 0.5
  CHECK(gap_fraction(toolkit, with_cause, 1.0) == Approx(0.5));
  CHECK(gap_side_value(results, "{r2 probe/Re0.05/recovery}") == Approx(0.97));
  CHECK_THROWS_WITH(gap_side_value(results, "fit probe/Re0.05/recovery.k_tau_r"), Catch::Contains("a Gap: side is"));
  CHECK_THROWS_WITH(gap_side_value(results, "{fit probe/Re1/recovery.k_tau_r}"), Catch::Contains("has no member Re1"));
  // Results without deviations.md's probes: every grade says what is missing, none is a number.
  for (const auto& g : grade_causes(results)) {
    INFO(g.gap.claim);
    CHECK_FALSE(g.measured);
    CHECK_FALSE(g.why.empty());
  }
}

TEST_CASE("Cause grades: every Gap: line of deviations.md is measured on the shipped results", "[analysis][dissertation]") {
  const DissertationResults results((fs::path(CAPSULE_SOURCE_DIR) / "results").string());
  const auto grades = grade_causes(results);
  std::size_t gaps = 0;
  for (const auto& d : known_deviations()) gaps += d.gaps.size();
  REQUIRE(grades.size() == gaps);
  REQUIRE(gaps >= 3);
  for (const auto& g : grades) {
    INFO(g.gap.claim << ": " << g.why);
    CHECK(g.measured);
    CHECK(std::isfinite(g.fraction));
    CHECK(g.toolkit != g.with_cause);  // a probe that does not move the quantity measures nothing
  }
}
