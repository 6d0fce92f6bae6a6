// A results folder belongs to the campaign file that made it, also in a fresh clone, where the
// git-ignored campaign_source is missing (study/state/campaign_owner.hpp): a different file that
// takes its name is refused, naming both files, and rewrites nothing.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "study/state/results_layout.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// Every file under dir with its content.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = testing::read_text(e.path());
  return files;
}

}  // namespace

TEST_CASE("in a fresh clone of the shipped results, a copy of a campaign file with one more Ca is refused and "
          "rewrites nothing", "[study]") {
  const fs::path source(CAPSULE_SOURCE_DIR);
  const std::string shipped = testing::read_text(source / "results" / "ch3_ca" / "campaign.json");
  REQUIRE_FALSE(shipped.empty());
  // The tracked campaign file that made results/ch3_ca (wherever campaigns/ keeps it).
  fs::path owner;
  for (const auto& e : fs::recursive_directory_iterator(source / "campaigns"))
    if (e.path().extension() == ".json" && testing::read_text(e.path()) == shipped) owner = e.path();
  REQUIRE_FALSE(owner.empty());

  // A fresh clone: the tracked campaign.json, no campaign_source, the campaign file in campaigns/.
  const fs::path clone = testing::scratch_dir("owner_fresh_clone");
  const fs::path cloned_owner = clone / fs::relative(owner, source);
  fs::create_directories(cloned_owner.parent_path());
  fs::copy_file(owner, cloned_owner);
  fs::create_directories(clone / "results" / "ch3_ca");
  testing::write_text(clone / "results" / "ch3_ca" / "campaign.json", shipped);

  // A copy elsewhere with one more Ca in its first case, keeping the name.
  nlohmann::json copy = nlohmann::json::parse(shipped);
  auto& ca = copy.at("cases").at(0).at("sweep").at("grid").at("Ca");
  ca.push_back(ca.back().get<double>() * 1.5);
  fs::create_directories(clone / "mine");
  testing::write_text(clone / "mine" / "ch3_ca.json", copy.dump(2));

  const auto before = tree(clone / "results");
  for (const std::string command : {"plan", "status", "run", "report"}) {
    INFO(command);
    const auto out = testing::run_study({command, "mine/ch3_ca.json"}, clone);
    INFO(out.output);
    CHECK(out.exit_code == 2);
    CHECK_THAT(out.output, Catch::Contains("different file with the same name") &&
                               Catch::Contains(fs::absolute(cloned_owner).lexically_normal().string()) &&
                               Catch::Contains((clone / "mine" / "ch3_ca.json").string()));
    CHECK(tree(clone / "results") == before);
  }
  CHECK(testing::read_text(clone / "results" / "ch3_ca" / "campaign.json") == shipped);
  CHECK_FALSE(fs::exists(clone / "results" / "ch3_ca" / "campaign_source"));

  // The tracked file itself, edited the same way, is still the campaign that made the folder.
  testing::write_text(cloned_owner, copy.dump(2));
  const auto edited = testing::run_study({"plan", fs::relative(cloned_owner, clone).string()}, clone);
  INFO(edited.output);
  CHECK(edited.exit_code == 0);
  fs::remove_all(clone);
}
