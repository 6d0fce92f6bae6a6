#pragma once
// The small numeric tests THESIS.md's claims are judged by (a straight line and its R^2,
// a power-law exponent, a relative spread, an order of magnitude) and the three verdicts.
// Each claim states its criterion in these terms, so a reader can judge it.
#include <cstddef>
#include <string>
#include <vector>

namespace capsule::analysis {

enum class Verdict { agrees, differs, cannot_tell };
const char* verdict_text(Verdict v);  // "agrees", "differs", "cannot tell"

struct LineFit {
  bool ok = false;  // needs >= 3 points and x not all equal
  double slope = 0.0, intercept = 0.0, r_squared = 0.0;
  std::size_t n = 0;
};

// Least-squares straight line y = slope x + intercept, R^2 about the mean of y
// (R^2 = 1 when y is constant and the line exact).
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

// y ~ x^p: the straight line through (ln x, ln y); slope = p. Not ok when any x or y <= 0.
LineFit fit_power(const std::vector<double>& x, const std::vector<double>& y);

// (max - min) / mean of y; NaN for an empty y or a zero mean.
double relative_spread(const std::vector<double>& y);

// Median of y (NaN when empty).
double median(std::vector<double> y);

// Round(log10 x): 0.283 -> -1 (O(0.1)), 2.6 -> 0 (O(1)), 7.5 -> 1 (O(10)). NaN for x <= 0.
double order_of_magnitude(double x);

// Three significant digits, for the "measured" column.
std::string short_number(double x);
// "value ± half_width", both at three significant digits.
std::string short_plus_minus(double value, double half_width);

}  // namespace capsule::analysis
