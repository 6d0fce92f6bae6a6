// What `study` says to a person: a misspelt key named first with the key it is near, a scene
// given where a campaign belongs, its version and examples in --help.
#include <catch2/catch.hpp>

#include "solver/scene/user_hints.hpp"
#include "solver/scene/version.hpp"
#include "study/campaign/campaign.hpp"
#include "study/campaign/campaign_error.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a misspelt key is named first, with the known key it is near", "[study]") {
  CHECK(capsule::nearest_key("Eb", {"Ca", "E_b", "V", "eta"}) == "E_b");
  CHECK(capsule::nearest_key("sweeps", {"name", "base", "sweep", "cases"}) == "sweep");
  CHECK(capsule::nearest_key("ca", {"Ca", "E_b"}) == "Ca");
  CHECK(capsule::nearest_key("resolutoin", {"resolution", "protocol"}) == "resolution");
  CHECK(capsule::nearest_key("xyz", {"Ca", "E_b", "V", "eta"}).empty());

  // In a campaign: the top-level key.
  nlohmann::json doc = testing::tiny_campaign("typo", {0.1}, 1, 1);
  doc["sweeps"] = doc["sweep"];
  doc.erase("sweep");
  CHECK_THROWS_WITH(parse_campaign(doc.dump(), "c.json"),
                    Catch::Contains("c.json: sweeps: unknown key, did you mean sweep?"));

  // In its base scene: "Eb" for "E_b" is named as unknown, not reported as a missing E_b.
  const fs::path dir = testing::scratch_dir("typo");
  nlohmann::json eb = testing::tiny_campaign("typo", {0.1}, 1, 1);
  eb["base"]["Eb"] = eb["base"]["E_b"];
  eb["base"].erase("E_b");
  testing::write_text(dir / "c.json", eb.dump());
  const auto plan = testing::run_study({"plan", "c.json"}, dir);
  INFO(plan.output);
  CHECK(plan.exit_code == 2);
  CHECK(plan.output.find("Eb: unknown key, did you mean E_b?") != std::string::npos);
  CHECK(plan.output.find("missing required key") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a scene given to study is named as a scene, not taken apart as a campaign", "[study]") {
  const auto r = testing::run_study({"plan", "tests/data/scenes/circle_quick_2d.json"}, CAPSULE_SOURCE_DIR);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("this is a scene file, not a campaign") != std::string::npos);
  CHECK(r.output.find("unknown key") == std::string::npos);
}

TEST_CASE("study --version names the code and physics version - --help shows examples", "[study]") {
  const auto version = testing::run_study({"--version"}, CAPSULE_SOURCE_DIR);
  INFO(version.output);
  CHECK(version.exit_code == 0);
  CHECK(version.output.rfind("study ", 0) == 0);
  CHECK(version.output.find(std::string("(physics version ") + capsule::physics_version + ")") != std::string::npos);
  const auto help = testing::run_study({"--help"}, CAPSULE_SOURCE_DIR);
  CHECK(help.exit_code == 0);
  CHECK(help.output.find("Examples:") != std::string::npos);
  CHECK(help.output.find("study run campaigns/demo.json") != std::string::npos);
}
