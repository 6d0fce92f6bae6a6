#pragma once
// The dissertation's Table 2 (Sec. 5.1.1): bilinear coefficients (95)-(96) of spherical
// capsules with 95 % half-widths, from analysis/reference/table2_dissertation.csv, embedded at
// build time so that nothing depends on the source tree.
#include <string>
#include <vector>

namespace capsule::analysis {

struct Table2Row {
  std::string target;  // "k_tau_s" (95) or "k_tau_r" (96)
  double Ca = 0.0, E_b = 0.0;
  double a = 0.0, a_half_width = 0.0;
  double b = 0.0, b_half_width = 0.0;
  double c = 0.0, c_half_width = 0.0;
};

// The embedded CSV text, byte for byte the shipped file.
const std::string& table2_csv_text();

// Parses CSV text in that layout (header line first); throws std::runtime_error on a malformed line.
std::vector<Table2Row> parse_table2_csv(const std::string& text);

// The parsed embedded table.
const std::vector<Table2Row>& table2_dissertation();

}  // namespace capsule::analysis
