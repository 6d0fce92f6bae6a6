#include "analysis/dissertation/rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace capsule::analysis {

const char* verdict_text(Verdict v) {
  switch (v) {
    case Verdict::agrees: return "agrees";
    case Verdict::differs: return "differs";
    case Verdict::cannot_tell: break;
  }
  return "cannot tell";
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  f.n = std::min(x.size(), y.size());
  if (f.n < 3) return f;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < f.n; ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(f.n);
  my /= static_cast<double>(f.n);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < f.n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0.0)) return f;
  f.ok = true;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ss_res = 0.0;
  for (std::size_t i = 0; i < f.n; ++i) {
    const double r = y[i] - (f.slope * x[i] + f.intercept);
    ss_res += r * r;
  }
  f.r_squared = syy > 0.0 ? 1.0 - ss_res / syy : 1.0;
  return f;
}

LineFit fit_power(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!(x[i] > 0.0) || !(y[i] > 0.0)) return LineFit{};
    lx.push_back(std::log(x[i]));
    ly.push_back(std::log(y[i]));
  }
  return fit_line(lx, ly);
}

double relative_spread(const std::vector<double>& y) {
  if (y.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double v : y) sum += v;
  const double mean = sum / static_cast<double>(y.size());
  if (mean == 0.0) return std::numeric_limits<double>::quiet_NaN();
  const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
  return (*hi - *lo) / std::abs(mean);
}

double median(std::vector<double> y) {
  if (y.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(y.begin(), y.end());
  const std::size_t n = y.size();
  return n % 2 ? y[n / 2] : 0.5 * (y[n / 2 - 1] + y[n / 2]);
}

double order_of_magnitude(double x) {
  return x > 0.0 ? std::round(std::log10(x)) : std::numeric_limits<double>::quiet_NaN();
}

std::string short_number(double x) {
  if (!std::isfinite(x)) return "n/a";
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

std::string short_plus_minus(double value, double half_width) { return short_number(value) + " ± " + short_number(half_width); }

}  // namespace capsule::analysis
