// THESIS.md's third column (analysis/dissertation/emulation.hpp) on synthetic results: a claim that
// differs is reproduced at the text's settings (the text's numerics), still differs there (the
// model), or its emulation campaign is not shipped (not run).
#include <catch2/catch.hpp>

#include "analysis/dissertation/emulation.hpp"
#include "analysis/dissertation/report.hpp"
#include "tests/analysis/dissertation_fixtures.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;

namespace {

// ch3_ca's case 2d (or its emulation) with k tau_r = time(Ca) at four Ca.
void write_ch3_ca(const TempDir& tmp, const std::string& campaign, double (*time)(double)) {
  nlohmann::json members = nlohmann::json::array();
  for (const double ca : {0.05, 0.1, 0.2, 0.4})
    members.push_back(member_json("Ca" + std::to_string(ca), "2d", {{"Ca", ca}, {"E_b", 0.05}, {"V", 1.0}, {"eta", 0.0}},
                                  {{"recovery", known_fit("recovery (86)", {{"k_tau_r", {time(ca), 0.01}}})}}));
  write_fits(tmp.path, campaign, members, nlohmann::json::array(), nlohmann::json({{"fits", {"recovery"}}}));
}

double proportional(double ca) { return 10.0 * ca; }
double flat(double) { return 0.5; }

const EmulationRow* proportional_2d(const std::vector<EmulationRow>& rows) {
  for (const auto& r : rows)
    if (r.toolkit.section == "3.2" && r.toolkit.statement.find("almost directly proportional to Ca (2d)") != std::string::npos)
      return &r;
  return nullptr;
}

std::vector<EmulationRow> third_column(const TempDir& tmp) {
  const DissertationResults toolkit(tmp.path.string());
  const DissertationResults emulated(tmp.path.string(), 0, k_emulation_prefix);
  std::vector<std::string> shipped;
  if (emulated.campaign("ch3_ca").found) shipped.push_back("ch3_ca");
  return emulation_rows(evaluate_claims_at_two_levels(toolkit), evaluate_claims(emulated), shipped);
}

}  // namespace

TEST_CASE("Third column: a claim that differs beside the toolkit at the text's settings", "[analysis][dissertation]") {
  TempDir tmp("dissertation_emulation");
  write_ch3_ca(tmp, "ch3_ca", flat);  // the toolkit: k tau_r flat in Ca, the claim differs

  SECTION("reproduced at the text's settings: the text's numerics") {
    write_ch3_ca(tmp, "emulation_ch3_ca", proportional);
    const auto rows = third_column(tmp);
    const EmulationRow* r = proportional_2d(rows);
    REQUIRE(r);
    CHECK(r->toolkit.verdict == Verdict::differs);
    CHECK(r->emulated.verdict == Verdict::agrees);
    CHECK(r->reason == EmulationReason::text_numerics);
    CHECK(r->sentence.find("the difference is the text's numerics") != std::string::npos);
    CHECK(count_emulation(rows).text_numerics >= 1);
  }
  SECTION("not reproduced at the text's settings: the model") {
    write_ch3_ca(tmp, "emulation_ch3_ca", flat);
    const EmulationRow* r = proportional_2d(third_column(tmp));
    REQUIRE(r);
    CHECK(r->emulated.verdict == Verdict::differs);
    CHECK(r->reason == EmulationReason::model);
    CHECK(r->sentence.find("still differs") != std::string::npos);
  }
  SECTION("no emulation campaign shipped: not run") {
    const auto rows = third_column(tmp);
    const EmulationRow* r = proportional_2d(rows);
    REQUIRE(r);
    CHECK(r->reason == EmulationReason::not_run);
    CHECK(r->emulated.measured.find("emulation_ch3_ca not run") != std::string::npos);
    // Only rows that differ get a third column, and every one of them is counted.
    for (const auto& row : rows) CHECK(row.toolkit.verdict == Verdict::differs);
    const EmulationCounts c = count_emulation(rows);
    CHECK(c.not_run == static_cast<int>(claim_emulation_reasons(rows).size()));
    CHECK(c.text_numerics + c.model + c.cannot_tell == 0);
  }
}

TEST_CASE("Third column: THESIS.md counts the reasons on its first screen and lists each row", "[analysis][dissertation]") {
  TempDir tmp("dissertation_emulation_document");
  write_ch3_ca(tmp, "ch3_ca", flat);
  write_ch3_ca(tmp, "emulation_ch3_ca", proportional);
  DissertationSummary s;
  const std::string md = dissertation_markdown(DissertationResults(tmp.path.string()), "results", &s);
  CHECK(s.emulation_text_numerics >= 1);
  const std::size_t section = md.find("## The dissertation's numerics");
  REQUIRE(section != std::string::npos);
  const std::size_t count_line = md.find("run again at the text's own settings");
  CHECK(count_line < section);  // on the first screen, before the section
  CHECK(md.find("| claim | the text | at the text's settings | the toolkit converged | reason |") != std::string::npos);
  CHECK(md.find("| Table 2 row | coefficient | the text | at the text's settings | the toolkit (finest level) |") !=
        std::string::npos);
  // No switch campaign shipped: no table of switched items.
  CHECK(md.find("Which item moves a claim") == std::string::npos);
}

TEST_CASE("Third column: an item switched back to the toolkit's value, one at a time", "[analysis][dissertation]") {
  TempDir tmp("dissertation_emulation_switch");
  write_ch3_ca(tmp, "ch3_ca", flat);
  write_ch3_ca(tmp, "emulation_ch3_ca", proportional);     // the text's numbers come back at its settings
  write_ch3_ca(tmp, "emulation_kernel_ch3_ca", flat);      // and go away with Peskin's kernel
  const DissertationResults toolkit(tmp.path.string());
  auto rows = emulation_rows(evaluate_claims_at_two_levels(toolkit),
                             evaluate_claims(DissertationResults(tmp.path.string(), 0, k_emulation_prefix)), {"ch3_ca"});
  for (const auto& sw : emulation_switches())
    attach_switch(rows, evaluate_claims(DissertationResults(tmp.path.string(), 0, std::string(k_emulation_prefix) + sw.label + "_")));
  const EmulationRow* r = proportional_2d(rows);
  REQUIRE(r);
  REQUIRE(r->switched.size() == emulation_switches().size());
  for (std::size_t k = 0; k < r->switched.size(); ++k) {
    INFO(emulation_switches()[k].label);
    if (emulation_switches()[k].label == "kernel") CHECK(r->switched[k].verdict == Verdict::differs);
    else CHECK(r->switched[k].measured.find("not run") != std::string::npos);
  }
  const std::string md = dissertation_markdown(toolkit, "results");
  CHECK(md.find("Which item moves a claim") != std::string::npos);
  CHECK(md.find("with resolution.kernel = peskin4") != std::string::npos);
  CHECK_THROWS_AS(attach_switch(rows, {}), std::logic_error);
}

TEST_CASE("Third column: the toolkit's and the emulated rows must be the same rules in the same order", "[analysis][dissertation]") {
  ClaimResult a, b;
  a.key = "3.2 proportional";
  b.key = "3.3 slight";
  CHECK_THROWS_AS(emulation_rows({a}, {b}, {}), std::logic_error);
  CHECK_THROWS_AS(emulation_rows({a}, {}, {}), std::logic_error);
}
