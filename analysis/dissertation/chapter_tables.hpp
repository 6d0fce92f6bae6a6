#pragma once
// THESIS.md's first screen after the bottom line: one table per chapter of the text (2-5), a
// short row per claim row (the claim, linked to its detail section; what the text says; what
// the toolkit measures; the verdict; the known causes that move it, linked), each row at most
// k_short_row_characters long: a cell that does not fit is cut at a word and ends in " …", its
// whole text being in the claim's detail section.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/claims.hpp"

namespace capsule::analysis {

inline constexpr std::size_t k_short_row_characters = 200;

// The chapters of the text that have claims, in order (2-5), with what each is about.
struct TextChapter {
  std::string number;  // as claim_chapter gives it
  std::string title;
};
const std::vector<TextChapter>& text_chapters();

// `text` cut to at most `limit` bytes at the end of a clause ("; ") or else at a blank, with " …"
// appended when cut.
std::string clip_text(const std::string& text, std::size_t limit);

// The known causes of claim `key`, each linked with the share of the gap it closes,
// "[C3](#cause-3) 35 %, [C8](#cause-8) -42 %"; where the claim differs (`verdict`) and no cause
// closes part of its gap, "unexplained" is added ("" for a claim that agrees with no cause).
std::string cause_links(const std::string& claim_key, Verdict verdict, const std::vector<CauseGrade>& grades);

// The tables, each under a "### Chapter n: ..." heading.
std::string chapter_tables_markdown(const std::vector<ClaimResult>& rows, const std::vector<CauseGrade>& grades);

}  // namespace capsule::analysis
