// What each claim says is a Markdown file (analysis/dissertation/claims.md, embedded at build
// time): every "## " claim has its four lines, a malformed file is refused with its line, every
// {placeholder} must be filled, and every claim of the file is one the code judges.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "analysis/dissertation/claim_texts.hpp"
#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/results.hpp"
#include "tests/analysis/dissertation/claims_md_keys.hpp"

using namespace capsule::analysis;

TEST_CASE("every claim in claims.md has a section, a statement, what tests it and a criterion", "[analysis][dissertation]") {
  const auto keys = capsule::analysis::testing::claims_md_keys();
  REQUIRE(keys.size() == claim_texts().size());  // the embedded copy is the file's (claim_registry_test.cpp: each has a rule)
  for (const auto& key : keys) {
    INFO(key);
    const ClaimText& t = claim_text(key);  // the embedded copy is the file's
    CHECK(t.key == key);
    CHECK(key.rfind(t.section, 0) == 0);  // the key starts with the section
    CHECK(t.statement.size() > 20);
    CHECK((t.tested_by.rfind("ch", 0) == 0 || t.tested_by.rfind("{campaign}", 0) == 0));  // a campaign first
    CHECK(t.criterion.size() > 40);
  }
  CHECK_THROWS_AS(claim_text("no such claim"), std::logic_error);
}

TEST_CASE("a claims text with a line missing, out of order or given twice is refused by line", "[analysis][dissertation]") {
  const std::string one = "## A\n\nSection: 1\nStatement: s\nTested by: ch_x\nCriterion: c\n";
  const auto parsed = parse_claim_texts("# title\n\nintro {x}\n\n" + one + "\n## B\nSection: 2\nStatement: t\nTested by: ch_y, case z\nCriterion: d {n}\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].key == "A");
  CHECK(parsed[1].tested_by == "ch_y, case z");
  CHECK(parsed[1].criterion == "d {n}");
  CHECK_THROWS_WITH(parse_claim_texts("## A\nSection: 1\nStatement: s\nCriterion: c\n"),
                    Catch::Contains("line 4") && Catch::Contains("Tested by: "));
  CHECK_THROWS_WITH(parse_claim_texts("## A\nSection: 1\nStatement: s\n\n## B\n"), Catch::Contains("line 5") && Catch::Contains("lacks"));
  CHECK_THROWS_WITH(parse_claim_texts(one + one), Catch::Contains("given twice"));
  CHECK_THROWS_WITH(parse_claim_texts(one + "stray\n"), Catch::Contains("line 7"));
  // One optional "Re-read: " line after the criterion, never two.
  const auto reread = parse_claim_texts(one + "Re-read: \"the sentence\"; the rule was x, now y\n");
  REQUIRE(reread.size() == 1);
  CHECK(reread[0].reread == "\"the sentence\"; the rule was x, now y");
  CHECK(parsed[0].reread.empty());
  CHECK_THROWS_WITH(parse_claim_texts(one + "Re-read: a\nRe-read: b\n"), Catch::Contains("line 8"));
  CHECK_THROWS_WITH(parse_claim_texts("## A\nSection: 1\nRe-read: a\n"), Catch::Contains("Statement: "));
}

TEST_CASE("claim placeholders are filled, and a missing value is an error naming it", "[analysis][dissertation]") {
  CHECK(fill_placeholders("k tau_r ({case}) over {n} values", {{"case", "2d"}, {"n", "4"}, {"unused", "x"}}, "k") ==
        "k tau_r (2d) over 4 values");
  CHECK(fill_placeholders("no placeholder", {}, "k") == "no placeholder");
  CHECK_THROWS_WITH(fill_placeholders("over {n} values", {}, "3.2 x"), Catch::Contains("3.2 x") && Catch::Contains("{n}"));
  CHECK_THROWS_WITH(fill_placeholders("open {n", {{"n", "1"}}, "k"), Catch::Contains("unclosed"));
}

TEST_CASE("every claim of claims.md is judged, with every placeholder filled", "[analysis][dissertation]") {
  // From an empty results folder every claim says "cannot tell", but each has read its text:
  // an unknown key or an unfilled placeholder would throw here.
  const auto dir = std::filesystem::temp_directory_path() / "capsule_claim_texts_empty";
  const auto claims = evaluate_claims(DissertationResults(dir.string()));
  for (const auto& c : claims) {
    INFO(c.statement);
    CHECK(c.statement.find('{') == std::string::npos);
    CHECK(c.criterion.find('{') == std::string::npos);
    CHECK(c.measured.rfind("cannot tell", 0) == 0);
  }
  // And the code judges every claim of the file: each key's statement (up to its first
  // placeholder) and criterion (likewise) open some judged claim of its section.
  for (const auto& key : capsule::analysis::testing::claims_md_keys()) {
    INFO(key);
    const ClaimText& t = claim_text(key);
    const std::string statement = t.statement.substr(0, t.statement.find('{'));
    const std::string criterion = t.criterion.substr(0, t.criterion.find('{'));
    bool judged = false;
    for (const auto& c : claims)
      judged = judged || (c.section == t.section && c.statement.rfind(statement, 0) == 0 && c.criterion.rfind(criterion, 0) == 0);
    CHECK(judged);
  }
}

TEST_CASE("one verdict per claim from its rows: all agree, all differ, none judged, or in part", "[analysis][dissertation]") {
  const auto row = [](const std::string& key, Verdict v) {
    ClaimResult r;
    r.key = key;
    r.verdict = v;
    return r;
  };
  const auto verdicts = claim_verdicts({row("a", Verdict::agrees), row("a", Verdict::agrees), row("b", Verdict::differs),
                                        row("c", Verdict::agrees), row("c", Verdict::differs), row("d", Verdict::cannot_tell),
                                        row("e", Verdict::agrees), row("e", Verdict::cannot_tell), row("f", Verdict::differs)});
  REQUIRE(verdicts.size() == 6);
  CHECK(verdicts[0] == std::make_pair(std::string("a"), ClaimVerdict::agrees));
  CHECK(verdicts[1].second == ClaimVerdict::differs);
  CHECK(verdicts[2].second == ClaimVerdict::in_part);      // the circle agrees, the sphere differs
  CHECK(verdicts[3].second == ClaimVerdict::cannot_tell);
  CHECK(verdicts[4].second == ClaimVerdict::in_part);      // one row judged, one not
  CHECK(verdicts[5] == std::make_pair(std::string("f"), ClaimVerdict::differs));
}
