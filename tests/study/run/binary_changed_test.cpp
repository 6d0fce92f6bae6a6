// A capsule binary rebuilt while a campaign runs would give its later members another code
// version than the earlier ones (or a -dirty one): study run records the binary's version when
// it starts, the wrapper hands it to run-member, and run-member starts no member with a binary
// that now reports another (study/run/member_job.hpp, step 3).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "study/run/member_job.hpp"
#include "study/run/shell_quote.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// A stand-in capsule: answers `version` with the code version in the file beside it, and runs
// the real capsule for anything else.
fs::path stand_in_capsule(const fs::path& dir, const std::string& version) {
  testing::write_text(dir / "version.txt", version + "\n");
  const fs::path script = dir / "capsule";
  testing::write_text(script, "#!/bin/sh\nif [ \"$1\" = version ]; then printf '{\"code_version\":\"%s\",\"physics_version\":\"6\"}\\n' "
                              "\"$(cat " + shell_quote((dir / "version.txt").string()) + ")\"; exit 0; fi\nexec " +
                              shell_quote(testing::capsule_binary().string()) + " \"$@\"\n");
  fs::permissions(script, fs::perms::owner_all);
  return script;
}

testing::CommandResult run_member(const fs::path& capsule, const fs::path& member_dir, const std::string& expected) {
  return testing::run_shell(shell_quote(testing::study_binary().string()) + " run-member --capsule " +
                            shell_quote(capsule.string()) + " --code-version " + shell_quote(expected) + " -- " +
                            shell_quote(member_dir.string()) + " 1 </dev/null");
}

}  // namespace

TEST_CASE("capsule version says what its member files record", "[study]") {
  const auto out = testing::run_shell(shell_quote(testing::capsule_binary().string()) + " version </dev/null");
  REQUIRE(out.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(out.output);
  CHECK_FALSE(j.at("code_version").get<std::string>().empty());
  CHECK(j.at("physics_version").get<std::string>() == "6");
}

TEST_CASE("run-member starts no member with a capsule binary rebuilt since the run began", "[study]") {
  const fs::path dir = testing::scratch_dir("binary_changed");
  testing::write_text(dir / "c.json", testing::tiny_campaign("binary_changed", {0.02}, 0.3, 0).dump());
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);
  const fs::path capsule = stand_in_capsule(dir, "abc123def456");

  // The run began with another version: refused, exit 3, nothing of the member written.
  const auto refused = run_member(capsule, p.dir, "0123456789ab");
  INFO(refused.output);
  CHECK(refused.exit_code == kExitBinaryChanged);
  CHECK_THAT(refused.output, Catch::Contains("not started") && Catch::Contains("now reports code version abc123def456") &&
                                 Catch::Contains("the run began with 0123456789ab"));
  CHECK_THAT(testing::read_text(p.log), Catch::Contains("not started"));
  CHECK_FALSE(fs::exists(p.partial));
  CHECK_FALSE(fs::exists(p.exit_status));
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::fresh);

  // The same version: it runs.
  const auto ran = run_member(capsule, p.dir, "abc123def456");
  INFO(ran.output);
  CHECK(ran.exit_code == 0);
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  fs::remove_all(dir);
}

TEST_CASE("study run hands the capsule binary's version to every member through the wrapper", "[study]") {
  const fs::path dir = testing::scratch_dir("binary_version_wrapper");
  testing::write_text(dir / "c.json", testing::tiny_campaign("binary_version_wrapper", {0.02}, 0.3, 0).dump());
  const fs::path capsule = stand_in_capsule(dir, "fedcba987654");
  const auto run = testing::run_shell("cd " + shell_quote(dir.string()) + " && CAPSULE_BIN=" + shell_quote(capsule.string()) +
                                      " " + shell_quote(testing::study_binary().string()) + " run c.json </dev/null");
  INFO(run.output);
  CHECK(run.exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK_THAT(testing::read_text(s.layout.wrapper()), Catch::Contains("--code-version 'fedcba987654'"));
  CHECK(nlohmann::json::parse(testing::read_text(s.layout.run_json())).at("capsule_code_version") == "fedcba987654");
  fs::remove_all(dir);
}
