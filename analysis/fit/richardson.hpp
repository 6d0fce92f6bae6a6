#pragma once
// Richardson extrapolation over a resolution ladder: q(h) = q0 + C h^p fitted exactly to
// the three finest levels, with the observed order p solved numerically so that
// non-uniform refinement ratios (a = 5, 7, 10) need no special case (Roache 1998, Sec. 5.4).
#include <cstddef>
#include <string>
#include <vector>

namespace capsule::analysis {

struct LadderLevel {
  double h = 0.0;  // grid spacing (1/a, 1/segments, 2^-level), > 0
  double q = 0.0;  // the quantity at that spacing
};

// Highest order the solver looks for: an observed order above it means the levels are not
// in the asymptotic range (the IB method is first order in 1/a, docs/guide/model.md "Immersed boundary kernel"), not a real p.
inline constexpr double k_max_observed_order = 16.0;

struct RichardsonResult {
  bool ok = false;              // an extrapolated value and an error estimate were made
  std::string reason;           // ok: a note (e.g. which order was assumed); !ok: why not
  std::size_t levels = 0;       // levels given
  double finest = 0.0;          // q at the smallest h (always set when levels >= 1)
  double extrapolated = 0.0;    // q0 (ok only)
  double order = 0.0;           // p (ok only)
  bool order_observed = false;  // true: p from three levels; false: assumed (two levels)
  double error_estimate = 0.0;  // three levels: |finest - q0|; two levels: |q1 - q2| (ok only)
};

// The observed order p solving (q3 - q2)/(q2 - q1) = (h3^p - h2^p)/(h2^p - h1^p) for
// h1 < h2 < h3, or a negative number with `why` set when no p in (0, k_max_observed_order]
// exists (not monotone, differences that do not shrink, order too high).
double observed_order(double h1, double h2, double h3, double q1, double q2, double q3, std::string& why);

// Levels in any order; their h must be distinct and positive (std::invalid_argument else).
// One level: refused (no ladder). Two levels: q0 with the `assumed_order`, error = |q1 - q2|.
// Three or more: the three finest give the observed order, q0 and |q1 - q0|.
RichardsonResult richardson(std::vector<LadderLevel> levels, double assumed_order);

}  // namespace capsule::analysis
