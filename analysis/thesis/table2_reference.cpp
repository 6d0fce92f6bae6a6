#include "analysis/thesis/table2_reference.hpp"

#include <sstream>
#include <stdexcept>

namespace capsule::analysis {

const std::string& table2_csv_text() {
  // Copied from analysis/reference/table2_dissertation.csv (the test
  // "Table 2 reference: embedded copy equals the shipped CSV" keeps them equal).
  static const std::string text = R"csv(target,Ca,E_b,a,a_half_width,b,b_half_width,c,c_half_width
k_tau_s,0.05,0,0.0208,0.0039,0.0590,0.0149,0.4158,0.0638
k_tau_r,0.05,0,0.0534,0.0028,0.2711,0.0109,0.3986,0.0466
k_tau_s,0.05,0.025,0.0157,0.0039,0.0550,0.0158,0.2567,0.0638
k_tau_r,0.05,0.025,0.0299,0.0018,0.1380,0.0075,0.2209,0.0303
k_tau_s,0.2,0,0.0417,0.0110,0.1464,0.0410,0.685,0.1402
k_tau_r,0.2,0,0.2438,0.0128,1.0120,0.0477,1.614,0.162
)csv";
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
