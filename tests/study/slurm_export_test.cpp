// Slurm export: the sbatch script is valid bash, and its task i runs member i.
#include <catch2/catch.hpp>

#include "study/campaign_survey.hpp"
#include "study/shell_quote.hpp"
#include "study/slurm_export.hpp"
#include "tests/study/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("array specs compress runs of indices", "[study]") {
  CHECK(array_spec({0, 1, 2, 3}) == "0-3");
  CHECK(array_spec({0, 2, 3, 4, 7}) == "0,2-4,7");
  CHECK(array_spec({5}) == "5");
}

TEST_CASE("the Slurm script passes bash -n and task i runs member i", "[study]") {
  const fs::path dir = testing::scratch_dir("slurm");
  testing::write_text(dir / "c.json", testing::tiny_campaign("slurm", {0.01, 0.02, 0.03}, 1, 1).dump());
  const auto exported = testing::run_study({"export", "c.json", "--slurm"}, dir);
  INFO(exported.output);
  REQUIRE(exported.exit_code == 0);

  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results");
  const fs::path script = s.layout.slurm_dir() / "capsule.sbatch";
  REQUIRE(fs::exists(script));
  const std::string text = testing::read_text(script);
  CHECK(text.find("#SBATCH --array=0-2\n") != std::string::npos);
  CHECK(text.find("#SBATCH --cpus-per-task=1\n") != std::string::npos);
  CHECK(testing::run_shell("bash -n " + shell_quote(script.string())).exit_code == 0);

  // Task 1 runs member 1 and nothing else.
  const auto task = testing::run_shell("SLURM_ARRAY_TASK_ID=1 bash " + shell_quote(script.string()));
  INFO(task.output);
  CHECK(task.exit_code == 0);
  const CampaignSurvey after = survey_campaign((dir / "c.json").string(), dir / "results");
  CHECK(after.conditions[0].state == MemberState::fresh);
  CHECK(after.conditions[1].state == MemberState::complete);
  CHECK(after.conditions[2].state == MemberState::fresh);

  // A task past the end of the list fails loudly instead of running something else.
  CHECK(testing::run_shell("SLURM_ARRAY_TASK_ID=7 bash " + shell_quote(script.string())).exit_code == 2);

  // Exporting again leaves the complete member out of the array.
  REQUIRE(testing::run_study({"export", "c.json", "--slurm"}, dir).exit_code == 0);
  CHECK(testing::read_text(script).find("#SBATCH --array=0,2\n") != std::string::npos);
  fs::remove_all(dir);
}
