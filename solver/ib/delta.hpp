#pragma once
// Discrete delta functions of the immersed boundary method, (17)-(18), h = dx = 1, as a
// tensor product over dimensions (17) of a 1D kernel of support 4:
//   Kernel::cosine  (18): delta_h(r) = (1 + cos(pi r / 2)) / 4 for |r| <= 2 -- the text's kernel;
//   Kernel::peskin4 (Peskin 2002, Acta Numerica 11, eq. 6.27):
//       (3 - 2|r| + sqrt(1 + 4|r| - 4 r^2)) / 8        for |r| <= 1,
//       (5 - 2|r| - sqrt(-7 + 12|r| - 4 r^2)) / 8      for 1 <= |r| <= 2.
// Both have the same support and cost.
//
// Properties (tested in tests/solver/ib/ib_test.cpp):
//  - partition of unity: sum_j delta(x - x_j) = 1 exactly for every offset;
//  - the first moment sum_j (x - x_j) delta(x - x_j) is NOT zero for the cosine kernel
//    (unlike Peskin's 4-point kernel): it equals first_moment_error(r) below, zero when
//    the point sits on a node or midway between two, and at most 0.0209 dx otherwise.
//    So interpolating a linear field u = g x is exact only at those offsets and off by
//    g * first_moment_error elsewhere (docs/guide/model.md "Immersed boundary kernel" asks for zero; the kernel (18) does not give it).
//  - peskin4 has partition of unity AND zero first moment for every offset (linear fields are
//    interpolated exactly) and sum of squared weights = 3/8 for every offset.
// Why the choice matters (measured, docs/guide/model.md "Immersed boundary kernel"): with the cosine
// kernel, a capsule in linear shear gets node velocities that err by k * first_moment_error,
// a pattern locked to the lattice; the 2D membrane (node spacing 0.45 dx at a = 10) turns it
// into curvature noise of order 1/a within kt ~ 0.1, which the fluid cannot damp (it is below
// the kernel's width), so any bending stiffness gives resolution-dependent nonsense
// (Ca = 0.05, E_b = 0.05: steady D = 0.28 at a = 5 vs 0.087 at a = 10). peskin4 gives
// 0.2737 vs 0.2742. The 2D driver uses peskin4; cosine stays available as the text's choice.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>

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

enum class Kernel { cosine, peskin4, roma3, linear2, keys4 };

// The scene's name for a kernel (resolution.kernel); Scene refuses any other name first.
inline Kernel kernel_from_name(const std::string& name) {
  if (name == "peskin4") return Kernel::peskin4;
  if (name == "roma3") return Kernel::roma3;
  if (name == "linear2") return Kernel::linear2;
  if (name == "cosine") return Kernel::cosine;
  if (name == "keys4") return Kernel::keys4;
  throw std::invalid_argument("unknown IB kernel '" + name + "' (allowed: peskin4, roma3, linear2, cosine, keys4)");
}

// Support width in nodes along one axis.
constexpr int kernel_width(Kernel k) { return k == Kernel::roma3 ? 3 : k == Kernel::linear2 ? 2 : 4; }

// Roma, Peskin and Berger's 3-point kernel (J. Comput. Phys. 153 (1999) 509, eq. 6.3):
//   (1 + sqrt(1 - 3 r^2)) / 3                    for |r| <= 1/2,
//   (5 - 3|r| - sqrt(1 - 3 (1 - |r|)^2)) / 6     for 1/2 <= |r| <= 3/2.
// Partition of unity and zero first moment for every offset, like peskin4, on a narrower support.
inline double roma3_delta(double r) {
  const double ar = std::abs(r);
  if (ar <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0 * ar * ar)) / 3.0;
  if (ar <= 1.5) return (5.0 - 3.0 * ar - std::sqrt(std::max(0.0, 1.0 - 3.0 * (1.0 - ar) * (1.0 - ar)))) / 6.0;
  return 0.0;
}

// Keys' cubic convolution kernel (R. G. Keys, IEEE Trans. ASSP 29 (1981) 1153, a = -1/2):
//   (3/2)|r|^3 - (5/2) r^2 + 1                   for |r| <= 1,
//   -(1/2)|r|^3 + (5/2) r^2 - 4|r| + 2          for 1 <= |r| <= 2.
// Partition of unity, zero first AND second moment for every offset (it interpolates
// quadratics exactly), continuous first derivative; negative between |r| = 1 and 2. Peskin's
// and Roma's kernels are positive, so their second moment cannot vanish (about 1/2 and 1/3
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

// Peskin's 4-point kernel (see above), |r| <= 2.
inline double peskin4_delta(double r) {
  const double ar = std::abs(r);
  if (ar <= 1.0) return 0.125 * (3.0 - 2.0 * ar + std::sqrt(1.0 + 4.0 * ar - 4.0 * ar * ar));
  if (ar <= 2.0) return 0.125 * (5.0 - 2.0 * ar - std::sqrt(std::max(0.0, -7.0 + 12.0 * ar - 4.0 * ar * ar)));
  return 0.0;
}

// The first node of the stencil of a point at coordinate x (delta_stencil(x, kernel).first).
inline int stencil_first(double x, Kernel kernel) {
  if (kernel == Kernel::roma3) return static_cast<int>(std::floor(x)) - 1;  // node floor(x) at floor(x) + 1/2 is the nearest
  if (kernel == Kernel::linear2) return static_cast<int>(std::floor(x - 0.5));
  return static_cast<int>(std::floor(x - 0.5)) - 1;  // peskin4 and cosine
}

// The stencil of the kernel K, chosen at compile time: the hot loops (interpolation.hpp,
// layer_spreading.hpp) are instantiated once per kernel through with_kernel(), so the width is
// a constant and their loops unroll. delta_stencil(x, kernel) picks it at run time.
template <Kernel K>
inline DeltaStencil1D delta_stencil_of(double x) {
  DeltaStencil1D s;
  s.width = kernel_width(K);
  s.first = stencil_first(x, K);
  if constexpr (K == Kernel::roma3) {
    const double r1 = x - (s.first + 1.5);          // offset from the middle node, in [-1/2, 1/2)
    s.w[1] = (1.0 + std::sqrt(std::max(0.0, 1.0 - 3.0 * r1 * r1))) / 3.0;
    // the outer two follow from partition of unity and zero first moment: w0 - w2 = -r1
    const double outer = 1.0 - s.w[1];
    s.w[0] = 0.5 * (outer - r1);
    s.w[2] = 0.5 * (outer + r1);
  } else if constexpr (K == Kernel::linear2) {
    const double r0 = x - (s.first + 0.5);  // in [0, 1)
    s.w[0] = 1.0 - r0;
    s.w[1] = r0;
  } else if constexpr (K == Kernel::keys4) {
    const double r0 = x - (s.first + 0.5);  // in [1, 2): offsets r0, r0 - 1, r0 - 2, r0 - 3
    const double t = r0 - 1.0;               // in [0, 1)
    const double u = 1.0 - t;                // 2 - r0, in (0, 1]
    s.w[1] = (1.5 * t - 2.5) * t * t + 1.0;
    s.w[2] = (1.5 * u - 2.5) * u * u + 1.0;
    s.w[0] = ((-0.5 * r0 + 2.5) * r0 - 4.0) * r0 + 2.0;
    const double r3 = 3.0 - r0;              // in (1, 2]
    s.w[3] = ((-0.5 * r3 + 2.5) * r3 - 4.0) * r3 + 2.0;
  } else if constexpr (K == Kernel::peskin4) {
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

// Calls f(std::integral_constant<Kernel, K>{}) for the kernel named at run time: a loop over
// membrane nodes placed inside f is compiled once per kernel, with no branch on the kernel inside.
template <class F>
inline decltype(auto) with_kernel(Kernel kernel, F&& f) {
  switch (kernel) {
    case Kernel::roma3: return f(std::integral_constant<Kernel, Kernel::roma3>{});
    case Kernel::peskin4: return f(std::integral_constant<Kernel, Kernel::peskin4>{});
    case Kernel::linear2: return f(std::integral_constant<Kernel, Kernel::linear2>{});
    case Kernel::keys4: return f(std::integral_constant<Kernel, Kernel::keys4>{});
    case Kernel::cosine: break;
  }
  return f(std::integral_constant<Kernel, Kernel::cosine>{});
}

inline DeltaStencil1D delta_stencil(double x, Kernel kernel = Kernel::cosine) {
  return with_kernel(kernel, [x](auto k) { return delta_stencil_of<decltype(k)::value>(x); });
}

// The kernel's first moment sum_m (x - x_m) w_m for a point whose first stencil node
// lies r0 = x - x_first in [1, 2) behind it (derived from the weights above).
inline double first_moment_error(double r0) {
  return r0 - 1.5 + 0.5 * (std::cos(0.5 * std::numbers::pi * r0) + std::sin(0.5 * std::numbers::pi * r0));
}

}  // namespace capsule::ib
