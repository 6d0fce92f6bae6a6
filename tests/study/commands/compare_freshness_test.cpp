// `study compare` warns when a campaign's report is older than one of its member files.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/commands/report_freshness.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study compare warns about a report older than its members", "[study]") {
  const fs::path dir = testing::scratch_dir("stale_report");
  auto doc = testing::tiny_campaign("stale", {0.02, 0.05}, 1, 1);
  doc["analysis"] = {{"fits", {"response"}}, {"figures", false}};
  testing::write_text(dir / "c.json", doc.dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  CHECK(stale_report_warning(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue))->find("no report yet") !=
        std::string::npos);
  REQUIRE(testing::run_study({"report", "c.json"}, dir).exit_code == 0);

  const auto fresh = testing::run_study({"compare", "c.json"}, dir);
  INFO(fresh.output);
  CHECK(fresh.output.find("warning:") == std::string::npos);

  // A member rerun after the report: its file is newer than fits.json.
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const fs::path h5 = s.layout.member(s.members[1]).h5;
  fs::last_write_time(h5, fs::last_write_time(s.layout.report_dir() / "fits.json") + std::chrono::seconds(5));
  const auto stale = testing::run_study({"compare", "c.json"}, dir);
  INFO(stale.output);
  CHECK(stale.output.find("warning: the report of campaign stale") != std::string::npos);
  CHECK(stale.output.find("older than its member " + s.members[1].dir_name()) != std::string::npos);
  fs::remove_all(dir);
}
