#include "analysis/report/table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace capsule::analysis {

namespace {
std::string md_cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}
std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += "\"\"";
    else out += c;
  }
  return out + "\"";
}
std::string tex_cell(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    switch (c) {
      case '\\': out += "\\textbackslash{}"; break;
      case '_': case '%': case '&': case '#': case '$': case '{': case '}':
        out += '\\';
        out += c;
        break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      default:
        // "±" (UTF-8 C2 B1) -> $\pm$
        if (static_cast<unsigned char>(c) == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0xB1) {
          out += "$\\pm$";
          ++i;
        } else {
          out += c;
        }
    }
  }
  return out;
}

// A cell that holds no number and says why: "n/a" or "n/a: reason".
bool is_missing(const std::string& c) { return c.rfind("n/a", 0) == 0; }
std::string missing_reason(const std::string& c) { return c.rfind("n/a: ", 0) == 0 ? c.substr(5) : "not available"; }
bool is_number(const std::string& c) {
  if (c.empty()) return false;
  char* end = nullptr;
  std::strtod(c.c_str(), &end);
  return end == c.c_str() + c.size();
}
std::string cell(const std::vector<std::string>& row, std::size_t i) { return i < row.size() ? row[i] : ""; }

// The columns whose cells are numbers, empty or missing ("n/a: reason"), with at least one
// missing: in CSV these stay numeric and the reasons go to a column of their own.
std::vector<bool> numeric_with_reasons(const std::vector<std::string>& header,
                                       const std::vector<std::vector<std::string>>& rows) {
  std::vector<bool> out(header.size(), false);
  for (std::size_t i = 0; i < header.size(); ++i) {
    bool any_missing = false, only_numbers = true;
    for (const auto& row : rows) {
      const std::string c = cell(row, i);
      if (is_missing(c)) any_missing = true;
      else if (!c.empty() && !is_number(c)) only_numbers = false;
    }
    out[i] = any_missing && only_numbers;
  }
  return out;
}
}  // namespace

std::string Table::to_markdown() const {
  std::ostringstream s;
  if (!title.empty()) s << "**" << md_cell(title) << "**\n\n";
  s << "|";
  for (const auto& h : header) s << " " << md_cell(h) << " |";
  s << "\n|";
  for (std::size_t i = 0; i < header.size(); ++i) s << "---|";
  s << "\n";
  for (const auto& row : rows) {
    s << "|";
    for (const auto& c : row) s << " " << md_cell(c) << " |";
    s << "\n";
  }
  return s.str();
}

// A numeric column never holds text: where it has no value the cell is empty and the column
// "<name> reason" beside it says why (Markdown and LaTeX keep "n/a: reason" in the cell).
std::string Table::to_csv() const {
  const std::vector<bool> split = numeric_with_reasons(header, rows);
  std::ostringstream s;
  for (std::size_t i = 0; i < header.size(); ++i) {
    s << (i ? "," : "") << csv_cell(header[i]);
    if (split[i]) s << "," << csv_cell(header[i] + " reason");
  }
  s << "\n";
  for (const auto& row : rows) {
    const std::size_t n = std::max(row.size(), header.size());
    for (std::size_t i = 0; i < n; ++i) {
      const std::string c = cell(row, i);
      s << (i ? "," : "");
      if (i < split.size() && split[i]) s << (is_missing(c) ? "," + csv_cell(missing_reason(c)) : csv_cell(c) + ",");
      else s << csv_cell(c);
    }
    s << "\n";
  }
  return s.str();
}

std::string Table::to_latex() const {
  std::ostringstream s;
  s << "\\begin{table}\n\\centering\n";
  if (!title.empty()) s << "\\caption{" << tex_cell(title) << "}\n";
  s << "\\begin{tabular}{" << std::string(header.size(), 'l') << "}\n\\hline\n";
  for (std::size_t i = 0; i < header.size(); ++i) s << (i ? " & " : "") << tex_cell(header[i]);
  s << " \\\\\n\\hline\n";
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) s << (i ? " & " : "") << tex_cell(row[i]);
    s << " \\\\\n";
  }
  s << "\\hline\n\\end{tabular}\n\\end{table}\n";
  return s.str();
}

std::vector<std::string> Table::write(const std::string& dir, const std::string& stem) const {
  std::filesystem::create_directories(dir);
  std::vector<std::string> files;
  const std::pair<const char*, std::string> outputs[] = {
      {".md", to_markdown()}, {".csv", to_csv()}, {".tex", to_latex()}};
  for (const auto& [ext, text] : outputs) {
    const std::string path = (std::filesystem::path(dir) / (stem + ext)).string();
    std::ofstream f(path);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path);
    files.push_back(path);
  }
  return files;
}

}  // namespace capsule::analysis
