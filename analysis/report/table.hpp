#pragma once
// A plain table of text cells written as Markdown, CSV (RFC 4180 quoting) and LaTeX. A cell
// "n/a: reason" in a column of numbers stays as it is in Markdown and LaTeX; in CSV the cell is
// empty and the reason goes to a column "<name> reason" beside it (table.cpp).
#include <string>
#include <vector>

#include "analysis/fit/number_format.hpp"

namespace capsule::analysis {

struct Table {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  std::string to_markdown() const;
  std::string to_csv() const;
  std::string to_latex() const;
  // Writes <dir>/<stem>.md, .csv, .tex; returns the three paths.
  std::vector<std::string> write(const std::string& dir, const std::string& stem) const;
};

}  // namespace capsule::analysis
