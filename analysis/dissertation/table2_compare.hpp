#pragma once
// A campaign's bilinear fits (95)-(96) (analysis/compare/bilinear_entries.hpp) set beside the
// dissertation's Table 2 row with the same target, Ca and E_b: per coefficient the
// difference and whether the 95 % intervals overlap. Used by `study compare --table2`
// and by the THESIS.md writer, so both say the same thing.
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/compare/bilinear_entries.hpp"
#include "analysis/fit/fit_result.hpp"
#include "analysis/dissertation/table2_reference.hpp"

namespace capsule::analysis {

// Table 2 names the bare time: "response.k_tau_s" -> "k_tau_s".
std::string bare_time(const std::string& target);

// The Table 2 row with the entry's target, Ca and E_b (decimals compared to 1e-9), or nullptr.
const Table2Row* table2_row_for(const BilinearEntry& entry);

// One coefficient ("a", "b" or "c") of a bilinear fit against Table 2.
struct CoefficientComparison {
  std::string name;
  double reference = 0.0, reference_half_width = 0.0;
  bool measured = false;  // false: the fit failed (reason) and nothing below is meaningful
  std::string reason;
  double value = 0.0, half_width = 0.0, difference = 0.0;  // difference = value - reference
  bool overlap = false;   // the two 95 % intervals overlap
};

// a, b, c of `fit` against `ref`, in that order.
std::vector<CoefficientComparison> compare_with_table2(const FitResult& fit, const Table2Row& ref);

// The `study compare --table2` section: every compared campaign's bilinear fits against Table 2,
// as Markdown (also printed to out and written to <out_dir>/compare_table2.csv). Sets status to
// 1 when some interval does not overlap Table 2's.
std::string table2_comparison(const std::vector<std::vector<BilinearEntry>>& campaigns, int& status,
                              const std::string& out_dir, std::ostream& out);

}  // namespace capsule::analysis
