// The known causes of disagreement are a Markdown file (analysis/dissertation/deviations.md, embedded
// at build time): every "## " cause has its text, its Moves: line and the claims it moves, and a malformed file is
// refused with its line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

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

TEST_CASE("a deviations text without its Moves: line or its links, or with text after them, is refused by line", "[analysis][dissertation]") {
  const std::string gap = "Gap: 3.1 R2 | R^2 at Ca 0.0125 | text 0.99 (\"> 0.99\") | {r2 p/a/recovery} -> {r2 p/b/recovery} | probe p\n";
  const auto parsed = parse_known_deviations("# title\n\nintro\n\n## A\n\nwhy A\nsecond line\n\nMoves: x\n" + gap +
                                             "Gap: 3.2 small Ca | k tau_r | text 1 (the text's words) | {fit p/a/r.k} / {fit p/a/s.k} -> {fit p/b/r.k} | q\n"
                                             "\n## B\n\nwhy B\n\nMoves: y\nClaims: none (nothing measured)\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].text == "why A second line");
  CHECK(parsed[0].claims == std::vector<std::string>{"3.1 R2", "3.2 small Ca"});
  REQUIRE(parsed[0].gaps.size() == 2);
  CHECK(parsed[0].gaps[0].quantity == "R^2 at Ca 0.0125");
  CHECK(parsed[0].gaps[0].text == Approx(0.99));
  CHECK(parsed[0].gaps[0].text_words == "\"> 0.99\"");
  CHECK(parsed[0].gaps[0].toolkit == "{r2 p/a/recovery}");
  CHECK(parsed[0].gaps[0].with_cause == "{r2 p/b/recovery}");
  CHECK(parsed[0].gaps[0].source == "probe p");
  CHECK(parsed[0].gaps[1].toolkit == "{fit p/a/r.k} / {fit p/a/s.k}");
  CHECK(parsed[1].affects == "y");
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\n## B\n\nwhy\n\nMoves: y\n" + gap),
                    Catch::Contains("line 5") && Catch::Contains("no Moves: line"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\n"), Catch::Contains("no Gap: lines"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\n" + gap + "\nstray\n"), Catch::Contains("text after the Moves: line"));
}

TEST_CASE("a cause is linked from a claim only by a Gap: line that says how to measure the share of the gap it closes", "[analysis][dissertation]") {
  // A bare list of claims links without a measurement: refused.
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nClaims: 3.1 R2; 5.2 mesh\n"), Catch::Contains("without a Gap: line"));
  const auto refused = [](const std::string& gap) { return parse_known_deviations("## A\n\nwhy\n\nMoves: y\nGap: " + gap + "\n"); };
  CHECK_THROWS_WITH(refused("3.1 R2 | q | text 0.99 (w) | {r2 p/a/f}"), Catch::Contains("has the form"));
  CHECK_THROWS_WITH(refused("3.1 R2 | q | 0.99 (w) | {r2 p/a/f} -> {r2 p/b/f} | s"), Catch::Contains("text <number>"));
  CHECK_THROWS_WITH(refused("3.1 R2 | q | text 0.99 | {r2 p/a/f} -> {r2 p/b/f} | s"), Catch::Contains("the text's words in parentheses"));
  CHECK_THROWS_WITH(refused("3.1 R2 | q | text 0.99 (w) | {r2 p/a/f} {r2 p/b/f} | s"), Catch::Contains("{toolkit} -> {with the cause}"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nGap: k | q | text 1 (w) | {a} -> {b} | s\nGap: k | q | text 1 (w) | {a} -> {b} | s\n"),
                    Catch::Contains("a second Gap: line for k"));
}

TEST_CASE("a cause no shipped probe measures says \"Claims: none (why)\" and is linked from no claim", "[analysis][dissertation]") {
  const auto parsed = parse_known_deviations("## A\n\nwhy A\n\nMoves: x\nClaims: none (nothing measured)\n\n## B\n\nwhy B\n\nMoves: y\n"
                                             "Gap: 5.2 mesh | D | text 1 (w) | {fit p/a/f.x} -> {fit p/b/f.x} | s\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].claims.empty());
  CHECK(parsed[0].unlinked == "nothing measured");
  CHECK(parsed[1].claims == std::vector<std::string>{"5.2 mesh"});
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nClaims: none\n"), Catch::Contains("needs its reason"));
  CHECK_THROWS_WITH(parse_known_deviations("## A\n\nwhy\n\nMoves: y\nClaims: none (x)\nGap: k | q | text 1 (w) | {a} -> {b} | s\n"),
                    Catch::Contains("text after the Moves: line"));
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

namespace {

std::string source_text(const std::string& relative) {
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/" + relative);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TypedNumber {
  std::string token;  // as typed: "0.669", "47 %"
  double value = 0.0;
  bool percent = false;
};

// The decimal numbers and percentages typed in `text`: placeholders ({...}) and section numbers
// with two dots or more (4.1.1) skipped; integers that are not percentages are not numbers here.
std::vector<TypedNumber> typed_numbers(const std::string& text) {
  std::vector<TypedNumber> out;
  bool in_placeholder = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '{') in_placeholder = true;
    if (text[i] == '}') in_placeholder = false;
    if (in_placeholder || !std::isdigit(static_cast<unsigned char>(text[i]))) continue;
    std::size_t end = i;
    while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.')) ++end;
    std::string token = text.substr(i, end - i);
    while (!token.empty() && token.back() == '.') token.pop_back();
    const auto dots = std::count(token.begin(), token.end(), '.');
    std::size_t after = i + token.size();
    while (after < text.size() && text[after] == ' ') ++after;
    const bool percent = after < text.size() && text[after] == '%';
    if (dots == 1 || (dots == 0 && percent)) out.push_back({token + (percent ? " %" : ""), std::stod(token), percent});
    i = end - 1;
  }
  return out;
}

void json_numbers(const nlohmann::json& j, std::vector<double>& out) {
  if (j.is_number()) out.push_back(j.get<double>());
  if (j.is_structured())
    for (const auto& item : j) json_numbers(item, out);
}

// What a typed number may be: a parameter of the runs (any number in campaigns/), a number claims.md
// quotes from the text, or one analysis/dissertation/typed_numbers.md lists with its source.
struct AllowedNumbers {
  std::vector<TypedNumber> quoted;
  std::vector<double> parameters;
  AllowedNumbers() {
    for (const char* file : {"analysis/dissertation/claims.md", "analysis/dissertation/typed_numbers.md"})
      for (const auto& n : typed_numbers(source_text(file))) quoted.push_back(n);
    for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(CAPSULE_SOURCE_DIR) + "/campaigns"))
      if (entry.path().extension() == ".json") json_numbers(nlohmann::json::parse(std::ifstream(entry.path())), parameters);
  }
  bool allows(const TypedNumber& n) const {
    const auto same = [&n](double v) { return std::abs(v - n.value) <= 1e-9 * std::max(1.0, std::abs(v)); };
    for (const auto& q : quoted)
      if (q.percent == n.percent && same(q.value)) return true;
    return !n.percent && std::any_of(parameters.begin(), parameters.end(), same);
  }
};

// The typed numbers of a deviations.md text (its causes, not the introduction) that nothing allows.
std::vector<std::string> untraced_numbers(const std::string& markdown, const AllowedNumbers& allowed) {
  std::vector<std::string> out;
  const std::size_t causes = markdown.find("\n## ");
  for (const auto& n : typed_numbers(causes == std::string::npos ? markdown : markdown.substr(causes)))
    if (!allowed.allows(n)) out.push_back(n.token);
  return out;
}

}  // namespace

TEST_CASE("Typed numbers: the scan finds decimal numbers and percentages outside placeholders and section numbers", "[analysis][dissertation]") {
  const auto found = typed_numbers("D_xy 0.669 at kt 75 (Sec. 4.1.1), R^2 {r2 p/m/recovery}, 47 % and 5% less, Fig. 30.");
  REQUIRE(found.size() == 3);
  CHECK(found[0].token == "0.669");
  CHECK(found[1].token == "47 %");
  CHECK(found[2].token == "5 %");
  const AllowedNumbers allowed;
  // A measured number typed into the prose is refused; the text's numbers (claims.md) and parameters pass.
  CHECK(untraced_numbers("## A\n\nk tau_r 0.6543 at Ca 0.0125, the text's 2.8, 47 % less\n", allowed) ==
        std::vector<std::string>{"0.6543", "47 %"});
}

TEST_CASE("Typed numbers: every number deviations.md types is a parameter, the text's, or listed with its source", "[analysis][dissertation]") {
  const AllowedNumbers allowed;
  const auto untraced = untraced_numbers(source_text("analysis/dissertation/deviations.md"), allowed);
  std::string list;
  for (const auto& token : untraced) list += token + "; ";
  INFO("typed numbers that are no parameter, not the text's and not in typed_numbers.md (write a measured one as a placeholder): " << list);
  CHECK(untraced.empty());
  // Each Gap: line's text value is the text's number.
  for (const auto& d : known_deviations())
    for (const auto& g : d.gaps) {
      INFO(g.claim);
      CHECK((g.text == std::round(g.text) || allowed.allows({"", g.text, false})));
    }
}
