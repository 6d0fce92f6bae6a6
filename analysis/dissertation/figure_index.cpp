#include "analysis/dissertation/figure_index.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "analysis/dissertation/document_links.hpp"
#include "analysis/report/table.hpp"
#include "figures_md.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

std::vector<std::string> markdown_row_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t at = 1;
  while (true) {
    const std::size_t end = line.find('|', at);
    if (end == std::string::npos) break;
    std::string cell = line.substr(at, end - at);
    const std::size_t first = cell.find_first_not_of(' ');
    const std::size_t last = cell.find_last_not_of(' ');
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    at = end + 1;
  }
  return cells;
}

std::vector<MarkdownRow> markdown_table_rows(const std::string& markdown) {
  std::vector<MarkdownRow> rows;
  std::istringstream in(markdown);
  std::string line;
  int line_number = 0;
  bool header_seen = false, separator_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.rfind("|", 0) != 0) continue;
    if (!header_seen) { header_seen = true; continue; }
    if (!separator_seen) { separator_seen = true; continue; }
    rows.push_back({line_number, markdown_row_cells(line)});
  }
  return rows;
}

namespace {

bool shipped(const std::string& results_dir, const std::string& file) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(results_dir) / file, ec);
}

}  // namespace

std::vector<TextFigure> parse_figure_index(const std::string& markdown) {
  std::vector<TextFigure> out;
  for (const auto& [line_number, cells] : markdown_table_rows(markdown)) {
    const std::string where = "analysis/dissertation/figures.md line " + std::to_string(line_number) + ": ";
    if (cells.size() != 4) throw std::runtime_error(where + "expected 4 cells, found " + std::to_string(cells.size()));
    if (cells[0].empty()) throw std::runtime_error(where + "a row without a figure number");
    out.push_back({cells[0], cells[1], split_list(cells[2]), split_list(cells[3])});
  }
  return out;
}

const std::vector<TextFigure>& figure_index() {
  static const std::vector<TextFigure> figures = parse_figure_index(k_figures_markdown);
  return figures;
}

std::vector<const TextFigure*> figures_of_claim(const std::string& claim_key) {
  std::vector<const TextFigure*> out;
  for (const auto& f : figure_index())
    for (const auto& key : f.claims)
      if (key == claim_key) out.push_back(&f);
  return out;
}

std::string figure_links(const TextFigure& figure, const std::string& results_dir, const std::string& link_base) {
  std::string out;
  for (const auto& file : figure.files) {
    const fs::path p(file);
    const std::string label = p.begin()->string() + ": " + p.stem().string();
    out += out.empty() ? "" : ", ";
    const std::string target = link_base == "." ? file : (fs::path(link_base) / file).generic_string();
    out += shipped(results_dir, file) ? markdown_link(label, target)
                                      : label + " (not shipped)";
  }
  return out;
}

int linked_figure_count(const std::vector<TextFigure>& figures, const std::string& results_dir) {
  int n = 0;
  for (const auto& f : figures)
    for (const auto& file : f.files) n += shipped(results_dir, file);
  return n;
}

std::string figures_markdown(const std::string& results_dir, const std::string& link_base) {
  Table regenerated, missing;
  regenerated.title = "Figures of the text and the toolkit's figures with the same axes";
  regenerated.header = {"Fig.", "the text shows", "the toolkit's figures", "claims"};
  missing.title = "Figures of the text that no shipped campaign regenerates";
  missing.header = {"Fig.", "what it shows, and why not"};
  for (const auto& f : figure_index()) {
    if (f.files.empty()) {
      missing.rows.push_back({f.number, f.shows});
      continue;
    }
    regenerated.rows.push_back({f.number, f.shows, figure_links(f, results_dir, link_base), claim_links(f.claims)});
  }
  return regenerated.to_markdown() + "\n" + missing.to_markdown();
}

}  // namespace capsule::analysis
