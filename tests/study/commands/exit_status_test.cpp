// The exit status of `study` (docs/guide/campaigns.md "Exit status"): command-line errors exit 2 (not
// CLI11's 104-109), status and report say with 3 / 4 that members failed or are missing,
// and `study status --json` gives scripts the same facts.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study command-line errors exit 2 with a plain message", "[study]") {
  const fs::path dir = testing::scratch_dir("cli_errors");
  testing::write_text(dir / "c.json", testing::tiny_campaign("cli", {0.05}, 1, 1).dump());
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> table{
      {{"run", "c.json", "-j", "0"}, "must be a whole number from 1 to 1000000, got \"0\""},
      {{"run", "c.json", "--threads", "-1"}, "must be a whole number from 1 to 1000000"},
      {{"run", "c.json", "--jobs", "many"}, "got \"many\""},
      {{"export", "c.json", "--slurm", "--threads", "0"}, "must be a whole number"},
      {{"export", "c.json", "--slurm", "--time", "soon"}, "not in Slurm's form"},
      {{"run", "c.json", "--frobnicate"}, "--frobnicate"},
      {{"status"}, "campaign is required"},
      {{"launch", "c.json"}, "subcommand"},
      {{}, "subcommand"},
  };
  for (const auto& c : table) {
    std::string line;
    for (const auto& a : c.args) line += a + " ";
    INFO("study " << line);
    const auto r = testing::run_study(c.args, dir);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(c.expected) != std::string::npos);
    CHECK(r.output.size() < 2000);  // one message and the usage, not a 300-digit range
  }
  CHECK_FALSE(fs::exists(dir / "results"));  // nothing ran
  const auto help = testing::run_study({"--help"}, dir);
  CHECK(help.exit_code == 0);
  CHECK(help.output.find("Exit status: 0 done") != std::string::npos);
  CHECK(help.output.find("5 run: another `study run`") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("study status and report exit 4 while members are missing, 0 when all are complete", "[study]") {
  const fs::path dir = testing::scratch_dir("status_codes");
  auto doc = testing::tiny_campaign("codes", {0.02, 0.05}, 1, 1);
  doc["analysis"] = {{"fits", {"response"}}, {"figures", false}};
  testing::write_text(dir / "c.json", doc.dump());

  const auto fresh = testing::run_study({"status", "c.json"}, dir);
  CHECK(fresh.exit_code == 4);
  const auto fresh_json = testing::run_study({"status", "c.json", "--json"}, dir);
  INFO(fresh_json.output);
  CHECK(fresh_json.exit_code == 4);
  const auto j = nlohmann::json::parse(fresh_json.output);
  CHECK(j.at("campaign") == "codes");
  CHECK(j.at("members") == 2);
  CHECK(j.at("counts").at("new") == 2);
  CHECK(j.at("exit_status") == 4);
  REQUIRE(j.at("not_complete").size() == 2);
  CHECK(j.at("not_complete")[0].at("state") == "new");
  CHECK(testing::run_study({"report", "c.json"}, dir).exit_code == 4);

  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  CHECK(testing::run_study({"status", "c.json"}, dir).exit_code == 0);
  const auto done = nlohmann::json::parse(testing::run_study({"status", "c.json", "--json"}, dir).output);
  CHECK(done.at("counts").at("complete") == 2);
  CHECK(done.at("not_complete").empty());
  CHECK(testing::run_study({"report", "c.json"}, dir).exit_code == 0);

  // One member's files removed: missing again (not failed).
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  clear_for_rerun(s.layout.member(s.members[1]));
  CHECK(testing::run_study({"status", "c.json"}, dir).exit_code == 4);
  CHECK(testing::run_study({"report", "c.json"}, dir).exit_code == 4);
  fs::remove_all(dir);
}
