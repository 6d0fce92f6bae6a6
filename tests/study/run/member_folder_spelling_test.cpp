// A member folder has one identity whatever the spelling of its path: `study run-member DIR/`
// is `study run-member DIR`, and the member's id comes from its scene.json, never from the
// folder's name (study/run/member_job.hpp).
#include <catch2/catch.hpp>

#include "study/run/member_job.hpp"
#include "study/run/shell_quote.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

testing::CommandResult run_member(const std::string& member_dir) {
  return testing::run_shell(shell_quote(testing::study_binary().string()) + " run-member --capsule " +
                            shell_quote(testing::capsule_binary().string()) + " -- " + shell_quote(member_dir) +
                            " 1 </dev/null");
}

}  // namespace

TEST_CASE("a complete member named with a trailing slash or dot parts is not run again", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("member_spelling");
  testing::write_text(dir / "c.json", testing::tiny_campaign("spelling", {0.05}, 1, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);
  REQUIRE(run_member(p.dir.string()).exit_code == 0);
  REQUIRE(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  const std::string before = testing::read_text(p.h5);
  const auto time_before = fs::last_write_time(p.h5);

  const std::string name = p.dir.filename().string();
  for (const std::string& spelling : {p.dir.string() + "/", p.dir.string() + "//", p.dir.string() + "/.",
                                     (p.dir / ".." / name).string() + "/"}) {
    INFO(spelling);
    const auto again = run_member(spelling);
    INFO(again.output);
    CHECK(again.exit_code == 0);
    CHECK_THAT(again.output, Catch::Contains(name + " is complete: nothing run"));
    CHECK(testing::read_text(p.h5) == before);
    CHECK(fs::last_write_time(p.h5) == time_before);
  }
  CHECK(normal_member_dir(p.dir.string() + "/") == p.dir);
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  fs::remove_all(dir);
}

TEST_CASE("a member folder whose name does not end in its scene's id is refused before anything runs", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("member_misnamed");
  testing::write_text(dir / "c.json", testing::tiny_campaign("misnamed", {0.05}, 1, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);
  const fs::path renamed = p.dir.parent_path() / "Ca0.05-0123456789abcdef";
  fs::rename(p.dir, renamed);
  const auto run = run_member(renamed.string());
  INFO(run.output);
  CHECK(run.exit_code != 0);
  CHECK_THAT(run.output, Catch::Contains(renamed.string()) && Catch::Contains("-" + s.members[0].id));
  CHECK_FALSE(fs::exists(renamed / "member.h5"));
  CHECK_FALSE(fs::exists(renamed / "member.lock"));
  fs::remove_all(dir);
}
