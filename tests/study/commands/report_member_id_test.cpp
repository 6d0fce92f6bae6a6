// `study report` fits a member's own file only: one copied from another campaign (another
// member id) is skipped and named, as `study status` reports it failed.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study report skips a member file that belongs to another member", "[study]") {
  const fs::path dir = testing::scratch_dir("report_id");
  auto a = testing::tiny_campaign("report_a", {0.05}, 1, 1);
  auto b = testing::tiny_campaign("report_b", {0.02, 0.04}, 1, 1);
  a["analysis"] = b["analysis"] = {{"fits", {"response"}}, {"figures", false}};
  testing::write_text(dir / "a.json", a.dump());
  testing::write_text(dir / "b.json", b.dump());
  REQUIRE(testing::run_study({"run", "a.json"}, dir).exit_code == 0);
  REQUIRE(testing::run_study({"run", "b.json"}, dir).exit_code == 0);

  const CampaignSurvey sa = survey_campaign((dir / "a.json").string(), dir / "results", slurm_queue);
  const CampaignSurvey sb = survey_campaign((dir / "b.json").string(), dir / "results", slurm_queue);
  // b's second member now holds a's member file.
  const fs::path target = sb.layout.member(sb.members[1]).h5;
  fs::copy_file(sa.layout.member(sa.members[0]).h5, target, fs::copy_options::overwrite_existing);

  const auto report = testing::run_study({"report", "b.json"}, dir);
  INFO(report.output);
  CHECK(report.exit_code == 3);
  CHECK(report.output.find("skipped " + sb.members[1].dir_name() + ": member file belongs to member \"" +
                           sa.members[0].id + "\"") != std::string::npos);
  const std::string fits = testing::read_text(sb.layout.report_dir() / "fits.json");
  CHECK(fits.find(sb.members[0].id) != std::string::npos);
  CHECK(fits.find(sa.members[0].id) == std::string::npos);
  CHECK(fits.find(sb.members[1].id) == std::string::npos);
  fs::remove_all(dir);
}
