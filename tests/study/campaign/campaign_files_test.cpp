// Every campaign shipped in campaigns/ parses, expands and plans without error.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/plan/cost_estimate.hpp"
#include "study/plan/plan_table.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("every campaign file plans without error", "[study]") {
  const fs::path campaigns = fs::path(CAPSULE_SOURCE_DIR) / "campaigns";
  const fs::path results = testing::scratch_dir("plan_all");
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(campaigns)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    INFO(entry.path().string());
    std::ostringstream out;
    {
      const Campaign c = load_campaign(entry.path().string());
      CHECK_NOTHROW(print_plan(c, ResultsLayout(results, c.name), out));
    }
    const CampaignSurvey s = survey_campaign(entry.path().string(), results, slurm_queue);
    CHECK(s.members.size() >= 1);
    CHECK(s.campaign.name == entry.path().stem().string());  // results/<name> matches the file name
    for (const auto& m : s.members) CHECK(estimate_cost(m.scene).nodes > 0);
  }
  CHECK(files >= 25);  // demo, the 18 dissertation campaigns (docs/guide/campaigns.md "The shipped campaigns"), precision_double/single, 4 accuracy/stability benches, the probes
  CHECK_FALSE(fs::exists(results / "demo"));  // planning wrote nothing
  fs::remove_all(results);
}

TEST_CASE("study plan prints every member and changes nothing", "[study]") {
  const fs::path dir = testing::scratch_dir("plan_cli");
  testing::write_text(dir / "c.json", testing::tiny_campaign("plan", {0.01, 0.02}, 1, 1).dump());
  const auto plan = testing::run_study({"plan", "c.json"}, dir);
  INFO(plan.output);
  CHECK(plan.exit_code == 0);
  CHECK(plan.output.find("Ca0.01-") != std::string::npos);
  CHECK(plan.output.find("Ca0.02-") != std::string::npos);
  CHECK(plan.output.find("2 members: 0 complete, 2 new") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "results"));

  // A folder that no member names (left by a run before the Ca grid changed) is named, once;
  // the folders of today's members are not.
  const std::string member_folder = plan.output.substr(plan.output.find("Ca0.01-"), std::string("Ca0.01-").size() + 16);
  fs::create_directories(dir / "results" / "plan" / "members" / "Ca0.005-0123456789abcdef");
  fs::create_directories(dir / "results" / "plan" / "members" / member_folder);
  const auto stale = testing::run_study({"plan", "c.json"}, dir);
  INFO(stale.output);
  CHECK(stale.exit_code == 0);
  CHECK(stale.output.find("1 folder under members/ belongs to no member of this campaign") != std::string::npos);
  CHECK(stale.output.find("\n  Ca0.005-0123456789abcdef\n") != std::string::npos);
  CHECK(stale.output.find("\n  " + member_folder + "\n") == std::string::npos);
  fs::remove_all(dir / "results");

  testing::write_text(dir / "bad.json", R"({"name": "x", "base": {}, "extra": 1})");
  const auto bad = testing::run_study({"plan", "bad.json"}, dir);
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("bad.json: extra: unknown key") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the dissertation's campaigns are at the top of campaigns/, the others found by name", "[study]") {
  // The short path every document uses is a real file.
  const auto plan = testing::run_study({"plan", "campaigns/ch3_ca.json"}, CAPSULE_SOURCE_DIR);
  INFO(plan.output);
  CHECK(plan.exit_code == 0);
  CHECK(plan.output.find("cannot open") == std::string::npos);
  // A name at another place: the OS reason, and where the name is.
  const auto grouped = testing::run_study({"plan", "campaigns/precision_double.json"}, CAPSULE_SOURCE_DIR);
  INFO(grouped.output);
  CHECK(grouped.exit_code == 2);
  CHECK(grouped.output.find("cannot open the campaign file: No such file or directory") != std::string::npos);
  CHECK(grouped.output.find("this name is at campaigns/accuracy/precision_double.json") != std::string::npos);
  const auto old_place = testing::run_study({"plan", "campaigns/dissertation/ch3_ca.json"}, CAPSULE_SOURCE_DIR);
  INFO(old_place.output);
  CHECK(old_place.exit_code == 2);
  CHECK(old_place.output.find("this name is at campaigns/ch3_ca.json") != std::string::npos);
  // A name without its .json.
  const auto bare = testing::run_study({"plan", "campaigns/demo"}, CAPSULE_SOURCE_DIR);
  INFO(bare.output);
  CHECK(bare.exit_code == 2);
  CHECK(bare.output.find("did you mean campaigns/demo.json?") != std::string::npos);
}
