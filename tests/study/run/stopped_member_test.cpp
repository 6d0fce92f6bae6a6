// A member that stopped (the solver refused its configuration) is kept like an unstable
// one: reported, not rerun by every `study run`, rerun with --rerun-stopped.
#include <catch2/catch.hpp>

#include "solver/io/member_file.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a stopped member is kept and rerun only with --rerun-stopped", "[study]") {
  const fs::path dir = testing::scratch_dir("stopped");
  testing::write_text(dir / "c.json", testing::tiny_campaign("stopped", {0.05}, 1, 1).dump(2));
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  // The member's file as the capsule writes it when the solver throws ("stopped: ...").
  const MemberPaths p = s.layout.member(s.members[0]);
  fs::remove(p.h5);
  {
    capsule::io::MemberWriter w(p.h5.string());
    w.set_attribute("member_id", s.members[0].id);
    w.finish("stopped: a configuration the solver refuses");
  }
  const auto status = testing::run_study({"status", "c.json"}, dir);
  INFO(status.output);
  CHECK(status.exit_code == 3);
  CHECK(status.output.find("[stopped] " + s.members[0].dir_name() + ": stopped: a configuration") != std::string::npos);

  const auto rerun = testing::run_study({"run", "c.json"}, dir);
  INFO(rerun.output);
  CHECK(rerun.output.find("nothing to run") != std::string::npos);
  CHECK(rerun.exit_code == 3);
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::stopped);

  const auto forced = testing::run_study({"run", "c.json", "--rerun-stopped"}, dir);
  INFO(forced.output);
  CHECK(forced.output.find("running 1 of 1 members") != std::string::npos);
  CHECK(forced.exit_code == 0);
  fs::remove_all(dir);
}
