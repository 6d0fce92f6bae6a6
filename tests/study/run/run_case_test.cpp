// `study run --case NAME`: only that case's members run (the 2D case of a campaign with 2D and
// 3D cases, say); a name that is no case is refused before anything is written. `--where
// KEY=VALUE`: only the members with that scene value (member_filter.hpp).
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/campaign/member_filter.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study run --case runs only that case's members - an unknown case is refused", "[study]") {
  const fs::path dir = testing::scratch_dir("run_case");
  nlohmann::json doc = testing::tiny_campaign("cases", {0.01, 0.02}, 0.5, 0);
  doc["cases"] = nlohmann::json::array({{{"name", "flat"}, {"set", {{"E_b", 0.0}}}},
                                        {{"name", "stiff"}, {"set", {{"E_b", 0.1}}}}});
  testing::write_text(dir / "c.json", doc.dump(2));

  const auto bad = testing::run_study({"run", "c.json", "--case", "bent"}, dir);
  INFO(bad.output);
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("c.json") && Catch::Contains("\"bent\"") && Catch::Contains("one of: flat, stiff"));
  CHECK_FALSE(fs::exists(dir / "results" / "cases" / "members"));  // nothing written

  const auto run = testing::run_study({"run", "c.json", "--case", "stiff", "-j", "1"}, dir);
  INFO(run.output);
  CHECK(run.exit_code == 4);  // the campaign is not complete: the flat members have not run
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  REQUIRE(s.members.size() == 4);
  for (std::size_t i = 0; i < s.members.size(); ++i) {
    INFO(s.members[i].dir_name());
    CHECK(s.conditions[i].state == (s.members[i].case_name == "stiff" ? MemberState::complete : MemberState::fresh));
  }
  fs::remove_all(dir);
}

TEST_CASE("study run --where runs only the members with that scene value - a value no member has is refused",
          "[study]") {
  // The use: run the cheap level of a resolution ladder first, the rest later.
  const fs::path dir = testing::scratch_dir("run_where");
  nlohmann::json doc = testing::tiny_campaign("where", {0.01, 0.02}, 0.5, 0);
  doc["sweep"]["grid"]["E_b"] = {0.0, 0.1};
  testing::write_text(dir / "c.json", doc.dump(2));

  for (const std::string bad_where : {"E_b=0.3", "resolution.a", "=5", "E_b..x=1"}) {
    const auto bad = testing::run_study({"run", "c.json", "--where", bad_where}, dir);
    INFO(bad_where << ": " << bad.output);
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.output, Catch::Contains("c.json") && Catch::Contains("--where"));
    CHECK_FALSE(fs::exists(dir / "results" / "where" / "members"));  // nothing written
  }

  // 0.1 matches the scene's 0.1 and 1e-1 the same number; both conditions must hold.
  const auto run = testing::run_study({"run", "c.json", "--where", "E_b=1e-1", "--where", "Ca=0.02", "-j", "1"}, dir);
  INFO(run.output);
  CHECK(run.exit_code == 4);  // the other members have not run
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  REQUIRE(s.members.size() == 4);
  int complete = 0;
  for (std::size_t i = 0; i < s.members.size(); ++i) {
    const auto& scene = s.members[i].scene;
    const bool chosen = scene.at("E_b").get<double>() == 0.1 && scene.at("Ca").get<double>() == 0.02;
    INFO(s.members[i].dir_name());
    CHECK(s.conditions[i].state == (chosen ? MemberState::complete : MemberState::fresh));
    complete += s.conditions[i].state == MemberState::complete;
  }
  CHECK(complete == 1);
  fs::remove_all(dir);
}

TEST_CASE("study run --where: KEY=VALUE read as JSON or a plain word, numbers compared by value", "[study]") {
  const SceneCondition a = parse_scene_condition("resolution.a=5");
  CHECK(a.key == "resolution.a");
  const nlohmann::json scene = {{"resolution", {{"a", 5.0}, {"precision", "single"}, {"domain", {10.0, 10.0, 8.0}}}}};
  CHECK(scene_matches(scene, {a}));
  CHECK(scene_matches(scene, {parse_scene_condition("resolution.precision=single")}));
  CHECK(scene_matches(scene, {parse_scene_condition("resolution.precision=\"single\"")}));
  CHECK(scene_matches(scene, {parse_scene_condition("resolution.domain=[10,10,8]")}));
  CHECK_FALSE(scene_matches(scene, {parse_scene_condition("resolution.domain=[10,10]")}));
  CHECK_FALSE(scene_matches(scene, {parse_scene_condition("resolution.a=7")}));
  CHECK_FALSE(scene_matches(scene, {parse_scene_condition("resolution.kernel=peskin4")}));  // absent key
  CHECK_FALSE(scene_matches(scene, {a, parse_scene_condition("resolution.a=7")}));
  CHECK_THROWS_AS(parse_scene_condition("resolution.a"), std::invalid_argument);
  CHECK_THROWS_AS(parse_scene_condition("=5"), std::invalid_argument);
  CHECK_THROWS_AS(parse_scene_condition("a..b=5"), std::invalid_argument);
}
