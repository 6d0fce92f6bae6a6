// README's campaign example (a ```jsonc block with // and /* */ comments) parses as written.
#include <catch2/catch.hpp>

#include "study/campaign/campaign.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;

TEST_CASE("the campaign example in README.md parses, comments and all", "[study]") {
  const std::string readme = testing::read_text(std::filesystem::path(CAPSULE_SOURCE_DIR) / "README.md");
  const auto start = readme.find("```jsonc\n");
  REQUIRE(start != std::string::npos);
  const auto end = readme.find("```", start + 9);
  REQUIRE(end != std::string::npos);
  const std::string example = readme.substr(start + 9, end - start - 9);
  REQUIRE(example.find("//") != std::string::npos);
  Campaign c;
  REQUIRE_NOTHROW(c = parse_campaign(example, "README.md"));
  CHECK(c.name == "ch3_ca");
  CHECK(c.sweep.grid.size() == 1);
  CHECK(c.sweep.zip.size() == 2);
  CHECK(c.cases.size() == 2);
}
