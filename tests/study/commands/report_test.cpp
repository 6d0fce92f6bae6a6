// `study report` hands the finished members to the analysis and writes results/<campaign>/report.
#include <catch2/catch.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

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

  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const fs::path fits = s.layout.report_dir() / "fits.json";
  REQUIRE(fs::exists(fits));
  const std::string text = testing::read_text(fits);
  for (const auto& m : s.members) CHECK(text.find(m.id) != std::string::npos);
  CHECK(report.output.find("fits.json") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("study report of a campaign still under way names the members it lacks, and drops the note once they ran", "[study]") {
  const fs::path dir = testing::scratch_dir("report_incomplete");
  auto doc = testing::tiny_campaign("report_incomplete", {0.02, 0.05}, 0.3, 0);
  doc["analysis"] = {{"fits", {"response"}}, {"figures", false}};
  testing::write_text(dir / "c.json", doc.dump());
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  REQUIRE(s.members.size() == 2);
  const std::size_t ran = s.members[0].scene.at("Ca").get<double>() == 0.02 ? 0 : 1, lacking = 1 - ran;

  REQUIRE(testing::run_study({"run", "c.json", "--where", "Ca=0.02"}, dir).exit_code == 4);  // one member not run
  const auto report = testing::run_study({"report", "c.json"}, dir);
  INFO(report.output);
  CHECK(report.exit_code == 4);
  CHECK_THAT(report.output, Catch::Contains("1 of 2 members have no member file yet"));
  const fs::path incomplete = s.layout.report_dir() / "INCOMPLETE.md";
  REQUIRE(fs::exists(incomplete));
  const std::string note = testing::read_text(incomplete);
  CHECK_THAT(note, Catch::Contains("1 of 2 members") && Catch::Contains(s.members[lacking].dir_name() + ": new"));
  CHECK(note.find(s.members[ran].dir_name()) == std::string::npos);
  // The member without a file is in the report's own tables, with the reason, not left out.
  const nlohmann::json fits = nlohmann::json::parse(testing::read_text(s.layout.report_dir() / "fits.json"));
  std::map<std::string, std::string> status;
  for (const auto& m : fits.at("members")) status[m.at("id").get<std::string>()] = m.at("status").get<std::string>();
  CHECK(status.at(s.members[ran].id) == "complete");
  CHECK(status.at(s.members[lacking].id) == "member file missing (not run)");

  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const auto whole = testing::run_study({"report", "c.json"}, dir);
  INFO(whole.output);
  CHECK(whole.output.find("no member file yet") == std::string::npos);
  CHECK_FALSE(fs::exists(incomplete));
  fs::remove_all(dir);
}

TEST_CASE("study report of a campaign that never ran writes no figures and says so", "[study]") {
  const fs::path dir = testing::scratch_dir("report_never_ran");
  testing::write_text(dir / "c.json", testing::tiny_campaign("never_ran", {0.02, 0.05}, 0.3, 0).dump());
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const auto report = testing::run_study({"report", "c.json"}, dir);
  INFO(report.output);
  CHECK_THAT(report.output, Catch::Contains("figures skipped: no member of this campaign has a member file yet"));
  const fs::path figures = s.layout.report_dir() / "figures";
  bool png = false;
  if (fs::exists(figures))
    for (const auto& e : fs::directory_iterator(figures)) png = png || e.path().extension() == ".png";
  CHECK_FALSE(png);
  fs::remove_all(dir);
}
