// `study run` clears the members it reruns under each member's lock, after reading its member
// file again (study/state/campaign_survey.hpp): a Slurm task that finished or holds a member
// between the survey and the clearing keeps its work.
#include <catch2/catch.hpp>

#include "study/state/member_lock.hpp"
#include "study/run/shell_quote.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a member a stand-in task completes or holds between the survey and the clearing is not cleared",
          "[study][lock]") {
  const fs::path dir = testing::scratch_dir("clear_race");
  testing::write_text(dir / "c.json", testing::tiny_campaign("race", {0.02, 0.05}, 0.3, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths done = s.layout.member(s.members[0]), held = s.layout.member(s.members[1]);
  // A failed attempt each: both need running at the survey.
  for (const auto& p : {done, held}) testing::write_text(p.exit_status, "1\n");
  s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  REQUIRE(s.conditions[0].state == MemberState::failed);
  REQUIRE(s.conditions[1].state == MemberState::failed);

  // After the survey: a task completes the first member, and another holds the second one's lock.
  const auto task = testing::run_shell(shell_quote(testing::study_binary().string()) + " run-member --capsule " +
                                       shell_quote(testing::capsule_binary().string()) + " -- " +
                                       shell_quote(done.dir.string()) + " 1 </dev/null");
  REQUIRE(task.exit_code == 0);
  const std::string complete = testing::read_text(done.h5);
  REQUIRE_FALSE(complete.empty());
  const MemberLock holder(held.dir);
  REQUIRE(holder.held());
  testing::write_text(held.partial, "the holder's work");

  const auto still = clear_members_to_rerun(s, {0, 1}, false, false);
  CHECK(still.empty());
  CHECK(testing::read_text(done.h5) == complete);  // not deleted, not to be run again
  CHECK(testing::read_text(held.partial) == "the holder's work");
  CHECK(fs::exists(held.exit_status));
  fs::remove_all(dir);
}

TEST_CASE("a member that still needs running is cleared under its lock and released", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("clear_plain");
  testing::write_text(dir / "c.json", testing::tiny_campaign("plain", {0.02}, 0.3, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);
  testing::write_text(p.exit_status, "1\n");
  testing::write_text(p.partial, "stale");
  s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const auto still = clear_members_to_rerun(s, {0}, false, false);
  CHECK(still == std::vector<std::size_t>{0});
  CHECK_FALSE(fs::exists(p.exit_status));
  CHECK_FALSE(fs::exists(p.partial));
  CHECK_FALSE(fs::exists(member_lock_file(p.dir)));
  fs::remove_all(dir);
}
