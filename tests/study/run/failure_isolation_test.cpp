// A failed and an unstable member never stop the others; status names both with reasons.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;
using nlohmann::json;

TEST_CASE("failed and unstable members do not stop the others", "[study]") {
  const fs::path dir = testing::scratch_dir("isolation");
  json doc = testing::tiny_campaign("isolation", {0.05}, 1, 1);
  doc["cases"] = json::array({
      {{"name", "ok"}, {"sweep", {{"grid", {{"Ca", {0.02, 0.05}}}}}}},
      // Ca = 10 (the largest a scene allows: a membrane 200 times softer than Ca = 0.05)
      // sheared for kt 6: the segments collapse and the solver's health check ends the
      // member as "unstable at kt = ..." (measured: within kt 3 at a = 4).
      {{"name", "soft"}, {"set", {{"protocol.shear.kt", 6.0}}}, {"sweep", {{"grid", {{"Ca", {10.0}}}}}}},
  });
  testing::write_text(dir / "c.json", doc.dump(2));

  const auto run = testing::run_study({"run", "c.json", "--jobs", "2", "--threads", "1"}, dir);
  INFO(run.output);
  CHECK(run.exit_code == 3);  // not every member completed (docs/guide/campaigns.md "Exit status")

  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  REQUIRE(s.members.size() == 3);
  CHECK(s.count(MemberState::complete) == 2);
  CHECK(s.conditions[2].state == MemberState::unstable);
  CHECK(s.conditions[2].reason.find("unstable at kt =") != std::string::npos);

  const auto status = testing::run_study({"status", "c.json"}, dir);
  INFO(status.output);
  CHECK(status.exit_code == 3);  // an unstable member
  CHECK(status.output.find("complete: 2") != std::string::npos);
  CHECK(status.output.find("[unstable] " + s.members[2].dir_name() + ": unstable at kt =") != std::string::npos);

  // Rerun: the unstable member is final (same id, same outcome) and not rerun; the complete
  // ones are kept (stopped members: stopped_member_test.cpp).
  const auto rerun = testing::run_study({"run", "c.json"}, dir);
  INFO(rerun.output);
  CHECK(rerun.output.find("nothing to run") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a capsule that exits without a member file is reported failed with its log", "[study]") {
  // A capsule that says its version and then fails at once (as /bin/false): the wrapper records
  // exit status 1 and no file.
  const fs::path dir = testing::scratch_dir("nofile");
  testing::write_text(dir / "c.json", testing::tiny_campaign("nofile", {0.05}, 1, 1).dump());
  testing::write_text(dir / "failing-capsule", "#!/bin/sh\n[ \"$1\" = version ] && exec '" +
                                                   testing::capsule_binary().string() + "' version\nexit 1\n");
  fs::permissions(dir / "failing-capsule", fs::perms::owner_all);
  const auto run = testing::run_shell("cd '" + dir.string() + "' && CAPSULE_BIN=failing-capsule '" +
                                      testing::study_binary().string() + "' run c.json </dev/null");
  INFO(run.output);
  CHECK(run.exit_code == 3);
  CHECK(run.output.find("[failed] ") != std::string::npos);
  CHECK(run.output.find("solver failure") != std::string::npos);
  fs::remove_all(dir);
}
