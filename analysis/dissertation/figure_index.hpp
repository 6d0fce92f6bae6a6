#pragma once
// The dissertation's figures beside the toolkit's: which figure of the text each shipped
// campaign's report regenerates with the same axes and quantities, and which claims it shows.
// The table is data, analysis/dissertation/figures.md (embedded at build time); this file
// reads it and writes THESIS.md's "Figures" section.
#include <string>
#include <vector>

namespace capsule::analysis {

struct TextFigure {
  std::string number;                // the dissertation's figure number, e.g. "15"
  std::string shows;                 // what it shows (or, with no toolkit figure, why none)
  std::vector<std::string> files;    // the toolkit's figures, relative to the results folder
  std::vector<std::string> claims;   // keys of claims.md it illustrates
};

// The cells of a Markdown table row "| a | b |", blanks around each trimmed.
std::vector<std::string> markdown_row_cells(const std::string& line);

// The body rows of a Markdown text's table: every "|" line below the header and its |---|
// line, with its line number in the text (for messages).
struct MarkdownRow {
  int line_number = 0;
  std::vector<std::string> cells;
};
std::vector<MarkdownRow> markdown_table_rows(const std::string& markdown);

// The rows of a figures.md text: every table row below the header and its |---| line, four
// cells (figure, shows, files, claims; lists separated by ';'). Throws std::runtime_error naming
// the line for a row with another number of cells or without a figure number.
std::vector<TextFigure> parse_figure_index(const std::string& markdown);

// The embedded figures.md.
const std::vector<TextFigure>& figure_index();

// The figures that show claim `claim_key`, in the order of the text.
std::vector<const TextFigure*> figures_of_claim(const std::string& claim_key);

// A figure's toolkit files as Markdown links relative to the document (`link_base`: the path
// from the document's folder to the results folder, "." when it lies in it), each labelled by
// its campaign and file name; a file missing under `results_dir` is named "(not shipped)"
// without a link. Joined by ", ".
std::string figure_links(const TextFigure& figure, const std::string& results_dir, const std::string& link_base);

// The number of files of `figures` present under `results_dir` (the links figure_links writes).
int linked_figure_count(const std::vector<TextFigure>& figures, const std::string& results_dir);

// THESIS.md's "Figures" section body: one table of the regenerated figures (the text's figure,
// what it shows, the toolkit's figures, the claims linked to their detail sections), then the
// figures of the text no shipped campaign regenerates, with why.
std::string figures_markdown(const std::string& results_dir, const std::string& link_base);

}  // namespace capsule::analysis
