#pragma once
// THESIS.md's Table 2 section (Sec. 5.1.1): each row of the dissertation's Table 2 beside
// the bilinear fit (95)-(96) of the campaign that regenerates it, and the ratios b/a the
// text quotes, with 95 % intervals. The matching and the per-coefficient verdicts are
// table2_compare's (the same as `study compare --table2`).
#include <optional>
#include <string>
#include <vector>

#include "analysis/report/table.hpp"
#include "analysis/dissertation/table2_compare.hpp"
#include "analysis/dissertation/results.hpp"

namespace capsule::analysis {

// Which campaign regenerates which (Ca, E_b) ensemble of Table 2 (docs/guide/campaigns.md "The shipped campaigns").
struct Table2Ensemble {
  double Ca = 0.0, E_b = 0.0;
  std::string campaign;
  std::string text_r2_response;   // R^2 of the text's k tau_s fit: "0.91", "0.96", "0.95"
  double text_ratio_response = 0.0, text_ratio_recovery = 0.0;  // b_s/a_s and b_r/a_r as the text words them
};
const std::vector<Table2Ensemble>& table2_ensembles();

struct Table2RowComparison {
  const Table2Row* reference = nullptr;
  const Table2Ensemble* ensemble = nullptr;
  bool found = false;   // false: `why` says what is missing (campaign not run, no bilinear fit)
  std::string why;
  BilinearEntry entry;  // the toolkit's fit (entry.fit may have failed: coefficients say why)
  std::vector<CoefficientComparison> coefficients;  // a, b, c
};

// One per Table 2 row, in the table's order.
std::vector<Table2RowComparison> compare_table2_rows(const DissertationResults& results);

// b/a with a 95 % half-width.
struct RatioInterval {
  bool ok = false;
  std::string why;
  double value = 0.0, half_width = 0.0;
  std::string method;  // how the interval was found
};

// From the fit's covariance (delta method with cov(a, b), times Student's t with N - 3
// degrees of freedom) when fits.json carries it, else from the 95 % half-widths.
RatioInterval ratio_b_over_a_interval(const FitResult& bilinear);

// From 95 % half-widths alone (first-order delta method, a and b taken as independent):
// hw = |b/a| sqrt((hw_a/a)^2 + (hw_b/b)^2). Used for the text's Table 2.
RatioInterval ratio_from_half_widths(double a, double a_hw, double b, double b_hw);

// A coefficient Richardson-extrapolated over the campaign's ladder (bilinear.ladder) against the
// text's: the difference test |extrapolated - text| <= 1.96 sigma, sigma^2 = (text half-width / 1.96)^2
// + (fit half-width / 1.96)^2 + error^2 (the Richardson error taken as one standard error), and
// whether the coefficient moved toward the text from the next coarser level to the finest.
struct ExtrapolatedComparison {
  double extrapolated = 0.0, error = 0.0, difference = 0.0, sigma = 0.0;
  bool passes = false;
  int moves = 0;  // +1 toward the text, -1 away, 0 unknown (no coarser level)
};
// nullopt when the fit failed or the campaign has no extrapolation of the coefficient.
std::optional<ExtrapolatedComparison> extrapolated_difference_test(const Table2RowComparison& row, const CoefficientComparison& c);

Table table2_side_by_side(const std::vector<Table2RowComparison>& rows);
Table table2_ratios(const std::vector<Table2RowComparison>& rows);

}  // namespace capsule::analysis
