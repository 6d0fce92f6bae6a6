// Several campaigns at once: `study plan` and `study run` take files or folders of them (a
// whole dissertation: campaigns/ch*.json), plan the total with shared members counted
// once, and run the campaigns one after another so a later one copies what an earlier one ran.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/state/exit_status.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a folder of campaigns plans with shared members counted once and runs in path order", "[study]") {
  const fs::path dir = testing::scratch_dir("campaign_folder");
  fs::create_directories(dir / "set" / "more");
  testing::write_text(dir / "set" / "a.json", testing::tiny_campaign("a", {0.01, 0.02}, 0.3, 0).dump());
  testing::write_text(dir / "set" / "more" / "b.json", testing::tiny_campaign("b", {0.02, 0.03}, 0.3, 0).dump());

  const auto plan = testing::run_study({"plan", "set"}, dir);
  INFO(plan.output);
  REQUIRE(plan.exit_code == 0);
  CHECK(plan.output.find("== set/a.json") < plan.output.find("== set/more/b.json"));
  CHECK(plan.output.find("== all 2 campaigns: 4 members to run, 3 of them different (1 shared between campaigns run "
                         "once, then copied)") != std::string::npos);

  const auto run = testing::run_study({"run", "set"}, dir);
  INFO(run.output);
  CHECK(run.exit_code == 0);
  CHECK(run.output.find("copied Ca0.02-") != std::string::npos);  // b's shared member, from a
  CHECK(survey_campaign((dir / "set" / "more" / "b.json").string(), dir / "results", slurm_queue).count(MemberState::complete) == 2);

  // A folder without campaigns is refused by name.
  fs::create_directories(dir / "empty");
  const auto none = testing::run_study({"plan", "empty"}, dir);
  CHECK(none.exit_code == 2);
  CHECK(none.output.find("a folder with no campaign file") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the exit status of several campaigns is the worst of theirs", "[study]") {
  CHECK(worst_exit_code({0, 0}) == 0);
  CHECK(worst_exit_code({0, 4, 3}) == 3);
  CHECK(worst_exit_code({4, 0}) == 4);
  CHECK(worst_exit_code({3, 5}) == 5);
  CHECK(worst_exit_code({5, 1}) == 1);
}
