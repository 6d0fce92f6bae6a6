#pragma once
// A campaign's bilinear fits (95)-(96), read back from its fits.json, set beside the
// dissertation's Table 2 row with the same target, Ca and E_b: per coefficient the
// difference and whether the 95 % intervals overlap. Used by `study compare --table2`
// and by the THESIS.md writer, so both say the same thing.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/fit_result.hpp"
#include "analysis/table2_reference.hpp"

namespace capsule::analysis {

struct BilinearEntry {
  std::string campaign, case_name, target;  // target: "response.k_tau_s", ...
  double Ca = 0.0, E_b = 0.0;               // NaN when the case's members disagree
  FitResult fit;
  std::string level_key;                    // bilinear.ladder: the resolution key ("" without)
  double level = 0.0;                       // its value for this fit
  // bilinear.ladder: per coefficient ("a", "b", "c") the discretisation-error estimate of this
  // (the finest) level's value from fits.json "bilinear_ladder", or why there is none.
  std::map<std::string, double> ladder_error;
  std::map<std::string, std::string> ladder_note;
};

// The "bilinear" array of a parsed fits.json (write_report's layout). With a ladder the
// report lists a case's levels finest first, so the first entry of a case and target is
// its finest level; the ladder's error estimates are attached to that entry.
std::vector<BilinearEntry> read_bilinear_entries(const std::string& campaign, const nlohmann::json& fits);

// Table 2 names the bare time: "response.k_tau_s" -> "k_tau_s".
std::string bare_time(const std::string& target);

// The Table 2 row with the entry's target, Ca and E_b (decimals compared to 1e-9), or nullptr.
const Table2Row* table2_row_for(const BilinearEntry& entry);

bool intervals_overlap(double lo1, double hi1, double lo2, double hi2);

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

// "v ± hw" with the tables' number format.
std::string plus_minus(double value, double half_width);

}  // namespace capsule::analysis
