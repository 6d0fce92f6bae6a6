// results/THESIS.md as a reader meets it: the bottom line and one short table per chapter first,
// every row short, every link resolving (to a shipped figure or an anchor of the document), the
// bottom line's counts those of the verdicts; and the data it is made from (figures.md, the
// Claims: lines of deviations.md) naming claims and files that exist.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "analysis/dissertation/bottom_line.hpp"
#include "analysis/dissertation/chapter_story.hpp"
#include "analysis/dissertation/prose_lines.hpp"
#include "analysis/dissertation/chapter_tables.hpp"
#include "analysis/dissertation/claim_texts.hpp"
#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/figure_index.hpp"
#include "analysis/dissertation/report.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;
namespace fs = std::filesystem;

namespace {

const fs::path k_shipped_results = fs::path(CAPSULE_SOURCE_DIR) / "results";

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// THESIS.md made from the shipped results, written into a scratch folder beside them so that
// its figure links are relative paths into the repository's results/ (made once: it reads
// every shipped campaign).
struct ShippedThesis {
  fs::path file;
  std::string md;
  DissertationSummary summary;
  std::vector<ClaimResult> rows;
};
const ShippedThesis& shipped_thesis() {
  static const ShippedThesis t = [] {
    static TempDir tmp("thesis_document");
    ShippedThesis out;
    out.file = tmp.path / "THESIS.md";
    out.summary = write_dissertation(k_shipped_results.string(), out.file.string());
    out.md = read_text(out.file);
    out.rows = evaluate_claims_at_two_levels(DissertationResults(k_shipped_results.string()));
    return out;
  }();
  return t;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The text between the heading `from` and the next "## " heading.
std::string section(const std::string& md, const std::string& from) {
  const std::size_t start = md.find(from);
  if (start == std::string::npos) return "";
  const std::size_t end = md.find("\n## ", start + from.size());
  return md.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// Every Markdown link target of `md`, and every <a id> it defines.
std::vector<std::string> link_targets(const std::string& md) {
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(md.begin(), md.end(), link); it != std::sregex_iterator(); ++it) out.push_back((*it)[1]);
  return out;
}
std::set<std::string> anchors(const std::string& md) {
  static const std::regex id(R"re(<a id="([^"]+)"></a>)re");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(md.begin(), md.end(), id); it != std::sregex_iterator(); ++it) out.insert((*it)[1]);
  return out;
}

// Fails for every link of the document at `file` that names no file beside it or no anchor in it.
int check_links(const fs::path& file, const std::string& md) {
  const auto ids = anchors(md);
  int figures = 0;
  for (const auto& target : link_targets(md)) {
    INFO(file.string() << " links to " << target);
    if (target.rfind('#', 0) == 0) {
      CHECK(ids.count(target.substr(1)) == 1);
    } else {
      CHECK(fs::is_regular_file(file.parent_path() / target));
      figures += target.size() > 4 && target.substr(target.size() - 4) == ".png";
    }
  }
  return figures;
}

// One row of a claim's verdict, for the document's counting and stories.
ClaimResult claim_row(const std::string& key, const std::string& section, Verdict v) {
  ClaimResult r;
  r.key = key;
  r.section = section;
  r.verdict = v;
  return r;
}

}  // namespace

TEST_CASE("Thesis document: the first screen is the bottom line and one table per chapter", "[analysis][dissertation]") {
  const auto& t = shipped_thesis();
  const auto lines = lines_of(t.md);
  REQUIRE(lines.size() > 10);
  CHECK(lines[0] == "# The dissertation beside this toolkit");
  // the bottom line comes before any table, within the first lines
  std::size_t bottom = 0;
  while (bottom < lines.size() && lines[bottom].rfind("**Bottom line**", 0) != 0) ++bottom;
  CHECK(bottom < 6);
  const std::string first_screen = section(t.md, "## Claims by chapter");
  REQUIRE_FALSE(first_screen.empty());
  CHECK(t.md.find("## Claims by chapter") < t.md.find("## Figures"));
  CHECK(t.md.find("## Figures") < t.md.find("## Table 2"));
  std::size_t at = 0;
  for (const auto& chapter : text_chapters()) {
    INFO(chapter.title);
    const std::size_t heading = first_screen.find("### " + chapter.title, at);
    REQUIRE(heading != std::string::npos);
    CHECK(first_screen.find("| claim | the text | the toolkit | verdict | text passes | cause |", heading) != std::string::npos);
    at = heading;
  }
}

TEST_CASE("Thesis document: every row of the chapter tables is short and links its claim's details", "[analysis][dissertation]") {
  const auto& t = shipped_thesis();
  const auto ids = anchors(t.md);
  std::size_t rows = 0;
  for (const auto& line : lines_of(section(t.md, "## Claims by chapter"))) {
    if (line.rfind("| [", 0) != 0) continue;
    ++rows;
    INFO(line);
    CHECK(line.size() <= k_short_row_characters);
    const std::string target = line.substr(line.find("](#") + 3, line.find(')') - line.find("](#") - 3);
    CHECK(ids.count(target) == 1);
  }
  CHECK(rows == t.rows.size());
}

TEST_CASE("Thesis document: every link resolves, and at least 15 toolkit figures are linked", "[analysis][dissertation]") {
  const auto& t = shipped_thesis();
  const int figures = check_links(t.file, t.md);
  CHECK(figures >= 15);
  CHECK(t.summary.linked_figures >= 15);
  // the committed document too: a figure renamed or removed breaks it until it is regenerated
  const fs::path committed = k_shipped_results / "THESIS.md";
  REQUIRE(fs::exists(committed));
  CHECK(check_links(committed, read_text(committed)) >= 15);
}

TEST_CASE("Thesis document: the bottom line's counts are the verdicts' counts", "[analysis][dissertation]") {
  const auto& t = shipped_thesis();
  std::map<ClaimVerdict, int> count;
  const auto verdicts = claim_verdicts(t.rows);
  for (const auto& [key, v] : verdicts) ++count[v];
  const std::size_t from = t.md.find("**Bottom line**");
  const std::string bottom = t.md.substr(from, t.md.find("## Claims by chapter") - from);
  INFO(bottom);
  // "1 claim agrees", "2 claims agree"
  const auto claims = [](int n, const std::string& plural_verb, const std::string& singular_verb) {
    return std::to_string(n) + (n == 1 ? " claim" + singular_verb : " claims" + plural_verb);
  };
  CHECK(bottom.find("(the dissertation's " + claims(static_cast<int>(verdicts.size()), "", "")) != std::string::npos);
  CHECK(bottom.find("**Reproduced:** " + claims(count[ClaimVerdict::agrees], " agree", " agrees")) != std::string::npos);
  CHECK(bottom.find("**Not reproduced:** " + claims(count[ClaimVerdict::differs], " differ", " differs")) != std::string::npos);
  if (count[ClaimVerdict::in_part] > 0)
    CHECK(bottom.find(claims(count[ClaimVerdict::in_part], " hold", " holds") + " only in part") != std::string::npos);
  CHECK(bottom.find("**Cannot tell:** " + claims(count[ClaimVerdict::cannot_tell], ",", ",")) != std::string::npos);
  CHECK(t.summary.claims_agree == count[ClaimVerdict::agrees]);
  CHECK(t.summary.claims_differ == count[ClaimVerdict::differs]);
  CHECK(t.summary.claims_in_part == count[ClaimVerdict::in_part]);
  CHECK(t.summary.claims_cannot_tell == count[ClaimVerdict::cannot_tell]);
  // each claim that cannot be told is named in it (a long line is wrapped, possibly inside a link's text)
  std::string flat;
  for (std::size_t i = 0; i < bottom.size(); ++i) {
    if (bottom[i] != '\n') {
      flat += bottom[i];
      continue;
    }
    while (i + 1 < bottom.size() && bottom[i + 1] == ' ') ++i;
    flat += ' ';
  }
  for (const auto& [key, v] : verdicts)
    if (v == ClaimVerdict::cannot_tell) CHECK(flat.find("[" + key + "](#" + claim_anchor(key) + ")") != std::string::npos);
}

TEST_CASE("Thesis document: figures.md and the causes' Claims: lines name claims and shipped files that exist", "[analysis][dissertation]") {
  const auto keys = [] {
    std::set<std::string> k;
    for (const auto& t : parse_claim_texts(read_text(fs::path(CAPSULE_SOURCE_DIR) / "analysis/dissertation/claims.md"))) k.insert(t.key);
    return k;
  }();
  const auto& figures = figure_index();
  REQUIRE(figures.size() == parse_figure_index(read_text(fs::path(CAPSULE_SOURCE_DIR) / "analysis/dissertation/figures.md")).size());
  std::set<std::string> numbers;
  for (const auto& f : figures) {
    INFO("Fig. " << f.number);
    CHECK(numbers.insert(f.number).second);
    CHECK_FALSE(f.shows.empty());
    for (const auto& key : f.claims) CHECK(keys.count(key) == 1);
    for (const auto& file : f.files) {
      INFO(file);
      // A campaign being rerun ships its report with INCOMPLETE.md (`study report` on an
      // unfinished campaign): its figures of members not yet run are missing until they run.
      const fs::path campaign_report = k_shipped_results / fs::path(file).begin()->string() / "report";
      if (!fs::is_regular_file(k_shipped_results / file) && fs::is_regular_file(campaign_report / "INCOMPLETE.md")) {
        WARN("Fig. " << f.number << ": " << file << " awaits its campaign's members (report INCOMPLETE.md)");
        continue;
      }
      CHECK(fs::is_regular_file(k_shipped_results / file));
    }
  }
  for (const auto& d : known_deviations()) {
    INFO(d.topic);
    CHECK(d.claims.empty() != d.unlinked.empty());  // linked from claims, or "Claims: none (why)"
    for (const auto& key : d.claims) CHECK(keys.count(key) == 1);
  }
}

TEST_CASE("Thesis document: a figures table row with a wrong number of cells is refused by line", "[analysis][dissertation]") {
  const auto parsed = parse_figure_index("# t\n\n| Fig. | shows | files | claims |\n|---|---|---|---|\n| 15 | times | a/b.png; c/d.png | 3.2 modest |\n| 13 | why not | | |\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].files == std::vector<std::string>{"a/b.png", "c/d.png"});
  CHECK(parsed[0].claims == std::vector<std::string>{"3.2 modest"});
  CHECK(parsed[1].files.empty());
  CHECK_THROWS_WITH(parse_figure_index("| a | b |\n|---|---|\n| 1 | x |\n"), Catch::Contains("line 3") && Catch::Contains("4 cells"));
}

TEST_CASE("Thesis document: a long cell is cut at a word, and anchors are stable ids", "[analysis][dissertation]") {
  CHECK(clip_text("short", 10) == "short");
  const std::string cut = clip_text("k tau_r: Ca 0.05: 0.984, Ca 0.1: 1.65, Ca 0.2: 2.97", 30);
  CHECK(cut.size() <= 30);
  CHECK(cut == "k tau_r: Ca 0.05: 0.984 …");
  CHECK(clip_text("spread 0.1; D_xy at the stop: level 3: 0.246, level 4: 0.246", 40) == "spread 0.1; D_xy at the stop: level …");  // too early a clause: at a word
  CHECK(clip_text("falls by 67.1 %; k tau_r: E_b 0.025: 1.27, E_b 0.05: 0.846", 40) == "falls by 67.1 % …");
  CHECK(anchor_id("claim", "3.2 small Ca") == "claim-3-2-small-ca");
  CHECK(claim_anchor("5.1.2 V*") == "claim-5-1-2-v");
  CHECK(split_list(" a; b ;; c") == std::vector<std::string>{"a", "b", "c"});
}

TEST_CASE("Thesis document: the bottom line's verbs follow its counts (1 claim agrees, 2 claims differ)", "[analysis][dissertation]") {
  const auto row = claim_row;
  // one claim agrees, two differ, one holds in part (its two rows disagree), one cannot be told
  const std::vector<ClaimResult> rows = {row("3.1 one", "3.1", Verdict::agrees),      row("3.1 two", "3.1", Verdict::differs),
                                         row("3.2 three", "3.2", Verdict::differs),    row("3.3 four", "3.3", Verdict::agrees),
                                         row("3.3 four", "3.3", Verdict::differs),     row("5.2 five", "5.2", Verdict::cannot_tell)};
  const std::string md = bottom_line_markdown(rows, DissertationSummary{});
  INFO(md);
  CHECK(md.find("(the dissertation's 5 claims against") != std::string::npos);
  CHECK(md.find("**Reproduced:** 1 claim agrees (Ch. 3: 1)") != std::string::npos);
  CHECK(md.find("**Not reproduced:** 2 claims differ (Ch. 3: 2), and 1 claim holds only in part") != std::string::npos);
  CHECK(md.find("**Cannot tell:** 1 claim, for want of") != std::string::npos);
}

TEST_CASE("Thesis document: prose is wrapped at 400 characters, list items indented, tables untouched", "[analysis][dissertation]") {
  std::string words;
  for (int i = 0; i < 150; ++i) words += "word" + std::to_string(i) + " ";
  words.pop_back();
  const std::string row = "| " + words + " |";
  const std::string wrapped = wrap_prose_lines("- " + words + "\n" + row + "\n", 100);
  const auto lines = lines_of(wrapped);
  REQUIRE(lines.size() > 3);
  CHECK(lines.back() == row);  // a table row is never broken
  std::string joined;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    INFO(lines[i]);
    CHECK(lines[i].size() <= 100);
    if (i > 0) CHECK(lines[i].rfind("  word", 0) == 0);  // the item's continuation
    joined += (i ? " " : "") + lines[i].substr(i ? 2 : 0);
  }
  CHECK(joined == "- " + words);  // nothing lost or added but the breaks
  // The shipped document: every line but a table row at most 400 characters.
  for (const auto& line : lines_of(shipped_thesis().md)) {
    if (line.rfind("|", 0) == 0) continue;
    INFO(line.substr(0, 120));
    CHECK(line.size() <= k_prose_line_characters);
  }
}

TEST_CASE("Thesis document: the first screen says per chapter where the text holds and which differences are unexplained", "[analysis][dissertation]") {
  const auto row = claim_row;
  // "5.9 closed" has a cause that closes 40 % of its gap, "5.9 widened" one that widens it, "5.9 nothing" none
  const std::vector<ClaimResult> rows = {row("3.9 one", "3.1", Verdict::agrees),      row("5.9 closed", "5.1", Verdict::differs),
                                         row("5.9 widened", "5.2", Verdict::differs), row("5.9 nothing", "5.2", Verdict::differs),
                                         row("5.9 open", "5.2", Verdict::cannot_tell)};
  const auto grade = [](const std::string& key, double fraction) {
    CauseGrade g;
    g.cause = 8, g.gap.claim = key, g.measured = true, g.fraction = fraction;
    return g;
  };
  const std::vector<CauseGrade> grades = {grade("5.9 closed", 0.4), grade("5.9 widened", -0.5)};
  const std::string md = chapter_story_markdown(rows, grades);
  INFO(md);
  CHECK(md.find("- **Ch. 3**: the text holds in 1 of its 1 claim here; it does not in 0.") != std::string::npos);
  CHECK(md.find("- **Ch. 5**: the text holds in 0 of its 4 claims here; it does not in 3; 1 cannot tell. Of those that differ: 1 with a "
                "measured cause closing part of the gap (the most: [C8](#cause-8) " + known_deviations()[7].topic +
                " closes 40 % of the gap of [5.9 closed](#claim-5-9-closed))") != std::string::npos);
  CHECK(md.find(", 2 unexplained ([C8](#cause-8) measured: it widens or barely moves the gap): [5.9 widened](#claim-5-9-widened)") != std::string::npos);
  CHECK(md.find("Ch. 2") == std::string::npos);
  // The chapter table's cause cell: the share closed, and "unexplained" where no cause closes part of the gap.
  CHECK(cause_links("5.9 closed", Verdict::differs, grades) == "[C8](#cause-8) 40 %");
  CHECK(cause_links("5.9 widened", Verdict::differs, grades) == "[C8](#cause-8) -50 %, unexplained");
  CHECK(cause_links("5.9 nothing", Verdict::differs, grades) == "unexplained");
  CHECK(cause_links("3.9 one", Verdict::agrees, grades).empty());
}
