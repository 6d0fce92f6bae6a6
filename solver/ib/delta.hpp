#pragma once
// Discrete delta functions of the immersed boundary method, (17)-(18), h = dx = 1: a tensor
// product (17) of a 1D delta of support 2 to 4 nodes. Delta::cosine is the text's (18);
// Delta::peskin4, roma3, keys4 and linear2 are the literature's (formulas below). Every property
// of a delta (its scene name, its width) is asked of it here. Their moments are tested in
// tests/solver/ib/ib_test.cpp; why the choice matters is measured in docs/guide/model.md
// "Immersed boundary kernel" (the cosine delta's nonzero first moment turns a linear shear into
// lattice-locked curvature noise on a 2D membrane; peskin4 interpolates linear fields exactly).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "solver/common/name_table.hpp"

namespace capsule::ib {

// (18), h = 1.
inline double cosine_delta(double r) {
  const double ar = std::abs(r);
  return ar <= 2.0 ? 0.25 * (1.0 + std::cos(0.5 * std::numbers::pi * ar)) : 0.0;
}

// The four nodes a point at coordinate x touches along one axis: nodes first..first+3,
// node i at i + 1/2, with weights w[m] = delta(x - (first + m + 1/2)). Indices are not
// wrapped: the caller wraps periodic axes and drops nodes outside walled ones.
struct DeltaStencil1D {
  int first = 0;
  int width = 4;  // nodes first..first+width-1 carry the weights w[0..width-1]
  double w[4] = {0, 0, 0, 0};
};

enum class Delta { cosine, peskin4, roma3, linear2, keys4 };

// The scene's names (resolution.kernel), in the order its error messages list them.
inline constexpr NameTable<Delta, 5> delta_names{{{Delta::peskin4, "peskin4"},
                                                  {Delta::roma3, "roma3"},
                                                  {Delta::linear2, "linear2"},
                                                  {Delta::cosine, "cosine"},
                                                  {Delta::keys4, "keys4"}}};
constexpr const auto& name_table(Delta) { return delta_names; }

// Support width in nodes along one axis.
constexpr int delta_width(Delta d) { return d == Delta::roma3 ? 3 : d == Delta::linear2 ? 2 : 4; }

// The largest stiffness number M = E_m (1 - exp(-1/tau_m)) tau_m / nu of a membrane's Maxwell
// element, coupled explicitly through this delta, that stays stable at rest (a long recovery
// grows a slow mode above it): 0.4 with peskin4, 0.15 measured with roma3 and taken for the
// deltas not measured (docs/findings/accuracy_and_stability.md "A slow instability at rest").
constexpr double maxwell_stiffness_bound(Delta d) { return d == Delta::peskin4 ? 0.4 : 0.15; }

// Lattice nodes one marker touches in dim dimensions: delta_width^dim.
constexpr int delta_support_nodes(Delta d, int dim) {
  int nodes = 1;
  for (int i = 0; i < dim; ++i) nodes *= delta_width(d);
  return nodes;
}

// Roma, Peskin and Berger's 3-point delta (J. Comput. Phys. 153 (1999) 509, eq. 6.3):
//   (1 + sqrt(1 - 3 r^2)) / 3                    for |r| <= 1/2,
//   (5 - 3|r| - sqrt(1 - 3 (1 - |r|)^2)) / 6     for 1/2 <= |r| <= 3/2.
// Partition of unity and zero first moment for every offset, like peskin4, on a narrower support.
inline double roma3_delta(double r) {
  const double ar = std::abs(r);
  if (ar <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0 * ar * ar)) / 3.0;
  if (ar <= 1.5) return (5.0 - 3.0 * ar - std::sqrt(std::max(0.0, 1.0 - 3.0 * (1.0 - ar) * (1.0 - ar)))) / 6.0;
  return 0.0;
}

// Keys' cubic convolution kernel, as a delta (R. G. Keys, IEEE Trans. ASSP 29 (1981) 1153, a = -1/2):
//   (3/2)|r|^3 - (5/2) r^2 + 1                   for |r| <= 1,
//   -(1/2)|r|^3 + (5/2) r^2 - 4|r| + 2          for 1 <= |r| <= 2.
// Partition of unity, zero first AND second moment for every offset (it interpolates
// quadratics exactly), continuous first derivative; negative between |r| = 1 and 2. Peskin's
// and Roma's deltas are positive, so their second moment cannot vanish (about 1/2 and 1/3
// node^2, varying with the offset): the smoothing they leave goes as that moment times the
// curvature of what is smoothed.
// Measured (docs/findings/immersed_boundary_error_budget.md
// "A kernel with zero second moment: removes the smoothing error, not stable (2026-12-06)"):
// it removes the finite-Ca deficit (Ca 0.2, a = 10: -0.5 % against roma3's -2.5 %), but a
// stiff membrane's deformation creeps at any tau and the volume leaks about 8x faster: a
// probe, not a default.
inline double keys4_delta(double r) {
  const double ar = std::abs(r);
  if (ar <= 1.0) return (1.5 * ar - 2.5) * ar * ar + 1.0;
  if (ar <= 2.0) return ((-0.5 * ar + 2.5) * ar - 4.0) * ar + 2.0;
  return 0.0;
}

// The 2-point hat (linear interpolation): 1 - |r| for |r| <= 1.
inline double linear2_delta(double r) { return std::max(0.0, 1.0 - std::abs(r)); }

// Peskin's 4-point delta (see above), |r| <= 2.
inline double peskin4_delta(double r) {
  const double ar = std::abs(r);
  if (ar <= 1.0) return 0.125 * (3.0 - 2.0 * ar + std::sqrt(1.0 + 4.0 * ar - 4.0 * ar * ar));
  if (ar <= 2.0) return 0.125 * (5.0 - 2.0 * ar - std::sqrt(std::max(0.0, -7.0 + 12.0 * ar - 4.0 * ar * ar)));
  return 0.0;
}

// The first node of the stencil of a point at coordinate x (delta_stencil(x, delta).first).
inline int stencil_first(double x, Delta delta) {
  if (delta == Delta::roma3) return static_cast<int>(std::floor(x)) - 1;  // node floor(x) at floor(x) + 1/2 is the nearest
  if (delta == Delta::linear2) return static_cast<int>(std::floor(x - 0.5));
  return static_cast<int>(std::floor(x - 0.5)) - 1;  // peskin4 and cosine
}

// The stencil of the delta K, chosen at compile time: the hot loops (interpolation.hpp,
// layer_spreading.hpp) are instantiated once per delta through with_delta(), so the width is
// a constant and their loops unroll. delta_stencil(x, delta) picks it at run time.
template <Delta K>
inline DeltaStencil1D delta_stencil_of(double x) {
  DeltaStencil1D s;
  s.width = delta_width(K);
  s.first = stencil_first(x, K);
  if constexpr (K == Delta::roma3) {
    const double r1 = x - (s.first + 1.5);          // offset from the middle node, in [-1/2, 1/2)
    s.w[1] = (1.0 + std::sqrt(std::max(0.0, 1.0 - 3.0 * r1 * r1))) / 3.0;
    // the outer two follow from partition of unity and zero first moment: w0 - w2 = -r1
    const double outer = 1.0 - s.w[1];
    s.w[0] = 0.5 * (outer - r1);
    s.w[2] = 0.5 * (outer + r1);
  } else if constexpr (K == Delta::linear2) {
    const double r0 = x - (s.first + 0.5);  // in [0, 1)
    s.w[0] = 1.0 - r0;
    s.w[1] = r0;
  } else if constexpr (K == Delta::keys4) {
    const double r0 = x - (s.first + 0.5);  // in [1, 2): offsets r0, r0 - 1, r0 - 2, r0 - 3
    const double t = r0 - 1.0;               // in [0, 1)
    const double u = 1.0 - t;                // 2 - r0, in (0, 1]
    s.w[1] = (1.5 * t - 2.5) * t * t + 1.0;
    s.w[2] = (1.5 * u - 2.5) * u * u + 1.0;
    s.w[0] = ((-0.5 * r0 + 2.5) * r0 - 4.0) * r0 + 2.0;
    const double r3 = 3.0 - r0;              // in (1, 2]
    s.w[3] = ((-0.5 * r3 + 2.5) * r3 - 4.0) * r3 + 2.0;
  } else if constexpr (K == Delta::peskin4) {
    const double r0 = x - (s.first + 0.5);  // in [1, 2): offsets r0, r0 - 1 in [0, 1), r0 - 2, r0 - 3
    const double r1 = r0 - 1.0;             // in [0, 1)
    // one square root serves the two inner nodes and one the two outer nodes
    const double q = std::sqrt(1.0 + 4.0 * r1 - 4.0 * r1 * r1);
    s.w[1] = 0.125 * (3.0 - 2.0 * r1 + q);
    s.w[2] = 0.125 * (1.0 + 2.0 * r1 + q);  // phi(1 - r1)
    s.w[0] = 0.5 - s.w[2];                  // phi(r) + phi(r - 2) = 1/2 (even/odd sums)
    s.w[3] = 0.5 - s.w[1];
  } else {
    // cosine (18). r_m = x - (first + m + 1/2): r_0 in [1, 2), r_m = r_0 - m. cos(pi (r - m)/2)
    // cycles through c, s, -c, -s with c = cos(pi r_0 / 2), s = sin(pi r_0 / 2): one cos and one sin.
    const double r0 = x - (s.first + 0.5);
    const double c = std::cos(0.5 * std::numbers::pi * r0);
    const double sn = std::sin(0.5 * std::numbers::pi * r0);
    s.w[0] = 0.25 * (1.0 + c);
    s.w[1] = 0.25 * (1.0 + sn);
    s.w[2] = 0.25 * (1.0 - c);
    s.w[3] = 0.25 * (1.0 - sn);
  }
  return s;
}

// Calls f(std::integral_constant<Delta, K>{}) for the delta named at run time: a loop over
// membrane nodes placed inside f is compiled once per delta, with no branch on the delta inside.
template <class F>
inline decltype(auto) with_delta(Delta delta, F&& f) {
  switch (delta) {
    case Delta::roma3: return f(std::integral_constant<Delta, Delta::roma3>{});
    case Delta::peskin4: return f(std::integral_constant<Delta, Delta::peskin4>{});
    case Delta::linear2: return f(std::integral_constant<Delta, Delta::linear2>{});
    case Delta::keys4: return f(std::integral_constant<Delta, Delta::keys4>{});
    case Delta::cosine: break;
  }
  return f(std::integral_constant<Delta, Delta::cosine>{});
}

inline DeltaStencil1D delta_stencil(double x, Delta delta = Delta::cosine) {
  return with_delta(delta, [x](auto k) { return delta_stencil_of<decltype(k)::value>(x); });
}

// The delta's first moment sum_m (x - x_m) w_m for a point whose first stencil node
// lies r0 = x - x_first in [1, 2) behind it (derived from the weights above).
inline double first_moment_error(double r0) {
  return r0 - 1.5 + 0.5 * (std::cos(0.5 * std::numbers::pi * r0) + std::sin(0.5 * std::numbers::pi * r0));
}

}  // namespace capsule::ib
