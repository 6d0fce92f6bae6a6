// Symbolic links inside a campaign's folder are refused clearly and nothing is deleted or
// written through them (study/state/results_layout.hpp); a results folder that is itself a link
// works.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a member folder linked to its sibling is unreadable: the sibling's complete file is not deleted",
          "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("linked_member");
  testing::write_text(dir / "c.json", testing::tiny_campaign("linked", {0.02, 0.05}, 0.3, 0).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const MemberPaths sibling = s.layout.member(s.members[0]), linked = s.layout.member(s.members[1]);
  const std::string complete = testing::read_text(sibling.h5);
  fs::remove_all(linked.dir);
  fs::create_directory_symlink(sibling.dir, linked.dir);

  for (const std::string command : {"status", "run"}) {
    INFO(command);
    const auto out = testing::run_study({command, "c.json"}, dir);
    INFO(out.output);
    CHECK(out.exit_code != 0);
    CHECK_THAT(out.output, Catch::Contains("[unreadable] " + s.members[1].dir_name()) &&
                               Catch::Contains("is a symbolic link"));
  }
  CHECK(testing::read_text(sibling.h5) == complete);
  CHECK(fs::is_symlink(linked.dir));
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  fs::remove_all(dir);
}

TEST_CASE("a members folder that is a link to another disk is refused, naming the link - nothing is written there",
          "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("linked_members");
  testing::write_text(dir / "c.json", testing::tiny_campaign("elsewhere", {0.02}, 0.3, 0).dump());
  fs::create_directories(dir / "results" / "elsewhere");
  fs::create_directories(dir / "other_disk");
  fs::create_directory_symlink(dir / "other_disk", dir / "results" / "elsewhere" / "members");
  const auto run = testing::run_study({"run", "c.json"}, dir);
  INFO(run.output);
  CHECK(run.exit_code != 0);
  CHECK_THAT(run.output, Catch::Contains((dir / "results" / "elsewhere" / "members").string()) &&
                             Catch::Contains("is a symbolic link"));
  CHECK(fs::is_empty(dir / "other_disk"));

  // The results folder itself as the link: supported.
  fs::remove_all(dir / "results");
  fs::create_directories(dir / "other_disk" / "results");
  fs::create_directory_symlink(dir / "other_disk" / "results", dir / "results");
  const auto linked = testing::run_study({"run", "c.json"}, dir);
  INFO(linked.output);
  CHECK(linked.exit_code == 0);
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  fs::remove_all(dir);
}
