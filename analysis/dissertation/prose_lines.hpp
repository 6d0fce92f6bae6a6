#pragma once
// THESIS.md's prose is wrapped so that no line is longer than a reader's screen allows: a long line
// (a paragraph, a list item) is broken at blanks into lines of at most k_prose_line_characters,
// continuation lines indented as the list item's text, which Markdown renders unchanged. Table rows
// (lines starting with '|') and headings are left as they are.
#include <cstddef>
#include <string>

namespace capsule::analysis {

inline constexpr std::size_t k_prose_line_characters = 400;

std::string wrap_prose_lines(const std::string& markdown, std::size_t limit = k_prose_line_characters);

}  // namespace capsule::analysis
