#pragma once
// The rules of the Sec. 5.1.1-5.1.3 claims on the bilinear models (95)-(96), as functions of
// numbers alone, so that each runs on the toolkit's fits and on the text's own Table 2 alike
// (the column "the text passes its rule").
#include <string>

#include "analysis/dissertation/table2.hpp"

namespace capsule::analysis::claims {

// A coefficient with its 95 % half-width.
struct Coefficient {
  double value = 0.0, half_width = 0.0;
};

// Sec. 5.1.1 "surprisingly similar": the coefficient of the bending ensemble does not differ from the
// base's by more than the 95 % half-width of the difference (the two half-widths in quadrature, the
// fits independent; Table 2's own intervals).
struct RuleOutcome {
  bool holds = false;
  std::string numbers;
};
RuleOutcome similar_coefficient(const std::string& name, const Coefficient& base, const Coefficient& bending);

// Sec. 5.1.3 "the ratio of the a and b coefficients differs for tau_s and tau_r": |b_r/a_r - b_s/a_s|
// above 10 % of the larger ratio, the bound "5.1.2 V*" takes for a time reproduced "well" by
// V* = V + (a/b) eta (a ratio off by more misplaces the viscous part of V* by more).
constexpr double k_ratio_differ_bound = 0.1;
RuleOutcome ratios_differ(const std::string& ensemble, double ratio_response, double ratio_recovery);

// Sec. 5.1.1's ratio trends: from the base ensemble b_s/a_s rises and b_r/a_r falls.
RuleOutcome ratio_trend(const std::string& name, double base, double other, bool rises, const std::string& with);

// Sec. 5.1.1's quoted ratio inside an interval of b/a.
RuleOutcome quoted_ratio_inside(const std::string& name, double quoted, const RatioInterval& interval);

}  // namespace capsule::analysis::claims
