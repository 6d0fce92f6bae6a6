#include "analysis/dissertation/chapter_tables.hpp"

#include <algorithm>

#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/report/table.hpp"

namespace capsule::analysis {

namespace {

// Bytes the Markdown row adds around its cells ("| " before each cell, " |" after the last),
// and room for the "\\" before a '|' inside a cell.
std::size_t row_overhead(std::size_t cells) { return 2 * cells + 1 + 8; }

}  // namespace

const std::vector<TextChapter>& text_chapters() {
  static const std::vector<TextChapter> c = {
      {"2", "Chapter 2: the solvers against published results"},
      {"3", "Chapter 3: circle and sphere, response and recovery times"},
      {"4", "Chapter 4: biconcave capsules, tank-treading, tumbling and shape memory"},
      {"5", "Chapter 5: the bilinear model of the times, and the power-law membrane"}};
  return c;
}

std::string clip_text(const std::string& text, std::size_t limit) {
  static const std::string ellipsis = " …";
  if (text.size() <= limit) return text;
  if (limit <= ellipsis.size()) return ellipsis.substr(1);
  // At the end of a clause ("; ") where one ends in the last two thirds of the room, else at a word.
  std::size_t cut = text.rfind("; ", limit - ellipsis.size() - 1);
  if (cut == std::string::npos || cut < limit / 3) cut = text.rfind(' ', limit - ellipsis.size());
  if (cut == std::string::npos || cut == 0) cut = limit - ellipsis.size();
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // never inside a UTF-8 character
  std::string out = text.substr(0, cut);
  while (!out.empty() && (out.back() == ' ' || out.back() == ';' || out.back() == ',')) out.pop_back();
  return out + ellipsis;
}

std::string cause_links(const std::string& claim_key, Verdict verdict, const std::vector<CauseGrade>& grades) {
  std::string out;
  bool explained = false;
  for (const CauseGrade* g : grades_of_claim(grades, claim_key)) {
    append_listed(out, anchor_link(cause_label(g->cause), cause_anchor(g->cause)) + " " + closes_percent(*g));
    explained = explained || explains(*g);
  }
  if (verdict == Verdict::differs && !explained) append_listed(out, "unexplained");
  return out;
}

std::string chapter_tables_markdown(const std::vector<ClaimResult>& rows, const std::vector<CauseGrade>& grades) {
  std::string md;
  for (const auto& chapter : text_chapters()) {
    Table t;
    t.header = {"claim", "the text", "the toolkit", "verdict", "text passes", "cause"};
    for (const auto& r : rows) {
      if (claim_chapter(r) != chapter.number) continue;
      const std::string claim = anchor_link(r.key, claim_anchor(r.key));
      const std::string levels = levels_text(r.levels);
      const std::string verdict = std::string(verdict_text(r.verdict)) + (levels.empty() ? "" : " (" + levels + ")");
      const std::string causes = cause_links(r.key, r.verdict, grades);
      const std::string text_passes = text_passes_text(r.text_passes);
      // What the claim, verdict and causes leave of the row goes to the two texts: the text's
      // words first (up to half and a little more), the toolkit's numbers the rest.
      const std::size_t fixed = claim.size() + verdict.size() + text_passes.size() + causes.size() + row_overhead(t.header.size());
      const std::size_t left = k_short_row_characters > fixed + 40 ? k_short_row_characters - fixed : 40;
      const std::size_t text_room = std::max<std::size_t>(left * 11 / 20, left > r.measured.size() ? left - r.measured.size() : 0);
      const std::string text = clip_text(r.statement, text_room);
      const std::string toolkit = clip_text(r.measured, left > text.size() + 20 ? left - text.size() : 20);
      t.rows.push_back({claim, text, toolkit, verdict, text_passes, causes});
    }
    md += "### " + chapter.title + "\n\n" + t.to_markdown() + "\n";
  }
  return md;
}

}  // namespace capsule::analysis
