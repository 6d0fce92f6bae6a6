// The known causes of disagreement are a Markdown file (analysis/dissertation/deviations.md, embedded
// at build time): every "## " cause has its text, its Moves: line and the claims it moves, and a malformed file is
// refused with its line.
#include <catch2/catch.hpp>

#include <algorithm>
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
    CHECK(k.claims.empty() != k.unlinked.empty());  // linked from claims, or says why it is not
  }
  CHECK(known_deviations_markdown().find("- <a id=\"cause-1\"></a>**C1 " + d.front().topic + ".** ") == 0);
}

TEST_CASE("a deviations text without its Moves: or Claims: line, or with text after them, is refused by line", "[analysis][dissertation]") {
  const auto parsed = parse_known_deviations(
      "# title\n\nintro\n\n## A\n\nwhy A\nsecond line\n\nMoves: x\nClaims: 3.1 R2; 3.2 small Ca\n\n## B\n\nwhy B\n\nMoves: y\nClaims: 5.2 mesh\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].text == "why A second line");
  CHECK(parsed[0].claims == std::vector<std::string>{"3.1 R2", "3.2 small Ca"});
  CHECK(parsed[1].affects == "y");
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\n## B\n\nwhy\n\nMoves: y\nClaims: k\n"),
                    Catch::Contains("line 5") && Catch::Contains("no Moves: line"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\n"), Catch::Contains("no Claims: line"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nClaims: k\n\nstray\n"), Catch::Contains("text after the Moves: line"));
}

TEST_CASE("a cause no shipped probe measures says \"Claims: none (why)\" and is linked from no claim", "[analysis][dissertation]") {
  const auto parsed = parse_known_deviations("## A\n\nwhy A\n\nMoves: x\nClaims: none (nothing measured)\n\n## B\n\nwhy B\n\nMoves: y\nClaims: 5.2 mesh\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].claims.empty());
  CHECK(parsed[0].unlinked == "nothing measured");
  CHECK(parsed[1].claims == std::vector<std::string>{"5.2 mesh"});
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nClaims: none\n"), Catch::Contains("needs its reason"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nClaims: none (x)\nClaims: k\n"), Catch::Contains("text after the Moves: line"));
  // The causes deviations.md unlinks for want of a measurement are named by no claim's row.
  const auto& d = known_deviations();
  for (std::size_t i = 0; i < d.size(); ++i)
    if (!d[i].unlinked.empty())
      for (const char* key : {"3.1 overshoot", "3.3 falls", "5.1.1 similar", "3.1 R2", "2 G"}) {
        const auto numbers = causes_of_claim(key);
        CHECK(std::find(numbers.begin(), numbers.end(), i + 1) == numbers.end());
      }
}

TEST_CASE("a claim is linked from the causes whose Claims: line names it", "[analysis][dissertation]") {
  const auto& d = known_deviations();
  for (std::size_t i = 0; i < d.size(); ++i)
    for (const auto& key : d[i].claims) {
      const auto numbers = causes_of_claim(key);
      CHECK(std::find(numbers.begin(), numbers.end(), i + 1) != numbers.end());
    }
  CHECK(causes_of_claim("no such claim").empty());
}
