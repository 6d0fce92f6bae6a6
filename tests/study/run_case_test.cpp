// `study run --case NAME`: only that case's members run (the 2D case of a campaign with 2D and
// 3D cases, say); a name that is no case is refused before anything is written.
#include <catch2/catch.hpp>

#include "study/campaign_survey.hpp"
#include "tests/study/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study run --case runs only that case's members; an unknown case is refused", "[study]") {
  const fs::path dir = testing::scratch_dir("run_case");
  nlohmann::json doc = testing::tiny_campaign("cases", {0.01, 0.02}, 0.5, 0);
  doc["cases"] = nlohmann::json::array({{{"name", "flat"}, {"set", {{"E_b", 0.0}}}},
                                        {{"name", "stiff"}, {"set", {{"E_b", 0.1}}}}});
  testing::write_text(dir / "c.json", doc.dump(2));

  const auto bad = testing::run_study({"run", "c.json", "--case", "bent"}, dir);
  INFO(bad.output);
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("c.json") && Catch::Contains("\"bent\"") && Catch::Contains("one of: flat, stiff"));
  CHECK_FALSE(fs::exists(dir / "results" / "cases" / "members"));  // nothing written

  const auto run = testing::run_study({"run", "c.json", "--case", "stiff", "-j", "1"}, dir);
  INFO(run.output);
  CHECK(run.exit_code == 4);  // the campaign is not complete: the flat members have not run
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results");
  REQUIRE(s.members.size() == 4);
  for (std::size_t i = 0; i < s.members.size(); ++i) {
    INFO(s.members[i].dir_name());
    CHECK(s.conditions[i].state == (s.members[i].case_name == "stiff" ? MemberState::complete : MemberState::fresh));
  }
  fs::remove_all(dir);
}
