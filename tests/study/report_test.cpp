// `study report` hands the finished members to the analysis and writes results/<campaign>/report.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "tests/study/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study report writes the campaign's report from its members", "[study]") {
  const fs::path dir = testing::scratch_dir("report");
  auto doc = testing::tiny_campaign("report", {0.02, 0.05}, 2, 2);
  doc["analysis"] = {{"fits", {"response", "recovery"}}, {"figures", false}};
  testing::write_text(dir / "c.json", doc.dump());

  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const auto report = testing::run_study({"report", "c.json"}, dir);
  INFO(report.output);
  CHECK(report.exit_code == 0);

  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results");
  const fs::path fits = s.layout.report_dir() / "fits.json";
  REQUIRE(fs::exists(fits));
  const std::string text = testing::read_text(fits);
  for (const auto& m : s.members) CHECK(text.find(m.id) != std::string::npos);
  CHECK(report.output.find("fits.json") != std::string::npos);
  fs::remove_all(dir);
}
