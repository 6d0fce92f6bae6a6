#pragma once
// The smeared membrane's hydrodynamic radius, and the marker inset that removes it.
//
// A rigid shell of markers on the radius r exerts on a shear flow the stresslet of a sphere of
// radius a_S = r + d_S(r): the delta spreads the markers' force over its width, so the flow sees
// a surface outside the markers (docs/findings/immersed_boundary_error_budget.md, measured with
// `capsule rigid-sphere`: the held shell's stresslet against Batchelor's (10/3) pi mu a^3 k, the
// box's own correction removed). The radius gap of each delta, fitted over marker radii:
//   d_S(r) = c0 + c1 / r
//   peskin4: c0 = 0.454, c1 = 1.32   (r = 4 and 10; reproduces r = 5 and 7 within 0.005)
//   roma3:   c0 = 0.343, c1 = 0.82   (r = 4.4, 5, 6.5 and 7; within 0.001 of all four)
//   keys4:   c0 = 0.101, c1 = 0.662  (r = 4.4, 5 and 7, a least-squares line; within 0.002 of all
//            three; Keys' delta, whose zero second moment smears the shell by a third as much)
// A capsule deforms as a sphere of the stresslet's radius (its small-Ca D/Ca read as a radius
// is a_S within a tenth of a node), so its markers go on the radius r_m that the flow sees as a:
//   r_m + d_S(r_m) = a   =>   r_m = ((a - c0) + sqrt((a - c0)^2 - 4 c1)) / 2,
// the marker inset is a - r_m (0.53 / 0.47 / 0.43 at a = 5 / 7 / 10 for roma3). The constants
// come from this one exact problem; the capsule's small-deformation limit validates them.
#include <cmath>
#include <optional>

#include "solver/ib/delta.hpp"

namespace capsule::ib {

struct StressletRadiusGap {
  double c0 = 0;  // lattice units
  double c1 = 0;  // lattice units squared
};

// The measured gap of a delta; none for deltas whose shell was not measured (cosine, linear2).
inline std::optional<StressletRadiusGap> stresslet_radius_gap(Delta delta) {
  switch (delta) {
    case Delta::peskin4: return StressletRadiusGap{0.454, 1.32};
    case Delta::roma3: return StressletRadiusGap{0.343, 0.82};
    case Delta::keys4: return StressletRadiusGap{0.101, 0.662};
    case Delta::cosine:
    case Delta::linear2: break;
  }
  return std::nullopt;
}

// The 2D twin: a rigid circle of markers on the radius r (capsule rigid-circle, 140 markers,
// spin -1/2, channel 10a x 10a, kt 8) exerts the stresslet of a circle of radius r + d_S(r):
//   peskin4: c0 = 0.49, c1 = 1.41   (r = a = 4, 5, 7, 10, 14, 20 fitted with the channel's own
//            factor, 1.040, as a third unknown; within 6e-5 of all six in sqrt(S))
// nearly the 3D values. In 2D the capsule does not follow it: an inset by this gap makes the
// circle's error at a = 10 larger, not smaller (docs/findings/immersed_boundary_error_budget.md
// "In 2D"), so 2D keeps its markers on a by default and the rule is a scene choice.
inline std::optional<StressletRadiusGap> stresslet_radius_gap_2d(Delta delta) {
  if (delta == Delta::peskin4) return StressletRadiusGap{0.49, 1.41};
  return std::nullopt;
}

// The smallest radius the rule solves for: below it r + d_S(r) = a has no root.
inline double stresslet_inset_min_radius(const StressletRadiusGap& g) { return g.c0 + 2.0 * std::sqrt(g.c1); }

// a - r_m with r_m + d_S(r_m) = a (the larger root); NaN where a is below the smallest radius.
inline double stresslet_marker_inset(const StressletRadiusGap& g, double a) {
  const double b = a - g.c0;
  const double disc = b * b - 4.0 * g.c1;
  if (disc < 0) return std::nan("");
  return a - 0.5 * (b + std::sqrt(disc));
}

}  // namespace capsule::ib
