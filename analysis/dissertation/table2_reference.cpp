#include "analysis/dissertation/table2_reference.hpp"

#include <sstream>
#include <stdexcept>

#include "table2_csv.hpp"

namespace capsule::analysis {

const std::string& table2_csv_text() {
  static const std::string text = k_table2_csv;  // analysis/reference/table2_dissertation.csv, embedded at build time
  return text;
}

std::vector<Table2Row> parse_table2_csv(const std::string& text) {
  std::vector<Table2Row> rows;
  std::istringstream in(text);
  std::string line;
  bool header = true;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream cells(line);
    std::string cell;
    std::vector<std::string> v;
    while (std::getline(cells, cell, ',')) v.push_back(cell);
    if (v.size() != 9) throw std::runtime_error("Table 2 CSV line " + std::to_string(line_no) + ": expected 9 cells");
    try {
      Table2Row r;
      r.target = v[0];
      r.Ca = std::stod(v[1]);
      r.E_b = std::stod(v[2]);
      r.a = std::stod(v[3]);
      r.a_half_width = std::stod(v[4]);
      r.b = std::stod(v[5]);
      r.b_half_width = std::stod(v[6]);
      r.c = std::stod(v[7]);
      r.c_half_width = std::stod(v[8]);
      rows.push_back(r);
    } catch (const std::logic_error&) {
      throw std::runtime_error("Table 2 CSV line " + std::to_string(line_no) + ": not a number");
    }
  }
  return rows;
}

const std::vector<Table2Row>& table2_dissertation() {
  static const std::vector<Table2Row> rows = parse_table2_csv(table2_csv_text());
  return rows;
}

}  // namespace capsule::analysis
