// The results folder keeps its history: the joblog and runs.jsonl grow with every run
// (run.json is the last run), and a second campaign file with the same name but other
// contents is refused instead of sharing results/<name>/.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <sstream>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/run/joblog.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("joblog and run records keep every run", "[study]") {
  const fs::path dir = testing::scratch_dir("history");
  testing::write_text(dir / "c.json", testing::tiny_campaign("history", {0.05}, 1, 1).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  fs::remove(s.layout.member(s.members[0]).h5);  // so the second run runs it again
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);

  CHECK(read_joblog(s.layout.joblog()).size() == 2);
  std::istringstream lines(testing::read_text(s.layout.run_history()));
  std::vector<nlohmann::json> runs;
  for (std::string line; std::getline(lines, line);) runs.push_back(nlohmann::json::parse(line));
  REQUIRE(runs.size() == 2);
  for (const auto& r : runs) {
    CHECK(r.at("campaign") == "history");
    CHECK(r.contains("finished"));
    CHECK(r.at("to_run") == 1);
  }
  const auto last = nlohmann::json::parse(testing::read_text(s.layout.run_json()));
  CHECK(last.at("started") == runs[1].at("started"));
  CHECK(last.at("member_seconds").get<double>() < 2 * runs[0].at("member_seconds").get<double>() + 5);
  fs::remove_all(dir);
}

TEST_CASE("two campaign files with one name but different contents are refused with both paths", "[study]") {
  const fs::path dir = testing::scratch_dir("same_name");
  fs::create_directories(dir / "other");
  testing::write_text(dir / "c.json", testing::tiny_campaign("shared", {0.05}, 1, 1).dump());
  testing::write_text(dir / "other" / "c.json", testing::tiny_campaign("shared", {0.02}, 1, 1).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);

  for (const std::string command : {"run", "plan", "status"}) {
    INFO(command);
    const auto second = testing::run_study({command, "other/c.json"}, dir);
    INFO(second.output);
    CHECK(second.exit_code == 2);
    CHECK(second.output.find(fs::canonical(dir / "c.json").string()) != std::string::npos);
    CHECK(second.output.find((fs::canonical(dir) / "other" / "c.json").string()) != std::string::npos);
  }
  CHECK(testing::read_text(dir / "results" / "shared" / "campaign.json") == testing::read_text(dir / "c.json"));

  // The same file edited is still the same campaign.
  testing::write_text(dir / "c.json", testing::tiny_campaign("shared", {0.05, 0.06}, 1, 1).dump());
  CHECK(testing::run_study({"plan", "c.json"}, dir).exit_code == 0);
  fs::remove_all(dir);
}
