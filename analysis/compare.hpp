#pragma once
// Bilinear coefficients (95)-(96) of several campaigns side by side, their differences
// and whether their 95 % intervals overlap; optionally against the dissertation's Table 2.
#include <ostream>
#include <string>
#include <vector>

namespace capsule::analysis {

struct CompareEntry {
  std::string name;
  std::string report_dir;  // holds the fits.json written by write_report
};

// Prints the comparison to `out` and writes <out_dir>/compare.md and compare.csv
// (and compare_table2.csv with against_table2).
// Returns 0 when every compared pair of intervals overlaps, 1 when at least one does
// not (like diff). Throws std::runtime_error when a report has no readable fits.json.
int compare_campaigns(const std::vector<CompareEntry>& entries, bool against_table2, std::ostream& out,
                      const std::string& out_dir);

}  // namespace capsule::analysis
