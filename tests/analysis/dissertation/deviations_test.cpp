// The known causes of disagreement are a Markdown file (analysis/dissertation/deviations.md, embedded
// at build time): every "## " cause has its text and its Moves: line, and a malformed file is
// refused with its line.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "analysis/dissertation/deviations.hpp"

using namespace capsule::analysis;

TEST_CASE("every cause in deviations.md has a topic, a text and what it moves", "[analysis][dissertation]") {
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/analysis/dissertation/deviations.md");
  std::stringstream file;
  file << in.rdbuf();
  std::size_t headings = 0;
  for (std::string line; std::getline(file, line);) headings += line.rfind("## ", 0) == 0;
  const auto& d = known_deviations();
  REQUIRE(d.size() == headings);  // the embedded copy is the file's
  REQUIRE(headings >= 10);
  for (const auto& k : d) {
    INFO(k.topic);
    CHECK_FALSE(k.topic.empty());
    CHECK(k.text.size() > 40);
    CHECK_FALSE(k.affects.empty());
  }
  CHECK(known_deviations_markdown().find("- **" + d.front().topic + ".** ") == 0);
}

TEST_CASE("a deviations text without its Moves: line, or with text after it, is refused by line", "[analysis][dissertation]") {
  const auto parsed = parse_known_deviations("# title\n\nintro\n\n## A\n\nwhy A\nsecond line\n\nMoves: x\n\n## B\n\nwhy B\n\nMoves: y\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].text == "why A second line");
  CHECK(parsed[1].affects == "y");
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\n## B\n\nwhy\n\nMoves: y\n"),
                    Catch::Contains("line 5") && Catch::Contains("no Moves: line"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\n\nstray\n"), Catch::Contains("text after the Moves: line"));
}
