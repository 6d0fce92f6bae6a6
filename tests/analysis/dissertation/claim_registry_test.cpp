// The claim registry (analysis/dissertation/claims/registry.hpp) and the words of claims.md agree:
// every registered rule has its words, every worded claim a rule, no key twice; evaluate_claims
// gives each claim's rows in the order of claims.md.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "analysis/dissertation/claim_texts.hpp"
#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/claims/registry.hpp"
#include "analysis/dissertation/results.hpp"
#include "tests/analysis/dissertation/claims_md_keys.hpp"

using namespace capsule::analysis;

namespace {
std::vector<std::string> registered_keys() {
  std::vector<std::string> keys;
  for (const auto& c : claims::claim_registry()) keys.push_back(c.key);
  return keys;
}

}  // namespace

TEST_CASE("claim registry: every registered claim has words in claims.md and every worded claim a rule", "[analysis][dissertation]") {
  const auto registered = registered_keys();
  const auto worded = capsule::analysis::testing::claims_md_keys();
  REQUIRE_FALSE(worded.empty());
  for (const auto& m : claims::registry_mismatches(registered, worded)) FAIL_CHECK(m);
  CHECK(registered.size() == worded.size());
  for (const auto& c : claims::claim_registry()) {
    INFO(c.key);
    CHECK_FALSE(c.rows.empty());
  }
}

TEST_CASE("claim registry: a rule without words, words without a rule and a key registered twice are named", "[analysis][dissertation]") {
  CHECK(claims::registry_mismatches({"a", "b"}, {"b", "a"}).empty());
  const auto m = claims::registry_mismatches({"a", "b", "a", "r"}, {"a", "b", "w"});
  REQUIRE(m.size() == 3);
  CHECK(m[0] == "the claim 'a' is registered twice");
  CHECK(m[1] == "the claim 'r' has a rule but no words in analysis/dissertation/claims.md");
  CHECK(m[2].find("'w' of analysis/dissertation/claims.md has no rule") != std::string::npos);
}

TEST_CASE("claim registry: evaluate_claims gives every claim's rows, in the order of claims.md", "[analysis][dissertation]") {
  const auto dir = std::filesystem::temp_directory_path() / "capsule_claim_registry_empty";
  const auto rows = evaluate_claims(DissertationResults(dir.string()));
  std::vector<std::string> keys;  // the rows' keys, each once, in order
  for (const auto& r : rows)
    if (keys.empty() || keys.back() != r.key) keys.push_back(r.key);
  CHECK(keys == capsule::analysis::testing::claims_md_keys());
  std::size_t expected_rows = 0;
  for (const auto& c : claims::claim_registry()) expected_rows += c.rows.size();
  CHECK(rows.size() == expected_rows);
}
