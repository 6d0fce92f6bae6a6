#include "analysis/fit/richardson.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/fit/number_format.hpp"

namespace capsule::analysis {

namespace {

// f(p) = (s3^p - s2^p) / (s2^p - 1) with s = h / h1, written with expm1 so that small p
// loses no digits; increasing in p from f(0+) = ln(s3/s2) / ln(s2) to infinity.
double ratio_of_differences(double p, double ln_s2, double ln_s32) {
  return std::exp(p * ln_s2) * std::expm1(p * ln_s32) / std::expm1(p * ln_s2);
}

}  // namespace

double observed_order(double h1, double h2, double h3, double q1, double q2, double q3, std::string& why) {
  const double d21 = q2 - q1, d32 = q3 - q2;
  if (d21 == 0.0 || d32 == 0.0 || (d21 > 0) != (d32 > 0)) {
    why = "not monotone: no order";
    return -1.0;
  }
  const double R = d32 / d21;
  const double ln_s2 = std::log(h2 / h1), ln_s32 = std::log(h3 / h2);
  const double f0 = ln_s32 / ln_s2;  // f(0+): the ratio a zero order would give
  if (R <= f0) {
    why = "not converging (the differences do not shrink with h): no order";
    return -1.0;
  }
  double lo = 0.0, hi = 1.0;
  while (ratio_of_differences(hi, ln_s2, ln_s32) < R) {
    lo = hi;
    hi *= 2.0;
    if (hi > k_max_observed_order) {
      why = "observed order above " + format_number(k_max_observed_order) + ": levels not in the asymptotic range";
      return -1.0;
    }
  }
  // Bisection to the last bit: f is monotone, so 200 halvings of [lo, hi] reach round-off.
  for (int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (ratio_of_differences(mid, ln_s2, ln_s32) < R) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

RichardsonResult richardson(std::vector<LadderLevel> levels, double assumed_order) {
  for (const auto& l : levels)
    if (!(l.h > 0.0) || !std::isfinite(l.h) || !std::isfinite(l.q))
      throw std::invalid_argument("richardson: every level needs a finite h > 0 and a finite value");
  std::sort(levels.begin(), levels.end(), [](const LadderLevel& a, const LadderLevel& b) { return a.h < b.h; });
  for (std::size_t i = 1; i < levels.size(); ++i)
    if (levels[i].h == levels[i - 1].h) throw std::invalid_argument("richardson: two levels with the same h");
  RichardsonResult r;
  r.levels = levels.size();
  if (levels.empty()) {
    r.reason = "no level with a value";
    return r;
  }
  r.finest = levels[0].q;
  if (levels.size() == 1) {
    r.reason = "one level only: no extrapolation";
    return r;
  }
  const double h1 = levels[0].h, h2 = levels[1].h, q1 = levels[0].q, q2 = levels[1].q;
  if (levels.size() == 2) {
    r.ok = true;
    r.order = assumed_order;
    r.order_observed = false;
    r.extrapolated = q1 - (q2 - q1) / std::expm1(assumed_order * std::log(h2 / h1));
    // The finest level's error under the stated order, as for three levels: |finest - q0|
    // (2.5 |q1 - q2| for a = 5, 7 at p = 1). |q1 - q2| alone would understate it whenever
    // the order is below about 2.
    r.error_estimate = std::abs(q1 - r.extrapolated);
    r.reason = "two levels: order assumed p = " + format_number(assumed_order) +
               ", error estimate = |finest - extrapolated| at that order";
    return r;
  }
  const double h3 = levels[2].h, q3 = levels[2].q;
  if (q1 == q2 && q2 == q3) {
    r.ok = true;
    r.extrapolated = q1;
    r.order = 0.0;
    r.error_estimate = 0.0;
    r.reason = "the three finest levels agree exactly: no order, error 0";
    return r;
  }
  std::string why;
  const double p = observed_order(h1, h2, h3, q1, q2, q3, why);
  if (p < 0.0) {
    r.reason = why;
    return r;
  }
  r.ok = true;
  r.order = p;
  r.order_observed = true;
  r.extrapolated = q1 - (q2 - q1) / std::expm1(p * std::log(h2 / h1));
  r.error_estimate = std::abs(q1 - r.extrapolated);
  return r;
}

}  // namespace capsule::analysis
