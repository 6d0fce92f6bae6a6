#pragma once
// Bilinear coefficients (95)-(96) of several campaigns side by side, their differences
// and whether their 95 % intervals overlap, and per-member fitted times.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "analysis/compare/bilinear_entries.hpp"

namespace capsule::analysis {

struct CompareEntry {
  std::string name;
  std::string report_dir;  // holds the fits.json written by write_report
};

// A further section of the comparison (`study compare --table2` adds the dissertation's Table 2,
// analysis/dissertation/table2_compare.hpp): given every campaign's bilinear fits, returns Markdown for
// compare.md, may print and write its own files, and sets status to 1 for a disagreement.
using CompareSection = std::function<std::string(const std::vector<std::vector<BilinearEntry>>& campaigns,
                                                 int& status, const std::string& out_dir, std::ostream& out)>;

// Prints the comparison to `out` and writes <out_dir>/compare.md and compare.csv (and what
// `extra` writes). Returns 0 when every compared pair of intervals overlaps, 1 when at least one
// does not (like diff). Throws std::runtime_error when a report has no readable fits.json.
int compare_campaigns(const std::vector<CompareEntry>& entries, std::ostream& out, const std::string& out_dir,
                      const CompareSection& extra = {});

}  // namespace capsule::analysis
