// `study thesis` writes THESIS.md from whatever results exist: with none run, every claim
// and Table 2 row says "cannot tell", and the command still succeeds.
#include <catch2/catch.hpp>

#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("study thesis writes THESIS.md from a results folder with no campaign run", "[study]") {
  const fs::path dir = testing::scratch_dir("thesis");
  fs::create_directories(dir / "results");

  const auto plain = testing::run_study({"thesis"}, dir);  // default: results/THESIS.md
  INFO(plain.output);
  CHECK(plain.exit_code == 0);
  REQUIRE(fs::exists(dir / "results" / "THESIS.md"));
  CHECK(plain.output.find("0 agree, 0 differ") != std::string::npos);

  const auto named = testing::run_study({"thesis", "--results", "results", "-o", "out/T.md"}, dir);
  INFO(named.output);
  CHECK(named.exit_code == 0);
  const std::string md = testing::read_text(dir / "out" / "T.md");
  CHECK(md.find("cannot tell (campaign ch5_bilinear_ca005 not run") != std::string::npos);
  CHECK(md.find("## Known causes of disagreement") != std::string::npos);

  // `study dissertation` is the same command under the word the documents use.
  const auto alias = testing::run_study({"dissertation", "-o", "out/D.md"}, dir);
  INFO(alias.output);
  CHECK(alias.exit_code == 0);
  CHECK(testing::read_text(dir / "out" / "D.md") == testing::read_text(dir / "results" / "THESIS.md"));
  fs::remove_all(dir);
}
